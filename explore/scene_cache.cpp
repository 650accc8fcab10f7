// The scene view's cache (scene_cache.h).
#include "scene_cache.h"

#include <algorithm>
#include <limits>

#include "common/figures.h"
#include "rigid/render/draw.h"

namespace rigid::explore {

const char* const kExactGhost = "the exact motion (faint): the drift is the gap";

namespace {

// The first of a view's names where it is the motion's.
std::optional<std::string> lead_choice(const lab::Session& s, bool scenes) {
  const lab::Animation* motion = s.animation();
  const bool lead = scenes ? motion != nullptr : motion != nullptr && bool(motion->strip);
  if (!lead) return std::nullopt;
  return scenes ? "motion" : "the motion's strip";
}

}  // namespace

std::vector<std::string> view_choices(const lab::Session& s, bool scenes) {
  std::vector<std::string> names;
  if (auto lead = lead_choice(s, scenes)) names.push_back(*lead);
  for (const lab::FigureName& f : s.figure_names()) {
    if (f.scene == scenes) names.push_back(f.name);
  }
  return names;
}

const lab::NamedFigure* figure_named(const lab::Session& s, const std::string& name) {
  return s.figure(name);
}

std::optional<render::Plot2D> shown_plot(const lab::Session& s, const ViewState& v) {
  const lab::Animation* motion = s.animation();
  const bool strip = motion != nullptr && motion->strip;
  // the motion's strip, first of the choices, needs none of the lab's figures described;
  // drawn without its cursor, the same in every frame, the view's cursor laid over it
  const double no_cursor = std::numeric_limits<double>::quiet_NaN();
  if (strip && v.plot_choice == 0) return motion->strip(no_cursor);
  const auto names = view_choices(s, false);
  if (names.empty()) return std::nullopt;
  const std::size_t k = std::min<std::size_t>(v.plot_choice, names.size() - 1);
  if (strip && k == 0) return motion->strip(no_cursor);
  return std::get<render::Plot2D>(figure_named(s, names[k])->figure);
}

std::vector<TimeCursor> time_cursors(const render::Plot2D& plot,
                                     const render::Plot2D::Layout& layout) {
  std::vector<TimeCursor> out;
  for (int r = 0, k = 0; r < plot.rows(); ++r) {
    for (int c = 0; c < plot.cols(); ++c, ++k) {
      const render::Axis& x = plot.panel(r, c).x;
      if (x.motion_time && x.scale == render::Scale::kLinear) {
        const auto& p = layout.panels[k];
        out.push_back({p.frame, p.x_lo, p.x_hi});
      }
    }
  }
  return out;
}

const SceneCache::Envelope& SceneCache::envelope(const lab::Session& s, const ViewState& v) {
  Envelope& e = envelope_;
  // Made once for a set of inputs, as the camera is fitted (a later result for the same
  // inputs shows the same parts), and held while a slider is dragged: sixteen scenes
  // would be most of a dragged step's time (a part the drag brings in is still named:
  // legend_from adds what it lacks).
  const bool current =
      e.generation == s.inputs_generation() || (v.interacting && e.generation >= 0);
  if (current) return e;
  render::Scene3D whole = lab::motion_envelope(*s.animation());
  whole.title = s.report().figure_title(whole.title);
  render::Scene3D legend = whole.legend_only();
  if (const lab::Animation* exact = exact_motion(s))
    legend.merge(exact->scene(0.0).faded(kExactGhost).legend_only());
  e.legend = std::make_shared<const render::Scene3D>(std::move(legend));
  // the camera is fitted clear of the legend the frames draw (the ghost's entry with it)
  whole.legend_from = e.legend;
  e.scene = std::make_shared<const render::Scene3D>(std::move(whole));
  e.generation = s.inputs_generation();
  return e;
}

const render::Scene3D* SceneCache::shown(const lab::Session& s, const ViewState& v) {
  const lab::Animation* motion = s.animation();
  // the motion, first of the choices, needs none of the lab's figures described
  if (motion == nullptr || v.scene_choice != 0) {
    const auto names = view_choices(s, true);
    if (names.empty()) return nullptr;
    const std::string& name = names[std::min<std::size_t>(v.scene_choice, names.size() - 1)];
    if (motion == nullptr || name != "motion") {
      return &std::get<render::Scene3D>(figure_named(s, name)->figure);
    }
  }
  // made once for a state and a time: a frame asks for it more than once
  MotionScene& m = motion_scene_;
  if (!(m.generation == s.generation() && m.time == v.time)) {
    m.scene = motion->scene(v.time);
    m.scene.title = s.report().figure_title(m.scene.title);
    // an integrator's motion, with the exact one laid over it faintly: drift is seen
    if (const lab::Animation* exact = exact_motion(s)) {
      m.scene.merge(exact->scene(std::min(v.time, exact->seconds)).faded(kExactGhost));
    }
    m.generation = s.generation();
    m.time = v.time;
  }
  m.scene.legend_from = envelope(s, v).legend;
  return &m.scene;
}

// The same inputs with the exact method, when an integrator's motion is shown (and the
// lab has a closed form to offer); nullptr otherwise.
const lab::Animation* SceneCache::exact_motion(const lab::Session& s) {
  const std::size_t m = s.find("--method");
  if (m >= s.input_count()) return nullptr;
  const lab::InputValue exact = std::string("exact");
  if (s.value(m) == exact || !s.rule(m).broken(exact).empty()) return nullptr;
  if (exact_generation_ != s.inputs_generation()) {
    exact_session_ = s.with(m, exact);
    exact_generation_ = s.inputs_generation();
  }
  return exact_session_ ? exact_session_->animation() : nullptr;
}

// The camera of the view before the orbit: the lab's own, fitted once to the figure, or
// to the whole motion (frames spread over it), so that playing does not move it.
render::Camera SceneCache::base_camera(const lab::Session& s, const ViewState& v, int width,
                                       int height) {
  const bool same_view =
      fit_.choice == v.scene_choice && fit_.width == width && fit_.height == height;
  // While a slider is dragged the camera holds still (a refit each step would make the
  // view breathe under the hand, and is most of a step's time); it is fitted again
  // when the hand lets go.
  if (same_view && (fit_.generation == s.inputs_generation() || v.interacting)) {
    return fit_.camera;
  }
  const render::Scene3D* scene = shown(s, v);
  // as the command line's --animate fits its camera
  const bool moving = s.animation() != nullptr && v.scene_choice == 0;
  fit_ = {s.inputs_generation(), v.scene_choice, width, height,
          render::fitted_camera(moving ? *envelope(s, v).scene : *scene, width, height)};
  return fit_.camera;
}

render::Scene3D SceneCache::view_scene(const lab::Session& s, const ViewState& v, int width,
                                       int height) {
  render::Scene3D scene = shown(s, v)->without(v.hidden);
  scene.camera = v.orbit.apply(base_camera(s, v, width, height));
  scene.show_legend = v.legend;
  return scene;
}

std::vector<std::string> SceneCache::parts(const lab::Session& s, const ViewState& v) {
  const render::Scene3D* scene = shown(s, v);
  return scene == nullptr ? std::vector<std::string>{} : scene->legend_labels();
}

}  // namespace rigid::explore
