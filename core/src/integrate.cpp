#include "rigid/integrate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

// GCC 12 sees odeint's fehlberg78 copy constructor copy its (never read) scratch
// arrays and warns -Wmaybe-uninitialized inside Boost; silence only that, only here.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <boost/numeric/odeint/stepper/bulirsch_stoer_dense_out.hpp>
#include <boost/numeric/odeint/stepper/generation.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta4.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_dopri5.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_fehlberg78.hpp>

#include "format_number.h"
#include "rigid/splitting.h"

namespace rigid {

namespace ode = boost::numeric::odeint;

namespace {

constexpr std::array<std::string_view, 6> kNames = {"splitting", "splitting4", "rk4",
                                                    "dopri5",    "rkf78",      "bulirsch-stoer"};

[[noreturn]] void too_many_steps(Method m, std::size_t max_steps, double t_end) {
  std::ostringstream os;
  os << method_name(m) << " needs more than " << max_steps
     << " steps to reach t = " << format_number(t_end)
     << " s; loosen the tolerance, lengthen the step, or raise max_steps";
  throw std::runtime_error(os.str());
}

// Accumulates samples and the drift of the invariants.
class Recorder {
 public:
  Recorder(const PrincipalMoments& I, const FreeBodyState& x0, IntegrationResult& out,
           std::size_t n)
      : I_(I), out_(out) {
    const Eigen::Vector3d w0 = omega_body(x0);
    T0_ = kinetic_energy(I, w0);
    L0_ = angular_momentum_magnitude(I, w0);
    L_space0_ = attitude(x0).normalized() * L_body(I, w0);
    out_.samples.reserve(n);
  }
  void operator()(double t, const Eigen::Vector3d& w, const Eigen::Quaterniond& q) {
    const double qn = q.norm();
    out_.quaternion_norm_drift = std::max(out_.quaternion_norm_drift, std::abs(qn - 1.0));
    const double T = kinetic_energy(I_, w), L = angular_momentum_magnitude(I_, w);
    if (T0_ > 0.0) out_.energy_drift_rel = std::max(out_.energy_drift_rel, std::abs(T - T0_) / T0_);
    if (L0_ > 0.0)
      out_.momentum_drift_rel = std::max(out_.momentum_drift_rel, std::abs(L - L0_) / L0_);
    if (L0_ > 0.0) {
      // No torque: L is fixed in space, so this measures the attitude's error too.
      const Eigen::Vector3d L_space = (q.normalized() * L_body(I_, w)) - L_space0_;
      out_.L_space_drift_rel = std::max(out_.L_space_drift_rel, L_space.norm() / L0_);
    }
    out_.samples.push_back({t, w, Eigen::Quaterniond(q.coeffs() / qn)});
  }
  void operator()(double t, const FreeBodyState& x) { (*this)(t, omega_body(x), attitude(x)); }

