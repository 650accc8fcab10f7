// poinsot: sections 4, 4.1 and 5.1 of the chapter. A free body turns with no
// torque: omega moves on the energy and the momentum ellipsoids at once, along
// their intersection, the polhode. For the text's solid ellipsoid
// x^2/9 + y^2/4 + z^2 = 1 (I = pi, 2 pi, 8.168) started at omega = (1, 1, 1),
// omega(t) follows in closed form from Jacobi's elliptic functions; every
// integrator is measured against it.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "common/free_body_run.h"
#include "common/lab.h"
#include "figures.h"
#include "rigid/inertia.h"
#include "rigid/poinsot.h"

using Eigen::Vector3d;
using rigid::lab::Lab;
using rigid::lab::printed;
using rigid::lab::UsageError;

namespace {

// A run longer than this many steps is refused rather than left to hang.
constexpr std::size_t kMaxSteps = 20'000'000;
// Each method of the comparison with the others gets at most this many steps:
// the comparison then costs at most a few hundred ms.
constexpr std::size_t kMaxComparisonSteps = 20'000;
// The comparison at equal cost: this many right-hand-side evaluations a polhode
// period over this many periods (a few tens of ms), enough for rk4's steady energy
// drift to leave the splittings' bounded band behind.
constexpr double kEqualCostEvaluations = 200.0;
constexpr double kEqualCostPeriods = 100.0;
// The herpolhode figure: enough polhode periods for its failure to close to show.
constexpr double kHerpolhodePeriods = 6.0;

}  // namespace

