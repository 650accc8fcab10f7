// A script read and checked before the window opens (script.h): its file, its words,
// every number's span, every file it writes, and its work in all.
#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <map>
#include <sstream>
#include <stdexcept>

#include "exports.h"
#include "rigid/render/video.h"
#include "rigid/support/text.h"
#include "script.h"
#include "view_state.h"

namespace rigid::explore {

namespace {

using support::terminal_safe;

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

// The spans of the numbers a command takes: a motion's time and speed, as the explorer
// clamps them, bounded so that no number is past what any motion needs; the view's
// angles a turn and its factor.
constexpr double kMaxPlaySeconds = kScriptMaxFrames * kScriptFrameSeconds;
constexpr double kMaxSeekSeconds = 1e6, kMaxScriptSpeed = 1e6;
constexpr double kMaxTurnDeg = 360, kMinZoomFactor = 1e-3, kMaxZoomFactor = 1e3;

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

// A number of a command in [lo, hi], read as every front door reads one (lab::read_number).
double number_in(const std::string& word, const std::string& what, double lo, double hi,
                 const char* unit = "") {
  const std::optional<double> x = lab::read_number(word);
  if (!x || !std::isfinite(*x)) {
    throw std::invalid_argument(what + " must be a number (got '" + terminal_safe(word) + "')");
  }
  if (*x < lo || *x > hi) {
    throw std::invalid_argument(
        fmt::format("{} must be {:g} to {:g}{} (got {})", what, lo, hi, unit, terminal_safe(word)));
  }
  return *x;
}

// What the script asks of the explorer so far, against its bounds in all.
struct Tally {
  long frames = 0;
  double waited = 0;
  // the slowest the explorer can play now: it starts at 1, a `speed` is clamped to at
  // least min(X, kMaxSpeed), and another lab starts at 1
  double slowest = 1;

