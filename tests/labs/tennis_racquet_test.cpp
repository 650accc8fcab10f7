// tennis_racquet's library in-process: the text's racquet (eqs. 83-85) and its flip
// about axis 2, the stable spins about 1 and 3, another racquet against eqs. 83-101
// typed here, every integrator's cross-check, the time series --csv writes, the
// rules compute() checks, and the motion sampled in any order.
#include "tennis_racquet/tennis_racquet.h"

#include <fmt/format.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cfloat>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "lab_library.h"

using rigid::lab::InputError;
using rigid::lab::tennis_racquet::compute;
using rigid::lab::tennis_racquet::Inputs;
using rigid::lab::tennis_racquet::Motion;
using rigid::test::check_same_scene;
using rigid::test::contains;
using rigid::test::element;
using rigid::test::kRoundoff;
using rigid::test::names_input;
using rigid::test::prints_as;
using rigid::test::value;

namespace {

// The text's racquet, written out from eqs. 83-85 (independent of core's primitives).
struct TextRacquet {
  double ma = 0.15, a = 0.13, ml = 0.18, l = 0.38;
  double R = ml * (a + l / 2) / (ma + ml);
  double I1 = ma * a * a / 2;
  double I2 =
      ma * a * a / 2 + ma * R * R + ml * l * l / 12 + ml * (a + l / 2 - R) * (a + l / 2 - R);
  double I3 = I1 + I2;
};

Inputs with_method(const std::string& method) {
  Inputs in;
  in.integration.method = method;
  return in;
}

// The defaults with `change` made.
template <class Change>
Inputs changed(Change change) {
  Inputs in;
  change(in);
  return in;
}

}  // namespace

