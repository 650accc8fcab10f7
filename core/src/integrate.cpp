#include "rigid/integrate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "rigid/splitting.h"

namespace rigid {

namespace {

// The splitting's variables: L_body (so no division by I between sub-flows) and q.
struct LiePoissonState {
  Eigen::Vector3d L_body;
  Eigen::Quaterniond q;
};

// The observer of a free-body run: accumulates samples and the drift of the invariants.
class Recorder {
 public:
  Recorder(const PrincipalMoments& I, const FreeBodyState& x0, IntegrationResult& out,
           std::size_t n)
      : I_(I), inv_I_(1.0 / I.I1, 1.0 / I.I2, 1.0 / I.I3), out_(out) {
    const Eigen::Vector3d w0 = omega_body(x0);
    T0_ = kinetic_energy(I, w0);
    L0_ = angular_momentum_magnitude(I, w0);
    L_space0_ = attitude(x0).normalized() * L_body(I, w0);
    out_.samples.reserve(n);
  }
  void operator()(const FreeBodyState& x, double t) { record(t, omega_body(x), attitude(x)); }
  void operator()(const LiePoissonState& x, double t) {
    record(t, x.L_body.cwiseProduct(inv_I_), x.q);
  }
  void record(double t, const Eigen::Vector3d& w, const Eigen::Quaterniond& q) {
    const double qn = q.norm();
    out_.quaternion_norm_drift = std::max(out_.quaternion_norm_drift, std::abs(qn - 1.0));
    const double T = kinetic_energy(I_, w), L = angular_momentum_magnitude(I_, w);
    const double dT = T0_ > 0.0 ? (T - T0_) / T0_ : 0.0, dL = L0_ > 0.0 ? (L - L0_) / L0_ : 0.0;
    out_.energy_drift_rel = std::max(out_.energy_drift_rel, std::abs(dT));
    out_.momentum_drift_rel = std::max(out_.momentum_drift_rel, std::abs(dL));
    if (L0_ > 0.0) {
      // No torque: L is fixed in space, so this measures the attitude's error too.
      const Eigen::Vector3d L_space = (q.normalized() * L_body(I_, w)) - L_space0_;
      out_.L_space_drift_rel = std::max(out_.L_space_drift_rel, L_space.norm() / L0_);
    }
    out_.samples.push_back({t, w, Eigen::Quaterniond(q.coeffs() / qn), dT, dL});
  }

 private:
  const PrincipalMoments& I_;
  Eigen::Vector3d inv_I_;
  IntegrationResult& out_;
  double T0_ = 0.0, L0_ = 0.0;
  Eigen::Vector3d L_space0_ = Eigen::Vector3d::Zero();
};

// Projection of omega onto the manifold {2T(omega) = 2T0, |L(omega)|^2 = L0^2}
// (Hairer, Lubich & Wanner, Geometric Numerical Integration, IV.4): one
// Gauss-Newton step omega -= J^T (J J^T)^-1 g with g the two constraint
// residuals and J their gradients; g is of the size of the local error, so one
// step leaves a residual of its square. Where the two gradients are parallel
// (omega on a principal axis) only the energy is restored.
class InvariantProjection {
 public:
  InvariantProjection(const PrincipalMoments& I, const FreeBodyState& x0)
      : I_(I.vector()), I2_(I_.cwiseProduct(I_)) {
    const Eigen::Vector3d w = omega_body(x0);
    two_T0_ = w.dot(I_.cwiseProduct(w));
    L0_sq_ = w.dot(I2_.cwiseProduct(w));
  }
  void operator()(FreeBodyState& x) const {
    const Eigen::Vector3d w = omega_body(x);
    const Eigen::Vector3d a = 2.0 * I_.cwiseProduct(w), b = 2.0 * I2_.cwiseProduct(w);
    const double g1 = w.dot(I_.cwiseProduct(w)) - two_T0_, g2 = w.dot(I2_.cwiseProduct(w)) - L0_sq_;
    const double aa = a.dot(a), ab = a.dot(b), bb = b.dot(b);
    const double det = aa * bb - ab * ab;
    Eigen::Vector3d dw;
    if (det > 1e-10 * aa * bb) {
      dw = a * ((bb * g1 - ab * g2) / det) + b * ((aa * g2 - ab * g1) / det);
    } else if (aa > 0.0) {
      dw = a * (g1 / aa);
    } else {
      return;
    }
    x[0] -= dw.x();
    x[1] -= dw.y();
    x[2] -= dw.z();
  }

