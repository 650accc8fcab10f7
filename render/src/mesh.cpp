// Mesh generators for the unit shapes and tubes.
#include "rigid/render/mesh.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace rigid::render {

namespace {

using V3 = Eigen::Vector3f;

std::uint32_t add_vertex(Mesh& m, const V3& p, const V3& n) {
  m.positions.push_back(p);
  m.normals.push_back(n);
  return static_cast<std::uint32_t>(m.positions.size() - 1);
}

void add_tri(Mesh& m, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  m.indices.insert(m.indices.end(), {a, b, c});
}

// A flat disk cap at height z with normal ±z.
void add_cap(Mesh& m, int slices, float z, bool up) {
  const V3 n(0, 0, up ? 1.f : -1.f);
  const std::uint32_t c = add_vertex(m, V3(0, 0, z), n);
  const std::uint32_t first = static_cast<std::uint32_t>(m.positions.size());
  for (int i = 0; i <= slices; ++i) {
    const double a = 2 * EIGEN_PI * i / slices;
    add_vertex(m, V3(float(std::cos(a)), float(std::sin(a)), z), n);
  }
  for (int i = 0; i < slices; ++i) {
    if (up)
      add_tri(m, c, first + i, first + i + 1);
    else
      add_tri(m, c, first + i + 1, first + i);
  }
}

}  // namespace

Mesh make_sphere(int slices) {
  slices = std::max(slices, 6);
  const int stacks = std::max(3, slices / 2);
  Mesh m;
  for (int j = 0; j <= stacks; ++j) {
    const double th = EIGEN_PI * j / stacks;
    for (int i = 0; i <= slices; ++i) {
      const double ph = 2 * EIGEN_PI * i / slices;
      const V3 p(float(std::sin(th) * std::cos(ph)), float(std::sin(th) * std::sin(ph)),
                 float(std::cos(th)));
      add_vertex(m, p, p);
    }
  }
  const int row = slices + 1;
  for (int j = 0; j < stacks; ++j)
    for (int i = 0; i < slices; ++i) {
      const std::uint32_t a = j * row + i, b = a + 1, c = a + row, d = c + 1;
      if (j != 0) add_tri(m, a, c, b);
      if (j != stacks - 1) add_tri(m, b, c, d);
    }
  return m;
}

Mesh make_cone(int slices) {
  slices = std::max(slices, 6);
  Mesh m;
  // Side normals tilt up by 45° for the unit cone (radius 1, height 1); apex per segment.
  const float k = 1.0f / std::sqrt(2.0f);
  for (int i = 0; i < slices; ++i) {
    const double a0 = 2 * EIGEN_PI * i / slices, a1 = 2 * EIGEN_PI * (i + 1) / slices,
                 am = 0.5 * (a0 + a1);
    const V3 n0(float(std::cos(a0)) * k, float(std::sin(a0)) * k, k);
    const V3 n1(float(std::cos(a1)) * k, float(std::sin(a1)) * k, k);
    const V3 nm(float(std::cos(am)) * k, float(std::sin(am)) * k, k);
    const auto b0 = add_vertex(m, V3(float(std::cos(a0)), float(std::sin(a0)), 0), n0);
    const auto b1 = add_vertex(m, V3(float(std::cos(a1)), float(std::sin(a1)), 0), n1);
    const auto t = add_vertex(m, V3(0, 0, 1), nm);
    add_tri(m, b0, b1, t);
  }
  add_cap(m, slices, 0, false);
  return m;
}

Mesh make_cylinder(int slices) {
  slices = std::max(slices, 6);
  Mesh m;
  for (int i = 0; i <= slices; ++i) {
    const double a = 2 * EIGEN_PI * i / slices;
    const V3 n(float(std::cos(a)), float(std::sin(a)), 0);
    add_vertex(m, V3(n.x(), n.y(), 0), n);
    add_vertex(m, V3(n.x(), n.y(), 1), n);
  }
  for (int i = 0; i < slices; ++i) {
    const std::uint32_t a = 2 * i, b = a + 1, c = a + 2, d = a + 3;
    add_tri(m, a, c, b);
    add_tri(m, b, c, d);
  }
  add_cap(m, slices, 0, false);
  add_cap(m, slices, 1, true);
  return m;
}

Mesh make_disk(int slices) {
  Mesh m;
  add_cap(m, std::max(slices, 6), 0, true);
  return m;
}

