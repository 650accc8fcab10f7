// football's library in-process: the three presets against the text's numbers
// and eqs. 143-149 typed here, a sphere, an oblate body of other inputs, the
// integrated cross-check, the rules compute() holds its inputs to, and the
// motion: exact at any time, in any order, its still the "cones" figure.
#include "football/football.h"

#include <fmt/format.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <optional>
#include <random>
#include <vector>

#include "lab_library.h"

using rigid::lab::football::compute;
using rigid::lab::football::Inputs;
using rigid::lab::football::Motion;
using rigid::test::check_same_scene;
using rigid::test::contains;
using rigid::test::KeptFigures;
using rigid::test::kRoundoff;
using rigid::test::notes_starting;
using rigid::test::value;

namespace {

constexpr double kDeg = M_PI / 180;

Inputs preset(const char* name) {
  Inputs in;
  in.preset = name;
  return in;
}

// The errata the report lists at `where`.
std::vector<rigid::lab::Erratum> errata_at(const rigid::lab::Report& report,
                                           const std::string& where) {
  std::vector<rigid::lab::Erratum> found;
  for (const auto& e : report.errata()) {
    if (e.where == where) found.push_back(e);
  }
  return found;
}

}  // namespace

TEST_CASE("football: the default football is prolate, its body cone rolls outside") {
  const auto report = compute(Inputs{});
  const auto& r = report.results();
  for (const char* key : {"body_precession_rate_rad_s", "space_precession_rate_rad_s", "theta_deg",
                          "body_cone_half_angle_deg", "space_cone_half_angle_deg", "cones_touch",
                          "body_precession_period_s", "space_precession_period_s"})
    CHECK(r.contains(key));
  CHECK(r.at("cones_touch") == "outside");
  CHECK(value(r, "body_precession_rate_rad_s") < 0);  // prolate: omega turns clockwise about 3
  CHECK(value(r, "theta_deg") > value(r, "body_cone_half_angle_deg"));
  // Independent: theta - alpha from tan theta = (I/Is) tan alpha, formed by subtraction:
  // theta = 18.1 deg, so the difference carries 2.2x the roundings of the angles.
  const double I = value(r, "moment_transverse_kg_m2"), Is = value(r, "moment_symmetry_kg_m2");
  const double alpha = 10.0 * M_PI / 180;
  const double theta = std::atan(I / Is * std::tan(alpha));
  CHECK(value(r, "space_cone_half_angle_deg") ==
        Approx((theta - alpha) * 180 / M_PI).epsilon(8 * DBL_EPSILON));
  // The NFL-sized spheroid, m (b^2 + c^2)/5 and m (a^2 + c^2)/5.
  CHECK(Is == Approx(0.42 * 2 * 0.085 * 0.085 / 5).epsilon(kRoundoff));
  CHECK(I == Approx(0.42 * (0.14 * 0.14 + 0.085 * 0.085) / 5).epsilon(kRoundoff));
  CHECK(value(r, "body_precession_period_s") ==
        Approx(2 * M_PI / std::abs(value(r, "body_precession_rate_rad_s"))).epsilon(kRoundoff));
}

TEST_CASE("football: the frisbee (Is = 2I) gives eqs. 148-149 and the wobble is twice the spin") {
  const auto report = compute(preset("frisbee"));
  const auto& r = report.results();
  const double omega = 30.0, alpha = 5.0 * M_PI / 180;
  CHECK(value(r, "moment_symmetry_kg_m2") == 2 * value(r, "moment_transverse_kg_m2"));
  // (Is - I)/I is exactly 1 for Is = 2I, so Omega = omega cos alpha to the last bit.
  CHECK(value(r, "body_precession_rate_rad_s") == omega * std::cos(alpha));
  // phi_dot / omega = sqrt(1 + 3 cos^2 a) = 2 - 3 a^2/4 + O(a^4); a^4 ~ 6e-5 bounds the rest.
  const double ratio = value(r, "space_precession_rate_rad_s") / omega;
  CHECK(ratio == Approx(2 - 0.75 * alpha * alpha).epsilon(0).margin(std::pow(alpha, 4)));
  CHECK(ratio == Approx(std::sqrt(1 + 3 * std::cos(alpha) * std::cos(alpha))).epsilon(1e-15));
  CHECK(r.at("cones_touch") == "inside");
  CHECK(report.textbook_printed().contains("body_precession_rate_rad_s"));
  CHECK(notes_starting(report,
                       "errata: section 6.1, Feynman's plate after eq. 149: the text "
                       "prints \"the medallion rotates twice as fast as the wobble "
                       "rate\"; ")
            .size() == 1);
  // Any other physical input takes the text's example away.
  Inputs other = preset("frisbee");
  other.omega = 10;
  CHECK(compute(other).textbook_printed().empty());
}