 private:
  const PrincipalMoments& I_;
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

// A first trial step for the adaptive methods: a fraction of a radian of rotation.
double initial_step(const FreeBodyState& x0, double tol, int order) {
  const double w = std::max(omega_body(x0).norm(), 1e-300);
  return 0.1 * std::pow(std::max(tol, 1e-16), 1.0 / (order + 1)) / w;
}

// Fixed-step methods: steps of h, the one that would pass a sample time shortened to land on it.
template <class Advance, class Emit>
void run_fixed(const std::vector<double>& times, double h, Method m, std::size_t max_steps,
               IntegrationResult& out, Advance&& advance, Emit&& emit) {
  const double t0 = times.front(), t1 = times.back();
  const double needed = std::ceil((t1 - t0) / h) + static_cast<double>(times.size());
  if (needed > static_cast<double>(max_steps)) {
    std::ostringstream os;
    os << method_name(m) << " with step " << format_number(h) << " s needs more than " << max_steps
       << " steps to reach t = " << format_number(t1) << " s; lengthen the step or raise max_steps";
    throw std::invalid_argument(os.str());
  }
  double t = t0;
  for (double ts : times) {
    while (t < ts) {
      // next point of the grid t0 + n h, so shortened steps do not shift the grid
      const double n = std::floor((t - t0) / h + 1e-9);
      double t_next = t0 + (n + 1.0) * h;
      if (t_next <= t) t_next = t + h;
      if (t_next > ts - 1e-9 * h) t_next = ts;  // land on the sample time
      advance(t_next - t);
      t = t_next;
      ++out.steps;
    }
    emit(ts);
  }
}

// Error-controlled stepping that lands on each sample time (for steppers without dense output).
template <class Stepper, class System, class Project>
void run_controlled(Stepper& stepper, System& rhs, FreeBodyState x,
                    const std::vector<double>& times, double dt0, Method m, std::size_t max_steps,
                    IntegrationResult& out, Recorder& rec, Project&& project) {
  double t = times.front();
  double dt_free = dt0;
  for (double ts : times) {
    while (t < ts) {
      if (out.steps + out.rejected_steps >= max_steps) too_many_steps(m, max_steps, times.back());
      const bool clamped = t + dt_free >= ts;
      double dt = clamped ? ts - t : dt_free;
      const ode::controlled_step_result r = stepper.try_step(rhs, x, t, dt);
      if (r == ode::success) {
        ++out.steps;
        project(x);
        if (clamped) {
          t = ts;  // land exactly; the free step was not tried, keep it
        } else {
          dt_free = dt;
        }
      } else {
        ++out.rejected_steps;
        dt_free = clamped ? std::min(dt_free, dt) : dt;
      }
      if (!(dt_free > 0.0) || t + dt_free == t) {
        std::ostringstream os;
        os << method_name(m) << ": step size underflow at t = " << format_number(t) << " s";
        throw std::runtime_error(os.str());
      }
    }
    rec(ts, x);
  }
}

// Dense-output stepping: free steps, samples interpolated.
template <class Dense, class System>
void run_dense(Dense& stepper, System& rhs, const FreeBodyState& x0,
               const std::vector<double>& times, double dt0, Method m, std::size_t max_steps,
               IntegrationResult& out, Recorder& rec) {
  stepper.initialize(x0, times.front(), dt0);
  FreeBodyState x;
  for (double ts : times) {
    while (stepper.current_time() < ts) {
      if (out.steps >= max_steps) too_many_steps(m, max_steps, times.back());
      stepper.do_step(rhs);
      ++out.steps;
    }
    if (ts == stepper.current_time()) {
      x = stepper.current_state();
    } else {
      stepper.calc_state(ts, x);
    }
    rec(ts, x);
  }
}

void check_inputs(const PrincipalMoments& I, const FreeBodyState& x0,
                  const std::vector<double>& times, const IntegrateOptions& o) {
  validate(I, o.moments_rule);
  for (double v : x0) {
    if (!std::isfinite(v)) throw std::invalid_argument("initial state must be finite");
  }
  const double qn = attitude(x0).norm();
  if (!(qn > 0.0)) throw std::invalid_argument("initial attitude quaternion must be nonzero");
  if (times.empty()) throw std::invalid_argument("sample times must not be empty");
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (!std::isfinite(times[i])) throw std::invalid_argument("sample times must be finite");
    if (i > 0 && times[i] < times[i - 1])
      throw std::invalid_argument("sample times must be nondecreasing");
  }
  if (is_adaptive(o.method)) {
    const auto bad = [](double tol) { return !(tol >= 0.0 && tol < 1.0); };
    if (bad(o.abs_tol) || bad(o.rel_tol) || (o.abs_tol == 0.0 && o.rel_tol == 0.0)) {
      std::ostringstream os;
      os << method_name(o.method) << ": tolerances must lie in [0, 1) and not both be 0, got abs "
         << format_number(o.abs_tol) << ", rel " << format_number(o.rel_tol);
      throw std::invalid_argument(os.str());
    }
  } else if (!(o.step > 0.0) || !std::isfinite(o.step)) {
    std::ostringstream os;
    os << method_name(o.method) << ": step must be positive and finite, got "
       << format_number(o.step);
    throw std::invalid_argument(os.str());
  }
}

}  // namespace

std::string_view method_name(Method m) {
  return kNames[static_cast<std::size_t>(m)];
}

Method method_from_name(std::string_view name) {
  for (Method m : kAllMethods) {
    if (method_name(m) == name) return m;
  }
  std::string list;
  for (auto n : kNames) list += (list.empty() ? "" : ", ") + std::string(n);
  throw std::invalid_argument("unknown method '" + std::string(name) + "'; expected one of " +
                              list);
}

bool is_adaptive(Method m) {
  return m == Method::kDopri5 || m == Method::kRkf78 || m == Method::kBulirschStoer;
}

bool can_project(Method m) {
  return m == Method::kRk4 || m == Method::kRkf78;
}

int fixed_step_order(Method m) {
  switch (m) {
    case Method::kSplitting:
      return 2;
    case Method::kSplitting4:
      return 4;
    case Method::kRk4:
      return 4;
    default:
      return 0;
  }
}

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
  check_inputs(I, x0, times, o);
  IntegrationResult out;
  out.method = o.method;
  Recorder rec(I, x0, out, times.size());
  const EulerRhs rhs{I};
  if (o.project_invariants && !can_project(o.method)) {
    throw std::invalid_argument(std::string(method_name(o.method)) +
                                " cannot project onto the invariants: only rk4 and rkf78 can");
  }
  const InvariantProjection projection(I, x0);
  const auto project = [&](FreeBodyState& x) {
    if (o.project_invariants) projection(x);
  };

