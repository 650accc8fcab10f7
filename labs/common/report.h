// What a lab says, as a plain value: its inputs as recorded, its results with
// keys, labels, units and the text's printed values, its sections, notes, errata
// and warnings, and the time series for --csv. A lab's compute() fills one; the
// writers (writers.h) print it as the table, JSON or CSV, and a live view shows it.
// A lab's own Report derives from this one and adds what its figures and its
// motion need.
#pragma once

#include <Eigen/Core>
#include <initializer_list>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/inputs.h"

namespace rigid::lab {

/// One column of a lab's CSV: its name in the header, its unit ("1" for a pure number)
/// and what it is.
struct SeriesColumn {
  std::string name;
  std::string unit;
  std::string meaning;
};

/// The table written by --csv: a header line of names, then rows of numbers, so that
/// every CSV reader takes it with no option. What the table is, and each column's unit
/// and meaning, go beside it as CSV on the Web metadata (writers.h) and into the JSON.
struct TimeSeries {
  TimeSeries() = default;
  explicit TimeSeries(std::string what) : title(std::move(what)) {}

  std::string title;
  std::vector<SeriesColumn> columns;
  std::vector<std::vector<double>> rows;

  /// Columns that share a unit and a meaning, named in order ("omega1", "omega2", ...).
  TimeSeries& add(std::initializer_list<const char*> names, const std::string& unit,
                  const std::string& meaning) {
    for (const char* name : names) columns.push_back({name, unit, meaning});
    return *this;
  }
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const SeriesColumn& c : columns) out.push_back(c.name);
    return out;
  }
};

/// What every free-body and top CSV says of its attitude columns qw, qx, qy, qz.
inline constexpr char kQuaternionConvention[] =
    "the attitude, the unit quaternion that turns body axes into space axes (Hamilton's "
    "convention, scalar first; v_space = q v_body q*), the identity at t = 0 unless the "
    "start sets it";

/// An error in the text: where (the section and equation), what the text prints, quoted,
/// and the correction with this run's numbers. docs/errata.md is made from these.
struct Erratum {
  std::string where;       ///< "section 8.1", "eq. 150", "eqs. 137-138"
  std::string printed;     ///< the text's own words or formula, as printed
  std::string correction;  ///< what is right, and the numbers that show it
};

/// One line of the human table: a heading, or a quantity with its value, unit,
/// the text's value and a remark.
struct TableRow {
  TableRow(std::string l, std::string v, std::string u, std::string t, bool h = false)
      : label(std::move(l)),
        value(std::move(v)),
        unit(std::move(u)),
        textbook(std::move(t)),
        heading(h) {}
  std::string label, value, unit, textbook;
  bool heading = false;
  std::string remark;  ///< printed after the unit and textbook, e.g. the roundoff bound
  std::string key;  ///< the result's JSON key ("" for a heading, a remark or a matrix's later rows)
};

class Report {
 public:
  Report() = default;
  /// `lab` is the lab's name, `title` its one-line description.
  Report(std::string lab, std::string title) : lab_(std::move(lab)), title_(std::move(title)) {}

  /// Checks `in` by `table`'s rules (an InputError names the first broken), then
  /// records the inputs and whether they are the textbook's.
  template <class In>
  void start(const InputTable<In>& table, const In& in) {
    check_inputs(table, in);
    inputs_ = record_inputs(table, in);
    textbook_inputs_ = lab::textbook_inputs(table, in);
    symbols_.clear();
    for (const auto& f : table.fields()) symbols_.push_back(f.rule);
  }

  const std::string& lab() const { return lab_; }
  const std::string& title() const { return title_; }

