// poinsot: sections 4, 4.1 and 5.1 of the chapter. A free body turns with no
// torque: omega moves on the energy and the momentum ellipsoids at once, along
// their intersection, the polhode. For the text's solid ellipsoid
// x^2/9 + y^2/4 + z^2 = 1 (I = pi, 2 pi, 8.168) started at omega = (1, 1, 1),
// omega(t) follows in closed form from Jacobi's elliptic functions; every
// integrator is measured against it.
#include "rigid/poinsot.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "common/lab.h"
#include "poinsot_figures.h"
#include "rigid/inertia.h"
#include "rigid/units.h"

using Eigen::Vector3d;
using rigid::lab::Lab;
using rigid::lab::textbook_if;
using rigid::lab::UsageError;

namespace {

// A run longer than this many steps is refused rather than left to hang.
constexpr std::size_t kMaxSteps = 20'000'000;

// The motion's time scale: the polhode period, or one turn for a steady spin.
double time_scale(const rigid::FreeBodyExact& motion, const Vector3d& omega0) {
  return std::isfinite(motion.period()) ? motion.period() : 2.0 * rigid::kPi / omega0.norm();
}

}  // namespace

int main(int argc, char** argv) {
  Lab lab("poinsot", "free asymmetric body: Poinsot's ellipsoids and polhodes (sections 4-5.1)");
  Vector3d inertia(1, 1, 1), ellipsoid(3, 2, 1), omega0(1, 1, 1);
  double mass = rigid::kPi, t_end = 0.0, tolerance = 1e-10, step = 0.0;
  std::string method = "exact";
  bool project = false;
  lab.option_vec3("--inertia", inertia, "kg m^2",
                  "principal moments I1,I2,I3 (instead of --ellipsoid)",
                  rigid::lab::Accept::Positive, false, false);
  lab.option_vec3("--ellipsoid", ellipsoid, "m", "semi-axes A,B,C of a uniform solid ellipsoid",
                  rigid::lab::Accept::Positive);
  lab.option("--mass", mass, "kg", "mass of the solid ellipsoid");
  lab.option_vec3("--omega", omega0, "rad/s", "initial angular velocity in body axes",
                  rigid::lab::Accept::Finite, true);
  lab.option("--t-end", t_end, "s", "end time (default: three polhode periods)",
             rigid::lab::Accept::Positive, false);
  lab.option_choice(
      "--method", method,
      {"exact", "splitting", "splitting4", "rk4", "dopri5", "rkf78", "bulirsch-stoer"},
      "how omega(t) is computed");
  lab.option("--tolerance", tolerance, "", "relative and absolute tolerance of adaptive methods");
  lab.option("--step", step, "s", "step of fixed-step methods (default: period / 2000)",
             rigid::lab::Accept::Positive, false);
  lab.flag("--project", project, "rk4, rkf78: project omega back onto T and |L| after each step");
  lab.enable_csv();

  return lab.run(argc, argv, [&](Lab& lab) {
    if (lab.given("--inertia") && (lab.given("--ellipsoid") || lab.given("--mass"))) {
      throw UsageError("--inertia",
                       "give the moments or an ellipsoid (--ellipsoid, --mass), not both");
    }
    if (!(tolerance < 1.0)) throw UsageError("--tolerance", "must lie in (0, 1)");
    const bool book = !lab.given("--inertia") && !lab.given("--ellipsoid") && !lab.given("--mass");
    if (lab.given("--inertia")) {
      lab.drop_input("ellipsoid");
      lab.drop_input("mass");
    }
    const Vector3d moments =
        lab.given("--inertia")
            ? inertia
            : Vector3d(rigid::solid_ellipsoid(mass, ellipsoid(0), ellipsoid(1), ellipsoid(2))
                           .I_com.diagonal());
    const rigid::PrincipalMoments I{moments(0), moments(1), moments(2)};
    try {
      rigid::validate(I);
    } catch (const std::invalid_argument& e) {
      throw UsageError(lab.given("--inertia") ? "--inertia" : "--ellipsoid", e.what());
    }

    lab.section("5.1 the body and its free motion (eqs. 116-120)");
    lab.result("principal_moments", "principal moments I1, I2, I3", moments, "kg m^2",
               textbook_if(book, "(pi, 2 pi, 8.168)"));
    const rigid::FreeBodyExact exact(I, omega0);
    lab.result("energy", "kinetic energy T (eq. 81)", exact.energy(), "J");
    lab.result("angular_momentum_magnitude", "|L| (eq. 79)", exact.angular_momentum_magnitude(),
               "kg m^2/s");
    const char* regimes[] = {"steady rotation", "polhode about the largest axis",
                             "polhode about the smallest axis", "separatrix"};
    const std::string regime = regimes[static_cast<int>(exact.regime())];
    if (std::isfinite(exact.period())) {
      lab.result("polhode_period_s", "polhode period", exact.period(), "s");
    } else {
      lab.result_none("polhode_period_s", "polhode period", "no polhode to go round: " + regime);
    }
    lab.result_text("regime", "motion", regime);

    const double scale = time_scale(exact, omega0);
    if (!lab.given("--t-end")) t_end = 3.0 * scale;
    // Past 1e9 periods the phase lambda t keeps fewer than 7 of its 16 digits.
    if (t_end > 1e9 * scale) {
      throw UsageError("--t-end", fmt::format("at most 1e9 periods ({:g} s) for these inputs: "
                                              "beyond, the phase of the motion loses its digits",
                                              1e9 * scale));
    }
    rigid::IntegrateOptions options;
    options.abs_tol = options.rel_tol = tolerance;
    options.step = lab.given("--step") ? step : scale / 2000.0;
    options.max_steps = kMaxSteps;
    options.method = method == "exact" ? rigid::Method::kDopri5 : rigid::method_from_name(method);
    // Two hundred samples a period; a fixed-step method is sampled on its own step grid.
    const bool fixed = method != "exact" && !rigid::is_adaptive(options.method);
    const std::vector<double> times = rigid::sample_times(t_end, scale, fixed ? options.step : 0.0);
    t_end = times.back();

    lab.section("integration to t_end = " + fmt::format("{:g} s", t_end));
    lab.result_text("method", "method", method);
    lab.result("t_end_s", "end time t_end", t_end, "s");
    if (fixed) lab.result("step_s", "step h", options.step, "s");
    rigid::IntegrationResult run;
    if (method == "exact") {
      run = rigid::sample_exact(exact, times);
    } else {
      options.project_invariants = project;
      if (project && !rigid::can_project(options.method)) {
        throw UsageError("--project", "works with --method rk4 or rkf78 only");
      }
      try {
        run = rigid::integrate_free_body(I, exact.state(0.0), times, options);
      } catch (const std::exception& e) {
        throw UsageError(rigid::is_adaptive(options.method) ? "--tolerance" : "--step", e.what());
      }
      const std::vector<double> errors = rigid::omega_errors(run, exact);
      // A step beyond the method's stability region blows omega up.
      if (!std::all_of(errors.begin(), errors.end(), [](double e) { return std::isfinite(e); })) {
        throw UsageError(rigid::is_adaptive(options.method) ? "--tolerance" : "--step",
                         "the integration diverged (omega overflowed); shorten the step");
      }
      lab.result("max_error_vs_exact", "max |omega - omega_exact| / |omega0|",
                 *std::max_element(errors.begin(), errors.end()), "");
      lab.result("steps", "steps taken", static_cast<double>(run.steps), "");
    }
    lab.result("omega_end", "omega at t_end", run.samples.back().omega_body, "rad/s");
    // Drift over the run, relative to the start (roundoff for "exact").
    lab.result("energy_drift_rel", "max |T - T0| / T0", run.energy_drift_rel, "");
    lab.result("momentum_drift_rel", "max ||L| - |L0|| / |L0|", run.momentum_drift_rel, "");
    lab.result("L_space_drift_rel", "max |L_space - L_space0| / |L0|", run.L_space_drift_rel, "");

    lab.section("4 Poinsot's ellipsoids through omega0 (eqs. 79-82)");
    const rigid::PoinsotEllipsoids ellipsoids = rigid::poinsot_ellipsoids(I, omega0);
    lab.result("energy_ellipsoid_semi_axes", "energy ellipsoid semi-axes sqrt(2T/I_i)",
               ellipsoids.energy_semi_axes, "rad/s");
    lab.result("momentum_ellipsoid_semi_axes", "momentum ellipsoid semi-axes |L|/I_i",
               ellipsoids.momentum_semi_axes, "rad/s");

    lab.section("4.1 the text's example I1 : I2 : I3 = 5 : 4 : 3");
    const Vector3d ratios(5, 4, 3);
    lab.result("ratios_momentum", "momentum ellipsoid 1/I_i (eq. 80)",
               rigid::momentum_ellipsoid_ratios(ratios), "",
               textbook_if(true, "(0.20 : 0.25 : 0.33)"));
    lab.result("ratios_energy", "energy ellipsoid 1/sqrt(I_i) (eq. 82)",
               rigid::energy_ellipsoid_ratios(ratios), "",
               textbook_if(true, "(0.44 : 0.50 : 0.58)"));
    lab.result("ratios_touching_axis1", "momentum, touching on axis 1",
               rigid::momentum_ratios_touching(ratios, 0), "",
               textbook_if(true, "(0.44 : 0.55 : 0.73)"));
    lab.result("ratios_touching_axis2", "momentum, touching on axis 2",
               rigid::momentum_ratios_touching(ratios, 1), "",
               textbook_if(true, "(0.40 : 0.50 : 0.66)"));
    lab.result("ratios_touching_axis3", "momentum, touching on axis 3",
               rigid::momentum_ratios_touching(ratios, 2), "",
               textbook_if(true, "(0.35 : 0.43 : 0.58)"));
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

    rigid::lab::Series series{
        {"t_s", "omega1", "omega2", "omega3", "qw", "qx", "qy", "qz", "energy_J", "L_kg_m2_s"}, {}};
    for (const auto& s : run.samples) {
      const auto& q = s.attitude;
      series.rows.push_back({s.t, s.omega_body(0), s.omega_body(1), s.omega_body(2), q.w(), q.x(),
                             q.y(), q.z(), rigid::kinetic_energy(I, s.omega_body),
                             rigid::angular_momentum_magnitude(I, s.omega_body)});
    }
    lab.series(std::move(series));

    lab.figures([&](Lab& lab) {
      rigid::lab::draw_poinsot_figures(lab, exact, omega0, run.samples, times, options);
    });
  });
}
