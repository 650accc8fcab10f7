#include "lab.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <regex>

#include "rigid/format.h"
#include "rigid/render/atomic_file.h"

namespace rigid::lab {
namespace fs = std::filesystem;
namespace {

// Every result is a product of at most five inputs (m a^2 omega^2, say); inside
// this range of magnitudes no such product overflows or underflows a double.
constexpr double kSmallest = 1e-60, kLargest = 1e60;

// A message as one printable line: user input may carry a line break or an escape
// sequence, which would forge a second error line or colour the terminal.
std::string escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\n') {
      out += "\\n";
    } else if (u < 0x20 || u == 0x7f) {
      out += fmt::format("\\x{:02x}", u);
    } else {
      out += c;
    }
  }
  return out;
}

// The longest file name written, leaving room for the temporary's suffix (NAME_MAX 255).
constexpr std::size_t kMaxFileName = 224;

std::string format_vec2(const Eigen::Vector2d& v) {
  return fmt::format("({}, {})", format_number(v(0), 5), format_number(v(1), 5));
}

std::string format_vec3(const Eigen::Vector3d& v) {
  return fmt::format("({}, {}, {})", format_number(v(0), 5), format_number(v(1), 5),
                     format_number(v(2), 5));
}

// A JSON input or result as the table shows it.
std::string text_of(const Json& value) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_boolean()) return value.get<bool>() ? "yes" : "no";
  if (value.is_number()) return format_number(value.get<double>(), 6);
  if (value.is_array() && value.size() == 3 && value[0].is_number()) {
    return format_vec3({value[0].get<double>(), value[1].get<double>(), value[2].get<double>()});
  }
  if (value.is_array() && value.size() == 2 && value[0].is_number()) {
    return format_vec2({value[0].get<double>(), value[1].get<double>()});
  }
  return value.dump();
}

}  // namespace

std::string json_key(const std::string& name) {
  std::string key = name.substr(name.find_first_not_of('-'));
  for (char& c : key) {
    if (c == '-') c = '_';
  }
  return key;
}

// ---- Options ----------------------------------------------------------------

Option::Option(Lab& lab, CLI::Option* cli, std::string key, std::string help)
    : lab_(lab), cli_(cli), key_(std::move(key)), help_(std::move(help)) {
  if (cli_) describe();
}

void Option::describe() {
  std::string text = help_;
  if (!unit_.empty()) text += " [" + unit_ + "]";
  if (!lab_default_.empty()) text += " (default: " + lab_default_ + ")";
  cli_->description(text);
}

Option& Option::unit(const std::string& unit) {
  unit_ = unit;
  describe();
  return *this;
}
Option& Option::positive() {
  rule_ = Rule::kPositive;
  return *this;
}
Option& Option::non_negative() {
  rule_ = Rule::kNonNegative;
  return *this;
}
Option& Option::open_range(double lo, double hi) {
  rule_ = Rule::kOpenRange;
  lo_ = lo;
  hi_ = hi;
  return *this;
}
Option& Option::range_from(double lo, double hi) {
  rule_ = Rule::kRangeFrom;
  lo_ = lo;
  hi_ = hi;
  return *this;
}
Option& Option::nonzero() {
  nonzero_ = true;
  return *this;
}
Option& Option::symbol(const std::string& markup) {
  symbol_ = markup;
  return *this;
}
Option& Option::numerical() {
  physical_ = false;
  return *this;
}
Option& Option::lab_default(const std::string& what) {
  lab_default_ = what;
  cli_->default_str("");
  describe();
  return *this;
}

