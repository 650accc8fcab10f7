#include "football/football.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "common/free_motion.h"
#include "rigid/inertia.h"
#include "rigid/units.h"

namespace rigid::lab::football {
namespace {

constexpr const char* kName = "football";
constexpr const char* kTitle = "the free symmetric top: football, frisbee, Earth (eqs. 142-149)";
constexpr const char* kInertiaWithPreset =
    "replaces the moments of --preset; give one or the other";

// The presets. football: a solid prolate spheroid of an NFL ball's size (semi-axes
// 0.14 m and 0.085 m, 0.42 kg) thrown with a wobble; frisbee: a thin disk
// (Is = 2I, eq. 148) of 0.175 kg and radius 0.1375 m; earth: Is/I = 1.00327, alpha = 0.2
// arcsec, one turn per sidereal day (the text's numbers, section 6.1).
constexpr double kSiderealDay = 86164.0905;   // s
constexpr double kSolarDay = 86400.0;         // s
constexpr double kEarthFlattening = 1.00327;  // Is/I, the text's
constexpr double kEarthI = 8.0e37;  // kg m^2, Earth's transverse moment; cancels in every rate

struct Preset {
  double I, Is, omega, alpha_deg;
};

Preset preset_of(const std::string& name) {
  if (name == "frisbee") {
    const Body disk = thin_disk(0.175, 0.1375);  // symmetry axis z
    return {disk.I_com(0, 0), disk.I_com(2, 2), 30.0, 5.0};
  }
  if (name == "earth") {
    return {kEarthI, kEarthFlattening * kEarthI, 2 * kPi / kSiderealDay, 0.2 / 3600.0};
  }
  const Body ball = solid_ellipsoid(0.42, 0.14, 0.085, 0.085);  // symmetry axis x
  return {ball.I_com(1, 1), ball.I_com(0, 0), 60.0, 10.0};
}

// What section 6.1 prints wrong, with this run's numbers: the cones' cases the wrong way
// round and alpha named for two angles (for any body with cones), Feynman's ratio upside
// down (the frisbee, a plate), the Earth's two periods from two different days.
void report_errata(Report& report, const Inputs& in, bool example) {
  const SymmetricPrecession& p = report.precession;
  const double theta_deg = rad_to_deg(p.theta), cone_deg = rad_to_deg(p.space_cone);
  const std::string numbers =
      fmt::format("Is/I = {:.6g}, alpha = {:.6g} deg, theta = {:.6g} deg, omega to L = {:.6g} deg",
                  report.Is / report.I, report.alpha_deg, theta_deg, cone_deg);
  const char* cones_printed =
      "This means that the space cone can engulf the body cone (prolate case) or the space "
      "cone can be outside the body cone (oblate case).";
  if (p.contact == ConeContact::kOutside) {
    report.erratum(
        {"section 6.1, after eq. 144", cones_printed,
         "the cases are the other way round. For this prolate body (" + numbers +
             ") theta > alpha: omega lies between L and 3, and the body cone rolls on the "
             "outside of the space cone; neither engulfs the other. It is an oblate body whose "
             "space cone lies inside its body cone. The text's 'alpha < theta for prolate' is "
             "right."});
  } else if (p.contact == ConeContact::kInside) {
    report.erratum(
        {"section 6.1, after eq. 144", cones_printed,
         "the cases are the other way round. For this oblate body (" + numbers +
             ") theta < alpha: L lies between 3 and omega, and the space cone lies inside the "
             "body cone, which rolls round it. A prolate body's cones touch from outside, "
             "neither engulfing the other. The text's 'alpha > theta for oblate' is right."});
  }
  if (p.contact != ConeContact::kNone) {
    report.erratum(
        {"section 6.1, the applet and Marion's alpha, before eq. 142",
         "The angle between vertical and the yellow(red) vector, i.e. between z and omega, is "
         "alpha ... the angular velocity omega precesses around the z-axis making a constant "
         "angle alpha with the angular momentum",
         fmt::format("in eqs. 142-147 alpha is the angle between omega and the symmetry axis 3 "
                     "(omega_z' = omega cos alpha, eq. 142), not between z (L) and omega. Here "
                     "omega makes the space cone's half-angle |theta - alpha| = {:.6g} deg with "
                     "L, and alpha = {:.6g} deg with 3.",
                     cone_deg, report.alpha_deg)});
  }
  // A thin plate (Is = 2I): phi_dot / |psi_dot| = sqrt(1 + 3 cos^2 alpha) / cos alpha, at
  // least 2 at any alpha, so the wobble is never half the spin.
  if (in.preset == "frisbee" && !in.inertia && !in.moment_ratio) {
    const double spin = std::abs(p.spin_rate);
    report.erratum(
        {"section 6.1, Feynman's plate after eq. 149",
         "the medallion rotates twice as fast as the wobble rate",
         fmt::format("the quote has the ratio upside down, and the text sets it beside eq. 149 "
                     "without comment; eq. 149 is right. The wobble, phi_dot = {:.6g} rad/s (3 "
                     "about L in space), is {:.6g} times the medallion's spin about the plate's "
                     "own axis, |psi_dot| = omega cos alpha = {:.6g} rad/s (equal in size to the "
                     "body-frame rate Omega = {:.6g} rad/s): wobble : spin = 2 : 1 at a slight "
                     "angle, not 1 : 2.",
                     p.space_rate, p.space_rate / spin, spin, p.body_rate)});
  }
  if (in.preset == "earth" && example) {
    const double day_ratio = kSolarDay / kSiderealDay;
    report.erratum(
        {"section 6.1, the Earth's free precession after eq. 149",
         "2 pi/Omega = 305 days ... yielding a period of 0.997 days",
         fmt::format("the two periods use two different days. With omega = 2 pi per sidereal "
                     "day, 2 pi/Omega = {:.4g} d and 2 pi/phi_dot = {:.4g} d; with omega = 2 pi "
                     "per solar day (86400 s), they are {:.4g} d and {:.4g} d. The text's printed "
                     "305 needs the sidereal day, its printed 0.997 the solar one.",
                     p.body_period / kSolarDay, p.space_period / kSolarDay,
                     p.body_period / kSolarDay * day_ratio,
                     p.space_period / kSolarDay * day_ratio)});
    report.note(
        "The observed free wobble of the Earth, the Chandler wobble, has a period of about "
        "433 days (the text says 440): the Earth is not rigid (its elastic mantle and oceans "
        "yield to the wobble), which lengthens the rigid-body period.");
  }
}

}  // namespace

std::string readable_period(double seconds) {
  if (seconds < 1000.0) return fmt::format("{:.4g} s", seconds);
  if (seconds < 0.5 * kSolarDay) return fmt::format("{:.4g} h", seconds / 3600.0);
  return fmt::format("{:.4g} d", seconds / kSolarDay);
}

// The rates against alpha for this body, as the rates figure draws them and --csv
// writes them: Omega / omega and phi_dot / omega at alpha = 0.5, 1, .., 89.5 deg, or,
// where the run's alpha lies above 0 and below 0.5 deg (the Earth's 0.2 arcsec), at 179 angles
// spaced evenly in log alpha from a decade below it to 89.5 deg.
TimeSeries rate_sweep(double I, double Is, double alpha_deg) {
  TimeSeries sweep(
      "football: the rates against alpha for this body (a sweep: the lab has no time series), "
      "as its rates figure draws them");
  sweep.add({"alpha_deg"}, "deg", "alpha, the angle between omega and the symmetry axis 3")
      .add({"Omega_over_omega"}, "1",
           "Omega / |omega|: omega's turn about 3 in the body (eq. 109; +: along omega_3)")
      .add({"phi_dot_over_omega"}, "1", "phi_dot / |omega|: 3's turn about L in space (eq. 147)");
  const bool fine = alpha_deg > 0 && alpha_deg < 0.5;
  const double low = std::max(std::log10(alpha_deg) - 1.0, -300.0), high = std::log10(89.5);
  for (int k = 1; k < 180; ++k) {
    const double a = fine ? std::pow(10.0, low + (high - low) * (k - 1) / 178.0) : 0.5 * k;
    const SymmetricPrecession q = free_symmetric_precession(I, Is, 1.0, deg_to_rad(a));
    sweep.rows.push_back({a, q.body_rate, q.space_rate});
  }
  return sweep;
}

const InputTable<Inputs>& input_table() {
  static const InputTable<Inputs> table = [] {
    InputTable<Inputs> t;
    t.choice("--preset", &Inputs::preset, {"football", "frisbee", "earth"},
             "the body: football = solid prolate spheroid, semi-axes 0.14 m and 0.085 m, 0.42 kg, "
             "omega 60 rad/s, alpha 10 deg; frisbee = thin disk 0.175 kg, radius 0.1375 m "
             "(Is = 2I), omega 30 rad/s, alpha 5 deg; earth = Is/I = 1.00327, alpha = 0.2 arcsec, "
             "omega = 2 pi per sidereal day (86164.0905 s)")
        .symbol("body");
    t.pair("--inertia", &Inputs::inertia,
           "moments I (transverse) and Is (symmetry axis), 0 < Is <= 2I")
        .value_name("I,IS")
        .unit("kg m^2")
        .positive()
        .lab_default("the preset's")
        .excludes("--preset", kInertiaWithPreset);
    t.number("--moment-ratio", &Inputs::moment_ratio,
             "Is / I with the preset's I (another Earth's flattening, say)")
        .open_range(0.0, 2.0)
        .symbol("I_s/I")
        .lab_default("the preset's")
        .excludes("--inertia", "give the moments (--inertia) or their ratio, not both");
    t.number("--omega", &Inputs::omega, "angular speed |omega|")
        .unit("rad/s")
        .positive()
        .symbol("\\omega")
        .lab_default("the preset's");
    t.number("--day", &Inputs::day, "one turn of the body (a day): omega = 2 pi / DAY")
        .unit("s")
        .positive()
        .lab_default("--omega's")
        .excludes("--omega", "give the speed once: --omega or --day");
    t.angle_deg("--alpha-deg", &Inputs::alpha_deg,
                "angle alpha between omega and the symmetry axis (0: a spin along it, "
                "which does not precess)")
        .range_from(0.0, 90.0)
        .symbol("\\alpha")
        .lab_default("the preset's");
    return t;
  }();
  return table;
}

namespace {

// The body and its spin as the run uses them: the preset's, but for what is given.
// A body of one's own moments is no preset: the inputs, the table and the figures'
// titles say "custom", with the preset's omega and alpha recorded where it lent them.
Preset body_of(Report& report, const Inputs& in) {
  // The preset always has a value here, so "--preset given" reads as a preset other
  // than the default: its moments and the ones given would contradict each other.
  if (in.inertia && in.preset != Inputs{}.preset) throw InputError("--inertia", kInertiaWithPreset);
  const Preset preset = preset_of(in.preset);
  const double I = in.inertia ? (*in.inertia)(0) : preset.I;
  const double Is = in.inertia        ? (*in.inertia)(1)
                    : in.moment_ratio ? *in.moment_ratio * preset.I
                                      : preset.Is;
  const double omega = in.day ? 2 * kPi / *in.day : in.omega.value_or(preset.omega);
  const double alpha_deg = in.alpha_deg.value_or(preset.alpha_deg);
  if (in.inertia) {
    report.set_input("preset", "custom");
    if (!in.omega && !in.day) report.set_input("omega", omega);
    if (!in.alpha_deg) report.set_input("alpha_deg", alpha_deg);
  }
  return {I, Is, omega, alpha_deg};
}

// The text's printed values of a preset's fixed example: only for that preset with
// nothing else changed.
struct ExampleText {
  bool example;
  const std::string& preset;
  std::optional<std::string> operator()(const char* name, const std::string& value) const {
    return example && preset == name ? printed(value) : std::nullopt;
  }
};

// Eqs. 104-105: the two moments and their ratio, which sets every rate.
void report_body(Report& report, const Inputs& in, const ExampleText& text, double alpha) {
  const double I = report.I, Is = report.Is;
  report.section("the body: Is = I3, I = I1 = I2 (eqs. 104-105)");
  report.result("moment_transverse_kg_m2", "I, transverse moment", I, "kg m^2");
  report.result("moment_symmetry_kg_m2", "Is, moment about the symmetry axis", Is, "kg m^2");
  report.result("moment_ratio", "Is / I", Is / I, "", text("earth", "1.00327"));
  report.precise(12);
  // Omega / omega is (Is - I)/I cos(alpha): formed without the cancellation of Is/I - 1.
  report.result("moment_ratio_excess", "(Is - I) / I, which sets Omega / omega", (Is - I) / I, "",
                text("earth", "0.00327"));
  if (in.preset == "earth" && !in.alpha_deg) {
    report.result("alpha_rad", "alpha", alpha, "rad", text("earth", "0.97e-6"));
  }
}

// Eqs. 109 and 145-149: Omega in the body, phi_dot in space, and their periods.
void report_rates(Report& report, const Inputs& in, const ExampleText& text, double alpha) {
  const SymmetricPrecession& p = report.precession;
  const double I = report.I, Is = report.Is, omega = report.omega;
  report.section("rates (eqs. 109, 145-149): Omega in the body, phi_dot in space");
  report.result("body_precession_rate_rad_s",
                "Omega = omega cos(alpha) (Is - I)/I, omega about 3 in the body (+: along omega_3)",
                p.body_rate, "rad/s", text("frisbee", "omega cos alpha (eq. 148)"));
  report.result("space_precession_rate_rad_s", "phi_dot = |L|/I, 3 and omega about L in space",
                p.space_rate, "rad/s", text("frisbee", "~ 2 omega (eq. 149)"));
  report.result("space_precession_rate_eq147_rad_s",
                "phi_dot = omega sqrt(1 + ((Is/I)^2 - 1) cos^2 alpha) (eq. 147)",
                omega * std::sqrt(1 + (Is / I * Is / I - 1) * std::cos(alpha) * std::cos(alpha)),
                "rad/s");
  report.result("body_rate_over_omega", "Omega / omega", p.body_rate / omega, "",
                text("earth", "0.00327"));
  report.result("space_rate_over_omega", "phi_dot / omega", p.space_rate / omega, "",
                text("earth", "1.00327"));
  report.result("spin_rate_rad_s",
                "psi_dot = omega_3 - phi_dot cos(theta), 3 spins in space about itself",
                p.spin_rate, "rad/s");
  if (alpha == 0.0) {
    report.remark(
        "(alpha = 0: nothing precesses; these are the rates of a wobble as it starts, "
        "alpha -> 0)");
  }
  if (p.body_rate != 0.0) {
    report.result("body_precession_period_s", "2 pi / |Omega|", p.body_period, "s");
  } else {
    report.result_none("body_precession_period_s", "2 pi / |Omega|", "s",
                       "Is = I: omega stays fixed in the body");
  }
  report.result("space_precession_period_s", "2 pi / phi_dot", p.space_period, "s");
  // In days where a period is that long (the Earth's 305, any body's beyond a day).
  const bool in_days = in.preset == "earth" || (p.body_rate != 0.0 && p.body_period >= kSolarDay) ||
                       p.space_period >= kSolarDay;
  if (in_days) {
    if (p.body_rate != 0.0) {
      report.result("body_precession_period_days", "2 pi / |Omega|, in days of 86400 s",
                    p.body_period / kSolarDay, "d", text("earth", "305"));
    }
    report.result("space_precession_period_days", "2 pi / phi_dot, in days of 86400 s",
                  p.space_period / kSolarDay, "d", text("earth", "0.997"));
  }
}

// phi_dot again, from Euler's equations integrated rather than the closed form.
void report_cross_check(Report& report, double alpha) {
  const SymmetricPrecession& p = report.precession;
  report.section(
      "cross-check: Euler's equations integrated (dopri5, tolerance 1e-12) for 2 pi / phi_dot");
  // Within a step budget (a body whose precession is many orders slower than its
  // spin would need years of steps): beyond it the cross-check is not run.
  constexpr std::size_t kCheckSteps = 2'000'000;
  std::optional<PrecessionCheck> check;
  std::string skipped = "not run: at alpha = 0 the axis 3 lies along L and does not turn";
  if (alpha > 0.0) {
    skipped = fmt::format("not run: needs more than {} steps", kCheckSteps);
    try {
      check = integrated_precession(report.I, report.Is, report.omega, alpha, 1e-12, kCheckSteps);
    } catch (const std::runtime_error&) {
    }
  }
  const char* labels[] = {
      "phi_dot, 3's turn about L in a quarter period", "|integrated / closed-form phi_dot - 1|",
      "angle of 3 from its start after 2 pi / phi_dot", "max |L - L0| / |L0| in space"};
  if (check) {
    report.result("integrated_space_precession_rate_rad_s", labels[0], check->space_rate, "rad/s");
    report.result("integrated_rate_error_rel", labels[1],
                  std::abs(check->space_rate / p.space_rate - 1), "");
    report.result("integrated_axis_return_rad", labels[2], check->axis_return, "rad");
    report.result("integrated_L_drift_rel", labels[3], check->L_space_drift_rel, "");
  } else {
    report.result_none("integrated_space_precession_rate_rad_s", labels[0], "rad/s", skipped);
    report.result_none("integrated_rate_error_rel", labels[1], "", skipped);
    report.result_none("integrated_axis_return_rad", labels[2], "rad", skipped);
    report.result_none("integrated_L_drift_rel", labels[3], "", skipped);
  }
}

// Eq. 144 and section 6.1: theta, the two cones and how they touch.
void report_cones(Report& report) {
  const SymmetricPrecession& p = report.precession;
  report.section("angles and cones (eq. 144, section 6.1)");
  report.result("theta_deg", "theta, L to 3: tan theta = (I/Is) tan alpha", rad_to_deg(p.theta),
                "deg", report.textbook("> alpha for a prolate body"));
  report.result("body_cone_half_angle_deg", "body cone about 3: alpha", rad_to_deg(p.body_cone),
                "deg");
  report.result("space_cone_half_angle_deg", "space cone about L: |theta - alpha| (omega to L)",
                rad_to_deg(p.space_cone), "deg");
  report.result_text("cones_touch", "the body cone rolls on the space cone's",
                     to_string(p.contact));
}

// In short: which cone rolls on which, and how fast.
void report_answer(Report& report) {
  const SymmetricPrecession& p = report.precession;
  const double I = report.I, Is = report.Is;
  const std::string kind = Is < I ? "prolate" : Is > I ? "oblate" : "a sphere";
  if (report.alpha_deg == 0.0) {
    report.answer(fmt::format(
        "{} (Is/I = {:.6g}), spun along its symmetry axis (alpha = 0): omega, L and 3 stay on "
        "one line and nothing precesses; it turns about 3 once every {}. A slight wobble would "
        "take 3 round L every {}{}",
        kind, Is / I, readable_period(2 * kPi / report.omega), readable_period(p.space_period),
        p.body_rate == 0.0
            ? ""
            : ", and omega round 3 in the body every " + readable_period(p.body_period)));
  } else if (p.contact == ConeContact::kNone) {
    report.answer(fmt::format("{}: omega, L and 3 stay together; nothing precesses", kind));
  } else {
    report.answer(fmt::format(
        "{} (Is/I = {:.6g}): the body cone ({:.3g} deg about 3) rolls {} the space cone ({:.3g} "
        "deg about L); 3 and omega go round L every {}, omega round 3 in the body every {}",
        kind, Is / I, rad_to_deg(p.body_cone),
        p.contact == ConeContact::kInside ? "round, enclosing" : "on the outside of",
        rad_to_deg(p.space_cone), readable_period(p.space_period), readable_period(p.body_period)));
  }
}

// Beside the run, the other kind of body at the same omega and alpha: the frisbee's
// thin disk (oblate) for a prolate run, the football's spheroid for an oblate one.
Contrast contrast_of(const Report& report, double alpha) {
  const bool prolate = report.precession.contact == ConeContact::kOutside;
  const Preset other = preset_of(prolate ? "frisbee" : "football");
  return {other.Is / other.I, free_symmetric_precession(other.I, other.Is, report.omega, alpha),
          prolate ? "for contrast, an oblate thin disk" : "for contrast, a prolate football",
          prolate ? "for contrast, an oblate body: its body cone surrounds the space cone"
                  : "for contrast, a prolate body: its body cone rolls outside the space cone"};
}

}  // namespace

Report compute(const Inputs& in) {
  Report report(kName, kTitle);
  report.start(input_table(), in);
  const Preset body = body_of(report, in);
  const double I = body.I, Is = body.Is, omega = body.omega, alpha_deg = body.alpha_deg;
  const double alpha = deg_to_rad(alpha_deg);
  report.I = I, report.Is = Is, report.omega = omega, report.alpha_deg = alpha_deg;
  report.precession =
      for_input("--inertia", [&] { return free_symmetric_precession(I, Is, omega, alpha); });
  report.series(rate_sweep(I, Is, alpha_deg));
  const bool example = !in.inertia && !in.moment_ratio && !in.omega && !in.day && !in.alpha_deg;
  const ExampleText text{example, in.preset};
  report_body(report, in, text, alpha);
  report_rates(report, in, text, alpha);
  report_cross_check(report, alpha);
  report_cones(report);
  report_errata(report, in, example);
  report_answer(report);
  report.contrast = contrast_of(report, alpha);
  return report;
}

namespace {

// The body itself, turning: the free motion of moments (I, I, Is) launched with omega at
// alpha from the symmetry axis 3, in the 1-3 plane, the body axes the space axes at t = 0.
BodyMotion body_motion(const Report& report) {
  const double alpha = deg_to_rad(report.alpha_deg);
  const Eigen::Vector3d omega0 =
      report.omega * Eigen::Vector3d(std::sin(alpha), 0.0, std::cos(alpha));
  return free_body_motion(FreeBodyExact({report.I, report.I, report.Is}, omega0), std::nullopt, {});
}

}  // namespace

LabProgram<Inputs, Report> program() {
  return {kName, kTitle, input_table(), compute, figures, animation,
          /*csv=*/
          "the rates Omega/omega and phi_dot/omega at each angle alpha between omega "
          "and the symmetry axis, up to 89.5 deg (a sweep, as the rates figure draws it; no "
          "time series)",
          /*preview=*/nullptr,
          /*textbook_example=*/true, body_motion};
}

}  // namespace rigid::lab::football
