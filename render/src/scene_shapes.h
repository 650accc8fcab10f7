// Internal: facts about a scene's shapes that drawing, the camera fit and the
// label placement share (description library; no GL).
#pragma once

#include <utility>

#include "rigid/render/mesh.h"
#include "rigid/render/scene3d.h"

namespace rigid::render::detail {

/// The minor/major ratio of a torus in thousandths (0 for other shapes): a cache key.
int torus_ratio_key(Scene3D::Shape shape, double torus_minor);

// An open surface (a disk, a plane) has no back: seen through once, drawn both sides.
inline bool is_open(Scene3D::Shape shape) {
  return shape == Scene3D::Shape::kDisk || shape == Scene3D::Shape::kPlane;
}

/// The unit mesh of a built-in shape with `segments` around (empty for tubes and custom meshes).
Mesh unit_shape_mesh(Scene3D::Shape shape, int segments, int ratio);

/// Bounding sphere of an object in world space (centre, radius).
std::pair<Eigen::Vector3d, double> bounds(const Scene3D::Object& o);

/// The largest distance from the origin that any object or polyline reaches.
double scene_extent(const Scene3D& scene);

/// The factor that brings a scene to about unit size for GL's floats (1 when it already is).
double normalising_scale(const Scene3D& scene);

}  // namespace rigid::render::detail
