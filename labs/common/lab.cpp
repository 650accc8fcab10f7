#include "lab.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <list>
#include <sstream>

namespace rigid::lab {
namespace fs = std::filesystem;
namespace {

// Option "--tilt-deg" is JSON input key "tilt_deg".
std::string key_of(const std::string& flag) {
  std::string key = flag.substr(flag.find_first_not_of('-'));
  for (char& c : key) {
    if (c == '-') c = '_';
  }
  return key;
}

// Parses a whole string as one double; nullopt if anything is left over.
std::optional<double> parse_number(const std::string& text) {
  if (text.empty()) return std::nullopt;
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(begin, &end);
  if (end == begin || *end != '\0') return std::nullopt;
  return value;
}

constexpr double kSmallest = 1e-60, kLargest = 1e60;

// The rule a number breaks, or "" when it is acceptable.
std::string number_rule(const std::string& text, Accept accept) {
  const auto value = parse_number(text);
  if (!value) return "must be a number (got '" + text + "')";
  if (!std::isfinite(*value)) return "must be finite (got '" + text + "')";
  if (accept == Accept::Positive && !(*value > 0.0)) return "must be positive (got " + text + ")";
  if (accept == Accept::NonNegative && *value < 0.0) {
    return "must not be negative (got " + text + ")";
  }
  // Every result is a product of at most five inputs (m a^2 omega^2, say); inside
  // this range no product overflows or underflows a double.
  const double magnitude = std::abs(*value);
  if (magnitude != 0.0 && (magnitude < kSmallest || magnitude > kLargest)) {
    return std::string(accept == Accept::Positive ? "must be between 1e-60 and 1e60"
                                                  : "must be 0 or between 1e-60 and 1e60 in magnitude") +
           " (got " + text + ")";
  }
  return "";
}

std::vector<std::string> split(const std::string& text, char by) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  std::string part;
  while (std::getline(stream, part, by)) parts.push_back(part);
  if (!text.empty() && text.back() == by) parts.emplace_back();
  return parts;
}

std::string vec3_rule(const std::string& text, Accept accept) {
  const auto parts = split(text, ',');
  if (parts.size() != 3) return "must be three comma-separated numbers X,Y,Z (got '" + text + "')";
  for (const auto& part : parts) {
    const std::string rule = number_rule(part, accept);
    if (!rule.empty()) return "each component " + rule;
  }
  return "";
}

// Adding +0.0 prints a negative zero as 0.
std::string format_number(double value) {
  return fmt::format("{:.6g}", value + 0.0);
}

std::string format_vec3(const Eigen::Vector3d& v) {
  return fmt::format("({:.5g}, {:.5g}, {:.5g})", v(0) + 0.0, v(1) + 0.0, v(2) + 0.0);
}

// Storage for string-valued options that are converted after parsing.
std::list<std::string>& option_strings() {
  static std::list<std::string> strings;
  return strings;
}

}  // namespace

void write_file_atomically(const std::string& path, const std::string& text,
                           const std::string& option) {
  const std::string temporary = path + ".tmp-" + std::to_string(::getpid());
  {
    std::ofstream out(temporary, std::ios::binary);
    out << text;
    out.close();
    if (!out) {
      std::remove(temporary.c_str());
      throw UsageError(option, "cannot write '" + path + "'");
    }
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw UsageError(option, "cannot write '" + path + "': " + reason);
  }
}

Lab::Lab(std::string name, std::string title)
    : name_(std::move(name)), title_(std::move(title)), app_(title_, name_) {
  app_.add_flag("--json", json_, "print one JSON object on stdout instead of the table");
  app_.add_flag("--quiet", quiet_, "print no table (files are still written)");
  app_.add_flag("--timing", timing_, "with --json: the wall time of each figure, for bench/");
  app_.add_option("--figures", figures_dir_, "write this lab's PNG figures into DIR")
      ->type_name("DIR");
  app_.add_option("--figure-size", figure_size_, "figure size in pixels")
      ->type_name("WxH")
      ->capture_default_str()
      ->check(CLI::Validator(
          [this](std::string& text) -> std::string {
            const auto parts = split(text, 'x');
            const auto w = parts.size() == 2 ? parse_number(parts[0]) : std::nullopt;
            const auto h = parts.size() == 2 ? parse_number(parts[1]) : std::nullopt;
            // The figure style is laid out for 800x600 and up; 8192 bounds memory.
            if (!w || !h || *w != std::floor(*w) || *h != std::floor(*h) || *w < 800 || *h < 600 ||
                *w > 8192 || *h > 8192) {
              return "must be WxH with 800 <= W <= 8192 and 600 <= H <= 8192 (got '" + text + "')";
            }
            figure_width_ = static_cast<int>(*w);
            figure_height_ = static_cast<int>(*h);
            return "";
          },
          ""));
}

