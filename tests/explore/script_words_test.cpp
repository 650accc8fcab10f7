// A script's words checked when it is read, each command's count of them and their
// types, so that a slip in the script's table or its parser is a refusal naming its rule;
// and a field's text for a vector or a pair, as the explorer's fields and a script's
// `set` read it (Session::set_text), holding exactly its count of numbers.
#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "common/registry.h"
#include "explore_common.h"
#include "script.h"

using namespace rigid::test;
namespace ex = rigid::explore;
using rigid::lab::InputValue;

namespace {

// The one line a script's text is refused with when read ("" if it is not).
std::string refusal(const std::string& text) {
  try {
    ex::Script::parse(text + "\n", "s.txt", all_labs());
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

// Every command, how many words follow it (at least, at most), and words it takes (as
// many as it may: a sample that must be read).
struct Spec {
  std::string op;
  int min, max;
  std::string words;
};
std::vector<Spec> specs(const fs::path& dir) {
  const std::string d = dir.string() + "/";
  return {{"set", 1, 2, "--mass 2"},
          {"unset", 1, 1, "--t-end"},
          {"drag", 2, 2, "--mass 2"},
          {"textbook", 0, 0, ""},
          {"lab", 1, 1, "poinsot"},
          {"play", 1, 1, "1"},
          {"pause", 0, 0, ""},
          {"seek", 1, 1, "1"},
          {"speed", 1, 1, "2"},
          {"turn", 2, 2, "30 -10"},
          {"zoom", 1, 1, "1.5"},
          {"reset-view", 0, 0, ""},
          {"show-scene", 1, 1, "motion"},
          {"show-plot", 1, 1, "omega"},
          {"hide", 1, 1, "herpolhode"},
          {"show", 1, 1, "herpolhode"},
          {"frames", 1, 1, "3"},
          {"wait", 1, 1, "1"},
          {"wait-for", 1, 1, d + "go"},
          {"screenshot", 1, 1, d + "s.png"},
          {"save-figure", 2, 3, "omega " + d + "f.svg 200x150"},
          {"save-view", 1, 2, d + "v.png 200x150"},
          {"export-json", 1, 1, d + "r.json"},
          {"export-csv", 1, 1, d + "r.csv"},
          {"record", 1, 1, d + "m.webp"},
          {"print-command", 0, 0, ""},
          {"print-json", 0, 0, ""},
          {"quit", 0, 0, ""}};
}

// The first `n` of `words`, after `op`.
std::string line_of(const std::string& op, const std::string& words, int n) {
  std::istringstream in(words);
  std::string line = op, w;
  for (int k = 0; k < n && in >> w; ++k) line += " " + w;
  return line;
}

}  // namespace

TEST_CASE("explore: every script command's count of words is checked when the script is read") {
  const fs::path dir = fresh_dir("effects-words");
  std::string names;
  std::vector<Spec> all = specs(dir);
  std::sort(all.begin(), all.end(), [](const Spec& a, const Spec& b) { return a.op < b.op; });
  for (const Spec& s : all) {
    INFO(s.op);
    names += (names.empty() ? "" : ", ") + s.op;
    CHECK(refusal(line_of(s.op, s.words, s.max)).empty());
    CHECK(refusal(line_of(s.op, s.words, s.min)).empty());
    const std::string takes =
        s.op + " takes " +
        (s.min == s.max ? std::to_string(s.min)
                        : std::to_string(s.min) + " to " + std::to_string(s.max)) +
        " words (got ";
    // one word too many, after every word it may take
    CHECK(refusal(line_of(s.op, s.words, s.max) + " extra") ==
          "s.txt:1: " + takes + std::to_string(s.max + 1) + ")");
    if (s.min > 0) {
      CHECK(refusal(line_of(s.op, s.words, s.min - 1)) ==
            "s.txt:1: " + takes + std::to_string(s.min - 1) + ")");
    }
  }
  // no command the script reads but these (each pinned below by its effect)
  CHECK(refusal("nope") == "s.txt:1: unknown command 'nope' (one of " + names + ")");
  // a word in quotes is one word, blanks and all
  CHECK(refusal("hide \"energy ellipsoid\"").empty());
  CHECK(refusal("hide energy ellipsoid") == "s.txt:1: hide takes 1 words (got 2)");
  CHECK(refusal("hide \"energy ellipsoid") == "s.txt:1: a quote is not closed");
}

TEST_CASE("explore: every script command's words are of their type when the script is read") {
  const fs::path dir = fresh_dir("effects-types");
  const std::string folder = (dir / "folder.webp").string();
  fs::create_directory(folder);
  const std::vector<std::pair<std::string, std::string>> refused{
      {"play x", "play must be a number (got 'x')"},
      {"seek x", "seek must be a number (got 'x')"},
      {"speed x", "speed must be a number (got 'x')"},
      {"zoom x", "zoom must be a number (got 'x')"},
      {"frames x", "frames must be a number (got 'x')"},
      {"frames 1.5", "frames must be a whole number"},
      {"wait x", "wait must be a number (got 'x')"},
      {"turn x 0", "turn's first angle must be a number (got 'x')"},
      {"turn 0 x", "turn's second angle must be a number (got 'x')"},
      {"save-figure omega " + (dir / "f.png").string() + " big",
       "save-figure: size: must be WxH, each 16 to 8192 (got 'big')"},
      {"save-view " + (dir / "v.png").string() + " 100", "save-view: size: must be WxH"},
      {"record " + (dir / "m.avi").string(), "record: the file name must end in .mp4 or .webp"},
      {"lab nope", "lab: 'nope' is not a lab (one of "},
  };
  for (const auto& [line, says] : refused) {
    INFO(line);
    CHECK(refusal(line).rfind("s.txt:1: " + says, 0) == 0);
  }
  // each word that names a file it writes is a file it may write
  for (const std::string op :
       {"screenshot", "save-view", "export-json", "export-csv", "record", "save-figure omega"}) {
    INFO(op);
    const std::string why = refusal(op + " " + folder);
    CHECK(why.rfind("s.txt:1: " + op.substr(0, op.find(' ')) + ": '", 0) == 0);
    CHECK(why.find("' is a directory, not a file") != std::string::npos);
  }
}

TEST_CASE("explore: a field for a vector or a pair takes exactly its count of numbers") {
  int checked = 0;
  for (const auto& entry : rigid::lab::all_labs()) {
    auto s = entry.make();
    for (std::size_t i = 0; i < s->input_count(); ++i) {
      const auto kind = s->rule(i).kind();
      if (kind != rigid::lab::InputKind::kVector && kind != rigid::lab::InputKind::kPair) continue;
      const std::string flag = s->rule(i).flag();
      INFO(entry.name << " " << flag);
      const bool vector = kind == rigid::lab::InputKind::kVector;
      const InputValue before = s->value(i);
      // its own numbers, one too many and one too few
      std::string own = rigid::lab::argument_text(before);
      if (own.empty() || own.find(',') == std::string::npos) own = vector ? "1,1,1" : "1,1";
      const std::string more = own + "," + own.substr(own.rfind(',') + 1);
      const std::string fewer = own.substr(0, own.rfind(','));
      for (const std::string& text : {more, fewer}) {
        const auto why = s->set_text(i, text);
        REQUIRE(why);
        CHECK(why->message == flag + ": needs " + (vector ? "3" : "2") +
                                  " numbers separated by commas (got '" + text + "')");
        CHECK(s->value(i) == before);
      }
      ++checked;
    }
  }
  // poinsot's four vectors, euler_angles' three, lamina_tensor's axis, tennis_racquet's
  // inertia; football's and top_nutation's pairs
  CHECK(checked == 11);
}
