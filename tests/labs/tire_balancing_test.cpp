// tire_balancing's library in-process: the text's numbers at its defaults,
// another wheel against eqs. 55-61 typed here, the road's spin, and the turn
// of L and the torque its CSV holds.
#include "tire_balancing/tire_balancing.h"

#include <fmt/format.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cfloat>
#include <cmath>

#include "lab_library.h"
#include "rigid/format.h"
#include "rigid/units.h"

using Catch::Matchers::WithinAbs;
using rigid::rad_to_deg;
using rigid::lab::tire_balancing::compute;
using rigid::lab::tire_balancing::Inputs;
using rigid::test::kRoundoff;
using rigid::test::value;

TEST_CASE("tire_balancing: defaults give both balancing masses") {
  const auto report = compute(Inputs{});
  const auto& r = report.results();
  REQUIRE(r.contains("balance_mass_kg"));
  REQUIRE(r.contains("balance_mass_small_angle_kg"));
  // Small angle: theta a m / (8 b) for the text's inputs, computed here independently.
  const double theta = 1.0 * 3.14159265358979323846 / 180.0;
  CHECK_THAT(value(r, "balance_mass_small_angle_kg"),
             WithinAbs(theta * 0.18 * 10 / 0.4, kRoundoff));
  CHECK(value(r, "balance_mass_kg") > value(r, "balance_mass_small_angle_kg"));
  CHECK(value(r, "residual_tilt_exact_deg") < 8 * DBL_EPSILON);
  CHECK(value(r, "torque_balanced_nm") < 1e-9 * value(r, "torque_unbalanced_nm"));
}

TEST_CASE("tire_balancing: the time series is one turn of L and the torque") {
  const auto report = compute(Inputs{});
  const auto& series = report.time_series();
  CHECK(series.names() == std::vector<std::string>{"t_s", "Lx", "Ly", "Lz", "Nx", "Ny", "Nz"});
  CHECK(series.rows.size() == 361);
}

TEST_CASE("tire_balancing: every row's torque is dL/dt, normal to L, of the reported size") {
  const auto report = compute(Inputs{});
  const double torque = value(report.results(), "torque_unbalanced_nm");
  const auto& rows = report.time_series().rows;
  REQUIRE(rows.size() > 2);
  for (std::size_t k = 1; k + 1 < rows.size(); ++k) {
    const auto& v = rows[k];
    const Eigen::Vector3d L(v[1], v[2], v[3]), N(v[4], v[5], v[6]);
    // |N| constant, N normal to L (L sweeps a cone at constant length). N.L is bounded by the
    // dot product's a-priori rounding, 3 eps |N| |L|: the 5e-18 reached here is luck of
    // cancellation, not a bound a test can rely on.
    CHECK(N.norm() == Approx(torque).epsilon(32 * DBL_EPSILON));
    CHECK(std::abs(N.dot(L)) <= 3 * DBL_EPSILON * N.norm() * L.norm());
    // N = dL/dt, by the central difference over the neighbouring rows (error h^2 / 6 |L'''|,
    // with 360 rows a turn: (2 pi / 360)^2 / 6 = 5e-5 of |N|)
    const auto& a = rows[k - 1];
    const auto& b = rows[k + 1];
    const Eigen::Vector3d dL =
        (Eigen::Vector3d(b[1], b[2], b[3]) - Eigen::Vector3d(a[1], a[2], a[3])) / (b[0] - a[0]);
    CHECK((dL - N).norm() <= 1e-4 * torque);
  }
}

