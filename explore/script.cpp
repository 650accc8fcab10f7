// A scripted session (script.h).
#include "script.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "explorer.h"
#include "rigid/support/text.h"

namespace rigid::explore {

namespace {

// Each command and how many words follow it: at least, at most.
struct Arity {
  int min = 0, max = 0;
};
const std::map<std::string, Arity>& commands() {
  static const std::map<std::string, Arity> table{
      {"set", {1, 2}},         {"unset", {1, 1}},      {"textbook", {0, 0}},
      {"lab", {1, 1}},         {"play", {1, 1}},       {"pause", {0, 0}},
      {"seek", {1, 1}},        {"speed", {1, 1}},      {"turn", {2, 2}},
      {"zoom", {1, 1}},        {"reset-view", {0, 0}}, {"show-scene", {1, 1}},
      {"show-plot", {1, 1}},   {"frames", {1, 1}},     {"screenshot", {1, 1}},
      {"save-figure", {2, 3}}, {"save-view", {1, 2}},  {"export-json", {1, 1}},
      {"export-csv", {1, 1}},  {"record", {1, 1}},     {"print-command", {0, 0}},
      {"print-json", {0, 0}},  {"wait", {1, 1}},       {"wait-for", {1, 1}},
      {"quit", {0, 0}},        {"drag", {2, 2}},       {"hide", {1, 1}},
      {"show", {1, 1}},
  };
  return table;
}

// How many times a `wait-for` looks for its file, once a frame: ten minutes at 60 frames
// a second.
constexpr int kWaitForLooks = 36000;

// Words of a line: split at blanks; a word in double quotes may hold blanks.
std::vector<std::string> words_of(const std::string& line) {
  std::vector<std::string> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    if (i >= line.size()) break;
    std::string word;
    if (line[i] == '"') {
      const std::size_t end = line.find('"', i + 1);
      if (end == std::string::npos) throw std::invalid_argument("a quote is not closed");
      word = line.substr(i + 1, end - i - 1);
      i = end + 1;
    } else {
      const std::size_t end = line.find_first_of(" \t", i);
      word = line.substr(i, end == std::string::npos ? std::string::npos : end - i);
      i = end == std::string::npos ? line.size() : end;
    }
    words.push_back(word);
  }
  return words;
}

// A number of a command, read as every front door reads one (lab::read_number).
double number_word(const std::string& word, const std::string& what) {
  const std::optional<double> x = lab::read_number(word);
  if (!x || !std::isfinite(*x)) {
    throw std::invalid_argument(what + " must be a number (got '" + support::terminal_safe(word) +
                                "')");
  }
  return *x;
}

// The numbers a command takes, read and held to its rules; throws std::invalid_argument.
std::vector<double> numbers_of(const std::vector<std::string>& words) {
  const std::string& op = words[0];
  if (op == "turn") {
    return {number_word(words[1], "turn's first angle"),
            number_word(words[2], "turn's second angle")};
  }
  if (op != "play" && op != "seek" && op != "speed" && op != "zoom" && op != "frames" &&
      op != "wait") {
    return {};
  }
  const double x = number_word(words[1], op);
  if (x < 0 || ((op == "speed" || op == "zoom") && !(x > 0)))
    throw std::invalid_argument(op + " must be positive (got " + words[1] + ")");
  if (op == "frames" && x > 100000) throw std::invalid_argument("frames: at most 100000");
  if (op == "play" && x > 3600) throw std::invalid_argument("play: at most 3600 s");
  if (op == "wait" && x > 600) throw std::invalid_argument("wait: at most 600 s");
  return {x};
}

// The rule a line breaks as a command (its name, its count of words), "" if none.
std::string command_rule(const std::vector<std::string>& words) {
  const auto c = commands().find(words[0]);
  if (c == commands().end()) {
    std::string all;
    for (const auto& [name, arity] : commands()) all += (all.empty() ? "" : ", ") + name;
    return "unknown command '" + support::terminal_safe(words[0]) + "' (one of " + all + ")";
  }
  const int n = static_cast<int>(words.size()) - 1;
  if (n >= c->second.min && n <= c->second.max) return "";
  return words[0] + " takes " +
         (c->second.min == c->second.max
              ? std::to_string(c->second.min)
              : std::to_string(c->second.min) + " to " + std::to_string(c->second.max)) +
         " words (got " + std::to_string(n) + ")";
}

}  // namespace

Script Script::read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::invalid_argument(support::terminal_safe(path) + ": cannot be read");
  std::stringstream text;
  text << in.rdbuf();
  return parse(text.str(), path);
}

Script Script::parse(const std::string& text, const std::string& path) {
  Script s;
  s.path_ = path;
  std::stringstream lines(text);
  int number = 0;
  for (std::string line; std::getline(lines, line);) {
    ++number;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    try {
      const std::vector<std::string> words = words_of(line);
      if (words.empty()) continue;
      if (const std::string rule = command_rule(words); !rule.empty())
        throw std::invalid_argument(rule);
      s.commands_.push_back({number, words, numbers_of(words)});
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(support::terminal_safe(path) + ":" + std::to_string(number) +
                                  ": " + e.what());
    }
  }
  return s;
}

