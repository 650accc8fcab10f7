// top_nutation: sections 8, 8.1 and 9 of the chapter, the heavy symmetric top.
// A top spins on a fixed tip; gravity's torque turns its axis about the
// vertical (precession) while the axis nods between two circles (nutation).
// The spin S and p_phi = L_z are conserved, and with the energy they reduce the
// motion to one coordinate in the effective potential V(theta) (eq. 195); the
// nodding follows exactly from a cubic and Jacobi's elliptic functions, and
// every integrator is measured against it.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "common/free_body_run.h"
#include "common/lab.h"
#include "figures.h"
#include "rigid/heavy_top.h"
#include "rigid/heavy_top_integrate.h"
#include "rigid/inertia.h"
#include "rigid/integrate.h"
#include "rigid/units.h"

using Eigen::Vector2d;
using rigid::lab::Lab;
using rigid::lab::printed;
using rigid::lab::UsageError;

namespace {

constexpr double kRpm = 2 * rigid::kPi / 60.0;  // rad/s per rpm
// A run longer than this many steps is refused rather than left to hang.
constexpr std::size_t kMaxSteps = 20'000'000;
// Each method of the comparison gets at most this many steps.
constexpr std::size_t kMaxComparisonSteps = 20'000;
// The comparison at equal cost: evaluations a nutation period, and periods.
constexpr double kEqualCostEvaluations = 200.0;
constexpr double kEqualCostPeriods = 100.0;

// The section 8.1 example's numbers from the rounded spin the text uses.
double rounded(double x, int digits) {
  const double scale = std::pow(10.0, digits - 1 - std::floor(std::log10(std::abs(x))));
  return std::round(x * scale) / scale;
}

}  // namespace

