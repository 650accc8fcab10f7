// The scene and plot views (views.h).
#include "views.h"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <utility>

#include "rigid/render/draw.h"
#include "rigid/support/text.h"
#include "style.h"

namespace rigid::explore {

namespace {

// A window for a figure's image at `at`, without padding or decoration; the image's
// size in pixels of the framebuffer.
std::pair<int, int> begin_view(const char* name, ViewRect at) {
  ImGui::SetNextWindowPos(ImVec2(at.x, at.y));
  ImGui::SetNextWindowSize(ImVec2(at.w, at.h));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::Begin(name, nullptr, kPanel | ImGuiWindowFlags_NoDecoration);
  ImGui::PopStyleVar();
  const ImGuiIO& io = ImGui::GetIO();
  return {std::max(16, static_cast<int>(at.w * io.DisplayFramebufferScale.x)),
          std::max(16, static_cast<int>(at.h * io.DisplayFramebufferScale.y))};
}

// The smallest text of a figure in a view, in the framebuffer's pixels.
double figure_text_px() {
  return kFigureTextPx * ui_scale() * ImGui::GetIO().DisplayFramebufferScale.y;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// GL's rows run bottom-up: the texture is shown flipped.
void show_texture(unsigned texture, ImVec2 origin, ViewRect at) {
  ImGui::GetWindowDrawList()->AddImage(
      reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(texture)), origin,
      ImVec2(origin.x + at.w, origin.y + at.h), ImVec2(0, 1), ImVec2(1, 0));
}

}  // namespace

void Views::reset() {
  scene_drawn_ = plot_drawn_ = Drawn{};
  cursors_.clear();
  draw_error_.clear();
}

// The legend collapses to a button and opens again from it (or the key L): a turn of
// the view may bring the scene under it.
void Views::legend_button(const ViewState& v, ImVec2 origin, ViewRect at,
                          std::vector<Action>& queue) const {
  const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
  const bool open = v.legend && !legend_box_.empty();
  const char* text = open ? "hide##legend" : "legend";
  const float w =
      ImGui::CalcTextSize(open ? "hide" : text).x + 2 * ImGui::GetStyle().FramePadding.x;
  // under the legend at its right, or in the view's top right corner
  const float right =
      open ? origin.x + static_cast<float>(legend_box_.x1) / scale.x : origin.x + at.w - 8;
  const float top =
      open ? origin.y + static_cast<float>(legend_box_.y1) / scale.y + 2 : origin.y + 8;
  ImGui::SetCursorScreenPos(ImVec2(right - w, top));
  if (ImGui::SmallButton(text)) queue.emplace_back(action::ToggleLegend{});
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(open ? "collapse the legend (key L)" : "show the legend (key L)");
}

void Views::scene(const lab::Session& s, const ViewState& v, SceneCache& cache, ViewRect at,
                  std::vector<Action>& queue) {
  const auto [pw, ph] = begin_view("Scene", at);
  const ImGuiIO& io = ImGui::GetIO();
  const auto start = std::chrono::steady_clock::now();
  const bool any = cache.shown(s, v) != nullptr;
  scene_timing_.scene = 0;
  scene_timing_.drawing = {};
  if (any) {
    const Drawn want{s.generation(),   v.scene_choice,   pw,  ph, v.time, v.orbit,
                     v.hidden_version, figure_text_px(), true};
    if (!(scene_drawn_.valid && scene_drawn_ == want)) {
      try {
        render::Scene3D scene = cache.view_scene(s, v, pw, ph);
        scene.min_text_px = figure_text_px();
        if (timed_) scene_timing_.scene = seconds_since(start);
        legend_box_ =
            scene_image_.draw(scene, pw, ph, timed_ ? &scene_timing_.drawing : nullptr).legend;
        draw_error_.clear();
      } catch (const std::exception& e) {
        draw_error_ = e.what();
      }
      scene_drawn_ = want;
    }
  }
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("view", ImVec2(at.w, at.h));
  if (any && scene_image_.texture() != 0) show_texture(scene_image_.texture(), origin, at);
  // the mouse turns the view, the wheel zooms, a double click resets it
  if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f)) {
    queue.emplace_back(action::MouseTurn{io.MouseDelta.x, io.MouseDelta.y, at.h});
  }
  if (ImGui::IsItemHovered()) {
    if (io.MouseWheel != 0.0f) queue.emplace_back(action::Wheel{io.MouseWheel});
    if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) queue.emplace_back(action::ResetView{});
  }
  if (any) legend_button(v, origin, at, queue);
  if (!draw_error_.empty()) {
    ImGui::SetCursorScreenPos(
        ImVec2(origin.x + 8, origin.y + at.h - 2 * ImGui::GetTextLineHeight()));
    ImGui::TextColored(kRuleColor, "%s", support::terminal_safe(draw_error_).c_str());
  }
  if (!any) {
    ImGui::SetCursorScreenPos(ImVec2(origin.x + 8, origin.y + 8));
    ImGui::TextColored(kDimColor, "this lab draws no 3D scene");
  }
  ImGui::End();
}

void Views::draw_plot(const lab::Session& s, const ViewState& v, int width, int height) {
  std::optional<render::Plot2D> plot = shown_plot(s, v);
  cursors_.clear();
  plot_drawn_.valid = plot.has_value();
  if (!plot) return;
  plot->min_text_px = figure_text_px();
  try {
    // timed, the drawing is waited for (its phases are the plot's one time)
    render::FigureTiming waited;
    const render::Plot2D::Layout drawn =
        plot_image_.draw(*plot, width, height, timed_ ? &waited : nullptr);
    // where the panels against the motion's time are, for the cursor
    if (s.animation() == nullptr) return;
    cursors_ = time_cursors(*plot, drawn);
  } catch (const std::exception& e) {
    draw_error_ = e.what();
  }
}

void Views::plot(const lab::Session& s, const ViewState& v, ViewRect at) {
  const auto [pw, ph] = begin_view("Plot", at);
  // drawn once (the motion's strip too), the motion's time cursor laid over it
  const Drawn want{s.generation(), v.plot_choice, pw, ph, 0.0, {}, 0, figure_text_px(), true};
  scene_timing_.plot = 0;
  if (!(plot_drawn_.valid && plot_drawn_ == want)) {
    const auto start = std::chrono::steady_clock::now();
    draw_plot(s, v, pw, ph);
    if (timed_) scene_timing_.plot = seconds_since(start);
    const bool valid = plot_drawn_.valid;
    plot_drawn_ = want;
    plot_drawn_.valid = valid;
  }
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  if (plot_drawn_.valid && plot_image_.texture() != 0) {
    show_texture(plot_image_.texture(), origin, at);
    const float sx = at.w / static_cast<float>(pw), sy = at.h / static_cast<float>(ph);
    for (const TimeCursor& c : cursors_) {
      const std::optional<double> px = c.x_at(v.time);
      if (!px) continue;
      const float X = origin.x + static_cast<float>(*px) * sx;
      ImGui::GetWindowDrawList()->AddLine(ImVec2(X, origin.y + static_cast<float>(c.frame.y0) * sy),
                                          ImVec2(X, origin.y + static_cast<float>(c.frame.y1) * sy),
                                          IM_COL32(0, 0, 0, 255), 2.0f);
    }
  } else {
    ImGui::SetCursorScreenPos(ImVec2(origin.x + 8, origin.y + 8));
    ImGui::TextColored(kDimColor, "this lab draws no plot");
  }
  ImGui::End();
}

}  // namespace rigid::explore
