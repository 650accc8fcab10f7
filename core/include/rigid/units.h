// Angle units: radians inside rigidlab, degrees only at the command line and in
// JSON keys ending in _deg.
#pragma once

namespace rigid {

inline constexpr double kPi =
    3.141592653589793238462643383279502884;  // the one pi of core and labs

/// Degrees from radians.
constexpr double rad_to_deg(double rad) {
  return rad * (180.0 / kPi);
}
/// Radians from degrees.
constexpr double deg_to_rad(double deg) {
  return deg * (kPi / 180.0);
}

}  // namespace rigid
