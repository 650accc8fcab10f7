// lamina_tensor: sections 1, 1.1, 1.2, 2, 2.1, 2.3, 2.4 and 3.1 of the chapter, as a
// library.
// A rectangular lamina of mass m, side a along x and b along y, turns at omega
// about an axis n through the origin (its corner or its centre). Section 1 sums
// its inertia tensor I (eqs. 6-11, 20; eq. 70 about the centre) and the moment
// n.I.n about the axis (eq. 21); section 1.1 finds L = I omega, which is not along
// omega (eq. 28); section 1.2 the kinetic energy omega.I omega / 2 (eqs. 33-34).
// Section 2.1 builds symmetric bodies from primitives (the model paddle, a block,
// a cube); section 2.3 finds the principal axes in the plate's plane from
// tan 2 theta (eqs. 53-56) and section 2.4 all three by diagonalising I
// (eqs. 62-69). Section 3.1 asks for the torque N = omega x (I omega) that holds
// the axis fixed (eqs. 74-76).
#pragma once

#include <optional>
#include <string>

#include "common/figures.h"
#include "common/inputs.h"
#include "common/program.h"
#include "common/report.h"
#include "rigid/inertia.h"

namespace rigid::lab::lamina_tensor {

/// The lab's inputs, with the text's defaults (section 1: b = 2a, corner, n at 37 deg).
struct Inputs {
  double mass = 1.0;  ///< kg
  double a = 1.0;     ///< m, the side along x
  double b = 2.0;     ///< m, the side along y
  double c = 0.5;     ///< m, the third side of section 2.1's block a x b x c
  std::string origin = "corner";
  Vec3 axis = Vec3(0.8, 0.6, 0.0);  ///< the rotation axis n, of any length
  /// "diagonal": n along the plate's diagonal (a, b, 0) instead of `axis`.
  std::string axis_word;
  /// If set, n = (cos, sin, 0) at this angle from x toward y, instead of `axis`.
  std::optional<double> axis_deg;
  double omega = 1.0;     ///< rad/s, about n
  bool examples = false;  ///< section 2.1's paddle, block and cube beside any plate
};

/// What the lab reports, and what its figures draw.
struct Report : lab::Report {
  using lab::Report::Report;
  double a = 0.0, b = 0.0;  ///< the plate's sides, m
  bool corner = true;       ///< the origin at the plate's corner (else at its centre)
  Vec3 n = Vec3::UnitX();   ///< the rotation axis, unit
  Mat3 I = Mat3::Zero();    ///< the inertia tensor about the origin
  PrincipalAxes principal;  ///< I diagonalised (section 2.4)
};

/// The inputs' rules: options, widgets and compute()'s checks.
const InputTable<Inputs>& input_table();
/// Everything the lab reports. Throws InputError naming a broken input.
Report compute(const Inputs& in);
/// The lamina with its rotation axis, omega, L and the principal axes; the moment
/// about an in-plane axis against its angle.
void figures(const Report& report, FigureSink& sink);

/// The lab as one program.
LabProgram<Inputs, Report> program();

}  // namespace rigid::lab::lamina_tensor
