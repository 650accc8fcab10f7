// A lab held live, as a window shows it: its inputs, always a set that computes,
// changed one at a time and held to the lab's own rules (a change that breaks one
// is refused with the rule, and the last valid state stays); the report, figures
// and motion of those inputs; and the command line that reproduces them. One type
// for every lab (the explorer holds any of them), and no GL, files or windows:
// the tests drive it in-process.
//
// A lab whose whole compute can take long (every integrator compared with the exact
// motion: LabProgram::preview) is computed in two steps: at once without the slow
// part, which a view shows at the next frame, then whole on a second thread; poll()
// takes the whole report in when it is done, if the inputs are still the same.
//
//   std::unique_ptr<Session> s = make_session(poinsot::program());
//   if (std::string why = s->set(s->find("--mass"), -1.0); !why.empty()) show(why);
//   draw(s->animation()->scene(t));
#pragma once

#include <algorithm>
#include <chrono>
#include <future>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "common/program.h"

namespace rigid::lab {

/// A lab's figure as its figures() hands it over, titled as the command line titles it.
struct NamedFigure {
  std::string name, caption;
  std::variant<render::Plot2D, render::Scene3D> figure;
  bool is_scene() const { return std::holds_alternative<render::Scene3D>(figure); }
};

/// A lab's figure as a list names it, none described: its name and whether it is a scene.
struct FigureName {
  std::string name;
  bool scene = false;
};

/// The refusal of a change: the rule, as the command line words it, and the inputs it names.
struct Refusal {
  std::string message;              ///< "--mass: must be positive (got -1)"
  std::vector<std::string> inputs;  ///< the options the rule names (empty: none in particular)
};

class Session {
 public:
  /// How finely an integrated motion is sampled ahead for a live view: the motion is then
  /// integrated once through these times and from the nearest one to any other.
  static constexpr int kMotionSamples = 600;

  virtual ~Session() = default;

  virtual const std::string& name() const = 0;
  virtual const std::string& title() const = 0;
  /// Whether the lab writes a CSV (--csv: a time series, or the sweep a figure draws).
  virtual bool has_time_series() const = 0;
  /// Whether the defaults are the text's worked example (else the lab's own choice).
  virtual bool has_textbook_example() const = 0;

  /// The inputs, in the table's order.
  virtual std::size_t input_count() const = 0;
  virtual const InputRule& rule(std::size_t i) const = 0;
  /// The index of the input named `flag`; input_count() if none.
  std::size_t find(const std::string& flag) const;
  /// Input i's value in the current (valid) state; std::monostate for an optional one not given.
  virtual InputValue value(std::size_t i) const = 0;
  /// Input i's textbook value (the lab's default).
  virtual InputValue textbook_value(std::size_t i) const = 0;

  /// Sets input i and computes. Refused (the state unchanged) when the value breaks its
  /// rule, or the inputs together break one of the lab's.
  virtual std::optional<Refusal> set(std::size_t i, const InputValue& value) = 0;
  /// Sets input i from its text, as typed in a field or given on the command line
  /// (read_input), and computes; refused as set() is, or when the text is not a value.
  std::optional<Refusal> set_text(std::size_t i, const std::string& text);
  /// Back to the textbook's example.
  virtual void reset() = 0;
  /// Whether every input is the textbook's (numerical ones too).
  bool at_textbook() const;

  /// What the current inputs give.
  virtual const Report& report() const = 0;
  /// Its figures (described on first asking after a change).
  virtual const std::vector<NamedFigure>& figures() const = 0;
  /// Its figures' names, in figures()'s order, none described (FigureSink::wants).
  virtual const std::vector<FigureName>& figure_names() const = 0;
  /// Figure `name` alone, described on first asking after a change (taken from
  /// figures() where they are described), or nullptr where the lab draws none of that
  /// name for these inputs: a view shows one figure for the work of one.
  virtual const NamedFigure* figure(const std::string& name) const = 0;
  /// Whether any figure has been described since the last change (figures() or figure()):
  /// a view that shows the motion need describe none (for some labs most of a change's
  /// work), and names them by figure_names().
  virtual bool figures_described() const = 0;
  /// Its motion (made on first asking after a change), or nullptr for a lab without one.
  virtual const Animation* animation() const = 0;
  /// The body's state at any time of its motion (empty for a lab without one): what
  /// import rigidlab's r.motion().at(t) reads.
  virtual BodyMotion body_motion() const = 0;
  /// How many times what is shown has changed (a view redraws when this moves).
  virtual long generation() const = 0;
  /// How many times the inputs have changed (the whole report's coming is not one).
  virtual long inputs_generation() const = 0;

