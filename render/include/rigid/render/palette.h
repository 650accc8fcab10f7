// Colours for every rigidlab figure: an RGBA colour type and the Okabe–Ito
// palette (Okabe & Ito 2008), which stays distinguishable under the common
// forms of colour blindness. Components are linear 0..1 floats, sRGB-encoded
// as written to the PNG (no gamma conversion is done anywhere).
#pragma once

#include <cstddef>

namespace rigid::render {

/// An RGBA colour with 0..1 components; alpha 1 is opaque.
struct Color {
  float r = 0, g = 0, b = 0, a = 1;

  /// The same colour with alpha replaced.
  constexpr Color with_alpha(float alpha) const { return {r, g, b, alpha}; }
};

/// A colour from 8-bit sRGB components.
constexpr Color rgb8(int r, int g, int b, float a = 1.0f) {
  return {r / 255.0f, g / 255.0f, b / 255.0f, a};
}

// Okabe–Ito, in the order series are coloured automatically.
inline constexpr Color kBlue = rgb8(0, 114, 178);
inline constexpr Color kOrange = rgb8(230, 159, 0);
inline constexpr Color kBluishGreen = rgb8(0, 158, 115);
inline constexpr Color kVermillion = rgb8(213, 94, 0);
inline constexpr Color kReddishPurple = rgb8(204, 121, 167);
inline constexpr Color kSkyBlue = rgb8(86, 180, 233);
inline constexpr Color kYellow = rgb8(240, 228, 66);
inline constexpr Color kBlack = rgb8(0, 0, 0);

// Two more for a figure that needs more than Okabe-Ito's seven that read on white (ten
// curves): an olive (a yellow dark enough for text on white) and Paul Tol's wine
// (#882255, of his colour-blind-safe "muted" set).
inline constexpr Color kOlive = rgb8(150, 135, 0);
inline constexpr Color kWine = rgb8(136, 34, 85);

// Neutrals for axes, grids and text.
inline constexpr Color kWhite = rgb8(255, 255, 255);
inline constexpr Color kGray = rgb8(120, 120, 120);
inline constexpr Color kLightGray = rgb8(225, 225, 225);
inline constexpr Color kTextColor = rgb8(25, 25, 25);

/// Marks "pick the next palette colour" in series and materials.
inline constexpr Color kAutoColor = {0, 0, 0, -1};

inline constexpr Color kOkabeIto[] = {kBlue,          kOrange,  kBluishGreen, kVermillion,
                                      kReddishPurple, kSkyBlue, kYellow,      kBlack};
inline constexpr std::size_t kOkabeItoSize = sizeof(kOkabeIto) / sizeof(kOkabeIto[0]);

/// The i-th automatic colour (cycling through Okabe–Ito).
constexpr Color palette_color(std::size_t i) {
  return kOkabeIto[i % kOkabeItoSize];
}

}  // namespace rigid::render
