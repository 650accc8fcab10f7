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
//                             makes FILE); looked for once a frame, at most 36000 times
//   screenshot FILE           the window as a PNG
//   save-figure NAME FILE [WxH]   a figure of the lab, as its --figures writes it (.svg and
//                                 .pdf as vectors, any other name a PNG)
//   save-view FILE [WxH]      the scene as shown (time, view) at a size
//   export-json FILE | export-csv FILE | record FILE (.mp4 or .webp, as --animate)
//   print-command | print-json   to stdout
//   quit
//
// A script is read whole before the window opens: an unknown command or a wrong
// count of words is one line naming the file, the line and the rule, exit 2.
// A script drives the explorer through the same actions as its panels (actions.h), and
// waits, the frames going on, while a lab it asked for opens, a recording is written, or
// an export needs the whole report.
#pragma once

#include <chrono>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "actions.h"

namespace rigid::explore {

class Explorer;

class Script {
 public:
  /// Reads and checks `path`; throws std::invalid_argument with "PATH:LINE: rule".
  static Script read(const std::string& path);
  /// Parses `text` (the file's contents) as read() does, naming `path` in its errors.
  static Script parse(const std::string& text, const std::string& path);

  /// Where its refusals and failures ("PATH:LINE: ...") and its prints go (std::cout).
  void report_to(std::ostream& out) { out_ = &out; }
  /// Runs the next command (or continues a long one); false once the script is done.
  bool step(Explorer& explorer);
  /// Whether a `wait` is under way, or the explorer's work (its frames unpaced would
  /// only spin).
  bool waiting() const { return wait_until_.has_value() || looks_left_ > 0 || blocked_; }
  /// Whether a refusal or a failed export happened (the exit status is then 1).
  bool failed() const { return failed_; }

 private:
  struct Command {
    int line = 0;
    std::vector<std::string> words;
    std::vector<double> numbers;  // the words after the first that are numbers, read
  };
  bool ready(const Command& c, const Explorer& e) const;
  bool run(const Command& c, Explorer& e);
  std::optional<Action> action_of(const Command& c);
  void report(const Command& c, const std::string& error);
  std::string path_;
  std::vector<Command> commands_;
  std::size_t next_ = 0;
  int frames_left_ = 0;  // of a `play` or `frames` under way
  std::optional<std::chrono::steady_clock::time_point> wait_until_;  // of a `wait`
  int looks_left_ = 0;                                               // of a `wait-for` under way
  bool blocked_ = false;                                             // waiting for the explorer
  bool failed_ = false;
  std::ostream* out_ = &std::cout;
};

}  // namespace rigid::explore
