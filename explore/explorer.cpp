// The explorer's frame: the panels, the views and the exports (explorer.h).
#include "explorer.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <imgui.h>
#include <imgui_stdlib.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "common/writers.h"
#include "rigid/render/atomic_file.h"
#include "rigid/render/draw.h"
#include "rigid/render/png.h"
#include "rigid/support/programs.h"
#include "rigid/support/text.h"
#include "script.h"

extern char** environ;

namespace rigid::explore {

namespace fs = std::filesystem;
using lab::InputKind;
using lab::InputRule;
using lab::InputValue;

namespace {

// The window's layout at any size: inputs on the left, numbers on the right, the
// scene between them over the time bar and the plot.
constexpr float kInputsWidth = 340.0f;
constexpr float kNumbersWidth = 390.0f;
constexpr float kTimeBarHeight = 64.0f;
constexpr float kPlotShare = 0.34f;  // of the height under the scene's top

// A script's frame: 1/30 s of wall time, so a script plays the same on any machine.
constexpr double kScriptFrameSeconds = 1.0 / 30.0;
constexpr double kMinSpeed = 0.1, kMaxSpeed = 10.0;
// The legend entry of the exact motion laid faintly over an integrator's.
const char* const kExactGhost = "the exact motion (faint): the drift is the gap";
// A motion longer than this plays faster than real time at first (the Earth's
// precession takes two days): in kLongMotionPlay seconds, and the speed reaches that far.
constexpr double kLongMotionPlay = 10.0;

double fastest(const lab::Animation& motion) {
  return std::max(kMaxSpeed, motion.seconds / kLongMotionPlay);
}

const ImVec4 kRuleColor(0.80f, 0.18f, 0.10f, 1.0f);
const ImVec4 kErrataColor(0.70f, 0.35f, 0.0f, 1.0f);
const ImVec4 kDimColor(0.40f, 0.40f, 0.45f, 1.0f);
const ImVec4 kHeadingColor(0.0f, 0.35f, 0.60f, 1.0f);

// A word a shell would read as itself, else single-quoted.
std::string shell_word(const std::string& word) {
  if (!word.empty() && word.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                              "0123456789_./=,:+-@%") == std::string::npos) {
    return word;
  }
  std::string quoted = "'";
  for (char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace

const char* const kFigureSizeRule = "size: must be WxH, each 16 to 8192";

bool read_figure_size(const std::string& text, int& width, int& height) {
  const auto size = lab::read_size(text, {16, 16, 8192, 8192, false});
  const auto* read = std::get_if<lab::Size>(&size);
  if (read == nullptr) return false;
  width = read->width;
  height = read->height;
  return true;
}

// What a field shows: the text as typed, and the rule it broke.
struct Explorer::Field {
  std::string text;
  std::string refusal;
};

// An animation written by the lab's own command (`LAB ... --animate FILE`) while the
// window goes on.
struct Explorer::Recording {
  pid_t pid = 0;
  std::string path;
  int err_fd = -1;
  std::string err;
};

Explorer::Explorer(std::vector<LabEntry> labs, const std::string& lab, Window window)
    : labs_(std::move(labs)), window_(std::move(window)) {
  open(lab);
}

Explorer::~Explorer() {
  if (recording_ && recording_->pid > 0) {
    ::kill(recording_->pid, SIGTERM);
    int status = 0;
    ::waitpid(recording_->pid, &status, 0);
    if (recording_->err_fd >= 0) ::close(recording_->err_fd);
  }
}

void Explorer::open(const std::string& name) {
  for (std::size_t k = 0; k < labs_.size(); ++k) {
    if (labs_[k].name != name) continue;
    lab_index_ = k;
    session_ = labs_[k].make();
    if (window_.set_title) window_.set_title("rigidlab explore: " + name);
    fields_.assign(session_->input_count(), Field{});
    orbit_ = {};
    scene_choice_ = plot_choice_ = export_figure_ = 0;
    time_ = 0.0;
    playing_ = session_->animation() != nullptr;
    speed_ = 1.0;
    exact_session_.reset();
    exact_generation_ = -1;
    hidden_.clear();
    ++hidden_version_;
    long_motion_ = false;
    message_.clear();
    after_change();
    return;
  }
  throw std::invalid_argument("no lab named '" + support::terminal_safe(name) + "'");
}

void Explorer::after_change() {
  // every field shows the state now taken; a refusal shown was of a value not taken
  for (std::size_t i = 0; i < fields_.size(); ++i) {
    fields_[i].text = lab::argument_text(session_->value(i));
    fields_[i].refusal.clear();
  }
  const lab::Animation* motion = session_->animation();
  if (motion != nullptr && time_ > motion->seconds) time_ = 0.0;
  // real time, unless the motion is too long to watch so (then as fast as it goes,
  // from when it became so)
  if (motion != nullptr) {
    const bool long_motion = motion->seconds > kMaxSpeed * kLongMotionPlay;
    if (long_motion && !long_motion_) speed_ = fastest(*motion);
    long_motion_ = long_motion;
    set_speed(speed_);
  }
}

std::string Explorer::set_text(const std::string& flag, const std::string& text) {
  const std::size_t i = session_->find(flag);
  if (i >= session_->input_count()) {
    return flag + ": " + session_->name() + " has no such input";
  }
  Field& field = fields_[i];
  field.text = text;
  if (auto refusal = session_->set_text(i, text)) {
    field.refusal = refusal->message;
    return field.refusal;
  }
  field.refusal.clear();
  after_change();
  return "";
}

void Explorer::set_speed(double speed) {
  const lab::Animation* motion = session_->animation();
  speed_ = std::clamp(speed, kMinSpeed, motion != nullptr ? fastest(*motion) : kMaxSpeed);
}

void Explorer::textbook() {
  session_->reset();
  for (Field& f : fields_) f.refusal.clear();
  after_change();
}

void Explorer::run(std::unique_ptr<Script> script) {
  script_ = std::move(script);
  playing_ = false;
}

bool Explorer::scripted() const {
  return script_ != nullptr && !script_->waiting();
}

bool Explorer::animating() const {
  return playing_ || script_ != nullptr || recording_ != nullptr || session_->pending();
}

void Explorer::say(const std::string& text, bool error) {
  message_ = text;
  message_error_ = error;
  if (script_) (error ? std::cerr : std::cout) << text << '\n';
}

// ---- the frame ---------------------------------------------------------------

void Explorer::frame(double seconds) {
  if (script_) {
    seconds = kScriptFrameSeconds;
    step_script();
  }
  // the whole report, if it has come (the numbers and plots follow it)
  session_->poll();
  ImGuiIO& io = ImGui::GetIO();
  const lab::Animation* motion = session_->animation();
  if (motion != nullptr && playing_) {
    time_ += seconds * speed_;
    // a motion plays in a loop
    if (time_ > motion->seconds) time_ = std::fmod(time_, motion->seconds);
  }
  // space plays and pauses, the arrows step a frame, while no field is being typed in
  if (!io.WantTextInput && motion != nullptr) {
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Space), false)) playing_ = !playing_;
    const double step = kScriptFrameSeconds * speed_;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_RightArrow)))
      time_ = std::min(time_ + step, motion->seconds);
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_LeftArrow)))
      time_ = std::max(time_ - step, 0.0);
  }
  if (recording_) {
    // the recording's stderr, and whether it has ended
    char buffer[512];
    ssize_t n = 0;
    while ((n = ::read(recording_->err_fd, buffer, sizeof buffer)) > 0)
      recording_->err.append(buffer, n);
    int status = 0;
    if (::waitpid(recording_->pid, &status, WNOHANG) == recording_->pid) {
      ::close(recording_->err_fd);
      const bool ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
      std::string err = recording_->err;
      while (!err.empty() && err.back() == '\n') err.pop_back();
      if (const auto nl = err.rfind('\n'); nl != std::string::npos) err = err.substr(nl + 1);
      say(ok ? "wrote " + support::terminal_safe(recording_->path)
             : "recording failed: " + support::terminal_safe(err),
          !ok);
      recording_.reset();
    }
  }

  const float W = io.DisplaySize.x, H = io.DisplaySize.y;
  const float center_w = std::max(W - kInputsWidth - kNumbersWidth, 160.0f);
  const float plot_h = std::floor((H - kTimeBarHeight) * kPlotShare);
  const float scene_h = std::max(H - kTimeBarHeight - plot_h, 80.0f);
  constexpr ImGuiWindowFlags kPanel =
      ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
      ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoSavedSettings;

  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(ImVec2(kInputsWidth, H));
  ImGui::Begin("Inputs", nullptr, kPanel | ImGuiWindowFlags_NoTitleBar);
  inputs_panel();
  ImGui::End();

  ImGui::SetNextWindowPos(ImVec2(W - kNumbersWidth, 0));
  ImGui::SetNextWindowSize(ImVec2(kNumbersWidth, H));
  ImGui::Begin("Numbers", nullptr, kPanel | ImGuiWindowFlags_NoTitleBar);
  numbers_panel();
  ImGui::End();

  scene_view(kInputsWidth, 0, center_w, scene_h);
  time_panel(kInputsWidth, scene_h, center_w, kTimeBarHeight);
  plot_view(kInputsWidth, scene_h + kTimeBarHeight, center_w, plot_h);
}

