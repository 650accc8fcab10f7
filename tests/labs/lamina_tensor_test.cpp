// lamina_tensor's library in-process: the text's numbers at its defaults (sections
// 1-2.4 and 3.1), other plates and axes against eqs. 20-76 typed here, section
// 2.1's bodies, tiny and huge plates, the table's textbook column, and the rules.
#include "lamina_tensor/lamina_tensor.h"

#include <fmt/format.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <sstream>

#include "common/writers.h"
#include "lab_library.h"

using Catch::Matchers::WithinAbs;
using rigid::lab::lamina_tensor::compute;
using rigid::lab::lamina_tensor::Inputs;
using rigid::test::kRoundoff;
using rigid::test::prints_as;
using rigid::test::value;

namespace {
// Counts the figures handed over, by kind.
struct CountingSink : rigid::lab::FigureSink {
  int plots = 0, scenes = 0;
  void add(const std::string&, const std::string&, rigid::render::Plot2D) override { ++plots; }
  void add(const std::string&, const std::string&, rigid::render::Scene3D) override { ++scenes; }
};
}  // namespace

TEST_CASE("lamina_tensor: defaults reproduce sections 1-2.4") {
  const auto report = compute(Inputs{});
  CHECK(report.lab() == "lamina_tensor");
  for (const char* key : {"mass", "a", "b", "origin", "axis", "omega"})
    CHECK(report.inputs().contains(key));
  const auto& r = report.results();
  for (const char* key :
       {"inertia_tensor", "scalar_moment", "angular_momentum", "angle_L_omega_deg",
        "kinetic_energy", "principal_moments", "principal_axes", "fixed_axis_torque"}) {
    CHECK(r.contains(key));
  }
  CHECK(prints_as(r["scalar_moment"], 0.493, 3));
  CHECK(prints_as(r["angle_L_omega_deg"], 51.0, 0));
  CHECK(prints_as(r["principal_moments"][0], 0.126, 3));
  CHECK(prints_as(r["principal_moments"][1], 1.540, 3));
  CHECK(prints_as(r["principal_moments"][2], 1.667, 3));
  CHECK_THAT(double(r["principal_angle_deg"]), WithinAbs(-22.5, 22.5 * kRoundoff));
  CHECK_THAT(double(r["principal_angle_other_deg"]), WithinAbs(67.5, 67.5 * kRoundoff));
}

TEST_CASE("lamina_tensor: an axis of any length is normalised: --axis 3,4,0 is (0.6, 0.8, 0)") {
  Inputs in;
  in.axis = rigid::Vec3(3, 4, 0), in.omega = 2;
  const auto report = compute(in);
  const auto& r = report.results();
  // The corner tensor of a 1 x 2 plate of mass 1 (eq. 20): (4/3, -1/2; -1/2, 1/3), Izz 5/3.
  const double n[2] = {0.6, 0.8}, w = 2;
  const double Lx = w * (4.0 / 3 * n[0] - 0.5 * n[1]), Ly = w * (-0.5 * n[0] + 1.0 / 3 * n[1]);
  CHECK(double(r["angular_momentum"][0]) == Approx(Lx).epsilon(kRoundoff));
  CHECK(double(r["angular_momentum"][1]) == Approx(Ly).epsilon(kRoundoff));
  CHECK(double(r["scalar_moment"]) ==
        Approx(4.0 / 3 * n[0] * n[0] - n[0] * n[1] + 1.0 / 3 * n[1] * n[1]).epsilon(kRoundoff));
  CHECK(double(r["kinetic_energy"]) ==
        Approx(0.5 * w * (Lx * n[0] + Ly * n[1])).epsilon(kRoundoff));
}

