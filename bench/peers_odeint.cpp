// Boost.Odeint as its documentation shows it: std::vector<double> state and
// integrate_adaptive with a controlled stepper from make_controlled(abs, rel).
#include <array>
#include <boost/numeric/odeint.hpp>
#include <vector>

#include "peers.h"

namespace bench {
namespace {

namespace odeint = boost::numeric::odeint;
using VectorState = std::vector<double>;

// The free-body system written the way a user writes it for odeint.
struct VectorEulerRhs {
  double I1, I2, I3;
  long long* evaluations;  // counted for the report's cost column
  void operator()(const VectorState& x, VectorState& dxdt, double /*t*/) const {
    ++*evaluations;
    const double w1 = x[0], w2 = x[1], w3 = x[2];
    dxdt[0] = -w2 * w3 * (I3 - I2) / I1;
    dxdt[1] = -w3 * w1 * (I1 - I3) / I2;
    dxdt[2] = -w1 * w2 * (I2 - I1) / I3;
    const double qw = x[3], qx = x[4], qy = x[5], qz = x[6];
    dxdt[3] = 0.5 * (-qx * w1 - qy * w2 - qz * w3);
    dxdt[4] = 0.5 * (qw * w1 + qy * w3 - qz * w2);
    dxdt[5] = 0.5 * (qw * w2 + qz * w1 - qx * w3);
    dxdt[6] = 0.5 * (qw * w3 + qx * w2 - qy * w1);
  }
};

template <class Stepper>
RunResult run(const Problem& p, double tol) {
  const rigid::RotationState x0 = p.initial_state();
  VectorState x(x0.begin(), x0.end());
  const double dt0 = 0.01;
  RunResult r;
  const auto steps = odeint::integrate_adaptive(
      odeint::make_controlled<Stepper>(tol, tol),
      VectorEulerRhs{p.I.I1, p.I.I2, p.I.I3, &r.evaluations}, x, 0.0, p.t_end, dt0);
  std::copy(x.begin(), x.end(), r.x.begin());
  r.steps = static_cast<long long>(steps);
  return r;
}

// The same system in long double, for the reference cross-check.
using LongState = std::array<long double, 7>;
struct LongEulerRhs {
  long double I1, I2, I3;
  void operator()(const LongState& x, LongState& dxdt, long double /*t*/) const {
    const long double w1 = x[0], w2 = x[1], w3 = x[2];
    dxdt[0] = -w2 * w3 * (I3 - I2) / I1;
    dxdt[1] = -w3 * w1 * (I1 - I3) / I2;
    dxdt[2] = -w1 * w2 * (I2 - I1) / I3;
    const long double qw = x[3], qx = x[4], qy = x[5], qz = x[6];
    dxdt[3] = 0.5L * (-qx * w1 - qy * w2 - qz * w3);
    dxdt[4] = 0.5L * (qw * w1 + qy * w3 - qz * w2);
    dxdt[5] = 0.5L * (qw * w2 + qz * w1 - qx * w3);
    dxdt[6] = 0.5L * (qw * w3 + qx * w2 - qy * w1);
  }
};

}  // namespace

rigid::RotationState long_double_rkf78(const Problem& p, long double tol) {
  // the initial data are the double values every other solver starts from
  const rigid::RotationState x0 = p.initial_state();
  LongState x;
  std::copy(x0.begin(), x0.end(), x.begin());
  odeint::integrate_adaptive(
      odeint::make_controlled<odeint::runge_kutta_fehlberg78<LongState, long double>>(tol, tol),
      LongEulerRhs{p.I.I1, p.I.I2, p.I.I3}, x, 0.0L, static_cast<long double>(p.t_end), 0.01L);
  rigid::RotationState out;
  std::copy(x.begin(), x.end(), out.begin());
  return out;
}

RunResult odeint_vector_dopri5(const Problem& p, double tol) {
  return run<odeint::runge_kutta_dopri5<VectorState>>(p, tol);
}

RunResult odeint_vector_rkf78(const Problem& p, double tol) {
  return run<odeint::runge_kutta_fehlberg78<VectorState>>(p, tol);
}

}  // namespace bench
