// top_nutation's exact motion at its edges, in-process: the errata's rounding, each
// regime word and steady rate on its side of its threshold, the invariants through
// the bottom, and tops a hair from a pole or the separatrix against mpmath at 80
// digits (make_lab_edges.py).
#include <fmt/format.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "lab_library.h"
#include "top_nutation/top_nutation.h"

using Catch::Matchers::WithinAbs;
using rigid::lab::InputError;
using rigid::lab::top_nutation::compute;
using rigid::lab::top_nutation::Inputs;
using rigid::test::element;
using rigid::test::kRoundoff;
using rigid::test::value;

TEST_CASE("top_nutation: the rounding errata quote the exact rates, the slow one as slow") {
  // Section 8.1's top evaluated here: a 2 kg disk of radius 5 cm, 4 cm up, g = 9.8,
  // 500 rpm, released at 30 deg; I = m r^2/4 + m l^2 about the tip, Is = m r^2/2.
  const double m = 2, r = 0.05, l = 0.04, g = 9.8, c = std::cos(M_PI / 6);
  const double I = m * r * r / 4 + m * l * l, Is = m * r * r / 2, mgl = m * g * l;
  const double rpm = 2 * M_PI / 60, S = 500 * rpm, S_text = 52.4;
  // eq. 187: I cos(theta) phi_dot^2 - Is S phi_dot + m g l = 0; the slow root, without
  // cancellation: 2 m g l / (Is S + sqrt((Is S)^2 - 4 I cos(theta) m g l))
  const auto slow = [&](double spin) {
    return 2 * mgl / (Is * spin + std::sqrt(Is * spin * Is * spin - 4 * I * c * mgl));
  };
  const double horizontal = mgl / (Is * S), text_horizontal = mgl / (Is * S_text);
  const auto report = compute(Inputs{});
  REQUIRE(report.errata().size() == 3);
  CHECK(report.errata()[0].where == "section 8.1 (b) and (c), eqs. 185 and 187");
  CHECK_THAT(report.errata()[0].printed, Catch::Contains("5.98 rad/s = 57.1 rpm"));
  CHECK(report.errata()[0].correction ==
        fmt::format("500 rpm is S = {:.6g} rad/s; the text rounds it to 52.4 before using it. "
                    "With the exact S, phi_dot (horizontal) = {:.4g} rad/s = {:.4g} rpm and the "
                    "slow steady rate at 30 deg is {:.4g} rad/s. The text's 5.98 and 7.75 rad/s "
                    "come from S = 52.4 ({:.4g} and {:.4g}), and its 57.1 rpm from the rounded "
                    "5.98 rad/s ({:.4g} rpm).",
                    S, horizontal, horizontal / rpm, slow(S), text_horizontal, slow(S_text),
                    std::round(100 * text_horizontal) / 100 / rpm));
  // eq. 189: S_min = sqrt(4 m g l I) / Is
  const double period = 2 * M_PI * Is / std::sqrt(4 * mgl * I);
  CHECK(report.errata()[1].printed == "This is a period of 0.132 s");
  CHECK(report.errata()[1].correction ==
        fmt::format("the sleeping top's spin period 2 pi / S_min = {:.5g} s rounds to {:.3f} s.",
                    period, period));
  // each erratum is also a note, in the same order
  for (std::size_t k = 0; k < 3; ++k) {
    CHECK(report.notes()[k].rfind("errata: " + report.errata()[k].where + ": the text prints", 0) ==
          0);
  }
  // eq. 186's misprint is the text's whatever the top; the rounding errata only for its top,
  // and with I where the text has S in the last term
  Inputs other;
  other.spin_rpm = 600;
  const auto changed = compute(other);
  REQUIRE(changed.errata().size() == 1);
  CHECK(changed.errata()[0].where == "eq. 186");
  CHECK_THAT(changed.errata()[0].printed, Catch::Contains("- S phi_dot^2 cos(theta)"));
  CHECK_THAT(changed.errata()[0].correction, Catch::Contains("- I phi_dot^2 cos(theta)"));
}

