// The numbers panel's wrapping: at blanks only, so no number is cut where a student
// would copy half of it (Dear ImGui's own breaks after a full stop: "0." / "6553 s").
#include "text_wrap.h"

#include <catch2/catch.hpp>
#include <string>

namespace ex = rigid::explore;

namespace {
// A monospaced measure: a character a unit.
float chars(std::string_view s) {
  return static_cast<float>(s.size());
}
}  // namespace

TEST_CASE("explore: the numbers panel wraps at blanks only and never inside a number") {
  const std::string answer =
      "the racquet turns over first at 0.6553 s, then every 1.311 s (Is/I = 1.00327); "
      "I = (0.0012675, 0.011812, 0.013079) kg m^2";
  for (int width = 1; width <= 90; ++width) {
    INFO("width " << width);
    const std::vector<std::string> lines = ex::wrap_lines(answer, static_cast<float>(width), chars);
    std::string joined;
    for (const std::string& line : lines) {
      // a line is as wide as it may be, or one word too wide to fit any line
      CHECK((chars(line) <= width || line.find(' ') == std::string::npos));
      CHECK_FALSE(line.empty());
      CHECK(line.front() != ' ');
      CHECK(line.back() != ' ');
      joined += (joined.empty() ? "" : " ") + line;
    }
    // every word whole, in order: the lines joined give the text back
    CHECK(joined == answer);
    // and as full as they can be: the next line's first word would not have fit
    for (std::size_t k = 0; k + 1 < lines.size(); ++k) {
      const std::string next_word = lines[k + 1].substr(0, lines[k + 1].find(' '));
      CHECK(chars(lines[k] + " " + next_word) > width);
    }
  }
  // its own line breaks are kept, blank runs are one blank
  CHECK(ex::wrap_lines("a  b\nc", 10, chars) == std::vector<std::string>{"a b", "c"});
  CHECK(ex::wrap_lines("", 10, chars) == std::vector<std::string>{""});
}