  void draw(const std::string& op, long frames_more) {
    frames += frames_more;
    if (frames > kScriptMaxFrames) {
      throw std::invalid_argument(fmt::format(
          "{}: the script would draw {} frames in all; play and frames draw at most {} (play "
          "counted at speed {:g})",
          op, frames, kScriptMaxFrames, slowest));
    }
  }
};

// The numbers a command takes, read and held to their spans and the script's bounds;
// throws std::invalid_argument.
std::vector<double> numbers_of(const std::vector<std::string>& w, Tally& t) {
  const std::string& op = w[0];
  if (op == "turn") {
    return {number_in(w[1], "turn's first angle", -kMaxTurnDeg, kMaxTurnDeg, " degrees"),
            number_in(w[2], "turn's second angle", -kMaxTurnDeg, kMaxTurnDeg, " degrees")};
  }
  if (op == "lab") t.slowest = std::min(t.slowest, 1.0);
  if (op == "play") {
    const double seconds = number_in(w[1], op, 0, kMaxPlaySeconds, " s");
    t.draw(op, std::lround(seconds / (t.slowest * kScriptFrameSeconds)));
    return {seconds};
  }
  if (op == "frames") {
    const double n = number_in(w[1], op, 0, kScriptMaxFrames);
    if (n != std::floor(n)) throw std::invalid_argument("frames must be a whole number");
    t.draw(op, static_cast<long>(n));
    return {n};
  }
  if (op == "speed") {
    const double speed = number_in(w[1], op, kMinSpeed, kMaxScriptSpeed, " times real time");
    t.slowest = std::min(speed, kMaxSpeed);
    return {speed};
  }
  if (op == "seek") return {number_in(w[1], op, 0, kMaxSeekSeconds, " s")};
  if (op == "zoom") return {number_in(w[1], op, kMinZoomFactor, kMaxZoomFactor)};
  if (op == "wait") {
    const double seconds = number_in(w[1], op, 0, kScriptMaxWaitSeconds, " s");
    t.waited += seconds;
    if (t.waited > kScriptMaxWaitSeconds) {
      throw std::invalid_argument(fmt::format(
          "wait: the script would wait {:g} s in all; wait and wait-for wait at most {:g} s",
          t.waited, kScriptMaxWaitSeconds));
    }
    return {seconds};
  }
  return {};
}

// The rule a line breaks as a command (its name, its count of words), "" if none.
std::string command_rule(const std::vector<std::string>& words) {
  const auto c = commands().find(words[0]);
  if (c == commands().end()) {
    std::string all;
    for (const auto& [name, arity] : commands()) all += (all.empty() ? "" : ", ") + name;
    return "unknown command '" + terminal_safe(words[0]) + "' (one of " + all + ")";
  }
  const int n = static_cast<int>(words.size()) - 1;
  if (n >= c->second.min && n <= c->second.max) return "";
  return words[0] + " takes " +
         (c->second.min == c->second.max
              ? std::to_string(c->second.min)
              : std::to_string(c->second.min) + " to " + std::to_string(c->second.max)) +
         " words (got " + std::to_string(n) + ")";
}

// Where a command's words name a file it writes (0: none), and a size (0: none).
std::size_t written_word(const std::string& op) {
  if (op == "save-figure") return 2;
  const bool writes = op == "screenshot" || op == "save-view" || op == "export-json" ||
                      op == "export-csv" || op == "record";
  return writes ? 1 : 0;
}
std::size_t size_word(const std::string& op) {
  return op == "save-figure" ? 3 : op == "save-view" ? 2 : 0;
}

// The words that name a lab, a file written or a size, held to their rules.
void check_words(const std::vector<std::string>& w, const std::vector<std::string>& labs) {
  const std::string& op = w[0];
  if (op == "lab" && !labs.empty() && std::find(labs.begin(), labs.end(), w[1]) == labs.end()) {
    std::string names;
    for (const std::string& l : labs) names += (names.empty() ? "" : ", ") + l;
    throw std::invalid_argument("lab: '" + terminal_safe(w[1]) + "' is not a lab (one of " + names +
                                ")");
  }
  if (const std::size_t at = written_word(op); at > 0) {
    if (op == "record" && !render::video_format_for(w[at])) {
      throw std::invalid_argument("record: the file name must end in .mp4 or .webp (got '" +
                                  terminal_safe(w[at]) + "')");
    }
    if (const std::string why = output_refusal(w[at]); !why.empty())
      throw std::invalid_argument(op + ": " + why);
  }
  int width = 0, height = 0;
  if (const std::size_t at = size_word(op);
      at > 0 && w.size() > at && !read_figure_size(w[at], width, height)) {
    throw std::invalid_argument(op + ": " + kFigureSizeRule + " (got '" + terminal_safe(w[at]) +
                                "')");
  }
  if (width > 0) {
    if (const std::string why = drawing_refusal(width, height); !why.empty())
      throw std::invalid_argument(op + ": " + why);
  }
}

// The script's file, whole: a regular file (not a folder, a pipe that may never end, or
// a device), of at most kScriptMaxBytes.
std::string file_text(const std::string& path) {
  const std::string name = terminal_safe(path);
  // not blocked by a pipe with no writer: refused below as not a regular file
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw std::invalid_argument(name + ": cannot be read (" + std::strerror(errno) + ")");
  struct stat st {};
  std::string text, why;
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    why = S_ISDIR(st.st_mode) ? "a directory" : "not a regular file";
  } else {
    char buffer[65536];
    for (ssize_t n = 0; why.empty();) {
      n = ::read(fd, buffer, sizeof buffer);
      if (n == 0) break;
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) why = std::strerror(errno);
      if (n > 0) text.append(buffer, static_cast<std::size_t>(n));
      if (text.size() > kScriptMaxBytes)
        why = fmt::format("longer than {} bytes, a script's bound", kScriptMaxBytes);
    }
  }
  ::close(fd);
  if (!why.empty()) throw std::invalid_argument(name + ": cannot be read (" + why + ")");
  return text;
}

}  // namespace

std::string script_rules() {
  return fmt::format(
      "A script is a regular file of at most {} bytes, read and checked whole before the window "
      "opens: a wrong command, a number out of its span, a size, a lab's name, or a file it "
      "would write that --csv would refuse (a link, a folder, a device, a pipe) is one line "
      "naming the file, the line and the command, exit 2. The spans: play 0 to {:g} s, seek 0 "
      "to {:g} s, speed {:g} to {:g}, turn -{:g} to {:g} degrees, zoom {:g} to {:g}, frames 0 "
      "to {}, wait 0 to {:g} s; and in all, play and frames draw at most {} frames (a play "
      "counted at the slowest speed the script can have then), wait and wait-for hold the "
      "window at most {:g} s. What only the running lab can refuse (a scene it does not show) "
      "ends the script with the same line, exit 2; a write that fails then, exit 1.",
      kScriptMaxBytes, kMaxPlaySeconds, kMaxSeekSeconds, kMinSpeed, kMaxScriptSpeed, kMaxTurnDeg,
      kMaxTurnDeg, kMinZoomFactor, kMaxZoomFactor, kScriptMaxFrames, kScriptMaxWaitSeconds,
      kScriptMaxFrames, kScriptMaxWaitSeconds);
}

Script Script::read(const std::string& path, const std::vector<std::string>& labs) {
  return parse(file_text(path), path, labs);
}

Script Script::parse(const std::string& text, const std::string& path,
                     const std::vector<std::string>& labs) {
  Script s;
  s.path_ = path;
  Tally tally;
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
      check_words(words, labs);
      s.commands_.push_back({number, words, numbers_of(words, tally)});
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(terminal_safe(path) + ":" + std::to_string(number) + ": " +
                                  terminal_safe(e.what()));
    }
  }
  return s;
}

}  // namespace rigid::explore
