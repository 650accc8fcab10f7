// 113-bit floating point (IEEE quadruple precision's significand) for the few sums and
// differences that decide an answer at a limit: a turning circle a hair from a pole, a
// tilt at its largest, a mass balancing a tilt of 1e-300 rad. Boost.Multiprecision's
// cpp_bin_float_quad, header-only, the same on every compiler and in WebAssembly; each
// value is rounded to a double once, where the double arithmetic can take over.
#pragma once

#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <optional>

#include "rigid/units.h"

namespace rigid {

using Quad = boost::multiprecision::cpp_bin_float_quad;

/// An angle in radians as a Quad: from its degrees `deg` where they are given and are this
/// angle's (deg_to_rad(deg) == rad), to a Quad's last bits where a double's radians keep an
/// angle only to ulp(pi) (179.9999999 deg: its distance from 180 to 1e-7 of itself); else
/// `rad` itself, so that a copy whose radians were changed since does not keep stale degrees.
inline Quad quad_angle(double rad, const std::optional<double>& deg) {
  if (deg && deg_to_rad(*deg) == rad) {
    return Quad(*deg) * boost::math::constants::pi<Quad>() / 180;
  }
  return Quad(rad);
}

}  // namespace rigid
