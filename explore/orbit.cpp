// Turning a fitted camera about its target (orbit.h).
#include "orbit.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace rigid::explore {

namespace {
constexpr double kPi = 3.14159265358979323846;
// a zoom beyond these shows nothing a student would want: the scene a dot, or inside it
constexpr double kMinZoom = 0.1, kMaxZoom = 20.0;
// short of the poles, where "up" and the line of sight would meet
constexpr double kMaxElevationDeg = 89.0;
}  // namespace

void Orbit::drag(double dx, double dy, double height) {
  // a drag across the view's height turns it by 180 degrees
  const double deg_per_px = 180.0 / std::max(height, 1.0);
  yaw_deg -= dx * deg_per_px;
  pitch_deg += dy * deg_per_px;
  clamp();
}

void Orbit::wheel(double steps) {
  zoom *= std::pow(1.1, steps);
  clamp();
}

void Orbit::clamp() {
  if (!std::isfinite(yaw_deg)) yaw_deg = 0.0;
  if (!std::isfinite(pitch_deg)) pitch_deg = 0.0;
  if (!std::isfinite(zoom)) zoom = 1.0;
  yaw_deg = std::remainder(yaw_deg, 360.0);
  pitch_deg = std::clamp(pitch_deg, -180.0, 180.0);
  zoom = std::clamp(zoom, kMinZoom, kMaxZoom);
}

render::Camera Orbit::apply(const render::Camera& base) const {
  render::Camera c = base;
  const Eigen::Vector3d up = base.up.normalized();
  Eigen::Vector3d sight = base.eye - base.target;
  const double distance = sight.norm();
  if (!(distance > 0.0) || !std::isfinite(distance)) return c;
  sight /= distance;
  // the view's present elevation over the plane normal to up, and the turn asked for,
  // kept short of the poles
  const double elevation = std::asin(std::clamp(sight.dot(up), -1.0, 1.0)) * 180.0 / kPi;
  const double wanted =
      std::clamp(elevation + pitch_deg, -kMaxElevationDeg, kMaxElevationDeg) - elevation;
  Eigen::Vector3d right = up.cross(sight);
  if (right.norm() < 1e-12) right = up.unitOrthogonal();
  right.normalize();
  const Eigen::Vector3d turned = Eigen::AngleAxisd(yaw_deg * kPi / 180.0, up) *
                                 (Eigen::AngleAxisd(-wanted * kPi / 180.0, right) * sight);
  c.eye = base.target + turned * (distance / zoom);
  if (c.orthographic) c.ortho_height = base.ortho_height / zoom;
  return c;
}

void Orbit::turn(double right_deg, double up_deg) {
  yaw_deg += right_deg;
  pitch_deg += up_deg;
  clamp();
}

void Orbit::zoom_by(double factor) {
  zoom *= factor;
  clamp();
}

}  // namespace rigid::explore
