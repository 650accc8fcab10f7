// What every lab's report shares (labs/common): how a result reads in the table,
// where roundoff is shown as 0, and the rules an input table checks.
#include <fmt/format.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "common/inputs.h"
#include "common/report.h"
#include "common/session.h"
#include "common/writers.h"
#include "rigid/support/text.h"

using rigid::lab::Report;

namespace {
const rigid::lab::TableRow& last_row(const Report& report) {
  REQUIRE(!report.rows().empty());
  return report.rows().back();
}
}  // namespace

TEST_CASE("lab common: a vector result reads in its own order in the table") {
  Report report;
  report.result("v3", "three", Eigen::Vector3d(1.5, -2, 3.25), "m");
  CHECK(last_row(report).value == "(1.5, -2, 3.25)");
  report.result("v2", "two", Eigen::Vector2d(7, -0.125), "m");
  CHECK(last_row(report).value == "(7, -0.125)");
}

TEST_CASE("lab common: roundoff reads 0 up to its bound, and a number past it") {
  // The bound is the method's roundoff: at it the value is noise, a hair above it a
  // result (a looser cut would print real numbers as 0).
  const double bound = 1e-14;
  Report report;
  report.result_roundoff("at", "at the bound", bound, bound, "N m");
  CHECK(last_row(report).value == "0");
  CHECK(last_row(report).remark == "(roundoff: |computed| <= 1e-14)");
  report.result_roundoff("above", "above the bound", 1.01 * bound, bound, "N m");
  CHECK(last_row(report).value != "0");
  CHECK(last_row(report).remark.empty());
  report.result_roundoff("negative", "below, negative", -0.5 * bound, bound, "N m");
  CHECK(last_row(report).value == "0");
  // The JSON keeps the computed number either way.
  CHECK(report.results().at("at").get<double>() == bound);
}

TEST_CASE("lab common: the table's value column is as wide as its numbers, not its sentences") {
  // A number sets the column; a sentence of 60 characters runs past it. The header
  // "value" and every number then start and end in the same columns.
  Report report;
  report.result("x", "a number", -1.2345678901e-300, "m");
  const std::string shown = last_row(report).value;
  REQUIRE(shown.size() > 5);  // wider than the header "value"
  const std::string sentence(60, 's');
  report.result_text("words", "the motion in words", sentence);
  std::ostringstream table;
  rigid::lab::write_table(table, report, rigid::lab::RunOutputs{});
  std::string header, number;
  std::istringstream lines(table.str());
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("quantity", 0) == 0) header = line;
    if (line.rfind("a number", 0) == 0) number = line;
  }
  REQUIRE(!header.empty());
  REQUIRE(!number.empty());
  const std::size_t value_at = header.find("value"), unit_at = header.find("unit");
  CHECK(number.find(shown) == value_at);
  CHECK(unit_at == value_at + shown.size() + 2);
  CHECK(number.find(" m") + 1 == unit_at);
}

TEST_CASE("lab common: user text is shown byte for byte and cannot act on a terminal") {
  using rigid::support::terminal_safe;
  using rigid::support::utf8_safe;
  // Valid UTF-8 stays: accents, the degree sign, a four-byte character.
  const std::string plain = "r\xc3\xa9sum\xc3\xa9 30\xc2\xb0 \xf0\x9f\x8e\xbe";
  CHECK(terminal_safe(plain) == plain);
  CHECK(utf8_safe(plain) == plain);
  // What is not UTF-8, byte by byte: a stray continuation, an overlong '/', a UTF-16
  // surrogate, a sequence cut short, beyond U+10FFFF.
  CHECK(utf8_safe("a\x80z") == "a\\x80z");
  CHECK(utf8_safe("\xc0\xaf") == "\\xc0\\xaf");
  CHECK(utf8_safe("\xed\xa0\x80") == "\\xed\\xa0\\x80");
  CHECK(utf8_safe("\xe2\x82") == "\\xe2\\x82");
  CHECK(utf8_safe("\xf4\x90\x80\x80") == "\\xf4\\x90\\x80\\x80");
  // JSON keeps control characters (it escapes them itself); a terminal line does not.
  CHECK(utf8_safe("a\nb\x1b[31m") == "a\nb\x1b[31m");
  CHECK(terminal_safe("a\nb\x1b[31m\x7f") == "a\\nb\\x1b[31m\\x7f");
  CHECK(terminal_safe("\xc2\x9b"
                      "31m") == "\\u{009b}31m");
  CHECK(terminal_safe("abc\xe2\x80\xae"
                      "def\xe2\x81\xa6") == "abc\\u{202e}def\\u{2066}");
}