// ---- inputs ------------------------------------------------------------------

void Explorer::inputs_panel() {
  ImGui::PushStyleColor(ImGuiCol_Text, kHeadingColor);
  ImGui::TextUnformatted("rigidlab explore");
  ImGui::PopStyleColor();
  ImGui::SetNextItemWidth(-1);
  if (ImGui::BeginCombo("##lab", session_->name().c_str())) {
    for (const LabEntry& entry : labs_) {
      if (ImGui::Selectable(entry.name.c_str(), entry.name == session_->name())) open(entry.name);
    }
    ImGui::EndCombo();
  }
  ImGui::PushStyleColor(ImGuiCol_Text, kDimColor);
  ImGui::TextWrapped("%s", session_->title().c_str());
  ImGui::PopStyleColor();
  const bool at_textbook = session_->at_textbook();
  if (at_textbook) ImGui::BeginDisabled();
  // a lab whose section prints no numbers starts from its own defaults, and says so
  const bool example = session_->has_textbook_example();
  if (ImGui::Button(example ? "Textbook example" : "Lab's defaults")) textbook();
  if (at_textbook) ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::TextColored(kDimColor, !at_textbook ? ""
                                : example    ? "(the text's inputs)"
                                             : "(the text prints no numbers here)");
  ImGui::Separator();

  ImGui::BeginChild("fields", ImVec2(0, -ImGui::GetFrameHeightWithSpacing() * 7.5f));
  interacting_ = script_dragging_;
  bool numerical_heading = false;
  for (std::size_t i = 0; i < session_->input_count(); ++i) {
    if (!session_->rule(i).physical() && !numerical_heading) {
      numerical_heading = true;
      ImGui::Spacing();
      ImGui::TextColored(kHeadingColor, "Numerical method");
      ImGui::Separator();
    }
    input_widget(i);
  }
  ImGui::EndChild();
  export_section();
}