void Lab::option(const std::string& flag, double& value, const std::string& unit,
                 const std::string& help, Accept accept, bool show_default) {
  CLI::Option* option = app_.add_option(flag, value, help + (unit.empty() ? "" : " [" + unit + "]"));
  option->type_name("NUMBER");
  if (show_default) option->capture_default_str();
  option->check(
          CLI::Validator([accept](std::string& text) { return number_rule(text, accept); }, ""));
  const std::string key = key_of(flag);
  // An option whose default means "chosen by the lab" is recorded only when given.
  record_inputs_.push_back([this, key, flag, show_default, &value] {
    if (show_default || given(flag)) inputs_[key] = value;
  });
}

void Lab::option_deg(const std::string& flag, double& degrees, double lo, double hi,
                     const std::string& help) {
  const std::string range = fmt::format("must be between {} and {} degrees, exclusive", lo, hi);
  app_.add_option(flag, degrees, help + " [deg]")
      ->type_name("DEG")
      ->capture_default_str()
      ->check(CLI::Validator(
          [lo, hi, range](std::string& text) -> std::string {
            const std::string rule = number_rule(text, Accept::Finite);
            if (!rule.empty()) return rule;
            const double value = *parse_number(text);
            return (value > lo && value < hi) ? "" : range + " (got " + text + ")";
          },
          ""));
  const std::string key = key_of(flag);
  record_inputs_.push_back([this, key, &degrees] { inputs_[key] = degrees; });
}

void Lab::option_vec3(const std::string& flag, Eigen::Vector3d& value, const std::string& unit,
                      const std::string& help, Accept accept, bool nonzero, bool show_default) {
  std::string& text =
      option_strings().emplace_back(fmt::format("{},{},{}", value(0), value(1), value(2)));
  CLI::Option* option = app_.add_option(flag, text, help + (unit.empty() ? "" : " [" + unit + "]"));
  option->type_name("X,Y,Z");
  if (show_default) option->capture_default_str();
  option
      ->check(CLI::Validator(
          [accept, nonzero](std::string& s) -> std::string {
            std::string rule = vec3_rule(s, accept);
            if (rule.empty() && nonzero) {
              const auto parts = split(s, ',');
              bool all_zero = true;
              for (const auto& part : parts) all_zero = all_zero && *parse_number(part) == 0.0;
              if (all_zero) rule = "must not be the zero vector";
            }
            return rule;
          },
          ""));
  const std::string key = key_of(flag);
  finish_parsing_.push_back([&text, &value] {
    const auto parts = split(text, ',');
    for (int i = 0; i < 3; ++i) value(i) = *parse_number(parts[static_cast<size_t>(i)]);
  });
  // An option whose default is unused appears in the inputs only when given.
  record_inputs_.push_back([this, key, flag, show_default, &value] {
    if (show_default || given(flag)) inputs_[key] = Json::array({value(0), value(1), value(2)});
  });
}

void Lab::option_choice(const std::string& flag, std::string& value,
                        const std::vector<std::string>& choices, const std::string& help) {
  std::string names;
  for (const auto& choice : choices) names += (names.empty() ? "" : "|") + choice;
  app_.add_option(flag, value, help + " (" + names + ")")
      ->type_name("WORD")
      ->capture_default_str()
      ->check(CLI::Validator(
          [choices, names](std::string& text) -> std::string {
            for (const auto& choice : choices) {
              if (text == choice) return "";
            }
            return "must be one of " + names + " (got '" + text + "')";
          },
          ""));
  const std::string key = key_of(flag);
  record_inputs_.push_back([this, key, &value] { inputs_[key] = value; });
}

void Lab::flag(const std::string& flag, bool& value, const std::string& help) {
  app_.add_flag(flag, value, help);
  const std::string key = key_of(flag);
  record_inputs_.push_back([this, key, &value] { inputs_[key] = value; });
}

void Lab::drop_input(const std::string& key) { inputs_.erase(key); }

bool Lab::given(const std::string& flag) const {
  return app_.count(flag) > 0;
}

void Lab::enable_csv() {
  csv_enabled_ = true;
  app_.add_option("--csv", csv_path_, "write the lab's time series to FILE as CSV")
      ->type_name("FILE");
}