// The rule a parsed number breaks, as CLI11's validation message ("" if none).
std::string Option::broken_rule(double value, const std::string& text) const {
  const auto fail = [&](const std::string& rule) { return rule + " (got " + text + ")"; };
  if (!std::isfinite(value)) return fail("must be finite");
  switch (rule_) {
    case Rule::kPositive:
      if (!(value > 0.0)) return fail("must be positive");
      break;
    case Rule::kNonNegative:
      if (value < 0.0) return fail("must not be negative");
      break;
    case Rule::kOpenRange:
      if (!(value > lo_ && value < hi_)) {
        return fail(fmt::format("must be between {} and {}{}, exclusive", lo_, hi_,
                                unit_.empty() ? "" : " " + unit_));
      }
      break;
    case Rule::kRangeFrom:
      if (!(value >= lo_ && value < hi_)) {
        return fail(fmt::format("must be at least {} and below {}{}", lo_, hi_,
                                unit_.empty() ? "" : " " + unit_));
      }
      break;
    case Rule::kFinite:
      break;
  }
  const double magnitude = std::abs(value);
  if (rule_ != Rule::kOpenRange && magnitude != 0.0 &&
      (magnitude < kSmallest || magnitude > kLargest)) {
    return fail(rule_ == Rule::kPositive ? "must be between 1e-60 and 1e60"
                                         : "must be 0 or between 1e-60 and 1e60 in magnitude");
  }
  return "";
}

Lab::Lab(std::string name, std::string title)
    : name_(std::move(name)), title_(std::move(title)), app_(title_, name_) {
  app_.add_flag("--json", json_, "print one JSON object on stdout instead of the table");
  app_.add_flag("--quiet", quiet_, "print no table (files are still written)");
  app_.add_flag("--timing", timing_,
                "with --json: the wall time of each figure and where it went, for bench/");
  app_.add_option("--figures", figures_dir_, "write this lab's PNG figures into DIR")
      ->type_name("DIR");
  // The figure style is laid out for 800x600 and up; 8192 bounds memory.
  app_.add_option("--figure-size", figure_size_, "figure size in pixels, 800x600 to 8192x8192")
      ->type_name("WxH")
      ->capture_default_str()
      ->check(CLI::Validator(
          [this](std::string& text) -> std::string {
            int w = 0, h = 0;
            char x = 0, extra = 0;
            const int read = std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra);
            // 1920x1080 or 1920X1080
            if (read != 3 || (x != 'x' && x != 'X') || w < 800 || h < 600 || w > 8192 || h > 8192) {
              return "must be WxH with 800 <= W <= 8192 and 600 <= H <= 8192 (got '" + text + "')";
            }
            figure_width_ = w;
            figure_height_ = h;
            return "";
          },
          ""));
  app_.add_option("--figure-prefix", figure_prefix_,
                  "prefix of the figure files, e.g. 'book-' for book-poinsot_omega.png (letters, "
                  "digits, '-', '_' and '.')")
      ->type_name("TEXT")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            const bool ok = !text.empty() && text.size() <= 64 && text.front() != '.' &&
                            std::all_of(text.begin(), text.end(), [](char c) {
                              return std::isalnum(static_cast<unsigned char>(c)) || c == '-' ||
                                     c == '_' || c == '.';
                            });
            return ok ? ""
                      : "must be 1 to 64 letters, digits, '-', '_' or '.', not starting "
                        "with '.' (got '" +
                            text + "')";
          },
          ""));
  app_.set_version_flag("--version", name_ + " (rigidlab) " + std::string(RIGID_VERSION),
                        "print the version and exit");
}

Option& Lab::declare(CLI::Option* cli, const std::string& flag, const std::string& help) {
  return options_.emplace_back(Option(*this, cli, json_key(flag), help));
}

Option& Lab::number(const std::string& flag, double& value, const std::string& help) {
  CLI::Option* cli = app_.add_option(flag, value)->type_name("NUMBER")->capture_default_str();
  Option& option = declare(cli, flag, help);
  cli->check(CLI::Validator(
      [&option](std::string& text) -> std::string {
        double parsed = 0.0;
        if (!CLI::detail::lexical_cast(text, parsed))
          return "must be a number (got '" + text + "')";
        return option.broken_rule(parsed, text);
      },
      ""));
  option.record_ = [&option, &value] { option.lab_.inputs_[option.key_] = value; };
  return option;
}

