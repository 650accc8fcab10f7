// 113-bit floating point (IEEE quadruple precision's significand) for the few sums and
// differences that decide an answer at a limit: a turning circle a hair from a pole, a
// tilt at its largest, a mass balancing a tilt of 1e-300 rad. Boost.Multiprecision's
// cpp_bin_float_quad, header-only, the same on every compiler and in WebAssembly; each
// value is rounded to a double once, where the double arithmetic can take over.
#pragma once

#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

namespace rigid {

using Quad = boost::multiprecision::cpp_bin_float_quad;

/// An angle given in degrees in radians, to a Quad's last bits: where a double's radians
/// keep an angle only to ulp(pi) (179.9999999 deg: its distance from 180 to 1e-7 of
/// itself), this keeps the angle meant.
inline Quad quad_radians(double deg) {
  return Quad(deg) * boost::math::constants::pi<Quad>() / 180;
}

}  // namespace rigid