TEST_CASE("top_nutation: each regime word on its side of its threshold") {
  // Section 8.1's top; only the spin and the start differ.
  const double m = 2, r = 0.05, l = 0.04, g = 9.8, c = std::cos(M_PI / 6);
  const double I = m * r * r / 4 + m * l * l, Is = m * r * r / 2, mgl = m * g * l;
  const auto regime = [](double spin, double phidot0, double thetadot0) {
    Inputs in;
    in.spin = spin;
    in.phidot0 = phidot0;
    in.thetadot0 = thetadot0;
    const auto report = compute(in);
    return report.results().at("regime").get<std::string>();
  };
  // Released from rest the axis stops at the top of each nod: cusped, however fast the
  // spin. At 1e7-1e8 rad/s the nod's amplitude (2 m g l I sin(theta0) / (Is S)^2 rad, about
  // 1e-12 to 1e-14 of a turn) still exceeds the steady threshold (64 eps of the circles'
  // distance from the poles) by a factor of about 10 to 1000: a loosened threshold reads
  // such a top as steady.
  for (const double S : {60.0, 1e3, 1e5, 1e7, 3e7, 1e8}) {
    INFO("S = " << S);
    CHECK(regime(S, 0, 0) == "cusped");
  }
  // Started at the slow steady rate of eq. 187, it does not nod: steady.
  for (const double S : {60.0, 1e3, 1e5}) {
    INFO("S = " << S);
    const double slow = 2 * mgl / (Is * S + std::sqrt(Is * S * Is * S - 4 * I * c * mgl));
    CHECK(regime(S, slow, 0) == "steady");
    // A little faster than steady: phi_dot keeps its sign through the nod, wavy ...
    CHECK(regime(S, 1.5 * slow, 0) == "wavy");
    // ... and started backwards it turns back and forth: looping.
    CHECK(regime(S, -slow, 0) == "looping");
  }
  // Upright with no nod at all: sleeping.
  Inputs upright;
  upright.theta0_deg = 0;
  CHECK(compute(upright).results().at("regime") == "sleeping");
}

TEST_CASE("top_nutation: no steady rates says why: horizontal, or too slow a spin for eq. 187") {
  // Eq. 187: Is S phi_dot = I cos theta phi_dot^2 + m g l; at theta = 90 deg the fast
  // root runs off to infinity, and a real pair needs Is^2 S^2 >= 4 m g l I cos theta.
  const auto why = [](const Inputs& in) -> std::string {
    const auto report = compute(in);
    for (const auto& row : report.rows()) {
      if (row.label == "phi_dot, slow and fast") return row.value + " " + row.textbook;
    }
    return "no row";
  };
  // horizontal: only the slow root, m g l / (Is S) (eq. 185); also one ulp either side
  // of 90 deg, which the conversion from degrees cannot tell from it
  for (const double deg : {90.0, std::nextafter(90.0, 0.0), std::nextafter(90.0, 180.0)}) {
    INFO(deg);
    Inputs horizontal;
    horizontal.theta0_deg = deg;
    CHECK(why(horizontal) == "none (horizontal: one steady rate, the slow one)");
    const auto r = compute(horizontal).results();
    CHECK(r.at("steady_precession_fast_rad_s").is_null());
    CHECK(value(r, "steady_precession_slow_rad_s") ==
          Approx(value(r, "horizontal_precession_rate_rad_s")).epsilon(kRoundoff));
  }
  // upright: the axis stays on the vertical; no rate of either kind
  Inputs upright;
  upright.theta0_deg = 0;
  CHECK(why(upright) ==
        "none (upright (theta0 = 0): the axis stays on the vertical, no precession)");
  CHECK(compute(upright).results().at("steady_precession_slow_rad_s").is_null());
  Inputs slow;  // the text's top at 30 deg: S_min = sqrt(4 mgl I cos 30) / Is = 44.0 rad/s
  slow.spin = 40.0;
  CHECK(why(slow) == "none (Is^2 S^2 < 4 m g l I cos(theta0): no steady precession)");
  Inputs hanging;  // below the pivot cos theta < 0: a real pair at any spin
  hanging.theta0_deg = 120;
  hanging.spin = 50.0;
  CHECK(why(hanging).rfind("none", 0) != 0);
  CHECK(why(Inputs{}).rfind("none", 0) != 0);
}

