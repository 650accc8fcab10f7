// The heavy symmetric top as an integrated problem (heavy_top_integrate.h): its
// invariants and its splitting; the generic run and comparison (compare_impl.h)
// are compiled for it here.
#include "rigid/heavy_top_integrate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "rigid/compare_impl.h"
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

// q <- q (x) (cos(angle/2), sin(angle/2) axis) for a unit axis in body axes.
void turn_body(Eigen::Quaterniond& q, const Eigen::Vector3d& axis, double angle) {
  q = q * Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis));
}

}  // namespace

// The observer's invariants: E, p_phi and p_psi against the start's.
class HeavyTopProblem::Invariants {
 public:
  Invariants(const HeavyTop& top, const State& x0) : top_(top) {
    measure(omega_body(x0), attitude(x0), E0_, p_phi0_, p_psi0_);
    const Eigen::Vector3d w0 = omega_body(x0);
    scale_E_ =
        0.5 * (top.I * (w0.x() * w0.x() + w0.y() * w0.y()) + top.Is * w0.z() * w0.z()) + top.mgl;
    // p_phi and p_psi are components of L, measured against the largest |L| the motion
    // can reach: |L|^2 <= 2 max(I, Is) T and T <= T0 + 2 m g l (the centre of mass falls
    // by 2 l at most). Against |L0| alone a top released from rest with a slow spin
    // (|L0| = Is S -> 0) would call the roundoff of its swing a drift.
    const double L0 = Eigen::Vector3d(top.I * w0.x(), top.I * w0.y(), top.Is * w0.z()).norm();
    const double L_reach = std::sqrt(2.0 * std::max(top.I, top.Is) * (scale_E_ + top.mgl));
    const double L_scale = std::max(L0, L_reach);
    inv_L_scale_ = L_scale > 0.0 ? 1.0 / L_scale : 0.0;
  }
  std::array<double, kInvariantCount> operator()(const State& x) const {
    double E, p_phi, p_psi;
    measure(omega_body(x), attitude(x), E, p_phi, p_psi);
    return {(E - E0_) / scale_E_, (p_phi - p_phi0_) * inv_L_scale_,
            (p_psi - p_psi0_) * inv_L_scale_};
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
  HeavyTop top_;
  double E0_ = 0, p_phi0_ = 0, p_psi0_ = 0, scale_E_ = 1, inv_L_scale_ = 0;
};

// Free flow and kicks of the heavy top (header comment) on L_body and the
// attitude, a fixed-step stepper for integrate_on_grid.
class HeavyTopProblem::Splitting {
 public:
  struct Variables {
    Eigen::Vector3d L_body;
    Eigen::Quaterniond q;
  };
  Splitting(const HeavyTop& top, int order) : top_(top), order_(order) {}
  Variables enter(const State& x0) const {
    const Eigen::Vector3d w0 = omega_body(x0);
    return {{top_.I * w0.x(), top_.I * w0.y(), top_.Is * w0.z()}, attitude(x0).normalized()};
  }
  State leave(const Variables& x) const {
    return make_state(
        Eigen::Vector3d(x.L_body.x() / top_.I, x.L_body.y() / top_.I, x.L_body.z() / top_.Is), x.q);
  }
  void do_step(const Splitting& /*self*/, Variables& x, double /*t*/, double h) const {
    if (order_ == 2) return strang(x, h);
    for (const double stage : {kSuzukiP, kSuzukiP, 1.0 - 4.0 * kSuzukiP, kSuzukiP, kSuzukiP}) {
      strang(x, stage * h);
    }
  }

 private:
  void kick(Variables& x, double h) const {
    const Eigen::Quaterniond& q = x.q;
    x.L_body += h * gravity_torque(top_.mgl, up_in_body(q.w(), q.x(), q.y(), q.z()));
  }
  // The free symmetric top exactly: H = |L|^2/(2I) + L3^2 (1/Is - 1/I)/2, two
  // commuting pieces; the first turns the body about L_body (L_body still), the
  // second turns L_body and the body about 3.
  void free_flow(Variables& x, double h) const {
    const double L = x.L_body.norm();
    if (L > 0.0) turn_body(x.q, x.L_body / L, L / top_.I * h);
    const double angle = x.L_body.z() * (1.0 / top_.Is - 1.0 / top_.I) * h;
    x.L_body = Eigen::AngleAxisd(-angle, Eigen::Vector3d::UnitZ()) * x.L_body;
    turn_body(x.q, Eigen::Vector3d::UnitZ(), angle);
  }
  void strang(Variables& x, double h) const {
    kick(x, 0.5 * h);
    free_flow(x, h);
    kick(x, 0.5 * h);
  }
  HeavyTop top_;
  int order_;
};

RotationState heavy_top_state(const TopAngles& a) {
  return make_state(euler_omega_body(a), euler_attitude(a.phi, a.theta, a.psi));
}

double tilt_of(const Eigen::Quaterniond& q) {
  // The symmetry axis in space, R e3; atan2 keeps theta accurate near 0 and pi.
  const Eigen::Vector3d axis = q * Eigen::Vector3d::UnitZ();
  return std::atan2(std::hypot(axis.x(), axis.y()), axis.z());
}

void HeavyTopProblem::validate(const State& x0) const {
  rigid::validate(top_);
  validate_start(x0);
}

HeavyTopProblem::Invariants HeavyTopProblem::invariants(const State& x0) const {
  return Invariants(top_, x0);
}

HeavyTopProblem::State HeavyTopProblem::sampled(const State& x) const {
  return make_state(omega_body(x), attitude(x).normalized());
}

HeavyTopProblem::Splitting HeavyTopProblem::splitting(int order, const State& /*x0*/) const {
  return Splitting(top_, order);
}

HeavyTopProblem::State HeavyTopProblem::exact_state(const Exact& exact, double t) const {
  const TopAngles a = exact.angles(t);
  return make_state(exact.omega_body(a), euler_attitude(a.phi, a.theta, a.psi));
}

ExactErrors HeavyTopProblem::errors_against(const Exact& exact,
                                            const std::vector<Sample>& samples) const {
  ExactErrors errors;
  errors.error.reserve(samples.size());
  errors.energy_error.reserve(samples.size());
  for (const Sample& s : samples) {
    errors.error.push_back(std::abs(tilt_of(attitude(s.x)) - exact.theta(s.t)));
    errors.energy_error.push_back(std::abs(s.invariant_errors[kEnergy]));
  }
  return errors;
}

template struct detail::ProblemCode<HeavyTopProblem>;

}  // namespace rigid
