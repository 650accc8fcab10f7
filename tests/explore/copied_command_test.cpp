// The command the explorer's "Copy command" gives (explore::command_line) reproduces what
// the explorer shows: pasted into a shell with --json after it, it prints the JSON the
// session's report prints (explore::json_text), byte for byte, but for the "--json" its
// argv names. The states are random walks over every lab's inputs, each change made as a
// user makes it: a slider's or a drag's value (Session::set), a word from a list, a switch
// ticked, text typed in a field (Session::set_text), an optional input given or handed
// back to the lab; values drawn inside each input's rule and the explorer's slider span,
// and an input's alternatives cleared (or the input it needs given) before it is set, as a
// user must. A change the session refuses leaves its state, which is still a state to try.
// Deterministic: one seed; the lab processes run a few at once beside the sessions.

#include <fmt/format.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <condition_variable>
#include <cstdlib>
#include <deque>
#include <iostream>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <thread>
#include <variant>
#include <vector>

#include "common/registry.h"
#include "exports.h"
#include "rigid/support/subprocess.h"

namespace {

namespace lab = rigid::lab;
using lab::InputValue;
using lab::Session;

// The random source of every choice, and the shapes of numbers drawn from it.
struct Draw {
  std::mt19937_64 rng{20240611};

  double uniform(double lo, double hi) { return std::uniform_real_distribution<>(lo, hi)(rng); }
  double log_uniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
  bool chance(double p) { return uniform(0, 1) < p; }
  std::size_t index(std::size_t n) {
    return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
  }
};

// A number for input i as its slider gives one: inside the slider's span about the
// textbook value (about 1 for an optional input the lab sets itself), now and then a
// physical one far beyond it, or zero, as typed. Every bit of the double is random.
double number_value(const Session& s, std::size_t i, Draw& d) {
  const lab::InputRule& r = s.rule(i);
  const InputValue book = s.textbook_value(i);
  const double* textbook = std::get_if<double>(&book);
  const lab::SliderSpan span = lab::slider_span(r, textbook ? *textbook : 1.0);
  double x = span.log ? d.log_uniform(span.lo, span.hi) : d.uniform(span.lo, span.hi);
  if (!r.own_range() && r.physical() && d.chance(0.1)) x *= std::pow(10.0, d.uniform(-4, 4));
  if (r.bound() == lab::InputRule::Bound::kFinite && d.chance(0.05)) x = 0;
  return x;
}

// A pair's or vector's numbers as a drag leaves them: each component about the textbook's
// (any sign where the rule allows one), or, for one the lab sets itself, positive numbers
// in increasing order (moments then keep their triangle rule, and a racquet's its order).
InputValue numbers_value(const Session& s, std::size_t i, Draw& d) {
  const lab::InputRule& r = s.rule(i);
  const InputValue book = s.textbook_value(i);
  const bool signed_ok = r.bound() == lab::InputRule::Bound::kFinite;
  const auto component = [&](double textbook, double size) {
    if (textbook == 0 || (signed_ok && d.chance(0.2))) return d.uniform(-size, size);
    return d.chance(0.1) ? textbook : textbook * d.log_uniform(0.3, 3.0);
  };
  if (const auto* v = std::get_if<Eigen::Vector3d>(&book)) {
    const double size = std::max(v->cwiseAbs().maxCoeff(), 1.0);
    return Eigen::Vector3d(component((*v)[0], size), component((*v)[1], size),
                           component((*v)[2], size));
  }
  if (const auto* v = std::get_if<Eigen::Vector2d>(&book)) {
    const double size = std::max(v->cwiseAbs().maxCoeff(), 1.0);
    return Eigen::Vector2d(component((*v)[0], size), component((*v)[1], size));
  }
  std::vector<double> parts;
  for (int k = 0; k < (r.kind() == lab::InputKind::kVector ? 3 : 2); ++k) {
    parts.push_back(d.uniform(1, 2));
  }
  std::sort(parts.begin(), parts.end());
  if (parts.size() == 2) return Eigen::Vector2d(parts[0], parts[1]);
  return Eigen::Vector3d(parts[0], parts[1], parts[2]);
}

// A value for input i other than absent: what its widget offers.
InputValue a_value(const Session& s, std::size_t i, Draw& d) {
  const lab::InputRule& r = s.rule(i);
  switch (r.kind()) {
    case lab::InputKind::kNumber:
      return number_value(s, i, d);
    case lab::InputKind::kPair:
    case lab::InputKind::kVector:
      if (!r.word_names().empty() && d.chance(0.5)) {
        return r.word_names()[d.index(r.word_names().size())];
      }
      return numbers_value(s, i, d);
    case lab::InputKind::kChoice:
      return r.choices()[d.index(r.choices().size())];
    case lab::InputKind::kFlag: {
      const InputValue now = s.value(i);
      return !(std::holds_alternative<bool>(now) && std::get<bool>(now));
    }
  }
  return {};
}

// `value` as a user types it into the field: every digit, or four significant ones; a
// zero now and then as "-0".
std::string typed(const InputValue& value, Draw& d) {
  const bool full = d.chance(0.5);
  const auto number = [&](double x) {
    if (x == 0 && d.chance(0.5)) return std::string("-0");
    return full ? fmt::format("{}", x) : fmt::format("{:.4g}", x);
  };
  if (const double* x = std::get_if<double>(&value)) return number(*x);
  if (const auto* v = std::get_if<Eigen::Vector2d>(&value)) {
    return number((*v)[0]) + "," + number((*v)[1]);
  }
  if (const auto* v = std::get_if<Eigen::Vector3d>(&value)) {
    return number((*v)[0]) + "," + number((*v)[1]) + "," + number((*v)[2]);
  }
  if (const bool* on = std::get_if<bool>(&value)) return *on ? "on" : "off";
  if (const auto* word = std::get_if<std::string>(&value)) return *word;
  return "";  // an optional input handed back to the lab
}

// Whether input i is given: what Session::arguments() writes on the command line.
bool given(const Session& s, std::size_t i) {
  const InputValue v = s.value(i);
  return !std::holds_alternative<std::monostate>(v) && !(v == s.textbook_value(i));
}

// A user's changes to a session, as the explorer's widgets and fields make them, counted.
class Walk {
 public:
  int changes = 0, refused = 0, typed_in = 0;