  /// True when every physical input is the textbook's.
  bool textbook_inputs() const { return textbook_inputs_; }
  /// The value the text prints, shown beside a result when the inputs are the textbook's.
  std::optional<std::string> textbook(const std::string& printed) const {
    return textbook_inputs_ ? std::optional<std::string>(printed) : std::nullopt;
  }
  /// Removes an input the run did not use (e.g. omega when the road speed sets it).
  void drop_input(const std::string& key) { inputs_.erase(key); }
  /// Records an input as the run used it (a preset's omega lent to a body of one's own,
  /// "custom" for a preset whose moments were replaced).
  void set_input(const std::string& key, Json value) { inputs_[key] = std::move(value); }
  /// The inputs recorded: JSON "inputs", the table's inputs line.
  const Json& inputs() const { return inputs_; }
  /// A figure's or animation's title: the lab's name and its inputs that carry a
  /// symbol, then `own` after a colon.
  std::string figure_title(const std::string& own) const;

  /// The answer to the section's question in words, with the numbers that decide it
  /// ("flips: first at 1.89 s, then every 3.33 s"): JSON "answer", and the table's
  /// first rows, whenever the lab says it.
  void answer(const std::string& text);
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
  /// A result that does not exist for these inputs (JSON null), with the reason in the table.
  void result_none(const std::string& key, const std::string& label, const std::string& unit,
                   const std::string& why);
  /// A count (JSON: an integer).
  void count(const std::string& key, const std::string& label, std::size_t value);
  /// A result in JSON only: the table shows it in a row's remark (remark()).
  void result_json(const std::string& key, double value, const std::string& unit);
  /// A result that does not exist, in JSON only (null): the table says why in another row.
  void result_json_none(const std::string& key, const std::string& unit);
  /// A count in JSON only.
  void count_json(const std::string& key, std::size_t value);
  /// The last row's value printed to `digits` significant digits, not 6: where the
  /// digits beyond matter (Is / I = 1.0032737, whose 0.0032737 sets the Earth's period).
  void precise(int digits);
  /// The last row's remark, printed after its unit: "(2000 evaluations, 500 steps)".
  void remark(const std::string& text);
  /// A text result (e.g. a method name).
  void result_text(const std::string& key, const std::string& label, const std::string& value);
  /// A JSON-only second name for a result already reported (a key renamed, kept one
  /// release under its old name; the schema marks it deprecated). Not in the table.
  void alias(const std::string& old_key, const std::string& key);
  /// A note under the table and in JSON "notes"; errata start with "errata:".
  void note(const std::string& text);
  /// An error in the text: a note "errata: WHERE: the text prints "PRINTED"; CORRECTION"
  /// and an entry of JSON "errata".
  void erratum(const Erratum& e);
  /// A warning about an input the run does not use: a note starting "warning:", and
  /// one line on stderr from the command line once the run has succeeded.
  void warn(const std::string& input, const std::string& text);
  /// The time series written by --csv.
  void series(TimeSeries s) { series_ = std::move(s); }

  const Json& results() const { return results_; }
  const Json& units() const { return units_; }
  /// The text's printed values, by result key.
  const Json& textbook_printed() const { return textbook_; }
  /// The text's printed values as numbers where they are plain numbers or lists of them.
  Json textbook_values() const;
  const std::vector<TableRow>& rows() const { return rows_; }
  const std::vector<std::string>& notes() const { return notes_; }
  const std::vector<std::string>& warnings() const { return warnings_; }
  const std::vector<Erratum>& errata() const { return errata_; }
  const TimeSeries& time_series() const { return series_; }

 private:
  void store(const std::string& key, Json value, bool finite, const std::string& unit,
             const std::optional<std::string>& printed);

  std::string lab_, title_;
  std::string last_key_;  ///< the result stored last, for precise()
  Json inputs_ = Json::object(), results_ = Json::object(), units_ = Json::object();
  Json textbook_ = Json::object();
  bool textbook_inputs_ = true;
  std::vector<InputRule> symbols_;  ///< the inputs' rules, for figure titles
  std::vector<TableRow> rows_;
  std::vector<std::string> notes_, warnings_;
  std::vector<Erratum> errata_;
  TimeSeries series_;
};

/// The text's printed value for a fixed example that does not depend on the inputs.
inline std::optional<std::string> printed(const std::string& value) {
  return value;
}

}  // namespace rigid::lab
