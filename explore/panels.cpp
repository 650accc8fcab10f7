// The explorer's panels (panels.h).
#include "panels.h"

#include <fmt/format.h>
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include "common/writers.h"
#include "rigid/support/text.h"
#include "scene_cache.h"
#include "style.h"
#include "text_wrap.h"

namespace rigid::explore {

using lab::InputKind;
using lab::InputRule;
using lab::InputValue;

namespace {

// Text wrapped to the space left, at its blanks only: a number is never broken.
void text_wrapped(const std::string& text) {
  const auto measure = [](std::string_view line) {
    return ImGui::CalcTextSize(line.data(), line.data() + line.size()).x;
  };
  ImGui::BeginGroup();
  for (const std::string& line : wrap_lines(text, ImGui::GetContentRegionAvail().x, measure))
    ImGui::TextUnformatted(line.c_str());
  ImGui::EndGroup();
}

// A number input: its slider (where it has a value) beside its field.
void number_widget(const PanelContext& c, std::size_t i, const InputValue& value) {
  const InputRule& r = c.session.rule(i);
  double x = std::get<double>(value);
  const InputValue book = c.session.textbook_value(i);
  const double textbook = std::holds_alternative<double>(book) ? std::get<double>(book) : x;
  const lab::SliderSpan span = lab::slider_span(r, textbook);
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
  ImGuiSliderFlags flags = ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_NoInput;
  if (span.log) flags |= ImGuiSliderFlags_Logarithmic;
  if (ImGui::SliderScalar("##slider", ImGuiDataType_Double, &x, &span.lo, &span.hi, "%.4g",
                          flags)) {
    c.queue.emplace_back(action::SetValue{i, x});
  }
  // the slider's ends; a value beyond them is typed in the field
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("%s", fmt::format("{:.4g} to {:.4g}{}; type any value the rule allows "
                                        "in the field",
                                        span.lo, span.hi, span.log ? ", logarithmic" : "")
                                .c_str());
  }
  // a slider held: the frames show the new inputs with the camera kept
  if (ImGui::IsItemActive()) c.view.interacting = true;
  ImGui::SameLine();
}

// A pair or vector input: its numbers dragged (where it has numbers).
void numbers_widget(const PanelContext& c, std::size_t i, const InputValue& value) {
  const int n = c.session.rule(i).kind() == InputKind::kVector ? 3 : 2;
  double v[3] = {0, 0, 0};
  if (const auto* p = std::get_if<Eigen::Vector3d>(&value)) {
    v[0] = (*p)[0], v[1] = (*p)[1], v[2] = (*p)[2];
  } else if (const auto* p = std::get_if<Eigen::Vector2d>(&value)) {
    v[0] = (*p)[0], v[1] = (*p)[1];
  } else {
    return;
  }
  // a drag's speed: a hundredth of the largest component per pixel
  double size = 0;
  for (int k = 0; k < n; ++k) size = std::max(size, std::abs(v[k]));
  const float speed = static_cast<float>(size > 0 ? size / 100 : 0.01);
  ImGui::SetNextItemWidth(-1);
  if (ImGui::DragScalarN("##drag", ImGuiDataType_Double, v, n, speed, nullptr, nullptr, "%.4g")) {
    c.queue.emplace_back(action::SetValue{i, n == 3 ? InputValue(Eigen::Vector3d(v[0], v[1], v[2]))
                                                    : InputValue(Eigen::Vector2d(v[0], v[1]))});
  }
  if (ImGui::IsItemActive()) c.view.interacting = true;
}

// One input: its label, its widget and field, and the rule it broke.
void input_widget(const PanelContext& c, std::size_t i) {
  const InputRule& r = c.session.rule(i);
  Field& field = c.view.fields[i];
  const InputValue value = c.session.value(i);
  const bool optional = !r.lab_default_text().empty();
  const bool absent = std::holds_alternative<std::monostate>(value);
  ImGui::PushID(static_cast<int>(i));
  std::string label = r.help();
  if (!r.unit_text().empty()) label += " [" + r.unit_text() + "]";
  text_wrapped(label);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", r.flag().c_str());
  // the typed text is taken on Enter, or when the field is left edited
  const auto text_field = [&](const char* hint) {
    ImGui::SetNextItemWidth(-1);
    const bool entered =
        ImGui::InputTextWithHint("##text", hint, &field.text, ImGuiInputTextFlags_EnterReturnsTrue);
    if (entered || ImGui::IsItemDeactivatedAfterEdit())
      c.queue.emplace_back(action::SetText{r.flag(), field.text});
  };
  const std::string lab_default = "the lab's: " + r.lab_default_text();
  switch (r.kind()) {
    case InputKind::kNumber:
      if (!absent) number_widget(c, i, value);
      text_field(optional ? lab_default.c_str() : "");
      break;
    case InputKind::kPair:
    case InputKind::kVector:
      numbers_widget(c, i, value);
      text_field(optional
                     ? lab_default.c_str()
                     : (r.word_names().empty() ? "X,Y,Z" : ("X,Y,Z or " + r.word_list()).c_str()));
      break;
    case InputKind::kChoice: {
      const std::string current = absent ? lab_default : std::get<std::string>(value);
      ImGui::SetNextItemWidth(-1);
      if (ImGui::BeginCombo("##choice", current.c_str())) {
        for (const std::string& choice : r.choices()) {
          if (ImGui::Selectable(choice.c_str(), choice == current))
            c.queue.emplace_back(action::SetValue{i, choice});
        }
        ImGui::EndCombo();
      }
      break;
    }
    case InputKind::kFlag: {
      bool on = !absent && std::get<bool>(value);
      if (ImGui::Checkbox(r.flag().c_str(), &on)) c.queue.emplace_back(action::SetValue{i, on});
      break;
    }
  }
  if (optional && !absent) {
    if (ImGui::SmallButton("use the lab's")) c.queue.emplace_back(action::SetValue{i, {}});
  }
  if (!field.refusal.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kRuleColor);
    text_wrapped(support::terminal_safe(field.refusal));
    ImGui::PopStyleColor();
  }
  ImGui::Spacing();
  ImGui::PopID();
}

