// football spun along its symmetry axis (--alpha-deg 0): omega, L and 3 on one line,
// nothing precesses; the rates are their limits as alpha -> 0, and the figures draw.
#include <catch2/catch.hpp>
#include <string>

#include "football/football.h"
#include "lab_library.h"

using rigid::lab::football::compute;
using rigid::lab::football::Inputs;
using rigid::test::contains;
using rigid::test::KeptFigures;
using rigid::test::kRoundoff;
using rigid::test::value;

TEST_CASE("football: a spin along the symmetry axis (alpha = 0) does not precess, with the rates") {
  for (const char* name : {"football", "frisbee", "earth"}) {
    INFO(name);
    Inputs in;
    in.preset = name;
    in.alpha_deg = 0;
    const auto report = compute(in);
    const auto& r = report.results();
    CHECK(r.at("cones_touch") == "none");
    CHECK(value(r, "theta_deg") == 0.0);
    CHECK(value(r, "space_cone_half_angle_deg") == 0.0);
    CHECK(r.at("integrated_space_precession_rate_rad_s").is_null());
    // The rates are their limits as alpha -> 0: phi_dot = omega Is / I, Omega = omega (Is -
    // I) / I, those of a wobble as it starts.
    const double omega = report.omega, ratio = report.Is / report.I;
    CHECK(value(r, "space_precession_rate_rad_s") == Approx(omega * ratio).epsilon(kRoundoff));
    CHECK(value(r, "body_precession_rate_rad_s") ==
          Approx(omega * (report.Is - report.I) / report.I).epsilon(kRoundoff));
    const std::string answer = r.at("answer");
    CHECK(contains(answer, "spun along its symmetry axis (alpha = 0)"));
    CHECK(contains(answer, "nothing precesses"));
    CHECK(contains(answer, "A slight wobble would take 3 round L every"));
    // Its figures draw: the cones are lines, omega, L and 3 one arrow each, named.
    KeptFigures figures;
    rigid::lab::football::figures(report, figures);
    CHECK(contains(figures.scenes.at("cones").title, "on one line; nothing precesses"));
    CHECK(figures.plots.at("rates").cols() == 1);
  }
}
