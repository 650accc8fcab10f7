// What each action does to the explorer (actions.h, explorer.h): the one place the
// lab's session and the view's state change.
#include <algorithm>
#include <system_error>

#include "explorer.h"
#include "exports.h"
#include "rigid/render/video.h"
#include "rigid/support/programs.h"
#include "rigid/support/text.h"

namespace rigid::explore {

struct Explorer::Apply {
  Explorer& e;

  // ---- the lab's inputs
  std::string operator()(const action::SetText& a) const {
    lab::Session& s = *e.session_;
    const std::size_t i = s.find(a.flag);
    if (i >= s.input_count()) return a.flag + ": " + s.name() + " has no such input";
    if (a.held) e.script_held_ = true;
    e.view_.fields[i].text = a.text;
    return taken(i, s.set_text(i, a.text));
  }
  std::string operator()(const action::SetValue& a) const {
    if (a.input >= e.session_->input_count()) return "";  // an input of a lab left
    return taken(a.input, e.session_->set(a.input, a.value));
  }
  // The field shows the refusal, or every field the state now taken.
  std::string taken(std::size_t i, const std::optional<lab::Refusal>& refusal) const {
    Field& field = e.view_.fields[i];
    if (refusal) return field.refusal = refusal->message;
    field.refusal.clear();
    e.after_change();
    return "";
  }
  std::string operator()(const action::Textbook&) const {
    e.session_->reset();
    e.after_change();
    return "";
  }
  std::string operator()(const action::OpenLab& a) const {
    for (std::size_t k = 0; k < e.labs_.size(); ++k) {
      if (e.labs_[k].name != a.name) continue;
      e.loader_.open(e.labs_[k], k);
      return "";
    }
    return "no lab named '" + support::terminal_safe(a.name) + "'";
  }

  // ---- time
  std::string operator()(const action::Play& a) const {
    e.view_.playing = a.on && e.session_->animation() != nullptr;
    return "";
  }
  std::string operator()(const action::TogglePlay&) const {
    return (*this)(action::Play{!e.view_.playing});
  }
  std::string operator()(const action::Seek& a) const {
    const lab::Animation* motion = e.session_->animation();
    e.view_.time = motion == nullptr ? 0.0 : std::clamp(a.time, 0.0, motion->seconds);
    return "";
  }
  std::string operator()(const action::Step& a) const {
    return (*this)(action::Seek{e.view_.time + a.frames * kScriptFrameSeconds * e.view_.speed});
  }
  std::string operator()(const action::Speed& a) const {
    e.set_speed(a.speed);
    return "";
  }

  // ---- the view
  std::string operator()(const action::Turn& a) const {
    e.view_.orbit.turn(a.right_deg, a.up_deg);
    return "";
  }
  std::string operator()(const action::MouseTurn& a) const {
    e.view_.orbit.drag(a.dx, a.dy, a.height);
    return "";
  }
  std::string operator()(const action::Zoom& a) const {
    e.view_.orbit.zoom_by(a.factor);
    return "";
  }
  std::string operator()(const action::Wheel& a) const {
    e.view_.orbit.wheel(a.steps);
    return "";
  }
  std::string operator()(const action::ResetView&) const {
    e.view_.orbit = {};
    return "";
  }
  std::string operator()(const action::Show& a) const {
    // a figure of the whole report (every method compared) is not in the first look at
    // new inputs yet: it is asked for by name, so the whole report is waited for
    if (e.session_->pending()) {
      const std::vector<std::string> first = view_choices(*e.session_, a.scene);
      if (std::find(first.begin(), first.end(), a.name) == first.end()) e.session_->wait();
    }
    const lab::Session& s = *e.session_;
    const std::vector<std::string> names = view_choices(s, a.scene);
    auto at = std::find(names.begin(), names.end(), a.name);
    // a script names the motion's strip by one word
    const lab::Animation* motion = s.animation();
    if (!a.scene && a.name == "strip" && motion != nullptr && motion->strip) at = names.begin();
    if (at == names.end()) return s.name() + " shows no '" + a.name + "'";
    (a.scene ? e.view_.scene_choice : e.view_.plot_choice) = static_cast<int>(at - names.begin());
    return "";
  }
  std::string operator()(const action::ShowPart& a) const {
    const std::vector<std::string> parts = e.scenes_.parts(*e.session_, e.view_);
    if (std::find(parts.begin(), parts.end(), a.part) == parts.end())
      return "the scene shows no part named '" + a.part + "'";
    const auto& hidden = e.view_.hidden;
    if ((std::find(hidden.begin(), hidden.end(), a.part) == hidden.end()) != a.shown)
      e.toggle(a.part);
    return "";
  }
  std::string operator()(const action::TogglePart& a) const {
    e.toggle(a.part);
    return "";
  }
  std::string operator()(const action::ToggleLegend&) const {
    e.view_.toggle_legend();
    return "";
  }