TEST_CASE("lamina_tensor: --axis 1,0,0 needs the section 3.1 torque 0.500 ma^2 omega^2") {
  Inputs in;
  in.axis = rigid::Vec3(1, 0, 0);
  const auto report = compute(in);
  const auto& N = report.results()["fixed_axis_torque"];
  CHECK_THAT(double(N[0]), WithinAbs(0.0, kRoundoff));
  CHECK_THAT(double(N[1]), WithinAbs(0.0, kRoundoff));
  // Errata: the size is the text's 0.500, the sign negative (eq. 76 with its axes).
  CHECK(prints_as(double(N[2]), -0.500, 3));
}

TEST_CASE("lamina_tensor: the human table shows the textbook column and errata") {
  const auto report = compute(Inputs{});
  std::ostringstream table;
  rigid::lab::write_table(table, report, {});
  const std::string out = table.str();
  CHECK(out.find("textbook") != std::string::npos);
  CHECK(out.find("0.493 ma^2") != std::string::npos);
  CHECK(out.find("errata") != std::string::npos);
}

TEST_CASE("lamina_tensor: section 3.1's rotation about x is always reported, beside --axis") {
  // N = x × (I x) with I's first column (4/3, -1/2, 0) m a^2: (0, 0, -1/2) m a^2 omega^2,
  // and z is the third principal axis. Roundoff of the eigen-solver: a few ulps.
  Inputs along_z;
  along_z.axis = rigid::Vec3(0, 0, 1);
  for (const Inputs& in : {Inputs{}, along_z}) {
    INFO("axis " << in.axis.transpose());
    const auto report = compute(in);
    const auto& N = report.results()["fixed_axis_torque_x_principal"];
    CHECK_THAT(double(N[0]), WithinAbs(0.0, kRoundoff));
    CHECK_THAT(double(N[1]), WithinAbs(0.0, kRoundoff));
    CHECK_THAT(double(N[2]), WithinAbs(-0.5, kRoundoff));
  }
  const auto report = compute(Inputs{});
  CHECK(report.units()["fixed_axis_torque_x_principal"] == "N m");
  CHECK(report.units()["inertia_tensor"] == "kg m^2");
  CHECK(report.units()["principal_axes"] == "1");
}

TEST_CASE(
    "lamina_tensor: the paddle and the block at other inputs, against eqs. 40-43 typed here") {
  const double m = 3, a = 0.4, b = 0.9, c = 0.25;
  Inputs in;
  in.mass = m, in.a = a, in.b = b, in.c = c, in.examples = true;
  const auto report = compute(in);
  const auto& r = report.results();
  // The model paddle (section 2.1): (1/8, 31/24, 17/12) m a^2 about its centre of mass.
  const double paddle[] = {m * a * a / 8, 31.0 / 24 * m * a * a, 17.0 / 12 * m * a * a};
  // The block a x b x c (eq. 40): m (b^2 + c^2)/12, m (a^2 + c^2)/12, m (a^2 + b^2)/12.
  const double block[] = {m * (b * b + c * c) / 12, m * (a * a + c * c) / 12,
                          m * (a * a + b * b) / 12};
  // The moments come from the eigensolver: its backward error eps |I| is relative
  // eps |I| / I_k on the k-th, up to 11 eps on the paddle's 1/8 beside 17/12.
  for (int i = 0; i < 3; ++i) {
    CHECK(double(r["paddle_principal_moments"][i]) == Approx(paddle[i]).epsilon(kRoundoff));
    CHECK(double(r["block_principal_moments"][i]) == Approx(block[i]).epsilon(kRoundoff));
  }
  // The cube of side a: m a^2 / 6 about any axis through its centre (the diagonal too).
  CHECK(double(r["cube_moment_about_axis"]) == Approx(m * a * a / 6).epsilon(12 * DBL_EPSILON));
  CHECK(double(r["cube_moment_about_diagonal"]) == Approx(m * a * a / 6).epsilon(12 * DBL_EPSILON));
  // --c sets only the block: given without --examples it shows section 2.1 rather than
  // be silently ignored; without either, another plate has no section 2.1.
  in.examples = false;
  CHECK(double(compute(in).results()["block_principal_moments"][0]) ==
        Approx(block[0]).epsilon(kRoundoff));
  in.c = Inputs{}.c;
  CHECK(!compute(in).results().contains("block_principal_moments"));
}

