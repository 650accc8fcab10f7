// Inertia tensors of rigid bodies (chapter sections 1, 2, 2.1, 2.3, 2.4, 3.1).
//
// Conventions, as in the text:
//  - The tensor holds the moments on its diagonal (eqs. 6-8) and the products
//    of inertia WITH the text's negative sign off the diagonal (eqs. 9-11):
//    I_xy = -sum m x y.
//  - Every primitive is built about its own centre of mass, in its own frame;
//    `shifted` and `rotated` place it, and `+` sums parts into one body.
//  - SI units: kg, m, kg m^2, rad/s.
#pragma once

#include <Eigen/Dense>

namespace rigid {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

/// A rigid body: its mass, centre of mass, and inertia tensor about that centre.
struct Body {
  double mass = 0.0;
  Vec3 com = Vec3::Zero();
  Mat3 I_com = Mat3::Zero();
};

/// A point mass m at position r.
Body point_mass(double m, const Vec3& r);
/// A thin rod of mass m and length l along the x axis, centred on the origin.
Body thin_rod(double m, double l);
/// A thin ring of mass m and radius a in the x-y plane (symmetry axis z).
Body thin_ring(double m, double a);
/// A uniform thin disk (circular lamina) of mass m and radius a in the x-y plane.
Body thin_disk(double m, double a);
/// A uniform rectangular lamina of mass m, side a along x and b along y, centred.
Body rectangular_lamina(double m, double a, double b);
/// A uniform solid box of mass m and sides a, b, c along x, y, z, centred.
Body solid_box(double m, double a, double b, double c);
/// A uniform solid ellipsoid of mass m and semi-axes a, b, c along x, y, z.
Body solid_ellipsoid(double m, double a, double b, double c);
/// A uniform solid sphere of mass m and radius r.
Body solid_sphere(double m, double r);

/// The section 2.1 model paddle about its centre of mass: a disk of mass m/2 and
/// radius a joined to a rod of mass m/2 and length 2a, symmetry axis x, in the x-y plane.
Body model_paddle(double m, double a);

/// A rectangular lamina of mass m, sides a (x) and b (y), in the x-y plane.
struct Lamina {
  double mass = 1.0;
  double a = 1.0;
  double b = 2.0;
  bool corner_origin = true;  ///< origin at a corner (the lamina in x, y >= 0) or the centre
};

/// The lamina's inertia tensor about its origin (eq. 20 for the corner, eq. 70 for the centre).
Mat3 lamina_tensor(const Lamina& lamina);

/// The body moved rigidly by the displacement d.
Body shifted(const Body& body, const Vec3& d);
/// The body turned rigidly by the rotation R about the origin.
Body rotated(const Body& body, const Mat3& R);
/// The composite of two bodies: masses add, centres average, tensors shift and add.
Body operator+(const Body& a, const Body& b);

/// Parallel-axis theorem: the tensor about `origin` of a body given about its centre.
Mat3 inertia_about(const Body& body, const Vec3& origin);

/// Scalar moment of inertia about the unit axis n through the tensor's origin (eq. 16).
double moment_about_axis(const Mat3& I, const Vec3& n);
/// Angular momentum L = I omega (eq. 27).
Vec3 angular_momentum(const Mat3& I, const Vec3& omega);
/// Rotational kinetic energy T = omega . I omega / 2 (eq. 33).
double kinetic_energy(const Mat3& I, const Vec3& omega);
/// Angle between two non-zero vectors in radians, accurate near 0 and pi.
double angle_between(const Vec3& a, const Vec3& b);

/// Principal moments (ascending) and axes (row i is the unit axis of moments[i]).
struct PrincipalAxes {
  Vec3 moments = Vec3::Zero();
  Mat3 axes = Mat3::Identity();
};

/// Diagonalises a valid inertia tensor (eqs. 62-66); the axes form a right-handed set.
PrincipalAxes principal_axes(const Mat3& I);

/// Principal axes in the x-y plane of a tensor whose z axis is principal (eqs. 45-56).
struct InPlaneAxes {
  double two_theta = 0.0;  ///< 2 theta in (-pi/2, pi/2], tan 2 theta = 2 Ixy / (Ixx - Iyy) (eq. 53)
  double theta = 0.0;      ///< one principal axis, rad from x, in (-pi/4, pi/4]
  double moment = 0.0;     ///< moment about it, Ixx + Ixy tan theta (eq. 50)
  double theta_other = 0.0;   ///< the perpendicular principal axis, theta +- pi/2 in (-pi/2, pi/2]
  double moment_other = 0.0;  ///< moment about it
};

/// Solves tan 2 theta = 2 Ixy / (Ixx - Iyy) for the in-plane principal axes;
/// throws std::invalid_argument if z is not a principal axis (Ixz or Iyz nonzero).
InPlaneAxes in_plane_principal_axes(const Mat3& I);

/// Torque that holds the body turning at constant omega about a fixed axis,
/// N = omega x (I omega) (eqs. 74-76, in whatever frame I and omega share).
Vec3 fixed_axis_torque(const Mat3& I, const Vec3& omega);

/// Throws std::invalid_argument unless I is finite, symmetric, positive definite
/// and its principal moments satisfy the triangle inequality I1 + I2 >= I3.
void validate_inertia_tensor(const Mat3& I);

}  // namespace rigid
