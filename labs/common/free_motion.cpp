#include "common/free_motion.h"

#include <fmt/format.h>

#include <cmath>
#include <string>
#include <tuple>
#include <utility>

#include "rigid/free_body_integrate.h"
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

}  // namespace rigid::lab