  switch (o.method) {
    case Method::kSplitting:
    case Method::kSplitting4: {
      // carry L_body (the splitting's variable) between samples, not omega
      const LiePoissonSplitting split(I, o.method == Method::kSplitting ? 2 : 4);
      Eigen::Vector3d L = L_body(I, omega_body(x0));
      Eigen::Quaterniond q = attitude(x0);
      const Eigen::Vector3d inv_I(1.0 / I.I1, 1.0 / I.I2, 1.0 / I.I3);
      // Every sub-flow is a rotation, so |L| is exact but for roundoff, which random-walks
      // (~eps sqrt(5 n): 1e-13 after 1e6 steps). One Newton step for 1/|L| pulls L back
      // to the sphere |L| = |L0| each step at the cost of a dot product; it moves nothing
      // but roundoff.
      const double L0_sq = L.squaredNorm();
      const double inv_L0_sq = L0_sq > 0.0 ? 1.0 / L0_sq : 0.0;
      run_fixed(
          times, o.step, o.method, o.max_steps, out,
          [&](double h) {
            split.step(L, q, h);
            if (inv_L0_sq > 0.0) L *= 1.5 - 0.5 * L.squaredNorm() * inv_L0_sq;
          },
          [&](double t) { rec(t, L.cwiseProduct(inv_I), q); });
      break;
    }
    case Method::kRk4: {
      ode::runge_kutta4<FreeBodyState> stepper;
      FreeBodyState x = x0;
      double t = times.front();
      run_fixed(
          times, o.step, o.method, o.max_steps, out,
          [&](double h) {
            stepper.do_step(rhs, x, t, h);
            project(x);
            t += h;
          },
          [&](double ts) { rec(ts, x); });
      break;
    }
    case Method::kDopri5: {
      auto stepper =
          ode::make_dense_output(o.abs_tol, o.rel_tol, ode::runge_kutta_dopri5<FreeBodyState>());
      run_dense(stepper, rhs, x0, times, initial_step(x0, std::max(o.abs_tol, o.rel_tol), 5),
                o.method, o.max_steps, out, rec);
      break;
    }
    case Method::kRkf78: {
      auto stepper =
          ode::make_controlled(o.abs_tol, o.rel_tol, ode::runge_kutta_fehlberg78<FreeBodyState>());
      run_controlled(stepper, rhs, x0, times, initial_step(x0, std::max(o.abs_tol, o.rel_tol), 8),
                     o.method, o.max_steps, out, rec, project);
      break;
    }
    case Method::kBulirschStoer: {
      ode::bulirsch_stoer_dense_out<FreeBodyState> stepper(o.abs_tol, o.rel_tol);
      run_dense(stepper, rhs, x0, times, initial_step(x0, std::max(o.abs_tol, o.rel_tol), 8),
                o.method, o.max_steps, out, rec);
      break;
    }
  }
  return out;
}

std::vector<double> sample_times(double t_end, double period, double step, double per_period,
                                 std::size_t max_samples) {
  double spacing = std::max(period / per_period, t_end / static_cast<double>(max_samples - 1));
  if (step > 0.0) {
    spacing = step * std::max(1.0, std::round(spacing / step));
    t_end = spacing * std::ceil(t_end / spacing - 1e-9);
  }
  const double intervals = std::max(1.0, std::round(t_end / spacing));
  return uniform_times(0.0, t_end, static_cast<std::size_t>(intervals) + 1);
}

IntegrationResult sample_exact(const FreeBodyExact& exact, const std::vector<double>& times) {
  IntegrationResult out;
  if (times.empty()) return out;
  Recorder rec(exact.moments(), exact.state(times.front()), out, times.size());
  for (double t : times) rec(t, exact.state(t));
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

}  // namespace rigid
