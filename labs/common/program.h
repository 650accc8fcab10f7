// A lab as one program: its name, its inputs' table, compute(), figures() and, if
// it moves, its animation. The command line (command.h), the tests and a live
// view all take a lab by this one description, as Box2D's samples register
// themselves with their host.
#pragma once

#include <string>

#include "common/figures.h"
#include "common/inputs.h"
#include "common/report.h"

namespace rigid::lab {

/// A lab, as the command line, the tests and a live view call it.
template <class In, class Rep>
struct LabProgram {
  std::string name;   ///< the executable and JSON "lab"
  std::string title;  ///< heads the table and --help
  const InputTable<In>& inputs;
  Rep (*compute)(const In&) = nullptr;
  void (*figures)(const Rep&, FigureSink&) = nullptr;
  /// The motion (nullptr for a lab without one); `frame_times` are the times the
  /// animation will ask for, at which an integrated motion is best sampled.
  Animation (*animation)(const Rep&, const FrameTimes& frame_times) = nullptr;
  /// What --csv writes, as its --help says it ("the run at its sample times: ..."): a time
  /// series or the sweep a figure draws; empty where the lab writes no CSV.
  std::string csv;
  /// What a live view computes first when the inputs change, if the whole compute can
  /// take long: the inputs with the slow part left out (nullptr: nothing is slow). The
  /// whole report follows when it is done (session.h).
  void (*preview)(In&) = nullptr;
  /// Whether the defaults are the text's worked example; false where the text prints no
  /// numbers (section 6), and the defaults are the lab's own choice.
  bool textbook_example = true;
  /// The body's state at any time of the lab's motion (nullptr: the lab has none, or its
  /// motion is not a body's); it copies what it needs from the report.
  BodyMotion (*body_motion)(const Rep&) = nullptr;
};

}  // namespace rigid::lab
