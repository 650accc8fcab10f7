#include "common/integrator_plot.h"

#include <fmt/format.h>

#include <algorithm>

namespace rigid::lab {

std::string method_label(const OdeOptions& o) {
  return std::string(method_name(o.method)) + ", " +
         (is_adaptive(o.method) ? fmt::format("tol {:g}", o.rel_tol)
                                : fmt::format("h = {:.3g} s", o.step));
}

render::Plot2D integrators_plot(const std::vector<MethodCurve>& methods,
                                const std::string& error_title, const std::string& error_label,
                                const std::string& energy_label) {
  render::Plot2D plot(1, 2);
  plot.title = "integrators against the exact solution";
  render::Panel& error = plot.panel(0, 0);
  error.title = error_title;
  error.x.label = "t (s)";
  error.y = {error_label, render::Scale::kLog10, 1e-17};
  render::Panel& energy = plot.panel(0, 1);
  energy.title = "energy error";
  energy.x.label = "t (s)";
  energy.y = {energy_label, render::Scale::kLog10, 1e-17};
  // Zero errors have no logarithm: show them at a floor below double roundoff.
  // The first sample (t = 0) has no error to show on a log axis.
  const auto floored = [](const std::vector<double>& v) {
    std::vector<double> out(v.begin() + 1, v.end());
    for (double& x : out) x = std::max(x, 1e-17);
    return out;
  };
  const auto after_start = [](const std::vector<double>& v) {
    return std::vector<double>(v.begin() + 1, v.end());
  };
  const render::Dash dashes[] = {render::Dash::kSolid,   render::Dash::kDashed,
                                 render::Dash::kSolid,   render::Dash::kDashDot,
                                 render::Dash::kSolid,   render::Dash::kDotted};
  for (std::size_t k = 0; k < methods.size(); ++k) {
    // A method that did not run, or blew up, has no curve to show.
    if (!methods[k].drawn || methods[k].t.size() < 2) continue;
    const std::vector<double> t = after_start(methods[k].t);
    auto& a = error.add_line(t, floored(methods[k].error), methods[k].name);
    auto& b = energy.add_line(t, floored(methods[k].energy_error), methods[k].name);
    a.color = b.color = render::palette_color(k);
    a.dash = b.dash = dashes[k % 6];
  }
  energy.legend = render::LegendPlace::kNone;
  return plot;
}

}  // namespace rigid::lab