  /// Whether the whole report is still being computed (the report is the preview's).
  virtual bool pending() const = 0;
  /// Takes the whole report in if it is done; true if it was.
  virtual bool poll() = 0;
  /// Waits for the whole report (an export writes what the command line would).
  virtual void wait() = 0;
  /// Why the whole report could not be computed for the inputs shown ("" if it could):
  /// the command line refuses them, though their preview computed.
  virtual const std::string& whole_error() const = 0;

  /// A session at this one's inputs but input i set to `value`, computed as a preview
  /// (nothing slow, never whole); nullptr if that is refused. A view draws it beside
  /// this one (the exact motion beside an integrator's).
  virtual std::unique_ptr<Session> with(std::size_t i, const InputValue& value) const = 0;

  /// The lab's arguments that reproduce the current state: every input that is not the
  /// textbook's, as `--option=value` (numbers to their last digit).
  std::vector<std::string> arguments() const;
};

/// A slider's span for a number input: its rule's range, or about its textbook value
/// (logarithmic for a positive one, a decade either side).
struct SliderSpan {
  double lo = 0, hi = 1;
  bool log = false;
};
SliderSpan slider_span(const InputRule& rule, double textbook);

/// An input's value as the command line takes it: "2", "1,2,3", a word; "" for a switch.
std::string argument_text(const InputValue& value);

/// The value of `text` typed for an input of `rule` (its numbers, a word, "on"/"off" for a
/// switch; "" is no value for an optional input), or the rule the text breaks, worded as
/// the command line words it.

/// Texts given for inputs at once, by option: what a script or a notebook asks of a lab in
/// one call ({"--mass", "2"}, {"--spin-rpm", "500"}; "" for a switch that is on).
using GivenTexts = std::vector<std::pair<std::string, std::string>>;

/// The refusal of a compute() that threw when input `changed` was set: an InputError
/// names its inputs; any other rule of core's, which the lab names no input for, is
/// laid to `changed`.
Refusal refusal_of(const std::exception& e, const std::string& changed);

namespace detail {

// How the whole report is computed: on a second thread, or, in a WebAssembly page
// built without threads (which would need the server to isolate the page), at the
// next poll() on the page's one thread.
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
constexpr std::launch kWholeLaunch = std::launch::deferred;
#else
constexpr std::launch kWholeLaunch = std::launch::async;
#endif

template <class In, class Rep>
class ProgramSession final : public Session {
 public:
  explicit ProgramSession(LabProgram<In, Rep> lab) : lab_(std::move(lab)) {
    compute(In{});
    wait();
  }
  // `in` computed once and whole, on this thread (session_at()).
  struct Whole {};
  ProgramSession(LabProgram<In, Rep> lab, const In& in, Whole)
      : lab_(std::move(lab)), in_(in), whole_never_(true) {
    show(std::make_shared<const Rep>(lab_.compute(in)));
    ++inputs_generation_;
  }
  // A preview of `in`, never made whole (with()).
  ProgramSession(LabProgram<In, Rep> lab, const In& in) : lab_(std::move(lab)), whole_never_(true) {
    compute(in);
  }

  std::unique_ptr<Session> with(std::size_t i, const InputValue& value) const override {
    const InputField<In>& f = fields().at(i);
    if (!f.rule.broken(value).empty()) return nullptr;
    In next = in_;
    f.set(next, value);
    try {
      return std::make_unique<ProgramSession>(lab_, next);
    } catch (const std::exception&) {
      return nullptr;
    }
  }

  const std::string& name() const override { return lab_.name; }
  const std::string& title() const override { return lab_.title; }
  bool has_time_series() const override { return !lab_.csv.empty(); }
  bool has_textbook_example() const override { return lab_.textbook_example; }
  std::size_t input_count() const override { return fields().size(); }
  const InputRule& rule(std::size_t i) const override { return fields().at(i).rule; }
  InputValue value(std::size_t i) const override { return fields().at(i).get(in_); }
  InputValue textbook_value(std::size_t i) const override { return fields().at(i).get(In{}); }

