#include "poinsot/poinsot.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "common/free_motion.h"
#include "rigid/inertia.h"
#include "rigid/poinsot.h"

namespace rigid::lab::poinsot {
using Eigen::Vector3d;
namespace {

constexpr const char* kName = "poinsot";
constexpr const char* kTitle =
    "free asymmetric body: Poinsot's ellipsoids and polhodes (sections 4-5.1)";

// Section 4: the two ellipsoids through omega0 and Poinsot's construction.
void report_ellipsoids(Report& report, const std::string& regime) {
  const FreeBodyExact& exact = report.exact;
  report.section("4 Poinsot's ellipsoids through omega0 (eqs. 79-82)");
  const PoinsotEllipsoids ellipsoids = poinsot_ellipsoids(exact.moments(), report.omega0);
  report.result("energy_ellipsoid_semi_axes", "energy ellipsoid semi-axes sqrt(2T/I_i)",
                ellipsoids.energy_semi_axes, "rad/s");
  report.result("momentum_ellipsoid_semi_axes", "momentum ellipsoid semi-axes |L|/I_i",
                ellipsoids.momentum_semi_axes, "rad/s");
  // Poinsot's construction: the energy ellipsoid rolls on the invariable plane, the
  // contact point (omega) tracing the herpolhode there
  report.result("invariable_plane_distance",
                "invariable plane's distance from the fixed point, 2T/|L|",
                2.0 * exact.energy() / exact.angular_momentum_magnitude(), "rad/s");
  const double turn = herpolhode_turn_per_period(exact);
  if (std::isfinite(turn)) {
    report.result("herpolhode_turn_per_period_deg", "herpolhode: turn about L a polhode period",
                  rad_to_deg(turn), "deg");
    const double apart = std::abs(std::remainder(kHerpolhodePeriods * turn, 2.0 * kPi));
    report.note(fmt::format(
        "the herpolhode closes only if its turn a polhode period, {:.4f} deg, is a rational "
        "multiple of 360 deg, and in general it is not: after {:g} periods the contact point is "
        "{:.2f} deg from where it started (the herpolhode figure shows it)",
        rad_to_deg(turn), kHerpolhodePeriods, rad_to_deg(apart)));
  } else {
    report.result_none("herpolhode_turn_per_period_deg",
                       "herpolhode: turn about L a polhode period", "deg",
                       "no polhode period: " + regime);
  }
}

// Section 4.1: the text's example I1 : I2 : I3 = 5 : 4 : 3, whatever the inputs.
void report_text_example(Report& report) {
  report.section("4.1 the text's example I1 : I2 : I3 = 5 : 4 : 3");
  const Vector3d ratios(5, 4, 3);
  report.result("ratios_momentum", "momentum ellipsoid 1/I_i (eq. 80)",
                momentum_ellipsoid_ratios(ratios), "", printed("(0.20 : 0.25 : 0.33)"));
  report.result("ratios_energy", "energy ellipsoid 1/sqrt(I_i) (eq. 82)",
                energy_ellipsoid_ratios(ratios), "", printed("(0.44 : 0.50 : 0.58)"));
  report.result("ratios_touching_axis1", "momentum, touching on axis 1",
                momentum_ratios_touching(ratios, 0), "", printed("(0.44 : 0.55 : 0.73)"));
  report.result("ratios_touching_axis2", "momentum, touching on axis 2",
                momentum_ratios_touching(ratios, 1), "", printed("(0.40 : 0.50 : 0.66)"));
  report.result("ratios_touching_axis3", "momentum, touching on axis 3",
                momentum_ratios_touching(ratios, 2), "", printed("(0.35 : 0.43 : 0.58)"));
  const Vector3d touch1 = momentum_ratios_touching(ratios, 0);
  const Vector3d touch2 = momentum_ratios_touching(ratios, 1);
  const Vector3d energy = energy_ellipsoid_ratios(ratios);
  report.erratum({"section 4.1, the energy ellipsoid's ratios",
                  "the ratio from kinetic energy is (0.44:0.50:0.58)",
                  fmt::format("1/sqrt(5) = {:.4f} rounds to {:.2f}, which the text truncates to "
                              "0.44: ({:.2f} : {:.2f} : {:.2f})",
                              energy(0), energy(0), energy(0), energy(1), energy(2))});
  report.erratum(
      {"section 4.1, the momentum ratios touching on axes 1 and 2",
       "resulting is (0.44:0.55:0.73) ... However for the 2-axis, intermediate moment, the "
       "ratio becomes (0.40:0.50:0.66)",
       fmt::format("the text rescales ratios it has already rounded; exactly, touching on axis 1 "
                   "gives ({:.3f} : {:.3f} : {:.3f}) and on axis 2 ({:.3f} : {:.3f} : {:.3f})",
                   touch1(0), touch1(1), touch1(2), touch2(0), touch2(1), touch2(2))});
}

// The body's principal moments: given, or those of a solid ellipsoid (the text's) or a
// solid box of the given mass.
Vector3d moments_of(Report& report, const Inputs& in) {
  const bool moments_given = in.inertia.has_value(), box = in.box.has_value();
  if (moments_given || box) report.drop_input("ellipsoid");
  if (moments_given) report.drop_input("mass");
  return moments_given ? *in.inertia
         : box
             ? Vector3d(
                   solid_box(in.mass, (*in.box)(0), (*in.box)(1), (*in.box)(2)).I_com.diagonal())
             : Vector3d(solid_ellipsoid(in.mass, in.ellipsoid(0), in.ellipsoid(1), in.ellipsoid(2))
                            .I_com.diagonal());
}

// The body as drawn: as given, or, from its moments alone, the solid ellipsoid with
// those moments (semi-axes^2 in proportion to I_j + I_k - I_i, eq. 40).
Vector3d extents_of(const Inputs& in, const Vector3d& moments) {
  const double floor = 1e-3 * moments.sum();
  const double I1 = moments(0), I2 = moments(1), I3 = moments(2);
  return in.box       ? Vector3d(0.5 * *in.box)
         : in.inertia ? Vector3d(std::sqrt(std::max(I2 + I3 - I1, floor)),
                                 std::sqrt(std::max(I1 + I3 - I2, floor)),
                                 std::sqrt(std::max(I1 + I2 - I3, floor)))
                      : in.ellipsoid;
}

// In short: stable or flips, and how soon, from what the motion's sections said.
void report_answer(Report& report) {
  const Json& said = report.results();
  const double period = report.exact.period();
  if (said.at("first_flip_s").is_number()) {
    report.answer(fmt::format(
        "it flips: spun near its intermediate axis, the body turns over first at {:.4g} s, then "
        "every {:.4g} s (a nudge grows at {:.4g}/s)",
        said.at("first_flip_s").get<double>(), said.at("flip_interval_s").get<double>(),
        said.at("growth_rate_per_s").get<double>()));
  } else if (std::isfinite(period)) {
    report.answer(fmt::format("{}; omega goes round its polhode every {:.4g} s",
                              said.at("motion").get<std::string>(), period));
  } else {
    report.answer(said.at("motion").get<std::string>());
  }
}

// The run as --csv writes it: t, omega, the attitude, T and |L| at each sample.
TimeSeries run_series(const FreeBodyRun& run, const PrincipalMoments& I) {
  TimeSeries series("poinsot: the run at its sample times (the closed form's, or --method's)");
  series.add({"t_s"}, "s", "time")
      .add({"omega1", "omega2", "omega3"}, "rad/s", "omega in the body's principal axes 1, 2, 3")
      .add({"qw", "qx", "qy", "qz"}, "1", kQuaternionConvention)
      .add({"energy_J"}, "J", "the kinetic energy T (constant but for the integrator's error)")
      .add({"L_kg_m2_s"}, "kg m^2/s", "|L| (constant but for the integrator's error)");
  for (const auto& s : run.samples) {
    const Vector3d w = omega_body(s.x);
    series.rows.push_back({s.t, w(0), w(1), w(2), s.x[3], s.x[4], s.x[5], s.x[6],
                           kinetic_energy(I, w), angular_momentum_magnitude(I, w)});
  }
  return series;
}

}  // namespace

const InputTable<Inputs>& input_table() {
  static const InputTable<Inputs> table = [] {
    InputTable<Inputs> t;
    const std::string body_or_moments =
        "give the moments or a body (--ellipsoid or --box, and --mass), not both";
    t.vector("--inertia", &Inputs::inertia, "principal moments I1,I2,I3 (instead of --ellipsoid)")
        .unit("kg m^2")
        .positive()
        .lab_default("from --ellipsoid and --mass")
        .symbol("I")
        .excludes("--ellipsoid", body_or_moments)
        .excludes("--mass", body_or_moments)
        .excludes("--box", body_or_moments);
    t.vector("--ellipsoid", &Inputs::ellipsoid, "semi-axes A,B,C of a uniform solid ellipsoid")
        .unit("m")
        .positive()
        .symbol("A, B, C");
    t.vector("--box", &Inputs::box,
             "side lengths A,B,C of a uniform solid box, a book or a phone (instead of "
             "--ellipsoid)")
        .unit("m")
        .positive()
        .lab_default("none: the ellipsoid")
        .symbol("box")
        .excludes("--ellipsoid", "give --ellipsoid or --box, not both");
    t.number("--mass", &Inputs::mass, "mass of the solid ellipsoid or box")
        .unit("kg")
        .positive()
        .symbol("M");
    t.vector("--omega", &Inputs::omega0, "initial angular velocity in body axes")
        .unit("rad/s")
        .nonzero()
        .symbol("\\omega_0");
    add_end_time_inputs(t, &Inputs::t_end, &Inputs::periods, "polhode period",
                        "three polhode periods");
    t.include(integration_inputs("how omega(t) is computed", "polhode period / 2000"),
              &Inputs::integration);
    return t;
  }();
  return table;
}

Report compute(const Inputs& in) {
  Report report(kName, kTitle);
  report.start(input_table(), in);
  const bool moments_given = in.inertia.has_value(), box = in.box.has_value();
  const Vector3d moments = moments_of(report, in);
  const PrincipalMoments I{moments(0), moments(1), moments(2)};
  for_input(moments_given ? "--inertia" : box ? "--box" : "--ellipsoid", [&] { validate(I); });

  report.section("5.1 the body and its free motion (eqs. 116-120)");
  report.result("principal_moments", "principal moments I1, I2, I3", moments, "kg m^2",
                report.textbook("(pi, 2 pi, 8.168)"));
  report.exact = FreeBodyExact(I, in.omega0);
  report.omega0 = in.omega0;
  const FreeBodyExact& exact = report.exact;
  report.result("energy", "kinetic energy T (eq. 81)", exact.energy(), "J");
  report.result("angular_momentum_magnitude", "|L| (eq. 79)", exact.angular_momentum_magnitude(),
                "kg m^2/s");
  const std::string regime = to_string(exact.regime());
  if (std::isfinite(exact.period())) {
    report.result("polhode_period_s", "polhode period", exact.period(), "s");
  } else {
    report.result_none("polhode_period_s", "polhode period", "s",
                       "no polhode to go round: " + regime);
  }
  report_motion(report, exact);
  report_flips(report, exact);
  report_answer(report);

  report.scale = time_scale(exact);
  const double scale = report.scale;
  report.t_end = end_time(in.t_end, in.periods, scale, 3.0 * scale);
  // Two hundred samples a period; a fixed-step method is sampled on its own step grid.
  // Every method is compared at --step and --tolerance, in a section of its own.
  const RunPlan plan = plan_run(report, in.integration, /*compared=*/true, report.t_end, scale);
  report.options = plan.options;
  report.method = in.integration.method;

  report.section("integration to t_end = " + fmt::format("{:g} s", report.t_end));
  report.result_text("method", "method", report.method);
  if (report.method != "exact") {
    report.result_text("method_kind", "  its kind", std::string(method_kind(plan.options.method)));
  }
  report_plan(report, plan);
  const FreeBodyProblem problem(I);
  report.run = run_chosen_method(report, problem, exact, in.integration, plan.options, plan.times,
                                 free_body_words());
  report.result("omega_end", "omega at t_end", omega_body(report.run.samples.back().x), "rad/s");
  report_drifts(report, report.run, scale, report.method == "exact", free_body_words());

  // Every method at --step and --tolerance, and "which method drifts" answered at
  // equal cost, over enough periods for a symplectic method's bounded band to tell
  // from a steady drift.
  if (in.integration.compare) {
    report.comparisons =
        compare_every_method(report, problem, exact, plan, scale, true, free_body_words());
  }

  report_ellipsoids(report, regime);
  report_text_example(report);
  report.series(run_series(report.run, I));

  report.box = box;
  report.extents = extents_of(in, moments);
  return report;
}

namespace {

// The body at any time: the closed form, or --method's run integrated on from its samples.
BodyMotion body_motion(const Report& report) {
  return free_body_motion(
      report.exact,
      report.method == "exact" ? std::nullopt : std::optional<OdeOptions>(report.options),
      report.run.samples);
}

}  // namespace

LabProgram<Inputs, Report> program() {
  return {kName, kTitle, input_table(), compute, figures, animation,
          /*csv=*/
          "the run at its sample times: omega in body axes, the attitude quaternion, "
          "T and |L|",
          /*preview=*/leave_out_comparisons<Inputs>,
          /*textbook_example=*/true, body_motion};
}

}  // namespace rigid::lab::poinsot
