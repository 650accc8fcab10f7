// What a user (or a script) does to the explorer, as values: the panels queue them
// while a frame is built, and the explorer applies them all at one point, before the
// next frame (as MuJoCo's simulate applies its UI's changes in Sync). A script applies
// the same actions, one a frame; so does the command line's list of a lab's inputs.
// Applying one gives "" or the one line that says why it was refused or failed.
#pragma once

#include <string>
#include <variant>

#include "common/inputs.h"
#include "rigid/render/figure_format.h"

namespace rigid::explore::action {

/// An input from its text, as typed in its field; `held` as a slider held and moved
/// there (the camera holds still this frame).
struct SetText {
  std::string flag, text;
  bool held = false;
};
/// An input set by its widget (a slider, a drag, a choice, a switch; absent: the lab's).
struct SetValue {
  std::size_t input = 0;
  lab::InputValue value;
};
/// Back to the text's example.
struct Textbook {};
/// Another lab, opened off the frame's thread (the lab shown stays until it is ready).
struct OpenLab {
  std::string name;
};
struct Play {
  bool on = true;
};
struct TogglePlay {};
struct Seek {
  double time = 0;  ///< s, clamped to the motion
};
/// A frame forward (+1) or back (-1) at the speed set.
struct Step {
  int frames = 1;
};
struct Speed {
  double speed = 1;  ///< clamped to what the motion allows
};
/// The view turned by degrees right and up, or by a mouse drag in a view `height` tall.
struct Turn {
  double right_deg = 0, up_deg = 0;
};
struct MouseTurn {
  double dx = 0, dy = 0, height = 1;
};
struct Zoom {
  double factor = 1;
};
struct Wheel {
  double steps = 0;
};
struct ResetView {};
/// Which scene (or plot) is shown, by its name in the view's list ("motion" and "strip"
/// name the motion's own).
struct Show {
  bool scene = true;
  std::string name;
};
/// A part of the scene (its legend entry) shown or hidden.
struct ShowPart {
  std::string part;
  bool shown = true;
};
struct TogglePart {
  std::string part;
};
/// The scene's legend drawn over it, or collapsed to a button (it may hide what a turn
/// brings under it).
struct ToggleLegend {};

// Exports, each through the lab's own writers, of the whole report (an export waits for
// it, the frames going on meanwhile).
// A figure's size is its text, "WxH", read when the export is made (kFigureSizeRule).
struct SaveFigure {
  std::string name, path;
  render::FigureFormat format = render::FigureFormat::kPng;
  std::string size = "1600x1200";
};
struct SaveView {
  std::string path;
  std::string size = "1600x1200";
};
struct ExportJson {
  std::string path;
};
struct ExportCsv {
  std::string path;
};
/// The motion as the lab's own `--animate PATH` writes it, in a child process.
struct Record {
  std::string path;
};
/// The window as a PNG, once the frame is drawn.
struct Screenshot {
  std::string path;
};
/// The command line that reproduces the view, onto the clipboard.
struct CopyCommand {};

}  // namespace rigid::explore::action

namespace rigid::explore {

using Action =
    std::variant<action::SetText, action::SetValue, action::Textbook, action::OpenLab, action::Play,
                 action::TogglePlay, action::Seek, action::Step, action::Speed, action::Turn,
                 action::MouseTurn, action::Zoom, action::Wheel, action::ResetView, action::Show,
                 action::ShowPart, action::TogglePart, action::ToggleLegend, action::SaveFigure,
                 action::SaveView, action::ExportJson, action::ExportCsv, action::Record,
                 action::Screenshot, action::CopyCommand>;

/// Whether `a` writes what the whole report says (it waits for the report to come).
bool needs_whole_report(const Action& a);
/// The file an export writes (a figure, the view, the JSON, the CSV); "" for another action.
std::string written_path(const Action& a);
/// Whether `a` writes a file (an export, a recording, a screenshot): its failure is a
/// failed write.
bool writes_file(const Action& a);

/// The rule of an exported figure's size, and "1600x1200" read by it (false: broken).
extern const char* const kFigureSizeRule;
bool read_figure_size(const std::string& text, int& width, int& height);

}  // namespace rigid::explore
