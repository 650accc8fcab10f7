// One reader of user text: the same text given to an input on the command line (the lab
// run as a process), typed into a live session (what the explorer's fields call) and set
// by an explorer script (`set --flag "text"`, where the explorer is built) gets the same
// verdict, and where refused the same message. Texts: numbers
// as people and programs spell them, spaces, overflow and underflow, infinities, vectors
// and pairs with too few or many parts, words, and bytes that are not UTF-8. And one check
// of pairings: every pairing a lab's table declares (alternatives given together, an input
// given without the one it acts with) is refused alike by the command line and a live
// session, and each of the command's own options that acts only with another is refused
// without it, as its --help says.

#include <catch2/catch.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "common/registry.h"
#include "rigid/support/subprocess.h"
#include "rigid/support/text.h"
#ifdef RIGID_HAVE_EXPLORER
#include "explorer.h"
#include "script.h"
#endif

namespace {

struct Verdict {
  bool accepted = false;
  std::string message;  ///< "--flag: rule" where refused
};

// The lab as a process with exactly these arguments: its verdict and its one error line
// less the "LAB: error: " in front.
Verdict command_line(const std::string& lab, const std::vector<std::string>& args) {
  std::vector<std::string> argv{lab};
  argv.insert(argv.end(), args.begin(), args.end());
  rigid::support::Subprocess run(
      std::string(RIGID_LAB_DIR) + "/" + lab, argv,
      {rigid::support::Redirect::null(), rigid::support::Redirect::pipe()});
  const std::string text = run.read_to_end();
  const int status = run.wait();
  Verdict v;
  v.accepted = status == 0;
  const std::string prefix = lab + ": error: ";
  if (!v.accepted && text.rfind(prefix, 0) == 0) {
    v.message = text.substr(prefix.size());
    if (!v.message.empty() && v.message.back() == '\n') v.message.pop_back();
  } else if (!v.accepted) {
    v.message = "(not one error line) " + text;
  }
  return v;
}

Verdict live(const std::string& lab, const std::string& flag, const std::string& text) {
  for (const auto& entry : rigid::lab::all_labs()) {
    if (entry.name != lab) continue;
    const auto session = entry.make();
    const auto refusal = session->set_text(session->find(flag), text);
    // as the command line's terminal line shows it (invalid UTF-8 as \xNN)
    return refusal ? Verdict{false, rigid::support::terminal_safe(refusal->message)}
                   : Verdict{true, {}};
  }
  FAIL("no lab " << lab);
  return {};
}

#ifdef RIGID_HAVE_EXPLORER
// The text set by a one-line explorer script, the explorer held in-process (no window: a
// script's step applies its action between frames); its verdict and its "refused:" line.
Verdict scripted(const std::string& lab, const std::string& flag, const std::string& text) {
  // a script's word in double quotes may hold any byte but a quote, a # or a line's end
  REQUIRE(text.find_first_of("\"#\n") == std::string::npos);
  rigid::explore::Explorer explorer(rigid::lab::all_labs(), lab, {});
  rigid::explore::Script script =
      rigid::explore::Script::parse("set " + flag + " \"" + text + "\"\n", "doors.txt");
  std::ostringstream out;
  script.report_to(out);
  for (int steps = 0; script.step(explorer); ++steps) REQUIRE(steps < 10);
  const std::string said = out.str();
  if (said.empty()) return {true, {}};
  const std::string prefix = "doors.txt:1: refused: ";
  if (said.rfind(prefix, 0) != 0 || said.back() != '\n') return {false, "(not one line) " + said};
  return {false, said.substr(prefix.size(), said.size() - prefix.size() - 1)};
}
#endif

// Texts to try for input i of a lab: another of its words, or numbers its kind takes.
std::vector<std::string> candidates(const rigid::lab::Session& s, std::size_t i) {
  const rigid::lab::InputRule& rule = s.rule(i);
  switch (rule.kind()) {
    case rigid::lab::InputKind::kNumber: {
      std::vector<std::string> texts{"0.5", "2", "30", "0.2"};
      const rigid::lab::InputValue textbook = s.textbook_value(i);
      if (const auto* x = std::get_if<double>(&textbook); x != nullptr && *x != 0) {
        texts.insert(texts.begin(), rigid::lab::argument_text(1.5 * *x));
      }
      return texts;
    }
    case rigid::lab::InputKind::kVector:
      return {"1,2,3", "0.2,0.3,0.4", "2,2,3"};
    case rigid::lab::InputKind::kPair:
      return {"1,1.5", "0.01,0.003", "2,1"};
    case rigid::lab::InputKind::kChoice:
      return rule.choices();
    case rigid::lab::InputKind::kFlag:
      return {"on"};
  }
  return {};
}

using Given = std::vector<std::pair<std::string, std::string>>;  // flag, text

std::string joined(const std::vector<std::string>& words) {
  std::string text;
  for (const std::string& w : words) text += (text.empty() ? "" : " ") + w;
  return text;
}

// The lab's session with `given` set in order; the refusal of the last one set, if any.
std::optional<rigid::lab::Refusal> set_all(const rigid::lab::LabEntry& lab, const Given& given) {
  const auto session = lab.make();
  std::optional<rigid::lab::Refusal> refusal;
  for (const auto& [flag, text] : given) refusal = session->set_text(session->find(flag), text);
  return refusal;
}

// A text for `flag` that the lab takes after `before` and that is not its textbook value.
std::optional<std::string> taken_text(const rigid::lab::LabEntry& lab, const std::string& flag,
                                      Given before) {
  const auto session = lab.make();
  const std::size_t i = session->find(flag);
  REQUIRE(i < session->input_count());
  for (const std::string& text : candidates(*session, i)) {
    const auto read = rigid::lab::read_input(session->rule(i), text);
    const auto* value = std::get_if<rigid::lab::InputValue>(&read);
    if (value == nullptr || *value == session->textbook_value(i)) continue;
    before.emplace_back(flag, text);
    if (!set_all(lab, before)) return text;
    before.pop_back();
  }
  return std::nullopt;
}

std::vector<std::string> arguments(const Given& given) {
  std::vector<std::string> args;
  for (const auto& [flag, text] : given) {
    args.push_back(flag);
    if (text != "on") args.push_back(text);
  }
  return args;
}

// The command line and a session refuse `given` (the last one set) with one message,
// "FLAG: RULE", and the command line takes `taken`.
void same_refusal(const rigid::lab::LabEntry& lab, const Given& given, const Given& taken,
                  const std::string& flag, const std::string& rule) {
  const std::string expected = flag + ": " + rule;
  INFO(lab.name << " " << rigid::support::terminal_safe(joined(arguments(given))));
  const Verdict cli = command_line(lab.name, arguments(given));
  CHECK(!cli.accepted);
  CHECK(cli.message == expected);
  const auto refusal = set_all(lab, given);
  REQUIRE(refusal.has_value());
  CHECK(refusal->message == expected);
  CHECK(command_line(lab.name, arguments(taken)).accepted);
}

// The texts tried on a number input, a vector, a pair and a bounded angle.
std::vector<std::string> number_texts() {
  return {"2",
          "2.5",
          "+2",
          "-2",
          "0",
          "-0",
          "2e0",
          "2E0",
          "2.",
          ".5",
          "0x10",
          "0x1p-3",
          "1e-60",
          "1e60",
          "1e61",
          "1e-61",
          "1e-400",
          "1e400",
          "-1e400",
          "4.9e-324",
          "1.8e308",
          "1e308",
          "inf",
          "-inf",
          "INF",
          "infinity",
          "nan",
          "NaN",
          "-nan",
          "",
          " ",
          "2 ",
          " 2",
          "\t2",
          "2\t",
          " 2 ",
          "2 3",
          "2,3",
          "2x",
          "x2",
          "two",
          "--",
          "-",
          "+",
          "e5",
          "1e",
          "1e+",
          "1..2",
          "1.2.3",
          "0b101",
          "1_000",
          "1'000",
          "١٢",
          "２",
          "\xff",
          "\xc3\x28",
          "2\xff",
          std::string(300, '9'),
          "0." + std::string(400, '0') + "1",
          std::string(50, '1') + "e-90"};
}

std::vector<std::string> vector_texts() {
  return {"1,2,3",     "1, 2, 3",    " 1,2,3 ",  "1,2",     "1,2,3,4",  "1,,3",
          ",2,3",      "1,2,",       "1;2;3",    "1 2 3",   "0,0,0",    "1,2,x",
          "1,2,1e400", "1,2,1e-400", "1,2,inf",  "nan,2,3", "",         " ",
          "1,2,3,",    "x",          "1,2,\xff", "-1,2,3",  "1e60,1,1", "1e61,1,1"};
}

std::vector<std::string> pair_texts() {
  return {"1,1.5", "1, 1.5", "1",       "1,1.5,2",  ",1", "1,", "1,x",
          "0,1",   "-1,1",   "1,1e400", "1e-400,1", "",   "x"};
}

void same_everywhere(const std::string& lab, const std::string& flag,
                     const std::vector<std::string>& texts, int& disagreements) {
  for (const std::string& text : texts) {
    const Verdict cli = command_line(lab, {flag, text, "--json", "--quiet"});
    const Verdict session = live(lab, flag, text);
    const auto said = [](const Verdict& v) {
      return v.accepted ? std::string("accepts") : "refuses: " + v.message;
    };
    INFO(lab << " " << flag << " '" << text << "': command line " << said(cli) << "; live "
             << said(session));
    CHECK(cli.accepted == session.accepted);
    if (!cli.accepted && !session.accepted) CHECK(cli.message == session.message);
    disagreements +=
        cli.accepted != session.accepted || (!cli.accepted && cli.message != session.message);
#ifdef RIGID_HAVE_EXPLORER
    const Verdict script = scripted(lab, flag, text);
    INFO("explorer script " << said(script));
    CHECK(script.accepted == cli.accepted);
    if (!cli.accepted && !script.accepted) CHECK(script.message == cli.message);
    disagreements +=
        script.accepted != cli.accepted || (!cli.accepted && script.message != cli.message);
#endif
  }
}

}  // namespace