TEST_CASE("lamina_tensor: the plate about its diagonal, or an axis by its angle in the plane") {
  // A 1 x 2 plate of mass 1 about its corner: I = (4/3, -1/2; -1/2, 1/3), Izz = 5/3 (eq. 20).
  Inputs diagonal;
  diagonal.axis_word = "diagonal";
  const auto diag = compute(diagonal);
  const auto& r = diag.results();
  const double n[2] = {1 / std::sqrt(5.0), 2 / std::sqrt(5.0)};
  CHECK(double(r["axis_unit"][0]) == Approx(n[0]).epsilon(kRoundoff));
  CHECK(double(r["axis_unit"][1]) == Approx(n[1]).epsilon(kRoundoff));
  // n.I.n = (4/3 - 2 + 4/3) / 5 = 2/15 (terms of 2 cancelling to 2/3: 7x the roundings); L = I n;
  // about the corner's diagonal the products of inertia do not vanish, so L is off the axis.
  CHECK(value(r, "scalar_moment") == Approx(2.0 / 15).epsilon(16 * DBL_EPSILON));
  const double Lx = 4.0 / 3 * n[0] - 0.5 * n[1], Ly = -0.5 * n[0] + 1.0 / 3 * n[1];
  CHECK(double(r["angular_momentum"][0]) == Approx(Lx).epsilon(kRoundoff));
  CHECK(double(r["angular_momentum"][1]) == Approx(Ly).epsilon(kRoundoff));
  CHECK(value(r, "angle_L_omega_deg") ==
        Approx(std::acos((Lx * n[0] + Ly * n[1]) / std::hypot(Lx, Ly)) * 180 / M_PI)
            .epsilon(kRoundoff));
  CHECK(diag.inputs()["axis"] == "diagonal");
  CHECK(!r.contains("paddle_principal_moments"));  // section 2.1 only when asked
  // About the centre the diagonal is no principal axis either (a != b), but Ixy = 0 there.
  Inputs at_30;
  at_30.axis_deg = 30;
  const auto angle = compute(at_30);
  CHECK(double(angle.results()["axis_unit"][0]) == Approx(std::sqrt(3.0) / 2).epsilon(kRoundoff));
  CHECK(value(angle.results(), "axis_angle_from_x_deg") == Approx(30).epsilon(kRoundoff));
  // The angle sets the axis: --axis is not among the inputs used, --axis-deg is.
  CHECK(!angle.inputs().contains("axis"));
  CHECK(angle.inputs()["axis_deg"] == 30.0);
}

TEST_CASE("lamina_tensor: tiny and huge legal inputs give true norms and angles") {
  // |L| of a 1e-60 m plate turning at 1e-60 rad/s is 1.2e-241 kg m^2/s: its square
  // underflows, so an unscaled norm printed 0 and the angle 0; at 1e60 it overflowed.
  for (const double s : {1e-60, 1e60}) {
    INFO(s);
    Inputs in;
    in.mass = s, in.a = s, in.b = s, in.omega = s;
    const auto report = compute(in);
    const auto& r = report.results();
    const double Lx = r["angular_momentum"][0], Ly = r["angular_momentum"][1];
    const double m = std::max(std::abs(Lx), std::abs(Ly));
    CHECK(double(r["angular_momentum_magnitude"]) ==
          Approx(m * std::hypot(Lx / m, Ly / m)).epsilon(kRoundoff));
    // A square plate about (0.8, 0.6, 0): L lies along x, so L makes acos(0.8) with omega
    // (acos amplifies a rounding of its argument by 0.8 / 0.6 / acos(0.8) = 2.1).
    CHECK(double(r["angle_L_omega_deg"]) ==
          Approx(std::acos(0.8) * 180 / M_PI).epsilon(16 * DBL_EPSILON));
  }
}