Option& Lab::angle_deg(const std::string& flag, double& degrees, const std::string& help) {
  Option& option = number(flag, degrees, help).unit("deg");
  option.cli_->type_name("DEG");
  return option;
}

namespace {
// A component the validator has accepted, as a number.
double component(const std::string& text) {
  double value = 0.0;
  CLI::detail::lexical_cast(text, value);
  return value;
}
}  // namespace

Option& Lab::vector(const std::string& flag, Eigen::Vector3d& value, const std::string& help) {
  Option& option =
      numbers(flag, 3, "X,Y,Z", fmt::format("{},{},{}", value(0), value(1), value(2)), help);
  option.store_ = [&option, &value, flag] {
    if (option.texts_.empty()) return;
    if (option.texts_.size() == 1 && option.takes_word(option.texts_[0])) {
      option.word_ = option.texts_[0];
      return;
    }
    const bool has_word =
        std::any_of(option.texts_.begin(), option.texts_.end(),
                    [&option](const std::string& t) { return option.takes_word(t); });
    if (option.texts_.size() != 3 || has_word) {
      throw UsageError(
          flag, "expects three numbers X,Y,Z" +
                    (option.words_.empty() ? std::string() : " or one of " + option.word_list()));
    }
    for (int i = 0; i < 3; ++i) value(i) = component(option.texts_[static_cast<std::size_t>(i)]);
    if (option.nonzero_ && value.isZero(0.0)) throw UsageError(flag, "must not be the zero vector");
  };
  option.record_ = [&option, &value] {
    option.lab_.inputs_[option.key_] =
        option.word_.empty() ? Json::array({value(0), value(1), value(2)}) : Json(option.word_);
  };
  return option;
}

Option& Option::words(const std::vector<std::string>& names, const std::string& meaning) {
  words_ = names;
  cli_->expected(1, static_cast<int>(count_));
  cli_->type_name(cli_->get_type_name() + "|" + word_list());
  help_ += " (" + meaning + ")";
  describe();
  return *this;
}

bool Option::takes_word(const std::string& text) const {
  return std::find(words_.begin(), words_.end(), text) != words_.end();
}

std::string Option::word_list() const {
  std::string list;
  for (const std::string& w : words_) list += (list.empty() ? "" : "|") + w;
  return list;
}

Option& Lab::pair(const std::string& flag, Eigen::Vector2d& value, const std::string& type_name,
                  const std::string& help) {
  Option& option = numbers(flag, 2, type_name, fmt::format("{},{}", value(0), value(1)), help);
  option.store_ = [&option, &value] {
    if (option.texts_.empty()) return;
    value = Eigen::Vector2d(component(option.texts_[0]), component(option.texts_[1]));
  };
  option.record_ = [&option, &value] {
    option.lab_.inputs_[option.key_] = Json::array({value(0), value(1)});
  };
  return option;
}

Option& Lab::numbers(const std::string& flag, int count, const std::string& type_name,
                     const std::string& default_text, const std::string& help) {
  // CLI11 splits the value at the commas, insists on `count` values and checks each.
  options_.emplace_back(Option(*this, nullptr, json_key(flag), help));
  Option& option = options_.back();
  CLI::Option* cli = app_.add_option(flag, option.texts_)
                         ->delimiter(',')
                         ->expected(count)
                         ->type_name(type_name)
                         ->default_str(default_text);
  option.cli_ = cli;
  option.count_ = static_cast<std::size_t>(count);
  option.describe();
  cli->check(CLI::Validator(
      [&option](std::string& text) -> std::string {
        if (option.takes_word(text)) return "";
        double parsed = 0.0;
        if (!CLI::detail::lexical_cast(text, parsed)) {
          // too few numbers before the next option ("--omega , --json"): CLI11 took it
          if (text.rfind("--", 0) == 0 && text.size() > 2) {
            return fmt::format("needs {} numbers separated by commas; '{}' is the next option",
                               option.count_, text);
          }
          return "each component must be a number (got '" + text + "')" +
                 (option.words_.empty() ? "" : ", or the value one of " + option.word_list());
        }
        return option.broken_rule(parsed, text);
      },
      ""));
  return option;
}