TEST_CASE("lab common: a long value is quoted in whole characters wherever the cut falls") {
  using rigid::lab::quoted_text;
  using rigid::support::utf8_safe;
  // A character of 2, 3 and 4 bytes, then bytes that are no character (a stray
  // continuation, 0xff, a sequence cut short, an overlong '/', a surrogate, beyond
  // U+10FFFF, a 4-byte one cut short), each after 0 to 40 ASCII bytes: the cut at byte 32
  // falls on every byte of each.
  struct Piece {
    std::string bytes;
    bool valid;
  };
  const std::vector<Piece> pieces{
      {"\xc3\xa9", true},     {"\xe2\x82\xac", true},  {"\xf0\x9f\x8e\xbe", true},
      {"\x80", false},        {"\xff", false},         {"\xe2\x82", false},
      {"\xc0\xaf", false},    {"\xed\xa0\x80", false}, {"\xf4\x90\x80\x80", false},
      {"\xf0\x9f\x8e", false}};
  int cuts = 0;
  for (const Piece& piece : pieces) {
    for (std::size_t lead = 0; lead <= 40; ++lead) {
      constexpr std::size_t kRepeats = 45;  // past 40 bytes with no ASCII before
      std::string text(lead, 'a');
      for (std::size_t k = 0; k < kRepeats; ++k) text += piece.bytes;
      const std::string quoted = quoted_text(text);
      INFO("text " << utf8_safe(text) << ", quoted " << utf8_safe(quoted));
      const std::size_t dots = quoted.rfind("... (");
      REQUIRE(dots != std::string::npos);
      const std::string head = quoted.substr(0, dots);
      // the first 32 bytes, less at most the 3 of a character the cut would split
      CHECK(text.compare(0, head.size(), head) == 0);
      CHECK(head.size() <= 32);
      CHECK(head.size() >= 29);
      // whole characters: shown as the tree shows text (an invalid byte as \xNN), the
      // head is the start of the text shown; a split character would show as escapes
      const std::string shown = utf8_safe(head);
      CHECK(utf8_safe(text).compare(0, shown.size(), shown) == 0);
      if (piece.valid) CHECK(shown == head);
      // the length in characters, an invalid byte one
      const std::size_t characters = lead + kRepeats * (piece.valid ? 1 : piece.bytes.size());
      CHECK(quoted.substr(dots) == "... (" + std::to_string(characters) + " characters)");
      ++cuts;
    }
  }
  CHECK(cuts == 410);
  // Short text is quoted whole, whatever its bytes.
  CHECK(quoted_text(std::string(40, 'x')) == std::string(40, 'x'));
  CHECK(quoted_text("\xe2\x82\xac\xff") == "\xe2\x82\xac\xff");
}