  // One change: an input given a value, or handed back to the lab.
  void change_one(Session& s) {
    const std::size_t i = d_.index(s.input_count());
    if (given(s, i) && d_.chance(0.2)) {
      clear(s, i);
      return;
    }
    make_way(s, i);
    enter(s, i, a_value(s, i, d_));
  }
  Draw& draw() { return d_; }

 private:
  // Sets input i as a widget would (its value) or as its field would (the value typed).
  void enter(Session& s, std::size_t i, const InputValue& value) {
    ++changes;
    const bool by_text = d_.chance(0.4);
    typed_in += by_text;
    refused += (by_text ? s.set_text(i, typed(value, d_)) : s.set(i, value)).has_value();
  }

  // Input i back to what it is when not given (the lab's own, or the textbook's).
  void clear(Session& s, std::size_t i) { enter(s, i, s.textbook_value(i)); }

  // Makes way for input i as a user must: its alternatives (declared on either side)
  // cleared, and one of the inputs it acts only with given.
  void make_way(Session& s, std::size_t i) {
    const std::string& flag = s.rule(i).flag();
    for (std::size_t k = 0; k < s.input_count(); ++k) {
      for (const lab::Pairing& p : s.rule(k).pairings()) {
        if (p.kind != lab::Pairing::Kind::kExcludes) continue;
        for (const std::string& other : p.others) {
          const std::size_t j = k == i ? s.find(other) : k;
          if ((k == i || other == flag) && j < s.input_count() && given(s, j)) clear(s, j);
        }
      }
    }
    for (const lab::Pairing& p : s.rule(i).pairings()) {
      if (p.kind != lab::Pairing::Kind::kRequires) continue;
      const auto is_given = [&](const std::string& o) { return given(s, s.find(o)); };
      if (std::none_of(p.others.begin(), p.others.end(), is_given)) {
        const std::size_t j = s.find(p.others[d_.index(p.others.size())]);
        make_way(s, j);
        enter(s, j, a_value(s, j, d_));
      }
    }
  }

