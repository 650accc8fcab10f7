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

// One line style a method, so a method looks alike in every lab and no two share one:
// each its own colour (Okabe-Ito's seven that read on white, olive, wine and grey), and
// a family one dash besides (Verner's pairs solid, dashed, dash-dot, dashed; the
// splittings solid and dashed), for a reader who cannot tell two colours apart.
LineStyle line_style(Method m) {
  using render::Dash;
  switch (m) {
    case Method::kSplitting:
      return {render::kBlue, Dash::kSolid};
    case Method::kSplitting4:
      return {render::kGray, Dash::kDashed};
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
      return {render::kOlive, Dash::kDashed};
    case Method::kVern8:
      return {render::kBlack, Dash::kDashDot};
    case Method::kVern9:
      return {render::kWine, Dash::kDashed};
  }
  return {render::kGray, Dash::kSolid};
}

// The first sample (t = 0) has no error to show on a log axis; an error below the
// floor (a zero's included) is drawn at it.
std::vector<double> running_max(const std::vector<double>& v, double floor) {
  std::vector<double> out;
  double most = floor;
  for (auto it = v.begin() + 1; it != v.end(); ++it) out.push_back(most = std::max(most, *it));
  return out;
}

// The legend lists the best first: by the largest error, floored, so methods at
// roundoff tie and keep the methods' own order instead of one their last bits choose.
std::vector<std::size_t> best_first(const std::vector<MethodCurve>& methods, double error_floor) {
  std::vector<std::size_t> order(methods.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  const auto floored_max = [&](const MethodCurve& m) {
    double most = error_floor;
    for (const double e : m.error) most = std::max(most, e);
    return most;
  };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const double ea = floored_max(methods[a]), eb = floored_max(methods[b]);
    if (ea != eb) return ea < eb;
    return methods[a].method < methods[b].method;
  });
  return order;
}

// The largest value a panel draws, its axis's start at least.
double largest(const render::Panel& panel) {
  double top = panel.y.min;
  for (const auto& series : panel.series)
    for (const double v : series.y) top = std::max(top, v);
  return top;
}

}  // namespace

render::Plot2D integrators_plot(const std::vector<MethodCurve>& methods, const std::string& title,
                                const TimeAxis& time, const std::string& error_title,
                                const std::string& error_label, const std::string& energy_label,
                                double error_floor, const ErrorCeiling& ceiling) {
  const bool in_periods = time.period > 0.0;
  const std::string t_label = in_periods ? "t (" + time.name + ")" : "t (s)";
  render::Plot2D plot(1, 2);
  // one floor where the error and the energy share it, else the error's, then the energy's
  plot.title = error_floor == kRoundoffFloor
                   ? fmt::format("{}; below {:.2g}, roundoff, drawn at it", title, error_floor)
                   : fmt::format("{}; below {:.2g} and {:.2g}, roundoff, drawn at them", title,
                                 error_floor, kRoundoffFloor);
  render::Panel& error = plot.panel(0, 0);
  error.title = error_title + ", largest so far";
  error.x.label = t_label;
  error.y = {error_label, render::Scale::kLog10};
  // the axes start a little below the floors, where a floored curve shows as a line
  error.y.min = error_floor / 3;
  render::Panel& energy = plot.panel(0, 1);
  energy.title = "energy error, largest so far";
  energy.x.label = t_label;
  energy.y = {energy_label, render::Scale::kLog10};
  energy.y.min = kRoundoffFloor / 3;
  for (const std::size_t k : best_first(methods, error_floor)) {
    // A method that did not run, or blew up, has no curve to show.
    if (!methods[k].drawn || methods[k].t.size() < 2) continue;
    std::vector<double> t(methods[k].t.begin() + 1, methods[k].t.end());
    if (in_periods) {
      for (double& x : t) x /= time.period;
    }
    auto& a = error.add_line(t, running_max(methods[k].error, error_floor), methods[k].name);
    auto& b =
        energy.add_line(t, running_max(methods[k].energy_error, kRoundoffFloor), methods[k].name);
    const LineStyle style = line_style(methods[k].method);
    a.color = b.color = style.color;
    a.dash = b.dash = style.dash;
  }
  // both panels draw the same methods: one legend under them, where no axis grows for it
  plot.shared_legend = true;
  // the most accurate on top: where several meet at the floor, the best shows
  error.first_on_top = energy.first_on_top = true;
  const double worst = largest(error);
  if (ceiling.value > 0.0 && worst >= 0.1 * ceiling.value) {
    error.add_ref_line(ceiling.value, false, ceiling.label).color = render::kBlack;
    // room above it, so that the line and the curves stopped at it are not the frame
    error.y.max = 5 * std::max(ceiling.value, worst);
  }
  // every curve at its floor: a decade above it to show them on
  for (render::Panel* panel : {&error, &energy})
    if (!(largest(*panel) > 3 * panel->y.min)) panel->y.max = 30 * panel->y.min;
  return plot;
}

}  // namespace rigid::lab
