// The explorer's colours and layout, shared by its panels and views.
#pragma once

#include <imgui.h>

namespace rigid::explore {

// The window's layout at any size: inputs on the left, numbers on the right, the
// scene between them over the time bar and the plot.
constexpr float kInputsWidth = 340.0f;
constexpr float kNumbersWidth = 390.0f;
constexpr float kTimeBarHeight = 64.0f;
constexpr float kPlotShare = 0.34f;  // of the height under the scene's top

// The panels stay where the layout puts them.
constexpr ImGuiWindowFlags kPanel =
    ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
    ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoSavedSettings;

const ImVec4 kRuleColor(0.80f, 0.18f, 0.10f, 1.0f);
const ImVec4 kErrataColor(0.70f, 0.35f, 0.0f, 1.0f);
const ImVec4 kDimColor(0.40f, 0.40f, 0.45f, 1.0f);
const ImVec4 kHeadingColor(0.0f, 0.35f, 0.60f, 1.0f);

}  // namespace rigid::explore
