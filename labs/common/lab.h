// The lab layer every rigidlab program shares: its options, its human table,
// its JSON, its CSV, its figures and its errors (design.md, "The lab
// contract"). A lab declares its inputs, computes with rigid::core, reports
// results here, and hands figure descriptions to the figure set; this layer
// does all the I/O.
//
//   Inputs in;                                  // the lab's aggregate of inputs, with defaults
//   Lab lab("tire_balancing", "dynamic balancing of a wheel (sections 2.2-2.3)");
//   lab.number("--mass", in.mass, "mass m of the disk").unit("kg").positive().symbol("m");
//   return lab.run(argc, argv, [&](Lab& lab) { lab.result(...); lab.figures(draw); });
#pragma once

#include <CLI/CLI.hpp>
#include <Eigen/Core>
#include <functional>
#include <list>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace rigid::render {
class Scene3D;
class Plot2D;
}  // namespace rigid::render

namespace rigid::lab {

using Json = nlohmann::ordered_json;

/// Bad input: names the option and the rule it breaks; the lab exits with status 2.
struct UsageError : std::runtime_error {
  UsageError(const std::string& option, const std::string& rule)
      : std::runtime_error(option + ": " + rule) {}
};

/// Runs `compute`; an std::invalid_argument from core (a physics rule broken by
/// the inputs) becomes a UsageError naming `option`.
template <class Compute>
auto for_option(const std::string& option, Compute&& compute) -> decltype(compute()) {
  try {
    return compute();
  } catch (const std::invalid_argument& e) {
    throw UsageError(option, e.what());
  }
}

/// A name as a JSON key: "--tilt-deg" is "tilt_deg", "bulirsch-stoer" is "bulirsch_stoer".
std::string json_key(const std::string& name);

/// The time series written by --csv: a header and rows of numbers.
struct TimeSeries {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
};

class Lab;
/// True if a file can be created in directory `dir`: tried (a probe file made with
/// O_EXCL and removed), since permission bits do not tell (root may write anywhere by
/// them, yet not into /proc or a read-only mount).
bool can_create_in(const std::string& dir);

class FigureSet;

/// One declared option; its rule, unit and role are chained onto the declaration.
class Option {
 public:
  /// The SI unit shown in --help, the inputs and figure titles.
  Option& unit(const std::string& unit);
  /// Values must be > 0.
  Option& positive();
  /// Values must be >= 0.
  Option& non_negative();
  /// Values must lie strictly between lo and hi.
  Option& open_range(double lo, double hi);
  /// A vector option also takes one of `names` instead of its numbers (its
  /// `meaning` is added to --help); Option::word() says which was given.
  Option& words(const std::vector<std::string>& names, const std::string& meaning);
  /// The word given instead of numbers ("" if numbers or nothing were given).
  const std::string& word() const { return word_; }
  /// Values must satisfy lo <= value < hi.
  Option& range_from(double lo, double hi);
  /// A vector must not be (0, 0, 0).
  Option& nonzero();
  /// The symbol (text markup) that names this input in figure titles, e.g. "\\theta".
  Option& symbol(const std::string& markup);
  /// How to compute (method, tolerance, step, end time), not what is computed:
  /// giving it keeps "the inputs are the textbook's" true.
  Option& numerical();
  /// The default is chosen by the lab from the other inputs (`what` says how, in
  /// --help); the value is recorded among the inputs only when given.
  Option& lab_default(const std::string& what);

 private:
  friend class Lab;
  Option(Lab& lab, CLI::Option* cli, std::string key, std::string help);
  std::string broken_rule(double value, const std::string& text) const;
  void describe();

  Lab& lab_;
  CLI::Option* cli_;
  std::string key_, help_, unit_, symbol_, lab_default_;
  bool physical_ = true, nonzero_ = false;
  double lo_ = -1, hi_ = -1;
  enum class Rule {
    kFinite,
    kPositive,
    kNonNegative,
    kOpenRange,
    kRangeFrom
  } rule_ = Rule::kFinite;
  std::vector<std::string> texts_;  // a vector's components (or word) as given
  std::size_t count_ = 0;           // how many components it takes
  std::vector<std::string> words_;  // words it takes instead of numbers
  std::string word_;                // the word given, if any
  bool takes_word(const std::string& text) const;
  std::string word_list() const;
  std::function<void()> store_, record_;  // after parsing: into the lab's inputs
};

/// One lab program: declare options, then `run` parses, computes and reports.
class Lab {
 public:
  /// `name` is the executable and JSON `lab`; `title` heads the table and --help.
  Lab(std::string name, std::string title);