TEST_CASE("tennis_racquet: defaults reproduce eqs. 83-85 and the flip about axis 2") {
  const auto report = compute(Inputs{});
  const auto& r = report.results();
  const TextRacquet t;
  // The printed 0.175 m, 1.27, 11.81 and 13.08 x 10^-3 kg m^2, to their last digit.
  CHECK(prints_as(value(r, "cm_offset_m"), 0.175, 3));
  CHECK(prints_as(element(r, "principal_moments", 0) * 1e3, 1.27, 2));
  CHECK(prints_as(element(r, "principal_moments", 1) * 1e3, 11.81, 2));
  CHECK(prints_as(element(r, "principal_moments", 2) * 1e3, 13.08, 2));
  // And to roundoff against the formulas written out.
  CHECK(value(r, "cm_offset_m") == Approx(t.R).epsilon(kRoundoff));
  CHECK(element(r, "principal_moments", 1) == Approx(t.I2).epsilon(kRoundoff));
  CHECK(report.textbook_printed().at("cm_offset_m") == "0.175");
  // Linear rates: axis 2 grows at omega_2 sqrt((I3 - I2)(I2 - I1)/(I1 I3)); eq. 92 says
  // omega_2: the spin's component, launched with 0.01 of |omega| = 10 rad/s off the axis.
  const double omega = 10 * std::sqrt(1 - 0.01 * 0.01);
  const double growth = omega * std::sqrt((t.I3 - t.I2) * (t.I2 - t.I1) / (t.I1 * t.I3));
  CHECK(value(r, "growth_rate_per_s") == Approx(growth).epsilon(16 * DBL_EPSILON));
  CHECK(value(r, "growth_rate_textbook_per_s") == Approx(omega).epsilon(kRoundoff));
  CHECK(
      element(r, "wobble_frequencies_rad_s", 0) ==
      Approx(omega * std::sqrt((t.I3 - t.I1) * (t.I2 - t.I1) / (t.I2 * t.I3))).epsilon(kRoundoff));
  CHECK(element(r, "wobble_frequencies_rad_s", 1) == Approx(omega).epsilon(16 * DBL_EPSILON));
  CHECK(report.units().at("growth_rate_per_s") == "1/s");
  CHECK(report.units().at("cm_offset_m") == "m");
  // Measured on the exact motion up to a share of 0.1: below the linear rate by less
  // than 0.1^2 / 2 of it (the nonlinear terms, racquet.h).
  // (I3 - I2 is a tenth of I3: its rounding, amplified tenfold, halved by the root.)
  const double measured = value(r, "growth_rate_measured_per_s");
  CHECK(measured < growth);
  CHECK(measured > growth * (1 - 0.005));
  CHECK(element(r, "growth_fit_shares", 1) == Approx(0.1).epsilon(32 * DBL_EPSILON));
  // Wobbles measured from the exact polhode periods: O(p^2) = 1e-4 from the linear ones.
  CHECK(element(r, "wobble_frequencies_measured_rad_s", 0) ==
        Approx(element(r, "wobble_frequencies_rad_s", 0)).epsilon(1e-4));
  CHECK(element(r, "wobble_frequencies_measured_rad_s", 1) ==
        Approx(element(r, "wobble_frequencies_rad_s", 1)).epsilon(1e-4));
  // Flips every half-period of omega_2; the first a quarter-period after launch (omega_2 at its
  // peak).
  const double period = value(r, "polhode_period_s");
  CHECK(value(r, "flip_interval_s") == Approx(period / 2).epsilon(kRoundoff));
  CHECK(value(r, "first_flip_s") == Approx(period / 4).epsilon(kRoundoff));
  // The handle tilts out of the plane across L by at most asin(L1/|L|) at L_2 = 0:
  // L1^2 = I1 (2T I3 - L^2)/(I3 - I1), with omega0 = 10 (0, sqrt(1 - p^2), p).
  const double p = 0.01, w2 = omega * std::sqrt(1 - p * p), w3 = omega * p;
  const double T2 = t.I2 * w2 * w2 + t.I3 * w3 * w3;
  const double L2 = t.I2 * t.I2 * w2 * w2 + t.I3 * t.I3 * w3 * w3;
  const double excursion = std::asin(std::sqrt(t.I1 * (T2 * t.I3 - L2) / ((t.I3 - t.I1) * L2)));
  CHECK(value(r, "handle_excursion_max_deg") ==
        Approx(excursion * 180 / M_PI).epsilon(16 * DBL_EPSILON));
  // The cross-check: dopri5 at 1e-10 over one period, measured 1.8e-9 from the exact omega
  // (the tolerance is per step; ~20 steps' worth accumulate).
  CHECK(value(r, "max_error_vs_exact") < 1e-8);
  CHECK(value(r, "t_end_s") == period);
  // Eq. 92's errata, with the rates written out above in their places.
  const auto errata = rigid::test::notes_starting(
      report,
      "errata: section 4.1, eq. 92: the text prints \"For the tennis racquet model I2 >> I1, so "
      "the last equation is approximately omega_3_dot + omega_1 omega_2 = 0\"; ");
  REQUIRE(errata.size() == 1);
  REQUIRE(report.errata().size() == 1);
  CHECK(report.errata()[0].where == "section 4.1, eq. 92");
  CHECK(errata[0] == "errata: section 4.1, eq. 92: the text prints \"" +
                         report.errata()[0].printed + "\"; " + report.errata()[0].correction);
  const double wobble1 = omega * std::sqrt((t.I3 - t.I1) * (t.I2 - t.I1) / (t.I2 * t.I3));
  CHECK(rigid::test::contains(
      errata[0],
      fmt::format("\"; it sets (I2 - I1)/(I2 + I1) = {:.4f} to 1", (t.I2 - t.I1) / (t.I2 + t.I1))));
  CHECK(rigid::test::contains(
      errata[0], fmt::format("= {:.6g} 1/s, not omega = {:.6g} 1/s; about axis 1 it goes round at "
                             "{:.6g} rad/s, not {:.6g},",
                             growth, omega, wobble1, omega)));
}