TEST_CASE("top_nutation: the exact top keeps E, p_phi and p_psi to roundoff through the bottom") {
  // A heavy top (l = 1e6 m: I / Is = 1e15) or a slow one (S = 1e-4 rad/s) released at 30
  // deg swings through the bottom 2e-11 rad from the south pole, where phi_dot ~ 1e8 and
  // sin of the rounded theta holds ulp(pi) / 2e-11 = 2e-5: built from it, the state read
  // drifts of 3e-5. From (1 - u)(1 + u), with omega_3 = S, and p_phi, p_psi against the
  // largest |L| the motion can reach, all three stay at roundoff: measured at most
  // 2.0e-15 in E (bound 32 eps), 2.3e-16 in p_phi and 0 in p_psi (omega_3 = S; 8 eps).
  for (const auto& [arm, rpm] : {std::pair{1e6, 500.0}, std::pair{0.04, 1e-3}, std::pair{1e6, 1e-3},
                                 std::pair{0.04, 500.0}}) {
    INFO("arm " << arm << " m, spin " << rpm << " rpm");
    Inputs in;
    in.arm = arm, in.spin_rpm = rpm;
    const auto report = compute(in);
    const auto& r = report.results();
    CHECK(value(r, "energy_drift_rel") < 32 * DBL_EPSILON);
    CHECK(value(r, "p_phi_drift_rel") < 8 * DBL_EPSILON);
    CHECK(value(r, "p_psi_drift_rel") < 8 * DBL_EPSILON);
  }
}

// Edges against mpmath at 80 digits from the lab's own double inputs (make_lab_edges.py).
struct LabEdge {
  const char* name;
  double I, Is, mgl, theta0_deg, theta_dot0, phi_dot0, spin;
  double theta_min_deg, theta_max_deg, period, mean_base, phi_dot_u1, phi_dot_u2, u3, condition;
};
const LabEdge kLabEdges[] = {
#include "../core/heavy_top/reference_lab_edges.inc"
};

const LabEdge& lab_edge(const std::string& name) {
  for (const LabEdge& e : kLabEdges)
    if (name == e.name) return e;
  throw std::logic_error("no reference " + name);
}

Inputs edge_inputs(const LabEdge& e) {
  Inputs in;
  in.inertia = Eigen::Vector2d(e.I, e.Is);
  in.g = e.mgl / (in.mass * in.arm);
  in.theta0_deg = e.theta0_deg, in.thetadot0 = e.theta_dot0, in.phidot0 = e.phi_dot0;
  in.spin = e.spin;
  return in;
}

auto edge_results(const LabEdge& e) {
  return compute(edge_inputs(e)).results();
}

bool near_rel(double x, double ref, double rel) {
  return std::abs(x - ref) <= rel * std::abs(ref);
}

