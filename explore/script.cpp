// A scripted session (script.h).
#include "script.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
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
      {"print-json", {0, 0}},  {"wait", {1, 1}},       {"quit", {0, 0}},
      {"drag", {2, 2}},        {"hide", {1, 1}},       {"show", {1, 1}},
  };
  return table;
}

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

double number_word(const std::string& word, const std::string& what) {
  std::size_t used = 0;
  double x = 0;
  try {
    x = std::stod(word, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != word.size() || !std::isfinite(x)) {
    throw std::invalid_argument(what + " must be a number (got '" + support::terminal_safe(word) +
                                "')");
  }
  return x;
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
    const auto where = [&](const std::string& rule) {
      return std::invalid_argument(support::terminal_safe(path) + ":" + std::to_string(number) +
                                   ": " + rule);
    };
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::vector<std::string> words;
    try {
      words = words_of(line);
    } catch (const std::invalid_argument& e) {
      throw where(e.what());
    }
    if (words.empty()) continue;
    const auto c = commands().find(words[0]);
    if (c == commands().end()) {
      std::string all;
      for (const auto& [name, arity] : commands()) all += (all.empty() ? "" : ", ") + name;
      throw where("unknown command '" + support::terminal_safe(words[0]) + "' (one of " + all +
                  ")");
    }
    const int n = static_cast<int>(words.size()) - 1;
    if (n < c->second.min || n > c->second.max) {
      throw where(words[0] + " takes " +
                  (c->second.min == c->second.max
                       ? std::to_string(c->second.min)
                       : std::to_string(c->second.min) + " to " + std::to_string(c->second.max)) +
                  " words (got " + std::to_string(n) + ")");
    }
    try {
      if (words[0] == "play" || words[0] == "seek" || words[0] == "speed" || words[0] == "zoom" ||
          words[0] == "frames") {
        const double x = number_word(words[1], words[0]);
        if (x < 0 || (words[0] == "speed" && !(x > 0)) || (words[0] == "zoom" && !(x > 0)))
          throw std::invalid_argument(words[0] + " must be positive (got " + words[1] + ")");
        if (words[0] == "frames" && x > 100000)
          throw std::invalid_argument("frames: at most 100000");
        if (words[0] == "play" && x > 3600) throw std::invalid_argument("play: at most 3600 s");
        if (words[0] == "wait" && x > 600) throw std::invalid_argument("wait: at most 600 s");
      }
      if (words[0] == "turn") {
        number_word(words[1], "turn's first angle");
        number_word(words[2], "turn's second angle");
      }
    } catch (const std::invalid_argument& e) {
      throw where(e.what());
    }
    s.commands_.push_back({number, words});
  }
  return s;
}

void Script::report(const Command& c, const std::string& error) {
  std::cout << path_ << ":" << c.line << ": " << support::terminal_safe(error) << std::endl;
}