TEST_CASE("tire_balancing: another wheel against eqs. 55-61 typed here") {
  constexpr double kDeg = M_PI / 180;
  const double m = 12, a = 0.3, b = 0.08, theta = 3 * kDeg, omega = 50;
  Inputs in;
  in.mass = m, in.radius = a, in.offset = b, in.tilt_deg = 3, in.omega = omega;
  const auto report = compute(in);
  const auto& r = report.results();
  // The disk's symmetry axis is x, the axle (cos, sin, 0): L = omega (m a^2/2 cos, m a^2/4 sin, 0).
  const double Lx = m * a * a / 2 * std::cos(theta), Ly = m * a * a / 4 * std::sin(theta);
  CHECK(value(r, "angle_L_axle_deg") ==
        Approx(theta / kDeg - std::atan2(Ly, Lx) / kDeg).epsilon(16 * DBL_EPSILON));
  // |omega x L| = omega^2 m a^2 sin(2 theta) / 8.
  CHECK(value(r, "torque_unbalanced_nm") ==
        Approx(omega * omega * m * a * a * std::sin(2 * theta) / 8).epsilon(kRoundoff));
  // Eq. 60 solved for m0: tan 2theta (m a^2/4 + 2 m0 (a^2 - b^2)) = 4 a b m0.
  const double t = std::tan(2 * theta);
  CHECK(value(r, "balance_mass_kg") ==
        Approx(t * m * a * a / 4 / (4 * a * b - 2 * t * (a * a - b * b))).epsilon(kRoundoff));
  // Eq. 61: theta = 8 b m0 / (a m).
  CHECK(value(r, "balance_mass_small_angle_kg") ==
        Approx(theta * a * m / (8 * b)).epsilon(kRoundoff));
  // Balanced exactly: the principal axis on the axle and no torque, to roundoff.
  CHECK(value(r, "residual_tilt_exact_deg") < 16 * DBL_EPSILON);
  CHECK(value(r, "torque_balanced_nm") <= 1e-13 * value(r, "torque_unbalanced_nm"));
  CHECK(value(r, "residual_tilt_small_angle_deg") > 1e-3);
}

TEST_CASE("tire_balancing: a straight axle is a balanced wheel, and the spin comes from the road") {
  Inputs in;
  in.tilt_deg = 0, in.road_speed = 27.8, in.tire_radius = 0.31;
  const auto report = compute(in);
  const auto& r = report.results();
  CHECK(value(r, "omega_rad_s") == Approx(27.8 / 0.31).epsilon(kRoundoff));
  CHECK(value(r, "road_speed_km_h") == Approx(100.08).epsilon(kRoundoff));
  // No tilt: L along the axle, no torque, no mass needed (all exactly: the disk's axis is x).
  CHECK(value(r, "angle_L_axle_deg") == 0.0);
  CHECK(value(r, "torque_unbalanced_nm") == 0.0);
  CHECK(value(r, "balance_mass_kg") == 0.0);
  CHECK(value(r, "balance_mass_small_angle_kg") == 0.0);
  CHECK(!report.inputs().contains("omega"));
  // A road speed gives the same wheel as its omega.
  Inputs road, direct;
  road.road_speed = 27.9, road.tire_radius = 0.31;
  direct.omega = 27.9 / 0.31;
  CHECK(value(compute(road).results(), "torque_unbalanced_nm") ==
        Approx(value(compute(direct).results(), "torque_unbalanced_nm")).epsilon(kRoundoff));
  // Roundoff is shown as 0 with its bound in the table; the JSON keeps the number.
  bool roundoff_shown = false;
  const auto defaults = compute(Inputs{});
  for (const auto& row : defaults.rows()) {
    roundoff_shown = roundoff_shown || row.remark.rfind("(roundoff: |computed| <=", 0) == 0;
  }
  CHECK(roundoff_shown);
}

TEST_CASE("tire_balancing: the balanced torque's roundoff bound is a few ulps of omega^2 |I|") {
  // The torque omega x I omega of the balanced wheel is roundoff of terms omega^2 I_max:
  // shown as 0 below 64 eps omega^2 I_max and no looser. I_max <= the disk's axial
  // moment m a^2 / 2 plus both masses' 2 m0 (a^2 + b^2). Across tilts and speeds.
  const std::string shown = "(roundoff: |computed| <= ";
  for (const double tilt : {0.5, 3.0, 10.0}) {
    for (const double omega : {1.0, 90.0, 3000.0}) {
      INFO("tilt " << tilt << " deg, omega " << omega);
      Inputs in;
      in.tilt_deg = tilt, in.omega = omega;
      const auto report = compute(in);
      const double m0 = value(report.results(), "balance_mass_kg");
      const double a = in.radius, b = in.offset;
      const double I_max = in.mass * a * a / 2 + 2 * m0 * (a * a + b * b);
      const double computed = value(report.results(), "torque_balanced_n_m");
      bool found = false;
      for (const auto& row : report.rows()) {
        if (row.label != "bearing torque after balancing") continue;
        found = true;
        REQUIRE(row.remark.rfind(shown, 0) == 0);
        CHECK(row.value == "0");
        const double bound = std::stod(row.remark.substr(shown.size()));
        CHECK(std::abs(computed) <= bound * 1.05);  // the remark's two digits
        CHECK(bound <= 64 * DBL_EPSILON * omega * omega * I_max * 1.05);
      }
      CHECK(found);
    }
  }
}