TEST_CASE("football: the Earth's periods near the text's 305 and 0.997 days") {
  const auto report = compute(preset("earth"));
  const auto& r = report.results();
  // Independent: omega = 2 pi per sidereal day, Omega = 0.00327 omega cos a,
  // phi_dot = omega sqrt(1 + (1.00327^2 - 1) cos^2 a); cos a = 1 - 5e-13.
  const double day = 86164.0905, a = 0.2 / 3600 * M_PI / 180, c = std::cos(a);
  const double body_days = day / (0.00327 * c) / 86400;
  const double space_days = day / std::sqrt(1 + (1.00327 * 1.00327 - 1) * c * c) / 86400;
  // The moments are 8e37 and 1.00327 times it: their half-ulp roundings, divided by their
  // difference 0.00327 I, make ~300 eps = 7e-14 in (Is - I)/I (measured 5e-14).
  CHECK(value(r, "body_precession_period_days") == Approx(body_days).epsilon(3e-13));
  CHECK(value(r, "space_precession_period_days") == Approx(space_days).epsilon(kRoundoff));
  CHECK(report.units().at("body_precession_period_days") == "d");
  // The text's printed values, within the rounding of their last digit and of the day used.
  CHECK(std::abs(value(r, "body_precession_period_days") - 305) < 0.5);
  CHECK(std::abs(value(r, "space_precession_period_days") - 0.997) < 0.004);
  CHECK(report.textbook_printed().at("body_precession_period_days") == "305");
  CHECK(report.textbook_printed().at("space_precession_period_days") == "0.997");
  CHECK(r.at("cones_touch") == "inside");
}

TEST_CASE("football: a sphere has no cones and no body period") {
  Inputs in;
  in.inertia = Eigen::Vector2d(1, 1), in.omega = 2, in.alpha_deg = 30;
  const auto report = compute(in);
  const auto& r = report.results();
  CHECK(r.at("cones_touch") == "none");
  CHECK(r.at("body_precession_period_s").is_null());
  CHECK(value(r, "space_precession_rate_rad_s") == Approx(2.0).epsilon(kRoundoff));
}

TEST_CASE("football: the integrated cross-check agrees with the closed form for every preset") {
  for (const char* name : {"football", "frisbee", "earth"}) {
    INFO(name);
    const auto report = compute(preset(name));
    const auto& r = report.results();
    // dopri5 at tolerance 1e-12 for one period: measured at most 9.3e-13 (rate),
    // 4.4e-13 (axis), 4.2e-13 (|L|) over the presets; the bounds are 5-7x those, so a
    // lab tolerance 10x looser fails here.
    CHECK(value(r, "integrated_rate_error_rel") < 5e-12);
    CHECK(value(r, "integrated_axis_return_rad") < 3e-12);
    CHECK(value(r, "integrated_L_drift_rel") < 3e-12);
    CHECK(report.units().at("integrated_space_precession_rate_rad_s") == "rad/s");
  }
}

TEST_CASE("football: an oblate body at another spin and angle against eqs. 109 and 143-147") {
  const double I = 0.3, Is = 0.5, omega = 7, alpha = 25 * kDeg;
  Inputs in;
  in.inertia = Eigen::Vector2d(0.3, 0.5), in.omega = 7, in.alpha_deg = 25;
  const auto report = compute(in);
  const auto& r = report.results();
  const double s = std::sin(alpha), c = std::cos(alpha);
  CHECK(value(r, "body_precession_rate_rad_s") ==
        Approx(omega * c * (Is - I) / I).epsilon(kRoundoff));
  const double L = omega * std::sqrt(I * I * s * s + Is * Is * c * c);  // eq. 143
  CHECK(value(r, "space_precession_rate_rad_s") == Approx(L / I).epsilon(kRoundoff));
  const double theta = std::atan(I / Is * std::tan(alpha));  // eq. 144
  CHECK(value(r, "theta_deg") == Approx(theta / kDeg).epsilon(kRoundoff));
  CHECK(value(r, "space_cone_half_angle_deg") == Approx((alpha - theta) / kDeg).epsilon(kRoundoff));
  CHECK(r.at("cones_touch") == "inside");  // oblate: theta < alpha
  CHECK(value(r, "body_precession_period_s") ==
        Approx(2 * M_PI * I / (omega * c * (Is - I))).epsilon(kRoundoff));
}