Option& Lab::choice(const std::string& flag, std::string& value,
                    const std::vector<std::string>& choices, const std::string& help) {
  std::string names;
  for (const auto& choice : choices) names += (names.empty() ? "" : "|") + choice;
  CLI::Option* cli = app_.add_option(flag, value)->type_name("WORD")->capture_default_str();
  cli->check(CLI::IsMember(choices).description(""));
  Option& option = declare(cli, flag, help + " (" + names + ")");
  option.record_ = [&option, &value] { option.lab_.inputs_[option.key_] = value; };
  return option;
}

Option& Lab::flag(const std::string& flag, bool& value, const std::string& help) {
  Option& option = declare(app_.add_flag(flag, value), flag, help);
  option.record_ = [&option, &value] { option.lab_.inputs_[option.key_] = value; };
  return option;
}

void Lab::enable_csv() {
  csv_enabled_ = true;
  app_.add_option("--csv", csv_path_, "write the lab's time series to FILE as CSV")
      ->type_name("FILE");
}

bool Lab::given(const std::string& flag) const {
  return app_.count(flag) > 0;
}

std::string Lab::blamed_option() const {
  for (const Option& o : options_) {
    if (o.physical_ && o.cli_->count() > 0) return o.cli_->get_name();
  }
  for (const Option& o : options_) {  // then a numerical one
    if (o.cli_->count() > 0) return o.cli_->get_name();
  }
  return "--inputs";
}

bool Lab::textbook_inputs() const {
  for (const Option& option : options_) {
    if (option.physical_ && option.cli_->count() > 0) return false;
  }
  return true;
}

std::optional<std::string> Lab::textbook(const std::string& printed) const {
  return textbook_inputs() ? std::optional<std::string>(printed) : std::nullopt;
}

void Lab::drop_input(const std::string& key) {
  inputs_.erase(key);
}

// ---- Results ----------------------------------------------------------------

void Lab::section(const std::string& heading) {
  rows_.push_back({heading, "", "", "", true});
}

void Lab::store(const std::string& key, Json value, bool finite, const std::string& unit,
                const std::optional<std::string>& printed) {
  // A NaN or an overflow must never reach the output: JSON would print null.
  if (!finite) {
    // The inputs overflow it: the defaults never do.
    throw UsageError(
        blamed_option(),
        "the result '" + key + "' overflows or is undefined for these inputs (out of range)");
  }
  results_[key] = std::move(value);
  // A pure number has the unit "1", as SI writes it.
  units_[key] = unit.empty() ? "1" : unit;
  if (printed) textbook_[key] = *printed;
}

void Lab::result(const std::string& key, const std::string& label, double value,
                 const std::string& unit, std::optional<std::string> printed) {
  // Adding +0.0 turns a negative zero into 0.
  store(key, value + 0.0, std::isfinite(value), unit, printed);
  rows_.push_back({label, format_number(value, 6), unit, printed.value_or("")});
}

void Lab::result(const std::string& key, const std::string& label, const Eigen::Vector2d& value,
                 const std::string& unit, std::optional<std::string> printed) {
  store(key, Json::array({value(0) + 0.0, value(1) + 0.0}), value.allFinite(), unit, printed);
  rows_.push_back({label, format_vec2(value), unit, printed.value_or("")});
}

void Lab::result(const std::string& key, const std::string& label, const Eigen::Vector3d& value,
                 const std::string& unit, std::optional<std::string> printed) {
  store(key, Json::array({value(0) + 0.0, value(1) + 0.0, value(2) + 0.0}), value.allFinite(), unit,
        printed);
  rows_.push_back({label, format_vec3(value), unit, printed.value_or("")});
}

void Lab::result(const std::string& key, const std::string& label, const Eigen::Matrix3d& value,
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
}