int main(int argc, char** argv) {
  Lab lab("top_nutation", "the heavy symmetric top: precession and nutation (sections 8-9)");
  rigid::lab::top_nutation::Inputs in;
  lab.number("--mass", in.mass, "mass m of the top").unit("kg").positive().symbol("m");
  lab.number("--arm", in.arm, "distance l from the tip to the centre of mass")
      .unit("m")
      .positive()
      .symbol("l");
  lab.number("--disk-radius", in.disk_radius, "radius of the top's disk (sets I and Is)")
      .unit("m")
      .positive()
      .symbol("r");
  lab.pair("--inertia", in.inertia, "I,IS",
           "moments about the tip: I (transverse) and Is (symmetry axis); not with --disk-radius")
      .unit("kg m^2")
      .positive()
      .lab_default("a thin disk of --disk-radius at --arm");
  lab.number("--g", in.g, "gravitational acceleration (9.8, as the text's numbers imply)")
      .unit("m/s^2")
      .positive()
      .symbol("g");
  lab.number("--spin", in.spin, "spin S about the symmetry axis (instead of --spin-rpm)")
      .unit("rad/s")
      .non_negative()
      .symbol("S")
      .lab_default("--spin-rpm");
  lab.number("--spin-rpm", in.spin_rpm, "spin S in revolutions per minute")
      .unit("rpm")
      .non_negative()
      .symbol("S");
  lab.number("--theta0-deg", in.theta0_deg, "initial tilt theta0 of the axis from the vertical")
      .unit("deg")
      .symbol("\\theta_0");
  lab.number("--thetadot0", in.thetadot0, "initial theta_dot")
      .unit("rad/s")
      .symbol("\\theta-dot_0");
  lab.number("--phidot0", in.phidot0, "initial precession rate phi_dot")
      .unit("rad/s")
      .symbol("\\phi-dot_0");
  rigid::lab::declare_end_time(lab, in.t_end, in.periods, "nutation period",
                               "three nutation periods");
  rigid::lab::declare_integration_options(lab, in.integration, "how the motion is computed",
                                          "nutation period / 2000", false);
  lab.enable_csv();
  lab.enable_animation();

  in.integration.compared = true;  // every method at --step and --tolerance, in a section
  return lab.run(argc, argv, [&](Lab& lab) {
    if (lab.given("--inertia") && lab.given("--disk-radius")) {
      throw UsageError("--inertia", "replaces the disk's moments; give --inertia or --disk-radius");
    }
    if (lab.given("--spin") && lab.given("--spin-rpm")) {
      throw UsageError("--spin", "give the spin once: --spin (rad/s) or --spin-rpm");
    }
    if (!(in.theta0_deg >= 0.0 && in.theta0_deg < 180.0)) {
      throw UsageError("--theta0-deg",
                       fmt::format("must lie in [0, 180) (got {:g})", in.theta0_deg));
    }
    // The top: a thin disk at the arm's height (parallel-axis theorem), or given moments.
    double I = in.inertia(0), Is = in.inertia(1);
    if (!lab.given("--inertia")) {
      const rigid::Body disk = rigid::thin_disk(in.mass, in.disk_radius);
      const rigid::Mat3 about_tip = rigid::inertia_about(
          rigid::shifted(disk, rigid::Vec3(0, 0, in.arm)), rigid::Vec3::Zero());
      I = about_tip(0, 0);
      Is = about_tip(2, 2);
    } else {
      lab.drop_input("disk_radius");
      rigid::lab::for_option("--inertia",
                             [&] { rigid::validate_top_body(I, Is, in.mass, in.arm); });
    }
    const rigid::HeavyTop top{I, Is, in.mass * in.g * in.arm};
    const double S = lab.given("--spin") ? in.spin : in.spin_rpm * kRpm;
    if (lab.given("--spin")) lab.drop_input("spin_rpm");
    const double theta0 = rigid::deg_to_rad(in.theta0_deg);

    lab.section("8.1 the top: a disk on a spindle, moments about the tip");
    lab.result("moment_symmetry_kg_m2", "Is = m r^2 / 2", Is, "kg m^2", lab.textbook("2.5e-3"));
    lab.result("moment_transverse_kg_m2", "I = m r^2 / 4 + m l^2 (parallel axes)", I, "kg m^2",
               lab.textbook("4.45e-3"));
    lab.result("mgl_n_m", "m g l", top.mgl, "N m");
    lab.alias("mgl_nm", "mgl_n_m");  // the old name, kept one release

    lab.section("8.1 (a) the sleeping top: Is^2 S^2 >= 4 m g l I (eqs. 188-189)");
    const double S_min = rigid::sleeping_min_spin(top);
    lab.result("min_spin_rad_s", "minimum spin S_min", S_min, "rad/s", lab.textbook("47.3"));
    lab.result("min_spin_rev_per_s", "  in revolutions per second", S_min / (2 * rigid::kPi), "1/s",
               lab.textbook("7.52"));
    lab.result("min_spin_rpm", "  in rpm", S_min / kRpm, "rpm", lab.textbook("451"));
    lab.result("min_spin_period_s", "  its spin period 2 pi / S_min", 2 * rigid::kPi / S_min, "s",
               lab.textbook("0.132"));

    lab.section(fmt::format("8.1 (b) horizontal, at S = {:.6g} rad/s (eq. 185)", S));
    lab.result("spin_rad_s", "spin S", S, "rad/s", lab.textbook("52.4"));
    if (S > 0) {
      const double horizontal = rigid::horizontal_precession_rate(top, S);
      lab.result("horizontal_precession_rate_rad_s", "phi_dot = m g l / (Is S)", horizontal,
                 "rad/s", lab.textbook("5.98"));
      lab.result("horizontal_precession_rpm", "  in rpm", horizontal / kRpm, "rpm",
                 lab.textbook("57.1"));
      lab.result("horizontal_precession_period_s", "  its period", 2 * rigid::kPi / horizontal, "s",
                 lab.textbook("1.05"));
    } else {
      lab.result_none("horizontal_precession_rate_rad_s", "phi_dot = m g l / (Is S)", "rad/s",
                      "no spin: a horizontal top just falls");
    }

    lab.section(
        fmt::format("8.1 (c) steady precession at theta0 = {:g} deg (eq. 187)", in.theta0_deg));
    const rigid::SteadyPrecession steady = rigid::steady_precession_rates(top, S, theta0);
    if (steady.exists && std::isfinite(steady.fast)) {
      lab.result("steady_precession_rates_rad_s", "phi_dot, slow and fast",
                 Vector2d(steady.slow, steady.fast), "rad/s", lab.textbook("(7.75, 26.2)"));
      lab.result(
          "steady_precession_periods_s", "  their periods",
          Vector2d(2 * rigid::kPi / std::abs(steady.slow), 2 * rigid::kPi / std::abs(steady.fast)),
          "s", lab.textbook("(0.81, 0.24)"));
    } else {
      lab.result_none("steady_precession_rates_rad_s", "phi_dot, slow and fast", "rad/s",
                      steady.exists ? "horizontal: the fast rate is infinite"
                                    : "Is^2 S^2 < 4 m g l I cos(theta0): no steady precession");
    }

    lab.section("9 the motion: E' = I theta_dot^2 / 2 + V(theta) (eqs. 191-195)");
    const rigid::HeavyTopExact motion = rigid::lab::for_option("--theta0-deg", [&] {
      return rigid::HeavyTopExact(top, {theta0, in.thetadot0, in.phidot0, S});
    });
    lab.result("energy_j", "E (eq. 191)", motion.energy(), "J");
    lab.result("p_phi", "p_phi = L_z (eq. 177)", motion.p_phi(), "kg m^2/s");
    lab.result("p_psi", "p_psi = Is S (eq. 176)", motion.p_psi(), "kg m^2/s");
    lab.result_text("regime", "the axis's path", rigid::to_string(motion.regime()));
    lab.result("theta_min_deg", "theta_min (u2 = cos theta_min)",
               rigid::rad_to_deg(motion.theta_min()), "deg");
    lab.result("theta_max_deg", "theta_max (u1 = cos theta_max)",
               rigid::rad_to_deg(motion.theta_max()), "deg");
    const bool sleeping = motion.regime() == rigid::TopRegime::kSleeping;
    if (sleeping) {
      lab.result_none("nutation_period_s", "nutation period", "s", "upright: no nodding");
      lab.result_text(
          "sleeping_stability", "upright at S vs S_min",
          S >= S_min ? "stable (S >= S_min)" : "unstable (S < S_min): a hair topples it");
    } else {
      lab.result("cubic_roots", "roots u1, u2, u3 of f(u) = 0, u = cos theta",
                 Eigen::Vector3d(motion.u1(), motion.u2(), motion.u3()), "");
      if (std::isfinite(motion.nutation_period())) {
        lab.result("nutation_period_s", "nutation period 2 K(k) / lambda", motion.nutation_period(),
                   "s");
      } else {
        lab.result_none("nutation_period_s", "nutation period", "s",
                        "on the separatrix: never returns");
      }
      lab.result("mean_precession_rate_rad_s", "mean phi_dot over a nutation period",
                 motion.mean_precession_rate(), "rad/s");
      lab.result("phi_dot_turning_rad_s", "phi_dot at theta_max and at theta_min",
                 Vector2d(motion.phi_dot_at_u1(), motion.phi_dot_at_u2()), "rad/s");
      // The fast top (Goldstein 5.7): nodding at Is S / I, by 2 m g l I sin(theta0)/(Is S)^2
      // when released from rest; both to relative order 2 m g l I / (Is S)^2.
      // Printed where that order is below 1 (the text's top: 0.41); a slower top has no
      // such estimate (at S = 1e-10 it read 3e24 deg).
      const std::string frequency_label = "fast-top estimate of 2 pi / period: Is S / I";
      const std::string amplitude_label =
          "fast-top estimate of theta_max - theta_min from rest: 2 m g l I sin(theta0) / (Is S)^2";
      const double order = 2 * top.mgl * I / ((Is * S) * (Is * S));
      if (S > 0 && order < 1.0) {
        lab.result("fast_top_nutation_frequency_rad_s", frequency_label, Is * S / I, "rad/s");
        lab.result("fast_top_nutation_amplitude_deg", amplitude_label,
                   rigid::rad_to_deg(order * std::sin(theta0)), "deg");
      } else if (S > 0) {
        const std::string why =
            fmt::format("not a fast top: 2 m g l I / (Is S)^2 = {:.3g} is not below 1", order);
        lab.result_none("fast_top_nutation_frequency_rad_s", frequency_label, "rad/s", why);
        lab.result_none("fast_top_nutation_amplitude_deg", amplitude_label, "deg", why);
      }
    }
    // The sleeping top's stability a hair from upright, just above and below S_min.
    const double hair = 1e-3;
    const double above = rigid::HeavyTopExact(top, {hair, 0, 0, 1.01 * S_min}).theta_max();
    const double below = rigid::HeavyTopExact(top, {hair, 0, 0, 0.99 * S_min}).theta_max();
    lab.result("sleeping_check_theta_max_deg",
               "theta_max from 0.001 rad at 1.01 S_min and at 0.99 S_min",
               Vector2d(rigid::rad_to_deg(above), rigid::rad_to_deg(below)), "deg");

    // Sampling: 200 a nutation period (or a turn of the spin for a sleeping top).
    const double scale = sleeping || !std::isfinite(motion.nutation_period())
                             ? 2 * rigid::kPi / std::max(std::abs(S), 1e-300)
                             : motion.nutation_period();
    const double t_end = rigid::lab::end_time(lab, in.t_end, in.periods, scale, 3.0 * scale);
    const rigid::lab::RunPlan plan =
        rigid::lab::plan_run(lab, in.integration, t_end, scale, kMaxSteps);
    const rigid::IntegrateOptions& options = plan.options;
    const std::vector<double>& times = plan.times;
    const bool fixed = plan.fixed;
    lab.section(fmt::format("{} to t_end = {:g} s", in.integration.method, t_end));
    rigid::lab::report_plan(lab, plan);
    if (in.integration.method != "exact") {
      lab.result_text("method_kind", "method", std::string(rigid::method_kind(options.method)));
    }
    rigid::TopRun run;
    if (in.integration.method == "exact") {
      run = rigid::sample_exact(motion, times);
    } else {
      const char* option = fixed ? "--step" : "--tolerance";
      try {
        run = rigid::integrate_heavy_top(top, rigid::heavy_top_state(motion.angles(0.0)), times,
                                         options);
      } catch (const std::exception& e) {
        throw UsageError(option, e.what());
      }
      double worst = 0;
      for (const rigid::TopSample& s : run.samples) {
        const double e = std::abs(s.theta - motion.theta(s.t));
        if (!std::isfinite(e)) {
          throw UsageError(option, "the integration diverged; shorten the step");
        }
        worst = std::max(worst, e);
      }
      rigid::lab::refuse_runaway(
          option, std::max({run.energy_drift_rel, run.p_phi_drift_rel, run.p_psi_drift_rel}));
      lab.result("max_theta_error_deg", "max |theta - theta_exact|", rigid::rad_to_deg(worst),
                 "deg");
      lab.count("steps", "steps taken", run.steps);
    }
    {
      std::vector<double> t, e[3];
      for (const rigid::TopSample& s : run.samples) {
        t.push_back(s.t);
        for (int i = 0; i < 3; ++i) e[i].push_back(s.invariant_errors(i));
      }
      const double roundoff =
          in.integration.method == "exact" ? rigid::lab::kClosedFormRoundoff : 0.0;
      rigid::lab::report_invariant(lab, "energy", "max |E - E0| / (T0 + m g l)", t, e[0], scale,
                                   roundoff);
      rigid::lab::report_invariant(lab, "p_phi", "max |p_phi - p_phi0| / |L0|", t, e[1], scale,
                                   roundoff);
      rigid::lab::report_invariant(lab, "p_psi", "max |p_psi - p_psi0| / |L0|", t, e[2], scale,
                                   roundoff);
    }

    // Every integrator against the exact motion, each within a step budget.
    const std::vector<rigid::TopComparison> methods =
        rigid::compare_top_methods(motion, times, scale, options, kMaxComparisonSteps);
    lab.section(
        fmt::format("every integrator against the exact theta (tolerance {:g}, step {:.4g} s)",
                    in.integration.tolerance, options.step));
    for (const rigid::TopComparison& c : methods) {
      const std::string name(rigid::method_name(c.options.method));
      const std::string key = "max_theta_error_" + rigid::lab::json_key(name) + "_deg";
      const std::string label = fmt::format("{:<15} max |theta - theta_exact|", name);
      if (!c.completed) {
        lab.result_none(key, label, "deg",
                        fmt::format("not run: needs more than {} steps", kMaxComparisonSteps));
      } else if (!std::isfinite(c.max_theta_error)) {
        lab.result_none(key, label, "deg", "diverged at this step");
      } else {
        lab.result(key, label, rigid::rad_to_deg(c.max_theta_error), "deg");
      }
    }

    // "Which method drifts" at equal cost: a sleeping top has no nutation to count
    // periods by, nor anything to drift through.
    std::vector<rigid::TopComparison> at_cost;
    if (!sleeping && std::isfinite(motion.nutation_period())) {
      at_cost = rigid::compare_top_methods_at_cost(motion, scale, kEqualCostPeriods,
                                                   kEqualCostEvaluations);
      std::vector<rigid::lab::EqualCostRow> rows;
      for (const rigid::TopComparison& c : at_cost) {
        rows.push_back(
            {c.options, c.completed && std::isfinite(c.max_theta_error), c.evaluations, c.energy});
      }
      rigid::lab::report_equal_cost(lab, rows, kEqualCostEvaluations, kEqualCostPeriods);
    }

    // The text's numbers use S rounded to 52.4 rad/s; the exact ones differ in the last digit.
    if (lab.textbook_inputs()) {
      const double S_text = rounded(S, 3);
      const rigid::SteadyPrecession text_steady =
          rigid::steady_precession_rates(top, S_text, theta0);
      const double text_horizontal = rigid::horizontal_precession_rate(top, S_text);
      lab.note(fmt::format(
          "errata: section 8.1 rounds S = {:.6g} rad/s to {:g} before using it. With the exact S, "
          "phi_dot (horizontal) = {:.4g} rad/s = {:.4g} rpm and the slow steady rate at 30 deg "
          "is {:.4g} rad/s. The text's 5.98 and 7.75 rad/s come from S = {:g} ({:.4g} and "
          "{:.4g}), and its 57.1 rpm from the rounded 5.98 rad/s ({:.4g} rpm).",
          S, S_text, rigid::horizontal_precession_rate(top, S),
          rigid::horizontal_precession_rate(top, S) / kRpm, steady.slow, S_text, text_horizontal,
          text_steady.slow, rounded(text_horizontal, 3) / kRpm));
      lab.note(fmt::format(
          "errata: the sleeping top's spin period 2 pi / S_min = {:.5g} s rounds to {:.3f} s, not "
          "the text's 0.132 s.",
          2 * rigid::kPi / S_min, 2 * rigid::kPi / S_min));
    }
    lab.note(
        "errata: eq. 186 is misprinted: theta_ddot = 0 in eq. 184 gives m g l = Is S phi_dot - "
        "I phi_dot^2 cos(theta), with I, not S, in the last term (eq. 187 solves the right one).");

    rigid::lab::TimeSeries series{{"t_s", "theta_rad", "theta_exact_rad", "omega1", "omega2",
                                   "omega3", "qw", "qx", "qy", "qz", "energy_error_rel"},
                                  {}};
    for (const rigid::TopSample& s : run.samples) {
      const auto& q = s.attitude;
      series.rows.push_back({s.t, s.theta, motion.theta(s.t), s.omega_body(0), s.omega_body(1),
                             s.omega_body(2), q.w(), q.x(), q.y(), q.z(), s.energy_error});
    }
    lab.series(std::move(series));

    if (lab.animating()) {
      // Frames from the chosen method: exact, or the integrator sampled at exactly the
      // animation's times (never at its steps)
      rigid::lab::top_nutation::TopStateAt state_at;
      std::vector<double> path_times;
      std::map<double, rigid::lab::top_nutation::TopState> states;
      if (in.integration.method != "exact") {
        path_times = lab.animation_times(t_end);
        const rigid::TopRun frames = rigid::lab::for_option(fixed ? "--step" : "--tolerance", [&] {
          return rigid::integrate_heavy_top(top, rigid::heavy_top_state(motion.angles(0.0)),
                                            path_times, options);
        });
        for (const rigid::TopSample& s : frames.samples) states[s.t] = {s.attitude, s.omega_body};
        state_at = [&states](double t) { return states.at(t); };
      }
      lab.animate(
          t_end, "the top precessing and nodding; the path of its axis on the sphere",
          [&](double t) {
            return rigid::lab::top_nutation::top_scene(motion, in.arm, in.disk_radius, t, state_at,
                                                       path_times);
          },
          "top");
    }

    lab.figures([&](rigid::lab::FigureSet& set) {
      // Beside the exact motion, an integrated one: the lab's own, or splitting4 at its default
      // step.
      rigid::TopRun integrated = run;
      if (in.integration.method == "exact") {
        rigid::OdeOptions o = options;
        o.method = rigid::Method::kSplitting4;
        integrated = rigid::integrate_heavy_top(top, rigid::heavy_top_state(motion.angles(0.0)),
                                                rigid::sample_times(t_end, scale, o.step), o);
      }
      // A sleeping top has no comparison at equal cost: the one at the lab's settings.
      const bool equal_cost = !at_cost.empty();
      rigid::lab::top_nutation::draw(
          set, {motion, run, integrated, equal_cost ? at_cost : methods, in.arm, in.disk_radius,
                t_end, equal_cost ? kEqualCostEvaluations : 0.0, kEqualCostPeriods});
    });
  });
}