TEST_CASE("tennis_racquet: spins about axes 1 and 3 are stable and do not flip") {
  for (const char* axis : {"1", "3"}) {
    INFO("axis " << axis);
    Inputs in;
    in.spin_axis = axis;
    const auto report = compute(in);
    const auto& r = report.results();
    CHECK(r.at("flip_interval_s").is_null());
    CHECK(r.at("first_flip_s").is_null());
    CHECK(r.at("stability") == "stable: a wobble");
    // The launch (omega_1 = 0 about 3, omega_3 = 0 about 1) is where the handle is
    // furthest: about 1, from L by atan(I2 p / (I1 sqrt(1 - p^2))) (5.3 deg, as I2 >> I1);
    // about 3, out of the plane across L by atan(I1 p / (I3 sqrt(1 - p^2))).
    const TextRacquet t;
    const double p = 0.01, c = std::sqrt(1 - p * p);
    const double expected =
        axis[0] == '1' ? std::atan(t.I2 * p / (t.I1 * c)) : std::atan(t.I1 * p / (t.I3 * c));
    CHECK(value(r, "handle_excursion_max_deg") ==
          Approx(expected * 180 / M_PI).epsilon(32 * DBL_EPSILON));
    // The run spins about the axis asked: the polhode period is 2 pi over the measured wobble.
    const int k = axis[0] == '1' ? 0 : 1;
    CHECK(value(r, "polhode_period_s") ==
          Approx(2 * M_PI / element(r, "wobble_frequencies_measured_rad_s", k)).epsilon(kRoundoff));
    // --spin-axis is physical: no textbook column.
    CHECK(report.textbook_printed().empty());
  }
}

// The numbers of lab_test.cpp's "--csv holds the exact motion and the integrator's omega
// beside it"; the file itself (written, read back) stays a process test.
TEST_CASE("tennis_racquet: the time series holds the exact motion and the integrator's omega") {
  Inputs in = with_method("rkf78");
  in.integration.tolerance = 1e-12;
  const auto report = compute(in);
  const double t_end = value(report.results(), "t_end_s");
  const auto& series = report.time_series();
  std::string header;
  for (const std::string& column : series.names()) header += (header.empty() ? "" : ",") + column;
  CHECK(header ==
        "t_s,omega1,omega2,omega3,qw,qx,qy,qz,omega1_integrated,omega2_integrated,"
        "omega3_integrated");
  std::size_t rows = 0;
  double last_t = -1, worst = 0, worst_norm = 0;
  for (const std::vector<double>& v : series.rows) {
    REQUIRE(v.size() == 11);
    ++rows;
    last_t = v[0];
    // |omega| of a free racquet is not constant, but T and |L| are; the unit quaternion is unit.
    worst_norm = std::max(worst_norm,
                          std::abs(std::hypot(std::hypot(v[4], v[5]), std::hypot(v[6], v[7])) - 1));
    for (int i = 1; i <= 3; ++i) worst = std::max(worst, std::abs(v[i] - v[i + 7]));
  }
  CHECK(rows > 100);
  CHECK(last_t == t_end);
  CHECK(worst_norm < 8 * DBL_EPSILON);
  // rkf78 at 1e-12 over one period: the integrated omega within 5e-10 rad/s of the exact
  // (measured 8.4e-11).
  CHECK(worst < 5e-10);
}

TEST_CASE("tennis_racquet: every integrator cross-checks the exact motion within its tolerance") {
  const std::pair<const char*, double> methods[] = {
      // Adaptive at 1e-10 over one period; fixed steps at period/2000: rk4's error
      // (h lambda)^4 ~ 1e-10 per unit time, the splitting's (h lambda)^2 ~ 1e-5.
      {"dopri5", 1e-7}, {"rkf78", 1e-7},     {"bulirsch-stoer", 1e-6},
      {"rk4", 1e-7},    {"splitting", 1e-3}, {"splitting4", 1e-7},
  };
  for (const auto& [method, bound] : methods) {
    INFO(method);
    const auto report = compute(with_method(method));
    const auto& r = report.results();
    CHECK(value(r, "max_error_vs_exact") < bound);
    CHECK(value(r, "energy_drift_rel") < bound);
  }
}