void Explorer::input_widget(std::size_t i) {
  const InputRule& r = session_->rule(i);
  Field& field = fields_[i];
  const InputValue value = session_->value(i);
  const bool optional = !r.lab_default_text().empty();
  const bool absent = std::holds_alternative<std::monostate>(value);
  ImGui::PushID(static_cast<int>(i));
  std::string label = r.help();
  if (!r.unit_text().empty()) label += " [" + r.unit_text() + "]";
  ImGui::TextWrapped("%s", label.c_str());
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", r.flag().c_str());
  const auto apply = [&](const InputValue& v) {
    if (auto refusal = session_->set(i, v)) {
      field.refusal = refusal->message;
    } else {
      field.refusal.clear();
      after_change();
    }
  };
  const auto text_field = [&](const char* hint) {
    ImGui::SetNextItemWidth(-1);
    const bool entered =
        ImGui::InputTextWithHint("##text", hint, &field.text, ImGuiInputTextFlags_EnterReturnsTrue);
    if (entered || ImGui::IsItemDeactivatedAfterEdit()) set_text(r.flag(), field.text);
  };
  const std::string lab_default = "the lab's: " + r.lab_default_text();
  switch (r.kind()) {
    case InputKind::kNumber: {
      if (!absent) {
        double x = std::get<double>(value);
        const InputValue book = session_->textbook_value(i);
        const double textbook = std::holds_alternative<double>(book) ? std::get<double>(book) : x;
        const lab::SliderSpan span = lab::slider_span(r, textbook);
        ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
        ImGuiSliderFlags flags = ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_NoInput;
        if (span.log) flags |= ImGuiSliderFlags_Logarithmic;
        if (ImGui::SliderScalar("##slider", ImGuiDataType_Double, &x, &span.lo, &span.hi, "%.4g",
                                flags)) {
          apply(x);
        }
        // the slider's ends; a value beyond them is typed in the field
        if (ImGui::IsItemHovered()) {
          ImGui::SetTooltip("%s", fmt::format("{:.4g} to {:.4g}{}; type any value the rule allows "
                                              "in the field",
                                              span.lo, span.hi, span.log ? ", logarithmic" : "")
                                      .c_str());
        }
        // a slider held: the frames show the new inputs with the camera kept
        if (ImGui::IsItemActive()) interacting_ = true;
        ImGui::SameLine();
      }
      text_field(optional ? lab_default.c_str() : "");
      break;
    }
    case InputKind::kPair:
    case InputKind::kVector: {
      const int n = r.kind() == InputKind::kVector ? 3 : 2;
      double v[3] = {0, 0, 0};
      bool numeric = false;
      if (const auto* p = std::get_if<Eigen::Vector3d>(&value)) {
        v[0] = (*p)[0], v[1] = (*p)[1], v[2] = (*p)[2];
        numeric = true;
      } else if (const auto* p = std::get_if<Eigen::Vector2d>(&value)) {
        v[0] = (*p)[0], v[1] = (*p)[1];
        numeric = true;
      }
      if (numeric) {
        // a drag's speed: a hundredth of the largest component per pixel
        double size = 0;
        for (int k = 0; k < n; ++k) size = std::max(size, std::abs(v[k]));
        const float speed = static_cast<float>(size > 0 ? size / 100 : 0.01);
        ImGui::SetNextItemWidth(-1);
        if (ImGui::DragScalarN("##drag", ImGuiDataType_Double, v, n, speed, nullptr, nullptr,
                               "%.4g")) {
          apply(n == 3 ? InputValue(Eigen::Vector3d(v[0], v[1], v[2]))
                       : InputValue(Eigen::Vector2d(v[0], v[1])));
        }
        if (ImGui::IsItemActive()) interacting_ = true;
      }
      text_field(optional
                     ? lab_default.c_str()
                     : (r.word_names().empty() ? "X,Y,Z" : ("X,Y,Z or " + r.word_list()).c_str()));
      break;
    }
    case InputKind::kChoice: {
      const std::string current = absent ? lab_default : std::get<std::string>(value);
      ImGui::SetNextItemWidth(-1);
      if (ImGui::BeginCombo("##choice", current.c_str())) {
        for (const std::string& c : r.choices()) {
          if (ImGui::Selectable(c.c_str(), c == current)) apply(c);
        }
        ImGui::EndCombo();
      }
      break;
    }
    case InputKind::kFlag: {
      bool on = !absent && std::get<bool>(value);
      if (ImGui::Checkbox(r.flag().c_str(), &on)) apply(on);
      break;
    }
  }
  if (optional && !absent) {
    if (ImGui::SmallButton("use the lab's")) apply(InputValue());
  }
  if (!field.refusal.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kRuleColor);
    ImGui::TextWrapped("%s", support::terminal_safe(field.refusal).c_str());
    ImGui::PopStyleColor();
  }
  ImGui::Spacing();
  ImGui::PopID();
}