  /// A number in SI units; finite, and nonzero values between 1e-60 and 1e60 in
  /// magnitude (every result is a product of at most five inputs, which then
  /// neither overflows nor underflows a double).
  Option& number(const std::string& flag, double& value, const std::string& help);
  /// An angle in degrees (unit "deg"); the flag ends in "-deg".
  Option& angle_deg(const std::string& flag, double& degrees, const std::string& help);
  /// Three numbers X,Y,Z, each under the number's rules.
  Option& vector(const std::string& flag, Eigen::Vector3d& value, const std::string& help);
  /// Two numbers A,B (`type_name` shows them in --help, e.g. "I,IS"), each under the number's
  /// rules.
  Option& pair(const std::string& flag, Eigen::Vector2d& value, const std::string& type_name,
               const std::string& help);
  /// One word out of `choices`.
  Option& choice(const std::string& flag, std::string& value,
                 const std::vector<std::string>& choices, const std::string& help);
  /// A switch with no value, e.g. --project.
  Option& flag(const std::string& flag, bool& value, const std::string& help);
  /// Offer --csv FILE for this lab's time series.
  void enable_csv();
  /// Offer --animate FILE for this lab's motion, with --fps, --duration and
  /// --animation-size (animation.cpp).
  void enable_animation();

  /// True if the user gave this option on the command line.
  bool given(const std::string& flag) const;
  /// True when no physical option was given: the run is the textbook's example.
  bool textbook_inputs() const;
  /// The value the text prints, shown beside a result when the inputs are the textbook's.
  std::optional<std::string> textbook(const std::string& printed) const;
  /// Removes an input the run did not use (e.g. --mass when --inertia is given).
  void drop_input(const std::string& key);

  /// Parses the command line, runs `body`, prints the table or JSON; returns the exit status.
  int run(int argc, char** argv, const std::function<void(Lab&)>& body);

  /// A section heading in the human table.
  void section(const std::string& heading);
  /// A scalar result with its unit ("" for a pure number); `printed` is the text's value.
  void result(const std::string& key, const std::string& label, double value,
              const std::string& unit, std::optional<std::string> printed = std::nullopt);
  /// A pair of numbers (JSON: an array of two).
  void result(const std::string& key, const std::string& label, const Eigen::Vector2d& value,
              const std::string& unit, std::optional<std::string> printed = std::nullopt);
  /// A vector result.
  void result(const std::string& key, const std::string& label, const Eigen::Vector3d& value,
              const std::string& unit, std::optional<std::string> printed = std::nullopt);
  /// A matrix result (JSON: array of rows).
  void result(const std::string& key, const std::string& label, const Eigen::Matrix3d& value,
              const std::string& unit, std::optional<std::string> printed = std::nullopt);
  /// A result that is zero but for roundoff: when |value| <= `bound` the table prints 0
  /// with the bound beside it (JSON keeps the value computed); else as result().
  void result_roundoff(const std::string& key, const std::string& label, double value, double bound,
                       const std::string& unit);
  /// A warning: one line on stderr ("lab: warning: option: text") once the run has
  /// succeeded, and a note starting "warning:", for an input the run does not use.
  void warn(const std::string& option, const std::string& text);
  /// A result that does not exist for these inputs (JSON null), with the reason in the table.
  void result_none(const std::string& key, const std::string& label, const std::string& unit,
                   const std::string& why);
  /// A count (JSON: an integer).
  void count(const std::string& key, const std::string& label, std::size_t value);
  /// A text result (e.g. a method name).
  void result_text(const std::string& key, const std::string& label, const std::string& value);
  /// A JSON-only second name for a result already reported (a key renamed, kept one
  /// release under its old name; the schema marks it deprecated). Not in the table.
  void alias(const std::string& old_key, const std::string& key);
  /// A note under the table and in JSON "notes"; errata start with "errata:".
  void note(const std::string& text);