TEST_CASE("top_nutation: a hair from the bottom, 1 + cos theta0 below the roundoff of 1") {
  // 179.9999999 deg from rest: cos theta0 rounds to -1, and the lab had the top 'steady' at
  // 180 deg with phi_dot -14.7. From the degrees, 1 + cos keeps its digits: 180 - theta_max
  // (7.4e-8 deg) to the ulps of 180 (2.8e-14), the period and phi_dot to a few hundred ulps
  // (K, lambda and the third-kind integrals each to a few ulps).
  const LabEdge& e = lab_edge("from rest at 179.9999999 deg");
  const auto r = edge_results(e);
  CHECK(r.at("regime") == "cusped");
  CHECK(std::abs(value(r, "theta_max_deg") - e.theta_max_deg) < 4 * 2.9e-14);
  CHECK(std::abs(value(r, "theta_min_deg") - e.theta_min_deg) < 4 * 2.9e-14);
  CHECK(near_rel(value(r, "nutation_period_s"), e.period, 1e-13));
  CHECK(near_rel(value(r, "mean_precession_rate_rad_s"), e.mean_base, 1e-12));
  CHECK(near_rel(element(r, "phi_dot_turning_rad_s", 0), e.phi_dot_u1, 1e-12));
  CHECK(std::abs(element(r, "phi_dot_turning_rad_s", 1)) < 1e-12);  // the cusp
  // the answer tells the two angles apart
  CHECK_THAT(r.at("answer").get<std::string>(),
             Catch::Contains("between 179.9999999 and 179.99999993 deg"));
}

TEST_CASE("top_nutation: rates of 1e60 keep their turning angles and period") {
  // u3 ~ 7e116: the cubic at u3 overflowed a double from rates of 3e52 on (theta_max 97.7
  // deg for 150). Its largest root is found in 113-bit numbers; the rest keeps its digits.
  const LabEdge& e = lab_edge("phi_dot0 = 1e60 at 30 deg");
  const auto r = edge_results(e);
  CHECK(std::abs(value(r, "theta_max_deg") - e.theta_max_deg) < 1e-12);
  CHECK(std::abs(value(r, "theta_min_deg") - e.theta_min_deg) < 1e-12);
  CHECK(near_rel(value(r, "nutation_period_s"), e.period, 1e-13));
  CHECK(near_rel(value(r, "mean_precession_rate_rad_s"), e.mean_base, 1e-12));
  CHECK(near_rel(element(r, "cubic_roots", 2), e.u3, 1e-13));
  // past the input's bound, a rule, not a number
  Inputs past;
  past.thetadot0 = 1e300;
  CHECK_THROWS_MATCHES(compute(past), InputError, rigid::test::names_input("--thetadot0"));
}

TEST_CASE("top_nutation: a top that just reaches upright, its roots polished about the pole") {
  // b - a = 3.5e-16 of terms of 17: in doubles it came out 0, theta_min read 0 and the
  // period 2.0465 (3 % short). u3 - u2 is formed from the pole (each to its own accuracy),
  // so k'^2 keeps its digits: the period and the mean to a few hundred ulps, as elsewhere;
  // the root u3 itself as a double, to ulp(1).
  const LabEdge& e = lab_edge("just reaching upright");
  const auto r = edge_results(e);
  CHECK(r.at("regime") == "wavy");  // phi_dot 20.9 and 4.6e9 rad/s: one sign
  CHECK(std::abs(element(r, "cubic_roots", 2) - e.u3) < 4 * DBL_EPSILON);
  CHECK(near_rel(value(r, "theta_min_deg"), e.theta_min_deg, 1e-9));
  CHECK(near_rel(value(r, "theta_max_deg"), e.theta_max_deg, 1e-13));
  CHECK(near_rel(value(r, "nutation_period_s"), e.period, 1e-13));
  CHECK(near_rel(value(r, "mean_precession_rate_rad_s"), e.mean_base, 1e-13));
  CHECK(near_rel(element(r, "phi_dot_turning_rad_s", 1), e.phi_dot_u2, 1e-8));
  // the period's condition number, 4.6e6, stated: by differences at 1e-3 of k'^2 = 6.5e-9,
  // T to 1e-15 over a step of 6.5e-12, so to ~2e-4 of itself
  CHECK(near_rel(value(r, "nutation_period_condition"), e.condition, 1e-3));
  bool stated = false;
  const auto report = compute(edge_inputs(e));
  for (const auto& row : report.rows()) {
    stated |= row.remark.rfind(fmt::format("(condition number {:.2g}", e.condition), 0) == 0;
  }
  CHECK(stated);
  // well away from it, small, and not in the table
  for (const char* name : {"from rest at 179.9999999 deg", "phi_dot0 = 1e60 at 30 deg"}) {
    const LabEdge& other = lab_edge(name);
    CHECK(near_rel(value(edge_results(other), "nutation_period_condition"), other.condition, 1e-6));
  }
}

