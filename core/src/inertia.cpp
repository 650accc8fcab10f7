#include "rigid/inertia.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "rigid/format.h"
#include "rigid/units.h"

namespace rigid {
namespace {

// Physical input must be finite and strictly positive: a primitive with zero
// mass or size is not a body.
void require_positive(double value, const char* what) {
  if (!std::isfinite(value) || !(value > 0.0)) {
    throw std::invalid_argument(std::string(what) + " must be a finite positive number, got " +
                                format_number(value));
  }
}

Body diagonal_body(double m, double Ixx, double Iyy, double Izz) {
  Body body;
  body.mass = m;
  body.I_com = Vec3(Ixx, Iyy, Izz).asDiagonal();
  return body;
}

// Tensor of a point mass m at r about the origin: m (|r|^2 1 - r r^T) (eq. 27),
// whose off-diagonal entries carry the text's negative sign (eqs. 9-11).
Mat3 point_tensor(double m, const Vec3& r) {
  // m (|r|^2 1 - r r^T), its diagonal formed as the sums of the other two squares: as
  // |r|^2 - r_i^2 it cancelled (a 1e-3 x 1 lamina's corner I_yy = m a^2 / 3 lost 6e-11)
  Mat3 t = -m * (r * r.transpose());
  t(0, 0) = m * (r.y() * r.y() + r.z() * r.z());
  t(1, 1) = m * (r.x() * r.x() + r.z() * r.z());
  t(2, 2) = m * (r.x() * r.x() + r.y() * r.y());
  return t;
}

}  // namespace

Body point_mass(double m, const Vec3& r) {
  require_positive(m, "mass");
  if (!r.allFinite()) throw std::invalid_argument("point mass position must be finite");
  Body body;
  body.mass = m;
  body.com = r;
  return body;
}

Body thin_rod(double m, double l) {
  require_positive(m, "mass");
  require_positive(l, "rod length");
  return diagonal_body(m, 0.0, m * l * l / 12.0, m * l * l / 12.0);
}

Body thin_ring(double m, double a) {
  require_positive(m, "mass");
  require_positive(a, "ring radius");
  return diagonal_body(m, m * a * a / 2.0, m * a * a / 2.0, m * a * a);
}

Body thin_disk(double m, double a) {
  require_positive(m, "mass");
  require_positive(a, "disk radius");
  return diagonal_body(m, m * a * a / 4.0, m * a * a / 4.0, m * a * a / 2.0);
}

Body rectangular_lamina(double m, double a, double b) {
  require_positive(m, "mass");
  require_positive(a, "lamina side a");
  require_positive(b, "lamina side b");
  return diagonal_body(m, m * b * b / 12.0, m * a * a / 12.0, m * (a * a + b * b) / 12.0);
}

Body solid_box(double m, double a, double b, double c) {
  require_positive(m, "mass");
  require_positive(a, "box side a");
  require_positive(b, "box side b");
  require_positive(c, "box side c");
  // Eq. 40.
  return diagonal_body(m, m * (b * b + c * c) / 12.0, m * (a * a + c * c) / 12.0,
                       m * (a * a + b * b) / 12.0);
}

Body solid_ellipsoid(double m, double a, double b, double c) {
  require_positive(m, "mass");
  require_positive(a, "ellipsoid semi-axis a");
  require_positive(b, "ellipsoid semi-axis b");
  require_positive(c, "ellipsoid semi-axis c");
  return diagonal_body(m, m * (b * b + c * c) / 5.0, m * (a * a + c * c) / 5.0,
                       m * (a * a + b * b) / 5.0);
}

Body solid_sphere(double m, double r) {
  require_positive(m, "mass");
  require_positive(r, "sphere radius");
  return diagonal_body(m, 0.4 * m * r * r, 0.4 * m * r * r, 0.4 * m * r * r);
}

Body model_paddle(double m, double a) {
  // Rod along x from -2a to 0, disk centred at x = a: the centre of mass is
  // where they meet (section 2.1).
  return shifted(thin_rod(m / 2.0, 2.0 * a), Vec3(-a, 0.0, 0.0)) +
         shifted(thin_disk(m / 2.0, a), Vec3(a, 0.0, 0.0));
}

Mat3 lamina_tensor(const Lamina& lamina) {
  const Body body = rectangular_lamina(lamina.mass, lamina.a, lamina.b);
  const Vec3 centre =
      lamina.corner_origin ? Vec3(lamina.a / 2.0, lamina.b / 2.0, 0.0) : Vec3::Zero();
  return inertia_about(shifted(body, centre), Vec3::Zero());
}

Body shifted(const Body& body, const Vec3& d) {
  Body moved = body;
  moved.com += d;
  return moved;
}

Body rotated(const Body& body, const Mat3& R) {
  Body turned;
  turned.mass = body.mass;
  turned.com = R * body.com;
  turned.I_com = R * body.I_com * R.transpose();
  return turned;
}

Body operator+(const Body& a, const Body& b) {
  Body sum;
  sum.mass = a.mass + b.mass;
  sum.com = (a.mass * a.com + b.mass * b.com) / sum.mass;
  // Each part's tensor about the new centre, by the parallel-axis theorem.
  sum.I_com = inertia_about(a, sum.com) + inertia_about(b, sum.com);
  return sum;
}

Mat3 inertia_about(const Body& body, const Vec3& origin) {
  return body.I_com + point_tensor(body.mass, body.com - origin);
}

double moment_about_axis(const Mat3& I, const Vec3& n) {
  const double length = n.stableNorm();  // scaled: no underflow for an axis of 1e-200
  if (!std::isfinite(length) || length == 0.0) {
    throw std::invalid_argument("axis must be a finite non-zero vector");
  }
  const Vec3 unit = n / length;
  return unit.dot(I * unit);
}

Vec3 angular_momentum(const Mat3& I, const Vec3& omega) {
  return I * omega;
}

double kinetic_energy(const Mat3& I, const Vec3& omega) {
  return 0.5 * omega.dot(I * omega);
}

double angle_between(const Vec3& a, const Vec3& b) {
  // atan2(|a x b|, a . b) keeps full precision at small and near-straight angles;
  // each vector scaled to unit size first, so tiny or huge ones neither underflow
  // nor overflow in the products (the angle does not depend on their lengths).
  const double sa = a.cwiseAbs().maxCoeff(), sb = b.cwiseAbs().maxCoeff();
  if (!(sa > 0.0) || !(sb > 0.0)) return 0.0;
  const Vec3 ua = a / sa, ub = b / sb;
  return std::atan2(ua.cross(ub).norm(), ua.dot(ub));
}

PrincipalAxes principal_axes(const Mat3& I) {
  validate_inertia_tensor(I);
  Eigen::SelfAdjointEigenSolver<Mat3> solver(I);
  PrincipalAxes result;
  result.moments = solver.eigenvalues();  // ascending
  result.axes = solver.eigenvectors().transpose();
  // Eigenvectors have no sign of their own. Point axes 2 and 3 so that their
  // largest component is positive, then take e1 = e2 x e3 for a right-handed
  // set; for the text's lamina this gives its e1, e2, e3 (eqs. 67-69).
  for (int i = 1; i < 3; ++i) {
    Eigen::Index k;
    result.axes.row(i).cwiseAbs().maxCoeff(&k);
    if (result.axes(i, k) < 0.0) result.axes.row(i) *= -1.0;
  }
  result.axes.row(0) = result.axes.row(1).cross(result.axes.row(2));
  return result;
}

InPlaneAxes in_plane_principal_axes(const Mat3& I) {
  const double scale = I.cwiseAbs().maxCoeff();
  if (std::abs(I(0, 2)) > 1e-14 * scale || std::abs(I(1, 2)) > 1e-14 * scale) {
    throw std::invalid_argument("z must be a principal axis (Ixz = Iyz = 0) for eq. 53");
  }
  const double Ixx = I(0, 0), Iyy = I(1, 1), Ixy = I(0, 1);
  // n.I.n for n = (cos t, sin t, 0) (eq. 12); on a principal axis it equals eq. 50.
  const auto moment_at = [&](double t) {
    const double c = std::cos(t), s = std::sin(t);
    return Ixx * c * c + Iyy * s * s + 2.0 * Ixy * c * s;
  };
  InPlaneAxes axes;
  // atan2 stays defined when Ixx = Iyy; folded into (-90, 90] deg, 2 theta is the
  // principal value of eq. 53's arctangent, as the text takes it (-45 deg). Axes are
  // lines, so each angle is given in (-90, 90] deg, and a +-0 as 0 (a rectangle about
  // its centre: 0 and 90, not 90 and 180).
  double two_theta = std::atan2(2.0 * Ixy, Ixx - Iyy);
  if (two_theta > 0.5 * kPi) two_theta -= kPi;
  if (two_theta <= -0.5 * kPi) two_theta += kPi;
  axes.two_theta = two_theta + 0.0;
  axes.theta = 0.5 * axes.two_theta;
  axes.theta_other = axes.theta <= 0.0 ? axes.theta + 0.5 * kPi : axes.theta - 0.5 * kPi;
  axes.moment = moment_at(axes.theta);
  axes.moment_other = moment_at(axes.theta_other);
  return axes;
}

Vec3 fixed_axis_torque(const Mat3& I, const Vec3& omega) {
  return omega.cross(I * omega);
}

void validate_inertia_tensor(const Mat3& I) {
  if (!I.allFinite()) throw std::invalid_argument("inertia tensor must be finite");
  const double scale = I.cwiseAbs().maxCoeff();
  // Symmetry to a few ulps of the largest entry (products are computed in two orders).
  if ((I - I.transpose()).cwiseAbs().maxCoeff() > 64 * 2.2e-16 * scale) {
    throw std::invalid_argument("inertia tensor must be symmetric");
  }
  Eigen::SelfAdjointEigenSolver<Mat3> solver(I, Eigen::EigenvaluesOnly);
  const Vec3 moments = solver.eigenvalues();
  // The eigen-solver resolves moments to ~eps times the largest: a smaller one (a
  // plate 1e-9 as thick as it is wide) has no sign to trust, even when it is positive.
  if (std::abs(moments(0)) <= 64 * 2.2e-16 * moments(2)) {
    throw std::invalid_argument(
        "the body is too thin for double precision: its smallest principal moment (" +
        format_number(moments(0)) + ") is below the roundoff of the largest (" +
        format_number(moments(2)) + ")");
  }
  if (!(moments(0) > 0.0)) {
    throw std::invalid_argument("inertia tensor must be positive definite (smallest moment " +
                                format_number(moments(0)) + ")");
  }
  // A lamina sits exactly on I1 + I2 = I3; allow the eigen-solver's roundoff there.
  const double slack = 64 * 2.2e-16 * moments(2);
  if (moments(0) + moments(1) < moments(2) - slack) {
    throw std::invalid_argument("principal moments must satisfy I1 + I2 >= I3 (got " +
                                format_number(moments(0)) + " + " + format_number(moments(1)) +
                                " < " + format_number(moments(2)) + ")");
  }
}

}  // namespace rigid