// The panel's head: the lab chosen, its title, the textbook's example.
void lab_heading(const PanelContext& c) {
  const lab::Session& s = c.session;
  ImGui::PushStyleColor(ImGuiCol_Text, kHeadingColor);
  ImGui::TextUnformatted("rigidlab explore");
  ImGui::PopStyleColor();
  ImGui::SetNextItemWidth(-1);
  if (ImGui::BeginCombo("##lab", s.name().c_str())) {
    for (const lab::LabEntry& entry : c.labs) {
      if (ImGui::Selectable(entry.name.c_str(), entry.name == s.name()))
        c.queue.emplace_back(action::OpenLab{entry.name});
    }
    ImGui::EndCombo();
  }
  ImGui::PushStyleColor(ImGuiCol_Text, kDimColor);
  text_wrapped(s.title());
  ImGui::PopStyleColor();
  const bool at_textbook = s.at_textbook();
  if (at_textbook) ImGui::BeginDisabled();
  // a lab whose section prints no numbers starts from its own defaults, and says so
  const bool example = s.has_textbook_example();
  if (ImGui::Button(example ? "Textbook example" : "Lab's defaults"))
    c.queue.emplace_back(action::Textbook{});
  if (at_textbook) ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::TextColored(kDimColor, !at_textbook ? ""
                                : example    ? "(the text's inputs)"
                                             : "(the text prints no numbers here)");
  ImGui::Separator();
}

// The figure chosen for export, and its size; whether the lab has figures. Named, none
// described: a change's frame need not describe them.
bool figure_choice(const PanelContext& c) {
  std::string& shown = c.view.export_figure_name;
  int& chosen = c.view.export_figure;
  const std::vector<lab::FigureName>& figures = c.session.figure_names();
  if (figures.empty()) return false;
  chosen = std::min<int>(chosen, static_cast<int>(figures.size()) - 1);
  shown = figures[chosen].name;
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.62f);
  if (ImGui::BeginCombo("##figure", shown.c_str())) {
    for (int k = 0; k < static_cast<int>(figures.size()); ++k) {
      if (ImGui::Selectable(figures[k].name.c_str(), k == chosen)) chosen = k;
    }
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1);
  ImGui::InputText("##size", &c.view.figure_size);
  return true;
}