void Lab::section(const std::string& heading) {
  rows_.push_back({heading, "", "", "", true});
}

void Lab::store(const std::string& key, Json value, bool finite,
                const std::optional<std::string>& textbook) {
  // A NaN or an overflow must never reach the output: JSON would print null.
  if (!finite) throw std::domain_error("result '" + key + "' is not finite for these inputs");
  results_[key] = std::move(value);
  if (textbook) textbook_[key] = *textbook;
}

void Lab::result(const std::string& key, const std::string& label, double value,
                 const std::string& unit, std::optional<std::string> textbook) {
  store(key, value + 0.0, std::isfinite(value), textbook);
  rows_.push_back({label, format_number(value), unit, textbook.value_or(std::string())});
}

void Lab::result(const std::string& key, const std::string& label, const Eigen::Vector3d& value,
                 const std::string& unit, std::optional<std::string> textbook) {
  // Adding +0.0 turns a negative zero into 0 in the JSON too.
  store(key, Json::array({value(0) + 0.0, value(1) + 0.0, value(2) + 0.0}), value.allFinite(),
        textbook);
  rows_.push_back({label, format_vec3(value), unit, textbook.value_or(std::string())});
}

void Lab::result(const std::string& key, const std::string& label, const Eigen::Matrix3d& value,
                 const std::string& unit, std::optional<std::string> textbook) {
  Json rows = Json::array();
  for (int i = 0; i < 3; ++i) {
    rows.push_back(Json::array({value(i, 0) + 0.0, value(i, 1) + 0.0, value(i, 2) + 0.0}));
  }
  store(key, rows, value.allFinite(), textbook);
  for (int i = 0; i < 3; ++i) {
    rows_.push_back({i == 0 ? label : "", format_vec3(value.row(i).transpose()),
                     i == 0 ? unit : "", i == 0 ? textbook.value_or("") : ""});
  }
}

void Lab::result_none(const std::string& key, const std::string& label,
                      const std::string& why) {
  results_[key] = nullptr;
  rows_.push_back({label, "none", "", "(" + why + ")"});
}

void Lab::result_text(const std::string& key, const std::string& label, const std::string& value) {
  results_[key] = value;
  rows_.push_back({label, value, "", ""});
}

void Lab::note(const std::string& text) {
  notes_.push_back(text);
}

void Lab::figure(const std::string& what,
                 const std::function<void(const std::string& path)>& save) {
  const std::string file = name_ + "_" + what + ".png";
  const fs::path path = fs::path(figures_dir_) / file;
  if (fs::is_directory(path)) {
    throw UsageError("--figures", "'" + path.string() + "' is a directory, not a figure");
  }
  const auto start = std::chrono::steady_clock::now();
  save(path.string());
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
  figures_.push_back(file);
  figure_seconds_[file] = elapsed.count();
}

std::string Lab::figure_title(const std::string& detail) const {
  std::string escaped;
  for (char c : name_) escaped += c == '_' ? std::string("\\_") : std::string(1, c);
  return escaped + ": " + detail;
}

void Lab::figures(const std::function<void(Lab&)>& draw) {
  if (!figures_requested()) return;
  std::error_code error;
  fs::create_directories(figures_dir_, error);
  if (error) {
    throw UsageError("--figures", "cannot create directory '" + figures_dir_ + "': " +
                                      error.message());
  }
  try {
    draw(*this);
  } catch (const UsageError&) {
    throw;
  } catch (const std::exception& e) {
    figures_failed_ = true;
    std::cerr << name_ << ": error: --figures: " << e.what() << '\n';
  }
}

void Lab::check_figures_directory() const {
  // Nothing is created before the lab has computed its results: find the
  // nearest existing ancestor and check that it can be written.
  fs::path dir = fs::absolute(figures_dir_);
  while (!fs::exists(dir) && dir.has_parent_path() && dir != dir.parent_path()) {
    dir = dir.parent_path();
  }
  if (!fs::is_directory(dir) || ::access(dir.c_str(), W_OK | X_OK) != 0) {
    throw UsageError("--figures", "cannot create or write directory '" + figures_dir_ + "'");
  }
}

