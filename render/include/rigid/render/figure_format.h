// The file formats a figure is written in: PNG (pixels), SVG and PDF (vectors for
// slides and papers: a plot's lines, fills and text as paths and text, a 3D scene
// as one image at the requested size inside). Names only; draw.h writes them.
#pragma once

#include <array>
#include <optional>
#include <string_view>

namespace rigid::render {

enum class FigureFormat { kPng, kSvg, kPdf };

/// Every format's name, which is also its file extension.
inline constexpr std::array<std::string_view, 3> kFigureFormatNames{"png", "svg", "pdf"};

/// The format's name and file extension (without the dot).
constexpr std::string_view figure_format_name(FigureFormat format) {
  return kFigureFormatNames[static_cast<std::size_t>(format)];
}

/// The format called `name` ("png", "svg" or "pdf"), or none.
constexpr std::optional<FigureFormat> figure_format_named(std::string_view name) {
  for (std::size_t k = 0; k < kFigureFormatNames.size(); ++k)
    if (kFigureFormatNames[k] == name) return static_cast<FigureFormat>(k);
  return std::nullopt;
}

}  // namespace rigid::render