Mesh make_box() {
  Mesh m;
  for (int axis = 0; axis < 3; ++axis)
    for (int sign = -1; sign <= 1; sign += 2) {
      V3 n = V3::Zero();
      n[axis] = float(sign);
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      std::uint32_t idx[4];
      const float uv[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
      for (int k = 0; k < 4; ++k) {
        V3 p = n;
        p[u] = uv[k][0];
        p[v] = uv[k][1];
        idx[k] = add_vertex(m, p, n);
      }
      // Wind counter-clockwise seen from outside.
      if (sign > 0) {
        add_tri(m, idx[0], idx[1], idx[2]);
        add_tri(m, idx[0], idx[2], idx[3]);
      } else {
        add_tri(m, idx[0], idx[2], idx[1]);
        add_tri(m, idx[0], idx[3], idx[2]);
      }
    }
  return m;
}

Mesh make_torus(double minor, int major_segments, int minor_segments) {
  major_segments = std::max(major_segments, 8);
  minor_segments = std::max(minor_segments, 6);
  Mesh m;
  for (int i = 0; i <= major_segments; ++i) {
    const double u = 2 * EIGEN_PI * i / major_segments;
    for (int j = 0; j <= minor_segments; ++j) {
      const double v = 2 * EIGEN_PI * j / minor_segments;
      const V3 n(float(std::cos(v) * std::cos(u)), float(std::cos(v) * std::sin(u)),
                 float(std::sin(v)));
      const V3 c(float(std::cos(u)), float(std::sin(u)), 0);
      add_vertex(m, c + float(minor) * n, n);
    }
  }
  const int row = minor_segments + 1;
  for (int i = 0; i < major_segments; ++i)
    for (int j = 0; j < minor_segments; ++j) {
      const std::uint32_t a = i * row + j, b = a + 1, c = a + row, d = c + 1;
      add_tri(m, a, c, b);
      add_tri(m, b, c, d);
    }
  return m;
}

Mesh make_plane() {
  Mesh m;
  const V3 n(0, 0, 1);
  const auto a = add_vertex(m, V3(-1, -1, 0), n), b = add_vertex(m, V3(1, -1, 0), n),
             c = add_vertex(m, V3(1, 1, 0), n), d = add_vertex(m, V3(-1, 1, 0), n);
  add_tri(m, a, b, c);
  add_tri(m, a, c, d);
  return m;
}

Mesh make_tube(const std::vector<Eigen::Vector3d>& path_in, double radius, int sides) {
  sides = std::max(sides, 4);
  Mesh m;
  std::vector<Eigen::Vector3d> path;
  for (const auto& p : path_in)
    if (path.empty() || (p - path.back()).norm() > 1e-9 * std::max(1.0, radius)) path.push_back(p);
  if (path.size() < 2) return m;
  const std::size_t n = path.size();
  // Tangents at vertices: average of adjacent segment directions.
  std::vector<Eigen::Vector3d> tangent(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d a = (path[std::min(i + 1, n - 1)] - path[i]).normalized();
    const Eigen::Vector3d b = (path[i] - path[i == 0 ? 0 : i - 1]).normalized();
    tangent[i] = (i == 0 ? a : i == n - 1 ? b : (a + b)).normalized();
    if (!tangent[i].allFinite() || tangent[i].norm() < 0.5) tangent[i] = i == 0 ? a : b;
  }
  // Parallel transport of a normal along the path (no twist).
  Eigen::Vector3d normal = tangent[0].unitOrthogonal();
  std::vector<Eigen::Vector3d> normals(n);
  normals[0] = normal;
  for (std::size_t i = 1; i < n; ++i) {
    normal = (normal - normal.dot(tangent[i]) * tangent[i]);
    if (normal.norm() < 1e-9) normal = tangent[i].unitOrthogonal();
    normals[i] = normal.normalized();
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d b = tangent[i].cross(normals[i]);
    for (int j = 0; j <= sides; ++j) {
      const double a = 2 * EIGEN_PI * j / sides;
      const Eigen::Vector3d d = std::cos(a) * normals[i] + std::sin(a) * b;
      add_vertex(m, (path[i] + radius * d).cast<float>(), d.cast<float>());
    }
  }
  const std::uint32_t row = sides + 1;
  for (std::uint32_t i = 0; i + 1 < n; ++i)
    for (int j = 0; j < sides; ++j) {
      const std::uint32_t a = i * row + j, b = a + 1, c = a + row, d = c + 1;
      add_tri(m, a, b, c);
      add_tri(m, b, d, c);
    }
  // End caps.
  for (int end = 0; end < 2; ++end) {
    const std::size_t i = end == 0 ? 0 : n - 1;
    const Eigen::Vector3f nn = (end == 0 ? -tangent[i] : tangent[i]).cast<float>();
    const Eigen::Vector3d b = tangent[i].cross(normals[i]);
    const auto c = add_vertex(m, path[i].cast<float>(), nn);
    const auto first = static_cast<std::uint32_t>(m.positions.size());
    for (int j = 0; j <= sides; ++j) {
      const double a = 2 * EIGEN_PI * j / sides;
      add_vertex(m, (path[i] + radius * (std::cos(a) * normals[i] + std::sin(a) * b)).cast<float>(),
                 nn);
    }
    for (int j = 0; j < sides; ++j) {
      if (end == 0)
        add_tri(m, c, first + j + 1, first + j);
      else
        add_tri(m, c, first + j, first + j + 1);
    }
  }
  return m;
}

int segments_for_radius(double radius_px) {
  // What the screen needs: n edges of a circle of radius r pixels miss it by
  // at most r (1 - cos(pi / n)); keep that under kChordError pixels, a small
  // fraction of one MSAA sample spacing, so the silhouette is as round as the
  // true surface. (Shading does not depend on n: normals are exact per vertex
  // and interpolated per fragment.) A 450 px ellipsoid gets 108 edges, a
  // 5 px tube 12.
  constexpr double kChordError = 0.2;
  const double r = std::max(radius_px, kChordError);
  const double n = EIGEN_PI / std::acos(std::max(1.0 - kChordError / r, -1.0));
  return std::clamp(static_cast<int>(std::ceil(n / 4.0)) * 4, 12, 160);
}

}  // namespace rigid::render