  /// The time series written by --csv (if the user asked for it).
  void series(TimeSeries s) { series_ = std::move(s); }
  /// Draws the figures if --figures DIR was given: `draw` hands each figure to the
  /// set. A drawing failure (no GL context, say) is reported on stderr and sets
  /// exit status 1; the numeric results still print.
  void figures(const std::function<void(FigureSet&)>& draw);
  /// Writes the animation if --animate FILE was given: `motion_seconds` of the motion in
  /// --duration seconds of video; `frame(t)` is the scene at motion time t in seconds, its
  /// title following the lab's name and inputs. Frames are drawn at their own times,
  /// with one camera fitted to the whole motion. `still` names the lab's figure whose
  /// scene frame(0) is, if one is (the JSON says which, and a test holds them together).
  void animate(double motion_seconds, const std::string& caption,
               const std::function<render::Scene3D(double)>& frame, const std::string& still = {});
  /// The same with a strip under the scene: `strip(t)`, a plot at motion time t drawn
  /// across the frame's lower `strip_share`, in the frame's text size.
  void animate(double motion_seconds, const std::string& caption,
               const std::function<render::Scene3D(double)>& frame,
               const std::function<render::Plot2D(double)>& strip, double strip_share,
               const std::string& still = {});
  /// Every time of the motion animate() will ask a frame for, sorted (the frames and the
  /// camera's fit): a lab that draws from an integrator samples it at exactly these.
  std::vector<double> animation_times(double motion_seconds) const;
  /// True if --animate FILE was given (what an animation needs is made only then).
  bool animating() const { return !animation_path_.empty(); }
  /// A figure's or animation's title: the lab's name and inputs, then `own` after a colon.
  std::string scene_title(const std::string& own) const;

  const std::string& name() const { return name_; }

 private:
  friend class Option;
  friend class FigureSet;
  struct Row {
    Row(std::string l, std::string v, std::string u, std::string t, bool h = false)
        : label(std::move(l)),
          value(std::move(v)),
          unit(std::move(u)),
          textbook(std::move(t)),
          heading(h) {}
    std::string label, value, unit, textbook;
    bool heading = false;
    std::string remark;  ///< printed after the unit and textbook, e.g. the roundoff bound
  };
  Option& declare(CLI::Option* cli, const std::string& flag, const std::string& help);
  /// A comma-separated list of `count` numbers; the caller sets how it is stored and recorded.
  Option& numbers(const std::string& flag, int count, const std::string& type_name,
                  const std::string& default_text, const std::string& help);
  void check_output_paths() const;
  /// The option a failure with no option of its own is blamed on: the first physical
  /// option given, else the first given at all.
  std::string blamed_option() const;
  void store(const std::string& key, Json value, bool finite, const std::string& unit,
             const std::optional<std::string>& printed);
  std::string title_inputs() const;
  void emit_table() const;
  void emit_json() const;
  void write_csv() const;
  Json textbook_values() const;

  std::string name_, title_;
  CLI::App app_;
  std::list<Option> options_;
  Json inputs_ = Json::object(), results_ = Json::object(), units_ = Json::object();
  Json textbook_ = Json::object(), captions_ = Json::object();
  std::vector<Row> rows_;
  std::vector<std::string> notes_, figures_, warnings_;
  TimeSeries series_;
  bool json_ = false, quiet_ = false, csv_enabled_ = false;
  bool figures_failed_ = false, timing_ = false;
  Json figure_seconds_ = Json::object();
  Json figure_phases_ = Json::object();
  std::string csv_path_, figures_dir_, figure_size_ = "1600x1200", figure_prefix_;
  std::vector<std::string> command_;  ///< argv as given
  // --animate and its settings (animation.cpp)
  bool animation_enabled_ = false;
  std::string animation_path_, animation_size_ = "1280x720";
  double animation_fps_ = 30.0, animation_duration_ = 10.0;
  int animation_width_ = 1280, animation_height_ = 720;
  Json animation_ = nullptr;  ///< what was written, for the JSON
  void check_animation_path() const;
  int figure_width_ = 1600, figure_height_ = 1200;
};

/// The text's printed value for a fixed example that does not depend on the inputs.
inline std::optional<std::string> printed(const std::string& value) {
  return value;
}

}  // namespace rigid::lab