  Draw d_;
};

// What the states given hold, by kind: each kind of input must be reached.
struct Reached {
  int switches = 0, choices = 0, optionals = 0, vectors = 0, words = 0, numbers = 0;

  void add(const Session& s) {
    for (std::size_t i = 0; i < s.input_count(); ++i) {
      if (!given(s, i)) continue;
      const lab::InputRule& r = s.rule(i);
      const InputValue v = s.value(i);
      switches += r.kind() == lab::InputKind::kFlag;
      choices += r.kind() == lab::InputKind::kChoice;
      optionals += !r.lab_default_text().empty();
      vectors +=
          std::holds_alternative<Eigen::Vector3d>(v) || std::holds_alternative<Eigen::Vector2d>(v);
      words += r.kind() != lab::InputKind::kChoice && std::holds_alternative<std::string>(v);
      numbers += std::holds_alternative<double>(v);
    }
  }
};

// A state to try: the session's command line and the JSON its report prints, then what
// the command line printed when run.
struct Case {
  std::string lab, line, shown;
  std::string printed;
  int status = 0;
};

// `line` pasted into a shell with --json after it: its stdout and exit status.
void run_pasted(Case& c) {
  rigid::support::Subprocess sh(
      "/bin/sh", {"sh", "-c", c.line + " --json"},
      {rigid::support::Redirect::pipe(), rigid::support::Redirect::null()});
  c.printed = sh.read_to_end();
  c.status = sh.wait();
}

// The session's JSON as the command line run with --json prints it: its "command" names
// that one word more.
std::string with_json_word(const std::string& json) {
  const std::size_t command = json.find("\"command\": [");
  const std::size_t end = json.find("\n  ]", command);
  if (command == std::string::npos || end == std::string::npos) return json;
  return json.substr(0, end) + ",\n    \"--json\"" + json.substr(end);
}

// Runs the cases handed to it, `workers` at a time, while the sessions make more.
class Runner {
 public:
  Runner(std::deque<Case>& cases, int workers) : cases_(cases) {
    for (int w = 0; w < workers; ++w) threads_.emplace_back([this] { work(); });
  }
  ~Runner() { finish(); }
  void add(Case c) {
    std::lock_guard<std::mutex> lock(mutex_);
    cases_.push_back(std::move(c));
    ready_.notify_one();
  }
  void finish() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      done_ = true;
    }
    ready_.notify_all();
    for (std::thread& t : threads_) {
      if (t.joinable()) t.join();
    }
  }

 private:
  void work() {
    for (;;) {
      std::unique_lock<std::mutex> lock(mutex_);
      ready_.wait(lock, [this] { return done_ || next_ < cases_.size(); });
      if (next_ == cases_.size()) return;
      Case& c = cases_[next_++];  // a deque's elements stay where they are as it grows
      lock.unlock();
      run_pasted(c);
    }
  }
  std::deque<Case>& cases_;
  std::mutex mutex_;
  std::condition_variable ready_;
  std::size_t next_ = 0;
  bool done_ = false;
  std::vector<std::thread> threads_;
};

// The labs' programs found by name, as a user's shell finds them.
void put_labs_on_path() {
  const char* path = std::getenv("PATH");
  ::setenv("PATH", (std::string(RIGID_LAB_DIR) + ":" + (path ? path : "/usr/bin:/bin")).c_str(), 1);
}

}  // namespace