  // ---- exports (each checks its path again as it writes: exports.h)
  std::string operator()(const action::SaveFigure& a) const {
    int w = 0, h = 0;
    if (!read_figure_size(a.size, w, h)) return kFigureSizeRule;
    if (std::string why = drawing_refusal(w, h); !why.empty()) return why;
    if (std::string why = e.unavailable(a); !why.empty()) return why;
    return save_figure(*e.session_, a.name, a.path, a.format, w, h);
  }
  std::string operator()(const action::SaveView& a) const {
    int w = 0, h = 0;
    if (!read_figure_size(a.size, w, h)) return kFigureSizeRule;
    if (std::string why = drawing_refusal(w, h); !why.empty()) return why;
    if (std::string why = e.unavailable(a); !why.empty()) return why;
    try {
      return save_view(e.scenes_.view_scene(*e.session_, e.view_, w, h), a.path, w, h);
    } catch (const std::exception& ex) {
      return ex.what();
    }
  }
  std::string operator()(const action::ExportJson& a) const {
    return export_json(*e.session_, a.path);
  }
  std::string operator()(const action::ExportCsv& a) const {
    if (std::string why = e.unavailable(a); !why.empty()) return why;
    return export_csv(*e.session_, a.path);
  }
  std::string operator()(const action::Record& a) const {
    if (e.recording_) return "a recording is under way";
    if (std::string why = e.unavailable(a); !why.empty()) return why;
    if (!render::video_format_for(a.path)) {
      return "the file name must end in .mp4 or .webp (got '" + support::terminal_safe(a.path) +
             "')";
    }
    if (std::string why = output_refusal(a.path); !why.empty()) return why;
    try {
      e.recording_.emplace(Recording{start_recording(*e.session_, a.path), a.path, ""});
    } catch (const std::system_error&) {
      return "record: cannot run " +
             support::terminal_safe(support::program_path(e.session_->name(), "labs").string());
    }
    e.say("recording " + support::terminal_safe(a.path) + " ...");
    return "";
  }
  std::string operator()(const action::Screenshot& a) const {
    if (std::string why = output_refusal(a.path); !why.empty()) return why;
    e.screenshot_path_ = a.path;
    return "";
  }
  std::string operator()(const action::CopyCommand&) const {
    const std::string command = e.command_line();
    if (e.window_.set_clipboard) e.window_.set_clipboard(command);
    e.say(command);
    return "";
  }
};

std::string Explorer::apply(const Action& action) {
  return std::visit(Apply{*this}, action);
}

std::string Explorer::unavailable(const Action& a) {
  const std::string& lab = session_->name();
  if (const auto* f = std::get_if<action::SaveFigure>(&a);
      f != nullptr && figure_named(*session_, f->name) == nullptr)
    return lab + " has no figure named '" + f->name + "'";
  if (std::holds_alternative<action::SaveView>(a) && scenes_.shown(*session_, view_) == nullptr)
    return "this lab draws no 3D scene";
  if (std::holds_alternative<action::ExportCsv>(a)) {
    session_->wait();  // the series the command line writes, from the whole report
    if (session_->report().time_series().columns.empty()) return "this run has no time series";
  }
  if (std::holds_alternative<action::Record>(a) && session_->animation() == nullptr)
    return lab + " has no motion to record";
  return "";
}

}  // namespace rigid::explore