TEST_CASE("lamina_tensor: the text's inputs by value, and what the figures are drawn from") {
  // The text's example is its inputs' values: giving a default (--mass 1) keeps the
  // textbook column; a numerical switch (--examples) does too; another plate drops it.
  Inputs same;
  same.mass = 1.0, same.examples = true;
  CHECK(compute(same).textbook_inputs());
  CHECK(!compute(same).textbook_printed().empty());
  Inputs other;
  other.b = 1.5;
  const auto report = compute(other);
  CHECK(!report.textbook_inputs());
  CHECK(!report.results().contains("paddle_principal_moments"));
  CHECK(report.notes().empty());  // the errata speak of the text's plate only
  // The figures' plate and axis are the run's: the centred plate about n along y.
  Inputs centred;
  centred.origin = "center", centred.axis_deg = 90;
  const auto c = compute(centred);
  CHECK(!c.corner);
  CHECK(c.n.isApprox(rigid::Vec3(0, 1, 0), 1e-15));
  CHECK(c.I(0, 1) == 0.0);  // about the centre, Ixy vanishes (eq. 70)
  CHECK(c.a == 1.0);
  CHECK(c.b == 2.0);
  // Every figure is handed over, at the text's inputs and at the extremes of the rules
  // (at 1e60 |I n|^2 overflowed and L's arrow had no length).
  for (const double s : {1.0, 1e-60, 1e60}) {
    INFO(s);
    Inputs in;
    in.mass = s, in.a = s, in.b = s;
    const auto run = compute(in);
    CountingSink sink;
    rigid::lab::lamina_tensor::figures(run, sink);
    CHECK(sink.scenes == 1);
    CHECK(sink.plots == 1);
  }
}

TEST_CASE("lamina_tensor: a broken rule is an InputError naming the input") {
  using rigid::test::names_input;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const auto refused = [](const Inputs& in, const char* input) {
    INFO(input);
    CHECK_THROWS_MATCHES(compute(in), rigid::lab::InputError, names_input(input));
  };
  for (const double mass : {-1.0, 0.0, nan, inf, 1e308}) {
    Inputs in;
    in.mass = mass;
    refused(in, "--mass");
  }
  Inputs in;
  in.a = 0;
  refused(in, "--a");
  in = Inputs{};
  in.b = -2;
  refused(in, "--b");
  in = Inputs{};
  in.c = 0;
  refused(in, "--c");
  in = Inputs{};
  in.axis = rigid::Vec3::Zero();
  refused(in, "--axis");
  in = Inputs{};
  in.axis = rigid::Vec3(1e-300, 0, 0);
  refused(in, "--axis");
  in = Inputs{};
  in.axis_word = "diag";
  refused(in, "--axis");
  in = Inputs{};
  in.origin = "middle";
  refused(in, "--origin");
  in = Inputs{};
  in.axis_deg = nan;
  refused(in, "--axis-deg");
  for (const double omega : {nan, 1e200, 0.0}) {
    in = Inputs{};
    in.omega = omega;
    refused(in, "--omega");
  }
}

