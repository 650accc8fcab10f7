// Text wrapped to a width at its blanks only, so a number ("0.6553 s", "1.00327",
// "(0.0012675, 0.011812)") is never broken where a student would copy half of it.
// Dear ImGui's own wrapping also breaks after a full stop, inside "0.6553".
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace rigid::explore {

/// The lines of `text` at most `width` wide by `measure` (a line's width), broken at
/// blanks and at its own line breaks. A word wider than `width` keeps a line of its own,
/// whole: cut off at the panel's edge rather than broken.
std::vector<std::string> wrap_lines(std::string_view text, float width,
                                    const std::function<float(std::string_view)>& measure);

}  // namespace rigid::explore