void export_section(const PanelContext& c) {
  const lab::Session& s = c.session;
  ViewState& v = c.view;
  ImGui::Separator();
  ImGui::TextColored(kHeadingColor, "Export");
  const bool figures = figure_choice(c);
  ImGui::SetNextItemWidth(-1);
  ImGui::InputTextWithHint("##path", "file (empty: named after the lab, here)", &v.export_path);
  const auto path_or = [&](const std::string& fallback) {
    return v.export_path.empty() ? fallback : v.export_path;
  };
  if (figures) {
    // the figure as a PNG, or as vectors for slides and papers
    for (const render::FigureFormat format :
         {render::FigureFormat::kPng, render::FigureFormat::kSvg, render::FigureFormat::kPdf}) {
      const std::string ext(render::figure_format_name(format));
      std::string label = ext;
      for (char& ch : label) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
      if (ImGui::Button(label.c_str())) {
        const std::string name = s.figure_names()[v.export_figure].name;
        c.queue.emplace_back(action::SaveFigure{name, path_or(s.name() + "_" + name + "." + ext),
                                                format, v.figure_size});
      }
      ImGui::SameLine();
    }
  }
  if (ImGui::Button("View PNG"))
    c.queue.emplace_back(action::SaveView{path_or(s.name() + "_view.png"), v.figure_size});
  // the numbers and the motion on a line of their own: the figures' row is full
  if (ImGui::Button("JSON")) c.queue.emplace_back(action::ExportJson{path_or(s.name() + ".json")});
  if (s.has_time_series()) {
    ImGui::SameLine();
    if (ImGui::Button("CSV")) c.queue.emplace_back(action::ExportCsv{path_or(s.name() + ".csv")});
  }
  if (s.animation() != nullptr) {
    ImGui::SameLine();
    if (c.recording) ImGui::BeginDisabled();
    if (ImGui::Button("MP4/WebP")) c.queue.emplace_back(action::Record{path_or(s.name() + ".mp4")});
    if (c.recording) ImGui::EndDisabled();
  }
  if (ImGui::Button("Copy command")) c.queue.emplace_back(action::CopyCommand{});
  if (!v.message.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, v.message_error ? kRuleColor : kDimColor);
    text_wrapped(v.message);
    ImGui::PopStyleColor();
  }
  if (c.recording) ImGui::TextColored(kDimColor, "recording %s ...", c.recording_path);
}

}  // namespace

void inputs_panel(const PanelContext& c, float width, float height) {
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(ImVec2(width, height));
  ImGui::Begin("Inputs", nullptr, kPanel | ImGuiWindowFlags_NoTitleBar);
  lab_heading(c);
  ImGui::BeginChild("fields", ImVec2(0, -ImGui::GetFrameHeightWithSpacing() * 7.5f));
  bool numerical_heading = false;
  for (std::size_t i = 0; i < c.session.input_count(); ++i) {
    if (!c.session.rule(i).physical() && !numerical_heading) {
      numerical_heading = true;
      ImGui::Spacing();
      ImGui::TextColored(kHeadingColor, "Numerical method");
      ImGui::Separator();
    }
    input_widget(c, i);
  }
  ImGui::EndChild();
  export_section(c);
  ImGui::End();
}

namespace {

// A value shown just before: a click copies it (the number alone, to paste into a
// calculator); hovering says so, after what the row remarks.
void copyable(const std::string& value, const std::string& remark) {
  if (!ImGui::IsItemHovered()) return;
  ImGui::SetMouseCursor(ImGuiMouseCursor_Hand);
  if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) ImGui::SetClipboardText(value.c_str());
  ImGui::SetTooltip("%s%sclick to copy %s", remark.c_str(), remark.empty() ? "" : "\n",
                    value.c_str());
}

