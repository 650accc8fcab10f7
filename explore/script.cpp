// A scripted session as it runs (script.h; read and checked in script_read.cpp).
#include "script.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "explorer.h"
#include "rigid/support/text.h"

namespace rigid::explore {

// A value refused, or what a command printed: on the script's output.
void Script::report(const Command& c, const std::string& error) {
  *out_ << support::terminal_safe(path_) << ":" << c.line << ": " << support::terminal_safe(error)
        << std::endl;
}

// The one line that ends the script, and the exit status it asks.
bool Script::fail(const Command& c, int status, const std::string& error) {
  *err_ << prefix_ << support::terminal_safe(path_) << ":" << c.line << ": "
        << support::terminal_safe(error) << std::endl;
  status_ = status;
  next_ = commands_.size();
  return false;
}

void Script::abort(int status, const std::string& error) {
  if (status_ == 0 && next_ > 0) fail(commands_[next_ - 1], status, error);
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

// A `wait` or `wait-for` under way: whether it still holds the script (false also when
// a file awaited did not come within the script's wall time left: the script ends).
bool Script::keep_waiting() {
  const Clock::time_point now = now_();
  if (looking_since_) {
    const Command& c = commands_[next_ - 1];
    std::error_code ec;
    const bool came = std::filesystem::exists(c.words[1], ec);
    if (came || now >= *wait_until_) {
      wait_left_ =
          std::max(0.0, wait_left_ - std::chrono::duration<double>(now - *looking_since_).count());
      looking_since_.reset();
      wait_until_.reset();
      if (!came) {
        fail(c, 1,
             "wait-for: '" + c.words[1] + "' did not come within the script's " + "wait of " +
                 std::to_string(static_cast<int>(kScriptMaxWaitSeconds)) + " s in all");
      }
      return false;
    }
    return true;
  }
  if (now < *wait_until_) return true;
  wait_until_.reset();
  return false;
}

bool Script::step(Explorer& e) {
  if (wait_until_ && keep_waiting()) return true;
  if (status_ != 0) return false;
  if (frames_left_ > 0) {
    if (--frames_left_ == 0) e.apply(action::Play{false});
    return true;
  }
  // the script's end waits for a recording it began, and a lab it asked for, as its next
  // command would
  if (next_ >= commands_.size()) return blocked_ = e.recording() || e.opening();
  blocked_ = !ready(commands_[next_], e);
  if (blocked_) return true;
  return run(commands_[next_++], e);
}

namespace {

// The command as the explorer's action, where it is one.
std::optional<Action> action_of(const Script::Command& c) {
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

}  // namespace

bool Script::run(const Command& c, Explorer& e) {
  const std::string& op = c.words[0];
  try {
    if (const std::optional<Action> a = action_of(c)) {
      if (writes_file(*a)) {
        if (const std::string why = e.unavailable(*a); !why.empty())
          return fail(c, 2, op + ": " + why);
      }
      const std::string error = e.apply(*a);
      if (error.empty()) return true;
      // a refused value is the lesson, not a failure
      if (std::holds_alternative<action::SetText>(*a)) {
        report(c, "refused: " + error);
        return true;
      }
      // a file that could not be written is a failed write; anything else the command
      // named (a scene, a part, a lab) is not there to be had
      return fail(c, writes_file(*a) ? 1 : 2, op + ": " + error);
    }
    if (op == "play") {
      // a lab without motion draws the frames all the same
      e.apply(action::Play{true});
      frames_left_ = std::min(frame_budget_,
                              std::lround(c.numbers[0] / (e.view().speed * kScriptFrameSeconds)));
      frame_budget_ -= frames_left_;
      if (frames_left_ == 0) e.apply(action::Play{false});
    } else if (op == "frames") {
      frames_left_ = std::min(frame_budget_, static_cast<long>(c.numbers[0]));
      frame_budget_ -= frames_left_;
    } else if (op == "wait") {
      wait_left_ -= c.numbers[0];
      wait_until_ = now_() + std::chrono::duration_cast<Clock::duration>(
                                 std::chrono::duration<double>(c.numbers[0]));
    } else if (op == "wait-for") {
      looking_since_ = now_();
      wait_until_ = *looking_since_ + std::chrono::duration_cast<Clock::duration>(
                                          std::chrono::duration<double>(wait_left_));
    } else if (op == "print-command") {
      *out_ << e.command_line() << std::endl;
    } else if (op == "print-json") {
      *out_ << e.json_text() << std::flush;
    } else if (op == "quit") {
      next_ = commands_.size();
      return false;
    }
  } catch (const std::exception& ex) {
    return fail(c, 1, op + ": " + ex.what());
  }
  return true;
}

}  // namespace rigid::explore
