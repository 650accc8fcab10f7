#include "common/integrator_plot.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace rigid::lab {

std::string method_label(const OdeOptions& o) {
  return std::string(method_name(o.method)) + ", " +
         (is_adaptive(o.method) ? fmt::format("tol {:.2g}", o.rel_tol)
                                : fmt::format("h = {:.3g} s", o.step));
}

std::vector<MethodCurve> method_curves(const std::vector<MethodComparison>& comparisons,
                                       double (*in_unit)(double)) {
  std::vector<MethodCurve> curves;
  for (const MethodComparison& c : comparisons) {
    // One curve a method, in its own style: a projected run (the table ranks it
    // beside its plain one) would share its method's.
    if (c.options.project_invariants) continue;
    std::vector<double> error = c.error;
    if (in_unit != nullptr) {
      for (double& e : error) e = in_unit(e);
    }
    curves.push_back({c.options.method, method_label(c.options),
                      c.completed && std::isfinite(c.max_error), c.t, std::move(error),
                      c.energy_error});
  }
  return curves;
}

namespace {

struct LineStyle {
  render::Color color;
  render::Dash dash;
};

// One line style a method, so a method looks alike in every lab and no two share
// one: a family shares a colour (the splittings blue, Verner's pairs orange and
// black), its members differ in dash.
LineStyle line_style(Method m) {
  using render::Dash;
  switch (m) {
    case Method::kSplitting:
      return {render::kBlue, Dash::kSolid};
    case Method::kSplitting4:
      return {render::kBlue, Dash::kDashed};
    case Method::kRk4:
      return {render::kBluishGreen, Dash::kSolid};
    case Method::kDopri5:
      return {render::kVermillion, Dash::kDashDot};
    case Method::kRkf78:
      return {render::kReddishPurple, Dash::kSolid};
    case Method::kBulirschStoer:
      return {render::kSkyBlue, Dash::kDotted};
    case Method::kVern6:
      return {render::kOrange, Dash::kSolid};
    case Method::kVern7:
      return {render::kOrange, Dash::kDashed};
    case Method::kVern8:
      return {render::kBlack, Dash::kDashDot};
    case Method::kVern9:
      return {render::kBlack, Dash::kDashed};
  }
  return {render::kGray, Dash::kSolid};
}

}  // namespace

render::Plot2D integrators_plot(const std::vector<MethodCurve>& methods, const std::string& title,
                                const TimeAxis& time, const std::string& error_title,
                                const std::string& error_label, const std::string& energy_label) {
  const bool in_periods = time.period > 0.0;
  const std::string t_label = in_periods ? "t (" + time.name + ")" : "t (s)";
  render::Plot2D plot(1, 2);
  plot.title = title;
  render::Panel& error = plot.panel(0, 0);
  error.title = error_title + ", largest so far";
  error.x.label = t_label;
  error.y = {error_label, render::Scale::kLog10};
  render::Panel& energy = plot.panel(0, 1);
  energy.title = "energy error, largest so far";
  energy.x.label = t_label;
  energy.y = {energy_label, render::Scale::kLog10};
  // The first sample (t = 0) has no error to show on a log axis; a zero error has
  // no logarithm either and sits at a floor below double roundoff.
  const auto running_max = [](const std::vector<double>& v) {
    std::vector<double> out;
    double most = 1e-17;
    for (auto it = v.begin() + 1; it != v.end(); ++it) out.push_back(most = std::max(most, *it));
    return out;
  };
  for (std::size_t k = 0; k < methods.size(); ++k) {
    // A method that did not run, or blew up, has no curve to show.
    if (!methods[k].drawn || methods[k].t.size() < 2) continue;
    std::vector<double> t(methods[k].t.begin() + 1, methods[k].t.end());
    if (in_periods) {
      for (double& x : t) x /= time.period;
    }
    auto& a = error.add_line(t, running_max(methods[k].error), methods[k].name);
    auto& b = energy.add_line(t, running_max(methods[k].energy_error), methods[k].name);
    const LineStyle style = line_style(methods[k].method);
    a.color = b.color = style.color;
    a.dash = b.dash = style.dash;
  }
  energy.legend = render::LegendPlace::kNone;
  return plot;
}

}  // namespace rigid::lab