int Lab::run(int argc, char** argv, const std::function<void(Lab&)>& body) {
  try {
    try {
      app_.allow_extras();
      app_.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
      return app_.exit(e);
    } catch (const CLI::ParseError& e) {
      throw std::invalid_argument(e.what());
    }
    // The first word CLI11 could not place names the mistake.
    if (const auto extras = app_.remaining(); !extras.empty()) {
      const std::string& word = extras.front();
      if (word.rfind("-", 0) == 0) throw UsageError(word, "unknown option (see --help)");
      throw UsageError(word, "unexpected argument (options take the form --name VALUE)");
    }
    for (auto& finish : finish_parsing_) finish();
    for (auto& record : record_inputs_) record();
    if (app_.count("--figures") > 0 && figures_dir_.empty()) {
      throw UsageError("--figures", "needs a directory name");
    }
    if (figures_requested()) check_figures_directory();
    if (csv_enabled_ && app_.count("--csv") > 0) {
      if (csv_path_.empty()) throw UsageError("--csv", "needs a file name");
      if (fs::is_directory(csv_path_)) {
        throw UsageError("--csv", "'" + csv_path_ + "' is a directory, not a file");
      }
      const fs::path parent = fs::absolute(csv_path_).parent_path();
      if (!fs::is_directory(parent) || ::access(parent.c_str(), W_OK) != 0) {
        throw UsageError("--csv", "cannot write into directory '" + parent.string() + "'");
      }
    }
    body(*this);
    if (!csv_path_.empty()) write_csv();
  } catch (const std::exception& e) {
    std::cerr << name_ << ": error: " << e.what() << '\n';
    return 2;
  }
  if (json_) {
    emit_json();
  } else if (!quiet_) {
    emit_table();
  }
  return figures_failed_ ? 1 : 0;
}

void Lab::emit_table() const {
  std::cout << name_ << " - " << title_ << "\n";
  std::string inputs;
  const auto text_of = [](const Json& value) -> std::string {
    if (value.is_string()) return value.get<std::string>();
    if (value.is_number()) return format_number(value.get<double>());
    if (value.is_array() && value.size() == 3) {
      return format_vec3({value[0].get<double>(), value[1].get<double>(), value[2].get<double>()});
    }
    return value.dump();
  };
  for (const auto& [key, value] : inputs_.items()) {
    inputs += (inputs.empty() ? "" : ", ") + key + " = " + text_of(value);
  }
  std::cout << "inputs: " << inputs << "\n";
  size_t label_width = 8, value_width = 5, unit_width = 4;
  for (const auto& row : rows_) {
    if (row.heading) continue;
    label_width = std::max(label_width, row.label.size());
    value_width = std::max(value_width, row.value.size());
    unit_width = std::max(unit_width, row.unit.size());
  }
  bool any_textbook = false;
  for (const auto& row : rows_) any_textbook = any_textbook || !row.textbook.empty();
  std::cout << "\n"
            << fmt::format("{:<{}}  {:<{}}  {:<{}}{}", "quantity", label_width, "value",
                           value_width, "unit", unit_width, any_textbook ? "  textbook" : "")
            << "\n";
  for (const auto& row : rows_) {
    if (row.heading) {
      std::cout << "\n[" << row.label << "]\n";
      continue;
    }
    std::string line = fmt::format("{:<{}}  {:<{}}  {:<{}}", row.label, label_width, row.value,
                                   value_width, row.unit, unit_width);
    if (!row.textbook.empty()) line += "  " + row.textbook;
    while (!line.empty() && line.back() == ' ') line.pop_back();
    std::cout << line << "\n";
  }
  if (!notes_.empty()) {
    std::cout << "\nnotes:\n";
    for (const auto& note : notes_) std::cout << "  - " << note << "\n";
  }
  if (!figures_.empty()) {
    std::cout << "\nfigures in " << figures_dir_ << ":\n";
    for (const auto& figure : figures_) std::cout << "  " << figure << "\n";
  }
}

void Lab::emit_json() const {
  Json out;
  out["lab"] = name_;
  out["inputs"] = inputs_;
  out["results"] = results_;
  out["figures"] = figures_;
  if (timing_) out["timing"] = {{"figure_seconds", figure_seconds_}};
  out["textbook"] = textbook_;
  out["notes"] = notes_;
  std::cout << out.dump(2) << "\n";
}

void Lab::write_csv() const {
  if (series_.columns.empty()) return;
  std::string text;
  for (size_t i = 0; i < series_.columns.size(); ++i) {
    text += (i ? "," : "") + series_.columns[i];
  }
  text += "\n";
  for (const auto& row : series_.rows) {
    for (size_t i = 0; i < row.size(); ++i) text += fmt::format("{}{:.17g}", i ? "," : "", row[i]);
    text += "\n";
  }
  write_file_atomically(csv_path_, text, "--csv");
}

}  // namespace rigid::lab
