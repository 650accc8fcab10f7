#include "rigid/free_body.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "rigid/format.h"

namespace rigid {

void validate(const PrincipalMoments& I, MomentsRule rule) {
  const double m[3] = {I.I1, I.I2, I.I3};
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(m[i]) || !(m[i] > 0.0)) {
      throw std::invalid_argument("principal moment I" + std::to_string(i + 1) +
                                  " must be positive and finite, got " + format_number(m[i]));
    }
  }
  if (rule == MomentsRule::kPositiveOnly) return;
  // A few ulps of slack: a lamina's I3 = I1 + I2 may round either way.
  constexpr double kSlack = 4.0 * std::numeric_limits<double>::epsilon();
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const int lo = std::min(i, j), hi = std::max(i, j);
    if (m[lo] + m[hi] < m[k] * (1.0 - kSlack)) {
      throw std::invalid_argument(
          "principal moments must satisfy the triangle inequality I" + std::to_string(lo + 1) +
          " + I" + std::to_string(hi + 1) + " >= I" + std::to_string(k + 1) + ", got " +
          format_number(m[lo]) + " + " + format_number(m[hi]) + " < " + format_number(m[k]));
    }
  }
}

Eigen::Vector3d L_body(const PrincipalMoments& I, const Eigen::Vector3d& omega_body) {
  return {I.I1 * omega_body.x(), I.I2 * omega_body.y(), I.I3 * omega_body.z()};
}

Eigen::Vector3d L_space(const PrincipalMoments& I, const RotationState& x) {
  return attitude(x).normalized() * L_body(I, omega_body(x));
}

double kinetic_energy(const PrincipalMoments& I, const Eigen::Vector3d& w) {
  return 0.5 * (I.I1 * w.x() * w.x() + I.I2 * w.y() * w.y() + I.I3 * w.z() * w.z());
}

double angular_momentum_magnitude(const PrincipalMoments& I, const Eigen::Vector3d& w) {
  return L_body(I, w).stableNorm();  // scaled: neither underflows nor overflows
}

}  // namespace rigid
