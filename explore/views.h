// The explorer's two views, between the panels: the scene (the motion or a 3D figure,
// turned by the mouse) over the time bar, and the plot (the motion's strip or a 2D
// figure, with the time cursor) under it. Each is drawn by render_gl into a texture of
// the window's context, again only when what it shows has changed.
#pragma once

#include <imgui.h>

#include <string>
#include <vector>

#include "actions.h"
#include "common/session.h"
#include "rigid/render/live.h"
#include "rigid/render/rect.h"
#include "scene_cache.h"
#include "view_state.h"

namespace rigid::explore {

/// Where a view is in the window, in its points.
struct ViewRect {
  float x = 0, y = 0, w = 0, h = 0;
};

class Views {
 public:
  /// Forgets what was drawn (another lab is shown).
  void reset();
  /// The scene view; the mouse's turns and zooms are queued.
  void scene(const lab::Session& s, const ViewState& v, SceneCache& cache, ViewRect at,
             std::vector<Action>& queue);
  /// The plot view.
  void plot(const lab::Session& s, const ViewState& v, ViewRect at);
  /// The scene's texture as last drawn (what the window shows of it).
  render::Image scene_pixels() const { return scene_image_.read(); }
  /// Where the views' time went in the last frame: the scene made (the motion at the time,
  /// the envelope its camera is fitted to) and seen through the camera (the CPU's), then its
  /// drawing's phases, each waited for (so only when asked: timed(true)), and the plot made and
  /// drawn; zero where a frame drew neither.
  struct SceneTiming {
    double scene = 0;
    render::FigureTiming drawing;
    double plot = 0;
    double total() const { return scene + drawing.total() + plot; }
  };
  void timed(bool on) { timed_ = on; }
  const SceneTiming& scene_timing() const { return scene_timing_; }

 private:
  // What a view's texture was drawn from: it is drawn again when this changes.
  using Drawn = DrawnFrom;
  // The plot's panels against the motion's time: where the time cursor goes.
  void legend_button(const ViewState& v, ImVec2 origin, ViewRect at,
                     std::vector<Action>& queue) const;
  void draw_plot(const lab::Session& s, const ViewState& v, int width, int height);
  render::LiveImage scene_image_, plot_image_;
  render::ScreenRect legend_box_;  ///< the scene's legend as drawn, framebuffer pixels
  Drawn scene_drawn_, plot_drawn_;
  std::vector<TimeCursor> cursors_;
  std::string draw_error_;
  bool timed_ = false;
  SceneTiming scene_timing_;
};

}  // namespace rigid::explore