// ---- numbers -----------------------------------------------------------------

void Explorer::numbers_panel() {
  const lab::Report& report = session_->report();
  ImGui::TextColored(kHeadingColor, "%s", report.lab().c_str());
  ImGui::SameLine();
  ImGui::TextColored(kDimColor, report.textbook_inputs() ? "the text's values beside" : "");
  if (session_->pending()) {
    ImGui::TextColored(kDimColor, "comparing every method with the exact motion ...");
  }
  if (!session_->whole_error().empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kRuleColor);
    ImGui::TextWrapped("the command line refuses these inputs: %s",
                       support::terminal_safe(session_->whole_error()).c_str());
    ImGui::PopStyleColor();
  }
  for (const std::string& w : report.warnings()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kErrataColor);
    ImGui::TextWrapped("%s", support::terminal_safe(w).c_str());
    ImGui::PopStyleColor();
  }
  // The rows as the command line's table has them: each section's heading across the
  // panel, its rows in three columns aligned from one section to the next.
  const float notes_h = std::min(ImGui::GetContentRegionAvail().y * 0.35f,
                                 ImGui::GetTextLineHeightWithSpacing() *
                                     (1.0f + 2.5f * static_cast<float>(report.notes().size())));
  ImGui::BeginChild("rows", ImVec2(0, -notes_h));
  constexpr ImGuiTableFlags kTable =
      ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_BordersInnerH;
  bool open = false;
  int table = 0;
  const auto begin_table = [&] {
    open = ImGui::BeginTable(fmt::format("rows{}", table++).c_str(), 3, kTable);
    if (open) {
      ImGui::TableSetupColumn("quantity", ImGuiTableColumnFlags_WidthStretch, 1.5f);
      ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch, 1.4f);
      ImGui::TableSetupColumn("the text", ImGuiTableColumnFlags_WidthStretch, 0.8f);
    }
  };
  begin_table();
  if (open) ImGui::TableHeadersRow();
  for (const lab::TableRow& row : report.rows()) {
    if (row.heading) {
      if (open) ImGui::EndTable();
      ImGui::Spacing();
      ImGui::PushStyleColor(ImGuiCol_Text, kHeadingColor);
      ImGui::TextWrapped("%s", row.label.c_str());
      ImGui::PopStyleColor();
      begin_table();
      continue;
    }
    if (!open) continue;
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    ImGui::TextWrapped("%s", row.label.c_str());
    ImGui::TableSetColumnIndex(1);
    const std::string value = row.unit.empty() ? row.value : row.value + " " + row.unit;
    ImGui::TextWrapped("%s", value.c_str());
    if (!row.remark.empty() && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", row.remark.c_str());
    ImGui::TableSetColumnIndex(2);
    ImGui::PushStyleColor(ImGuiCol_Text, kDimColor);
    ImGui::TextWrapped("%s", row.textbook.c_str());
    ImGui::PopStyleColor();
  }
  if (open) ImGui::EndTable();
  ImGui::EndChild();
  ImGui::BeginChild("notes");
  for (const std::string& note : report.notes()) {
    const bool errata = note.rfind("errata", 0) == 0;
    ImGui::PushStyleColor(ImGuiCol_Text, errata ? kErrataColor : kDimColor);
    ImGui::TextWrapped("%s", support::terminal_safe(note).c_str());
    ImGui::PopStyleColor();
  }
  ImGui::EndChild();
}

// ---- the views ---------------------------------------------------------------