void Lab::result_none(const std::string& key, const std::string& label, const std::string& unit,
                      const std::string& why) {
  results_[key] = nullptr;
  units_[key] = unit.empty() ? "1" : unit;
  rows_.push_back({label, "none", "", "(" + why + ")"});
}

void Lab::result_text(const std::string& key, const std::string& label, const std::string& value) {
  results_[key] = value;
  rows_.push_back({label, value, "", ""});
}

void Lab::result_roundoff(const std::string& key, const std::string& label, double value,
                          double bound, const std::string& unit) {
  result(key, label, value, unit);
  if (std::abs(value) <= bound) {
    rows_.back().value = "0";
    rows_.back().remark = "(roundoff: |computed| <= " + format_number(bound, 2) + ")";
  }
}

void Lab::warn(const std::string& option, const std::string& text) {
  // Said once the run has succeeded: a refused run prints its one error line only.
  warnings_.push_back(option + ": " + text);
  notes_.push_back("warning: " + option + ": " + text);
}

void Lab::alias(const std::string& old_key, const std::string& key) {
  results_[old_key] = results_.at(key);
  units_[old_key] = units_.at(key);
}

void Lab::note(const std::string& text) {
  notes_.push_back(text);
}

// The inputs that carry a symbol, as figure titles show them: "m = 1 kg, a = 1 m".
std::string Lab::title_inputs() const {
  std::string text;
  for (const Option& option : options_) {
    if (option.symbol_.empty() || !inputs_.contains(option.key_)) continue;
    const Json& value = inputs_[option.key_];
    std::string shown;
    if (value.is_number()) {
      shown = fmt::format("{:g}", value.get<double>() + 0.0);
    } else if (value.is_array()) {
      for (const Json& part : value) {
        shown += fmt::format("{}{:g}", shown.empty() ? "(" : ", ", part.get<double>() + 0.0);
      }
      shown += ")";
    } else {
      shown = text_of(value);
    }
    if (option.unit_ == "deg") {
      shown += "\\deg";
    } else if (!option.unit_.empty()) {
      shown += " " + option.unit_;
    }
    text += (text.empty() ? "" : ", ") + option.symbol_ + " = " + shown;
  }
  return text;
}

// ---- Running ----------------------------------------------------------------

bool can_create_in(const std::string& dir) {
  const std::string probe =
      (fs::path(dir) / fmt::format(".rigidlab-probe-{}", ::getpid())).string();
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) return false;
  ::close(fd);
  ::unlink(probe.c_str());
  return true;
}

void Lab::check_output_paths() const {
  check_animation_path();
  std::error_code ec;  // every filesystem question is asked without throwing
  if (app_.count("--figures") > 0 && figures_dir_.empty()) {
    throw UsageError("--figures", "needs a directory name");
  }
  if (!figures_dir_.empty()) {
    // Nothing is created before the lab has computed its results: find the
    // nearest existing ancestor and check that it can be written.
    fs::path dir = fs::absolute(figures_dir_, ec);
    while (!ec && !fs::exists(dir, ec) && dir.has_parent_path() && dir != dir.parent_path()) {
      dir = dir.parent_path();
    }
    if (ec || !fs::is_directory(dir, ec) || !can_create_in(dir.string())) {
      throw UsageError("--figures", "cannot create or write directory '" + figures_dir_ + "'");
    }
  }
  if (csv_enabled_ && app_.count("--csv") > 0) {
    if (csv_path_.empty()) throw UsageError("--csv", "needs a file name");
    const fs::path path = fs::absolute(csv_path_, ec);
    if (ec || path.filename().string().size() > kMaxFileName) {
      throw UsageError("--csv", fmt::format("file name longer than {} characters", kMaxFileName));
    }
    // Only a regular file is written (by rename, so a link would be replaced, not
    // followed, and a device or pipe replaced by a file): refuse anything else.
    const fs::file_status status = fs::symlink_status(path, ec);
    if (!ec && fs::exists(status)) {
      if (fs::is_symlink(status)) {
        throw UsageError("--csv", "'" + csv_path_ + "' is a symbolic link; give the file itself");
      }
      if (fs::is_directory(status)) {
        throw UsageError("--csv", "'" + csv_path_ + "' is a directory, not a file");
      }
      if (!fs::is_regular_file(status)) {
        throw UsageError("--csv", "'" + csv_path_ +
                                      "' is not a regular file (a device, pipe or "
                                      "socket); give a file name");
      }
    }
    const fs::path parent = path.parent_path();
    if (!fs::is_directory(parent, ec) || !can_create_in(parent.string())) {
      throw UsageError("--csv", "cannot write into directory '" + parent.string() + "'");
    }
  }
}

