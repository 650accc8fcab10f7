// Triangle meshes for 3D scenes. The unit shapes (sphere, cone, cylinder,
// disk, box, torus, plane) are made once per process per tessellation level
// and placed by a transform; tubes are built per polyline. Normals point
// outwards; triangles wind counter-clockwise seen from outside.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace rigid::render {

/// An indexed triangle mesh with per-vertex normals.
struct Mesh {
  std::vector<Eigen::Vector3f> positions;
  std::vector<Eigen::Vector3f> normals;
  std::vector<std::uint32_t> indices;  ///< three per triangle
};

/// Unit sphere (radius 1, centre 0) with `slices` around z and slices/2 stacks.
Mesh make_sphere(int slices);
/// Cone with apex (0,0,1) and base circle of radius 1 in z = 0, base cap included.
Mesh make_cone(int slices);
/// Cylinder of radius 1 from z = 0 to z = 1, with end caps.
Mesh make_cylinder(int slices);
/// Disk of radius 1 in the plane z = 0, facing +z (both sides are lit).
Mesh make_disk(int slices);
/// Cube [-1, 1]^3 with flat faces.
Mesh make_box();
/// Torus about z with major radius 1 and tube radius `minor` (< 1).
Mesh make_torus(double minor, int major_segments, int minor_segments);
/// Square [-1, 1]^2 in z = 0, facing +z.
Mesh make_plane();
/// Tube of a given radius along a polyline (parallel-transport frames), capped at both ends.
Mesh make_tube(const std::vector<Eigen::Vector3d>& path, double radius, int sides);

/// Segment count around a circle of the given on-screen radius in pixels (chord error under 0.2
/// px, 12..160).
int segments_for_radius(double radius_px);

}  // namespace rigid::render