int main(int argc, char** argv) {
  Lab lab("poinsot", "free asymmetric body: Poinsot's ellipsoids and polhodes (sections 4-5.1)");
  rigid::lab::poinsot::Inputs in;
  lab.vector("--inertia", in.inertia, "principal moments I1,I2,I3 (instead of --ellipsoid)")
      .unit("kg m^2")
      .positive()
      .lab_default("from --ellipsoid and --mass")
      .symbol("I");
  lab.vector("--ellipsoid", in.ellipsoid, "semi-axes A,B,C of a uniform solid ellipsoid")
      .unit("m")
      .positive()
      .symbol("A, B, C");
  lab.vector("--box", in.box,
             "side lengths A,B,C of a uniform solid box, a book or a phone (instead of "
             "--ellipsoid)")
      .unit("m")
      .positive()
      .lab_default("none: the ellipsoid")
      .symbol("box");
  lab.number("--mass", in.mass, "mass of the solid ellipsoid or box")
      .unit("kg")
      .positive()
      .symbol("M");
  lab.vector("--omega", in.omega0, "initial angular velocity in body axes")
      .unit("rad/s")
      .nonzero()
      .symbol("\\omega_0");
  rigid::lab::declare_end_time(lab, in.t_end, in.periods, "polhode period",
                               "three polhode periods");
  rigid::lab::declare_integration_options(lab, in.integration, "how omega(t) is computed",
                                          "polhode period / 2000");
  lab.enable_csv();
  lab.enable_animation();

  in.integration.compared = true;  // every method at --step and --tolerance, in a section
  return lab.run(argc, argv, [&](Lab& lab) {
    // The body: its moments, a solid ellipsoid (the text's) or a solid box.
    const bool moments_given = lab.given("--inertia"), box = lab.given("--box");
    if (moments_given && (lab.given("--ellipsoid") || lab.given("--mass") || box)) {
      throw UsageError("--inertia",
                       "give the moments or a body (--ellipsoid or --box, and --mass), not both");
    }
    if (box && lab.given("--ellipsoid")) {
      throw UsageError("--box", "give --ellipsoid or --box, not both");
    }
    if (moments_given || box) lab.drop_input("ellipsoid");
    if (moments_given) lab.drop_input("mass");
    const Vector3d moments =
        moments_given ? in.inertia
        : box
            ? Vector3d(rigid::solid_box(in.mass, in.box(0), in.box(1), in.box(2)).I_com.diagonal())
            : Vector3d(
                  rigid::solid_ellipsoid(in.mass, in.ellipsoid(0), in.ellipsoid(1), in.ellipsoid(2))
                      .I_com.diagonal());
    const rigid::PrincipalMoments I{moments(0), moments(1), moments(2)};
    rigid::lab::for_option(moments_given ? "--inertia"
                           : box         ? "--box"
                                         : "--ellipsoid",
                           [&] { rigid::validate(I); });

    lab.section("5.1 the body and its free motion (eqs. 116-120)");
    lab.result("principal_moments", "principal moments I1, I2, I3", moments, "kg m^2",
               lab.textbook("(pi, 2 pi, 8.168)"));
    const rigid::FreeBodyExact exact(I, in.omega0);
    lab.result("energy", "kinetic energy T (eq. 81)", exact.energy(), "J");
    lab.result("angular_momentum_magnitude", "|L| (eq. 79)", exact.angular_momentum_magnitude(),
               "kg m^2/s");
    const std::string regime = rigid::to_string(exact.regime());
    if (std::isfinite(exact.period())) {
      lab.result("polhode_period_s", "polhode period", exact.period(), "s");
    } else {
      lab.result_none("polhode_period_s", "polhode period", "s",
                      "no polhode to go round: " + regime);
    }
    rigid::lab::report_motion(lab, exact);

    const double scale = rigid::lab::time_scale(exact);
    const double t_end = rigid::lab::end_time(lab, in.t_end, in.periods, scale, 3.0 * scale);
    // Two hundred samples a period; a fixed-step method is sampled on its own step grid.
    const rigid::lab::RunPlan plan =
        rigid::lab::plan_run(lab, in.integration, t_end, scale, kMaxSteps);
    const rigid::IntegrateOptions& options = plan.options;
    const std::vector<double>& times = plan.times;

    lab.section("integration to t_end = " + fmt::format("{:g} s", t_end));
    lab.result_text("method", "method", in.integration.method);
    if (in.integration.method != "exact") {
      lab.result_text("method_kind", "  its kind", std::string(rigid::method_kind(options.method)));
    }
    rigid::lab::report_plan(lab, plan);
    const rigid::IntegrationResult run =
        rigid::lab::run_free_body(lab, exact, in.integration, options, times);
    lab.result("omega_end", "omega at t_end", run.samples.back().omega_body, "rad/s");
    rigid::lab::report_drifts(lab, run, scale, in.integration.method == "exact");

    lab.section(
        fmt::format("every integrator against the exact solution (tolerance {:g}, step {:.4g} s)",
                    in.integration.tolerance, options.step));
    // An aside: a method needing more steps than this is reported as not run.
    const std::vector<rigid::MethodComparison> methods =
        rigid::compare_methods(exact, times, scale, options, kMaxComparisonSteps);
    for (const rigid::MethodComparison& c : methods) {
      const std::string name(rigid::method_name(c.options.method));
      const std::string key = "max_error_" + rigid::lab::json_key(name);
      const std::string label = fmt::format("{:<15} max |omega - omega_exact| / |omega0|", name);
      if (!c.completed) {
        lab.result_none(key, label, "",
                        fmt::format("not run: needs more than {} steps", kMaxComparisonSteps));
      } else if (!std::isfinite(c.max_omega_error)) {
        lab.result_none(key, label, "", "diverged at this step");
      } else {
        lab.result(key, label, c.max_omega_error, "");
      }
    }

    // "Which method drifts" answered at equal cost, over enough periods for a
    // symplectic method's bounded band to tell from a steady drift.
    const std::vector<rigid::MethodComparison> at_cost =
        rigid::compare_methods_at_cost(exact, scale, kEqualCostPeriods, kEqualCostEvaluations);
    std::vector<rigid::lab::EqualCostRow> cost_rows;
    for (const rigid::MethodComparison& c : at_cost) {
      cost_rows.push_back(
          {c.options, c.completed && std::isfinite(c.max_omega_error), c.evaluations, c.energy});
    }
    rigid::lab::report_equal_cost(lab, cost_rows, kEqualCostEvaluations, kEqualCostPeriods);

    lab.section("4 Poinsot's ellipsoids through omega0 (eqs. 79-82)");
    const rigid::PoinsotEllipsoids ellipsoids = rigid::poinsot_ellipsoids(I, in.omega0);
    lab.result("energy_ellipsoid_semi_axes", "energy ellipsoid semi-axes sqrt(2T/I_i)",
               ellipsoids.energy_semi_axes, "rad/s");
    lab.result("momentum_ellipsoid_semi_axes", "momentum ellipsoid semi-axes |L|/I_i",
               ellipsoids.momentum_semi_axes, "rad/s");
    // Poinsot's construction: the energy ellipsoid rolls on the invariable plane, the
    // contact point (omega) tracing the herpolhode there
    lab.result("invariable_plane_distance",
               "invariable plane's distance from the fixed point, 2T/|L|",
               2.0 * exact.energy() / exact.angular_momentum_magnitude(), "rad/s");
    const double turn = rigid::herpolhode_turn_per_period(exact);
    if (std::isfinite(turn)) {
      lab.result("herpolhode_turn_per_period_deg", "herpolhode: turn about L a polhode period",
                 rigid::rad_to_deg(turn), "deg");
      const double apart = std::abs(std::remainder(kHerpolhodePeriods * turn, 2.0 * rigid::kPi));
      lab.note(fmt::format(
          "the herpolhode closes only if its turn a polhode period, {:.4f} deg, is a rational "
          "multiple of 360 deg, and in general it is not: after {:g} periods the contact point is "
          "{:.2f} deg from where it started (the herpolhode figure shows it)",
          rigid::rad_to_deg(turn), kHerpolhodePeriods, rigid::rad_to_deg(apart)));
    } else {
      lab.result_none("herpolhode_turn_per_period_deg", "herpolhode: turn about L a polhode period",
                      "deg", "no polhode period: " + regime);
    }

    lab.section("4.1 the text's example I1 : I2 : I3 = 5 : 4 : 3");
    const Vector3d ratios(5, 4, 3);
    lab.result("ratios_momentum", "momentum ellipsoid 1/I_i (eq. 80)",
               rigid::momentum_ellipsoid_ratios(ratios), "", printed("(0.20 : 0.25 : 0.33)"));
    lab.result("ratios_energy", "energy ellipsoid 1/sqrt(I_i) (eq. 82)",
               rigid::energy_ellipsoid_ratios(ratios), "", printed("(0.44 : 0.50 : 0.58)"));
    lab.result("ratios_touching_axis1", "momentum, touching on axis 1",
               rigid::momentum_ratios_touching(ratios, 0), "", printed("(0.44 : 0.55 : 0.73)"));
    lab.result("ratios_touching_axis2", "momentum, touching on axis 2",
               rigid::momentum_ratios_touching(ratios, 1), "", printed("(0.40 : 0.50 : 0.66)"));
    lab.result("ratios_touching_axis3", "momentum, touching on axis 3",
               rigid::momentum_ratios_touching(ratios, 2), "", printed("(0.35 : 0.43 : 0.58)"));
    const Vector3d touch1 = rigid::momentum_ratios_touching(ratios, 0);
    const Vector3d touch2 = rigid::momentum_ratios_touching(ratios, 1);
    lab.note(fmt::format(
        "errata: section 4.1 rescales ratios it has already rounded; exactly, touching on axis 1 "
        "gives ({:.3f} : {:.3f} : {:.3f}) and on axis 2 ({:.3f} : {:.3f} : {:.3f}), where the "
        "text prints (0.44 : 0.55 : 0.73) and (0.40 : 0.50 : 0.66)",
        touch1(0), touch1(1), touch1(2), touch2(0), touch2(1), touch2(2)));
    lab.note(fmt::format(
        "errata: 1/sqrt(5) = {:.4f} rounds to {:.2f}; the text's energy ratio "
        "prints 0.44, truncated",
        rigid::energy_ellipsoid_ratios(ratios)(0), rigid::energy_ellipsoid_ratios(ratios)(0)));

    rigid::lab::TimeSeries series{
        {"t_s", "omega1", "omega2", "omega3", "qw", "qx", "qy", "qz", "energy_J", "L_kg_m2_s"}, {}};
    for (const auto& s : run.samples) {
      const auto& q = s.attitude;
      series.rows.push_back({s.t, s.omega_body(0), s.omega_body(1), s.omega_body(2), q.w(), q.x(),
                             q.y(), q.z(), rigid::kinetic_energy(I, s.omega_body),
                             rigid::angular_momentum_magnitude(I, s.omega_body)});
    }
    lab.series(std::move(series));

    // The body as drawn: as given, or, from its moments alone, the solid ellipsoid with
    // those moments (semi-axes^2 in proportion to I_j + I_k - I_i, eq. 40).
    const Vector3d extents =
        box             ? Vector3d(0.5 * in.box)
        : moments_given ? Vector3d(std::sqrt(std::max(I.I2 + I.I3 - I.I1, 1e-3 * moments.sum())),
                                   std::sqrt(std::max(I.I1 + I.I3 - I.I2, 1e-3 * moments.sum())),
                                   std::sqrt(std::max(I.I1 + I.I2 - I.I3, 1e-3 * moments.sum())))
                        : in.ellipsoid;
    if (lab.animating()) {
      // Frames from the chosen method: the exact solution, or the integrator sampled at
      // exactly the animation's times (never at its own steps)
      rigid::lab::poinsot::Animation::StateAt state_at;
      std::vector<double> path_times;
      std::map<double, rigid::FreeBodyState> states;
      if (in.integration.method != "exact") {
        path_times = lab.animation_times(t_end);
        const rigid::IntegrationResult frames =
            rigid::lab::run_free_body(lab, exact, in.integration, options, path_times);
        for (const rigid::FreeBodySample& s : frames.samples)
          states[s.t] = rigid::make_state(s.omega_body, s.attitude);
        state_at = [&states](double t) { return states.at(t); };
      }
      const rigid::lab::poinsot::Animation animation(exact, extents, box, t_end, state_at,
                                                     path_times);
      lab.animate(t_end,
                  "the body turning with L fixed, and its energy ellipsoid rolling on the "
                  "invariable plane: polhode and herpolhode",
                  [&](double t) { return animation.frame(t); });
    }

    lab.figures([&](rigid::lab::FigureSet& set) {
      rigid::lab::poinsot::draw(
          set, {exact, in.omega0, run.samples, at_cost, kEqualCostEvaluations, kEqualCostPeriods,
                scale, std::isfinite(exact.period()) ? "polhode periods" : "turns"});
      if (std::isfinite(exact.period())) {
        set.add("herpolhode",
                fmt::format("Poinsot's construction seen from above: the herpolhode over {:g} "
                            "polhode periods does not close",
                            kHerpolhodePeriods),
                rigid::lab::poinsot::Animation(exact, extents, box, t_end)
                    .herpolhode_scene(kHerpolhodePeriods));
      }
    });
  });
}