TEST_CASE("tennis_racquet: another racquet against eqs. 83-85 and 94-101 typed here") {
  const double ma = 0.2, a = 0.15, ml = 0.1, l = 0.3, omega = 7;
  Inputs in;
  in.head_mass = ma, in.head_radius = a, in.handle_mass = ml, in.handle_length = l;
  in.omega = omega;
  const auto report = compute(in);
  const auto& r = report.results();
  const double R = ml * (a + l / 2) / (ma + ml);  // eq. 83: the centre of mass from the head's
  CHECK(value(r, "cm_offset_m") == Approx(R).epsilon(kRoundoff));
  const double I1 = ma * a * a / 2;  // eq. 84
  const double I2 = ma * a * a / 2 + ma * R * R + ml * l * l / 12 +
                    ml * (a + l / 2 - R) * (a + l / 2 - R);  // eq. 85
  const double I3 = I1 + I2;
  CHECK(element(r, "principal_moments", 0) == Approx(I1).epsilon(kRoundoff));
  CHECK(element(r, "principal_moments", 1) == Approx(I2).epsilon(kRoundoff));
  CHECK(element(r, "principal_moments", 2) == Approx(I3).epsilon(kRoundoff));
  // Linearised Euler equations about each axis (eqs. 94-101 without eq. 92's rounding),
  // at the spin's own component, sqrt(1 - p^2) of |omega| (p = 0.01 off the axis).
  const double spin = omega * std::sqrt(1 - 0.01 * 0.01);
  CHECK(value(r, "growth_rate_per_s") ==
        Approx(spin * std::sqrt((I2 - I1) * (I3 - I2) / (I1 * I3))).epsilon(kRoundoff));
  CHECK(element(r, "wobble_frequencies_rad_s", 0) ==
        Approx(spin * std::sqrt((I2 - I1) * (I3 - I1) / (I2 * I3))).epsilon(kRoundoff));
  CHECK(element(r, "wobble_frequencies_rad_s", 1) ==
        Approx(spin * std::sqrt((I3 - I1) * (I3 - I2) / (I1 * I2))).epsilon(kRoundoff));
  // The launch: omega = 7 (0, sqrt(1 - p^2), p), p = 0.01 along axis 3; its period by Landau.
  const double p = 0.01, w[3] = {0, omega * std::sqrt(1 - p * p), omega * p}, Is[3] = {I1, I2, I3};
  double E2 = 0, L2 = 0;
  for (int i = 0; i < 3; ++i) E2 += Is[i] * w[i] * w[i], L2 += Is[i] * Is[i] * w[i] * w[i];
  REQUIRE(L2 > E2 * I2);  // about the largest axis
  const double rate = std::sqrt((I3 - I2) * (L2 - E2 * I1) / (I1 * I2 * I3));
  const double k2 = (I2 - I1) * (E2 * I3 - L2) / ((I3 - I2) * (L2 - E2 * I1));
  // Near the separatrix (k'^2 ~ p^2) K is conditioned by ~1/k'^2 ~ 1e4: 1e-11.
  CHECK(value(r, "polhode_period_s") ==
        Approx(4 * std::comp_ellint_1(std::sqrt(k2)) / rate).epsilon(2e-12));
  // The spin flips every half period, the first a quarter period in (launched at sn = 0).
  CHECK(value(r, "flip_interval_s") == Approx(value(r, "polhode_period_s") / 2).epsilon(kRoundoff));
}

// tennis_racquet's cases of lab_test.cpp's "labs: extreme but legal inputs end with finite
// numbers or one line, never a crash": a report (whose numbers are finite, or it would have
// refused) or an error naming an input, never a crash.
TEST_CASE("tennis_racquet: extreme but legal inputs give a report or an InputError") {
  // moments equal to double precision (head, handle, heavy head): no flip, no growth to measure
  const Inputs head = changed([](Inputs& in) { in.head_mass = 1e-60; });
  const Inputs cases[] = {changed([](Inputs& in) { in.t_end = 1e-60; }),
                          changed([](Inputs& in) { in.omega = 1e30; }), head,
                          changed([](Inputs& in) { in.handle_length = 1e60; }),
                          changed([](Inputs& in) { in.head_mass = 1e60, in.handle_mass = 1e-60; })};
  for (const Inputs& in : cases) {
    try {
      const auto report = compute(in);
      CHECK(report.results().is_object());
      for (const auto& [key, result] : report.results().items()) {
        INFO(key);
        if (result.is_number()) CHECK(std::isfinite(result.get<double>()));
      }
    } catch (const InputError& e) {
      SUCCEED(e.what());
    }
  }
  // Those without a flip say so rather than measure a growth.
  const auto no_flip = compute(head);
  CHECK(no_flip.results().at("growth_rate_measured_per_s").is_null());
  CHECK(!no_flip.growth);
}

