// A sum or product carried in two doubles (Dekker's exact product, Knuth's exact sum):
// about 106 bits from double arithmetic alone, for a few sums that cancel where long
// double is not the x87's hardware type. Where long double is binary128 (WebAssembly,
// AArch64) it is emulated in software at many times the cost; this is not.
#pragma once

namespace rigid {

struct Wide {
  double hi = 0.0, lo = 0.0;

  Wide() = default;
  Wide(double value) : hi(value) {}  // NOLINT: a double is a Wide exactly
  Wide(double h, double l) : hi(h), lo(l) {}
  /// hi and lo of a long double, its first 106 bits.
  static Wide of(long double value) {
    const double h = static_cast<double>(value);
    return {h, static_cast<double>(value - h)};
  }
  double value() const { return hi + lo; }
};

namespace detail {

// a + b exactly, as the rounded sum and its error (Knuth)
inline Wide two_sum(double a, double b) {
  const double s = a + b, v = s - a;
  return {s, (a - (s - v)) + (b - v)};
}
// the same where |a| >= |b|
inline Wide quick_two_sum(double a, double b) {
  const double s = a + b;
  return {s, b - (s - a)};
}
// a * b exactly, as the rounded product and its error (Dekker's split at 2^27 + 1)
inline Wide two_product(double a, double b) {
  constexpr double kSplit = 134217729.0;
  const double p = a * b;
  const double ca = kSplit * a, cb = kSplit * b;
  const double ah = ca - (ca - a), al = a - ah;
  const double bh = cb - (cb - b), bl = b - bh;
  return {p, ((ah * bh - p) + ah * bl + al * bh) + al * bl};
}

}  // namespace detail

inline Wide operator+(const Wide& x, const Wide& y) {
  Wide s = detail::two_sum(x.hi, y.hi);
  s.lo += x.lo + y.lo;
  return detail::quick_two_sum(s.hi, s.lo);
}

inline Wide operator*(const Wide& x, const Wide& y) {
  Wide p = detail::two_product(x.hi, y.hi);
  p.lo += x.hi * y.lo + x.lo * y.hi;
  return detail::quick_two_sum(p.hi, p.lo);
}

}  // namespace rigid
