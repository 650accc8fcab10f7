// Text for labels, titles and tick numbers: FreeType with DejaVu Sans,
// hinting off so that glyph shapes and advances scale exactly with size and
// output is the same on every machine.
//
// Strings are UTF-8 with a tiny TeX-like markup, enough for the textbook's
// symbols:
//   \omega \theta \phi \psi \Omega ...  Greek letters by name (UTF-8 ω works too)
//   x_1  x_{12}                         subscript (one character or a {group})
//   m a^2  10^{-6}                      superscript
//   \dot{\theta}  \dot\phi  θ̇           a dot above (also U+0307 after a glyph)
//   \deg  \cdot  \times  \pm \approx    °, ·, ×, ±, ≈ ; also \le \ge \to \infty \perp
//   \\ \_ \^ \{ \}                      the literal character
// Sub- and superscripts are drawn at 70% size, shifted down or up. Spaces
// after a command are kept (unlike TeX), so "\omega (rad/s)" reads "ω (rad/s)";
// write "\Delta{}E" for ΔE.
#pragma once

#include <string>
#include <string_view>

namespace rigid::render {

/// Horizontal placement of text relative to its anchor point.
enum class HAlign { kLeft, kCenter, kRight };
/// Vertical placement of text relative to its anchor point.
enum class VAlign { kTop, kCenter, kBaseline, kBottom };

/// The size of a laid-out string in pixels: width, and ascent/descent about the baseline.
struct TextExtent {
  double width = 0;
  double ascent = 0;   ///< above the baseline (font ascender, taller if superscripts)
  double descent = 0;  ///< below the baseline (font descender, deeper if subscripts), positive
  /// Total height ascent + descent.
  double height() const { return ascent + descent; }
};

/// Measures markup text at a font size in pixels (the em size); needs no GL context.
TextExtent measure_text(std::string_view markup, double size_px);

/// Converts markup to plain UTF-8 (Greek names to letters, sub/superscripts inline), e.g. for CSV
/// headers.
std::string plain_text(std::string_view markup);

}  // namespace rigid::render
