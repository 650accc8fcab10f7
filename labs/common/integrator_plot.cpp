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
  render::Marker marker;
};

// One line style a method, so a method looks alike in every lab and no two share one:
// each its own colour (Okabe-Ito's seven that read on white, olive, wine and grey), a
// family one dash besides (Verner's pairs solid, dashed, dash-dot, dashed; the splittings
// solid and dashed), for a reader who cannot tell two colours apart, and its own marker:
// curves that lie on one another (several at the roundoff floor) each show theirs.
LineStyle line_style(Method m) {
  using render::Dash;
  using render::Marker;
  switch (m) {
    case Method::kSplitting:
      return {render::kBlue, Dash::kSolid, Marker::kCircle};
    case Method::kSplitting4:
      return {render::kGray, Dash::kDashed, Marker::kSquare};
    case Method::kRk4:
      return {render::kBluishGreen, Dash::kSolid, Marker::kTriangle};
    case Method::kDopri5:
      return {render::kVermillion, Dash::kDashDot, Marker::kTriangleDown};
    case Method::kRkf78:
      return {render::kReddishPurple, Dash::kSolid, Marker::kDiamond};
    case Method::kBulirschStoer:
      return {render::kSkyBlue, Dash::kDotted, Marker::kHexagon};
    case Method::kVern6:
      return {render::kOrange, Dash::kSolid, Marker::kTriangleLeft};
    case Method::kVern7:
      return {render::kOlive, Dash::kDashed, Marker::kTriangleRight};
    case Method::kVern8:
      return {render::kBlack, Dash::kDashDot, Marker::kPlus};
    case Method::kVern9:
      return {render::kWine, Dash::kDashed, Marker::kCross};
  }
  return {render::kGray, Dash::kSolid, Marker::kNone};
}

// Markers along each curve this far apart (reference pixels), each method's at its own
// phase of that spacing: ten methods' markers, 16 px apart, side by side where their
// curves coincide.
constexpr double kMarkerSpacing = 160;

double marker_phase(Method m) {
  return (static_cast<double>(m) + 0.5) / static_cast<double>(kAllMethods.size());
}

// The first sample (t = 0) has no error to show on a log axis; an error below the
// floor (a zero's included) is drawn at it.
std::vector<double> running_max(const std::vector<double>& v, double floor) {
  std::vector<double> out;
  double most = floor;
  for (auto it = v.begin() + 1; it != v.end(); ++it) out.push_back(most = std::max(most, *it));
  return out;
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
  for (std::size_t k = 0; k < methods.size(); ++k) {
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
    a.marker = b.marker = style.marker;
    a.marker_size = b.marker_size = 12;
    a.marker_spacing = b.marker_spacing = kMarkerSpacing;
    a.marker_phase = b.marker_phase = marker_phase(methods[k].method);
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