TEST_CASE("one reader: the command line, a live session and a script read text the same way") {
  int disagreements = 0;
  same_everywhere("poinsot", "--mass", number_texts(), disagreements);
  same_everywhere("top_nutation", "--theta0-deg", number_texts(), disagreements);
  same_everywhere("top_nutation", "--phidot0", number_texts(), disagreements);
  same_everywhere("poinsot", "--omega", vector_texts(), disagreements);
  same_everywhere("top_nutation", "--inertia", pair_texts(), disagreements);
  same_everywhere("lamina_tensor", "--axis", {"diagonal", "x", "1,1,0", "Diagonal", ""},
                  disagreements);
  CHECK(disagreements == 0);
}

TEST_CASE("one check of pairings: every pairing a table declares is refused alike everywhere") {
  using rigid::lab::Pairing;
  int checked = 0;
  for (const rigid::lab::LabEntry& lab : rigid::lab::all_labs()) {
    const auto session = lab.make();
    for (std::size_t i = 0; i < session->input_count(); ++i) {
      const rigid::lab::InputRule& rule = session->rule(i);
      for (const Pairing& p : rule.pairings()) {
        INFO(lab.name << " " << rule.flag() << " " << p.stated());
        const std::string& other = p.others.front();
        const auto other_text = taken_text(lab, other, {});
        REQUIRE(other_text.has_value());
        if (p.kind == Pairing::Kind::kExcludes) {
          // each alone is taken; together they are refused, set in either order
          const auto text = taken_text(lab, rule.flag(), {});
          REQUIRE(text.has_value());
          same_refusal(lab, {{other, *other_text}, {rule.flag(), *text}}, {{rule.flag(), *text}},
                       rule.flag(), p.rule);
          same_refusal(lab, {{rule.flag(), *text}, {other, *other_text}}, {{other, *other_text}},
                       rule.flag(), p.rule);
        } else {
          // taken with the one it acts with, refused without it
          const auto text = taken_text(lab, rule.flag(), {{other, *other_text}});
          REQUIRE(text.has_value());
          same_refusal(lab, {{rule.flag(), *text}}, {{other, *other_text}, {rule.flag(), *text}},
                       rule.flag(), p.rule);
        }
        ++checked;
      }
    }
  }
  // poinsot 5, tennis_racquet 5, top_nutation 3, lamina_tensor 1, football 3,
  // tire_balancing 2, euler_angles 3
  CHECK(checked == 22);
}

