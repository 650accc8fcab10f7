// The figure layer of the labs: a lab's figures.cpp builds each figure as a
// render description (a Plot2D or a Scene3D) and hands it to a sink with a name
// and a caption; a lab with motion describes it as an Animation. The sink owns
// everything else (the command line's: the GL context, the title, the size,
// atomic saving, the timing, the JSON listing). Figure code never sees a path,
// a context or a pixel offset.
#pragma once

#include <Eigen/Geometry>
#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "rigid/render/plot2d.h"
#include "rigid/render/scene3d.h"

namespace rigid::lab {

/// One colour per concept across every lab's figure : what a reader learns
/// in one figure holds in the next. Okabe-Ito, so colour-blind readers keep it too.
namespace colors {
inline constexpr render::Color kOmega = render::kBlue;    ///< omega, and its path
inline constexpr render::Color kL = render::kVermillion;  ///< L, and what is about L
/// Principal axes 1, 2, 3 (ascending moments, or the body's own numbering).
inline constexpr render::Color kPrincipal[3] = {render::kBluishGreen, render::kOrange,
                                                render::kReddishPurple};
/// A symmetric body's symmetry axis: its principal axis 3.
inline constexpr render::Color kSymmetryAxis = render::kReddishPurple;
inline constexpr render::Color kPolhode = kOmega;  ///< the body's polhode: omega's path
inline constexpr render::Color kSeparatrix = render::kBlack;
inline constexpr render::Color kTorque = render::kYellow;   ///< a torque (apart from the grey axes)
inline constexpr render::Color kFixedAxis = render::kGray;  ///< an axle, a fixed axis, the vertical
inline constexpr render::Color kBody = render::kSkyBlue;    ///< a body's surface, translucent
inline constexpr render::Color kMarker = render::kBlack;    ///< a start, a chosen instant
}  // namespace colors

/// A thin translucent body (a plate, a disk) drawn in its flat colour, unshaded, so
/// that it shows its legend swatch's colour from whichever side it is seen.
inline render::Material flat_body(render::Color color, float opacity) {
  render::Material m;
  m.color = color;
  m.opacity = opacity;
  m.specular = 0.0f;
  m.lit = false;
  return m;
}

/// Where a lab's figures go: each figure as a render description with a name and a
/// caption. The command line saves them as PNGs (<lab>_<name>.png); a live view
/// shows them. A figure's title, if any, is what the figure itself shows after
/// the lab's name and inputs; the sink adds those.
class FigureSink {
 public:
  virtual ~FigureSink() = default;
  /// A 2D plot.
  virtual void add(const std::string& name, const std::string& caption, render::Plot2D plot) = 0;
  /// A 3D scene.
  virtual void add(const std::string& name, const std::string& caption, render::Scene3D scene) = 0;
  /// Whether the sink takes figure `name`, a scene or a plot: the command line takes
  /// every one; a live view lists the names and describes only the figure it shows.
  virtual bool wants(const std::string& name, bool scene) {
    (void)name, (void)scene;
    return true;
  }
  /// Figure `name` as `describe()` makes it (a Plot2D or a Scene3D), described only
  /// where the sink wants it: how a lab hands over a figure that costs work.
  template <class Describe, std::enable_if_t<std::is_invocable_v<Describe&>, int> = 0>
  void add(const std::string& name, const std::string& caption, Describe describe) {
    using Figure = std::invoke_result_t<Describe&>;
    static_assert(std::is_same_v<Figure, render::Plot2D> || std::is_same_v<Figure, render::Scene3D>,
                  "a figure is a Plot2D or a Scene3D");
    if (wants(name, std::is_same_v<Figure, render::Scene3D>)) add(name, caption, describe());
  }
};

/// What a lab with motion shows moving (--animate, a live view): the scene, and
/// optionally a strip plot under it, at any time of the motion, in any order.
struct Animation {
  double seconds = 0.0;  ///< the span of the motion shown, from t = 0
  std::string caption;
  /// The lab's figure whose scene is scene(0), if one is (named in the JSON).
  std::string still;
  std::function<render::Scene3D(double)> scene;
  /// A plot at time t drawn across the frame's lower `strip_share` (none if empty), its
  /// time axis the motion's (Axis::motion_time) and a cursor at t; at a NaN time none,
  /// the same plot for every frame (a live view draws it once and lays its cursor over).
  std::function<render::Plot2D(double)> strip;
  double strip_share = 0.0;
};

/// The body at a time of its motion: its attitude, the unit quaternion that turns body
/// axes into space axes (as the lab's CSV writes it, not renormalised), and omega in
/// body axes, rad/s.
struct BodyState {
  Eigen::Quaterniond attitude = Eigen::Quaterniond::Identity();
  Eigen::Vector3d omega_body = Eigen::Vector3d::Zero();
};

/// A lab's body at any time t >= 0 (s) of its motion, in the lab's own time (not a
/// film's): the closed form, or the integrator the lab's method names, the same at a
/// time its CSV samples as the CSV's row. Throws std::invalid_argument for t < 0.
using BodyMotion = std::function<BodyState(double)>;

/// How many scenes, spread over a motion (at k/16 of it), a film's one camera is fitted
/// to and its one legend gathered from.
inline constexpr int kFitSamples = 16;

/// The time of frame k of `count` spread over `seconds` of motion: k/count of it (the
/// last one short of the end, so a periodic motion loops without a repeated frame).
inline double film_time(double seconds, int k, int count) {
  return seconds * k / count;
}

/// The union of `motion`'s scenes at kFitSamples times spread over it, with its first
/// scene's title: what one camera for the whole film is fitted to, and whose legend (of
/// every part any frame shows) every frame keeps, through Scene3D::legend_from, so that
/// it neither grows nor reorders when a part appears mid-film.
inline render::Scene3D motion_envelope(const Animation& motion) {
  render::Scene3D envelope = motion.scene(0.0);
  for (int k = 1; k < kFitSamples; ++k)
    envelope.merge(motion.scene(film_time(motion.seconds, k, kFitSamples)));
  return envelope;
}

/// The Animation that plays `motion` (a lab's Motion: seconds() and scene(t)), shared
/// by every copy of its functions.
template <class Motion>
Animation play(std::shared_ptr<const Motion> motion, std::string caption, std::string still = {}) {
  Animation a;
  a.seconds = motion->seconds();
  a.caption = std::move(caption);
  a.still = std::move(still);
  a.scene = [motion](double t) { return motion->scene(t); };
  return a;
}

/// The times, sorted, at which an animation of `seconds` of motion asks for its
/// scene (its frames and the camera's fit): a lab that draws from an integrator
/// samples it at exactly these.
using FrameTimes = std::function<std::vector<double>(double seconds)>;

}  // namespace rigid::lab