TEST_CASE(
    "lamina_tensor: the three errata carry the plate's own numbers, and only for the text's") {
  // The text's plate: m = a = 1, b = 2 a, corner origin, n = (0.8, 0.6, 0). Eq. 20 here:
  // Ixx = m b^2/3, Iyy = m a^2/3, Ixy = -m a b/4 (in units of m a^2).
  const double Ixx = 4.0 / 3, Iyy = 1.0 / 3, Ixy = -0.5;
  const double Lx = Ixx * 0.8 + Ixy * 0.6, Ly = Ixy * 0.8 + Iyy * 0.6;
  // The in-plane principal moments of the 2x2 block, and the axis of the larger:
  // (Ixx - I) cos + Ixy sin = 0.
  const double mean = (Ixx + Iyy) / 2, half = std::hypot((Ixx - Iyy) / 2, Ixy);
  const double large = mean + half, small = mean - half;
  const double large_deg = std::atan(-(Ixx - large) / Ixy) * 180 / M_PI;
  const auto report = compute(Inputs{});
  // where each is, what the text prints (quoted), and the correction with the plate's numbers
  const std::vector<rigid::lab::Erratum> expected = {
      // the text's |L| from L_x to three digits and L_y to two, as it prints them
      {"section 1.1, after eq. 28", "The magnitude of this (L) is 0.793ma^2 omega",
       fmt::format("|L| = {:.4f} ma^2 omega exactly; 0.793 comes from rounding L_x to {:.3f} "
                   "before taking the norm (|({:.3f}, {:.2f}, 0)| = {:.4f})",
                   std::hypot(Lx, Ly), std::round(1e3 * Lx) / 1e3, std::round(1e3 * Lx) / 1e3,
                   std::round(1e2 * Ly) / 1e2,
                   std::hypot(std::round(1e3 * Lx) / 1e3, std::round(1e2 * Ly) / 1e2))},
      {"section 2.3, after eq. 56",
       "So the 1-axis is at -22 deg and the 2-axis is at 67.5 deg relative to the original x-axis",
       fmt::format("the axis at {:.1f} deg has the moment {:.3f} ma^2, I2 when moments ascend (as "
                   "in the text's own section 2.4); the axis at {:.1f} deg carries I1 = {:.3f} "
                   "ma^2",
                   large_deg, large, large_deg + 90, small)},
      // about +x: N = x cross (I x) = (0, 0, Ixy) m a^2 omega^2
      {"section 3.1, after eq. 77", "we find N1 = N2 = 0, N3 = 0.500 ma^2 omega^2",
       fmt::format("for rotation about +x, N3 = omega1 omega2 (I2 - I1) = {:.3f} ma^2 omega^2: the "
                   "right size with the wrong sign; the axle pushes along -z",
                   Ixy)}};
  REQUIRE(report.errata().size() == expected.size());
  std::vector<std::string> notes;
  for (std::size_t k = 0; k < expected.size(); ++k) {
    CHECK(report.errata()[k].where == expected[k].where);
    CHECK(report.errata()[k].printed == expected[k].printed);
    CHECK(report.errata()[k].correction == expected[k].correction);
    notes.push_back("errata: " + expected[k].where + ": the text prints \"" + expected[k].printed +
                    "\"; " + expected[k].correction);
  }
  CHECK(report.notes() == notes);
  // Any other plate is not the text's example: no errata.
  Inputs other;
  other.b = 3.0;
  CHECK(compute(other).notes().empty());
  CHECK(compute(other).errata().empty());
  Inputs centred;
  centred.origin = "center";
  CHECK(compute(centred).notes().empty());
  CHECK(compute(centred).errata().empty());
}

TEST_CASE("lamina_tensor: the answer in short, with the numbers that decide it") {
  const auto report = compute(Inputs{});
  const auto& r = report.results();
  const std::string answer = r.at("answer");
  CHECK_THAT(answer, Catch::Contains(
                         fmt::format("L is {:.3g} deg from omega", value(r, "angle_L_omega_deg"))));
  CHECK_THAT(answer, Catch::Contains("not a principal axis"));
  // the table's first rows
  REQUIRE(report.rows().size() > 2);
  CHECK(report.rows()[0].heading);
  CHECK(report.rows()[1].value == answer);
  // about a principal axis (the in-plane one at -22.5 deg), no torque
  Inputs principal;
  principal.axis_deg = value(r, "principal_angle_deg");
  CHECK_THAT(compute(principal).results().at("answer").get<std::string>(),
             Catch::Contains("L is along omega"));
}