// tennis_racquet's part of lab_test.cpp's "labs: an option the method does not use is said
// so, once the run succeeds" (the stderr line is the command's).
TEST_CASE("tennis_racquet: an option the method does not use is warned of") {
  Inputs in = with_method("rk4");
  in.integration.tolerance = 1e-6;
  const auto report = compute(in);
  CHECK(report.warnings() ==
        std::vector<std::string>{"--tolerance: rk4 takes a fixed step; it is not used "
                                 "(--step sets it)"});
  bool noted = false;
  for (const auto& note : report.notes()) noted |= note.rfind("warning:", 0) == 0;
  CHECK(noted);
  CHECK(compute(Inputs{}).warnings().empty());
}

TEST_CASE("tennis_racquet: a broken rule is an InputError naming the input") {
  const auto refused = [](const Inputs& in, const std::string& input) {
    INFO(input);
    CHECK_THROWS_MATCHES(compute(in), InputError, names_input(input));
  };
  for (const char* axis : {"4", "0", ""}) {
    refused(changed([axis](Inputs& in) { in.spin_axis = axis; }), "--spin-axis");
  }
  for (const double p : {1e-61, 0.5, std::nan(""), -0.1}) {
    refused(changed([p](Inputs& in) { in.perturbation = p; }), "--perturbation");
  }
  refused(changed([](Inputs& in) { in.head_mass = -1; }), "--head-mass");
  refused(changed([](Inputs& in) { in.head_radius = 0; }), "--head-radius");
  refused(changed([](Inputs& in) { in.handle_mass = INFINITY; }), "--handle-mass");
  refused(changed([](Inputs& in) { in.omega = 0; }), "--omega");
  refused(changed([](Inputs& in) { in.t_end = -1; }), "--t-end");
  refused(changed([](Inputs& in) { in.t_end = 1, in.periods = 2; }), "--periods");
  Inputs in = with_method("dopri5");
  in.integration.project = true;
  refused(in, "--project");
  in = with_method("rk4");
  in.integration.step = 1e-9;
  refused(in, "--step");
  in = with_method("nonesuch");
  refused(in, "--method");
  // contract_test.cpp's "a tolerance below double precision is refused, not a crash"
  in = Inputs{};
  in.integration.tolerance = 1e-183;
  refused(in, "--tolerance");
  // contract_test.cpp's "a step asked for that is longer than the run is refused"
  in = with_method("rk4");
  in.integration.step = 100, in.t_end = 1;
  refused(in, "--step");
  try {
    compute(in);
  } catch (const InputError& e) {
    CHECK(e.rule.rfind("100 s is longer than the run", 0) == 0);
  }
}

TEST_CASE("tennis_racquet: what a run's inputs and method leave for its motion") {
  // Given an end time, the run records it; its default's end is one polhode period of axis 2.
  Inputs in;
  in.periods = 2;
  in.spin_axis = "1";
  const auto two = compute(in);
  CHECK(two.inputs().at("periods") == 2.0);
  CHECK(!two.inputs().contains("t_end"));
  CHECK(two.t_end == Approx(2 * value(two.results(), "polhode_period_s")).epsilon(kRoundoff));
  CHECK(two.spin_axis == 0);
  // The cross-check's default method checks the closed form but does not replace it in
  // the motion; another method does, and the closed form is its own.
  CHECK(!compute(Inputs{}).drawn_integrator);
  CHECK(!compute(with_method("exact")).drawn_integrator);
  const auto rk4 = compute(with_method("rk4"));
  REQUIRE(rk4.drawn_integrator);
  CHECK(rk4.drawn_integrator->step == Approx(value(rk4.results(), "step_s")).epsilon(kRoundoff));
  CHECK(rk4.run.size() == rk4.time_series().rows.size());
  // Its results once each: drawing the motion reports nothing a second time.
  std::size_t steps_rows = 0;
  for (const auto& row : rk4.rows()) steps_rows += row.label == "steps taken";
  CHECK(steps_rows == 1);
}

