// The torque-free body as an integrated problem (free_body_integrate.h): its
// invariants, its Lie-Poisson splitting and its projection; the generic run and
// comparison (compare_impl.h) are compiled for it here.
#include "rigid/free_body_integrate.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rigid/compare_impl.h"
#include "rigid/splitting.h"

namespace rigid {

// The invariants' signed errors against the start's.
class FreeBodyProblem::Invariants {
 public:
  Invariants(const PrincipalMoments& I, const State& x0) : I_(I) {
    const Eigen::Vector3d w0 = omega_body(x0);
    T0_ = kinetic_energy(I, w0);
    L0_ = angular_momentum_magnitude(I, w0);
    L_space0_ = attitude(x0).normalized() * L_body(I, w0);
  }
  std::array<double, kInvariantCount> operator()(const State& x) const {
    const Eigen::Vector3d w = omega_body(x);
    const Eigen::Quaterniond q = attitude(x);
    const double T = kinetic_energy(I_, w), L = angular_momentum_magnitude(I_, w);
    std::array<double, kInvariantCount> e{};
    e[kEnergy] = T0_ > 0.0 ? (T - T0_) / T0_ : 0.0;
    e[kMomentum] = L0_ > 0.0 ? (L - L0_) / L0_ : 0.0;
    // No torque: L is fixed in space, so this measures the attitude's error too.
    if (L0_ > 0.0) e[kLSpace] = ((q.normalized() * L_body(I_, w)) - L_space0_).norm() / L0_;
    e[kQuaternionNorm] = q.norm() - 1.0;
    return e;
  }

 private:
  PrincipalMoments I_;
  double T0_ = 0.0, L0_ = 0.0;
  Eigen::Vector3d L_space0_ = Eigen::Vector3d::Zero();
};

// The Lie-Poisson splitting as a fixed-step stepper for integrate_on_grid, on
// L_body (so no division by I between sub-flows) and q; the system it steps is the
// splitting itself, whose sub-flows are exact and need no right-hand side. Every
// sub-flow is a rotation, so |L| is exact but for roundoff, which random-walks
// (~eps sqrt(5 n): 1e-13 after 1e6 steps). One Newton step for 1/|L| pulls L back
// to the sphere |L| = |L0| each step at the cost of a dot product; it moves
// nothing but roundoff.
class FreeBodyProblem::Splitting {
 public:
  struct Variables {
    Eigen::Vector3d L_body;
    Eigen::Quaterniond q;
  };
  Splitting(const PrincipalMoments& I, int order, const State& x0)
      : split_(I, order), I_(I), inv_I_(1.0 / I.I1, 1.0 / I.I2, 1.0 / I.I3) {
    const double L0_sq = L_body(I, omega_body(x0)).squaredNorm();
    inv_L0_sq_ = L0_sq > 0.0 ? 1.0 / L0_sq : 0.0;
  }
  Variables enter(const State& x0) const { return {L_body(I_, omega_body(x0)), attitude(x0)}; }
  State leave(const Variables& x) const { return make_state(x.L_body.cwiseProduct(inv_I_), x.q); }
  void do_step(const Splitting& /*self*/, Variables& x, double /*t*/, double dt) const {
    split_.step(x.L_body, x.q, dt);
    if (inv_L0_sq_ > 0.0) x.L_body *= 1.5 - 0.5 * x.L_body.squaredNorm() * inv_L0_sq_;
  }

 private:
  LiePoissonSplitting split_;
  PrincipalMoments I_;
  Eigen::Vector3d inv_I_;
  double inv_L0_sq_ = 0.0;
};

// Projection of omega onto the manifold {2T(omega) = 2T0, |L(omega)|^2 = L0^2}
// (Hairer, Lubich & Wanner, Geometric Numerical Integration, IV.4): one
// Gauss-Newton step omega -= J^T (J J^T)^-1 g with g the two constraint
// residuals and J their gradients; g is of the size of the local error, so one
// step leaves a residual of its square. Where the two gradients are parallel
// (omega on a principal axis) only the energy is restored.
class FreeBodyProblem::Projection {
 public:
  Projection(const PrincipalMoments& I, const State& x0)
      : I_(I.vector()), I2_(I_.cwiseProduct(I_)) {
    const Eigen::Vector3d w = omega_body(x0);
    two_T0_ = w.dot(I_.cwiseProduct(w));
    L0_sq_ = w.dot(I2_.cwiseProduct(w));
  }
  void operator()(State& x) const {
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

void FreeBodyProblem::validate(const State& x0) const {
  rigid::validate(I_, rule_);
  validate_start(x0);
}

FreeBodyProblem::Invariants FreeBodyProblem::invariants(const State& x0) const {
  return Invariants(I_, x0);
}

FreeBodyProblem::State FreeBodyProblem::sampled(const State& x) const {
  const Eigen::Quaterniond q = attitude(x);
  return make_state(omega_body(x), Eigen::Quaterniond(q.coeffs() / q.norm()));
}

FreeBodyProblem::Splitting FreeBodyProblem::splitting(int order, const State& x0) const {
  return Splitting(I_, order, x0);
}

FreeBodyProblem::Projection FreeBodyProblem::projection(const State& x0) const {
  return Projection(I_, x0);
}

ExactErrors FreeBodyProblem::errors_against(const Exact& exact,
                                            const std::vector<Sample>& samples) const {
  const double scale = exact.omega_body(0.0).norm();
  ExactErrors errors;
  errors.error.reserve(samples.size());
  errors.energy_error.reserve(samples.size());
  for (const Sample& s : samples) {
    const Eigen::Vector3d w = omega_body(s.x);
    errors.error.push_back((w - exact.omega_body(s.t)).norm() / scale);
    errors.energy_error.push_back(
        std::abs(kinetic_energy(exact.moments(), w) / exact.energy() - 1.0));
  }
  return errors;
}

ExactErrors FreeBodyProblem::errors_against(const std::vector<Sample>& reference,
                                            const std::vector<Sample>& samples) const {
  if (reference.size() != samples.size() || samples.empty()) {
    throw std::invalid_argument("a reference run must have the run's samples");
  }
  const double scale = omega_body(reference.front().x).norm();
  ExactErrors errors;
  errors.error.reserve(samples.size());
  errors.energy_error.reserve(samples.size());
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const Eigen::Vector3d w = omega_body(samples[k].x), w_ref = omega_body(reference[k].x);
    errors.error.push_back((w - w_ref).norm() / scale);
    errors.energy_error.push_back(
        std::abs(kinetic_energy(I_, w) / kinetic_energy(I_, w_ref) - 1.0));
  }
  return errors;
}

template struct detail::ProblemCode<FreeBodyProblem>;

}  // namespace rigid