TEST_CASE("tire_balancing: a broken rule is an InputError naming the input") {
  Inputs in;
  // The tilt's rule is [0, 45) deg, said as such at 45 (tan 2 theta is infinite); just
  // below, the rule of eq. 60 that no mass reaches the tilt.
  in.tilt_deg = 45;
  CHECK_THROWS_MATCHES(compute(in), rigid::lab::InputError, rigid::test::names_input("--tilt-deg"));
  CHECK_THROWS_WITH(compute(in),
                    Catch::StartsWith("--tilt-deg: must be at least 0 and below 45 deg"));
  in.tilt_deg = std::nextafter(45.0, 0.0);
  // Eq. 60's rule joins the tilt, the offset and the radius: the error names all three
  // (the command line then names those given).
  CHECK_THROWS_WITH(compute(in), Catch::StartsWith("--tilt-deg, --offset, --radius: no balancing "
                                                   "mass reaches"));
  try {
    compute(in);
  } catch (const rigid::lab::InputError& e) {
    CHECK(e.joint == std::vector<std::string>{"--tilt-deg", "--offset", "--radius"});
    CHECK(e.rule.rfind("no balancing mass reaches this tilt", 0) == 0);
  }
  in = Inputs{};
  in.tire_radius = 0.1, in.road_speed = 10;  // smaller than the disk
  CHECK_THROWS_MATCHES(compute(in), rigid::lab::InputError,
                       rigid::test::names_input("--tire-radius"));
  in = Inputs{};
  in.mass = -1;
  CHECK_THROWS_MATCHES(compute(in), rigid::lab::InputError, rigid::test::names_input("--mass"));
}

TEST_CASE(
    "tire_balancing: the errata note quotes both masses, each its own, for the text's wheel") {
  // eq. 61 (small angle) and eq. 60 (exact) evaluated here for m = 10 kg, a = 18 cm,
  // b = 5 cm, theta = 1 deg; the note prints them in grams to one decimal
  const double m = 10, a = 0.18, b = 0.05, theta = M_PI / 180, t = std::tan(2 * theta);
  const double small = theta * a * m / (8 * b);
  const double exact = t * m * a * a / 4 / (4 * a * b - 2 * t * (a * a - b * b));
  const auto report = compute(Inputs{});
  REQUIRE(report.notes().size() == 1);
  REQUIRE(report.errata().size() == 1);
  const auto& erratum = report.errata()[0];
  CHECK(erratum.where == "section 2.3, eqs. 60-61");
  CHECK(erratum.printed == "we find the required balancing masses to be m0 = 76 grams");
  CHECK(erratum.correction ==
        fmt::format("its own small-angle formula (eq. 61) gives {:.1f} g and the exact eq. 60 "
                    "gives {:.1f} g for m = 10 kg, a = 18 cm, b = 5 cm, theta = 1 deg",
                    1e3 * small, 1e3 * exact));
  CHECK(report.notes()[0] ==
        "errata: section 2.3, eqs. 60-61: the text prints \"we find the "
        "required balancing masses to be m0 = 76 grams\"; " +
            erratum.correction);
  // Another wheel is not the text's: no errata, no printed values.
  Inputs other;
  other.tilt_deg = 2;
  const auto changed = compute(other);
  CHECK(changed.notes().empty());
  CHECK(changed.errata().empty());
  CHECK(changed.textbook_printed().empty());
}

TEST_CASE("tire_balancing: the answer in short, with the numbers that decide it") {
  const auto r = compute(Inputs{}).results();
  const std::string answer = r.at("answer");
  CHECK_THAT(answer, Catch::Contains("unbalanced"));
  CHECK_THAT(answer,
             Catch::Contains(fmt::format("|N| = {:.4g} N m", value(r, "torque_unbalanced_n_m"))));
  CHECK_THAT(answer, Catch::Contains(fmt::format("{:.4g} g", 1e3 * value(r, "balance_mass_kg"))));
  Inputs straight;
  straight.tilt_deg = 0;
  CHECK_THAT(compute(straight).results().at("answer").get<std::string>(),
             Catch::Contains("balanced already"));
}