namespace {

// The names a view offers: the motion first (if any), then the lab's figures of a kind.
std::vector<std::string> choices_of(const lab::Session& s, bool scenes, bool has_motion_part) {
  std::vector<std::string> names;
  if (has_motion_part) names.push_back(scenes ? "motion" : "the motion's strip");
  for (const lab::NamedFigure& f : s.figures()) {
    if (f.is_scene() == scenes) names.push_back(f.name);
  }
  return names;
}

const lab::NamedFigure* figure_named(const lab::Session& s, const std::string& name) {
  for (const lab::NamedFigure& f : s.figures()) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

}  // namespace

const Explorer::MotionEnvelope& Explorer::motion_envelope() const {
  MotionEnvelope& e = motion_envelope_;
  // Made once for a set of inputs, as the camera is fitted (a later result for the same
  // inputs shows the same parts), and held while a slider is dragged: sixteen scenes
  // would be most of a dragged step's time (a part the drag brings in is still named:
  // legend_from adds what it lacks).
  const bool current =
      e.generation == session_->inputs_generation() || (interacting_ && e.generation >= 0);
  if (current && e.lab == lab_index_) return e;
  const lab::Animation* motion = session_->animation();
  render::Scene3D envelope = lab::motion_envelope(*motion);
  envelope.title = session_->report().figure_title(envelope.title);
  render::Scene3D legend = envelope.legend_only();
  if (const lab::Animation* exact = exact_motion())
    legend.merge(exact->scene(0.0).faded(kExactGhost).legend_only());
  e.legend = std::make_shared<const render::Scene3D>(std::move(legend));
  // the camera is fitted clear of the legend the frames draw (the ghost's entry with it)
  envelope.legend_from = e.legend;
  e.scene = std::make_shared<const render::Scene3D>(std::move(envelope));
  e.generation = session_->inputs_generation();
  e.lab = lab_index_;
  return e;
}

const render::Scene3D* Explorer::shown_scene() const {
  const lab::Animation* motion = session_->animation();
  const auto names = choices_of(*session_, true, motion != nullptr);
  if (names.empty()) return nullptr;
  const std::string& name = names[std::min<std::size_t>(scene_choice_, names.size() - 1)];
  if (motion != nullptr && name == "motion") {
    // made once for a state and a time: a frame asks for it more than once
    MotionScene& m = motion_scene_;
    if (!(m.generation == session_->generation() && m.time == time_ && m.lab == lab_index_)) {
      m.scene = motion->scene(time_);
      m.scene.title = session_->report().figure_title(m.scene.title);
      // an integrator's motion, with the exact one laid over it faintly: drift is seen
      if (const lab::Animation* exact = exact_motion()) {
        m.scene.merge(exact->scene(std::min(time_, exact->seconds)).faded(kExactGhost));
      }
      m.generation = session_->generation();
      m.time = time_;
      m.lab = lab_index_;
    }
    m.scene.legend_from = motion_envelope().legend;
    return &m.scene;
  }
  return &std::get<render::Scene3D>(figure_named(*session_, name)->figure);
}

namespace {

// A window for a figure's image at (x, y), w × h, without padding or decoration; the
// image's size in pixels of the framebuffer.
std::pair<int, int> begin_view(const char* name, float x, float y, float w, float h) {
  ImGui::SetNextWindowPos(ImVec2(x, y));
  ImGui::SetNextWindowSize(ImVec2(w, h));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::Begin(name, nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoSavedSettings);
  ImGui::PopStyleVar();
  const ImGuiIO& io = ImGui::GetIO();
  return {std::max(16, static_cast<int>(w * io.DisplayFramebufferScale.x)),
          std::max(16, static_cast<int>(h * io.DisplayFramebufferScale.y))};
}

}  // namespace

// The same inputs with the exact method, when an integrator's motion is shown (and the
// lab has a closed form to offer); nullptr otherwise.
const lab::Animation* Explorer::exact_motion() const {
  const std::size_t m = session_->find("--method");
  if (m >= session_->input_count()) return nullptr;
  const lab::InputValue exact = std::string("exact");
  if (session_->value(m) == exact || !session_->rule(m).broken(exact).empty()) return nullptr;
  if (exact_generation_ != session_->inputs_generation()) {
    exact_session_ = session_->with(m, exact);
    exact_generation_ = session_->inputs_generation();
  }
  return exact_session_ ? exact_session_->animation() : nullptr;
}

// The camera of the view before the orbit: the lab's own, fitted once to the figure, or
// to the whole motion (frames spread over it), so that playing does not move it.
render::Camera Explorer::base_camera(int width, int height) {
  const bool same_view = fit_.choice == scene_choice_ && fit_.width == width &&
                         fit_.height == height && fit_.lab == lab_index_;
  // While a slider is dragged the camera holds still (a refit each step would make the
  // view breathe under the hand, and is most of a step's time); it is fitted again
  // when the hand lets go.
  if (same_view && (fit_.generation == session_->inputs_generation() || interacting_)) {
    return fit_.camera;
  }
  const render::Scene3D* shown = shown_scene();
  const lab::Animation* motion = session_->animation();
  // as the command line's --animate fits its camera
  const bool moving = motion != nullptr && scene_choice_ == 0;
  fit_ = {session_->inputs_generation(),
          scene_choice_,
          width,
          height,
          lab_index_,
          render::fitted_camera(moving ? *motion_envelope().scene : *shown, width, height)};
  return fit_.camera;
}

render::Scene3D Explorer::view_scene(int width, int height) {
  const render::Scene3D* shown = shown_scene();
  render::Scene3D scene = shown->without(hidden_);
  scene.camera = orbit_.apply(base_camera(width, height));
  return scene;
}

void Explorer::toggle(const std::string& label) {
  const auto at = std::find(hidden_.begin(), hidden_.end(), label);
  if (at == hidden_.end()) {
    hidden_.push_back(label);
  } else {
    hidden_.erase(at);
  }
  ++hidden_version_;
}

std::vector<std::string> Explorer::scene_parts() const {
  const render::Scene3D* shown = shown_scene();
  return shown == nullptr ? std::vector<std::string>{} : shown->legend_labels();
}

void Explorer::scene_view(float x, float y, float w, float h) {
  const auto [pw, ph] = begin_view("Scene", x, y, w, h);
  const ImGuiIO& io = ImGui::GetIO();
  const bool any = shown_scene() != nullptr;
  if (any) {
    const Drawn want{session_->generation(), scene_choice_, pw, ph, time_, orbit_, true,
                     hidden_version_};
    const Drawn& had = scene_drawn_;
    const bool stale = !had.valid || had.generation != want.generation ||
                       had.choice != want.choice || had.width != pw || had.height != ph ||
                       had.time != want.time || had.orbit.yaw_deg != orbit_.yaw_deg ||
                       had.orbit.pitch_deg != orbit_.pitch_deg || had.orbit.zoom != orbit_.zoom ||
                       had.hidden != hidden_version_;
    if (stale) {
      try {
        scene_image_.draw(view_scene(pw, ph), pw, ph);
        draw_error_.clear();
      } catch (const std::exception& e) {
        draw_error_ = e.what();
      }
      scene_drawn_ = want;
    }
  }
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("view", ImVec2(w, h));
  if (any && scene_image_.texture() != 0) {
    // GL's rows run bottom-up: the texture is shown flipped
    ImGui::GetWindowDrawList()->AddImage(
        reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(scene_image_.texture())), origin,
        ImVec2(origin.x + w, origin.y + h), ImVec2(0, 1), ImVec2(1, 0));
  }
  if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f)) {
    orbit_.drag(io.MouseDelta.x, io.MouseDelta.y, h);
  }
  if (ImGui::IsItemHovered()) {
    if (io.MouseWheel != 0.0f) orbit_.wheel(io.MouseWheel);
    if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) orbit_ = {};
  }
  if (!draw_error_.empty()) {
    ImGui::SetCursorScreenPos(ImVec2(origin.x + 8, origin.y + h - 2 * ImGui::GetTextLineHeight()));
    ImGui::TextColored(kRuleColor, "%s", support::terminal_safe(draw_error_).c_str());
  }
  if (!any) {
    ImGui::SetCursorScreenPos(ImVec2(origin.x + 8, origin.y + 8));
    ImGui::TextColored(kDimColor, "this lab draws no 3D scene");
  }
  ImGui::End();
}