// The report's rows as the command line's table has them: each section's heading across
// the panel, its rows in three columns aligned from one section to the next.
void report_rows(const lab::Report& report) {
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
      text_wrapped(row.label);
      ImGui::PopStyleColor();
      begin_table();
      continue;
    }
    if (!open) continue;
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    text_wrapped(row.label);
    ImGui::TableSetColumnIndex(1);
    const std::string value = row.unit.empty() ? row.value : row.value + " " + row.unit;
    text_wrapped(value);
    copyable(row.value, row.remark);
    ImGui::TableSetColumnIndex(2);
    ImGui::PushStyleColor(ImGuiCol_Text, kDimColor);
    text_wrapped(row.textbook);
    ImGui::PopStyleColor();
  }
  if (open) ImGui::EndTable();
}

void wrapped(const ImVec4& colour, const std::string& text) {
  ImGui::PushStyleColor(ImGuiCol_Text, colour);
  text_wrapped(text);
  ImGui::PopStyleColor();
}

}  // namespace

void numbers_panel(const lab::Session& s, float x, float width, float height) {
  ImGui::SetNextWindowPos(ImVec2(x, 0));
  ImGui::SetNextWindowSize(ImVec2(width, height));
  ImGui::Begin("Numbers", nullptr, kPanel | ImGuiWindowFlags_NoTitleBar);
  const lab::Report& report = s.report();
  ImGui::TextColored(kHeadingColor, "%s", report.lab().c_str());
  ImGui::SameLine();
  ImGui::TextColored(kDimColor, report.textbook_inputs() ? "the text's values beside" : "");
  // the table as the command line prints it, to paste into notes (a value alone: a click)
  // at the right of the heading's line, or under it where the panel is too narrow
  const float button_w = ImGui::CalcTextSize("Copy table").x + 2 * ImGui::GetStyle().FramePadding.x;
  const float at = ImGui::GetWindowContentRegionMax().x - button_w;
  const float heading_end = ImGui::GetItemRectMax().x - ImGui::GetWindowPos().x;
  if (heading_end + ImGui::GetStyle().ItemSpacing.x <= at) {
    ImGui::SameLine(at);
  } else {
    ImGui::SetCursorPosX(at);
  }
  if (ImGui::SmallButton("Copy table")) {
    std::ostringstream table;
    lab::write_table(table, report, {});
    ImGui::SetClipboardText(table.str().c_str());
  }
  if (s.pending()) {
    ImGui::TextColored(kDimColor, "comparing every method with the exact motion ...");
  }
  if (!s.whole_error().empty()) {
    wrapped(kRuleColor,
            "the command line refuses these inputs: " + support::terminal_safe(s.whole_error()));
  }
  for (const std::string& w : report.warnings()) wrapped(kErrataColor, support::terminal_safe(w));
  const float notes_h = std::min(ImGui::GetContentRegionAvail().y * 0.35f,
                                 ImGui::GetTextLineHeightWithSpacing() *
                                     (1.0f + 2.5f * static_cast<float>(report.notes().size())));
  ImGui::BeginChild("rows", ImVec2(0, -notes_h));
  report_rows(report);
  ImGui::EndChild();
  ImGui::BeginChild("notes");
  for (const std::string& note : report.notes()) {
    const bool errata = note.rfind("errata", 0) == 0;
    wrapped(errata ? kErrataColor : kDimColor, support::terminal_safe(note));
  }
  ImGui::EndChild();
  ImGui::End();
}