bool Script::step(Explorer& e) {
  if (wait_until_) {
    if (std::chrono::steady_clock::now() < *wait_until_) return true;
    wait_until_.reset();
  }
  e.script_dragging_ = false;
  if (frames_left_ > 0) {
    --frames_left_;
    if (frames_left_ == 0) e.playing_ = false;
    return true;
  }
  if (e.recording_) return true;  // a `record` waits for the file
  if (next_ >= commands_.size()) return false;
  const Command& c = commands_[next_++];
  e.script_dragging_ = c.words[0] == "drag";
  const std::vector<std::string>& w = c.words;
  const std::string& op = w[0];
  const auto size_of = [&](std::size_t k, int& width, int& height) {
    width = 1600, height = 1200;
    if (w.size() <= k || read_figure_size(w[k], width, height)) return true;
    report(c, std::string(kFigureSizeRule) + " (got " + w[k] + ")");
    failed_ = true;
    return false;
  };
  const auto exported = [&](const std::string& error) {
    if (error.empty()) return;
    report(c, op + ": " + error);
    failed_ = true;
  };
  try {
    if (op == "set" || op == "unset" || op == "drag") {
      const std::string refusal = e.set_text(w[1], op == "unset" ? "" : w.size() > 2 ? w[2] : "");
      if (!refusal.empty()) report(c, "refused: " + refusal);
    } else if (op == "textbook") {
      e.textbook();
    } else if (op == "lab") {
      e.open(w[1]);
      e.playing_ = false;
    } else if (op == "play") {
      // a lab without motion draws the frames all the same
      e.playing_ = e.session_->animation() != nullptr;
      frames_left_ = static_cast<int>(std::lround(std::stod(w[1]) / (e.speed_ / 30.0)));
      if (frames_left_ == 0) e.playing_ = false;
    } else if (op == "wait") {
      wait_until_ = std::chrono::steady_clock::now() +
                    std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                        std::chrono::duration<double>(std::stod(w[1])));
    } else if (op == "pause") {
      e.playing_ = false;
    } else if (op == "seek") {
      const lab::Animation* motion = e.session_->animation();
      e.time_ = motion == nullptr ? 0.0 : std::min(std::stod(w[1]), motion->seconds);
    } else if (op == "speed") {
      e.set_speed(std::stod(w[1]));
    } else if (op == "turn") {
      e.orbit_.yaw_deg += std::stod(w[1]);
      e.orbit_.pitch_deg += std::stod(w[2]);
      e.orbit_.clamp();
    } else if (op == "zoom") {
      e.orbit_.zoom *= std::stod(w[1]);
      e.orbit_.clamp();
    } else if (op == "reset-view") {
      e.orbit_ = {};
    } else if (op == "show-scene" || op == "show-plot") {
      const bool scenes = op == "show-scene";
      const lab::Animation* motion = e.session_->animation();
      const bool lead = scenes ? motion != nullptr : motion != nullptr && bool(motion->strip);
      std::vector<std::string> names;
      if (lead) names.push_back(scenes ? "motion" : "strip");
      for (const auto& f : e.session_->figures()) {
        if (f.is_scene() == scenes) names.push_back(f.name);
      }
      const auto at = std::find(names.begin(), names.end(), w[1]);
      if (at == names.end()) {
        report(c, op + ": " + e.session_->name() + " shows no " + w[1]);
        failed_ = true;
      } else {
        (scenes ? e.scene_choice_ : e.plot_choice_) = static_cast<int>(at - names.begin());
      }
    } else if (op == "hide" || op == "show") {
      const auto parts = e.scene_parts();
      const bool hidden = std::find(e.hidden_.begin(), e.hidden_.end(), w[1]) != e.hidden_.end();
      if (std::find(parts.begin(), parts.end(), w[1]) == parts.end()) {
        report(c, op + ": the scene shows no part named '" + w[1] + "'");
        failed_ = true;
      } else if (hidden == (op == "show")) {
        e.toggle(w[1]);
      }
    } else if (op == "frames") {
      frames_left_ = static_cast<int>(std::stod(w[1]));
    } else if (op == "screenshot") {
      e.screenshot_path_ = w[1];
    } else if (op == "save-figure") {
      int width = 0, height = 0;
      // the file's ending names the format: .svg, .pdf, or a PNG
      const std::string ext = std::filesystem::path(w[2]).extension().string();
      const auto format = render::figure_format_named(ext.empty() ? "" : ext.substr(1));
      if (size_of(3, width, height))
        exported(
            e.save_figure(w[1], w[2], format.value_or(render::FigureFormat::kPng), width, height));
    } else if (op == "save-view") {
      int width = 0, height = 0;
      if (size_of(2, width, height)) exported(e.save_view(w[1], width, height));
    } else if (op == "export-json") {
      exported(e.export_json(w[1]));
    } else if (op == "export-csv") {
      exported(e.export_csv(w[1]));
    } else if (op == "record") {
      exported(e.record(w[1]));
    } else if (op == "print-command") {
      std::cout << e.command_line() << std::endl;
    } else if (op == "print-json") {
      std::cout << e.json_text() << std::flush;
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
