#include "top_nutation/top_nutation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "rigid/inertia.h"
#include "rigid/units.h"

namespace rigid::lab::top_nutation {

using Eigen::Vector2d;

namespace {

constexpr char kName[] = "top_nutation";
constexpr char kTitle[] = "the heavy symmetric top: precession and nutation (sections 8-9)";
constexpr double kRpm = 2 * kPi / 60.0;  // rad/s per rpm

// The section 8.1 example's numbers from the rounded spin the text uses.
double rounded(double x, int digits) {
  const double scale = std::pow(10.0, digits - 1 - std::floor(std::log10(std::abs(x))));
  return std::round(x * scale) / scale;
}

// Section 8.1: the top's moments, (a) the sleeping top's least spin, (b) a horizontal
// top's precession and (c) steady precession at theta0.
void report_section_8_1(Report& report, const Inputs& in, double S, double theta0) {
  const HeavyTop& top = report.top;
  report.section("8.1 the top: a disk on a spindle, moments about the tip");
  report.result("moment_symmetry_kg_m2", "Is = m r^2 / 2", top.Is, "kg m^2",
                report.textbook("2.5e-3"));
  report.result("moment_transverse_kg_m2", "I = m r^2 / 4 + m l^2 (parallel axes)", top.I, "kg m^2",
                report.textbook("4.45e-3"));
  report.result("mgl_n_m", "m g l", top.mgl, "N m");
  report.alias("mgl_nm", "mgl_n_m");  // the old name, kept one release

  report.section("8.1 (a) the sleeping top: Is^2 S^2 >= 4 m g l I (eqs. 188-189)");
  const double S_min = sleeping_min_spin(top);
  report.result("min_spin_rad_s", "minimum spin S_min", S_min, "rad/s", report.textbook("47.3"));
  report.result("min_spin_rev_per_s", "  in revolutions per second", S_min / (2 * kPi), "1/s",
                report.textbook("7.52"));
  report.result("min_spin_rpm", "  in rpm", S_min / kRpm, "rpm", report.textbook("451"));
  report.result("min_spin_period_s", "  its spin period 2 pi / S_min", 2 * kPi / S_min, "s",
                report.textbook("0.132"));

  report.section(fmt::format("8.1 (b) horizontal, at S = {:.6g} rad/s (eq. 185)", S));
  report.result("spin_rad_s", "spin S", S, "rad/s", report.textbook("52.4"));
  if (S > 0) {
    const double horizontal = horizontal_precession_rate(top, S);
    report.result("horizontal_precession_rate_rad_s", "phi_dot = m g l / (Is S)", horizontal,
                  "rad/s", report.textbook("5.98"));
    report.result("horizontal_precession_rpm", "  in rpm", horizontal / kRpm, "rpm",
                  report.textbook("57.1"));
    report.result("horizontal_precession_period_s", "  its period", 2 * kPi / horizontal, "s",
                  report.textbook("1.05"));
  } else {
    report.result_none("horizontal_precession_rate_rad_s", "phi_dot = m g l / (Is S)", "rad/s",
                       "no spin: a horizontal top just falls");
  }

  report.section(
      fmt::format("8.1 (c) steady precession at theta0 = {:g} deg (eq. 187)", in.theta0_deg));
  const SteadyPrecession steady = steady_precession_rates(top, S, theta0);
  const std::string rates = "phi_dot, slow and fast";
  if (theta0 == 0.0) {
    // sin(theta0) = 0: an upright axis stays upright whatever phi does (eq. 184)
    const std::string why = "upright (theta0 = 0): the axis stays on the vertical, no precession";
    report.result_none("steady_precession_rates_rad_s", rates, "rad/s", why);
    report.result_json_none("steady_precession_slow_rad_s", "rad/s");
    report.result_json_none("steady_precession_fast_rad_s", "rad/s");
  } else if (!steady.exists) {
    report.result_none(
        "steady_precession_rates_rad_s", rates, "rad/s",
        S == 0.0 && std::abs(std::cos(theta0)) < 1e-15
            ? "horizontal with no spin: eq. 187 would need m g l = 0, nothing balances gravity"
            : "Is^2 S^2 < 4 m g l I cos(theta0): no steady precession");
    report.result_json_none("steady_precession_slow_rad_s", "rad/s");
    report.result_json_none("steady_precession_fast_rad_s", "rad/s");
  } else if (!std::isfinite(steady.fast)) {
    // Horizontal: I cos(theta) phi_dot^2 drops out of eq. 187, which keeps one root.
    report.result_none("steady_precession_rates_rad_s", rates, "rad/s",
                       "horizontal: one steady rate, the slow one");
    report.result("steady_precession_slow_rad_s", "phi_dot, slow = m g l / (Is S) (eq. 185)",
                  steady.slow, "rad/s");
    report.result_none("steady_precession_fast_rad_s", "phi_dot, fast", "rad/s",
                       "horizontal: no second steady rate (the fast one is infinite)");
  } else {
    report.result("steady_precession_rates_rad_s", rates, Vector2d(steady.slow, steady.fast),
                  "rad/s", report.textbook("(7.75, 26.2)"));
    report.result("steady_precession_periods_s", "  their periods",
                  Vector2d(2 * kPi / std::abs(steady.slow), 2 * kPi / std::abs(steady.fast)), "s",
                  report.textbook("(0.81, 0.24)"));
    report.result_json("steady_precession_slow_rad_s", steady.slow, "rad/s");
    report.result_json("steady_precession_fast_rad_s", steady.fast, "rad/s");
  }
}

// Two angles in degrees with the fewest significant digits, at least 4, that tell them
// apart (179.9999999 and 179.99999992576 read "180 and 180" at 4).
std::pair<std::string, std::string> distinct_degrees(double lo_rad, double hi_rad) {
  const double lo = rad_to_deg(lo_rad), hi = rad_to_deg(hi_rad);
  for (int digits = 4; digits < 17; ++digits) {
    std::string a = fmt::format("{:.{}g}", lo, digits), b = fmt::format("{:.{}g}", hi, digits);
    if (a != b || lo == hi) return {a, b};
  }
  return {fmt::format("{:.17g}", lo), fmt::format("{:.17g}", hi)};
}

// Why the mean precession is undefined where the axis goes through the vertical: phi is
// no coordinate there and turns by pi at once, either way; a path a hair to one side or
// the other takes one of the two limits.
std::string undefined_mean(const HeavyTopExact& motion) {
  const auto& limits = motion.mean_precession_limits();
  if (motion.regime() == TopRegime::kPlanar) {
    return fmt::format(
        "undefined: the axis swings in one vertical plane and phi only jumps by pi where it "
        "passes the vertical (a hair of spin either way makes the mean {:.6g} or {:.6g} rad/s)",
        limits[0], limits[1]);
  }
  return fmt::format(
      "undefined: the axis goes through the vertical, where phi turns by pi at once either way; "
      "a path a hair to one side or the other precesses at a mean {:.6g} or {:.6g} rad/s",
      limits[0], limits[1]);
}

// A turning circle a hair from a pole whose side the inputs' last digits decide (core's
// undecided_sides): said, with the other side's mean precession.
void report_pass_side(Report& report, const HeavyTopExact& motion) {
  for (const HeavyTopExact::UndecidedSide& side : motion.undecided_sides()) {
    const char* sign = side.upright ? "-" : "+";
    report.note(fmt::format(
        "the axis passes {:.3g} deg from {}, on the side the sign of b {} a decides; b {} a is "
        "within 1e3 ulps of the terms that form it ({:.3g}), so an input's last digits decide "
        "the side: on the other, the mean precession is {:.6g} rad/s, not {:.6g}",
        rad_to_deg(side.distance), side.upright ? "upright" : "the bottom", sign, sign, side.terms,
        side.other_mean, motion.mean_precession_rate()));
  }
}

// Section 9: the exact motion's invariants, turning circles and period, and the
// fast-top estimates where they hold.
// The fast top (Goldstein 5.7): nodding at Is S / I, by (2 I / Is S) times the speed
// of the axis at the start relative to the slow precession m g l / (Is S), both to
// relative order 2 m g l I / (Is S)^2 = (S_min / S)^2 / 2. Printed for a top that
// could sleep (S >= S_min, the order at most 1/2: the text's top 0.41); a slower one
// has no such estimate (at S = 1e-10 it read 3e24 deg).
void report_fast_top(Report& report, const TopStart& start) {
  const HeavyTop& top = report.top;
  const HeavyTopExact& motion = *report.motion;
  const double S = start.spin, S_min = sleeping_min_spin(top);
  const std::string frequency_label = "fast-top estimate of 2 pi / period: Is S / I";
  const bool rest = start.theta_dot == 0.0 && start.phi_dot == 0.0;
  const std::string amplitude_label =
      rest ? "fast-top estimate of theta_max - theta_min from rest: 2 m g l I sin(theta0) / "
             "(Is S)^2"
           : "fast-top estimate of theta_max - theta_min: (2 I / Is S) |axis speed at t = 0 "
             "relative to the precession m g l / (Is S)|";
  if (S < S_min) {
    const std::string why = "the top spins too slowly to sleep (S < S_min)";
    report.result_text(
        "below_sleeping_spin", "S below S_min",
        fmt::format("S = {:.4g} rpm is below S_min = {:.4g} rpm: the top cannot sleep, and from "
                    "theta0 = {:.4g} deg it falls to theta_max = {:.4g} deg; the fast-top "
                    "estimates do not apply",
                    S / kRpm, S_min / kRpm, rad_to_deg(start.theta),
                    rad_to_deg(motion.theta_max())));
    report.result_none("fast_top_nutation_frequency_rad_s", frequency_label, "rad/s", why);
    report.result_none("fast_top_nutation_amplitude_deg", amplitude_label, "deg", why);
    report.result_json_none("fast_top_relative_order", "");
    return;
  }
  const FastTopNutation fast = fast_top_nutation(top, start);
  report.result("fast_top_nutation_frequency_rad_s", frequency_label, fast.frequency, "rad/s");
  report.result("fast_top_nutation_amplitude_deg", amplitude_label, rad_to_deg(fast.range), "deg");
  report.result("fast_top_relative_order", "  both to relative order 2 m g l I / (Is S)^2",
                fast.order, "");
}

void report_section_9(Report& report, const TopStart& start) {
  const double S = start.spin;
  const HeavyTop& top = report.top;
  const HeavyTopExact& motion = *report.motion;
  report.result("energy_j", "E (eq. 191)", motion.energy(), "J");
  report.result("p_phi", "p_phi = L_z (eq. 177)", motion.p_phi(), "kg m^2/s");
  report.result("p_psi", "p_psi = Is S (eq. 176)", motion.p_psi(), "kg m^2/s");
  report.result_text("regime", "the axis's path", to_string(motion.regime()));
  report.result("theta_min_deg", "theta_min (u2 = cos theta_min)", rad_to_deg(motion.theta_min()),
                "deg");
  report.result("theta_max_deg", "theta_max (u1 = cos theta_max)", rad_to_deg(motion.theta_max()),
                "deg");
  const double S_min = sleeping_min_spin(top);
  if (motion.regime() == TopRegime::kSleeping) {
    report.result_none("nutation_period_s", "nutation period", "s", "upright: no nodding");
    report.result_text(
        "sleeping_stability", "upright at S vs S_min",
        S >= S_min ? "stable (S >= S_min)" : "unstable (S < S_min): a hair topples it");
  } else {
    report.result("cubic_roots", "roots u1, u2, u3 of f(u) = 0, u = cos theta",
                  Eigen::Vector3d(motion.u1(), motion.u2(), motion.u3()), "");
    if (std::isfinite(motion.nutation_period())) {
      report.result("nutation_period_s", "nutation period 2 K(k) / lambda",
                    motion.nutation_period(), "s");
      const double condition = nutation_period_condition(motion);
      report.result_json("nutation_period_condition", condition, "");
      if (condition > 1e3) {
        report.remark(fmt::format(
            "(condition number {:.2g}: a relative change d in theta0 or a rate moves it by up "
            "to {:.2g} d; near the separatrix it grows as 1 / (u3 - u2))",
            condition, condition));
      }
    } else {
      report.result_none("nutation_period_s", "nutation period", "s",
                         "on the separatrix: never returns");
    }
    const double mean_error = motion.mean_precession_error();
    if (motion.mean_precession_defined() &&
        !(std::abs(motion.mean_precession_rate()) > mean_error)) {
      report.result_none(
          "mean_precession_rate_rad_s", "mean phi_dot over a nutation period", "rad/s",
          fmt::format("below the roundoff of the two turns (about each pole) it is the "
                      "difference of: |mean| < {:.2g} rad/s",
                      mean_error));
    } else if (motion.mean_precession_defined()) {
      report.result("mean_precession_rate_rad_s", "mean phi_dot over a nutation period",
                    motion.mean_precession_rate(), "rad/s");
      report_pass_side(report, motion);
    } else {
      report.result_none("mean_precession_rate_rad_s", "mean phi_dot over a nutation period",
                         "rad/s", undefined_mean(motion));
    }
    report.result_json("mean_precession_rate_error_rad_s", mean_error, "rad/s");
    report.result_json("mean_precession_limits_rad_s_low", motion.mean_precession_limits()[0],
                       "rad/s");
    report.result_json("mean_precession_limits_rad_s_high", motion.mean_precession_limits()[1],
                       "rad/s");
    report.result("phi_dot_turning_rad_s", "phi_dot at theta_max and at theta_min",
                  Vector2d(motion.phi_dot_at_u1(), motion.phi_dot_at_u2()), "rad/s");
    report_fast_top(report, start);
  }
  // The sleeping top's stability a hair from upright, just above and below S_min.
  const double hair = 1e-3;
  const double above = HeavyTopExact(top, {hair, 0, 0, 1.01 * S_min}).theta_max();
  const double below = HeavyTopExact(top, {hair, 0, 0, 0.99 * S_min}).theta_max();
  report.result("sleeping_check_theta_max_deg",
                "theta_max from 0.001 rad at 1.01 S_min and at 0.99 S_min",
                Vector2d(rad_to_deg(above), rad_to_deg(below)), "deg");
}

// The top's error against the exact motion, |theta - theta_exact| in degrees, and its
// invariants E, p_phi and p_psi: a run that lost any of them ran away.
const ExactErrorWords& top_words() {
  static const ExactErrorWords words = [] {
    ExactErrorWords w;
    w.key = "max_theta_error_deg";
    w.label = "max |theta - theta_exact|";
    w.unit = "deg";
    w.in_unit = rad_to_deg;
    w.method_key_prefix = "max_theta_error_";
    w.method_key_suffix = "_deg";
    w.against = "the exact theta";
    w.diverged = "the integration diverged; shorten the step";
    w.runaway_invariants = HeavyTopProblem::kInvariantCount;
    w.invariants = {{HeavyTopProblem::kEnergy, "energy", "max |E - E0| / (T0 + m g l)"},
                    {HeavyTopProblem::kPPhi, "p_phi", "max |p_phi - p_phi0| / L_max"},
                    {HeavyTopProblem::kPPsi, "p_psi", "max |p_psi - p_psi0| / L_max"}};
    return w;
  }();
  return words;
}

// A top on a table, not a pivot: the disk's lowest point, l cos theta - r sin theta above
// the tip, reaches the table at tan theta = l / r (38.66 deg for the text's top). The text
// (and this lab) take a pivot with nothing below the disk; where the motion tilts past
// that angle, a student's top on a table would catch its rim there.
void report_table(Report& report, const Inputs& in) {
  if (in.inertia) return;  // moments given: no disk to catch
  const double table = std::atan2(in.arm, in.disk_radius);
  report.table_theta = table;
  const HeavyTopExact& motion = *report.motion;
  if (!(motion.theta_max() > table)) return;
  report.note(fmt::format(
      "a table: the disk's rim (r = {:g} m, l = {:g} m up the axis) would touch a table under "
      "the tip where l cos theta = r sin theta, at theta = {:.4g} deg; this motion tilts to "
      "{:.4g} deg, through it. The text's top, like this lab's, turns on a pivot with nothing "
      "below the disk.",
      in.disk_radius, in.arm, rad_to_deg(table), rad_to_deg(motion.theta_max())));
}

// The text's numbers use S rounded to 52.4 rad/s; the exact ones differ in the last digit.
void report_errata(Report& report, double S, double theta0) {
  const HeavyTop& top = report.top;
  if (report.textbook_inputs()) {
    const double S_text = rounded(S, 3);
    const SteadyPrecession steady = steady_precession_rates(top, S, theta0);
    const SteadyPrecession text_steady = steady_precession_rates(top, S_text, theta0);
    const double text_horizontal = horizontal_precession_rate(top, S_text);
    report.erratum(
        {"section 8.1 (b) and (c), eqs. 185 and 187",
         "S = 52.4 rad/s ... phi_dot = mgl / (Is S) = 5.98 rad/s = 57.1 rpm ... The precession "
         "rates are 7.75 rad/s",
         fmt::format("500 rpm is S = {:.6g} rad/s; the text rounds it to {:g} before using it. "
                     "With the exact S, phi_dot (horizontal) = {:.4g} rad/s = {:.4g} rpm and the "
                     "slow steady rate at 30 deg is {:.4g} rad/s. The text's 5.98 and 7.75 rad/s "
                     "come from S = {:g} ({:.4g} and {:.4g}), and its 57.1 rpm from the rounded "
                     "5.98 rad/s ({:.4g} rpm).",
                     S, S_text, horizontal_precession_rate(top, S),
                     horizontal_precession_rate(top, S) / kRpm, steady.slow, S_text,
                     text_horizontal, text_steady.slow, rounded(text_horizontal, 3) / kRpm)});
    const double S_min = sleeping_min_spin(top);
    report.erratum({"section 8.1 (a), eq. 189", "This is a period of 0.132 s",
                    fmt::format("the sleeping top's spin period 2 pi / S_min = {:.5g} s rounds to "
                                "{:.3f} s.",
                                2 * kPi / S_min, 2 * kPi / S_min)});
  }
  report.erratum({"eq. 186", "mgl = Is S phi_dot - S phi_dot^2 cos(theta)",
                  "theta_ddot = 0 in eq. 184 gives m g l = Is S phi_dot - I phi_dot^2 "
                  "cos(theta), with I, not S, in the last term (eq. 187 solves the right one)."});
}

}  // namespace

const InputTable<Inputs>& input_table() {
  static const InputTable<Inputs> table = [] {
    InputTable<Inputs> t;
    t.number("--mass", &Inputs::mass, "mass m of the top").unit("kg").positive().symbol("m");
    t.number("--arm", &Inputs::arm, "distance l from the tip to the centre of mass")
        .unit("m")
        .positive()
        .symbol("l");
    t.number("--disk-radius", &Inputs::disk_radius, "radius of the top's disk (sets I and Is)")
        .unit("m")
        .positive()
        .symbol("r");
    t.pair("--inertia", &Inputs::inertia,
           "moments about the tip: I (transverse) and Is (symmetry axis)")
        .value_name("I,IS")
        .unit("kg m^2")
        .positive()
        .lab_default("a thin disk of --disk-radius at --arm")
        .excludes("--disk-radius", "replaces the disk's moments; give --inertia or --disk-radius");
    t.number("--g", &Inputs::g, "gravitational acceleration (9.8, as the text's numbers imply)")
        .unit("m/s^2")
        .positive()
        .symbol("g");
    t.number("--spin", &Inputs::spin, "spin S about the symmetry axis (instead of --spin-rpm)")
        .unit("rad/s")
        .non_negative()
        .symbol("S")
        .lab_default("--spin-rpm")
        .excludes("--spin-rpm", "give the spin once: --spin (rad/s) or --spin-rpm");
    t.number("--spin-rpm", &Inputs::spin_rpm, "spin S in revolutions per minute")
        .unit("rpm")
        .non_negative()
        .symbol("S");
    t.number("--theta0-deg", &Inputs::theta0_deg,
             "initial tilt theta0 of the axis from the vertical")
        .unit("deg")
        .symbol("\\theta_0");
    t.number("--thetadot0", &Inputs::thetadot0, "initial theta_dot")
        .unit("rad/s")
        .symbol("\\theta-dot_0");
    t.number("--phidot0", &Inputs::phidot0, "initial precession rate phi_dot")
        .unit("rad/s")
        .symbol("\\phi-dot_0");
    add_end_time_inputs(t, &Inputs::t_end, &Inputs::periods, "nutation period",
                        "three nutation periods");
    t.include(integration_inputs("how the motion is computed", "nutation period / 2000", false),
              &Inputs::integration);
    return t;
  }();
  return table;
}

namespace {

// The top: a thin disk at the arm's height (parallel-axis theorem), or given moments.
void make_top(Report& report, const Inputs& in) {
  double I = 0.0, Is = 0.0;
  if (!in.inertia) {
    const Body disk = thin_disk(in.mass, in.disk_radius);
    const Mat3 about_tip = inertia_about(shifted(disk, Vec3(0, 0, in.arm)), Vec3::Zero());
    I = about_tip(0, 0);
    Is = about_tip(2, 2);
  } else {
    I = (*in.inertia)(0), Is = (*in.inertia)(1);
    report.drop_input("disk_radius");
    for_input("--inertia", [&] { validate_top_body(I, Is, in.mass, in.arm); });
  }
  report.top = HeavyTop{I, Is, in.mass * in.g * in.arm};
  report.arm = in.arm;
  report.disk_radius = in.disk_radius;
}

// The run to t_end by --method, sampled 200 a nutation period (or a turn of the spin for
// a sleeping top), and with --compare every method against the closed form.
void report_run(Report& report, const Inputs& in, double S) {
  const HeavyTopExact& motion = *report.motion;
  const bool sleeping = motion.regime() == TopRegime::kSleeping;
  report.scale = sleeping || !std::isfinite(motion.nutation_period())
                     ? 2 * kPi / std::max(std::abs(S), 1e-300)
                     : motion.nutation_period();
  report.t_end = end_time(in.t_end, in.periods, report.scale, 3.0 * report.scale);
  // Every method runs at --step and --tolerance in the comparison, so neither is unused.
  // The step also from the fastest turn (the spin and the axis's own speed): near S_min a
  // top released a hair from upright nods once in minutes (period / 2000 = 33 s) while it
  // spins 50 times a second.
  const double fastest = 2 * kPi / motion.fastest_rate();
  const RunPlan plan =
      plan_run(report, in.integration, /*compared=*/true, report.t_end, report.scale, fastest);
  report.method = in.integration.method;
  report.options = plan.options;
  report.fixed = plan.fixed;
  report.section(fmt::format("{} to t_end = {:g} s", report.method, report.t_end));
  report_plan(report, plan);
  if (report.method != "exact") {
    report.result_text("method_kind", "method", std::string(method_kind(plan.options.method)));
  }
  const HeavyTopProblem problem(report.top);
  report.run = run_chosen_method(report, problem, motion, in.integration, plan.options, plan.times,
                                 top_words());
  report_drifts(report, report.run, report.scale, report.method == "exact", top_words());
  // "Which method drifts" at equal cost too: a sleeping top has no nutation to count
  // periods by, nor anything to drift through.
  const bool at_cost = !sleeping && std::isfinite(motion.nutation_period());
  if (in.integration.compare) {
    report.comparisons =
        compare_every_method(report, problem, motion, plan, report.scale, at_cost, top_words());
  }
}

// --csv: the run at its sample times beside the closed form, with the Euler angles.
void add_series(Report& report) {
  const HeavyTopExact& motion = *report.motion;
  TimeSeries series("top_nutation: the run at its sample times (the closed form's, or --method's)");
  series.add({"t_s"}, "s", "time")
      .add({"theta_rad"}, "rad", "the tilt of the axis from the vertical")
      .add({"theta_exact_rad"}, "rad", "the closed form's tilt at the same time")
      .add({"omega1", "omega2", "omega3"}, "rad/s", "omega in body axes (3 the symmetry axis)")
      .add({"qw", "qx", "qy", "qz"}, "1", kQuaternionConvention)
      .add({"energy_error_rel"}, "1", "|E - E0| / (T0 + m g l)")
      .add({"phi_rad", "psi_rad"}, "rad",
           "the z-x-z Euler angles of section 6 with theta (q = Rz(phi) Rx(theta) Rz(psi)): "
           "phi the precession about the vertical z, psi the spin about 3, in (-pi, pi]; at "
           "theta = 0 only phi + psi is defined and psi is 0")
      .add({"theta_dot_rad_s", "phi_dot_rad_s", "psi_dot_rad_s"}, "rad/s",
           "the angles' rates from omega (eqs. 134-136 inverted)");
  for (const HeavyTopRun::Sample& s : report.run.samples) {
    const TopAngles a = euler_angles_and_rates(attitude(s.x), omega_body(s.x));
    series.rows.push_back({s.t, tilt_of(attitude(s.x)), motion.theta(s.t), s.x[0], s.x[1], s.x[2],
                           s.x[3], s.x[4], s.x[5], s.x[6],
                           std::abs(s.invariant_errors[HeavyTopProblem::kEnergy]), a.phi, a.psi,
                           a.theta_dot, a.phi_dot, a.psi_dot});
  }
  report.series(std::move(series));
}

// In short: the axis's path and the numbers that decide it.
void report_answer(Report& report, double S) {
  const HeavyTopExact& motion = *report.motion;
  const double S_min = sleeping_min_spin(report.top);
  const std::string sleep =
      S == 0.0     ? fmt::format("with no spin (S_min = {:.4g} rpm) it is a pendulum", S_min / kRpm)
      : S >= S_min ? fmt::format(
                         "S = {:.4g} rpm is above S_min = {:.4g} rpm: upright, it could "
                         "sleep",
                         S / kRpm, S_min / kRpm)
                   : fmt::format(
                         "S = {:.4g} rpm is below S_min = {:.4g} rpm: upright, any nudge "
                         "would topple it",
                         S / kRpm, S_min / kRpm);
  const auto [lo, hi] = distinct_degrees(motion.theta_min(), motion.theta_max());
  const std::string every = std::isfinite(motion.nutation_period())
                                ? fmt::format("every {:.4g} s", motion.nutation_period())
                                : std::string("once, never to return (the separatrix)");
  const bool resolved = std::abs(motion.mean_precession_rate()) > motion.mean_precession_error();
  const std::string mean =
      motion.mean_precession_defined() && !resolved
          ? fmt::format("precesses at a mean below its roundoff (|mean| < {:.2g} rad/s)",
                        motion.mean_precession_error())
      : motion.mean_precession_defined()
          ? fmt::format("precesses at a mean {:.4g} rad/s", motion.mean_precession_rate())
          : fmt::format(
                "has no mean precession (it is {:.4g} or {:.4g} rad/s as the path passes "
                "a hair to one side of the vertical or the other)",
                motion.mean_precession_limits()[0], motion.mean_precession_limits()[1]);
  switch (motion.regime()) {
    case TopRegime::kSleeping:
      report.answer(S >= S_min
                        ? "sleeping, stable: the axis stays upright; " + sleep
                        : fmt::format("upright but unstable: S = {:.4g} rpm is below S_min = "
                                      "{:.4g} rpm, so the least nudge topples it",
                                      S / kRpm, S_min / kRpm));
      break;
    case TopRegime::kSteady:
      report.answer(fmt::format(
          "steady precession: the axis stays at {} deg and goes round at {:.4g} rad/s; {}", lo,
          motion.mean_precession_rate(), sleep));
      break;
    case TopRegime::kPlanar:
      report.answer(fmt::format(
          "planar: with no spin and no precession the axis swings in one vertical plane "
          "through the {} to {} deg on the other side {} (back where it started in twice that); "
          "{}",
          motion.theta_max() >= kPi / 2 ? "bottom" : "top", motion.theta_max() >= kPi / 2 ? lo : hi,
          every, sleep));
      break;
    case TopRegime::kThroughPole:
      report.answer(fmt::format(
          "through the pole: the axis passes through the vertical and out to {} deg {} (phi_dot "
          "{:.4g} rad/s at theta_max, {:.4g} at theta_min), and {}; {}",
          motion.theta_min() == 0.0 ? hi : lo, every, motion.phi_dot_at_u1(),
          motion.phi_dot_at_u2(), mean, sleep));
      break;
    default:
      report.answer(fmt::format(
          "{}: the axis nods between {} and {} deg {} while it {} (phi_dot {:.4g} rad/s at "
          "theta_max, {:.4g} at theta_min); {}",
          to_string(motion.regime()), lo, hi, every, mean, motion.phi_dot_at_u1(),
          motion.phi_dot_at_u2(), sleep));
  }
}

}  // namespace

Report compute(const Inputs& in) {
  Report report(kName, kTitle);
  report.start(input_table(), in);
  if (!(in.theta0_deg >= 0.0 && in.theta0_deg < 180.0)) {
    throw InputError("--theta0-deg", fmt::format("must lie in [0, 180) (got {:g})", in.theta0_deg));
  }
  make_top(report, in);
  const double S = in.spin ? *in.spin : in.spin_rpm * kRpm;
  if (in.spin) report.drop_input("spin_rpm");
  const double theta0 = deg_to_rad(in.theta0_deg);

  report_section_8_1(report, in, S, theta0);

  report.section("9 the motion: E' = I theta_dot^2 / 2 + V(theta) (eqs. 191-195)");
  TopStart start{theta0, in.thetadot0, in.phidot0, S};
  start.theta_deg = in.theta0_deg;
  report.motion.emplace(
      for_input("--theta0-deg", [&] { return HeavyTopExact(report.top, start); }));
  report_section_9(report, start);

  report_run(report, in, S);
  report_errata(report, S, theta0);
  report_table(report, in);
  add_series(report);
  report_answer(report, S);
  return report;
}

LabProgram<Inputs, Report> program() {
  return {kName, kTitle, input_table(), compute, figures, animation,
          /*csv=*/
          "the run at its sample times: theta (and the closed form's), omega, the "
          "attitude quaternion, the energy error and the Euler angles and their rates",
          /*preview=*/leave_out_comparisons<Inputs>,
          /*textbook_example=*/true, [](const Report& report) -> BodyMotion {
            const auto motion = std::make_shared<const Motion>(report);
            return keeping_samples([motion](double t) { return motion->state(t); },
                                   report.run.samples);
          }};
}

}  // namespace rigid::lab::top_nutation