std::optional<render::Plot2D> Explorer::shown_plot() const {
  const lab::Animation* motion = session_->animation();
  const bool strip = motion != nullptr && motion->strip;
  const auto names = choices_of(*session_, false, strip);
  if (names.empty()) return std::nullopt;
  const std::size_t k = std::min<std::size_t>(plot_choice_, names.size() - 1);
  if (strip && k == 0) return motion->strip(time_);
  render::Plot2D plot = std::get<render::Plot2D>(figure_named(*session_, names[k])->figure);
  return plot;
}

void Explorer::plot_view(float x, float y, float w, float h) {
  const auto [pw, ph] = begin_view("Plot", x, y, w, h);
  const lab::Animation* motion = session_->animation();
  // the motion's strip is drawn again as it plays; another plot once, its time cursor
  // laid over it
  const bool strip = motion != nullptr && motion->strip && plot_choice_ == 0;
  const Drawn want{session_->generation(), plot_choice_, pw, ph, strip ? time_ : 0.0, {}, true};
  const Drawn& had = plot_drawn_;
  const bool stale = !had.valid || had.generation != want.generation || had.choice != want.choice ||
                     had.width != pw || had.height != ph || had.time != want.time;
  if (stale) {
    const std::optional<render::Plot2D> plot = shown_plot();
    cursors_.clear();
    if (plot) {
      try {
        plot_image_.draw(*plot, pw, ph);
        // where the panels against the motion's time are, for the cursor
        if (motion != nullptr && !strip) {
          const render::Plot2D::Layout layout = render::layout(*plot, pw, ph);
          for (int r = 0, k = 0; r < plot->rows(); ++r) {
            for (int c = 0; c < plot->cols(); ++c, ++k) {
              const render::Axis& x = plot->panel(r, c).x;
              if (x.motion_time && x.scale == render::Scale::kLinear) {
                const auto& p = layout.panels[k];
                cursors_.push_back({p.frame, p.x_lo, p.x_hi});
              }
            }
          }
        }
      } catch (const std::exception& e) {
        draw_error_ = e.what();
      }
    }
    plot_drawn_ = want;
    plot_drawn_.valid = plot.has_value();
  }
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  if (plot_drawn_.valid && plot_image_.texture() != 0) {
    ImDrawList* list = ImGui::GetWindowDrawList();
    list->AddImage(
        reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(plot_image_.texture())), origin,
        ImVec2(origin.x + w, origin.y + h), ImVec2(0, 1), ImVec2(1, 0));
    const float sx = w / static_cast<float>(pw), sy = h / static_cast<float>(ph);
    for (const Cursor& c : cursors_) {
      if (!(time_ >= c.x_lo && time_ <= c.x_hi) || !(c.x_hi > c.x_lo)) continue;
      const double px = c.frame.x0 + (time_ - c.x_lo) / (c.x_hi - c.x_lo) * c.frame.width();
      const float X = origin.x + static_cast<float>(px) * sx;
      list->AddLine(ImVec2(X, origin.y + static_cast<float>(c.frame.y0) * sy),
                    ImVec2(X, origin.y + static_cast<float>(c.frame.y1) * sy),
                    IM_COL32(0, 0, 0, 255), 2.0f);
    }
  } else {
    ImGui::SetCursorScreenPos(ImVec2(origin.x + 8, origin.y + 8));
    ImGui::TextColored(kDimColor, "this lab draws no plot");
  }
  ImGui::End();
}