TEST_CASE("lab common: an input with a range of its own is held to that range alone") {
  using rigid::lab::InputKind;
  using rigid::lab::InputRule;
  InputRule tilt(InputKind::kNumber, "--tilt-deg", "tilt");
  tilt.unit("deg").range_from(0.0, 45.0);
  InputRule alpha(InputKind::kNumber, "--alpha-deg", "alpha");
  alpha.unit("deg").open_range(0.0, 90.0);
  InputRule mass(InputKind::kNumber, "--mass", "mass");
  mass.positive();
  // Tiny values inside the range are taken, with no word of the general magnitudes.
  for (const char* text : {"0", "1e-61", "1e-300", "2.3e-308"}) {
    CHECK(tilt.broken(std::stod(text), text).empty());
  }
  CHECK(alpha.broken(1e-61, "1e-61").empty());
  // Below a normal double, where its digits run out (5e-324 deg was a zero angle), the
  // rule says so; outside the range, the range.
  const std::string below = "is nonzero and below 2.2e-308 in magnitude";
  CHECK_THAT(tilt.broken(5e-324, "5e-324"), Catch::StartsWith(below));
  CHECK_THAT(alpha.broken(0.0, "1e-400"), Catch::StartsWith(below));
  CHECK(tilt.broken(-1e-61, "-1e-61") == "must be at least 0 and below 45 deg (got -1e-61)");
  CHECK(alpha.broken(HUGE_VAL, "1e400") == "must be between 0 and 90 deg, exclusive (got 1e400)");
  // An input without a range of its own keeps the general magnitudes, as --help's footer says.
  CHECK(mass.broken(1e-61, "1e-61") == "must be between 1e-60 and 1e60 (got 1e-61)");
  CHECK_THAT(std::string(rigid::lab::kNumberRule), Catch::Contains("between 1e-60 and 1e60"));
  // --help states the range and the pairings.
  CHECK(tilt.description() == "tilt [deg] (at least 0 and below 45 deg)");
  // A range whose small end keeps the digits, and 0 besides (an answer of its own): 0
  // is taken, exactly; between 0 and the range, and outside it, the rule names both.
  InputRule share(InputKind::kNumber, "--perturbation", "share");
  share.range_from(1e-60, 0.5).or_zero();
  CHECK(share.takes_zero());
  CHECK(share.broken(0.0, "0").empty());
  CHECK(share.broken(-0.0, "-0").empty());
  CHECK(share.broken(1e-60, "1e-60").empty());
  for (const char* text : {"1e-61", "-1e-300", "0.5"}) {
    CHECK(share.broken(std::stod(text), text) ==
          fmt::format("must be 0, or at least 1e-60 and below 0.5 (got {})", text));
  }
  CHECK(share.description() == "share (0, or at least 1e-60 and below 0.5)");
  CHECK(rigid::lab::slider_span(share, 0.01).lo == 0.0);
  InputRule rate(InputKind::kNumber, "--phi-dot", "phi's rate");
  rate.excludes("--from-omega", "give the rates or --from-omega, not both");
  InputRule timing(InputKind::kFlag, "--timing", "times");
  timing.requires_input("--json", "j").requires_any({"--figures", "--animate"}, "d");
  CHECK(rate.description() == "phi's rate (not with --from-omega)");
  CHECK(timing.description() == "times (only with --json; only with --figures or --animate)");
}

TEST_CASE("lab common: one check of pairings, whatever says what was given") {
  using rigid::lab::InputError;
  using rigid::lab::InputKind;
  using rigid::lab::InputRule;
  InputRule timing(InputKind::kFlag, "--timing", "times");
  timing.requires_any({"--figures", "--animate"}, "times the drawing");
  InputRule axis_deg(InputKind::kNumber, "--axis-deg", "axis");
  axis_deg.excludes("--axis", "give --axis or --axis-deg, not both");
  const std::vector<const InputRule*> rules{&timing, &axis_deg};
  const auto check = [&](std::vector<std::string> given) {
    try {
      rigid::lab::check_pairings(rules, [&](const std::string& flag) {
        return std::find(given.begin(), given.end(), flag) != given.end();
      });
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK(check({}) == "");
  CHECK(check({"--timing"}) == "--timing: times the drawing");
  CHECK(check({"--timing", "--animate"}) == "");
  CHECK(check({"--timing", "--figures"}) == "");
  CHECK(check({"--figures", "--axis"}) == "");
  CHECK(check({"--axis-deg"}) == "");
  CHECK(check({"--axis", "--axis-deg"}) == "--axis-deg: give --axis or --axis-deg, not both");
  // the first broken, in the rules' order
  CHECK(check({"--axis", "--axis-deg", "--timing"}) == "--timing: times the drawing");
}