TEST_CASE("football: the inputs recorded are the preset and those given") {
  const auto text = compute(Inputs{});
  CHECK(text.inputs() == rigid::lab::Json{{"preset", "football"}});
  CHECK(text.textbook_inputs());
  Inputs in = preset("earth");
  in.omega = 1e-4;
  const auto earth = compute(in);
  CHECK(earth.inputs() == rigid::lab::Json{{"preset", "earth"}, {"omega", 1e-4}});
  CHECK(!earth.textbook_inputs());
  // alpha the preset's: the Earth's 0.2 arcsec is reported in radians too
  CHECK(value(earth.results(), "alpha_rad") == Approx(0.2 / 3600 * kDeg).epsilon(kRoundoff));
  // what the figures and the motion draw is what was used
  CHECK(earth.omega == 1e-4);
  CHECK(earth.alpha_deg == 0.2 / 3600.0);
  CHECK(earth.Is / earth.I == Approx(1.00327).epsilon(kRoundoff));
}

TEST_CASE("football: a body of one's own says custom, another Earth by its Is/I or day") {
  // --inertia replaces the preset's moments: the inputs, and so the table and the
  // figures' titles, say "custom", with the preset's omega and alpha it still uses.
  Inputs in;
  in.inertia = Eigen::Vector2d(1, 1.5);
  const auto custom = compute(in);
  CHECK(custom.inputs() ==
        rigid::lab::Json{
            {"preset", "custom"}, {"inertia", {1.0, 1.5}}, {"omega", 60.0}, {"alpha_deg", 10.0}});
  CHECK_THAT(custom.figure_title("cones"), Catch::Contains("body = custom"));
  CHECK_THAT(custom.figure_title("cones"), !Catch::Contains("body = football"));
  // an input the figure's own title states with the same value is said once; with
  // another value (a figure drawn at another angle) the run's own stays
  const std::string alpha = "\\alpha = 10\\deg";
  const std::string once = custom.figure_title("Is/I = 1.5, " + alpha + ", rolls");
  CHECK(once.find(alpha) == once.rfind(alpha));
  CHECK(once.find(alpha) != std::string::npos);
  const std::string other = custom.figure_title("drawn at \\alpha = 8\\deg");
  CHECK_THAT(other, Catch::Contains(alpha) && Catch::Contains("\\alpha = 8\\deg"));
  // Is/I to the digit: (Is - I)/I sets Omega / omega, the Earth's 305 days
  in = preset("earth");
  in.moment_ratio = 1.0032737;
  const auto earth = compute(in);
  const auto& r = earth.results();
  CHECK(value(r, "moment_ratio_excess") == Approx(0.0032737).epsilon(1e-12));
  bool whole = false;
  for (const auto& row : earth.rows()) whole = whole || row.value == "1.0032737";
  CHECK(whole);
  // the sidereal day's omega, the moments' ratio given: 86164.0905 / (0.0032737 cos a) s
  const double a = 0.2 / 3600 * M_PI / 180;
  CHECK(value(r, "body_precession_period_days") ==
        Approx(86164.0905 / (0.0032737 * std::cos(a)) / 86400).epsilon(1e-12));
  // and the day: a solar one, 86400 s, gives 305.8 days (the errata's other day)
  in = preset("earth");
  in.day = 86400;
  const auto solar = compute(in);
  CHECK(value(solar.results(), "body_precession_period_days") ==
        Approx(86400 / (0.00327 * std::cos(a)) / 86400).epsilon(3e-13));
  // periods in days wherever one is that long, not only for the Earth's preset
  Inputs slow;
  slow.inertia = Eigen::Vector2d(1, 1.001);
  slow.omega = 1e-3;
  const auto days = compute(slow).results();
  CHECK(value(days, "body_precession_period_days") ==
        Approx(value(days, "body_precession_period_s") / 86400).epsilon(kRoundoff));
  CHECK(!compute(Inputs{}).results().contains("body_precession_period_days"));
}