TEST_CASE("top_nutation: through the pole and planar swings have no mean precession") {
  // Exactly through the vertical phi turns by pi at once, either way: the mean is either
  // limit, base -+ pi / period, and null, with both in the reason.
  for (const char* name : {"upright with theta_dot0 = 1", "no spin at 150 deg"}) {
    INFO(name);
    const LabEdge& e = lab_edge(name);
    const auto r = edge_results(e);
    CHECK(r.at("regime") == (e.spin == 0.0 ? "planar" : "through the pole"));
    CHECK(r.at("mean_precession_rate_rad_s").is_null());
    const double low = e.mean_base - M_PI / e.period, high = e.mean_base + M_PI / e.period;
    CHECK_THAT(value(r, "mean_precession_limits_rad_s_low"), WithinAbs(low, 1e-12 * high));
    CHECK_THAT(value(r, "mean_precession_limits_rad_s_high"), WithinAbs(high, 1e-12 * high));
    CHECK(near_rel(value(r, "nutation_period_s"), e.period, 1e-13));
    CHECK(near_rel(value(r, "theta_max_deg"), e.theta_max_deg, 1e-13));
    const std::string answer = r.at("answer");
    CHECK_THAT(answer, Catch::StartsWith(r.at("regime").get<std::string>() + ":"));
    if (e.spin != 0.0) {
      CHECK_THAT(answer, Catch::Contains(fmt::format("{:.4g} or {:.4g} rad/s", low, high)));
      // phi_dot at theta_max first, then at theta_min, each where it is
      CHECK_THAT(answer, Catch::Contains(fmt::format("phi_dot {:.4g} rad/s at theta_max, {:.4g} "
                                                     "at theta_min",
                                                     e.phi_dot_u1, e.phi_dot_u2)));
    }
  }
  // the pendulum released level runs: no steady rate, said why
  Inputs level;
  level.spin = 0, level.theta0_deg = 90;
  const auto r = compute(level).results();
  CHECK(r.at("regime") == "planar");
  CHECK(r.at("steady_precession_slow_rad_s").is_null());
  const auto report = compute(level);
  bool said = false;
  for (const auto& row : report.rows())
    said |= row.textbook.find("nothing balances") != std::string::npos;
  CHECK(said);
}

TEST_CASE("top_nutation: the answer names phi_dot at theta_max and theta_min the right way") {
  Inputs in;
  in.phidot0 = 3.0, in.thetadot0 = 0.5;  // wavy, phi_dot differs at the two circles
  const auto r = compute(in).results();
  const double at_max = element(r, "phi_dot_turning_rad_s", 0);
  const double at_min = element(r, "phi_dot_turning_rad_s", 1);
  REQUIRE(std::abs(at_max - at_min) > 0.1 * std::abs(at_max));
  CHECK_THAT(r.at("answer").get<std::string>(),
             Catch::Contains(fmt::format("phi_dot {:.4g} rad/s at theta_max, {:.4g} at theta_min",
                                         at_max, at_min)));
  // upright: stable on one side of S_min, unstable on the other, in the answer's words
  const double S_min = value(r, "min_spin_rad_s");
  for (const double f : {1.001, 0.999}) {
    Inputs up;
    up.theta0_deg = 0, up.spin = f * S_min;
    CHECK_THAT(compute(up).results().at("answer").get<std::string>(),
               Catch::StartsWith(f > 1 ? "sleeping, stable" : "upright but unstable"));
  }
}