namespace {

void check_same_strip(const rigid::render::Plot2D& a, const rigid::render::Plot2D& b) {
  const auto &p = a.panel(), &q = b.panel();
  REQUIRE(p.series.size() == q.series.size());
  for (std::size_t i = 0; i < p.series.size(); ++i) {
    CHECK(p.series[i].label == q.series[i].label);
    CHECK(p.series[i].x == q.series[i].x);
    CHECK(p.series[i].y == q.series[i].y);
  }
  REQUIRE(p.ref_lines.size() == q.ref_lines.size());
  for (std::size_t i = 0; i < p.ref_lines.size(); ++i) {
    CHECK(p.ref_lines[i].value == q.ref_lines[i].value);
  }
  CHECK(p.x.max == q.x.max);
}

// The largest difference between two scenes' object placements.
double placement_difference(const rigid::render::Scene3D& a, const rigid::render::Scene3D& b) {
  double worst = 0;
  for (std::size_t i = 0; i < a.objects().size(); ++i) {
    worst = std::max(worst, (a.objects()[i].transform.matrix() - b.objects()[i].transform.matrix())
                                .cwiseAbs()
                                .maxCoeff());
  }
  return worst;
}

}  // namespace

TEST_CASE("tennis_racquet: the motion is the same sampled in any order") {
  for (const char* method : {"exact", "rk4", "rkf78"}) {
    INFO(method);
    const auto report = compute(with_method(method));
    const double T = report.t_end;
    // An animation's frames (20 of them and 16 for the camera's fit), and times between
    // them that an integrated motion reaches from its nearest earlier state.
    std::vector<double> frames, times;
    for (int k = 0; k < 20; ++k) frames.push_back(T * k / 20);
    for (int k = 0; k < 16; ++k) frames.push_back(T * k / 16);
    std::sort(frames.begin(), frames.end());
    frames.erase(std::unique(frames.begin(), frames.end()), frames.end());
    times = frames;
    for (const double t : {0.123 * T, 0.5001 * T, 0.99 * T, 1.2 * T}) times.push_back(t);

    const Motion in_order(report, frames);
    std::vector<rigid::render::Scene3D> scenes;
    std::vector<rigid::render::Plot2D> strips;
    for (const double t : times) {
      scenes.push_back(in_order.scene(t));
      strips.push_back(in_order.strip(t));
    }
    std::vector<std::size_t> order(times.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::shuffle(order.begin(), order.end(), std::mt19937(12345));
    const Motion shuffled(report, frames);
    for (const std::size_t i : order) {
      INFO("t = " << times[i]);
      check_same_scene(shuffled.scene(times[i]), scenes[i]);
      check_same_strip(shuffled.strip(times[i]), strips[i]);
    }
    CHECK(in_order.seconds() == T);
    // The integrated motion is the exact one to the cross-check's error: the placements
    // differ by 3.3e-9 at most (dopri5 at 1e-10).
    const Motion exact(compute(with_method("exact")));
    for (std::size_t i = 0; i < times.size(); ++i) {
      INFO("t = " << times[i]);
      CHECK(placement_difference(scenes[i], exact.scene(times[i])) < 2e-8);
    }
  }
}

TEST_CASE("tennis_racquet: the animation draws the motion at its frame times") {
  const auto report = compute(with_method("rk4"));
  std::vector<double> asked;
  const rigid::lab::FrameTimes frame_times = [&asked](double seconds) {
    asked.push_back(seconds);
    return std::vector<double>{0.0, 0.25 * seconds, 0.5 * seconds};
  };
  const auto animation = rigid::lab::tennis_racquet::animation(report, frame_times);
  CHECK(asked == std::vector<double>{report.t_end});
  CHECK(animation.seconds == report.t_end);
  CHECK(animation.strip_share == 0.3);
  const Motion motion(report, frame_times(report.t_end));
  for (const double t : {0.0, 0.25 * report.t_end, 0.3 * report.t_end}) {
    check_same_scene(animation.scene(t), motion.scene(t));
    check_same_strip(animation.strip(t), motion.strip(t));
  }
  // The strip's lines span the whole run, 0 to t_end, and are the exact omega there.
  const rigid::render::Plot2D strip = motion.strip(0.0);
  const rigid::FreeBodyExact& exact = report.launches.at(report.spin_axis);
  REQUIRE(strip.panel().series.size() >= 3);
  for (int i = 0; i < 3; ++i) {
    const auto& line = strip.panel().series[i];
    REQUIRE(line.x.size() >= 2);
    CHECK(line.x.front() == 0.0);
    CHECK(line.x.back() == Approx(report.t_end).epsilon(4 * DBL_EPSILON));
    CHECK(line.y.back() == Approx(exact.omega_body(report.t_end)(i)).epsilon(kRoundoff));
  }
  // The closed form asks for no frame times: nothing to integrate.
  asked.clear();
  rigid::lab::tennis_racquet::animation(compute(Inputs{}), frame_times);
  CHECK(asked.empty());
}

TEST_CASE("tennis_racquet: 'not small' is said of a large disturbance only, with its fit's share") {
  const std::string start = "The disturbance at launch (";
  const auto said = [&](double perturbation) -> std::string {
    Inputs in;
    in.perturbation = perturbation;
    const auto notes = rigid::test::notes_starting(compute(in), start);
    return notes.empty() ? std::string() : notes[0];
  };
  // The linear rates hold while the disturbance is small: up to 5 % of omega no note.
  CHECK(said(0.01).empty());
  CHECK(said(0.05).empty());
  // Beyond, the note, with the share the growth fit runs to: twice the disturbance
  // (at least 0.1, at most halfway from it to 1).
  for (const double p : {0.0501, 0.1, 0.3, 0.49}) {
    INFO(p);
    const double share = std::min(std::max(0.1, 2 * p), 0.5 * (1 + p));
    CHECK(said(p) == fmt::format("The disturbance at launch ({:g} of omega) is not small: the "
                                 "linear rates describe only its start, and the fit runs to a "
                                 "share of {:g}.",
                                 p, share));
  }
}

TEST_CASE("tennis_racquet: a disturbance a double cannot follow is refused, not a false 'stable'") {
  // The polhode's k'^2 ~ share^2 underflows below a share of ~1e-154 (an infinite period:
  // "first flip: none"); the rule starts at 1e-60, as every input's magnitude does, and
  // there the spin about 2 flips after ln(1/share)/rate.
  Inputs in;
  in.perturbation = 1e-60;
  const auto report = compute(in);
  CHECK(std::isfinite(value(report.results(), "polhode_period_s")));
  CHECK(value(report.results(), "first_flip_s") > 0.0);
  for (const double p : {1e-61, 1e-154, 1e-160, 1e-300, -1e-300}) {
    in.perturbation = p;
    CHECK_THROWS_MATCHES(compute(in), rigid::lab::InputError,
                         rigid::test::names_input("--perturbation"));
  }
}

TEST_CASE("tennis_racquet: every valid racquet draws its figures, a vanishing handle seen") {
  // A 1e-20 m handle beside a 13 cm head: its ends are one point in doubles; drawn at a
  // tenth of the head's radius along axis 1. A 1e20 m head with the text's handle too.
  for (const auto& [handle, head] : {std::pair{1e-20, 0.13}, std::pair{0.3, 1e20}}) {
    INFO("handle " << handle << ", head " << head);
    Inputs in;
    in.handle_length = handle, in.head_radius = head;
    rigid::test::KeptFigures kept;
    REQUIRE_NOTHROW(figures(compute(in), kept));
    CHECK(kept.scenes.count("flip") == 1);
  }
}

TEST_CASE("tennis_racquet: the answer in short - which spin flips, and how soon") {
  const auto flips = compute(Inputs{}).results();
  const std::string answer = flips.at("answer");
  CHECK_THAT(answer, Catch::StartsWith("a spin about axis 2"));
  CHECK_THAT(answer, Catch::Contains(fmt::format("first at {:.4g} s, then every {:.4g} s",
                                                 value(flips, "first_flip_s"),
                                                 value(flips, "flip_interval_s"))));
  for (const char* axis : {"1", "3"}) {
    Inputs in;
    in.spin_axis = axis;
    const std::string stable = compute(in).results().at("answer");
    CHECK_THAT(stable, Catch::Contains("is stable"));
    CHECK_THAT(stable, Catch::Contains("only a spin about axis 2 flips"));
  }
}

TEST_CASE("tennis_racquet: any body by its moments - a book's growth rate and first flip") {
  // The book of poinsot's test (24 x 16 x 4 cm, 0.8 kg) by its moments (eq. 40).
  const double m = 0.8, a = 0.24, b = 0.16, c = 0.04;
  const double I1 = m * (b * b + c * c) / 12, I2 = m * (a * a + c * c) / 12,
               I3 = m * (a * a + b * b) / 12;
  Inputs in;
  in.inertia = Eigen::Vector3d(I1, I2, I3);
  in.omega = 6;
  const auto report = compute(in);
  const auto& r = report.results();
  // eqs. 86-88 at the spin's component omega_2(0) = 6 sqrt(1 - 0.01^2)
  const double spin = 6 * std::sqrt(1 - 0.01 * 0.01);
  CHECK(value(r, "growth_rate_per_s") ==
        Approx(spin * std::sqrt((I2 - I1) * (I3 - I2) / (I1 * I3))).epsilon(kRoundoff));
  // The first flip against a second method: the cross-check's dopri5 run (tolerance
  // 1e-10) has omega_2 change sign between two samples that bracket the closed form's.
  const double flip = value(r, "first_flip_s");
  bool bracketed = false;
  for (std::size_t k = 1; k < report.run.size() && !bracketed; ++k) {
    if (report.run[k - 1].x[1] > 0 && report.run[k].x[1] <= 0) {
      bracketed = report.run[k - 1].t < flip && flip <= report.run[k].t;
    }
  }
  CHECK(bracketed);
  CHECK(r.at("cm_offset_m").is_null());
  CHECK(report.inputs().contains("inertia"));
  CHECK(!report.inputs().contains("head_mass"));
  CHECK_THAT(r.at("answer").get<std::string>(), Catch::Contains("the body turns over"));
  // drawn as the box with those moments: its half-extents in the book's 6 : 4 : 1, the
  // thinnest from I1 + I2 - I3, which cancels to 1/26 of I3 (~26 eps, halved by the root)
  REQUIRE(report.body.box);
  const double cancelled = 8 * I3 / (I1 + I2 - I3) * DBL_EPSILON;
  CHECK(report.body.box->x() / report.body.box->z() == Approx(a / c).epsilon(cancelled));
  CHECK(report.body.box->y() / report.body.box->z() == Approx(b / c).epsilon(cancelled));
  rigid::test::KeptFigures kept;
  REQUIRE_NOTHROW(figures(report, kept));
  CHECK(kept.scenes.count("flip") == 1);
  REQUIRE_NOTHROW(Motion(report).scene(1.0));
  // the rules: axis 2 the intermediate; the moments or the model, not both
  in.inertia = Eigen::Vector3d(I2, I1, I3);
  CHECK_THROWS_MATCHES(compute(in), InputError, names_input("--inertia"));
  in.inertia = Eigen::Vector3d(I1, I2, I3);
  in.head_mass = 0.2;
  CHECK_THROWS_MATCHES(compute(in), InputError, names_input("--inertia"));
}