TEST_CASE("football: a broken rule is an InputError naming the input") {
  using rigid::lab::InputError;
  using rigid::test::names_input;
  Inputs in;
  in.alpha_deg = -1e-9;
  CHECK_THROWS_MATCHES(compute(in), InputError, names_input("--alpha-deg"));
  in.alpha_deg = 90;
  CHECK_THROWS_MATCHES(compute(in), InputError, names_input("--alpha-deg"));
  in.alpha_deg = std::nan("");
  CHECK_THROWS_MATCHES(compute(in), InputError, names_input("--alpha-deg"));
  in = Inputs{};
  in.inertia = Eigen::Vector2d(1, 3);  // Is > 2I: no such body
  CHECK_THROWS_MATCHES(compute(in), InputError, names_input("--inertia"));
  in.inertia = Eigen::Vector2d(-1, 1);
  CHECK_THROWS_MATCHES(compute(in), InputError, names_input("--inertia"));
  in = preset("moon");
  CHECK_THROWS_MATCHES(compute(in), InputError, names_input("--preset"));
  in = Inputs{};
  in.omega = 0;
  CHECK_THROWS_MATCHES(compute(in), InputError, names_input("--omega"));
  // a preset's moments and moments given are alternatives, as are the moments and
  // their ratio, and the speed and the day
  in = preset("earth");
  in.inertia = Eigen::Vector2d(1, 1);
  CHECK_THROWS_MATCHES(compute(in), InputError, names_input("--inertia"));
  in = Inputs{};
  in.inertia = Eigen::Vector2d(1, 1);
  in.moment_ratio = 1.5;
  CHECK_THROWS(compute(in));
  in = Inputs{};
  in.moment_ratio = 2.5;  // Is > 2I: no such body
  CHECK_THROWS_MATCHES(compute(in), InputError, names_input("--moment-ratio"));
  in = Inputs{};
  in.omega = 1, in.day = 86400;
  CHECK_THROWS(compute(in));
}

