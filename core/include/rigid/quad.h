// 113-bit floating point (IEEE quadruple precision's significand) for the few sums and
// differences that decide an answer at a limit: a turning circle a hair from a pole, a
// tilt at its largest, a mass balancing a tilt of 1e-300 rad. Boost.Multiprecision's
// cpp_bin_float_quad, header-only, the same on every compiler and in WebAssembly; each
// value is rounded to a double once, where the double arithmetic can take over.
#pragma once

#include <boost/multiprecision/cpp_bin_float.hpp>

namespace rigid {

using Quad = boost::multiprecision::cpp_bin_float_quad;

}  // namespace rigid