void Explorer::time_panel(float x, float y, float w, float h) {
  ImGui::SetNextWindowPos(ImVec2(x, y));
  ImGui::SetNextWindowSize(ImVec2(w, h));
  ImGui::Begin(
      "Time", nullptr,
      ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings);
  const lab::Animation* motion = session_->animation();
  // what the two views show
  const auto scenes = choices_of(*session_, true, motion != nullptr);
  const auto plots = choices_of(*session_, false, motion != nullptr && motion->strip);
  const auto combo = [](const char* id, const std::vector<std::string>& names, int& choice,
                        float width) {
    if (names.empty()) return;
    choice = std::min<int>(choice, static_cast<int>(names.size()) - 1);
    ImGui::SetNextItemWidth(width);
    if (ImGui::BeginCombo(id, names[choice].c_str())) {
      for (int k = 0; k < static_cast<int>(names.size()); ++k) {
        if (ImGui::Selectable(names[k].c_str(), k == choice)) choice = k;
      }
      ImGui::EndCombo();
    }
  };
  if (motion != nullptr) {
    if (ImGui::Button(playing_ ? "Pause" : "Play", ImVec2(60, 0))) playing_ = !playing_;
    ImGui::SameLine();
    if (ImGui::ArrowButton("back", ImGuiDir_Left))
      time_ = std::max(0.0, time_ - kScriptFrameSeconds * speed_);
    ImGui::SameLine();
    if (ImGui::ArrowButton("on", ImGuiDir_Right))
      time_ = std::min(motion->seconds, time_ + kScriptFrameSeconds * speed_);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(std::max(80.0f, ImGui::GetContentRegionAvail().x - 130.0f));
    double t = time_, lo = 0.0, hi = motion->seconds;
    if (ImGui::SliderScalar("##time", ImGuiDataType_Double, &t, &lo, &hi, "t = %.3f s",
                            ImGuiSliderFlags_AlwaysClamp)) {
      time_ = t;
    }
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1);
    double s = speed_, slo = kMinSpeed, shi = fastest(*motion);
    if (ImGui::SliderScalar("##speed", ImGuiDataType_Double, &s, &slo, &shi, "%.2gx",
                            ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_Logarithmic)) {
      speed_ = s;
    }
  } else {
    ImGui::TextColored(kDimColor, "no motion: the figures follow the inputs");
  }
  ImGui::TextUnformatted("scene");
  ImGui::SameLine();
  combo("##scene", scenes, scene_choice_, w * 0.30f);
  ImGui::SameLine();
  // each part of the scene shown or not (its legend entry); keys 1 to 9 as well
  const std::vector<std::string> parts = scene_parts();
  if (ImGui::Button("Show")) ImGui::OpenPopup("parts");
  if (ImGui::BeginPopup("parts")) {
    for (std::size_t k = 0; k < parts.size(); ++k) {
      bool on = std::find(hidden_.begin(), hidden_.end(), parts[k]) == hidden_.end();
      const std::string label =
          (k < 9 ? std::to_string(k + 1) + "  " : std::string("   ")) + parts[k];
      if (ImGui::Checkbox(label.c_str(), &on)) toggle(parts[k]);
    }
    ImGui::EndPopup();
  }
  if (!ImGui::GetIO().WantTextInput) {
    for (std::size_t k = 0; k < std::min<std::size_t>(parts.size(), 9); ++k) {
      // (Dear ImGui 1.86 names no digit keys: the windowing backend's own codes, which
      // for GLFW's digits are their characters)
      if (ImGui::IsKeyPressed('1' + static_cast<int>(k), false)) toggle(parts[k]);
    }
  }
  ImGui::SameLine();
  ImGui::TextUnformatted("plot");
  ImGui::SameLine();
  combo("##plot", plots, plot_choice_, w * 0.30f);
  ImGui::End();
}

// ---- exports -----------------------------------------------------------------

void Explorer::export_section() {
  ImGui::Separator();
  ImGui::TextColored(kHeadingColor, "Export");
  const auto& figures = session_->figures();
  if (!figures.empty()) {
    export_figure_ = std::min<int>(export_figure_, static_cast<int>(figures.size()) - 1);
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.62f);
    if (ImGui::BeginCombo("##figure", figures[export_figure_].name.c_str())) {
      for (int k = 0; k < static_cast<int>(figures.size()); ++k) {
        if (ImGui::Selectable(figures[k].name.c_str(), k == export_figure_)) export_figure_ = k;
      }
      ImGui::EndCombo();
    }
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1);
    ImGui::InputText("##size", &figure_size_);
  }
  ImGui::SetNextItemWidth(-1);
  ImGui::InputTextWithHint("##path", "file (empty: named after the lab, here)", &export_path_);
  const auto path_or = [this](const std::string& fallback) {
    return export_path_.empty() ? fallback : export_path_;
  };
  const auto done = [this](const std::string& error, const std::string& path) {
    if (error.empty()) {
      say("wrote " + support::terminal_safe(path));
    } else {
      say(support::terminal_safe(error), true);
    }
  };
  int w = 0, h = 0;
  const bool size_ok = read_figure_size(figure_size_, w, h);
  if (!figures.empty()) {
    // the figure as a PNG, or as vectors for slides and papers
    for (const render::FigureFormat format :
         {render::FigureFormat::kPng, render::FigureFormat::kSvg, render::FigureFormat::kPdf}) {
      const std::string ext(render::figure_format_name(format));
      std::string label = ext;
      for (char& c : label) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      if (ImGui::Button(label.c_str())) {
        const std::string name = figures[export_figure_].name;
        const std::string path = path_or(session_->name() + "_" + name + "." + ext);
        done(size_ok ? save_figure(name, path, format, w, h) : kFigureSizeRule, path);
      }
      ImGui::SameLine();
    }
  }
  if (ImGui::Button("View PNG")) {
    const std::string path = path_or(session_->name() + "_view.png");
    done(size_ok ? save_view(path, w, h) : kFigureSizeRule, path);
  }
  // the numbers and the motion on a line of their own: the figures' row is full
  if (ImGui::Button("JSON")) {
    const std::string path = path_or(session_->name() + ".json");
    done(export_json(path), path);
  }
  if (session_->has_time_series()) {
    ImGui::SameLine();
    if (ImGui::Button("CSV")) {
      const std::string path = path_or(session_->name() + ".csv");
      done(export_csv(path), path);
    }
  }
  if (session_->animation() != nullptr) {
    ImGui::SameLine();
    if (recording_) ImGui::BeginDisabled();
    if (ImGui::Button("MP4/WebP")) {
      const std::string path = path_or(session_->name() + ".mp4");
      if (std::string error = record(path); !error.empty()) say(error, true);
    }
    if (recording_) ImGui::EndDisabled();
  }
  if (ImGui::Button("Copy command")) {
    const std::string command = command_line();
    if (window_.set_clipboard) window_.set_clipboard(command);
    say(command);
  }
  if (!message_.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, message_error_ ? kRuleColor : kDimColor);
    ImGui::TextWrapped("%s", message_.c_str());
    ImGui::PopStyleColor();
  }
  if (recording_) ImGui::TextColored(kDimColor, "recording %s ...", recording_->path.c_str());
}

