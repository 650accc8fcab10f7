// GSL as its documentation shows it: gsl_odeiv2_driver_alloc_y_new with an
// explicit stepper, driven to t_end by gsl_odeiv2_driver_apply; and the Jacobi
// elliptic functions gsl_sf_elljac_e. GPL: compiled into bench executables only.
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_sf_elljac.h>

#include <stdexcept>

#include "peers.h"

namespace bench {
namespace {

// The free-body system in GSL's calling convention; it counts its calls.
struct Params {
  rigid::PrincipalMoments I;
  long long evaluations = 0;
};
int euler_rhs(double /*t*/, const double x[], double dxdt[], void* params) {
  auto& par = *static_cast<Params*>(params);
  ++par.evaluations;
  const rigid::PrincipalMoments& I = par.I;
  const double w1 = x[0], w2 = x[1], w3 = x[2];
  dxdt[0] = -w2 * w3 * (I.I3 - I.I2) / I.I1;
  dxdt[1] = -w3 * w1 * (I.I1 - I.I3) / I.I2;
  dxdt[2] = -w1 * w2 * (I.I2 - I.I1) / I.I3;
  const double qw = x[3], qx = x[4], qy = x[5], qz = x[6];
  dxdt[3] = 0.5 * (-qx * w1 - qy * w2 - qz * w3);
  dxdt[4] = 0.5 * (qw * w1 + qy * w3 - qz * w2);
  dxdt[5] = 0.5 * (qw * w2 + qz * w1 - qx * w3);
  dxdt[6] = 0.5 * (qw * w3 + qx * w2 - qy * w1);
  return GSL_SUCCESS;
}

RunResult run(const Problem& p, double tol, const gsl_odeiv2_step_type* type) {
  // report failures by status, not by GSL's default abort()
  static const bool quiet = (gsl_set_error_handler_off(), true);
  (void)quiet;
  Params par{p.I};
  gsl_odeiv2_system sys = {euler_rhs, nullptr, 7, &par};
  // hstart 1e-6 as in the GSL manual's example
  gsl_odeiv2_driver* d = gsl_odeiv2_driver_alloc_y_new(&sys, type, 1e-6, tol, tol);
  RunResult r;
  r.x = p.initial_state();
  double t = 0.0;
  const int status = gsl_odeiv2_driver_apply(d, &t, p.t_end, r.x.data());
  r.steps = static_cast<long long>(d->e->count);
  r.evaluations = par.evaluations;
  gsl_odeiv2_driver_free(d);
  if (status != GSL_SUCCESS) throw std::runtime_error("gsl_odeiv2_driver_apply failed");
  return r;
}

}  // namespace

RunResult gsl_rk8pd(const Problem& p, double tol) {
  return run(p, tol, gsl_odeiv2_step_rk8pd);
}
RunResult gsl_rkf45(const Problem& p, double tol) {
  return run(p, tol, gsl_odeiv2_step_rkf45);
}

double gsl_elljac_sum(double u0, double du, int n, double m) {
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    double sn, cn, dn;
    gsl_sf_elljac_e(u0 + i * du, m, &sn, &cn, &dn);
    sum += sn + cn + dn;
  }
  return sum;
}

}  // namespace bench
