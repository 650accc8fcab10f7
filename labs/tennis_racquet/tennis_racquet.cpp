#include "tennis_racquet/tennis_racquet.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "common/free_motion.h"
#include "rigid/units.h"

namespace rigid::lab::tennis_racquet {
using Eigen::Vector2d;
using Eigen::Vector3d;
namespace {

const char* const kName = "tennis_racquet";
const char* const kTitle =
    "the tennis racquet theorem: the flip about the intermediate axis (section 4.1)";
const char* const kAxisNames[] = {"1 (the handle)", "2 (in the plane, across the handle)",
                                  "3 (normal to the face)"};
const char* const kInertiaOrModel =
    "replaces the ring-and-rod model: give --inertia or the head's and handle's options, not "
    "both";

}  // namespace

const InputTable<Inputs>& input_table() {
  static const InputTable<Inputs> table = [] {
    InputTable<Inputs> t;
    t.number("--head-mass", &Inputs::head_mass, "mass m_a of the head, a ring")
        .unit("kg")
        .positive()
        .symbol("m_a");
    t.number("--head-radius", &Inputs::head_radius, "radius a of the head")
        .unit("m")
        .positive()
        .symbol("a");
    t.number("--handle-mass", &Inputs::handle_mass, "mass m_l of the handle, a thin rod")
        .unit("kg")
        .positive()
        .symbol("m_l");
    t.number("--handle-length", &Inputs::handle_length, "length l of the handle")
        .unit("m")
        .positive()
        .symbol("l");
    t.vector("--inertia", &Inputs::inertia,
             "principal moments I1 < I2 < I3 of any body (a book, a phone: axis 2 the "
             "intermediate), instead of the ring-and-rod model")
        .unit("kg m^2")
        .positive()
        .lab_default("the ring-and-rod model's")
        .excludes("--head-mass", kInertiaOrModel)
        .excludes("--head-radius", kInertiaOrModel)
        .excludes("--handle-mass", kInertiaOrModel)
        .excludes("--handle-length", kInertiaOrModel);
    t.choice("--spin-axis", &Inputs::spin_axis, {"1", "2", "3"},
             "principal axis of the spin: 1 handle, 2 in the plane, 3 normal to the face")
        .symbol("axis");
    t.number("--omega", &Inputs::omega, "the spin |omega| at launch")
        .unit("rad/s")
        .positive()
        .symbol("\\omega");
    t.number("--perturbation", &Inputs::perturbation,
             "transverse share of omega at launch, along the next axis (1->2, 2->3, 3->1); "
             "0: a spin exactly along the axis, which stays there")
        // From 1e-60, as every input's magnitude: the polhode's k'^2 ~ share^2 must not
        // underflow (below ~1e-154 the period came out infinite, "first flip: none").
        .range_from(1e-60, 0.5)
        .or_zero()
        .symbol("\\epsilon");
    add_end_time_inputs(t, &Inputs::t_end, &Inputs::periods, "polhode period",
                        "one polhode period of the spin about axis 2: two flips");
    t.include(integration_inputs("the integrator that cross-checks the exact motion "
                                 "(exact: none)",
                                 "polhode period / 2000"),
              &Inputs::integration);
    return t;
  }();
  return table;
}

namespace {

// Why a launch with no disturbance (--perturbation 0) has no wobble, growth or flip.
constexpr char kUndisturbed[] =
    "launched exactly along the axis (perturbation 0): it stays there, nothing to measure";

// The body: the ring-and-rod model of Figure 5, or any body's moments (--inertia), drawn
// as the box with those moments.
void make_body(Report& report, const Inputs& in) {
  DrawnBody& body = report.body;
  if (in.inertia) {
    // Any body: its moments replace the model's (the table refuses the model's options
    // beside them), axis 2 the intermediate as the lab's is.
    const Vector3d given = *in.inertia;
    if (!(given(0) < given(1) && given(1) < given(2))) {
      throw InputError("--inertia", fmt::format("must be I1 < I2 < I3, axis 2 the intermediate as "
                                                "the racquet's (got {:g}, {:g}, {:g})",
                                                given(0), given(1), given(2)));
    }
    body.racquet.moments = {given(0), given(1), given(2)};
    for_input("--inertia", [&] { validate(body.racquet.moments); });
    // The box with these moments (eq. 40): half-extents in proportion to sqrt(I_j + I_k - I_i).
    body.box = Vector3d(std::sqrt(given(1) + given(2) - given(0)),
                        std::sqrt(given(0) + given(2) - given(1)),
                        std::sqrt(given(0) + given(1) - given(2)));
    const double floor = 1e-3 * body.box->maxCoeff();
    body.box = body.box->cwiseMax(floor);
    report.drop_input("head_mass"), report.drop_input("head_radius");
    report.drop_input("handle_mass"), report.drop_input("handle_length");
  } else {
    body.racquet = for_input("--head-mass", [&] {
      return make_racquet({in.head_mass, in.head_radius, in.handle_mass, in.handle_length});
    });
  }
}

// Section 4.1: the model's centre of mass and principal moments (eqs. 83-85), or the
// moments given.
void report_body(Report& report, const Inputs& in) {
  const Racquet& racquet = report.body.racquet;
  const PrincipalMoments& I = racquet.moments;
  if (in.inertia) {
    report.section("the body: its principal moments, given (in place of Figure 5's model)");
    report.result("principal_moments", "I1, I2 (the intermediate), I3", Vector3d(I.vector()),
                  "kg m^2");
    report.result_none("cm_offset_m", "R, centre of mass from the head's centre (eq. 83)", "m",
                       "a body of given moments has no head or handle");
  } else {
    report.section("4.1 the model racquet of Figure 5: a ring and a rod (eqs. 83-85)");
    report.result("cm_offset_m", "R, centre of mass from the head's centre (eq. 83)",
                  racquet.cm_offset, "m", report.textbook("0.175"));
    report.result("principal_moments", "I1 (handle), I2 (in the plane), I3 (normal) (eqs. 84-85)",
                  Vector3d(I.vector()), "kg m^2", report.textbook("(1.27e-3, 11.81e-3, 13.08e-3)"));
  }
  report.result("perpendicular_axis_ratio", "I3 / (I1 + I2), a lamina's 1", I.I3 / (I.I1 + I.I2),
                "");
}

// Sections 4.1.1-4.1.2: each axis's rate to first order (eqs. 86-103), in full and as
// eq. 92 has it; returns eq. 92's, which the erratum sets beside the full ones.
std::array<SpinStability, 3> report_linear_theory(Report& report, const Inputs& in) {
  const PrincipalMoments& I = report.body.racquet.moments;
  report.section(
      fmt::format("4.1.1-4.1.2 a spin omega = {:g} rad/s about each axis, "
                  "to first order (eqs. 86-103)",
                  in.omega));
  // The same disturbance for each axis; the exact motion of each launch.
  std::vector<FreeBodyExact>& launches = report.launches;
  for (int axis = 0; axis < 3; ++axis) {
    launches.emplace_back(I, launch_omega(axis, in.omega, in.perturbation));
  }
  // The linear theory's rate is that of the spin's own component, omega_i(0) (eqs.
  // 86-88 hold it constant to first order), not |omega|: sqrt(1 - share^2) of it.
  const EulerCoefficients full = euler_coefficients(I);
  const EulerCoefficients text = simplified_racquet_coefficients();
  std::array<SpinStability, 3>& predicted = report.predicted;
  std::array<SpinStability, 3> simplified;
  for (int axis = 0; axis < 3; ++axis) {
    const double spin = launches[axis].omega_body(0.0)(axis);
    predicted[axis] = linear_stability(full, axis, spin);
    simplified[axis] = linear_stability(text, axis, spin);
  }
  report.textbook_rate = simplified[1].rate;
  report.result("growth_rate_per_s", "axis 2: growth rate, eqs. 86-88 in full", predicted[1].rate,
                "1/s");
  report.remark(fmt::format("(from omega_2(0) = {:.6g} rad/s, the spin's component)",
                            launches[1].omega_body(0.0)(1)));
  report.result("growth_rate_textbook_per_s", "axis 2: growth rate, eq. 92 (omega_2)",
                simplified[1].rate, "1/s", report.textbook("omega_2 (eqs. 100-101)"));
  report.result("wobble_frequencies_rad_s", "axes 1, 3: wobble frequency, eqs. 86-88 in full",
                Vector2d(predicted[0].rate, predicted[2].rate), "rad/s");
  report.result("wobble_frequencies_textbook_rad_s", "axes 1, 3: wobble frequency, eq. 92",
                Vector2d(simplified[0].rate, simplified[2].rate), "rad/s",
                report.textbook("(omega_1, omega_3) (eq. 95)"));
  const Vector2d ratios(predicted[0].axis_ratio, predicted[2].axis_ratio);
  const std::string ratios_label =
      "axes 1, 3: |omega_2|/|omega_3|, |omega_1|/|omega_2| of the wobble";
  if (ratios.allFinite()) {
    report.result("ellipse_axis_ratios", ratios_label, ratios, "");
  } else {
    report.result_none("ellipse_axis_ratios", ratios_label, "",
                       "two moments equal to double precision: no wobble to shape");
  }
  return simplified;
}

// The fit runs from launch until the disturbance reaches a tenth of omega (or
// twice its start, if that is larger): its deviation from the linear rate is
// of the order of the share squared (racquet.h).
double fit_share_limit(double perturbation) {
  return std::min(std::max(0.1, 2.0 * perturbation), 0.5 * (1.0 + perturbation));
}

// The growth about axis 2 fitted to the exact motion, and each wobble's frequency.
void report_measured(Report& report, const Inputs& in) {
  const std::vector<FreeBodyExact>& launches = report.launches;
  const double share_limit = fit_share_limit(in.perturbation);
  // A racquet whose moments coincide to double precision (a ring with a handle of
  // 1e-60 kg, say) does not flip: there is then no growth to measure.
  if (std::isfinite(first_sign_change(launches[1], 1))) {
    report.growth = measure_growth_rate(launches[1], 1, share_limit);
  }
  const std::optional<GrowthFit>& growth = report.growth;

  report.section(
      fmt::format("measured on the exact motion, launched with {:g} of omega along the "
                  "next axis",
                  in.perturbation));
  const char* measured = "axis 2: growth rate fitted to the exact omega_1, omega_3";
  if (in.perturbation == 0) {
    report.result_none("growth_rate_measured_per_s", measured, "1/s", kUndisturbed);
  } else if (growth) {
    report.result("growth_rate_measured_per_s", measured, growth->rate, "1/s");
    report.result("growth_fit_interval_s", "  fitted over t from, to",
                  Vector2d(growth->t_begin, growth->t_end), "s");
    report.result("growth_fit_shares", "  transverse share of omega at the interval's ends",
                  Vector2d(growth->share_begin, growth->share_end), "");
  } else {
    report.result_none(
        "growth_rate_measured_per_s", measured, "1/s",
        "the spin about 2 does not flip: I1, I2, I3 not distinct to double precision");
  }
  const char* wobbles = "axes 1, 3: 2 pi / polhode period";
  if (in.perturbation > 0) {
    report.result("wobble_frequencies_measured_rad_s", wobbles,
                  Vector2d(2 * kPi / launches[0].period(), 2 * kPi / launches[2].period()),
                  "rad/s");
  } else {
    report.result_none("wobble_frequencies_measured_rad_s", wobbles, "rad/s", kUndisturbed);
  }
}

// What the answer says of the spin about the chosen axis.
struct ChosenSpin {
  std::string name;         ///< the axis: the racquet's by what it is, a given body's by number
  std::string axis1;        ///< axis 1 by what it is
  double first_flip = 0.0;  ///< s; infinite where it does not flip
  double excursion = 0.0;   ///< rad: axis 1's largest angle from L, or out of the plane across L
  double scale = 0.0;       ///< the motion's time scale, s
};

// The spin about the chosen axis: its stability, motion, flips and how far the handle
// strays.
ChosenSpin report_chosen_spin(Report& report, const Inputs& in) {
  const std::vector<FreeBodyExact>& launches = report.launches;
  const std::array<SpinStability, 3>& predicted = report.predicted;
  const int axis = in.spin_axis[0] - '1';
  report.spin_axis = axis;
  const FreeBodyExact& motion = launches[axis];
  // The racquet's axes by what they are; a body of given moments' by number.
  const std::string axis_name =
      in.inertia ? std::to_string(axis + 1) : std::string(kAxisNames[axis]);
  const std::string axis1 = in.inertia ? "axis 1" : "the handle";
  report.section(fmt::format("the spin about axis {}", axis_name));
  report.result_text(
      "stability", "first order",
      predicted[axis].unstable ? "unstable: the disturbance grows" : "stable: a wobble");
  report_motion(report, motion);
  if (std::isfinite(motion.period())) {
    report.result("polhode_period_s", "polhode period", motion.period(), "s");
  } else {
    report.result_none("polhode_period_s", "polhode period", "s", "no polhode to go round");
  }
  const double first_flip = first_sign_change(motion, axis);
  if (std::isfinite(first_flip)) {
    report.result("first_flip_s", "first flip: omega_2 changes sign", first_flip, "s");
    report.result("flip_interval_s", "time between flips: half the period of omega_2",
                  0.5 * motion.period(), "s");
  } else {
    const char* why = in.perturbation == 0 ? kUndisturbed : "stable: it does not flip";
    report.result_none("first_flip_s", "first flip", "s", why);
    report.result_none("flip_interval_s", "time between flips", "s", why);
  }
  // The handle stays near the plane across L (spins about 2 and 3) or near L (about 1).
  // Over a polhode period, or over the run where there is none (the separatrix).
  const double scale = time_scale(motion);
  const double t_end = end_time(in.t_end, in.periods, scale, time_scale(launches[1]));
  report.t_end = t_end;
  const CosineRange handle =
      direction_cosine_range(motion, 0, std::isfinite(motion.period()) ? motion.period() : t_end);
  const double handle_max = std::max(std::abs(handle.min), std::abs(handle.max));
  const double handle_min = handle.min <= 0 && handle.max >= 0
                                ? 0.0
                                : std::min(std::abs(handle.min), std::abs(handle.max));
  const double excursion =
      axis == 0 ? std::acos(std::min(handle_min, 1.0)) : std::asin(std::min(handle_max, 1.0));
  report.result("handle_excursion_max_deg",
                axis == 0 ? "largest angle of " + axis1 + " from L"
                          : "largest angle of " + axis1 + " out of the plane across L",
                rad_to_deg(excursion), "deg");
  return {axis_name, axis1, first_flip, excursion, scale};
}

// Two flips: one polhode period of the spin about 2 (its time scale, if it does not flip).
void report_cross_check(Report& report, const Inputs& in, double scale) {
  const FreeBodyExact& motion = report.launches[report.spin_axis];
  const PrincipalMoments& I = report.body.racquet.moments;
  const double t_end = report.t_end;
  const RunPlan plan = plan_run(report, in.integration, false, t_end, scale);
  report.section(fmt::format("cross-check: {} to t_end = {:g} s", in.integration.method, t_end));
  report_plan(report, plan);
  const FreeBodyRun run = run_chosen_method(report, FreeBodyProblem(I), motion, in.integration,
                                            plan.options, plan.times, free_body_words());
  report_drifts(report, run, scale, in.integration.method == "exact", free_body_words());
  report.run = run.samples;
  // The motion is drawn from the integrator when a method other than the cross-check's
  // default is asked for: the default alone does not replace the exact motion.
  const std::string& method = in.integration.method;
  if (method != "exact" && method != Inputs{}.integration.method) {
    report.drawn_integrator = plan.options;
  }
}

// Eq. 92's simplification where it changes the rates, and what the run leaves out.
void report_erratum_and_notes(Report& report, const Inputs& in,
                              const std::array<SpinStability, 3>& simplified) {
  const PrincipalMoments& I = report.body.racquet.moments;
  const std::array<SpinStability, 3>& predicted = report.predicted;
  const double share_limit = fit_share_limit(in.perturbation);
  if (predicted[1].rate != simplified[1].rate) {
    report.erratum(
        {"section 4.1, eq. 92",
         "For the tennis racquet model I2 >> I1, so the last equation is "
         "approximately omega_3_dot + omega_1 omega_2 = 0",
         fmt::format(
             "it sets (I2 - I1)/(I2 + I1) = {:.4f} to 1, and with it every rate to the "
             "spin. In full (eqs. 86-88), about axis 2 the disturbance grows at omega sqrt((I2 - "
             "I1)(I3 - I2)/(I1 I3)) = {:.6g} 1/s, not omega = {:.6g} 1/s; about axis 1 it goes "
             "round "
             "at {:.6g} rad/s, not {:.6g}, {}, not the circle of eqs. 96-97. About axis 3 the rate "
             "omega_3 and the circle are exact for a lamina.",
             (I.I2 - I.I1) / (I.I2 + I.I1), predicted[1].rate, simplified[1].rate,
             predicted[0].rate, simplified[0].rate,
             std::isfinite(predicted[0].axis_ratio)
                 ? fmt::format("on an ellipse (|omega_2|/|omega_3| = {:.4f})",
                               predicted[0].axis_ratio)
                 : std::string("with omega_3 still (I1 = I2 to double precision)"))});
  }
  if (in.perturbation > 0.05) {
    report.note(
        fmt::format("The disturbance at launch ({:g} of omega) is not small: the linear "
                    "rates describe only its start, and the fit runs to a share of {:g}.",
                    in.perturbation, share_limit));
  }
  report.note(
      "Section 4.1's ratios of the ellipsoids for I1 : I2 : I3 = 5 : 4 : 3 are the poinsot "
      "lab's (results ratios_*); they are not repeated here.");
}

// --csv: the spin about the chosen axis, exact and integrated, at the run's times.
void add_series(Report& report) {
  const FreeBodyExact& motion = report.launches[report.spin_axis];
  TimeSeries series("tennis_racquet: the spin about the chosen axis, exact and integrated");
  series.add({"t_s"}, "s", "time")
      .add({"omega1", "omega2", "omega3"}, "rad/s",
           "the exact omega in the racquet's principal axes (1 the handle, 2 in the head's "
           "plane, 3 normal to it)")
      .add({"qw", "qx", "qy", "qz"}, "1", kQuaternionConvention)
      .add({"omega1_integrated", "omega2_integrated", "omega3_integrated"}, "rad/s",
           "--method's omega at the same times");
  for (const FreeBodyRun::Sample& s : report.run) {
    const RotationState x = motion.state(s.t);
    series.rows.push_back({s.t, x[0], x[1], x[2], x[3], x[4], x[5], x[6], s.x[0], s.x[1], s.x[2]});
  }
  report.series(std::move(series));
}

// In short: which spin flips, and how soon.
void report_answer(Report& report, const Inputs& in, const ChosenSpin& spin) {
  const int axis = report.spin_axis;
  const FreeBodyExact& motion = report.launches[axis];
  const std::array<SpinStability, 3>& predicted = report.predicted;
  const std::string& axis_name = spin.name;
  const std::string& axis1 = spin.axis1;
  const double first_flip = spin.first_flip, excursion = spin.excursion;
  if (in.perturbation == 0) {
    report.answer(fmt::format(
        "a spin exactly along axis {} stays there, turning steadily at {:g} rad/s: nothing "
        "wobbles and nothing flips. The balance is {}: {}",
        axis_name, in.omega, predicted[axis].unstable ? "unstable" : "stable",
        predicted[axis].unstable
            ? fmt::format("the slightest disturbance grows at {:.4g}/s and turns the {} over",
                          predicted[axis].rate, in.inertia ? "body" : "racquet")
            : fmt::format("a slight disturbance wobbles at {:.4g} rad/s and {} stays near {}",
                          predicted[axis].rate, axis1, axis == 0 ? "L" : "the plane across L")));
  } else if (std::isfinite(first_flip)) {
    report.answer(fmt::format(
        "a spin about axis {} flips: launched {:g} off it, the {} turns over first at {:.4g} "
        "s, then every {:.4g} s (the disturbance grows at {:.4g}/s); about axes 1 and 3 it "
        "only wobbles",
        axis_name, in.perturbation, in.inertia ? "body" : "racquet", first_flip,
        0.5 * motion.period(), predicted[axis].rate));
  } else {
    report.answer(fmt::format(
        "a spin about axis {} is {}: launched {:g} off it, it wobbles at {:.4g} rad/s and "
        "{} stays within {:.3g} deg of {}; only a spin about axis 2 flips",
        axis_name, predicted[axis].unstable ? "unstable" : "stable", in.perturbation,
        predicted[axis].rate, axis1, rad_to_deg(excursion),
        axis == 0 ? "L" : "the plane across L"));
  }
}

}  // namespace

Report compute(const Inputs& in) {
  Report report(kName, kTitle);
  report.start(input_table(), in);
  make_body(report, in);
  report_body(report, in);
  const std::array<SpinStability, 3> simplified = report_linear_theory(report, in);
  report_measured(report, in);
  const ChosenSpin spin = report_chosen_spin(report, in);
  report_cross_check(report, in, spin.scale);
  report_erratum_and_notes(report, in, simplified);
  add_series(report);
  report_answer(report, in, spin);
  return report;
}

namespace {

// The racquet at any time as its film draws it: the closed form, or the method asked
// for integrated on from the cross-check's samples.
BodyMotion body_motion(const Report& report) {
  // (the run is the cross-check's, which the film draws only when its method was asked for)
  return free_body_motion(
      report.launches.at(report.spin_axis), report.drawn_integrator,
      report.drawn_integrator ? report.run : std::vector<FreeBodyRun::Sample>{});
}

}  // namespace

LabProgram<Inputs, Report> program() {
  return {kName, kTitle, input_table(), compute, figures, animation,
          /*csv=*/
          "the spin about --spin-axis at its sample times: the exact omega, the "
          "attitude quaternion and --method's omega",
          /*preview=*/nullptr,
          /*textbook_example=*/true, body_motion};
}

}  // namespace rigid::lab::tennis_racquet