  std::optional<Refusal> set(std::size_t i, const InputValue& value) override {
    const InputField<In>& f = fields().at(i);
    if (const std::string why = f.rule.broken(value); !why.empty()) {
      return Refusal{f.rule.flag() + ": " + why, {f.rule.flag()}};
    }
    In next = in_;
    f.set(next, value);
    try {
      compute(next);
    } catch (const std::exception& e) {
      return refusal_of(e, f.rule.flag());
    }
    return std::nullopt;
  }

  void reset() override { compute(In{}); }

  bool pending() const override { return whole_.valid(); }

  bool poll() override {
    if (!whole_.valid()) return false;
    const std::future_status status = whole_.wait_for(std::chrono::seconds(0));
    // Where there is no second thread, the whole report is computed here, after the
    // preview has been shown.
    if (status != std::future_status::ready && status != std::future_status::deferred) {
      return false;
    }
    take_whole();
    return true;
  }

  void wait() override {
    while (whole_.valid()) take_whole();
  }

  const std::string& whole_error() const override { return whole_error_; }

  const Report& report() const override { return *report_; }

  const std::vector<NamedFigure>& figures() const override {
    if (!figures_) {
      Collect sink(*report_);
      lab_.figures(*report_, sink);
      figures_ = std::move(sink.figures);
    }
    return *figures_;
  }
  bool figures_described() const override { return figures_ || !described_.empty(); }

  const std::vector<FigureName>& figure_names() const override {
    if (!figure_names_) {
      Collect sink(*report_, "");
      lab_.figures(*report_, sink);
      figure_names_ = std::move(sink.names);
    }
    return *figure_names_;
  }

  const NamedFigure* figure(const std::string& name) const override {
    if (figures_) {
      for (const NamedFigure& f : *figures_) {
        if (f.name == name) return &f;
      }
      return nullptr;
    }
    if (const auto it = described_.find(name); it != described_.end()) return &it->second;
    Collect sink(*report_, name);
    lab_.figures(*report_, sink);
    if (sink.figures.empty()) return nullptr;
    return &described_.emplace(name, std::move(sink.figures.front())).first->second;
  }

  const Animation* animation() const override {
    if (lab_.animation == nullptr) return nullptr;
    if (!animation_) {
      animation_ = lab_.animation(*report_, [](double seconds) {
        std::vector<double> times;
        for (int k = 0; k <= kMotionSamples; ++k) times.push_back(seconds * k / kMotionSamples);
        return times;
      });
    }
    return &*animation_;
  }

  BodyMotion body_motion() const override {
    return lab_.body_motion == nullptr ? BodyMotion{} : lab_.body_motion(*report_);
  }

  long generation() const override { return generation_; }
  long inputs_generation() const override { return inputs_generation_; }

 private:
  // The figures as the command line titles them: every one; with `only`, that one
  // alone; with "" none, their names listed.
  struct Collect : FigureSink {
    explicit Collect(const Report& report, std::optional<std::string> only = std::nullopt)
        : report(report), only(std::move(only)) {}
    bool wants(const std::string& name, bool scene) override {
      // listed once: a figure handed over described comes here from add() alone
      if (names.empty() || names.back().name != name) names.push_back({name, scene});
      return !only || name == *only;
    }
    void add(const std::string& name, const std::string& caption, render::Plot2D plot) override {
      if (!wants(name, false)) return;
      plot.title = report.figure_title(plot.title);
      figures.push_back({name, caption, std::move(plot)});
    }
    void add(const std::string& name, const std::string& caption, render::Scene3D scene) override {
      if (!wants(name, true)) return;
      scene.title = report.figure_title(scene.title);
      figures.push_back({name, caption, std::move(scene)});
    }
    const Report& report;
    std::optional<std::string> only;
    std::vector<FigureName> names;
    std::vector<NamedFigure> figures;
  };

  const std::vector<InputField<In>>& fields() const { return lab_.inputs.fields(); }