TEST_CASE("tire_balancing: tilts from 1e-300 deg to an ulp short of the limit, against mpmath") {
  // tests/labs/references/tire_balancing/make_reference.py: eqs. 57-61 at 60 digits beyond each
  // tilt's exponent, the text's way (eq. 60 through tan 2 theta, the axis from atan2 of the
  // tensor's entries), from the double inputs.
  struct Row {
    double m, a, b, omega, tilt_deg;
    double exact_g, small_g, small_residual_deg, per_mass, angle_L_deg, torque;
  };
  const Row rows[] = {
#include "references/tire_balancing/reference_tilts.inc"
  };
  constexpr double eps = DBL_EPSILON;
  const auto relative = [](double x, double ref) { return ref == 0 ? x : std::abs(x / ref - 1); };
  for (const Row& row : rows) {
    INFO("m = " << row.m << ", a = " << row.a << ", b = " << row.b << ", tilt "
                << fmt::format("{:.17g}", row.tilt_deg) << " deg");
    rigid::CrookedWheel wheel{row.m, row.a, row.b};
    wheel.set_tilt_deg(row.tilt_deg);
    // Core at any tilt. Eq. 60's m0 formed in quadruple precision and rounded once: within
    // an ulp (2 eps relative) even where b cos theta - a sin theta keeps 1e-16 of its size.
    const double m0 = rigid::balance_mass_exact(wheel);
    CHECK(relative(1e3 * m0, row.exact_g) <= 2 * eps);
    // Eq. 61: theta (one rounding from degrees) a m / (8 b): five roundings in all.
    CHECK(relative(1e3 * rigid::balance_mass_small_angle(wheel), row.small_g) <= 5 * eps);
    // Eq. 61's mass taken exactly misses by about theta^2 (a^2 - b^2)/(a b): from a Quad ratio,
    // then atan and degrees in double (a few roundings); 0 where that underflows a double.
    const double small = rad_to_deg(rigid::small_angle_misalignment(wheel));
    CHECK(relative(small, row.small_residual_deg) <= 4 * eps);
    // The double m0 misses eq. 60 by at most an ulp (2 eps relative, above): the axis then
    // turns by no more than 2 eps d phi / d ln m0. d phi / d ln m0 itself, to its Quad's digits
    // (mpmath's derivative is good to 1e-40).
    CHECK(rigid::misalignment_per_mass(wheel, m0) == Approx(row.per_mass).epsilon(4 * eps));
    const double residual = rigid::principal_axis_misalignment(wheel, m0);
    CHECK(residual <= 2 * eps * row.per_mass);
    // The lab, where its rules allow the tilt (1e-60 to 45 deg).
    if (row.tilt_deg < 1e-60) continue;
    Inputs in;
    in.mass = row.m, in.radius = row.a, in.offset = row.b, in.tilt_deg = row.tilt_deg;
    in.omega = row.omega;
    const auto r = compute(in).results();
    CHECK(value(r, "balance_mass_kg") == m0);
    CHECK(relative(value(r, "residual_tilt_small_angle_deg"), row.small_residual_deg) <= 4 * eps);
    CHECK(value(r, "residual_tilt_exact_deg") <= rad_to_deg(2 * eps * row.per_mass));
    // angle_between's atan2 of a scaled cross and dot product, and |omega x I omega|: a few
    // roundings each (measured at most 2 eps).
    CHECK(relative(value(r, "angle_L_axle_deg"), row.angle_L_deg) <= 8 * eps);
    CHECK(relative(value(r, "torque_unbalanced_n_m"), row.torque) <= 8 * eps);
    // The torque the double m0 leaves: its ulp's share of the unbalanced torque, eps.
    CHECK(value(r, "torque_balanced_n_m") <= eps * row.torque * (1 + 8 * eps));
  }
}

TEST_CASE("tire_balancing: a tilt past eq. 60's limit atan(b/a) is refused with both angles") {
  // The text's wheel: no mass reaches a tilt of atan(b/a) = atan(5/18) or more. The largest
  // double below it runs (m0 = 2.7e16 kg, in the reference above); four ulps above (past the
  // rounding of atan and of degrees) is refused with the rule and both angles.
  const double limit = std::atan2(0.05, 0.18) * 180 / M_PI;
  Inputs in;
  in.tilt_deg = limit;
  for (int k = 0; k < 4; ++k) in.tilt_deg = std::nextafter(in.tilt_deg, 90.0);
  CHECK_THROWS_WITH(compute(in),
                    Catch::StartsWith("--tilt-deg, --offset, --radius: no balancing mass reaches "
                                      "this tilt: need a tan theta < b") &&
                        Catch::Contains(fmt::format("got theta = {} deg against atan(b/a) = {} deg",
                                                    rigid::format_number(in.tilt_deg, 10),
                                                    rigid::format_number(limit, 10))));
  in.tilt_deg = limit * (1 - 1e-12);
  CHECK(value(compute(in).results(), "balance_mass_kg") > 1e9);
}
