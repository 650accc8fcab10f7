// Scenes that every lab of the free body draws alike (poinsot, tennis_racquet):
// the camera that looks at a body's ellipsoids, and the polhodes on one energy
// ellipsoid split by the separatrix (section 4.1).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "rigid/free_body_exact.h"
#include "rigid/render/scene3d.h"

namespace rigid::lab {

/// Looks at ellipsoids of semi-axes up to `size` from between the axes.
void frame_camera(render::Scene3D& scene, double size);

/// Polhodes on the motion's energy ellipsoid, about the largest and the smallest
/// axis, the separatrix through the intermediate axis, and `polhode` (this body's,
/// from omega0) drawn over them.
render::Scene3D polhodes_scene(const FreeBodyExact& motion, const Eigen::Vector3d& omega0,
                               const std::vector<std::vector<Eigen::Vector3d>>& polhode);

}  // namespace rigid::lab
