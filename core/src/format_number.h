// Numbers in core's error messages (private to core; no fmt here).
#pragma once

#include <Eigen/Core>
#include <charconv>
#include <string>

namespace rigid {

/// x in the shortest form that reads back as the same double, %g-like ("1e-320",
/// "0.3", "2.0000001"): std::to_string's fixed six decimals print 1e-320 as
/// 0.000000, and six significant digits print 2.0000001 as 2, so a message
/// like "1 + 1 < 2" could contradict itself. Locale-independent.
inline std::string format_number(double x) {
  char buf[32];
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

/// v as "(x, y, z)" with format_number's components.
inline std::string format_vector(const Eigen::Vector3d& v) {
  return "(" + format_number(v.x()) + ", " + format_number(v.y()) + ", " + format_number(v.z()) +
         ")";
}

}  // namespace rigid
