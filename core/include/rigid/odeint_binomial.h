// Boost.Math's binomial coefficient in double, for the small arguments Odeint's
// Bulirsch-Stoer dense output asks of it on every step (its finite differences
// take C(kappa, c) with kappa at most twice the extrapolation order plus one).
//
// Boost 1.74 computes it from its long-double factorial table, which C++14's
// constexpr tables make a local array: every call copies 171 long doubles onto
// the stack, three copies a coefficient. That copying was 15 % of a whole lab's
// comparison of every method (perf: poinsot, 1000 periods), for coefficients
// that are small whole numbers. Here they are multiplied out exactly in integers
// instead: the same double (Boost rounds its quotient to the nearest whole
// number, and every C(n, k) with n <= 56 is below 2^53, so a double holds it
// exactly), so a run's numbers are unchanged to the bit. Larger arguments keep
// Boost's path.
//
// Must be included before Odeint's bulirsch_stoer_dense_out.hpp (ode.h does), so
// that its one call sees this specialisation; it is the only caller here.
#pragma once

#include <boost/math/special_functions/binomial.hpp>
#include <cstdint>

namespace boost::math {

template <>
inline double binomial_coefficient<double>(unsigned n, unsigned k) {
  constexpr unsigned kExactUpTo = 56;  // C(56, 28) < 2^53; below, i * C(n - k + i, i) < 2^64
  if (k > n || n > kExactUpTo) return binomial_coefficient<double>(n, k, policies::policy<>());
  if (k > n - k) k = n - k;
  std::uint64_t c = 1;
  // c * (n - k + i) / i is C(n - k + i, i), a whole number, at every step.
  for (unsigned i = 1; i <= k; ++i) c = c * (n - k + i) / i;
  return static_cast<double>(c);
}

}  // namespace boost::math
