// The tennis racquet theorem (racquet.h).
#include "rigid/racquet.h"

#include <Eigen/QR>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "rigid/format.h"

namespace rigid {
namespace {

// A body axis's direction cosine with L at time t: L_axis / |L|.
double cosine_with_L(const FreeBodyExact& motion, int axis, double t) {
  const PrincipalMoments& I = motion.moments();
  return I.vector()(axis) * motion.omega_body(t)(axis) / motion.angular_momentum_magnitude();
}

// Bisection for the point where `above(t)` turns true in [lo, hi] (false at lo,
// true at hi), down to adjacent doubles.
template <class Above>
double bisect(double lo, double hi, Above above) {
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (above(mid) ? hi : lo) = mid;
  }
  return hi;
}

}  // namespace

Racquet make_racquet(const RacquetModel& model) {
  // thin_ring and thin_rod refuse a mass or size that is not positive and finite.
  const double a = model.head_radius, l = model.handle_length;
  // The head in the 1-2 plane about the origin; the handle along 1 from the rim.
  const Body head = thin_ring(model.head_mass, a);
  const Body handle = shifted(thin_rod(model.handle_mass, l), Vec3(a + l / 2, 0, 0));
  Racquet r;
  r.body = head + handle;  // eq. 83 and the parallel-axis theorem (eq. 85)
  r.cm_offset = r.body.com.x();
  r.moments = {r.body.I_com(0, 0), r.body.I_com(1, 1), r.body.I_com(2, 2)};
  r.head_centre = -r.body.com;
  r.handle_start = Vec3(a, 0, 0) - r.body.com;
  r.handle_end = Vec3(a + l, 0, 0) - r.body.com;
  r.body.com = Vec3::Zero();  // body axes have their origin at the centre of mass
  return r;
}

EulerCoefficients euler_coefficients(const PrincipalMoments& I) {
  return {Eigen::Vector3d((I.I2 - I.I3) / I.I1, (I.I3 - I.I1) / I.I2, (I.I1 - I.I2) / I.I3)};
}

EulerCoefficients simplified_racquet_coefficients() {
  return {Eigen::Vector3d(-1.0, 1.0, -1.0)};  // eqs. 89, 90 and 92
}

SpinStability linear_stability(const EulerCoefficients& c, int axis, double spin) {
  // omega_j_dot = c_j Omega omega_k and omega_k_dot = c_k Omega omega_j.
  const double cj = c.c((axis + 1) % 3), ck = c.c((axis + 2) % 3);
  const double s = cj * ck;
  return {s > 0.0, std::abs(spin) * std::sqrt(std::abs(s)), std::sqrt(std::abs(cj / ck))};
}

Eigen::Vector3d launch_omega(int axis, double spin, double perturbation) {
  Eigen::Vector3d omega = Eigen::Vector3d::Zero();
  // sqrt(1 - p^2) without the cancellation of 1 - p*p
  omega(axis) = spin * std::sqrt((1.0 - perturbation) * (1.0 + perturbation));
  omega((axis + 1) % 3) = spin * perturbation;
  return omega;
}

double transverse_share(const Eigen::Vector3d& omega_body, int axis) {
  const double transverse = std::hypot(omega_body((axis + 1) % 3), omega_body((axis + 2) % 3));
  return transverse / std::hypot(transverse, omega_body(axis));
}

double first_sign_change(const FreeBodyExact& motion, int axis) {
  const double period = motion.period();
  if (!std::isfinite(period)) return std::numeric_limits<double>::infinity();
  // A component that changes sign (the sn one) does so once every half-period,
  // so 256 cells of half a period hold at most one change each.
  const double start = motion.omega_body(0.0)(axis);
  const auto changed = [&](double t) { return motion.omega_body(t)(axis) * start <= 0.0; };
  const int cells = 256;
  double previous = 0.0;
  for (int n = 1; n <= cells; ++n) {
    const double t = 0.5 * period * n / cells;
    if (changed(t)) return bisect(previous, t, changed);
    previous = t;
  }
  return std::numeric_limits<double>::infinity();
}