TEST_CASE("one check of pairings: the command's own settings act only with their output") {
  int checked = 0;
  for (const rigid::lab::LabEntry& lab : rigid::lab::all_labs()) {
    rigid::support::Subprocess run(
        std::string(RIGID_LAB_DIR) + "/" + lab.name, {lab.name, "--help"},
        {rigid::support::Redirect::pipe(), rigid::support::Redirect::null()});
    const std::string help = run.read_to_end();
    REQUIRE(run.wait() == 0);
    const bool film = help.find("--animate FILE") != std::string::npos;
    const std::vector<std::vector<std::string>> alone{
        {"--figure-format", "svg"}, {"--figure-size", "800x600"},   {"--figure-prefix", "a-"},
        {"--timing", "--json"},     {"--timing", "--figures", "d"}, {"--fps", "10"},
        {"--duration", "1"},        {"--animation-size", "320x240"}};
    for (const auto& args : alone) {
      if (!film && (args[0] == "--fps" || args[0] == "--duration" || args[0] == "--animation-size"))
        continue;
      INFO(lab.name << " " << joined(args));
      // --help says what it acts only with (its entry may take a second line)
      const std::size_t entry = help.find("\n  " + args[0] + " ");
      REQUIRE(entry != std::string::npos);
      const std::size_t next = help.find("\n  -", entry + 1);
      CHECK(help.substr(entry, next - entry).find("only with ") != std::string::npos);
      const Verdict cli = command_line(lab.name, args);
      CHECK(!cli.accepted);
      // (a build without the renderer refuses --figures itself first)
      const bool no_renderer = cli.message.rfind("--figures: needs the renderer", 0) == 0;
      CHECK((cli.message.rfind(args[0] + ": ", 0) == 0 || no_renderer));
      ++checked;
    }
  }
  CHECK(checked == 7 * 5 + 5 * 3);  // five labs have --animate
}