int Lab::run(int argc, char** argv, const std::function<void(Lab&)>& body) {
  // A closed pipe is a failed write to report, not a silent death by SIGPIPE.
  std::signal(SIGPIPE, SIG_IGN);
  try {
    try {
      app_.allow_extras();
      for (int i = 0; i < argc; ++i) command_.emplace_back(argv[i]);
      app_.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
      return app_.exit(e);
    } catch (const CLI::CallForVersion& e) {
      return app_.exit(e);
    } catch (const CLI::ArgumentMismatch& e) {
      // A wrong count of values: say it in the student's terms.
      const std::string what = e.what();
      const std::string name = what.substr(0, what.find(':'));
      const CLI::Option* option = app_.get_option_no_throw(name);
      const int count = option != nullptr ? option->get_items_expected_max() : 1;
      const std::string rule = count == 3   ? "must be three numbers X,Y,Z"
                               : count == 2 ? "must be two numbers"
                                            : "needs a value";
      throw UsageError(name, rule + " (" + what.substr(what.find(':') + 2) + ")");
    } catch (const CLI::ParseError& e) {
      // The option's own rules speak as "--option: rule"; anything else (CLI11's
      // wording) is said as it is, under the option it names first.
      const std::string what = e.what();
      const std::size_t colon = what.find(": ");
      if (what.rfind("--", 0) == 0 && colon != std::string::npos) {
        throw UsageError(what.substr(0, colon), what.substr(colon + 2));
      }
      const std::size_t dash = what.find("--");
      const std::size_t end = what.find_first_of(" ,:=", dash);
      throw UsageError(dash == std::string::npos ? "--inputs" : what.substr(dash, end - dash),
                       what);
    }
    // The first word CLI11 could not place names the mistake.
    if (const auto extras = app_.remaining(); !extras.empty()) {
      const std::string& word = extras.front();
      if (word.rfind("-", 0) == 0) throw UsageError(word, "unknown option (see --help)");
      throw UsageError(word, "unexpected argument (options take the form --name VALUE)");
    }
    for (Option& option : options_) {
      if (option.store_) option.store_();
      // An option whose default the lab chooses is an input only when given.
      if (option.lab_default_.empty() || option.cli_->count() > 0) option.record_();
    }
    check_output_paths();
    // The run's files (figures, CSV) land together or not at all.
    render::FileTransaction files;
    body(*this);
    if (!csv_path_.empty()) write_csv();
    try {
      files.commit();
    } catch (const std::runtime_error& e) {
      throw UsageError(csv_path_.empty() ? "--figures" : "--csv", e.what());
    }
  } catch (const UsageError& e) {
    std::cerr << name_ << ": error: " << escaped(e.what()) << '\n';
    return 2;
  } catch (const std::exception& e) {
    // A rule of core's broken where the lab named no option (or a failure it did
    // not foresee): the inputs given are to blame, the first physical one named.
    std::cerr << name_ << ": error: " << escaped(blamed_option() + ": " + e.what()) << '\n';
    return 2;
  }
  for (const std::string& warning : warnings_) {
    std::cerr << name_ << ": warning: " << escaped(warning) << '\n';
  }
  if (json_) {
    emit_json();
  } else if (!quiet_) {
    emit_table();
  }
  // Output that never arrived (stdout closed, a full disk, a closed pipe) is an error.
  std::cout.flush();
  if (!std::cout) {
    std::cerr << name_ << ": error: stdout: the output could not be written ("
              << std::strerror(errno) << ")\n";
    return 1;
  }
  return figures_failed_ ? 1 : 0;
}

