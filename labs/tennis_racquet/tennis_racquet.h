// tennis_racquet: section 4.1, "The Tennis Racquet Theorem" (eqs. 83-103), as a
// library. A racquet spun about the handle (1) or about the normal to its face (3)
// keeps spinning with a small wobble; spun about the axis in its plane across the
// handle (2), the intermediate moment, a small disturbance grows until the racquet
// turns over, and it keeps turning over at regular intervals. The model of Figure 5
// is a ring (the head) and a rod (the handle); its motion is the exact torque-free
// solution, with an integrator as the cross-check.
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "common/figures.h"
#include "common/free_motion.h"
#include "common/inputs.h"
#include "common/integrated_motion.h"
#include "common/integrated_run.h"
#include "common/program.h"
#include "common/report.h"
#include "rigid/free_body_exact.h"
#include "rigid/free_body_integrate.h"
#include "rigid/racquet.h"

namespace rigid::lab::tennis_racquet {

/// The lab's inputs, with the text's model racquet (section 4.1, Figure 5).
struct Inputs {
  double head_mass = 0.15;      ///< m_a, kg
  double head_radius = 0.13;    ///< a, m
  double handle_mass = 0.18;    ///< m_l, kg
  double handle_length = 0.38;  ///< l, m
  /// Any body's principal moments I1 < I2 < I3 instead of the model's, kg m^2
  std::optional<Eigen::Vector3d> inertia;
  std::string spin_axis = "2";  ///< the axis the run spins about
  double omega = 10.0;          ///< the spin, rad/s
  double perturbation = 0.01;   ///< transverse share of omega at launch
  /// s; unless given (or periods), one polhode period of the spin about axis 2: two flips.
  std::optional<double> t_end;
  std::optional<double> periods;  ///< t_end as a number of polhode periods
  /// The cross-check. Its default method checks the exact motion but does not replace
  /// it in the animation; another method does.
  IntegrationInputs integration = [] {
    IntegrationInputs dopri5;
    dopri5.method = "dopri5";
    return dopri5;
  }();
};

/// The body the scenes draw: the ring-and-rod racquet, or, for moments given
/// (--inertia), the box with those moments (a book, a phone).
struct DrawnBody {
  Racquet racquet;  ///< the model; for moments given, only its moments are set
  /// The box's half-extents, for moments given: sqrt(I_j + I_k - I_i) in proportion
  /// (a box's moments are m (b^2 + c^2) / 3 in its half-extents, eq. 40).
  std::optional<Eigen::Vector3d> box;
  /// The size arrows and spacings scale with: the head's radius, or half the box's
  /// longest half-extent.
  double radius() const;
  /// The body's length: the racquet's from its head's far rim to the handle's end, or
  /// three times the box's longest half-extent (so arrows of a share of it clear the box).
  double length() const;
};

/// What the lab reports, and what its figures and its motion draw.
struct Report : lab::Report {
  using lab::Report::Report;
  DrawnBody body;
  /// The exact motion launched about axes 1, 2 and 3 with the same disturbance.
  std::vector<FreeBodyExact> launches;
  std::array<SpinStability, 3> predicted{};  ///< the linear prediction for each axis (eqs. 86-88)
  double textbook_rate = 0.0;                ///< eq. 92's rate for every axis: the spin
  std::optional<GrowthFit> growth;           ///< the growth measured about axis 2; none: no flip
  double t_end = 0.0;                        ///< the run's span, and the omega panels', s
  int spin_axis = 1;                         ///< the run's axis (0, 1, 2)
  /// The integrator the motion is drawn from (a method other than the cross-check's
  /// default); none: the closed form.
  std::optional<OdeOptions> drawn_integrator;
  std::vector<FreeBodyRun::Sample> run;  ///< the cross-check's samples, 0 to t_end
};

/// The inputs' rules: options, widgets and compute()'s checks.
const InputTable<Inputs>& input_table();
/// Everything the lab reports. Throws InputError naming a broken input.
Report compute(const Inputs& in);
/// omega against t for a spin about each axis, the growth of the disturbance on a log
/// scale, the racquet turning over during one flip, and its polhode with the separatrix.
void figures(const Report& report, FigureSink& sink);

/// The body turned by R (body to display) about its centre of mass at c: the racquet's
/// head, its two faces and the handle, or the box with its +3 face marked; named in the
/// legend if `named` (the figures' and the motion's).
void add_body(render::Scene3D& scene, const DrawnBody& body, const Eigen::Matrix3d& R,
              const Eigen::Vector3d& c, bool named);

/// The racquet of the run turning in space, L fixed and drawn up, with omega's components
/// in a strip below.
class Motion {
 public:
  /// `sample_times`: times at which an integrated motion is sampled ahead in one run (the
  /// animation's frame times; IntegratedMotion), so those frames come from one run from
  /// t = 0. Exact: the closed form at any t. Nothing mutable: the same t gives the same
  /// scene in any order.
  explicit Motion(const Report& report, const std::vector<double>& sample_times = {});
  /// The span shown: the run's t_end.
  double seconds() const { return t_end_; }
  /// The racquet at time t (t >= 0 for an integrated motion).
  render::Scene3D scene(double t) const;
  /// omega's components over the run with a line at t (the strip below the scene).
  render::Plot2D strip(double t) const;

 private:
  RotationState state(double t) const;

  DrawnBody body_;
  FreeBodyExact motion_;
  int axis_ = 1;
  double t_end_ = 0.0;
  std::optional<IntegratedMotion<FreeBodyProblem>> integrated_;  ///< none: the closed form
  std::vector<double> strip_t_;  ///< omega's exact components over the run
  std::array<std::vector<double>, 3> strip_omega_;
};

/// The motion as --animate shows it; an integrated motion is sampled at `frame_times`.
Animation animation(const Report& report, const FrameTimes& frame_times);

/// The lab as one program.
LabProgram<Inputs, Report> program();

}  // namespace rigid::lab::tennis_racquet
