#include "common/free_body_scenes.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "common/figures.h"
#include "rigid/poinsot.h"
#include "rigid/units.h"

namespace rigid::lab {
using Eigen::Vector3d;

// A camera that looks at the ellipsoids from between the axes.
void frame_camera(render::Scene3D& scene, double size) {
  scene.camera.eye = size * Vector3d(3.2, 2.3, 2.0);
  scene.camera.target = Vector3d(0, 0, 0.2 * size);
  scene.camera.fov_y_deg = 27;
}

namespace {

// A family of polhodes named by the axis it circles: that of the largest moment is the
// energy ellipsoid's shortest axis (semi-axis sqrt(2T / I)), which "the largest axis" had
// a student look for on the ellipsoid.
std::string family_name(bool about_largest, Eigen::Index largest, Eigen::Index smallest) {
  return about_largest
             ? fmt::format("polhodes about \\omega_{}: largest I, shortest semi-axis", largest + 1)
             : fmt::format("polhodes about \\omega_{}: smallest I, longest semi-axis",
                           smallest + 1);
}

}  // namespace

// Polhodes on one energy ellipsoid, about the axes of the largest and the smallest moment (in
// the colours of those principal axes), split by the separatrix through the
// intermediate axis (section 4.1); this body's in omega's colour.
render::Scene3D polhodes_scene(const FreeBodyExact& motion, const Vector3d& omega0,
                               const std::vector<std::vector<Vector3d>>& polhode) {
  const PrincipalMoments& I = motion.moments();
  const double T = motion.energy();
  const Vector3d moments = I.vector();
  const double I_min = moments.minCoeff(), I_max = moments.maxCoeff();
  const Vector3d semi = (2.0 * T * moments.cwiseInverse()).cwiseSqrt();
  const double size = semi.maxCoeff();
  render::Scene3D scene;
  scene.title = "polhodes on the energy ellipsoid";
  frame_camera(scene, size);
  scene.add_ellipsoid(Vector3d::Zero(), semi, Eigen::Matrix3d::Identity(),
                      {render::kLightGray, 1.0f, 0.15f}, "energy ellipsoid");
  // Slightly outside the surface so the curves are not buried in it.
  const auto lift = [](std::vector<Vector3d> curve) {
    for (auto& p : curve) p *= 1.004;
    return curve;
  };
  const double I_mid = moments.sum() - I_min - I_max;
  Eigen::Index largest = 0, smallest = 0;  // body axes 1-3 as given, not sorted
  moments.maxCoeff(&largest);
  moments.minCoeff(&smallest);
  const int family = 7;
  for (int k = 1; k <= family; ++k) {
    for (const bool about_largest : {true, false}) {
      // L^2 evenly between 2T I_mid and the end of each family.
      const double end = about_largest ? I_max : I_min;
      const double L2 = 2.0 * T * (I_mid + (end - I_mid) * k / (family + 1.0));
      const Vector3d w = omega_on_energy_ellipsoid(I, T, L2);
      for (const double sign : {1.0, -1.0}) {
        for (const auto& curve : rigid::polhode(I, sign * w, 240)) {
          scene.add_tube(lift(curve), 0.006 * size,
                         {colors::kPrincipal[about_largest ? largest : smallest]},
                         k == 1 && sign > 0 ? family_name(about_largest, largest, smallest) : "");
        }
      }
    }
  }
  bool first = true;
  for (const auto& curve : separatrices(I, T, 400)) {
    scene.add_tube(lift(curve), 0.009 * size, {colors::kSeparatrix}, first ? "separatrix" : "");
    first = false;
  }
  // This body's polhode thinner than the separatrix and lifted above it: near the
  // separatrix (a body spun near its middle axis) it runs along it, and the black shows
  // on each side of the blue rather than under it.
  for (std::size_t k = 0; k < polhode.size(); ++k) {
    std::vector<Vector3d> curve = polhode[k];
    for (auto& p : curve) p *= 1.018;
    scene.add_tube(std::move(curve), 0.0065 * size, {colors::kPolhode},
                   k == 0 ? "this body's polhode" : "");
  }
  scene.add_marker(omega0 * 1.004, 0.03 * size, {colors::kMarker}, "\\omega_0");
  scene.add_axes(Vector3d::Zero(), Eigen::Matrix3d::Identity(), 1.3 * size,
                 {"\\omega_1", "\\omega_2", "\\omega_3"});
  return scene;
}

}  // namespace rigid::lab
