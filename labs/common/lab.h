// The lab layer every rigidlab program shares: its options, its human table,
// its JSON, its CSV, its figure directory and its errors (design.md, "The lab
// contract"). A lab declares options, computes with rigid::core, reports
// results here, and hands figures to rigid::render; this layer does the I/O.
#pragma once

#include <CLI/CLI.hpp>
#include <Eigen/Dense>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace rigid::lab {

using Json = nlohmann::ordered_json;

/// Bad input: names the option and the rule it breaks; the lab exits with status 2.
struct UsageError : std::runtime_error {
  UsageError(const std::string& option, const std::string& rule)
      : std::runtime_error(option + ": " + rule) {}
};

/// Which values a numeric option accepts.
enum class Accept { Finite, Positive, NonNegative };

/// Time series for --csv: a header and rows of numbers.
struct Series {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
};

/// One lab program: declare options, then `run` parses, computes and reports.
class Lab {
 public:
  /// `name` is the executable and JSON `lab`; `title` heads the table and --help.
  Lab(std::string name, std::string title);

  /// A number in SI units with its default; `unit` shows in --help and the inputs.
  /// Nonzero values must lie between 1e-60 and 1e60 in magnitude. With
  /// `show_default` off the default is the lab's to choose (say so in `help`).
  void option(const std::string& flag, double& value, const std::string& unit,
              const std::string& help, Accept accept = Accept::Positive,
              bool show_default = true);
  /// An angle in degrees that must lie in the open interval (lo, hi).
  void option_deg(const std::string& flag, double& degrees, double lo, double hi,
                  const std::string& help);
  /// Three comma-separated finite numbers, e.g. --axis 0.8,0.6,0; `show_default`
  /// off for an option whose default is not used unless it is given.
  void option_vec3(const std::string& flag, Eigen::Vector3d& value, const std::string& unit,
                   const std::string& help, Accept accept = Accept::Finite, bool nonzero = false,
                   bool show_default = true);
  /// One word out of `choices`.
  void option_choice(const std::string& flag, std::string& value,
                     const std::vector<std::string>& choices, const std::string& help);
  /// A switch with no value, e.g. --project.
  void flag(const std::string& flag, bool& value, const std::string& help);
  /// Removes an input the run did not use (e.g. --mass when --inertia is given).
  void drop_input(const std::string& key);
  /// True if the user gave this option on the command line.
  bool given(const std::string& flag) const;
  /// Offer --csv FILE for this lab's time series.
  void enable_csv();

  /// Parses the command line, runs `body`, prints the table or JSON; returns the exit status.
  int run(int argc, char** argv, const std::function<void(Lab&)>& body);

  /// A section heading in the human table.
  void section(const std::string& heading);
  /// A scalar result; `textbook` is the value the seed prints for these inputs,
  /// shown beside it (pass it only when the inputs are the textbook's).
  void result(const std::string& key, const std::string& label, double value,
              const std::string& unit, std::optional<std::string> textbook = std::nullopt);
  /// A vector result.
  void result(const std::string& key, const std::string& label, const Eigen::Vector3d& value,
              const std::string& unit, std::optional<std::string> textbook = std::nullopt);
  /// A matrix result (JSON: array of rows).
  void result(const std::string& key, const std::string& label, const Eigen::Matrix3d& value,
              const std::string& unit, std::optional<std::string> textbook = std::nullopt);
  /// A result that does not exist for these inputs (JSON null), with the reason in the table.
  void result_none(const std::string& key, const std::string& label, const std::string& why);
  /// A text result (e.g. a method name).
  void result_text(const std::string& key, const std::string& label, const std::string& value);
  /// A note under the table and in JSON "notes"; errata start with "errata:".
  void note(const std::string& text);

  /// The time series written by --csv (if the user asked for it).
  void series(Series s) { series_ = std::move(s); }
  /// True if --figures DIR was given; then `figure` writes each PNG.
  bool figures_requested() const { return !figures_dir_.empty(); }
  /// Writes figure `<lab>_<what>.png`: `save` gets the full path; the figure is
  /// listed in the JSON "figures" and, with --timing, its wall time in "timing".
  void figure(const std::string& what, const std::function<void(const std::string& path)>& save);
  /// Runs `draw` if --figures was given; a failure there (no GL context, say) is
  /// reported on stderr and sets exit status 1, but the numeric results still print.
  void figures(const std::function<void(Lab&)>& draw);
  /// Requested figure size in pixels (--figure-size WxH, default 1600x1200).
  int figure_width() const { return figure_width_; }
  int figure_height() const { return figure_height_; }
  const std::string& name() const { return name_; }
  /// A figure title "<lab>: <detail>" in the renderer's markup (the lab's name escaped).
  std::string figure_title(const std::string& detail) const;

 private:
  struct Row {
    std::string label, value, unit, textbook;
    bool heading = false;
  };
  void check_figures_directory() const;
  void store(const std::string& key, Json value, bool finite,
             const std::optional<std::string>& textbook);
  void emit_table() const;
  void emit_json() const;
  void write_csv() const;

  std::string name_, title_;
  CLI::App app_;
  Json inputs_ = Json::object();
  Json results_ = Json::object();
  Json textbook_ = Json::object();
  std::vector<std::function<void()>> record_inputs_;
  std::vector<std::function<void()>> finish_parsing_;
  std::vector<Row> rows_;
  std::vector<std::string> notes_;
  std::vector<std::string> figures_;
  Series series_;
  bool json_ = false, quiet_ = false, csv_enabled_ = false;
  bool figures_failed_ = false, timing_ = false;
  Json figure_seconds_ = Json::object();
  std::string csv_path_, figures_dir_, figure_size_ = "1600x1200";
  int figure_width_ = 1600, figure_height_ = 1200;
};

/// The textbook's printed value, when `applies` (the inputs are the text's).
inline std::optional<std::string> textbook_if(bool applies, const std::string& printed) {
  return applies ? std::optional<std::string>(printed) : std::nullopt;
}

/// Writes `text` to `path` through a temporary file renamed into place.
void write_file_atomically(const std::string& path, const std::string& text,
                           const std::string& option);

}  // namespace rigid::lab