TEST_CASE("explore: the copied command run in a shell prints the JSON the explorer shows") {
  put_labs_on_path();
  const std::vector<lab::LabEntry> labs = lab::all_labs();
  std::vector<std::unique_ptr<Session>> sessions;
  for (const auto& entry : labs) sessions.push_back(entry.make());
  Walk walk;
  Reached reached;
  std::deque<Case> cases;
  Runner runner(cases, 2);
  for (int k = 0; k < RIGID_ROUNDTRIP_STATES; ++k) {
    Session& s = *sessions[k % sessions.size()];
    if (walk.draw().chance(0.1)) s.reset();
    for (std::size_t n = 1 + walk.draw().index(3); n > 0; --n) walk.change_one(s);
    reached.add(s);
    Case c;
    c.lab = s.name();
    c.line = rigid::explore::command_line(s);
    c.shown = rigid::explore::json_text(s);
    runner.add(std::move(c));
  }
  runner.finish();
  int matched = 0, with_inputs = 0;
  for (const Case& c : cases) {
    INFO(c.line);
    CHECK(c.status == 0);
    CHECK(c.printed == with_json_word(c.shown));
    matched += c.status == 0 && c.printed == with_json_word(c.shown);
    with_inputs += c.line != c.lab;
  }
  std::cout << "copied command round trip: " << cases.size() << " states over " << labs.size()
            << " labs (" << with_inputs << " with inputs given; " << walk.changes << " changes, "
            << walk.typed_in << " typed, " << walk.refused << " refused), " << matched
            << " matched; inputs given: " << reached.numbers << " numbers, " << reached.vectors
            << " pairs and vectors, " << reached.words << " vector words, " << reached.choices
            << " choices, " << reached.switches << " switches on, " << reached.optionals
            << " optional\n";
  // the walk reaches every kind of input given: a switch on, a choice, an optional
  // input, numbers, pairs and vectors, a vector's word
  const int n = static_cast<int>(cases.size());
  CHECK(with_inputs > n * 9 / 10);
  CHECK(reached.numbers > n);
  for (const int kind :
       {reached.vectors, reached.words, reached.choices, reached.switches, reached.optionals}) {
    CHECK(kind >= n / 50);
  }
  CHECK(walk.refused < walk.changes / 2);
}

TEST_CASE("explore: the JSON's command names the argv the command line was given") {
  std::unique_ptr<Session> poinsot;
  for (const auto& entry : lab::all_labs()) {
    if (entry.name == "poinsot") poinsot = entry.make();
  }
  REQUIRE(poinsot);
  REQUIRE(!poinsot->set_text(poinsot->find("--mass"), "2.5"));
  REQUIRE(!poinsot->set_text(poinsot->find("--method"), "rk4"));
  REQUIRE(!poinsot->set_text(poinsot->find("--project"), "on"));
  const std::vector<std::string> words{"poinsot", "--mass=2.5", "--method=rk4", "--project"};
  CHECK(rigid::explore::command_line(*poinsot) == "poinsot --mass=2.5 --method=rk4 --project");
  const auto shown = nlohmann::json::parse(rigid::explore::json_text(*poinsot));
  CHECK(shown["command"] == nlohmann::json(words));

  std::vector<std::string> argv = words;
  argv.push_back("--json");
  rigid::support::Subprocess run(
      std::string(RIGID_LAB_DIR) + "/poinsot", argv,
      {rigid::support::Redirect::pipe(), rigid::support::Redirect::null()});
  const std::string printed = run.read_to_end();
  REQUIRE(run.wait() == 0);
  CHECK(nlohmann::json::parse(printed)["command"] == nlohmann::json(argv));
}

TEST_CASE("explore: a word of the copied command is read back by a shell as itself") {
  // no input of today's labs holds a blank or a quote, but a word that did (a choice,
  // a path) must still reach the lab whole
  const std::vector<std::string> words{
      "plain", "--omega=1,2,3", "two words",   "it's",       "tab\there", "$HOME", "`ls`", "*",
      "a\nb",  "\"quoted\"",    "back\\slash", "semi;colon", "amp&",      "",      "é"};
  std::string line = "printf '%s|' ";
  for (const std::string& w : words) line += " " + rigid::explore::shell_word(w);
  rigid::support::Subprocess sh(
      "/bin/sh", {"sh", "-c", line},
      {rigid::support::Redirect::pipe(), rigid::support::Redirect::null()});
  const std::string printed = sh.read_to_end();
  REQUIRE(sh.wait() == 0);
  std::string expected;
  for (const std::string& w : words) expected += w + "|";
  CHECK(printed == expected);
  // and a safe word is left as it is
  CHECK(rigid::explore::shell_word("--omega=1,2,3") == "--omega=1,2,3");
}