std::string Explorer::json_text() const {
  session_->wait();  // the numbers the command line prints, the whole report's
  // the command line that reproduces it, as the command's own JSON names its argv
  lab::RunOutputs outputs;
  outputs.command.push_back(session_->name());
  for (const std::string& a : session_->arguments()) outputs.command.push_back(a);
  std::ostringstream text;
  lab::write_json(text, session_->report(), outputs, RIGID_VERSION);
  return text.str();
}

std::string Explorer::command_line() const {
  std::string line = session_->name();
  for (const std::string& a : session_->arguments()) line += " " + shell_word(a);
  return line;
}

std::string Explorer::save_figure(const std::string& name, const std::string& path,
                                  render::FigureFormat format, int w, int h) {
  session_->wait();  // the figure the command line draws, from the whole report
  const lab::NamedFigure* f = figure_named(*session_, name);
  if (f == nullptr) return "save-figure: " + session_->name() + " has no figure named " + name;
  try {
    std::visit([&](const auto& figure) { render::save_figure(figure, path, format, w, h); },
               f->figure);
  } catch (const std::exception& e) {
    return std::string(e.what());
  }
  return "";
}

std::string Explorer::save_view(const std::string& path, int w, int h) {
  if (shown_scene() == nullptr) return "this lab draws no 3D scene";
  try {
    render::Scene3D scene = view_scene(w, h);
    render::save_png(scene, path, w, h);
  } catch (const std::exception& e) {
    return std::string(e.what());
  }
  return "";
}

std::string Explorer::export_json(const std::string& path) {
  const std::string s = json_text();
  try {
    render::write_file_atomically(
        path, [&](std::FILE* file) { std::fwrite(s.data(), 1, s.size(), file); });
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

std::string Explorer::export_csv(const std::string& path) {
  session_->wait();
  const lab::TimeSeries& series = session_->report().time_series();
  if (series.columns.empty()) return "this run has no time series";
  const std::string s = lab::csv_text(series);
  try {
    render::write_file_atomically(
        path, [&](std::FILE* file) { std::fwrite(s.data(), 1, s.size(), file); });
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

// The lab's own command writes the animation (`LAB ARGS --animate FILE --quiet`), so
// the file is the command line's, byte for byte, and the window goes on meanwhile.
std::string Explorer::record(const std::string& path) {
  if (recording_) return "a recording is under way";
  const std::string program = support::program_path(session_->name(), "labs").string();
  std::vector<std::string> args{program};
  for (const std::string& a : session_->arguments()) args.push_back(a);
  for (const char* a : {"--animate", "--quiet"}) args.emplace_back(a);
  args.insert(args.end() - 1, path);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  int err[2];
  if (::pipe2(err, O_CLOEXEC | O_NONBLOCK) != 0) return "record: cannot make a pipe";
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, err[1], STDERR_FILENO);
  pid_t pid = 0;
  const int spawned = ::posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(err[1]);
  if (spawned != 0) {
    ::close(err[0]);
    return "record: cannot run " + support::terminal_safe(program);
  }
  recording_ = std::make_unique<Recording>();
  recording_->pid = pid;
  recording_->path = path;
  recording_->err_fd = err[0];
  say("recording " + support::terminal_safe(path) + " ...");
  return "";
}

void Explorer::after_render() {
  if (screenshot_path_.empty()) return;
  const std::string path = std::move(screenshot_path_);
  screenshot_path_.clear();
  try {
    render::write_png(window_.read_frame(), path);
    say("wrote " + support::terminal_safe(path));
  } catch (const std::exception& e) {
    say(std::string("screenshot: ") + e.what(), true);
    if (script_) status_ = 1;
  }
}

void Explorer::step_script() {
  if (script_ && !script_->step(*this)) {
    if (script_->failed()) status_ = 1;
    script_.reset();
    if (window_.close) window_.close();
  }
}

}  // namespace rigid::explore