GrowthFit measure_growth_rate(const FreeBodyExact& motion, int axis, double share_limit,
                              std::size_t samples) {
  const double share0 = transverse_share(motion.omega_body(0.0), axis);
  if (!(share_limit > share0 && share_limit < 1.0)) {
    throw std::invalid_argument(
        "the share that ends the fit must lie between the share at "
        "launch (" +
        format_number(share0) + ") and 1, got " + format_number(share_limit));
  }
  const double flip = first_sign_change(motion, axis);
  if (!std::isfinite(flip)) {
    throw std::invalid_argument("the spin does not flip: there is no growth to measure");
  }
  // The share is 1 at the flip (omega_axis = 0), so it crosses share_limit before.
  const auto reached = [&](double t) {
    return transverse_share(motion.omega_body(t), axis) >= share_limit;
  };
  const int cells = 512;
  double t_end = flip, previous = 0.0;
  for (int n = 1; n <= cells; ++n) {
    const double t = flip * n / cells;
    if (reached(t)) {
      t_end = bisect(previous, t, reached);
      break;
    }
    previous = t;
  }

  // The transverse components at the samples, one column each.
  const int j = (axis + 1) % 3, k = (axis + 2) % 3;
  const Eigen::Index n = static_cast<Eigen::Index>(std::max<std::size_t>(samples, 8));
  Eigen::VectorXd t(n);
  Eigen::MatrixXd y(n, 2);
  for (Eigen::Index i = 0; i < n; ++i) {
    t(i) = t_end * static_cast<double>(i) / static_cast<double>(n - 1);
    const Eigen::Vector3d w = motion.omega_body(t(i));
    y(i, 0) = w(j);
    y(i, 1) = w(k);
  }
  // Variable projection: for a rate lambda the amplitudes follow by linear least
  // squares on the basis e^{lambda (t - t_end)}, e^{-lambda t} (each at most 1, so
  // the basis stays well conditioned however long the window).
  const auto residual = [&](double lambda) {
    Eigen::MatrixXd basis(n, 2);
    basis.col(0) = (lambda * (t.array() - t_end)).exp();
    basis.col(1) = (-lambda * t.array()).exp();
    const Eigen::MatrixXd amplitudes = basis.householderQr().solve(y);
    return (basis * amplitudes - y).squaredNorm();
  };
  // A first guess from a pure cosh growth, share0 -> share_limit; the fit's rate
  // lies within a factor of a few of it, so a bracket of 8x either way holds it.
  const double guess = std::acosh(share_limit / share0) / t_end;
  const auto [rate, sum_squares] = boost::math::tools::brent_find_minima(
      residual, guess / 8, guess * 8, std::numeric_limits<double>::digits / 2);

  GrowthFit fit;
  fit.rate = rate;
  fit.t_begin = 0.0;
  fit.t_end = t_end;
  fit.share_begin = share0;
  fit.share_end = transverse_share(motion.omega_body(t_end), axis);
  fit.rms_residual = std::sqrt(sum_squares / (2.0 * n)) / y.cwiseAbs().maxCoeff();
  fit.samples = static_cast<std::size_t>(n);
  return fit;
}

CosineRange direction_cosine_range(const FreeBodyExact& motion, int axis, double t_span) {
  const double c0 = cosine_with_L(motion, axis, 0.0);
  CosineRange range{c0, c0};
  if (motion.regime() == FreeMotionRegime::kSteady || !(t_span > 0.0)) return range;
  if (!std::isfinite(t_span))
    throw std::invalid_argument("direction_cosine_range: t_span must be finite");
  // 2048 samples resolve every extremum of a period to within one cell; Brent's
  // method then finds it to ~sqrt(eps) in t, which is eps in the value.
  const int cells = 2048;
  int i_min = 0, i_max = 0;
  for (int n = 1; n <= cells; ++n) {
    const double c = cosine_with_L(motion, axis, t_span * n / cells);
    if (c < range.min) range.min = c, i_min = n;
    if (c > range.max) range.max = c, i_max = n;
  }
  const auto refine = [&](int i, double sign) {
    const double lo = t_span * std::max(i - 1, 0) / cells;
    const double hi = t_span * std::min(i + 1, cells) / cells;
    const auto f = [&](double t) { return sign * cosine_with_L(motion, axis, t); };
    return sign *
           boost::math::tools::brent_find_minima(f, lo, hi, std::numeric_limits<double>::digits / 2)
               .second;
  };
  range.min = std::min(range.min, refine(i_min, 1.0));
  range.max = std::max(range.max, refine(i_max, -1.0));
  return range;
}

}  // namespace rigid
