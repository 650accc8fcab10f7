#include "rigid/poinsot.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "rigid/free_body_exact.h"
#include "rigid/periodic_mean.h"
#include "rigid/units.h"

namespace rigid {
namespace {

// Indices of the smallest, intermediate and largest moments.
std::array<int, 3> sorted_axes(const Eigen::Vector3d& I) {
  std::array<int, 3> index{0, 1, 2};
  std::sort(index.begin(), index.end(), [&](int a, int b) { return I(a) < I(b); });
  return index;
}

}  // namespace

PoinsotEllipsoids poinsot_ellipsoids(const PrincipalMoments& I, const Eigen::Vector3d& omega_body) {
  const Eigen::Vector3d moments = I.vector();
  const double two_T = 2.0 * kinetic_energy(I, omega_body);
  const double L = angular_momentum_magnitude(I, omega_body);
  PoinsotEllipsoids e;
  e.energy_semi_axes = (two_T * moments.cwiseInverse()).cwiseSqrt();
  e.momentum_semi_axes = L * moments.cwiseInverse();
  return e;
}

Eigen::Vector3d momentum_ellipsoid_ratios(const Eigen::Vector3d& moments) {
  return moments.cwiseInverse();
}

Eigen::Vector3d energy_ellipsoid_ratios(const Eigen::Vector3d& moments) {
  return moments.cwiseSqrt().cwiseInverse();
}

Eigen::Vector3d momentum_ratios_touching(const Eigen::Vector3d& moments, int j) {
  const Eigen::Vector3d m = momentum_ellipsoid_ratios(moments);
  return m * (energy_ellipsoid_ratios(moments)(j) / m(j));
}

std::vector<std::vector<Eigen::Vector3d>> polhode(const PrincipalMoments& I,
                                                  const Eigen::Vector3d& omega0_body, int samples) {
  const FreeBodyExact motion(I, omega0_body);
  if (motion.regime() == FreeMotionRegime::kSeparatrix) {
    return separatrices(I, motion.energy(), samples);
  }
  if (!std::isfinite(motion.period())) return {};
  std::vector<Eigen::Vector3d> curve;
  curve.reserve(static_cast<size_t>(samples));
  for (int k = 0; k < samples; ++k) {
    curve.push_back(motion.omega_body(motion.period() * k / (samples - 1)));
  }
  return {curve};
}

std::vector<Eigen::Vector3d> herpolhode(const FreeBodyExact& motion, double t_end, int samples) {
  std::vector<Eigen::Vector3d> points;
  points.reserve(static_cast<std::size_t>(std::max(samples, 0)));
  for (int k = 0; k < samples; ++k) {
    const double t = samples > 1 ? t_end * k / (samples - 1) : 0.0;
    const RotationState x = motion.state(t);
    points.push_back(attitude(x) * omega_body(x));
  }
  return points;
}

double herpolhode_turn_per_period(const FreeBodyExact& motion) {
  const double T = motion.period();
  if (!std::isfinite(T)) return std::nan("");
  // The contact point is omega in space, p = R omega, and dp/dt = R omega_dot (R_dot omega
  // = omega x omega = 0): its azimuth about n = L/|L| turns at n.(p x p_dot) / |n x p|^2,
  // in body axes n_b.(omega x omega_dot) / |n_b x omega|^2, omega_dot from Euler's
  // equations. That rate is smooth and T-periodic: its mean by periodic_mean (sampling
  // the angle itself instead missed whole turns once the contact point goes round L many
  // times a period, as near a symmetric body).
  const Eigen::Vector3d I = motion.moments().vector();
  const double L = I.cwiseProduct(motion.omega_body(0.0)).norm();
  const auto rate = [&](double t) {
    const Eigen::Vector3d w = motion.omega_body(t);
    const Eigen::Vector3d w_dot((I(1) - I(2)) * w(1) * w(2) / I(0),
                                (I(2) - I(0)) * w(2) * w(0) / I(1),
                                (I(0) - I(1)) * w(0) * w(1) / I(2));
    const Eigen::Vector3d n = I.cwiseProduct(w) / L;
    return n.dot(w.cross(w_dot)) / n.cross(w).squaredNorm();
  };
  return T * periodic_mean(rate, T);
}

Eigen::Vector3d omega_on_energy_ellipsoid(const PrincipalMoments& I, double T, double L2) {
  const Eigen::Vector3d moments = I.vector();
  const auto [s, m, l] = sorted_axes(moments);
  const double Is = moments(s), Il = moments(l);
  if (!(Il > Is)) return Eigen::Vector3d::Constant(std::sqrt(2.0 * T / Is / 3.0));
  // Solve I_s w_s^2 + I_l w_l^2 = 2T and I_s^2 w_s^2 + I_l^2 w_l^2 = L^2 (eqs. 79, 81).
  const double ws2 = std::max(0.0, (2.0 * T * Il - L2) / (Is * (Il - Is)));
  const double wl2 = std::max(0.0, (L2 - 2.0 * T * Is) / (Il * (Il - Is)));
  Eigen::Vector3d omega = Eigen::Vector3d::Zero();
  omega(s) = std::sqrt(ws2);
  omega(l) = std::sqrt(wl2);
  (void)m;
  return omega;
}

std::vector<std::vector<Eigen::Vector3d>> separatrices(const PrincipalMoments& I, double T,
                                                       int samples) {
  const Eigen::Vector3d moments = I.vector();
  const auto [s, m, l] = sorted_axes(moments);
  const double Is = moments(s), Im = moments(m), Il = moments(l);
  if (!(Im > Is) || !(Il > Im)) return {};
  // On the separatrix sum I_i (I_i - I_m) w_i^2 = L^2 - 2 T I_m = 0, so it lies
  // in the planes w_l = +-c w_s through the intermediate axis.
  const double c = std::sqrt(Is * (Im - Is) / (Il * (Il - Im)));
  std::vector<std::vector<Eigen::Vector3d>> curves;
  for (double sign : {1.0, -1.0}) {
    // Points alpha e_m + beta (e_s + sign c e_l) on the energy ellipsoid.
    const double alpha = std::sqrt(2.0 * T / Im), beta = std::sqrt(2.0 * T / (Is + Il * c * c));
    std::vector<Eigen::Vector3d> ellipse;
    for (int k = 0; k < samples; ++k) {
      const double angle = 2.0 * kPi * k / (samples - 1);
      Eigen::Vector3d w = Eigen::Vector3d::Zero();
      w(m) = alpha * std::cos(angle);
      w(s) = beta * std::sin(angle);
      w(l) = sign * c * beta * std::sin(angle);
      ellipse.push_back(w);
    }
    curves.push_back(std::move(ellipse));
  }
  return curves;
}

}  // namespace rigid
