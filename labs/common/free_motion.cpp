#include "common/free_motion.h"

#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <string>
#include <tuple>
#include <utility>

#include "common/integrated_motion.h"
#include "rigid/free_body_integrate.h"
#include "rigid/racquet.h"
#include "rigid/units.h"

namespace rigid::lab {

namespace {

// A steady spin in words: about which axis, and whether a nudge grows.
std::pair<std::string, std::string> steady_in_words(const FreeBodyExact& motion) {
  const Eigen::Vector3d w = motion.omega_body(0.0), I = motion.moments().vector();
  if (w.isZero(0.0)) return {"at rest", "neutral"};
  if (I.minCoeff() == I.maxCoeff())
    return {"steady rotation of a spherical body: every axis is steady", "neutral"};
  Eigen::Index axis = 0;
  w.cwiseAbs().maxCoeff(&axis);
  const bool on_axis = (w.cwiseAbs().array() > 0.0).count() == 1;
  if (!on_axis) {
    // omega in the plane of two equal moments: every axis of that plane is principal
    return {"steady rotation about an axis of the plane of two equal moments", "neutral"};
  }
  const double Ii = I(axis);
  const int below = (I.array() < Ii).count(), above = (I.array() > Ii).count();
  const std::string name = fmt::format("axis {}", axis + 1);
  if (below > 0 && above > 0) {
    return {"steady rotation about the intermediate " + name +
                ": unstable, the least nudge grows and flips it (the tennis racquet theorem)",
            "unstable"};
  }
  if (below + above < 2) {
    return {"steady rotation about " + name + ", one of two equal moments: neutral", "neutral"};
  }
  return {"steady rotation about the " + std::string(above == 0 ? "largest " : "smallest ") + name +
              ": stable, a nudge only wobbles it",
          "stable"};
}

// The intermediate axis: the one whose moment lies strictly between the others; -1
// where two moments are equal.
int intermediate_axis(const Eigen::Vector3d& I) {
  int m = -1;
  for (int i = 0; i < 3; ++i) {
    if ((I.array() < I(i)).count() == 1 && (I.array() > I(i)).count() == 1) m = i;
  }
  return m;
}

// The rate fitted from launch until the disturbance is a tenth of omega (or twice
// its start): its deviation from the linear rate is of the order of that share
// squared (racquet.h). Where the start is already past it, there is no first growth.
void report_measured_growth(Report& report, const FreeBodyExact& motion, int m, double share,
                            const std::string& label) {
  const double share_limit = std::min(std::max(0.1, 2.0 * share), 0.5 * (1.0 + share));
  try {
    const GrowthFit fit = measure_growth_rate(motion, m, share_limit);
    report.result("growth_rate_measured_per_s", label, fit.rate, "1/s");
    report.remark(
        fmt::format("(t from {:.4g} to {:.4g} s, omega's share off the axis from "
                    "{:.2g} to {:.2g})",
                    fit.t_begin, fit.t_end, fit.share_begin, fit.share_end));
  } catch (const std::invalid_argument&) {
    report.result_none("growth_rate_measured_per_s", label, "1/s",
                       fmt::format("omega starts {:.2g} off the axis: too far for a first "
                                   "growth to fit",
                                   share));
  }
}

}  // namespace

void report_motion(Report& report, const FreeBodyExact& motion) {
  const FreeMotionRegime regime = motion.regime();
  report.result_text("regime", "motion", to_string(regime));
  std::string words, stability;
  if (regime == FreeMotionRegime::kSteady) {
    std::tie(words, stability) = steady_in_words(motion);
    report.result_none("complementary_parameter", "  k'^2", "", "a steady spin has no polhode");
  } else if (regime == FreeMotionRegime::kSeparatrix) {
    words =
        "on the separatrix: unstable, omega leaves the intermediate axis and only "
        "approaches it again, never returning";
    stability = "unstable";
    report.result("complementary_parameter", "  k'^2 (0: on the separatrix)", 0.0, "");
  } else {
    const double kp2 = motion.complementary_parameter();
    // k'^2 measures the distance to the separatrix; below 0.01 the period grows as
    // ln(4/k') and omega lingers by the intermediate axis between flips: the orbit of
    // a spin about that axis, nudged, whose fate a further nudge may change.
    if (kp2 < 0.01) {
      report.remark("(just outside the separatrix: the body flips, see below)");
      stability = "unstable";
      words = fmt::format(
          "near the separatrix (k'^2 = {:.2g}): unstable, omega lingers by the "
          "intermediate axis and the body flips over every {:.4g} s ({})",
          kp2, 0.5 * motion.period(), to_string(regime));
    } else {
      stability = "stable";
      words = to_string(regime) + ": stable, omega circles that axis";
    }
    report.result("complementary_parameter", "  k'^2 (1: far from the separatrix, 0: on it)", kp2,
                  "");
  }
  report.result_text("motion", "  in words", words);
  report.result_text("motion_stability", "  stability", stability);
}

void report_flips(Report& report, const FreeBodyExact& motion) {
  const Eigen::Vector3d I = motion.moments().vector(), w0 = motion.omega_body(0.0);
  const int m = intermediate_axis(I);
  const std::string axis = fmt::format("axis {}", m + 1);
  const std::string growth_label =
      m < 0 ? "growth rate of a nudge" : "growth rate of a nudge about " + axis + ", eqs. 86-88";
  const std::string measured_label = "  fitted to the exact motion's first growth";
  const std::string first_label = m < 0 ? "first flip"
                                        : fmt::format(
                                              "first flip: omega_{} "
                                              "changes sign",
                                              m + 1);
  const std::string interval_label = "time between flips: half the polhode period";
  const auto none = [&](const std::string& why) {
    report.result_none("first_flip_s", first_label, "s", why);
    report.result_none("flip_interval_s", interval_label, "s", why);
  };
  if (m < 0) {
    const std::string why = "two equal moments: no intermediate axis to flip about";
    report.result_none("growth_rate_per_s", growth_label, "1/s", why);
    report.result_none("growth_rate_measured_per_s", measured_label, "1/s", why);
    none(why);
    return;
  }
  const double spin = w0(m);
  const SpinStability linear = linear_stability(euler_coefficients(motion.moments()), m, spin);
  report.result("growth_rate_per_s", growth_label, linear.rate, "1/s");
  report.remark(fmt::format("(from omega_{}(0) = {:.6g} rad/s)", m + 1, spin));
  // Flips: omega_m changes sign, which needs the polhode to pass the intermediate axis's
  // side of the separatrix, i.e. the spin mostly about m. A spin mostly about the largest
  // or smallest axis only wobbles, though omega_m changes sign there too.
  const double share = transverse_share(w0, m);
  const FreeMotionRegime regime = motion.regime();
  const bool near = regime != FreeMotionRegime::kSteady &&
                    regime != FreeMotionRegime::kSeparatrix &&
                    motion.complementary_parameter() < 0.01;
  if (regime == FreeMotionRegime::kSteady) {
    const std::string why = share == 0.0 ? "exactly on the axis: no nudge to grow, it never flips"
                                         : "a steady spin: it does not flip";
    report.result_none("growth_rate_measured_per_s", measured_label, "1/s", why);
    none(why);
    return;
  }
  if (regime == FreeMotionRegime::kSeparatrix) {
    const std::string why = "on the separatrix: omega leaves the axis and never returns past it";
    report.result_none("growth_rate_measured_per_s", measured_label, "1/s", why);
    none(why);
    return;
  }
  if (!near) {
    const std::string why =
        fmt::format("not spun near {}: a {}, omega circles that axis: a wobble, not a flip", axis,
                    to_string(regime));
    report.result_none("growth_rate_measured_per_s", measured_label, "1/s", why);
    none(why);
    return;
  }
  report_measured_growth(report, motion, m, share, measured_label);
  report.result("first_flip_s", first_label, first_sign_change(motion, m), "s");
  report.result("flip_interval_s", interval_label, 0.5 * motion.period(), "s");
}

double time_scale(const FreeBodyExact& motion) {
  return std::isfinite(motion.period()) ? motion.period()
                                        : 2.0 * kPi / motion.omega_body(0.0).norm();
}

const ExactErrorWords& free_body_words() {
  static const ExactErrorWords words = [] {
    ExactErrorWords w;
    w.key = "max_error_vs_exact";
    w.label = "max |omega - omega_exact| / |omega0|";
    w.method_key_prefix = "max_error_";
    w.against = "the exact solution";
    w.diverged = "the integration diverged (omega overflowed); shorten the step";
    w.runaway_invariants = 2;  // T and |L|
    w.invariants = {
        {FreeBodyProblem::kEnergy, "energy", "max |T - T0| / T0"},
        {FreeBodyProblem::kMomentum, "momentum", "max ||L| - |L0|| / |L0|"},
        {FreeBodyProblem::kLSpace, "L_space_drift_rel", "max |L_space - L_space0| / |L0|", false}};
    return w;
  }();
  return words;
}

BodyMotion free_body_motion(const FreeBodyExact& exact, const std::optional<OdeOptions>& integrator,
                            const std::vector<FreeBodyRun::Sample>& samples) {
  if (!integrator) {
    return keeping_samples(
        [exact](double t) {
          if (!(t >= 0.0)) refuse_before_start(t);
          const RotationState x = exact.state(t);
          return BodyState{attitude(x), omega_body(x)};
        },
        samples);
  }
  const auto integrated = std::make_shared<const IntegratedMotion<FreeBodyProblem>>(
      FreeBodyProblem(exact.moments()), exact.state(0.0), *integrator,
      free_body_words().runaway_invariants, samples, std::vector<double>{});
  return [integrated](double t) {
    const RotationState x = integrated->state(t);
    return BodyState{attitude(x), omega_body(x)};
  };
}

}  // namespace rigid::lab
