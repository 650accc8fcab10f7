// The explorer's colours and layout, shared by its panels and views.
#pragma once

#include <imgui.h>

namespace rigid::explore {

// The window's layout at any size: inputs on the left, numbers on the right, the
// scene between them over the time bar and the plot.
// Widths and heights at the window's own font size, kFontPx; a monitor's content scale
// (HiDPI) enlarges the font, and ui_scale() every size with it.
constexpr float kInputsWidth = 340.0f;
constexpr float kNumbersWidth = 390.0f;
constexpr float kTimeBarHeight = 64.0f;
constexpr float kPlotShare = 0.34f;       // of the height under the scene's top
constexpr float kMinSceneWidth = 320.0f;  // the panels at the sides narrow to keep it
constexpr float kFontPx = 15.0f;
/// The smallest text of a figure in a view (ticks, legends) at ui_scale() 1: a little
/// under the panels' own, where a figure that small would shrink it to 6 px.
constexpr float kFigureTextPx = 12.0f;

/// The window's sizes against kFontPx's: its font's, never under 1.
inline float ui_scale() {
  return ImGui::GetFontSize() > kFontPx ? ImGui::GetFontSize() / kFontPx : 1.0f;
}

// The panels stay where the layout puts them. They tile the window, which is cleared to
// their colour (the style's WindowBg): painting it again under each would be a second
// pass over every pixel, on a software rasteriser a fifth of a frame.
constexpr ImGuiWindowFlags kPanel =
    ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
    ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoSavedSettings |
    ImGuiWindowFlags_NoBackground;

const ImVec4 kRuleColor(0.80f, 0.18f, 0.10f, 1.0f);
const ImVec4 kErrataColor(0.70f, 0.35f, 0.0f, 1.0f);
const ImVec4 kDimColor(0.40f, 0.40f, 0.45f, 1.0f);
const ImVec4 kHeadingColor(0.0f, 0.35f, 0.60f, 1.0f);

}  // namespace rigid::explore
