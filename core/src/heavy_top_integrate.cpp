// The heavy symmetric top integrated (heavy_top_integrate.h).
#include "rigid/heavy_top_integrate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "rigid/integrate.h"
#include "rigid/splitting.h"

namespace rigid {
namespace {

// R^T z for the (not necessarily unit) quaternion q: z in body axes.
Eigen::Vector3d up_in_body(double w, double x, double y, double z) {
  const double n2 = w * w + x * x + y * y + z * z;
  return Eigen::Vector3d(2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z) /
         n2;
}

// The gravity torque in body axes, -mgl e3 x (R^T z).
Eigen::Vector3d gravity_torque(double mgl, const Eigen::Vector3d& up_body) {
  return {mgl * up_body.y(), -mgl * up_body.x(), 0.0};
}

// The splitting's variables: L_body and the attitude.
struct SplitState {
  Eigen::Vector3d L_body;
  Eigen::Quaterniond q;
};

// q <- q (x) (cos(angle/2), sin(angle/2) axis) for a unit axis in body axes.
void turn_body(Eigen::Quaterniond& q, const Eigen::Vector3d& axis, double angle) {
  q = q * Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis));
}

// Free flow and kicks of the heavy top (header comment), a fixed-step stepper
// for integrate_on_grid.
class TopSplitting {
 public:
  TopSplitting(const HeavyTop& top, int order) : top_(top), order_(order) {}
  void do_step(const TopSplitting& /*self*/, SplitState& x, double /*t*/, double h) const {
    if (order_ == 2) return strang(x, h);
    for (const double stage : {kSuzukiP, kSuzukiP, 1.0 - 4.0 * kSuzukiP, kSuzukiP, kSuzukiP}) {
      strang(x, stage * h);
    }
  }

 private:
  void kick(SplitState& x, double h) const {
    const Eigen::Quaterniond& q = x.q;
    x.L_body += h * gravity_torque(top_.mgl, up_in_body(q.w(), q.x(), q.y(), q.z()));
  }
  // The free symmetric top exactly: H = |L|^2/(2I) + L3^2 (1/Is - 1/I)/2, two
  // commuting pieces; the first turns the body about L_body (L_body still), the
  // second turns L_body and the body about 3.
  void free_flow(SplitState& x, double h) const {
    const double L = x.L_body.norm();
    if (L > 0.0) turn_body(x.q, x.L_body / L, L / top_.I * h);
    const double angle = x.L_body.z() * (1.0 / top_.Is - 1.0 / top_.I) * h;
    x.L_body = Eigen::AngleAxisd(-angle, Eigen::Vector3d::UnitZ()) * x.L_body;
    turn_body(x.q, Eigen::Vector3d::UnitZ(), angle);
  }
  void strang(SplitState& x, double h) const {
    kick(x, 0.5 * h);
    free_flow(x, h);
    kick(x, 0.5 * h);
  }
  HeavyTop top_;
  int order_;
};

// The observer: samples and the drift of E, p_phi, p_psi.
class TopRecorder {
 public:
  TopRecorder(const HeavyTop& top, const FreeBodyState& x0, TopRun& out, std::size_t n)
      : top_(top), out_(out) {
    measure(omega_body(x0), attitude(x0), E0_, p_phi0_, p_psi0_);
    const Eigen::Vector3d w0 = omega_body(x0);
    scale_E_ =
        0.5 * (top.I * (w0.x() * w0.x() + w0.y() * w0.y()) + top.Is * w0.z() * w0.z()) + top.mgl;
    const double L0 = Eigen::Vector3d(top.I * w0.x(), top.I * w0.y(), top.Is * w0.z()).norm();
    inv_L0_ = L0 > 0.0 ? 1.0 / L0 : 0.0;
    out_.samples.reserve(n);
  }
  void operator()(const FreeBodyState& x, double t) { record(t, omega_body(x), attitude(x)); }
  void operator()(const SplitState& x, double t) {
    record(t, Eigen::Vector3d(x.L_body.x() / top_.I, x.L_body.y() / top_.I, x.L_body.z() / top_.Is),
           x.q);
  }

 private:
  void measure(const Eigen::Vector3d& w, const Eigen::Quaterniond& q, double& E, double& p_phi,
               double& p_psi) const {
    const Eigen::Vector3d up = up_in_body(q.w(), q.x(), q.y(), q.z());
    const Eigen::Vector3d L(top_.I * w.x(), top_.I * w.y(), top_.Is * w.z());
    E = 0.5 * w.dot(L) + top_.mgl * up.z();  // up.z() = cos(theta)
    p_phi = L.dot(up);                       // L_z in space
    p_psi = L.z();
  }
  void record(double t, const Eigen::Vector3d& w, const Eigen::Quaterniond& q) {
    double E, p_phi, p_psi;
    measure(w, q, E, p_phi, p_psi);
    const Eigen::Vector3d errors((E - E0_) / scale_E_, (p_phi - p_phi0_) * inv_L0_,
                                 (p_psi - p_psi0_) * inv_L0_);
    out_.energy_drift_rel = std::max(out_.energy_drift_rel, std::abs(errors(0)));
    out_.p_phi_drift_rel = std::max(out_.p_phi_drift_rel, std::abs(errors(1)));
    out_.p_psi_drift_rel = std::max(out_.p_psi_drift_rel, std::abs(errors(2)));
    const Eigen::Quaterniond unit = q.normalized();
    out_.samples.push_back({t, tilt_of(unit), std::abs(errors(0)), w, unit, errors});
  }
  HeavyTop top_;
  TopRun& out_;
  double E0_ = 0, p_phi0_ = 0, p_psi0_ = 0, scale_E_ = 1, inv_L0_ = 0;
};

}  // namespace

