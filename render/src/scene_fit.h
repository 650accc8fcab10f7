// Internal: the camera of a 3D scene: view and projection matrices, and the
// fit that frames the scene in the region the overlay leaves (Camera::fit).
#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "rigid/render/rect.h"
#include "rigid/render/scene3d.h"

namespace rigid::render::detail {

/// View and projection for a camera at an aspect ratio, with depth range fitted to the scene.
struct View {
  Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
  Eigen::Matrix4d proj = Eigen::Matrix4d::Identity();
  double focal_px = 1;  // pixels per unit length at unit depth (perspective) or per unit (ortho)
  bool ortho = false;
  int width = 1, height = 1;

  /// Screen position in logical pixels (y down) and NDC depth; w <= 0 means behind the camera.
  Eigen::Vector4d project(const Eigen::Vector3d& p) const {
    const Eigen::Vector4d c = proj * view * p.homogeneous();
    if (c.w() <= 1e-12) return {0, 0, 0, -1};
    const Eigen::Vector3d n = c.head<3>() / c.w();
    return {(n.x() + 1) * 0.5 * width, (1 - n.y()) * 0.5 * height, n.z(), 1};
  }
  double depth(const Eigen::Vector3d& p) const { return -(view * p.homogeneous()).z(); }
  /// Pixels covered by a length r at point p.
  double pixels(double r, const Eigen::Vector3d& p) const {
    return ortho ? r * focal_px : r * focal_px / std::max(1e-6, depth(p));
  }
};

/// The view of a camera at an image size with a depth range.
View make_view(const Camera& cam, int width, int height, double znear, double zfar);

/// What the fit keeps in view: a sphere of a world radius about p (0 for a point), and a
/// screen box reaching left, right, up and down that many pixels beyond its projection
/// (a label's text, half a line's width).
struct FitPoint {
  Eigen::Vector3d p;
  double radius = 0;
  double left = 0, right = 0, up = 0, down = 0;
};

/// The surfaces and lines of a scene as fit points (labels are added by the caller).
std::vector<FitPoint> fit_points(const Scene3D& scene, double geometry_scale);

/// The camera moved along its line of sight and sideways (direction and up kept) so every
/// point lies in `region` and clear of `legend` by `margin` (unchanged if cam.fit is off).
Camera fitted(Camera cam, const std::vector<FitPoint>& points, const ScreenRect& region,
              const ScreenRect& legend, double margin, int width, int height);

/// Depth range of the points seen from a camera, padded a little.
std::pair<double, double> depth_range(const Camera& cam, const std::vector<FitPoint>& points);

}  // namespace rigid::render::detail