 private:
  Eigen::Vector3d I_, I2_;
  double two_T0_ = 0.0, L0_sq_ = 0.0;
};

// The Lie-Poisson splitting as a fixed-step stepper for integrate_on_grid: the
// system it steps is the splitting itself, whose sub-flows are exact and need no
// right-hand side. Every sub-flow is a rotation, so |L| is exact but for
// roundoff, which random-walks (~eps sqrt(5 n): 1e-13 after 1e6 steps). One
// Newton step for 1/|L| pulls L back to the sphere |L| = |L0| each step at the
// cost of a dot product; it moves nothing but roundoff.
class LiePoissonStepper {
 public:
  explicit LiePoissonStepper(const Eigen::Vector3d& L0_body)
      : inv_L0_sq_(L0_body.squaredNorm() > 0.0 ? 1.0 / L0_body.squaredNorm() : 0.0) {}
  void do_step(const LiePoissonSplitting& split, LiePoissonState& x, double /*t*/,
               double dt) const {
    split.step(x.L_body, x.q, dt);
    if (inv_L0_sq_ > 0.0) x.L_body *= 1.5 - 0.5 * x.L_body.squaredNorm() * inv_L0_sq_;
  }

 private:
  double inv_L0_sq_;
};

void check_inputs(const PrincipalMoments& I, const FreeBodyState& x0, MomentsRule rule) {
  validate(I, rule);
  detail::require_finite(x0);
  const double qn = attitude(x0).norm();
  if (!(qn > 0.0)) throw std::invalid_argument("initial attitude quaternion must be nonzero");
}

}  // namespace

std::vector<double> uniform_times(double t0, double t1, std::size_t n) {
  if (n == 0) throw std::invalid_argument("uniform_times: need at least one time");
  std::vector<double> t(n, t0);
  for (std::size_t i = 1; i < n; ++i) {
    t[i] = t0 + (t1 - t0) * static_cast<double>(i) / static_cast<double>(n - 1);
  }
  if (n > 1) t.back() = t1;
  return t;
}

IntegrationResult integrate_free_body(const PrincipalMoments& I, const FreeBodyState& x0,
                                      const std::vector<double>& times, const IntegrateOptions& o) {
  check_inputs(I, x0, o.moments_rule);
  // the generic rules here too: the splittings do not pass through integrate_sampled
  validate_run(o, times, o.project_invariants);
  IntegrationResult out;
  out.method = o.method;
  Recorder rec(I, x0, out, times.size());
  OdeStats stats;
  if (o.method == Method::kSplitting || o.method == Method::kSplitting4) {
    // carry L_body (the splitting's variable) between samples, not omega
    const LiePoissonSplitting split(I, fixed_step_order(o.method));
    LiePoissonState x{L_body(I, omega_body(x0)), attitude(x0)};
    LiePoissonStepper stepper(x.L_body);
    stats = integrate_on_grid(stepper, split, x, times, o, rec);
    stats.evaluations = stats.steps * static_cast<std::size_t>(evaluations_per_step(o.method));
  } else if (o.project_invariants) {
    stats = integrate_sampled(EulerRhs{I}, x0, times, o, rec, InvariantProjection(I, x0));
  } else {
    stats = integrate_sampled(EulerRhs{I}, x0, times, o, rec);
  }
  out.steps = stats.steps;
  out.rejected_steps = stats.rejected_steps;
  out.evaluations = stats.evaluations;
  return out;
}

std::vector<double> sample_times(double t_end, double period, double step, double per_period,
                                 std::size_t max_samples) {
  const double spacing =
      std::max(period / per_period, t_end / static_cast<double>(max_samples - 1));
  if (!(step > 0.0)) {
    const double intervals = std::max(1.0, std::round(t_end / spacing));
    return uniform_times(0.0, t_end, static_cast<std::size_t>(intervals) + 1);
  }
  // every k-th step, and k large enough that the grid samples and t_end fit max_samples;
  // k is kept in a double (a step of 1e-24 s makes it 1e22, past any integer type) and
  // is a whole number, so n * step is still the product integrate_on_grid steps to
  const double k = std::max({1.0, std::round(spacing / step),
                             std::ceil(t_end / (step * static_cast<double>(max_samples - 1)))});
  // grid samples n * step short of t_end by more than roundoff, then t_end itself
  const double last = t_end * (1.0 - 8.0 * std::numeric_limits<double>::epsilon());
  std::vector<double> times;
  for (std::size_t i = 0; i < max_samples; ++i) {
    const double t = static_cast<double>(i) * k * step;
    if (!(t < last)) break;
    times.push_back(t);
  }
  times.push_back(t_end);
  return times;
}

IntegrationResult sample_exact(const FreeBodyExact& exact, const std::vector<double>& times) {
  IntegrationResult out;
  if (times.empty()) return out;
  Recorder rec(exact.moments(), exact.state(times.front()), out, times.size());
  for (double t : times) rec(exact.state(t), t);
  return out;
}

std::vector<double> omega_errors(const IntegrationResult& run, const FreeBodyExact& exact) {
  const double scale = exact.omega_body(0.0).norm();
  std::vector<double> errors;
  errors.reserve(run.samples.size());
  for (const FreeBodySample& s : run.samples) {
    errors.push_back((s.omega_body - exact.omega_body(s.t)).norm() / scale);
  }
  return errors;
}

std::vector<double> energy_errors(const IntegrationResult& run, const FreeBodyExact& exact) {
  std::vector<double> errors;
  errors.reserve(run.samples.size());
  for (const FreeBodySample& s : run.samples) {
    errors.push_back(
        std::abs(kinetic_energy(exact.moments(), s.omega_body) / exact.energy() - 1.0));
  }
  return errors;
}

namespace {

// A completed run measured against the exact motion: its errors sample by sample,
// its cost, and its invariants' largest error and drift per period.
void measure(MethodComparison& c, const IntegrationResult& run, const FreeBodyExact& exact,
             double period) {
  c.completed = true;
  c.evaluations = run.evaluations;
  std::vector<double> dT, dL;
  for (const FreeBodySample& sample : run.samples) {
    c.t.push_back(sample.t);
    dT.push_back(sample.energy_error);
    dL.push_back(sample.momentum_error);
  }
  c.omega_error = omega_errors(run, exact);
  c.energy_error = energy_errors(run, exact);
  for (double e : c.omega_error) {
    // A NaN (a run that blew up) counts as an infinite error.
    c.max_omega_error =
        std::isfinite(e) ? std::max(c.max_omega_error, e) : std::numeric_limits<double>::infinity();
  }
  c.energy = invariant_error(c.t, dT, period);
  c.momentum = invariant_error(c.t, dL, period);
}

// The comparison with only its settings: a run that could not finish.
MethodComparison not_completed(const IntegrateOptions& options) {
  MethodComparison c;
  c.options = options;
  return c;
}

}  // namespace

std::vector<MethodComparison> compare_methods(const FreeBodyExact& exact,
                                              const std::vector<double>& times, double period,
                                              const IntegrateOptions& options,
                                              std::size_t max_steps) {
  std::vector<MethodComparison> out;
  for (const Method m : kAllMethods) {
    MethodComparison c;
    c.options = options;
    c.options.method = m;
    c.options.project_invariants = false;
    c.options.max_steps = max_steps;
    const std::vector<double> each_times =
        is_adaptive(m) ? times : sample_times(times.back(), period, options.step);
    try {
      const IntegrationResult run =
          integrate_free_body(exact.moments(), exact.state(0.0), each_times, c.options);
      measure(c, run, exact, period);
    } catch (const std::exception&) {
      c = not_completed(c.options);  // more steps than allowed
    }
    out.push_back(std::move(c));
  }
  return out;
}

std::vector<MethodComparison> compare_methods_at_cost(const FreeBodyExact& exact, double period,
                                                      double periods, double evaluations_per_period,
                                                      double samples_per_period) {
  const double t_end = periods * period;
  const auto max_samples = static_cast<std::size_t>(std::ceil(periods * samples_per_period)) + 1;
  std::vector<MethodComparison> out;
  for (const Method m : kAllMethods) {
    const auto run_with = [&](const OdeOptions& o) {
      const std::vector<double> times = sample_times(t_end, period, is_adaptive(m) ? 0.0 : o.step,
                                                     samples_per_period, max_samples);
      IntegrateOptions io;
      static_cast<OdeOptions&>(io) = o;
      return integrate_free_body(exact.moments(), exact.state(0.0), times, io);
    };
    MethodComparison c;
    static_cast<OdeOptions&>(c.options) =
        settings_at_cost(m, period, periods, evaluations_per_period,
                         [&](const OdeOptions& o) { return run_with(o).evaluations; });
    try {
      measure(c, run_with(c.options), exact, period);
    } catch (const std::exception&) {
      c = not_completed(c.options);
    }
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace rigid
