// tennis_racquet: section 4.1, "The Tennis Racquet Theorem" (eqs. 83-103). A
// racquet spun about the handle (1) or about the normal to its face (3) keeps
// spinning with a small wobble; spun about the axis in its plane across the
// handle (2), the intermediate moment, a small disturbance grows until the
// racquet turns over, and it keeps turning over at regular intervals. The model
// of Figure 5 is a ring (the head) and a rod (the handle); its motion is the
// exact torque-free solution, with an integrator as the cross-check.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <optional>

#include "common/free_body_run.h"
#include "common/lab.h"
#include "figures.h"
#include "rigid/racquet.h"
#include "rigid/units.h"

using Eigen::Vector2d;
using Eigen::Vector3d;
using rigid::lab::Lab;

namespace {

// A run longer than this many steps is refused rather than left to hang.
constexpr std::size_t kMaxSteps = 20'000'000;
const char* const kAxisNames[] = {"1 (the handle)", "2 (in the plane, across the handle)",
                                  "3 (normal to the face)"};

}  // namespace

int main(int argc, char** argv) {
  Lab lab("tennis_racquet",
          "the tennis racquet theorem: the flip about the intermediate axis "
          "(section 4.1)");
  rigid::lab::tennis_racquet::Inputs in;
  lab.number("--head-mass", in.head_mass, "mass m_a of the head, a ring")
      .unit("kg")
      .positive()
      .symbol("m_a");
  lab.number("--head-radius", in.head_radius, "radius a of the head")
      .unit("m")
      .positive()
      .symbol("a");
  lab.number("--handle-mass", in.handle_mass, "mass m_l of the handle, a thin rod")
      .unit("kg")
      .positive()
      .symbol("m_l");
  lab.number("--handle-length", in.handle_length, "length l of the handle")
      .unit("m")
      .positive()
      .symbol("l");
  lab.choice("--spin-axis", in.spin_axis, {"1", "2", "3"},
             "principal axis of the spin: 1 handle, 2 in the plane, 3 normal to the face")
      .symbol("axis");
  lab.number("--omega", in.omega, "the spin |omega| at launch")
      .unit("rad/s")
      .positive()
      .symbol("\\omega");
  lab.number("--perturbation", in.perturbation,
             "transverse share of omega at launch, along the next axis (1->2, 2->3, 3->1)")
      .open_range(0.0, 0.5)
      .symbol("\\epsilon");
  rigid::lab::declare_end_time(lab, in.t_end, in.periods, "polhode period",
                               "one polhode period of the spin about axis 2: two flips");
  rigid::lab::declare_integration_options(lab, in.integration,
                                          "the integrator that cross-checks the exact motion "
                                          "(exact: none)",
                                          "polhode period / 2000");
  lab.enable_csv();
  lab.enable_animation();

  return lab.run(argc, argv, [&](Lab& lab) {
    const rigid::Racquet racquet = rigid::lab::for_option("--head-mass", [&] {
      return rigid::make_racquet({in.head_mass, in.head_radius, in.handle_mass, in.handle_length});
    });
    const rigid::PrincipalMoments& I = racquet.moments;

    lab.section("4.1 the model racquet of Figure 5: a ring and a rod (eqs. 83-85)");
    lab.result("cm_offset_m", "R, centre of mass from the head's centre (eq. 83)",
               racquet.cm_offset, "m", lab.textbook("0.175"));
    lab.result("principal_moments", "I1 (handle), I2 (in the plane), I3 (normal) (eqs. 84-85)",
               Vector3d(I.vector()), "kg m^2", lab.textbook("(1.27e-3, 11.81e-3, 13.08e-3)"));
    lab.result("perpendicular_axis_ratio", "I3 / (I1 + I2), a lamina's 1", I.I3 / (I.I1 + I.I2),
               "");

    lab.section(
        fmt::format("4.1.1-4.1.2 a spin omega = {:g} rad/s about each axis, "
                    "to first order (eqs. 86-103)",
                    in.omega));
    const rigid::EulerCoefficients full = rigid::euler_coefficients(I);
    const rigid::EulerCoefficients text = rigid::simplified_racquet_coefficients();
    std::array<rigid::SpinStability, 3> predicted, simplified;
    for (int axis = 0; axis < 3; ++axis) {
      predicted[axis] = rigid::linear_stability(full, axis, in.omega);
      simplified[axis] = rigid::linear_stability(text, axis, in.omega);
    }
    lab.result("growth_rate_per_s", "axis 2: growth rate, eqs. 86-88 in full", predicted[1].rate,
               "1/s");
    lab.result("growth_rate_textbook_per_s", "axis 2: growth rate, eq. 92 (omega_2)",
               simplified[1].rate, "1/s", lab.textbook("omega_2 (eqs. 100-101)"));
    lab.result("wobble_frequencies_rad_s", "axes 1, 3: wobble frequency, eqs. 86-88 in full",
               Vector2d(predicted[0].rate, predicted[2].rate), "rad/s");
    lab.result("wobble_frequencies_textbook_rad_s", "axes 1, 3: wobble frequency, eq. 92",
               Vector2d(simplified[0].rate, simplified[2].rate), "rad/s",
               lab.textbook("(omega_1, omega_3) (eq. 95)"));
    const Vector2d ratios(predicted[0].axis_ratio, predicted[2].axis_ratio);
    const std::string ratios_label =
        "axes 1, 3: |omega_2|/|omega_3|, |omega_1|/|omega_2| of the wobble";
    if (ratios.allFinite()) {
      lab.result("ellipse_axis_ratios", ratios_label, ratios, "");
    } else {
      lab.result_none("ellipse_axis_ratios", ratios_label, "",
                      "two moments equal to double precision: no wobble to shape");
    }

    // The same disturbance for each axis; the exact motion of each launch.
    const std::array<rigid::FreeBodyExact, 3> launches = {
        rigid::FreeBodyExact(I, rigid::launch_omega(0, in.omega, in.perturbation)),
        rigid::FreeBodyExact(I, rigid::launch_omega(1, in.omega, in.perturbation)),
        rigid::FreeBodyExact(I, rigid::launch_omega(2, in.omega, in.perturbation))};
    // The fit runs from launch until the disturbance reaches a tenth of omega (or
    // twice its start, if that is larger): its deviation from the linear rate is
    // of the order of the share squared (racquet.h).
    const double share_limit =
        std::min(std::max(0.1, 2.0 * in.perturbation), 0.5 * (1.0 + in.perturbation));
    // A racquet whose moments coincide to double precision (a ring with a handle of
    // 1e-60 kg, say) does not flip: there is then no growth to measure.
    const bool flips = std::isfinite(rigid::first_sign_change(launches[1], 1));
    const std::optional<rigid::GrowthFit> growth =
        flips ? std::optional(rigid::measure_growth_rate(launches[1], 1, share_limit))
              : std::nullopt;

    lab.section(
        fmt::format("measured on the exact motion, launched with {:g} of omega along the "
                    "next axis",
                    in.perturbation));
    const char* measured = "axis 2: growth rate fitted to the exact omega_1, omega_3";
    if (growth) {
      lab.result("growth_rate_measured_per_s", measured, growth->rate, "1/s");
      lab.result("growth_fit_interval_s", "  fitted over t from, to",
                 Vector2d(growth->t_begin, growth->t_end), "s");
      lab.result("growth_fit_shares", "  transverse share of omega at the interval's ends",
                 Vector2d(growth->share_begin, growth->share_end), "");
    } else {
      lab.result_none(
          "growth_rate_measured_per_s", measured, "1/s",
          "the spin about 2 does not flip: I1, I2, I3 not distinct to double precision");
    }
    lab.result(
        "wobble_frequencies_measured_rad_s", "axes 1, 3: 2 pi / polhode period",
        Vector2d(2 * rigid::kPi / launches[0].period(), 2 * rigid::kPi / launches[2].period()),
        "rad/s");

    const int axis = in.spin_axis[0] - '1';
    const rigid::FreeBodyExact& motion = launches[axis];
    lab.section(fmt::format("the spin about axis {}", kAxisNames[axis]));
    lab.result_text(
        "stability", "first order",
        predicted[axis].unstable ? "unstable: the disturbance grows" : "stable: a wobble");
    rigid::lab::report_motion(lab, motion);
    if (std::isfinite(motion.period())) {
      lab.result("polhode_period_s", "polhode period", motion.period(), "s");
    } else {
      lab.result_none("polhode_period_s", "polhode period", "s", "no polhode to go round");
    }
    const double first_flip = rigid::first_sign_change(motion, axis);
    if (std::isfinite(first_flip)) {
      lab.result("first_flip_s", "first flip: omega_2 changes sign", first_flip, "s");
      lab.result("flip_interval_s", "time between flips: half the period of omega_2",
                 0.5 * motion.period(), "s");
    } else {
      lab.result_none("first_flip_s", "first flip", "s", "stable: it does not flip");
      lab.result_none("flip_interval_s", "time between flips", "s", "stable: it does not flip");
    }
    // The handle stays near the plane across L (spins about 2 and 3) or near L (about 1).
    // Over a polhode period, or over the run where there is none (the separatrix).
    const double scale = rigid::lab::time_scale(motion);
    const double t_end =
        rigid::lab::end_time(lab, in.t_end, in.periods, scale, rigid::lab::time_scale(launches[1]));
    const rigid::CosineRange handle = rigid::direction_cosine_range(
        motion, 0, std::isfinite(motion.period()) ? motion.period() : t_end);
    const double handle_max = std::max(std::abs(handle.min), std::abs(handle.max));
    const double handle_min = handle.min <= 0 && handle.max >= 0
                                  ? 0.0
                                  : std::min(std::abs(handle.min), std::abs(handle.max));
    const double excursion =
        axis == 0 ? std::acos(std::min(handle_min, 1.0)) : std::asin(std::min(handle_max, 1.0));
    lab.result("handle_excursion_max_deg",
               axis == 0 ? "largest angle of the handle from L"
                         : "largest angle of the handle out of the plane across L",
               rigid::rad_to_deg(excursion), "deg");

    // Two flips: one polhode period of the spin about 2 (its time scale, if it does not flip).
    const rigid::lab::RunPlan plan =
        rigid::lab::plan_run(lab, in.integration, t_end, scale, kMaxSteps);
    lab.section(fmt::format("cross-check: {} to t_end = {:g} s", in.integration.method, t_end));
    rigid::lab::report_plan(lab, plan);
    const rigid::IntegrationResult run =
        rigid::lab::run_free_body(lab, motion, in.integration, plan.options, plan.times);
    rigid::lab::report_drifts(lab, run, scale, in.integration.method == "exact");

    if (predicted[1].rate != simplified[1].rate) {
      lab.note(fmt::format(
          "errata: eq. 92 sets (I2 - I1)/(I2 + I1) = {:.4f} to 1, and with it every rate to the "
          "spin. In full (eqs. 86-88), about axis 2 the disturbance grows at omega sqrt((I2 - "
          "I1)(I3 - I2)/(I1 I3)) = {:.6g} 1/s, not omega = {:.6g} 1/s; about axis 1 it goes round "
          "at {:.6g} rad/s, not {:.6g}, {}, not the circle of eqs. 96-97. About axis 3 the rate "
          "omega_3 and the circle are exact for a lamina.",
          (I.I2 - I.I1) / (I.I2 + I.I1), predicted[1].rate, simplified[1].rate, predicted[0].rate,
          simplified[0].rate,
          std::isfinite(predicted[0].axis_ratio)
              ? fmt::format("on an ellipse (|omega_2|/|omega_3| = {:.4f})", predicted[0].axis_ratio)
              : std::string("with omega_3 still (I1 = I2 to double precision)")));
    }
    if (in.perturbation > 0.05) {
      lab.note(
          fmt::format("The disturbance at launch ({:g} of omega) is not small: the linear "
                      "rates describe only its start, and the fit runs to a share of {:g}.",
                      in.perturbation, share_limit));
    }
    lab.note(
        "Section 4.1's ratios of the ellipsoids for I1 : I2 : I3 = 5 : 4 : 3 are the poinsot "
        "lab's (results ratios_*); they are not repeated here.");

    rigid::lab::TimeSeries series{{"t_s", "omega1", "omega2", "omega3", "qw", "qx", "qy", "qz",
                                   "omega1_integrated", "omega2_integrated", "omega3_integrated"},
                                  {}};
    for (const rigid::FreeBodySample& s : run.samples) {
      const rigid::FreeBodyState x = motion.state(s.t);
      series.rows.push_back({s.t, x[0], x[1], x[2], x[3], x[4], x[5], x[6], s.omega_body(0),
                             s.omega_body(1), s.omega_body(2)});
    }
    lab.series(std::move(series));

    // Frames from the exact motion, or, when --method names an integrator, from it sampled
    // at exactly the animation's times (never at its steps); the cross-check's default
    // method alone does not replace the exact motion
    std::map<double, rigid::FreeBodyState> states;
    if (lab.animating() && lab.given("--method") && in.integration.method != "exact") {
      const rigid::IntegrationResult frames = rigid::lab::run_free_body(
          lab, motion, in.integration, plan.options, lab.animation_times(t_end));
      for (const rigid::FreeBodySample& s : frames.samples)
        states[s.t] = rigid::make_state(s.omega_body, s.attitude);
    }
    lab.animate(
        t_end, "the racquet turning in space, omega's components below",
        [&](double t) {
          return rigid::lab::tennis_racquet::spin_scene(
              racquet, motion, axis, t,
              states.empty() ? std::function<rigid::FreeBodyState(double)>()
                             : [&states](double s) { return states.at(s); });
        },
        [&](double t) { return rigid::lab::tennis_racquet::omega_strip(motion, t_end, t); }, 0.3);

    lab.figures([&](rigid::lab::FigureSet& set) {
      rigid::lab::tennis_racquet::draw(set, {racquet, launches, predicted, simplified[1].rate,
                                             growth ? &*growth : nullptr, t_end, axis});
    });
  });
}