  // Computes `next` (its preview, if the lab has one, and the whole on a second thread);
  // only if that succeeds does it become the state.
  void compute(const In& next) {
    In quick = next;
    if (lab_.preview != nullptr) lab_.preview(quick);
    auto report = std::make_shared<Rep>(lab_.compute(quick));
    in_ = next;
    ++inputs_generation_;
    show(std::move(report));
    whole_error_.clear();
    if (lab_.preview != nullptr && !whole_never_ && !whole_.valid()) start_whole();
  }

  void show(std::shared_ptr<const Rep> report) {
    report_ = std::move(report);
    figures_.reset();
    figure_names_.reset();
    described_.clear();
    animation_.reset();
    ++generation_;
  }

  void start_whole() {
    whole_in_ = in_;
    whole_ = std::async(kWholeLaunch, [compute = lab_.compute, in = in_] {
      return std::make_shared<const Rep>(compute(in));
    });
  }

  // Waits for the whole report under way and takes it if its inputs are still the
  // state's; else starts the whole report of the state's.
  void take_whole() {
    std::shared_ptr<const Rep> whole;
    std::string error;
    try {
      whole = whole_.get();
    } catch (const std::exception& e) {
      error = e.what();
    }
    if (!same_inputs(whole_in_, in_)) {
      start_whole();
      return;
    }
    if (whole) {
      show(std::move(whole));
    } else {
      whole_error_ = error;
    }
  }

  bool same_inputs(const In& a, const In& b) const {
    for (const InputField<In>& f : fields()) {
      if (!(f.get(a) == f.get(b))) return false;
    }
    return true;
  }

  LabProgram<In, Rep> lab_;
  In in_{};
  std::shared_ptr<const Rep> report_;
  mutable std::optional<std::vector<NamedFigure>> figures_;
  mutable std::optional<std::vector<FigureName>> figure_names_;
  mutable std::map<std::string, NamedFigure> described_;  // figure() asked one at a time
  mutable std::optional<Animation> animation_;
  long generation_ = 0, inputs_generation_ = 0;
  bool whole_never_ = false;
  std::future<std::shared_ptr<const Rep>> whole_;  // the whole report, under way
  In whole_in_{};
  std::string whole_error_;
};

}  // namespace detail

/// A session of `lab`, at the textbook's example.
template <class In, class Rep>
std::unique_ptr<Session> make_session(LabProgram<In, Rep> lab) {
  return std::make_unique<detail::ProgramSession<In, Rep>>(std::move(lab));
}

/// A session of `lab` at the textbook's inputs but for `given`, as the command line takes
/// them: each text read by the one reader (read_input), an option given twice or not the
/// lab's refused, the pairings checked among the options given; then computed once and
/// whole (no preview, no second thread). What a script or a notebook asks in one call.
template <class In, class Rep>
std::variant<std::unique_ptr<Session>, Refusal> session_at(LabProgram<In, Rep> lab,
                                                           const GivenTexts& given) {
  In in{};
  std::vector<std::string> flags;
  for (const auto& [flag, text] : given) {
    const InputField<In>* f = lab.inputs.find(flag);
    if (f == nullptr) return Refusal{flag + ": not an input of " + lab.name, {}};
    if (std::find(flags.begin(), flags.end(), flag) != flags.end()) {
      return Refusal{flag + ": given twice", {flag}};
    }
    flags.push_back(flag);
    const auto read = read_input(f->rule, text);
    if (const auto* why = std::get_if<std::string>(&read))
      return Refusal{flag + ": " + *why, {flag}};
    f->set(in, std::get<InputValue>(read));
  }
  std::vector<const InputRule*> rules;
  for (const InputField<In>& f : lab.inputs.fields()) rules.push_back(&f.rule);
  const auto given_flag = [&](const std::string& flag) {
    return std::find(flags.begin(), flags.end(), flag) != flags.end();
  };
  try {
    check_pairings(rules, given_flag);
    using Made = detail::ProgramSession<In, Rep>;
    return std::make_unique<Made>(std::move(lab), in, typename Made::Whole{});
  } catch (const std::exception& e) {
    std::vector<std::string> named;
    if (const auto* input = dynamic_cast<const InputError*>(&e)) {
      named = input->joint.empty() ? std::vector<std::string>{input->input} : input->joint;
    }
    return Refusal{refusal_message(e, rules, given_flag), named};
  }
}

}  // namespace rigid::lab