FreeBodyState heavy_top_state(const TopAngles& a) {
  return make_state(euler_omega_body(a), euler_attitude(a.phi, a.theta, a.psi));
}

double tilt_of(const Eigen::Quaterniond& q) {
  // The symmetry axis in space, R e3; atan2 keeps theta accurate near 0 and pi.
  const Eigen::Vector3d axis = q * Eigen::Vector3d::UnitZ();
  return std::atan2(std::hypot(axis.x(), axis.y()), axis.z());
}

TopRun integrate_heavy_top(const HeavyTop& top, const FreeBodyState& x0,
                           const std::vector<double>& times, const OdeOptions& o) {
  validate(top);
  detail::require_finite(x0);
  if (!(attitude(x0).norm() > 0.0)) {
    throw std::invalid_argument("initial attitude quaternion must be nonzero");
  }
  TopRun out;
  out.method = o.method;
  TopRecorder rec(top, x0, out, times.size());
  OdeStats stats;
  if (o.method == Method::kSplitting || o.method == Method::kSplitting4) {
    validate_run(o, times);  // integrate_sampled checks the others
    const TopSplitting split(top, fixed_step_order(o.method));
    const Eigen::Vector3d w0 = omega_body(x0);
    SplitState x{{top.I * w0.x(), top.I * w0.y(), top.Is * w0.z()}, attitude(x0).normalized()};
    TopSplitting stepper = split;
    stats = integrate_on_grid(stepper, split, x, times, o, rec);
    stats.evaluations = stats.steps * static_cast<std::size_t>(evaluations_per_step(o.method));
  } else {
    stats = integrate_sampled(HeavyTopRhs(top), x0, times, o, rec);
  }
  out.steps = stats.steps;
  out.evaluations = stats.evaluations;
  return out;
}

TopRun sample_exact(const HeavyTopExact& exact, const std::vector<double>& times) {
  TopRun out;
  const FreeBodyState x0 = heavy_top_state(exact.angles(0.0));
  TopRecorder rec(exact.top(), x0, out, times.size());
  for (const double t : times) rec(heavy_top_state(exact.angles(t)), t);
  return out;
}

namespace {

// A completed run measured against the exact motion (as measure() in integrate.cpp).
void measure(TopComparison& c, const TopRun& run, const HeavyTopExact& exact, double period) {
  c.completed = true;
  c.evaluations = run.evaluations;
  std::vector<double> dE;
  for (const TopSample& s : run.samples) {
    c.t.push_back(s.t);
    const double e = std::abs(s.theta - exact.theta(s.t));
    c.theta_error.push_back(e);
    c.energy_error.push_back(s.energy_error);
    dE.push_back(s.invariant_errors(0));
    // A NaN (a run that blew up) counts as an infinite error.
    c.max_theta_error =
        std::isfinite(e) ? std::max(c.max_theta_error, e) : std::numeric_limits<double>::infinity();
  }
  c.energy = invariant_error(c.t, dE, period);
}

// The comparison with only its settings: a run that could not finish.
TopComparison not_completed(const OdeOptions& options) {
  TopComparison c;
  c.options = options;
  return c;
}

}  // namespace

std::vector<TopComparison> compare_top_methods(const HeavyTopExact& exact,
                                               const std::vector<double>& times, double period,
                                               const OdeOptions& options, std::size_t max_steps) {
  const FreeBodyState x0 = heavy_top_state(exact.angles(0.0));
  std::vector<TopComparison> out;
  for (const Method m : kAllMethods) {
    OdeOptions o = options;
    o.method = m;
    o.max_steps = max_steps;
    const std::vector<double> each_times =
        is_adaptive(m) ? times : sample_times(times.back(), period, options.step);
    TopComparison c;
    c.options = o;
    try {
      measure(c, integrate_heavy_top(exact.top(), x0, each_times, o), exact, period);
    } catch (const std::exception&) {
      c = not_completed(o);  // more steps than allowed
    }
    out.push_back(std::move(c));
  }
  return out;
}

std::vector<TopComparison> compare_top_methods_at_cost(const HeavyTopExact& exact, double period,
                                                       double periods,
                                                       double evaluations_per_period,
                                                       double samples_per_period) {
  const FreeBodyState x0 = heavy_top_state(exact.angles(0.0));
  const double t_end = periods * period;
  const auto max_samples = static_cast<std::size_t>(std::ceil(periods * samples_per_period)) + 1;
  std::vector<TopComparison> out;
  for (const Method m : kAllMethods) {
    const auto run_with = [&](const OdeOptions& settings) {
      const std::vector<double> times = sample_times(
          t_end, period, is_adaptive(m) ? 0.0 : settings.step, samples_per_period, max_samples);
      return integrate_heavy_top(exact.top(), x0, times, settings);
    };
    const OdeOptions o = settings_at_cost(
        m, period, periods, evaluations_per_period,
        [&](const OdeOptions& settings) { return run_with(settings).evaluations; });
    TopComparison c;
    c.options = o;
    try {
      measure(c, run_with(o), exact, period);
    } catch (const std::exception&) {
      c = not_completed(o);
    }
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace rigid