// The widest value that sets the value column's width; longer ones (sentences) overflow it.
constexpr std::size_t kValueColumnMax = 40;

void Lab::emit_table() const {
  std::cout << name_ << " - " << title_ << "\n";
  std::string inputs;
  for (const auto& [key, value] : inputs_.items()) {
    inputs += (inputs.empty() ? "" : ", ") + key + " = " + text_of(value);
  }
  std::cout << "inputs: " << inputs << "\n";
  size_t label_width = 8, value_width = 5, unit_width = 4;
  bool any_textbook = false;
  for (const auto& row : rows_) {
    if (row.heading) continue;
    label_width = std::max(label_width, row.label.size());
    // A sentence (the motion in words) runs past the column instead of widening it.
    if (row.value.size() <= kValueColumnMax) value_width = std::max(value_width, row.value.size());
    unit_width = std::max(unit_width, row.unit.size());
    any_textbook = any_textbook || !row.textbook.empty();
  }
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
    if (!row.remark.empty()) line += "  " + row.remark;
    while (!line.empty() && line.back() == ' ') line.pop_back();
    std::cout << line << "\n";
  }
  if (!notes_.empty()) {
    std::cout << "\nnotes:\n";
    for (const auto& note : notes_) std::cout << "  - " << note << "\n";
  }
  if (!animation_.is_null()) {
    std::cout << "\nanimation: " << animation_path_ << "  "
              << animation_["caption"].get<std::string>() << "\n";
  }
  if (!figures_.empty()) {
    std::cout << "\nfigures in " << figures_dir_ << ":\n";
    for (const auto& figure : figures_) {
      std::cout << "  " << figure << "  " << captions_[figure].get<std::string>() << "\n";
    }
  }
}

void Lab::emit_json() const {
  Json out;
  out["lab"] = name_;
  out["version"] = RIGID_VERSION;
  out["command"] = command_;
  out["inputs"] = inputs_;
  out["results"] = results_;
  out["units"] = units_;
  out["figures"] = figures_;
  out["captions"] = captions_;
  if (!animation_.is_null()) out["animation"] = animation_;
  if (timing_)
    out["timing"] = {{"figure_seconds", figure_seconds_}, {"figure_phases", figure_phases_}};
  out["textbook"] = textbook_;
  out["textbook_values"] = textbook_values();
  // Every file the run wrote, by its absolute path.
  Json outputs = Json::array();
  std::error_code ec;
  for (const std::string& figure : figures_) {
    outputs.push_back(
        fs::absolute(fs::path(figures_dir_) / figure, ec).lexically_normal().string());
  }
  if (!csv_path_.empty() && !series_.columns.empty()) {
    outputs.push_back(fs::absolute(csv_path_, ec).lexically_normal().string());
  }
  if (!animation_.is_null()) outputs.push_back(animation_["path"]);
  out["outputs"] = outputs;
  out["notes"] = notes_;
  std::cout << out.dump(2) << "\n";
}

// The text's printed values as numbers in the result's unit where the print is a
// plain number (a parenthetical after it, "0.076 (76 g)", is commentary) or a list
// of them ("(0.20 : 0.25 : 0.33)"); where it is an expression ("0.493 ma^2",
// "(pi, 2 pi, 8.168)") the value is null.
Json Lab::textbook_values() const {
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

void Lab::count(const std::string& key, const std::string& label, std::size_t value) {
  results_[key] = value;
  units_[key] = "1";
  rows_.emplace_back(label, std::to_string(value), "", "");
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
  try {
    render::write_file_atomically(
        csv_path_, [&](std::FILE* file) { std::fwrite(text.data(), 1, text.size(), file); });
  } catch (const std::runtime_error& e) {
    throw UsageError("--csv", e.what());
  }
}

}  // namespace rigid::lab