TEST_CASE("football: the motion is exact at any time, in any order, its still is the cones") {
  for (const char* name : {"football", "frisbee", "earth"}) {
    INFO(name);
    std::optional<Motion> first, second;
    {
      // the motion keeps no reference to its report
      const auto report = compute(preset(name));
      first.emplace(report);
      second.emplace(report);
      CHECK(first->seconds() == 2 * report.precession.space_period);
      const auto animation = rigid::lab::football::animation(report, nullptr);
      CHECK(animation.seconds == first->seconds());
      CHECK(animation.still == "cones");
      KeptFigures figures;
      rigid::lab::football::figures(report, figures);
      REQUIRE(figures.scenes.count("cones") == 1);
      check_same_scene(animation.scene(0.0), figures.scenes.at("cones"));
      CHECK(figures.scenes.count("cones_contrast") == 1);
      CHECK(figures.plots.count("rates") == 1);
    }
    std::vector<double> times;
    for (int k = 0; k < 24; ++k) times.push_back(first->seconds() * k / 17.0);
    std::vector<rigid::render::Scene3D> in_order;
    for (const double t : times) in_order.push_back(first->scene(t));
    std::vector<std::size_t> order(times.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::shuffle(order.begin(), order.end(), std::mt19937(7));
    for (const std::size_t k : order) {
      INFO("t = " << times[k]);
      check_same_scene(second->scene(times[k]), in_order[k]);
    }
    // and it moves: the symmetry axis has turned about L a quarter period on
    const auto axis3 = [](const rigid::render::Scene3D& s) { return s.labels()[1].position; };
    CHECK((axis3(first->scene(0.25 * first->seconds() / 2)) - axis3(in_order[0])).norm() > 0.1);
  }
}

// Every erratum of the lab: the numbers inside it (from eqs. 142-149 evaluated here) and
// the condition under which it appears, on both sides.

TEST_CASE("football: the cone errata quote section 6.1 and turn it round, with the numbers") {
  constexpr double kDeg = M_PI / 180;
  const std::string cones = "section 6.1, after eq. 144";
  const std::string alpha_where = "section 6.1, the applet and Marion's alpha, before eq. 142";
  const std::string quote =
      "This means that the space cone can engulf the body cone (prolate case) or the space cone "
      "can be outside the body cone (oblate case).";
  // (I, Is, alpha in degrees): the football (prolate: Is < I), the frisbee (oblate: Is = 2I)
  struct Body {
    double I, Is, alpha_deg;
    bool prolate;
  };
  const double m = 0.42, a = 0.14, b = 0.085;  // the football: a solid spheroid
  const double md = 0.175, r = 0.1375;         // the frisbee: a thin disk
  for (const Body& body : {Body{m * (a * a + b * b) / 5, m * 2 * b * b / 5, 10, true},
                           Body{md * r * r / 4, md * r * r / 2, 5, false}, Body{2.0, 1.5, 33, true},
                           Body{1.0, 1.7, 61, false}, Body{1.0, 1.0 + 1e-9, 1, false},
                           Body{1.0, 1.0 - 1e-9, 1, true}}) {
    INFO("I = " << body.I << ", Is = " << body.Is << ", alpha = " << body.alpha_deg);
    Inputs in;
    in.inertia = Eigen::Vector2d(body.I, body.Is);
    in.alpha_deg = body.alpha_deg;
    const auto report = compute(in);
    // eq. 144: tan theta = (I / Is) tan alpha; omega makes |theta - alpha| with L
    const double theta = std::atan(body.I / body.Is * std::tan(body.alpha_deg * kDeg)) / kDeg;
    const std::string numbers = fmt::format(
        "Is/I = {:.6g}, alpha = {:.6g} deg, theta = {:.6g} deg, omega to L = {:.6g} deg",
        body.Is / body.I, body.alpha_deg, theta, std::abs(theta - body.alpha_deg));
    const auto said = errata_at(report, cones);
    REQUIRE(said.size() == 1);
    CHECK(said[0].printed == quote);
    CHECK(contains(said[0].correction, "the cases are the other way round"));
    CHECK(contains(said[0].correction, numbers));
    // which way round: the body's own case first, then the other kind's
    if (body.prolate) {
      CHECK(contains(said[0].correction, "For this prolate body (" + numbers +
                                             ") theta > alpha: omega lies between L and 3, and "
                                             "the body cone rolls on the outside of the space "
                                             "cone; neither engulfs the other."));
      CHECK(contains(said[0].correction,
                     "It is an oblate body whose space cone lies inside its body cone."));
    } else {
      CHECK(contains(said[0].correction, "For this oblate body (" + numbers +
                                             ") theta < alpha: L lies between 3 and omega, and "
                                             "the space cone lies inside the body cone, which "
                                             "rolls round it."));
      CHECK(contains(said[0].correction, "A prolate body's cones touch from outside"));
    }
    CHECK(report.results().at("cones_touch") == (body.prolate ? "outside" : "inside"));
    // and the note it makes, under the table
    CHECK(notes_starting(report, "errata: " + cones + ": the text prints \"" + quote + "\"; " +
                                     said[0].correction)
              .size() == 1);
    // alpha: the angle omega makes with L is the space cone's, not alpha
    const auto alpha = errata_at(report, alpha_where);
    REQUIRE(alpha.size() == 1);
    CHECK(contains(alpha[0].printed, "between z and omega, is alpha"));
    CHECK(contains(alpha[0].printed, "making a constant angle alpha with the angular momentum"));
    CHECK(contains(alpha[0].correction,
                   fmt::format("omega makes the space cone's half-angle |theta - alpha| = {:.6g} "
                               "deg with L, and alpha = {:.6g} deg with 3.",
                               std::abs(theta - body.alpha_deg), body.alpha_deg)));
    CHECK(contains(alpha[0].correction,
                   "in eqs. 142-147 alpha is the angle between omega and the symmetry axis 3"));
  }
  // A sphere has no cones: neither erratum.
  Inputs sphere;
  sphere.inertia = Eigen::Vector2d(1.0, 1.0);
  const auto report = compute(sphere);
  CHECK(errata_at(report, cones).empty());
  CHECK(errata_at(report, alpha_where).empty());
  CHECK(report.errata().empty());
}

TEST_CASE("football: Feynman's ratio for any thrown plate, the Earth's days for the text's") {
  const std::string feynman = "section 6.1, Feynman's plate after eq. 149";
  const std::string days = "section 6.1, the Earth's free precession after eq. 149";
  const auto frisbee = compute(preset("frisbee"));
  const auto earth = compute(preset("earth"));
  REQUIRE(errata_at(frisbee, feynman).size() == 1);
  REQUIRE(errata_at(earth, days).size() == 1);
  CHECK(errata_at(frisbee, days).empty());
  CHECK(errata_at(earth, feynman).empty());
  CHECK(errata_at(compute(Inputs{}), feynman).empty());
  CHECK(errata_at(frisbee, feynman)[0].printed ==
        "the medallion rotates twice as fast as the wobble rate");
  // A thin disk (Is = 2I) at omega, alpha (eqs. 148-149): phi_dot = omega sqrt(1 + 3 cos^2
  // alpha), |psi_dot| = omega cos alpha, so phi_dot / |psi_dot| >= 2 at any alpha: the wobble is
  // at least twice the spin, never half. The text's 30 rad/s and 5 deg, and others.
  for (const auto& [w, alpha_deg] : {std::pair{30.0, 5.0}, {31.0, 5.0}, {30.0, 60.0}}) {
    INFO("omega " << w << ", alpha " << alpha_deg);
    Inputs in = preset("frisbee");
    if (w != 30.0) in.omega = w;
    if (alpha_deg != 5.0) in.alpha_deg = alpha_deg;
    const auto plate = compute(in);
    const auto said = errata_at(plate, feynman);
    REQUIRE(said.size() == 1);
    const double c = std::cos(alpha_deg * M_PI / 180);
    const double phi_dot = w * std::sqrt(1 + 3 * c * c), psi_dot = w * c;
    CHECK(phi_dot / psi_dot >= 2);
    CHECK(contains(said[0].correction, "the quote has the ratio upside down"));
    CHECK(contains(said[0].correction,
                   fmt::format("The wobble, phi_dot = {:.6g} rad/s (3 about L in space), is {:.6g} "
                               "times the medallion's spin",
                               phi_dot, phi_dot / psi_dot)));
    // psi_dot = omega_3 - phi_dot cos theta = -omega cos alpha for the plate: its size is
    // said, and the body-frame rate Omega = omega cos alpha (Is - I)/I equals it for Is = 2I.
    CHECK(contains(said[0].correction,
                   fmt::format("|psi_dot| = omega cos alpha = {:.6g} rad/s (equal in size to the "
                               "body-frame rate Omega = {:.6g} rad/s): wobble : spin = 2 : 1",
                               psi_dot, psi_dot)));
  }
  // Another body than the plate (its Is/I changed) is not Feynman's plate.
  Inputs other = preset("frisbee");
  other.moment_ratio = 1.5;
  CHECK(errata_at(compute(other), feynman).empty());
  // The Earth's periods (eqs. 145-147 with Is/I = 1.00327, alpha = 0.2"): Omega = omega cos
  // alpha (Is - I)/I, so 2 pi/Omega is 1/0.00327 sidereal days, in solar days.
  const double sidereal = 86164.0905, solar = 86400.0, k = 0.00327;
  const double alpha = 0.2 / 3600 * M_PI / 180;
  const double body_days = sidereal / (std::cos(alpha) * k) / solar;
  const double space_days =
      sidereal / std::sqrt(1 + ((1 + k) * (1 + k) - 1) * std::cos(alpha) * std::cos(alpha)) / solar;
  const auto said = errata_at(earth, days)[0];
  CHECK(said.printed == "2 pi/Omega = 305 days ... yielding a period of 0.997 days");
  CHECK(contains(said.correction, fmt::format("2 pi/Omega = {:.4g} d and 2 pi/phi_dot = {:.4g} d",
                                              body_days, space_days)));
  // With omega = 2 pi per solar day the same periods are 1/(k cos alpha) and
  // 1/sqrt(1 + ((1 + k)^2 - 1) cos^2 alpha) solar days.
  CHECK(contains(said.correction,
                 fmt::format("solar day (86400 s), they are {:.4g} d and {:.4g} d.",
                             body_days * solar / sidereal, space_days * solar / sidereal)));
  CHECK(
      contains(said.correction,
               "The text's printed 305 needs the sidereal day, its printed 0.997 the solar one."));
  // Beside it, not an erratum: the observed wobble and why it is longer than the rigid one.
  const std::string chandler =
      "The observed free wobble of the Earth, the Chandler wobble, has a period of about 433 "
      "days (the text says 440)";
  CHECK(notes_starting(earth, chandler).size() == 1);
  // Another tilt is not the text's example: neither.
  Inputs tilted = preset("earth");
  tilted.alpha_deg = 1.0;
  CHECK(errata_at(compute(tilted), days).empty());
  CHECK(notes_starting(compute(tilted), chandler).empty());
}

TEST_CASE("football: the answer in short - which cone rolls on which, and how fast") {
  const auto football = compute(Inputs{}).results();
  const std::string prolate = football.at("answer");
  CHECK_THAT(prolate, Catch::StartsWith("prolate"));
  CHECK_THAT(prolate, Catch::Contains("rolls on the outside of the space cone"));
  CHECK_THAT(prolate, Catch::Contains(fmt::format("every {:.4g} s",
                                                  value(football, "space_precession_period_s"))));
  const std::string oblate = compute(preset("frisbee")).results().at("answer");
  CHECK_THAT(oblate, Catch::StartsWith("oblate"));
  CHECK_THAT(oblate, Catch::Contains("rolls round, enclosing the space cone"));
}

TEST_CASE("football: the Earth's periods in days in short, any body's in its own unit") {
  // The text's 0.997 d and 305 d: 2 pi / phi_dot and 2 pi / |Omega| for omega = 2 pi per
  // sidereal day (eqs. 145-147, Is/I = 1.00327, alpha = 0.2"), in days of 86400 s.
  const double sidereal = 86164.0905, k = 0.00327, c = std::cos(0.2 / 3600 * M_PI / 180);
  const double space_days = sidereal / std::sqrt(1 + ((1 + k) * (1 + k) - 1) * c * c) / 86400;
  const double body_days = sidereal / (k * c) / 86400;
  const std::string earth = compute(preset("earth")).results().at("answer");
  CHECK(fmt::format("{:.4g}", space_days) == "0.994");
  CHECK(fmt::format("{:.4g}", body_days) == "305");
  CHECK_THAT(earth, Catch::EndsWith(fmt::format("3 and omega go round L every {:.4g} d, omega "
                                                "round 3 in the body every {:.4g} d",
                                                space_days, body_days)));
  // seconds below 1000 s, hours below half a day, days beyond: each period by its own size
  using rigid::lab::football::readable_period;
  CHECK(readable_period(0.18757) == "0.1876 s");
  CHECK(readable_period(999.94) == "999.9 s");
  CHECK(readable_period(1000.0) == "0.2778 h");
  CHECK(readable_period(43199.0) == "12 h");
  CHECK(readable_period(43200.0) == "0.5 d");
  CHECK(readable_period(2.635e7) == "305 d");
  // a slow body of one's own: its body period in days, its space period in hours
  Inputs slow;
  slow.inertia = Eigen::Vector2d(1, 1.01);
  slow.omega = 2 * M_PI / 7200;  // one turn in two hours
  slow.alpha_deg = 10;
  const auto r = compute(slow).results();
  CHECK_THAT(r.at("answer").get<std::string>(),
             Catch::EndsWith(fmt::format("every {:.4g} h, omega round 3 in the body every {:.4g} d",
                                         value(r, "space_precession_period_s") / 3600,
                                         value(r, "body_precession_period_s") / 86400)));
}

namespace {

// The rates figure's scale on both sides of its threshold: log where one rate is 20 times
// the other or more, linear below.
void check_rate_scale_threshold() {
  using rigid::render::Scale;
  // The scale's threshold, on both sides: phi_dot / |Omega| = sqrt(s^2 + (1 + e)^2 c^2) /
  // (e c) at alpha = 60 deg for Is = (1 + e) I (eqs. 109, 147), 20 at the e found here by
  // bisection (the ratio falls as e grows); a rod (Is = I / 100) at 1 deg, |Omega| / phi_dot =
  // 0.99 c / sqrt(s^2 + 1e-4 c^2) = 49 there, and at 5 deg with Is = I / 10, 6.8.
  const double s60 = std::sqrt(0.75), c60 = 0.5;
  const auto space_over_body = [&](double e) {
    return std::sqrt(s60 * s60 + (1 + e) * (1 + e) * c60 * c60) / (e * c60);
  };
  double lo = 1e-3, hi = 1;
  for (int i = 0; i < 200; ++i) {
    const double mid = (lo + hi) / 2;
    (space_over_body(mid) > 20 ? lo : hi) = mid;
  }
  struct Case {
    double Is, alpha_deg;
    bool log;
  };
  for (const Case& body :
       {Case{1 + lo * (1 - 1e-9), 60, true}, Case{1 + lo * (1 + 1e-9), 60, false},
        Case{0.01, 1, true}, Case{0.1, 5, false}}) {
    INFO("Is = " << body.Is << ", alpha = " << body.alpha_deg);
    Inputs in;
    in.inertia = Eigen::Vector2d(1, body.Is);
    in.alpha_deg = body.alpha_deg;
    KeptFigures f;
    rigid::lab::football::figures(compute(in), f);
    const auto& p = f.plots.at("rates").panel();
    CHECK((p.y.scale == Scale::kLog10) == body.log);
    CHECK(p.x.scale == Scale::kLinear);
    CHECK(p.annotations.size() == (body.log ? 2u : 0u));
  }
}

}  // namespace

TEST_CASE("football: the rates figure shows the Earth's two rates apart, with their periods") {
  using rigid::render::Scale;
  // The Earth: rates 1.00327 and 0.00327 of omega (eqs. 145-147) on a log scale, against log
  // alpha from a decade below its 0.2 arcsec; the run's two points carry their periods.
  const auto earth = compute(preset("earth"));
  KeptFigures figures;
  rigid::lab::football::figures(earth, figures);
  const auto& panel = figures.plots.at("rates").panel();
  CHECK(panel.y.scale == Scale::kLog10);
  CHECK(panel.x.scale == Scale::kLog10);
  const double alpha = 0.2 / 3600, c = std::cos(alpha * M_PI / 180), k = 0.00327;
  REQUIRE(panel.series.size() == 3);
  const auto& points = panel.series[2];
  CHECK(points.x == std::vector<double>{alpha, alpha});
  CHECK(points.y[0] == Approx(std::sqrt(1 + ((1 + k) * (1 + k) - 1) * c * c)).epsilon(kRoundoff));
  // (Is - I)/I from moments 8e37 and 1.00327 times it: ~300 eps (see the periods' test)
  CHECK(points.y[1] == Approx(k * c).epsilon(3e-13));
  // the sweep starts a decade below the run's alpha and ends at 89.5 deg, log-spaced
  const auto& sweep = panel.series[0].x;
  CHECK(sweep.front() == Approx(alpha / 10).epsilon(1e-14));
  CHECK(sweep.back() == Approx(89.5).epsilon(1e-14));
  CHECK(sweep[1] / sweep[0] == Approx(sweep.back() / sweep[sweep.size() - 2]).epsilon(1e-12));
  CHECK(panel.x.min == sweep.front());
  // |Omega| / omega on the log scale: positive everywhere it is drawn
  for (const double y : panel.series[1].y) CHECK(y > 0);
  const double sidereal = 86164.0905;
  REQUIRE(panel.annotations.size() == 2);
  CHECK(panel.annotations[0].text ==
        fmt::format("2\\pi / \\phi-dot = {:.4g} d",
                    sidereal / std::sqrt(1 + ((1 + k) * (1 + k) - 1) * c * c) / 86400));
  CHECK(panel.annotations[0].y == points.y[0]);
  CHECK(panel.annotations[1].text ==
        fmt::format("2\\pi / |\\Omega| = {:.4g} d", sidereal / (k * c) / 86400));
  CHECK(panel.annotations[1].y == points.y[1]);
  // log alpha from just below the sweep's first angle, 0.5 deg; linear from it on
  for (const auto& [alpha_deg, log] : {std::pair{std::nextafter(0.5, 0.0), true}, {0.5, false}}) {
    Inputs in = preset("earth");
    in.alpha_deg = alpha_deg;
    KeptFigures f;
    rigid::lab::football::figures(compute(in), f);
    CHECK((f.plots.at("rates").panel().x.scale == Scale::kLog10) == log);
  }
  // The football's rates are of one size: linear, signed, no annotations (its committed figure).
  KeptFigures ball;
  rigid::lab::football::figures(compute(Inputs{}), ball);
  const auto& linear = ball.plots.at("rates").panel();
  CHECK(linear.y.scale == Scale::kLinear);
  CHECK(linear.x.scale == Scale::kLinear);
  CHECK(linear.annotations.empty());
  CHECK(linear.series[2].y[1] < 0);  // prolate: Omega against omega_3
  check_rate_scale_threshold();
}
