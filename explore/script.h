// A session without a person: one command a line, run a command a frame, for the
// tests and for an instructor's reproducible demo (`rigidlab explore LAB --script FILE`).
//
//   # comments and blank lines are skipped
//   set --mass 2              the input, as typed in its field (a refusal is printed)
//   drag --mass 2.5           the input, as its slider held and moved there (the camera
//                             holds still until the next command lets go)
//   unset --spin              an optional input back to the lab's default
//   textbook                  the text's example
//   lab top_nutation          another lab
//   play 2.5                  plays 2.5 s of the motion (frames of 1/30 s at the speed set);
//                             a lab without motion draws as many frames
//   seek 1.2 | speed 2 | pause
//   turn 30 -10 | zoom 1.5 | reset-view      the view: degrees right and up, a factor
//   show-scene NAME|motion | show-plot NAME|strip
//   hide "energy ellipsoid" | show "energy ellipsoid"   a part of the scene (its legend entry)
//   frames 3                  draws 3 frames
//   wait 5                    5 s of wall time, the window live (a person acts)
//   wait-for FILE             until FILE exists, the window live (a test's xdotool acts, then
//                             makes FILE); looked for once a frame
//   screenshot FILE           the window as a PNG
//   save-figure NAME FILE [WxH]   a figure of the lab, as its --figures writes it (.svg and
//                                 .pdf as vectors, any other name a PNG)
//   save-view FILE [WxH]      the scene as shown (time, view) at a size
//   export-json FILE | export-csv FILE | record FILE (.mp4 or .webp, as --animate)
//   print-command | print-json   to stdout
//   quit
//
// A script is read whole before the window opens, and every word it can check then is
// checked then: an unknown command, a wrong count of words, a number out of its span,
// a size, a lab's name, a file it would write that output_paths.h refuses (a link, a
// folder, a device, a pipe, an unwritable folder, a name too long), and its work in
// all past the bounds below. Each is one line naming the file, the line, the command
// and the rule, exit 2. What only the running lab can say (a scene it does not show) is
// the same one line when its command comes, exit 2; a write that fails then (the file
// system changed) is exit 1. Either ends the script. A refused `set` is the lesson, not
// a failure: it is printed and the script goes on.
//
// A script drives the explorer through the same actions as its panels (actions.h), and
// waits, the frames going on, while a lab it asked for opens, a recording is written, or
// an export needs the whole report.
#pragma once

#include <chrono>
#include <functional>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "actions.h"

namespace rigid::explore {

class Explorer;

/// What one script may do, in all: its file's size, the frames `play` and `frames` draw
/// (a `play` counted at the slowest speed the script can have then), and the wall time
/// `wait` and `wait-for` hold the window.
constexpr std::size_t kScriptMaxBytes = 1 << 20;
constexpr long kScriptMaxFrames = 18000;
constexpr double kScriptMaxWaitSeconds = 600;

/// The rules above in words, with their numbers (for --help).
std::string script_rules();

class Script {
 public:
  /// Reads and checks `path` (a regular file of at most kScriptMaxBytes); throws
  /// std::invalid_argument with "PATH:LINE: rule". `labs`: the names `lab` may open
  /// (none given: any name, refused when it comes).
  static Script read(const std::string& path, const std::vector<std::string>& labs = {});
  /// Parses `text` (the file's contents) as read() does, naming `path` in its errors.
  static Script parse(const std::string& text, const std::string& path,
                      const std::vector<std::string>& labs = {});

  /// Where its refusals of a value and its prints go (std::cout).
  void report_to(std::ostream& out) { out_ = &out; }
  /// Where its one line of failure goes (std::cerr), after `prefix` (the program's name).
  void errors_to(std::ostream& err, std::string prefix = "") {
    err_ = &err;
    prefix_ = std::move(prefix);
  }
  /// The clock its waits read (steady_clock's own): a test gives one it moves itself.
  void clock_from(std::function<std::chrono::steady_clock::time_point()> now) {
    now_ = std::move(now);
  }
  /// Runs the next command (or continues a long one); false once the script is done.
  bool step(Explorer& explorer);
  /// Whether a `wait` is under way, or the explorer's work (its frames unpaced would
  /// only spin).
  bool waiting() const { return wait_until_.has_value() || blocked_; }
  /// Ends the script at the command last run, its one line `error`, status `status` (a
  /// failure the explorer met after the command: a recording's, a screenshot's).
  void abort(int status, const std::string& error);
  /// 0, or the exit status its end asks: 2 for a command refused when it came, 1 for a
  /// failed write or a file awaited that did not come.
  int status() const { return status_; }

  struct Command {
    int line = 0;
    std::vector<std::string> words;
    std::vector<double> numbers;  // the words after the first that are numbers, read
  };

 private:
  bool ready(const Command& c, const Explorer& e) const;
  bool run(const Command& c, Explorer& e);
  bool keep_waiting();
  void report(const Command& c, const std::string& error);
  bool fail(const Command& c, int status, const std::string& error);
  std::string path_;
  std::vector<Command> commands_;
  std::size_t next_ = 0;
  long frames_left_ = 0;                  // of a `play` or `frames` under way
  long frame_budget_ = kScriptMaxFrames;  // what `play` and `frames` may still draw
  using Clock = std::chrono::steady_clock;
  std::function<Clock::time_point()> now_ = Clock::now;
  std::optional<Clock::time_point> wait_until_;     // of a `wait`, or a `wait-for`'s last look
  std::optional<Clock::time_point> looking_since_;  // a `wait-for` under way
  double wait_left_ = kScriptMaxWaitSeconds;        // s of wall time still to wait, in all
  bool blocked_ = false;                            // waiting for the explorer
  int status_ = 0;
  std::ostream* out_ = &std::cout;
  std::ostream* err_ = &std::cerr;
  std::string prefix_;
};

}  // namespace rigid::explore