TEST_CASE("top_nutation: the default step comes from the fastest turn, not only the period") {
  // A hair from upright at S_min the top nods once in minutes; period / 2000 was a 33 s step
  // for rk4, which diverged. The step is at most 1/200 of the spin's turn.
  Inputs in;
  in.theta0_deg = 1e-9;
  const auto probe = compute(Inputs{}).results();
  in.spin = value(probe, "min_spin_rad_s");
  in.integration.method = "rk4";
  in.t_end = 1.0;  // its three periods would take 5e8 steps: past the work budget, refused
  const auto r = compute(in).results();
  CHECK(value(r, "step_s") <= 2 * M_PI / *in.spin / 200);
  CHECK(value(r, "max_theta_error_deg") < 1e-6);
}

TEST_CASE("top_nutation: a table under the tip would catch the rim past tan theta = l / r") {
  // The text's top: l cos theta = r sin theta at atan(0.04 / 0.05) = 38.66 deg, and its
  // own example nods to 52.36 deg, through such a table: said, with both numbers.
  const auto report = compute(Inputs{});
  REQUIRE(report.table_theta);
  CHECK(*report.table_theta == Approx(std::atan2(0.04, 0.05)).epsilon(4 * DBL_EPSILON));
  const auto notes = report.notes();
  const auto table = std::find_if(notes.begin(), notes.end(),
                                  [](const std::string& n) { return n.rfind("a table:", 0) == 0; });
  REQUIRE(table != notes.end());
  CHECK_THAT(*table, Catch::Contains(fmt::format("at theta = {:.4g} deg", 38.65980825409009)));
  CHECK_THAT(*table, Catch::Contains(fmt::format("tilts to {:.4g} deg",
                                                 value(report.results(), "theta_max_deg"))));
  // a fast top released at 10 deg stays clear of it; moments given have no disk to catch
  Inputs clear;
  clear.theta0_deg = 10, clear.spin_rpm = 3000;
  Inputs moments;
  moments.inertia = Eigen::Vector2d(4.45e-3, 2.5e-3);
  for (const Inputs& in : {clear, moments}) {
    const auto r = compute(in);
    CHECK(std::none_of(r.notes().begin(), r.notes().end(),
                       [](const std::string& n) { return n.rfind("a table:", 0) == 0; }));
  }
  CHECK_FALSE(compute(moments).table_theta);
}

TEST_CASE("top_nutation: planar and through-the-pole on their side of the threshold only") {
  const auto regime = [](double theta0_deg, double thetadot0, double phidot0, double spin) {
    Inputs in;
    in.theta0_deg = theta0_deg, in.thetadot0 = thetadot0, in.phidot0 = phidot0, in.spin = spin;
    return compute(in).results();
  };
  // no spin, no phi_dot0: a plane; a hair of either, and the axis goes round the vertical
  CHECK(regime(150, 0, 0, 0).at("regime") == "planar");
  for (const auto& r : {regime(150, 0, 0, 1e-6), regime(150, 0, 1e-6, 0)}) {
    CHECK(r.at("regime") != "planar");
    CHECK(r.at("regime") != "through the pole");
    CHECK_FALSE(r.at("mean_precession_rate_rad_s").is_null());
  }
  // started upright with theta_dot0: through the pole; a hair off upright, beside it
  CHECK(regime(0, 1, 0, 52.36).at("regime") == "through the pole");
  const auto beside = regime(1e-9, 1, 0, 52.36);
  CHECK(beside.at("regime") != "through the pole");
  CHECK_FALSE(beside.at("mean_precession_rate_rad_s").is_null());
  // and beside it the mean is one of the two limits through it
  const auto through = regime(0, 1, 0, 52.36);
  const double mean = value(beside, "mean_precession_rate_rad_s");
  const double low = value(through, "mean_precession_limits_rad_s_low");
  const double high = value(through, "mean_precession_limits_rad_s_high");
  CHECK(std::min(std::abs(mean - low), std::abs(mean - high)) < 1e-6 * high);
}