void Script::report(const Command& c, const std::string& error) {
  *out_ << path_ << ":" << c.line << ": " << support::terminal_safe(error) << std::endl;
}

// Whether the explorer can take the command now: not while a lab it asked for opens or a
// recording is written, nor an export before the whole report has come.
bool Script::ready(const Command& c, const Explorer& e) const {
  if (e.opening() || e.recording()) return false;
  const std::string& op = c.words[0];
  const bool whole =
      op == "save-figure" || op == "export-json" || op == "export-csv" || op == "print-json";
  return !(whole && e.session().pending());
}

bool Script::step(Explorer& e) {
  if (wait_until_) {
    if (std::chrono::steady_clock::now() < *wait_until_) return true;
    wait_until_.reset();
  }
  if (looks_left_ > 0) {
    const Command& c = commands_[next_ - 1];
    std::error_code ec;
    if (std::filesystem::exists(c.words[1], ec)) {
      looks_left_ = 0;
    } else if (--looks_left_ == 0) {
      report(c, "wait-for: " + c.words[1] + " did not come");
      failed_ = true;
    }
    return true;
  }
  if (frames_left_ > 0) {
    if (--frames_left_ == 0) e.apply(action::Play{false});
    return true;
  }
  if (next_ >= commands_.size()) return false;
  blocked_ = !ready(commands_[next_], e);
  if (blocked_) return true;
  return run(commands_[next_++], e);
}

// The command as the explorer's action, where it is one.
std::optional<Action> Script::action_of(const Command& c) {
  const std::vector<std::string>& w = c.words;
  const std::string& op = w[0];
  const auto size = [&](std::size_t k) { return w.size() > k ? w[k] : std::string("1600x1200"); };
  if (op == "set" || op == "unset" || op == "drag")
    return action::SetText{w[1], op == "unset" ? "" : w.size() > 2 ? w[2] : "", op == "drag"};
  if (op == "textbook") return action::Textbook{};
  if (op == "lab") return action::OpenLab{w[1]};
  if (op == "pause") return action::Play{false};
  if (op == "seek") return action::Seek{c.numbers[0]};
  if (op == "speed") return action::Speed{c.numbers[0]};
  if (op == "turn") return action::Turn{c.numbers[0], c.numbers[1]};
  if (op == "zoom") return action::Zoom{c.numbers[0]};
  if (op == "reset-view") return action::ResetView{};
  if (op == "show-scene" || op == "show-plot") return action::Show{op == "show-scene", w[1]};
  if (op == "hide" || op == "show") return action::ShowPart{w[1], op == "show"};
  if (op == "screenshot") return action::Screenshot{w[1]};
  if (op == "save-figure") {
    // the file's ending names the format: .svg, .pdf, or a PNG
    const std::string ext = std::filesystem::path(w[2]).extension().string();
    const auto format = render::figure_format_named(ext.empty() ? "" : ext.substr(1));
    return action::SaveFigure{w[1], w[2], format.value_or(render::FigureFormat::kPng), size(3)};
  }
  if (op == "save-view") return action::SaveView{w[1], size(2)};
  if (op == "export-json") return action::ExportJson{w[1]};
  if (op == "export-csv") return action::ExportCsv{w[1]};
  if (op == "record") return action::Record{w[1]};
  return std::nullopt;
}

bool Script::run(const Command& c, Explorer& e) {
  const std::vector<std::string>& w = c.words;
  const std::string& op = w[0];
  // a size is read before the export, and its rule said with what was given
  const std::size_t size_at = op == "save-figure" ? 3 : op == "save-view" ? 2 : 0;
  int width = 0, height = 0;
  if (size_at > 0 && w.size() > size_at && !read_figure_size(w[size_at], width, height)) {
    report(c, std::string(kFigureSizeRule) + " (got " + w[size_at] + ")");
    failed_ = true;
    return true;
  }
  try {
    if (const std::optional<Action> a = action_of(c)) {
      const std::string error = e.apply(*a);
      if (error.empty()) return true;
      // a refused value is the lesson, not a failure
      if (std::holds_alternative<action::SetText>(*a)) {
        report(c, "refused: " + error);
        return true;
      }
      throw std::runtime_error(error);
    }
    if (op == "play") {
      // a lab without motion draws the frames all the same
      e.apply(action::Play{true});
      frames_left_ = static_cast<int>(std::lround(c.numbers[0] / (e.view().speed / 30.0)));
      if (frames_left_ == 0) e.apply(action::Play{false});
    } else if (op == "wait") {
      wait_until_ = std::chrono::steady_clock::now() +
                    std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                        std::chrono::duration<double>(c.numbers[0]));
    } else if (op == "wait-for") {
      looks_left_ = kWaitForLooks;
    } else if (op == "frames") {
      frames_left_ = static_cast<int>(c.numbers[0]);
    } else if (op == "print-command") {
      *out_ << e.command_line() << std::endl;
    } else if (op == "print-json") {
      *out_ << e.json_text() << std::flush;
    } else if (op == "quit") {
      next_ = commands_.size();
      return false;
    }
  } catch (const std::exception& ex) {
    report(c, op + ": " + ex.what());
    failed_ = true;
  }
  return true;
}

}  // namespace rigid::explore