namespace {

// A view's choice among its names (view_choices: none of the figures described), `width`
// wide.
void view_combo(const PanelContext& c, const char* id, bool scenes, int choice, float width) {
  const std::vector<std::string> names = view_choices(c.session, scenes);
  if (names.empty()) return;
  choice = std::min<int>(choice, static_cast<int>(names.size()) - 1);
  ImGui::SetNextItemWidth(width);
  if (ImGui::BeginCombo(id, names[choice].c_str())) {
    for (int k = 0; k < static_cast<int>(names.size()); ++k) {
      if (ImGui::Selectable(names[k].c_str(), k == choice))
        c.queue.emplace_back(action::Show{scenes, names[k]});
    }
    ImGui::EndCombo();
  }
}

// Play, a frame back and on, the time and the speed.
void motion_controls(const PanelContext& c, const lab::Animation& motion) {
  const ViewState& v = c.view;
  if (ImGui::Button(v.playing ? "Pause" : "Play", ImVec2(60, 0)))
    c.queue.emplace_back(action::TogglePlay{});
  ImGui::SameLine();
  if (ImGui::ArrowButton("back", ImGuiDir_Left)) c.queue.emplace_back(action::Step{-1});
  ImGui::SameLine();
  if (ImGui::ArrowButton("on", ImGuiDir_Right)) c.queue.emplace_back(action::Step{1});
  ImGui::SameLine();
  ImGui::SetNextItemWidth(std::max(80.0f, ImGui::GetContentRegionAvail().x - 130.0f));
  double t = v.time, lo = 0.0, hi = motion.seconds;
  if (ImGui::SliderScalar("##time", ImGuiDataType_Double, &t, &lo, &hi, "t = %.3f s",
                          ImGuiSliderFlags_AlwaysClamp)) {
    c.queue.emplace_back(action::Seek{t});
  }
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1);
  double speed = v.speed, slo = kMinSpeed, shi = fastest(motion);
  if (ImGui::SliderScalar("##speed", ImGuiDataType_Double, &speed, &slo, &shi, "%.2gx",
                          ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_Logarithmic)) {
    c.queue.emplace_back(action::Speed{speed});
  }
}

// Each part of the scene shown or not (its legend entry).
void parts_popup(const PanelContext& c) {
  if (ImGui::Button("Show")) ImGui::OpenPopup("parts");
  if (!ImGui::BeginPopup("parts")) return;
  const std::vector<std::string>& parts = c.scene_parts;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    bool on =
        std::find(c.view.hidden.begin(), c.view.hidden.end(), parts[k]) == c.view.hidden.end();
    const std::string label =
        (k < 9 ? std::to_string(k + 1) + "  " : std::string("   ")) + parts[k];
    if (ImGui::Checkbox(label.c_str(), &on)) c.queue.emplace_back(action::TogglePart{parts[k]});
  }
  ImGui::EndPopup();
}

}  // namespace

void time_panel(const PanelContext& c, float x, float y, float w, float h) {
  ImGui::SetNextWindowPos(ImVec2(x, y));
  ImGui::SetNextWindowSize(ImVec2(w, h));
  ImGui::Begin("Time", nullptr, kPanel | ImGuiWindowFlags_NoDecoration);
  if (const lab::Animation* motion = c.session.animation()) {
    motion_controls(c, *motion);
  } else {
    ImGui::TextColored(kDimColor, "no motion: the figures follow the inputs");
  }
  ImGui::TextUnformatted("scene");
  ImGui::SameLine();
  view_combo(c, "##scene", true, c.view.scene_choice, w * 0.30f);
  ImGui::SameLine();
  parts_popup(c);
  ImGui::SameLine();
  ImGui::TextUnformatted("plot");
  ImGui::SameLine();
  view_combo(c, "##plot", false, c.view.plot_choice, w * 0.30f);
  ImGui::End();
}

void keys(const PanelContext& c) {
  if (ImGui::GetIO().WantTextInput) return;
  // space plays and pauses, the arrows step a frame
  if (c.session.animation() != nullptr) {
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Space), false))
      c.queue.emplace_back(action::TogglePlay{});
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_RightArrow)))
      c.queue.emplace_back(action::Step{1});
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_LeftArrow)))
      c.queue.emplace_back(action::Step{-1});
  }
  if (ImGui::IsKeyPressed('L', false)) c.queue.emplace_back(action::ToggleLegend{});
  // the keys 1 to 9 show and hide the scene's parts
  for (std::size_t k = 0; k < std::min<std::size_t>(c.scene_parts.size(), 9); ++k) {
    // (Dear ImGui 1.86 names no digit keys: the windowing backend's own codes, which
    // for GLFW's digits are their characters)
    if (ImGui::IsKeyPressed('1' + static_cast<int>(k), false))
      c.queue.emplace_back(action::TogglePart{c.scene_parts[k]});
  }
}

}  // namespace rigid::explore
