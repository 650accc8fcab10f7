// What the explorer's scene view shows, made from the lab's session and the view's
// state and kept while they stay the same: the motion's scene at the time shown (a
// frame asks for it more than once), the whole motion's envelope (what the camera is
// fitted to, and the legend every frame keeps), the exact motion laid faintly over an
// integrator's, and the camera fitted to the figure. Apart from the view's state, so
// that ViewState stays what the user sees and set.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/session.h"
#include "rigid/render/plot2d.h"
#include "rigid/render/rect.h"
#include "view_state.h"

namespace rigid::explore {

/// The legend entry of the exact motion laid faintly over an integrator's.
extern const char* const kExactGhost;

/// The names a view offers: the motion first ("motion", "the motion's strip") where the
/// lab has one, then the lab's figures of the kind (3D scenes or 2D plots).
std::vector<std::string> view_choices(const lab::Session& s, bool scenes);
/// The lab's figure named `name`, described alone (Session::figure), or nullptr.
const lab::NamedFigure* figure_named(const lab::Session& s, const std::string& name);
/// The plot shown: the motion's strip at the time shown, or a 2D figure; none if none.
std::optional<render::Plot2D> shown_plot(const lab::Session& s, const ViewState& v);

/// Where a plot's panel against the motion's time lies in its image at a size: its frame
/// and the times at its two ends. A view draws the time shown as a line across it.
struct TimeCursor {
  render::ScreenRect frame;
  double x_lo = 0, x_hi = 1;
  /// The image's x of time t, or nothing where t is outside the panel.
  std::optional<double> x_at(double t) const {
    if (!(t >= x_lo && t <= x_hi) || !(x_hi > x_lo)) return std::nullopt;
    return frame.x0 + (t - x_lo) / (x_hi - x_lo) * frame.width();
  }
};
/// The time cursors of `plot` as drawn (`layout`, what its drawing gave back): a panel each
/// whose x axis is the motion's time on a linear scale.
std::vector<TimeCursor> time_cursors(const render::Plot2D& plot,
                                     const render::Plot2D::Layout& layout);

/// What a view's image was drawn from: it is drawn again when any of it changes (a frame
/// that only lays the same image out again draws nothing).
struct DrawnFrom {
  long generation = -1;  ///< the session's
  int choice = -1, width = 0, height = 0;
  double time = -1.0;  ///< the time shown, where the image shows one
  Orbit orbit;         ///< a scene's
  long hidden = 0;     ///< ViewState::hidden_version, a scene's
  double text_px = 0;  ///< the figure's least text
  bool valid = false;  ///< false: nothing drawn yet, or the drawing failed (not compared)
  bool operator==(const DrawnFrom& o) const {
    return generation == o.generation && choice == o.choice && width == o.width &&
           height == o.height && time == o.time && orbit.yaw_deg == o.orbit.yaw_deg &&
           orbit.pitch_deg == o.orbit.pitch_deg && orbit.zoom == o.orbit.zoom &&
           hidden == o.hidden && text_px == o.text_px;
  }
};

class SceneCache {
 public:
  /// Forgets everything (another lab is shown).
  void reset() { *this = SceneCache(); }
  /// The scene shown (the motion at the time shown, or a 3D figure); nullptr if none.
  const render::Scene3D* shown(const lab::Session& s, const ViewState& v);
  /// The scene shown, its hidden parts left out, seen through the view's orbit at a size.
  render::Scene3D view_scene(const lab::Session& s, const ViewState& v, int width, int height);
  /// The parts of the scene shown that can be shown or hidden: its legend's entries.
  std::vector<std::string> parts(const lab::Session& s, const ViewState& v);

 private:
  struct MotionScene {
    long generation = -1;
    double time = -1.0;
    render::Scene3D scene;
  };
  struct Envelope {
    long generation = -1;
    std::shared_ptr<const render::Scene3D> scene, legend;
  };
  struct Fit {
    long generation = -1;
    int choice = -1, width = 0, height = 0;
    render::Camera camera;
  };
  const Envelope& envelope(const lab::Session& s, const ViewState& v);
  const lab::Animation* exact_motion(const lab::Session& s);
  render::Camera base_camera(const lab::Session& s, const ViewState& v, int width, int height);

  MotionScene motion_scene_;
  Envelope envelope_;
  Fit fit_;
  // the exact motion beside an integrator's, for the inputs of exact_generation_
  std::unique_ptr<lab::Session> exact_session_;
  long exact_generation_ = -1;
};

}  // namespace rigid::explore
