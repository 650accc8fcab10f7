// Numbers as text, for core's error messages and the labs' tables: one
// formatter, locale-independent (std::to_chars), never a negative zero.
#pragma once

#include <Eigen/Core>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace rigid {

/// x in the shortest form that reads back as the same double, %g-like ("1e-320",
/// "0.3", "2.0000001"): six significant digits would print 2.0000001 as 2, so a
/// message like "1 + 1 < 2" could contradict itself.
inline std::string format_number(double x) {
  char buf[32];
#if defined(__cpp_lib_to_chars)
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof buf, x + 0.0);
  return std::string(buf, r.ptr);
#else
  // libc++ before 17 (emscripten's) has no floating-point to_chars: %g at the
  // fewest digits that read back, the same digits (where the two would choose
  // fixed or exponent notation differently, this prints %g's choice).
  for (int digits = 1; digits < 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, x + 0.0);
    if (std::strtod(buf, nullptr) == x) return buf;
  }
  std::snprintf(buf, sizeof buf, "%.17g", x + 0.0);
  return buf;
#endif
}

/// x to `significant` digits as printf's %g writes it ("0.493333", "1e-07").
inline std::string format_number(double x, int significant) {
  char buf[64];
#if defined(__cpp_lib_to_chars)
  const std::to_chars_result r =
      std::to_chars(buf, buf + sizeof buf, x + 0.0, std::chars_format::general, significant);
  return std::string(buf, r.ptr);
#else
  std::snprintf(buf, sizeof buf, "%.*g", significant, x + 0.0);
  return buf;
#endif
}

/// v as "(x, y, z)" with format_number's shortest components.
inline std::string format_vector(const Eigen::Vector3d& v) {
  return "(" + format_number(v.x()) + ", " + format_number(v.y()) + ", " + format_number(v.z()) +
         ")";
}

}  // namespace rigid
