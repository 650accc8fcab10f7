#include "common/report.h"

#include <fmt/format.h>

#include <cmath>
#include <regex>

#include "rigid/format.h"

namespace rigid::lab {

namespace {

std::string format_vec2(const Eigen::Vector2d& v) {
  return fmt::format("({}, {})", format_number(v(0), 5), format_number(v(1), 5));
}

std::string format_vec3(const Eigen::Vector3d& v) {
  return fmt::format("({}, {}, {})", format_number(v(0), 5), format_number(v(1), 5),
                     format_number(v(2), 5));
}

}  // namespace

// ---- Inputs ----------------------------------------------------------------

std::string Report::figure_title(const std::string& own) const {
  // The lab's name in text markup: '_' would start a subscript.
  std::string text;
  for (char c : lab_) text += c == '_' ? std::string("\\_") : std::string(1, c);
  // The inputs that carry a symbol: "m = 1 kg, a = 1 m".
  std::string inputs;
  // An input the figure's own title states with the same value ("alpha = 10 deg") is
  // said there, not twice; one it states otherwise (the figure drawn at another theta)
  // stays, so the run's own value is always in the title.
  const auto stated = [&own](const std::string& item) {
    for (std::size_t at = own.find(item); at != std::string::npos; at = own.find(item, at + 1)) {
      const std::size_t end = at + item.size();
      const bool starts = at == 0 || own[at - 1] == ' ' || own[at - 1] == '(';
      const bool ends = end == own.size() || own[end] == ',' || own[end] == ' ' ||
                        own[end] == ';' || own[end] == ':' || own[end] == ')';
      if (starts && ends) return true;
    }
    return false;
  };
  for (const InputRule& rule : symbols_) {
    if (rule.symbol_text().empty() || !inputs_.contains(rule.key())) continue;
    const Json& value = inputs_[rule.key()];
    std::string shown;
    if (value.is_number()) {
      shown = fmt::format("{:g}", value.get<double>() + 0.0);
    } else if (value.is_array()) {
      for (const Json& part : value) {
        shown += fmt::format("{}{:g}", shown.empty() ? "(" : ", ", part.get<double>() + 0.0);
      }
      shown += ")";
    } else if (value.is_string()) {
      shown = value.get<std::string>();
    } else if (value.is_boolean()) {
      shown = value.get<bool>() ? "yes" : "no";
    } else {
      shown = value.dump();
    }
    if (rule.unit_text() == "deg") {
      shown += "\\deg";
    } else if (!rule.unit_text().empty()) {
      shown += " " + rule.unit_text();
    }
    const std::string item = rule.symbol_text() + " = " + shown;
    if (stated(item)) continue;
    inputs += (inputs.empty() ? "" : ", ") + item;
  }
  if (!inputs.empty()) text += ": " + inputs;
  if (!own.empty()) text += ": " + own;
  return text;
}

// ---- Results ----------------------------------------------------------------

void Report::section(const std::string& heading) {
  rows_.push_back({heading, "", "", "", true});
}

void Report::store(const std::string& key, Json value, bool finite, const std::string& unit,
                   const std::optional<std::string>& printed) {
  // A NaN or an overflow must never reach the output: JSON would print null.
  if (!finite) {
    // The inputs overflow it (the defaults never do); the caller names the inputs given.
    throw InputError(
        "", "the result '" + key + "' overflows or is undefined for these inputs (out of range)");
  }
  results_[key] = std::move(value);
  last_key_ = key;
  // A pure number has the unit "1", as SI writes it.
  units_[key] = unit.empty() ? "1" : unit;
  if (printed) textbook_[key] = *printed;
}

void Report::result(const std::string& key, const std::string& label, double value,
                    const std::string& unit, std::optional<std::string> printed) {
  // Adding +0.0 turns a negative zero into 0.
  store(key, value + 0.0, std::isfinite(value), unit, printed);
  rows_.push_back({label, format_number(value, 6), unit, printed.value_or("")});
  rows_.back().key = key;
}

void Report::result(const std::string& key, const std::string& label, const Eigen::Vector2d& value,
                    const std::string& unit, std::optional<std::string> printed) {
  store(key, Json::array({value(0) + 0.0, value(1) + 0.0}), value.allFinite(), unit, printed);
  rows_.push_back({label, format_vec2(value), unit, printed.value_or("")});
  rows_.back().key = key;
}

void Report::result(const std::string& key, const std::string& label, const Eigen::Vector3d& value,
                    const std::string& unit, std::optional<std::string> printed) {
  store(key, Json::array({value(0) + 0.0, value(1) + 0.0, value(2) + 0.0}), value.allFinite(), unit,
        printed);
  rows_.push_back({label, format_vec3(value), unit, printed.value_or("")});
  rows_.back().key = key;
}

void Report::result(const std::string& key, const std::string& label, const Eigen::Matrix3d& value,
                    const std::string& unit, std::optional<std::string> printed) {
  Json rows = Json::array();
  for (int i = 0; i < 3; ++i) {
    rows.push_back(Json::array({value(i, 0) + 0.0, value(i, 1) + 0.0, value(i, 2) + 0.0}));
  }
  store(key, rows, value.allFinite(), unit, printed);
  for (int i = 0; i < 3; ++i) {
    rows_.push_back({i == 0 ? label : "", format_vec3(value.row(i).transpose()), i == 0 ? unit : "",
                     i == 0 ? printed.value_or("") : ""});
  }
  rows_[rows_.size() - 3].key = key;
}

void Report::result_none(const std::string& key, const std::string& label, const std::string& unit,
                         const std::string& why) {
  results_[key] = nullptr;
  units_[key] = unit.empty() ? "1" : unit;
  rows_.push_back({label, "none", "", "(" + why + ")"});
  rows_.back().key = key;
}

void Report::result_text(const std::string& key, const std::string& label,
                         const std::string& value) {
  results_[key] = value;
  rows_.push_back({label, value, "", ""});
  rows_.back().key = key;
}

void Report::result_roundoff(const std::string& key, const std::string& label, double value,
                             double bound, const std::string& unit) {
  result(key, label, value, unit);
  if (std::abs(value) <= bound) {
    rows_.back().value = "0";
    rows_.back().remark = "(roundoff: |computed| <= " + format_number(bound, 2) + ")";
  }
}

void Report::count(const std::string& key, const std::string& label, std::size_t value) {
  results_[key] = value;
  units_[key] = "1";
  rows_.emplace_back(label, std::to_string(value), "", "");
  rows_.back().key = key;
}

void Report::answer(const std::string& text) {
  results_["answer"] = text;
  const TableRow heading("in short", "", "", "", true);
  TableRow row("answer", text, "", "");
  row.key = "answer";
  rows_.insert(rows_.begin(), {heading, row});
}

void Report::result_json(const std::string& key, double value, const std::string& unit) {
  store(key, value + 0.0, std::isfinite(value), unit, std::nullopt);
}

void Report::result_json_none(const std::string& key, const std::string& unit) {
  results_[key] = nullptr;
  units_[key] = unit.empty() ? "1" : unit;
}

void Report::count_json(const std::string& key, std::size_t value) {
  results_[key] = value;
  units_[key] = "1";
}

void Report::precise(int digits) {
  // the value the last row was made from: JSON keeps it whole
  if (rows_.empty() || !results_.contains(last_key_) || !results_[last_key_].is_number()) return;
  rows_.back().value = format_number(results_[last_key_].get<double>(), digits);
}

void Report::remark(const std::string& text) {
  if (!rows_.empty()) rows_.back().remark = text;
}

void Report::warn(const std::string& input, const std::string& text) {
  warnings_.push_back(input + ": " + text);
  notes_.push_back("warning: " + input + ": " + text);
}

void Report::alias(const std::string& old_key, const std::string& key) {
  results_[old_key] = results_.at(key);
  units_[old_key] = units_.at(key);
}

void Report::note(const std::string& text) {
  notes_.push_back(text);
}

void Report::erratum(const Erratum& e) {
  notes_.push_back("errata: " + e.where + ": the text prints \"" + e.printed + "\"; " +
                   e.correction);
  errata_.push_back(e);
}

// The text's printed values as numbers in the result's unit where the print is a
// plain number (a parenthetical after it, "0.076 (76 g)", is commentary) or a list
// of them ("(0.20 : 0.25 : 0.33)"); where it is an expression ("0.493 ma^2",
// "(pi, 2 pi, 8.168)") the value is null.
Json Report::textbook_values() const {
  static const std::regex number(R"(^\s*([-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?)\s*(\(.*\))?\s*$)");
  static const std::regex list(R"(^\s*\(([^()]*)\)\s*$)"), separator(R"(\s*[,:]\s*)");
  Json values = Json::object();
  for (const auto& [key, printed] : textbook_.items()) {
    const std::string text = printed.get<std::string>();
    std::smatch m;
    Json value = nullptr;
    if (std::regex_match(text, m, number)) {
      value = std::stod(m[1].str());
    } else if (std::regex_match(text, m, list)) {
      // "(0.20 : 0.25 : 0.33)" or "(0.4, 0.5, 0.66)": each part a plain number
      Json parts = Json::array();
      const std::string inner = m[1].str();
      std::sregex_token_iterator it(inner.begin(), inner.end(), separator, -1), end;
      for (; it != end && parts.is_array(); ++it) {
        std::smatch part;
        const std::string piece = it->str();
        if (std::regex_match(piece, part, number) && !part[4].matched) {
          parts.push_back(std::stod(part[1].str()));
        } else {
          parts = nullptr;
        }
      }
      value = parts;
    }
    values[key] = {{"value", value}, {"unit", units_.value(key, "1")}, {"printed", text}};
  }
  return values;
}

}  // namespace rigid::lab
