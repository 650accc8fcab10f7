// Each lab's own contract: its JSON keys, the text's numbers at its defaults,
// and exit status 2 with one line naming the option for its own bad input
// (what every lab shares is in contract_test.cpp).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>

#include "lab_common.h"

using Catch::Matchers::WithinAbs;
using rigid::test::run_lab;

namespace {
// Half a unit in the last place the text prints.
bool prints_as(double value, double printed, int decimals) {
  return std::abs(value - printed) <= 0.5 * std::pow(10.0, -decimals) + 1e-12;
}
}  // namespace

TEST_CASE("lamina_tensor: defaults reproduce sections 1-2.4") {
  const auto run = run_lab("lamina_tensor", "--json");
  REQUIRE(run.status == 0);
  const auto j = run.json();
  CHECK(j["lab"] == "lamina_tensor");
  for (const char* key : {"mass", "a", "b", "origin", "axis", "omega"})
    CHECK(j["inputs"].contains(key));
  const auto& r = j["results"];
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
  CHECK_THAT(double(r["principal_angle_deg"]), WithinAbs(-22.5, 1e-9));
  CHECK_THAT(double(r["principal_angle_other_deg"]), WithinAbs(67.5, 1e-9));
  CHECK(j["figures"].empty());
}

TEST_CASE("lamina_tensor: an axis of any length is normalised: --axis 3,4,0 is (0.6, 0.8, 0)") {
  const auto run = run_lab("lamina_tensor", "--axis 3,4,0 --omega 2 --json");
  REQUIRE(run.status == 0);
  const auto j = run.json();
  const auto& r = j["results"];
  // The corner tensor of a 1 x 2 plate of mass 1 (eq. 20): (4/3, -1/2; -1/2, 1/3), Izz 5/3.
  const double n[2] = {0.6, 0.8}, w = 2;
  const double Lx = w * (4.0 / 3 * n[0] - 0.5 * n[1]), Ly = w * (-0.5 * n[0] + 1.0 / 3 * n[1]);
  CHECK(double(r["angular_momentum"][0]) == Approx(Lx).epsilon(1e-14));
  CHECK(double(r["angular_momentum"][1]) == Approx(Ly).epsilon(1e-14));
  CHECK(double(r["scalar_moment"]) ==
        Approx(4.0 / 3 * n[0] * n[0] - n[0] * n[1] + 1.0 / 3 * n[1] * n[1]).epsilon(1e-14));
  CHECK(double(r["kinetic_energy"]) == Approx(0.5 * w * (Lx * n[0] + Ly * n[1])).epsilon(1e-14));
}

TEST_CASE("lamina_tensor: --axis 1,0,0 needs the section 3.1 torque 0.500 ma^2 omega^2") {
  const auto run = run_lab("lamina_tensor", "--axis 1,0,0 --json");
  REQUIRE(run.status == 0);
  const auto j = run.json();
  const auto& N = j["results"]["fixed_axis_torque"];
  CHECK_THAT(double(N[0]), WithinAbs(0.0, 1e-14));
  CHECK_THAT(double(N[1]), WithinAbs(0.0, 1e-14));
  // Errata: the size is the text's 0.500, the sign negative (eq. 76 with its axes).
  CHECK(prints_as(double(N[2]), -0.500, 3));
}

TEST_CASE("lamina_tensor: the human table shows the textbook column and errata") {
  const auto run = run_lab("lamina_tensor", "");
  REQUIRE(run.status == 0);
  CHECK(run.out.find("textbook") != std::string::npos);
  CHECK(run.out.find("0.493 ma^2") != std::string::npos);
  CHECK(run.out.find("errata") != std::string::npos);
  CHECK(run_lab("lamina_tensor", "--help").status == 0);
}

TEST_CASE("tire_balancing: defaults give both balancing masses") {
  const auto run = run_lab("tire_balancing", "--json");
  REQUIRE(run.status == 0);
  const auto j = run.json();
  const auto& r = j["results"];
  REQUIRE(r.contains("balance_mass_kg"));
  REQUIRE(r.contains("balance_mass_small_angle_kg"));
  // Small angle: theta a m / (8 b) for the text's inputs, computed here independently.
  const double theta = 1.0 * 3.14159265358979323846 / 180.0;
  CHECK_THAT(double(r["balance_mass_small_angle_kg"]), WithinAbs(theta * 0.18 * 10 / 0.4, 1e-15));
  CHECK(double(r["balance_mass_kg"]) > double(r["balance_mass_small_angle_kg"]));
  CHECK(double(r["residual_tilt_exact_deg"]) < 1e-10);
  CHECK(double(r["torque_balanced_nm"]) < 1e-9 * double(r["torque_unbalanced_nm"]));
}

TEST_CASE("tire_balancing: --csv writes one turn of L and the torque") {
  const std::string path = "/tmp/rigid_tire_test_" + std::to_string(::getpid()) + ".csv";
  std::remove(path.c_str());
  REQUIRE(run_lab("tire_balancing", "--quiet --csv " + path).status == 0);
  std::ifstream csv(path);
  std::string header;
  std::getline(csv, header);
  CHECK(header == "t_s,Lx,Ly,Lz,Nx,Ny,Nz");
  int rows = 0;
  for (std::string line; std::getline(csv, line);) ++rows;
  CHECK(rows == 361);
  std::remove(path.c_str());
}

TEST_CASE("labs: bad input exits 2 with one line naming the option") {
  struct Case {
    const char* lab;
    const char* args;
    const char* option;
  };
  const Case cases[] = {
      {"lamina_tensor", "--mass -1", "--mass"},
      {"lamina_tensor", "--mass 0", "--mass"},
      {"lamina_tensor", "--mass nan", "--mass"},
      {"lamina_tensor", "--mass inf", "--mass"},
      {"lamina_tensor", "--mass abc", "--mass"},
      {"lamina_tensor", "--a 0", "--a"},
      {"lamina_tensor", "--b -2", "--b"},
      {"lamina_tensor", "--axis 0,0,0", "--axis"},
      {"lamina_tensor", "--axis 1,2", "--axis"},
      {"lamina_tensor", "--axis 1,x,2", "--axis"},
      {"lamina_tensor", "--origin middle", "--origin"},
      {"lamina_tensor", "--omega nan", "--omega"},
      {"tire_balancing", "--mass -10", "--mass"},
      {"tire_balancing", "--radius 0", "--radius"},
      {"tire_balancing", "--offset nan", "--offset"},
      {"tire_balancing", "--offset inf", "--offset"},
      {"tire_balancing", "--tilt-deg -1e-9", "--tilt-deg"},
      {"tire_balancing", "--road-speed-m-s 30 --omega 90", "--road-speed-m-s"},
      {"tire_balancing", "--tyre-radius-m 0.3", "--tyre-radius-m"},
      {"tire_balancing", "--road-speed-m-s 30 --tyre-radius-m 0.1", "--tyre-radius-m"},
      {"tire_balancing", "--road-speed-m-s 0", "--road-speed-m-s"},
      {"lamina_tensor", "--axis diag", "--axis"},
      {"lamina_tensor", "--axis 1,2", "--axis"},
      {"lamina_tensor", "--axis diagonal,1,2", "--axis"},
      {"lamina_tensor", "--axis diagonal --axis-deg 30", "--axis-deg"},
      {"lamina_tensor", "--axis-deg nan", "--axis-deg"},
      {"tire_balancing", "--tilt-deg 45", "--tilt-deg"},
      {"tire_balancing", "--tilt-deg -3", "--tilt-deg"},
      {"tire_balancing", "--tilt-deg 40 --offset 0.001", "--tilt-deg"},
      {"tire_balancing", "--csv /proc/nope/x.csv", "--csv"},
      {"tire_balancing", "--csv /tmp", "--csv"},
      {"tire_balancing", "--mass 1e308", "--mass"},
      {"tire_balancing", "--radius 1e-300", "--radius"},
      {"tire_balancing", "--offset 1e300", "--offset"},
      {"lamina_tensor", "--omega 1e200", "--omega"},
      {"lamina_tensor", "--axis 1e-300,0,0", "--axis"},
  };
  for (const auto& c : cases) {
    INFO(c.lab << " " << c.args);
    const auto run = run_lab(c.lab, c.args);
    CHECK(run.status == 2);
    CHECK(run.one_error_line());
    CHECK(run.err.rfind(std::string(c.lab) + ": error: " + c.option, 0) == 0);
    CHECK(run.out.empty());
  }
}

TEST_CASE("poinsot: defaults reproduce the text's ellipsoid of section 5.1") {
  const auto run = run_lab("poinsot", "--json");
  REQUIRE(run.status == 0);
  const auto j = run.json();
  const auto& r = j["results"];
  for (const char* key : {"principal_moments", "omega_end", "energy", "angular_momentum_magnitude",
                          "polhode_period_s", "method", "energy_drift_rel", "momentum_drift_rel"}) {
    CHECK(r.contains(key));
  }
  const double pi = 3.14159265358979323846;
  CHECK_THAT(double(r["principal_moments"][0]), WithinAbs(pi, 1e-14));
  CHECK_THAT(double(r["principal_moments"][1]), WithinAbs(2 * pi, 1e-14));
  CHECK(prints_as(r["principal_moments"][2], 8.168, 3));
  CHECK(r["method"] == "exact");
  // The closed form keeps T and |L| to roundoff: a few ulps per sample.
  CHECK(double(r["energy_drift_rel"]) < 1e-14);
  CHECK(double(r["momentum_drift_rel"]) < 1e-14);
  CHECK(double(r["L_space_drift_rel"]) < 1e-14);
  // Section 4.1 ratios for I = 5 : 4 : 3.
  CHECK(prints_as(r["ratios_momentum"][0], 0.20, 2));
  CHECK(prints_as(r["ratios_momentum"][2], 0.33, 2));
  // Errata: 1/sqrt(5) = 0.447 prints as 0.45, not the text's 0.44.
  CHECK(prints_as(r["ratios_energy"][0], 0.45, 2));
  CHECK(prints_as(r["ratios_energy"][1], 0.50, 2));
  CHECK(prints_as(r["ratios_energy"][2], 0.58, 2));
}

TEST_CASE("poinsot: every method agrees with the exact solution within its tolerance") {
  // Default run: three polhode periods T; fixed steps h = T/2000; tolerance 1e-10.
  struct Case {
    const char* method;
    double bound;
  };
  // A p-th order method's global error over n periods with step h is about
  // n (2 pi h/T)^p; a factor 10 covers the error constant. Adaptive methods
  // control the local error per step to the tolerance; over a few hundred steps
  // their global error stays within 100 times it.
  const double h = 2 * 3.14159265358979323846 / 2000;
  const Case cases[] = {{"splitting", 10 * 3 * h * h},    {"splitting4", 10 * 3 * std::pow(h, 4)},
                        {"rk4", 10 * 3 * std::pow(h, 4)}, {"dopri5", 100 * 1e-10},
                        {"rkf78", 100 * 1e-10},           {"bulirsch-stoer", 100 * 1e-10}};
  for (const auto& c : cases) {
    INFO(c.method);
    const auto run = run_lab("poinsot", std::string("--json --method ") + c.method);
    REQUIRE(run.status == 0);
    const auto j = run.json();
    CHECK(double(j["results"]["max_error_vs_exact"]) < c.bound);
  }
}

TEST_CASE("poinsot: --csv writes t, omega, the quaternion, energy and |L|") {
  const std::string path = "/tmp/rigid_poinsot_test_" + std::to_string(::getpid()) + ".csv";
  std::remove(path.c_str());
  REQUIRE(run_lab("poinsot", "--quiet --method splitting --csv " + path).status == 0);
  std::ifstream csv(path);
  std::string header;
  std::getline(csv, header);
  CHECK(header == "t_s,omega1,omega2,omega3,qw,qx,qy,qz,energy_J,L_kg_m2_s");
  std::remove(path.c_str());
}

TEST_CASE("poinsot: bad input exits 2 with one line naming the option") {
  const std::pair<const char*, const char*> cases[] = {
      {"--inertia 1,1,3", "--inertia"},
      {"--inertia -1,1,1", "--inertia"},
      {"--inertia 1,2", "--inertia"},
      {"--inertia 0,1,1", "--inertia"},
      {"--ellipsoid 0,1,1", "--ellipsoid"},
      {"--mass -1", "--mass"},
      {"--omega nan,1,1", "--omega"},
      {"--omega 0,0,0", "--omega"},
      {"--t-end -1", "--t-end"},
      {"--method euler", "--method"},
      {"--tolerance 0", "--tolerance"},
      {"--tolerance 1", "--tolerance"},
      {"--step -1", "--step"},
      {"--inertia 1,2,2 --ellipsoid 1,2,3", "--inertia"},
      {"--method rk4 --step 1e-9 --t-end 100", "--step"},
      {"--method dopri5 --project", "--project"},
      {"--step 0", "--step"},
      {"--t-end 0", "--t-end"},
      {"--t-end 1e300", "--t-end"},
      {"--t-end 1e59", "--t-end"},
      {"--omega 1e200,1,1", "--omega"},
      {"--method rk4 --step 10", "--step"},
      // below double precision's reach no step meets a tolerance
      {"--method dopri5 --tolerance 1e-17", "--tolerance"},
      {"--tolerance 1e-300", "--tolerance"},
      {"--periods 2 --t-end 3", "--periods"},
      {"--periods 0", "--periods"},
      // too few numbers before the next option: named as such, not as a bad component
      {"--omega , --json", "--omega: needs 3 numbers separated by commas; '--json'"},
  };
  rigid::test::check_bad_inputs("poinsot", cases);
}

TEST_CASE("poinsot: steady rotation and the separatrix have no polhode period") {
  struct Case {
    const char* args;
    const char* regime;
  };
  const Case cases[] = {{"--omega 0,1,0", "steady rotation"},
                        {"--omega 1,0,0", "steady rotation"},
                        {"--inertia 2,2,2 --omega 1,2,3", "steady rotation"},
                        // L1 = L3 = 15: L^2 = 2 T I2 exactly
                        {"--inertia 3,3.75,5 --omega 5,1,3", "separatrix"}};
  for (const auto& c : cases) {
    INFO(c.args);
    const auto run = run_lab("poinsot", std::string("--json ") + c.args);
    REQUIRE(run.status == 0);
    const auto j = run.json();
    CHECK(j["results"]["polhode_period_s"].is_null());
    CHECK(j["results"]["regime"] == c.regime);
    CHECK(double(j["results"]["energy_drift_rel"]) < 1e-14);
  }
}

TEST_CASE("poinsot: a fixed step is taken as given, only the last shortened to end at t_end") {
  // h = 1 s on a 10.3 s polhode period: rk4's error is large, as it must be.
  const auto run = run_lab("poinsot", "--json --method rk4 --step 1");
  REQUIRE(run.status == 0);
  const auto j = run.json();
  const auto& r = j["results"];
  CHECK(double(r["step_s"]) == 1.0);
  // t_end is three periods, reached by whole steps and one shortened last step.
  CHECK(double(r["t_end_s"]) == 3 * double(r["polhode_period_s"]));
  CHECK(double(r["steps"]) == std::ceil(double(r["t_end_s"])));
  CHECK(double(r["max_error_vs_exact"]) > 1e-3);
  CHECK(!j["inputs"].contains("inertia"));
}

TEST_CASE("poinsot: omega is reported at exactly the t_end asked for, by every fixed-step method") {
  // 37.5 s is no whole number of steps of period / 2000 nor of 0.00125 s (to roundoff).
  const char* cases[] = {"--method rk4", "--method rk4 --step 0.00125", "--method splitting",
                         "--method splitting4"};
  for (const char* c : cases) {
    INFO(c);
    const auto run =
        run_lab("poinsot", std::string("--json --inertia 1.2,2.3,3.1 --omega 0.3,1.7,-0.4 "
                                       "--t-end 37.5 ") +
                               c);
    REQUIRE(run.status == 0);
    const auto j = run.json();
    CHECK(double(j["results"]["t_end_s"]) == 37.5);
  }
}

TEST_CASE("poinsot: stress - nearly spherical, flat, fast and near-separatrix bodies") {
  const char* cases[] = {
      "--inertia 1,1.000000001,1.000000002 --omega 1,1,1",  // nearly spherical: k' -> 0
      "--inertia 1,2,3 --omega 0.3,1,0.2",                  // a lamina, I3 = I1 + I2
      "--omega 1e6,1e6,1e6",                                // huge spin
      "--inertia 3,5,7 --omega 0,0.4,0.00111",              // next to the separatrix
      "--inertia 3,5,7 --omega 0,0.4,0.00111 --method rkf78 --project"};
  for (const char* args : cases) {
    INFO(args);
    const auto run = run_lab("poinsot", std::string("--json ") + args);
    REQUIRE(run.status == 0);
    const auto j = run.json();
    const auto& r = j["results"];
    // Any NaN would have been refused; both invariants hold to roundoff
    // (a few ulps per sample for the closed form and for the projected rkf78).
    CHECK(double(r["energy_drift_rel"]) < 1e-13);
    CHECK(double(r["momentum_drift_rel"]) < 1e-13);
  }
}

TEST_CASE("lamina_tensor: section 3.1's rotation about x is always reported, beside --axis") {
  // N = x × (I x) with I's first column (4/3, -1/2, 0) m a^2: (0, 0, -1/2) m a^2 omega^2,
  // and z is the third principal axis. Roundoff of the eigen-solver: a few ulps.
  for (const char* args : {"--json", "--json --axis 0,0,1"}) {
    INFO(args);
    const auto run = run_lab("lamina_tensor", args);
    REQUIRE(run.status == 0);
    const auto j = run.json();
    const auto& N = j["results"]["fixed_axis_torque_x_principal"];
    CHECK_THAT(double(N[0]), WithinAbs(0.0, 1e-15));
    CHECK_THAT(double(N[1]), WithinAbs(0.0, 1e-15));
    CHECK_THAT(double(N[2]), WithinAbs(-0.5, 1e-15));
  }
  const auto j = run_lab("lamina_tensor", "--json").json();
  CHECK(j["units"]["fixed_axis_torque_x_principal"] == "N m");
  CHECK(j["units"]["inertia_tensor"] == "kg m^2");
  CHECK(j["units"]["principal_axes"] == "1");
}

TEST_CASE("poinsot: the integrator comparison is each method's own run") {
  // The comparison runs every method at the lab's settings: its number for a
  // method is the one that method gives as the lab's --method, bit for bit.
  const auto all = run_lab("poinsot", "--json --method exact").json()["results"];
  for (const char* method : {"splitting", "rk4", "dopri5", "rkf78", "bulirsch-stoer"}) {
    INFO(method);
    std::string key = std::string("max_error_") + method;
    std::replace(key.begin(), key.end(), '-', '_');
    const auto own = run_lab("poinsot", std::string("--json --method ") + method).json();
    CHECK(double(all[key]) == double(own["results"]["max_error_vs_exact"]));
    CHECK(double(own["results"][key]) == double(own["results"]["max_error_vs_exact"]));
  }
  CHECK(run_lab("poinsot", "--json").json()["units"]["polhode_period_s"] == "s");
}

TEST_CASE("poinsot: a method the comparison cannot afford is reported as not run") {
  // I nearly spherical: the polhode period is ~1e10 s and the adaptive methods
  // would need millions of steps; the lab still answers, quickly, with nulls.
  const auto run = run_lab("poinsot", "--json --inertia 1,1.000000001,1.000000002 --omega 1,1,1");
  REQUIRE(run.status == 0);
  const auto j = run.json();
  const auto& r = j["results"];
  CHECK(r["max_error_dopri5"].is_null());
  CHECK(r["max_error_rk4"].is_number());
}

TEST_CASE("football: the default football is prolate, its body cone rolls outside") {
  const auto run = run_lab("football", "--json");
  REQUIRE(run.status == 0);
  const auto j = run.json();
  const auto& r = j["results"];
  for (const char* key : {"body_precession_rate_rad_s", "space_precession_rate_rad_s", "theta_deg",
                          "body_cone_half_angle_deg", "space_cone_half_angle_deg", "cones_touch",
                          "body_precession_period_s", "space_precession_period_s"})
    CHECK(r.contains(key));
  CHECK(r["cones_touch"] == "outside");
  CHECK(double(r["body_precession_rate_rad_s"]) < 0);  // prolate: omega turns clockwise about 3
  CHECK(double(r["theta_deg"]) > double(r["body_cone_half_angle_deg"]));
  // Independent: theta - alpha from tan theta = (I/Is) tan alpha, formed by subtraction
  // (fine at 10 deg: cancellation costs ~1 digit of 16).
  const double I = r["moment_transverse_kg_m2"], Is = r["moment_symmetry_kg_m2"];
  const double alpha = 10.0 * M_PI / 180;
  const double theta = std::atan(I / Is * std::tan(alpha));
  CHECK(double(r["space_cone_half_angle_deg"]) ==
        Approx((theta - alpha) * 180 / M_PI).epsilon(1e-12));
  // The NFL-sized spheroid, m (b^2 + c^2)/5 and m (a^2 + c^2)/5.
  CHECK(Is == Approx(0.42 * 2 * 0.085 * 0.085 / 5).epsilon(1e-15));
  CHECK(I == Approx(0.42 * (0.14 * 0.14 + 0.085 * 0.085) / 5).epsilon(1e-15));
  CHECK(double(r["body_precession_period_s"]) ==
        Approx(2 * M_PI / std::abs(double(r["body_precession_rate_rad_s"]))).epsilon(1e-15));
}

TEST_CASE("football: the frisbee (Is = 2I) gives eqs. 148-149 and the wobble is twice the spin") {
  const auto run = run_lab("football", "--json --preset frisbee");
  REQUIRE(run.status == 0);
  const auto j = run.json();
  const auto& r = j["results"];
  const double omega = 30.0, alpha = 5.0 * M_PI / 180;
  CHECK(double(r["moment_symmetry_kg_m2"]) == 2 * double(r["moment_transverse_kg_m2"]));
  // (Is - I)/I is exactly 1 for Is = 2I, so Omega = omega cos alpha to the last bit.
  CHECK(double(r["body_precession_rate_rad_s"]) == omega * std::cos(alpha));
  // phi_dot / omega = sqrt(1 + 3 cos^2 a) = 2 - 3 a^2/4 + O(a^4); a^4 ~ 6e-5 bounds the rest.
  const double ratio = double(r["space_precession_rate_rad_s"]) / omega;
  CHECK(ratio == Approx(2 - 0.75 * alpha * alpha).margin(std::pow(alpha, 4)));
  CHECK(ratio == Approx(std::sqrt(1 + 3 * std::cos(alpha) * std::cos(alpha))).epsilon(1e-15));
  CHECK(r["cones_touch"] == "inside");
  CHECK(j["textbook"].contains("body_precession_rate_rad_s"));
  bool feynman = false;
  for (const auto& note : j["notes"]) feynman |= note.get<std::string>().find("Feynman") == 0;
  CHECK(feynman);
  // Any other physical option takes the text's example away.
  CHECK(run_lab("football", "--json --preset frisbee --omega 10").json()["textbook"].empty());
}

TEST_CASE("football: the Earth's periods near the text's 305 and 0.997 days") {
  const auto run = run_lab("football", "--json --preset earth");
  REQUIRE(run.status == 0);
  const auto j = run.json();
  const auto& r = j["results"];
  // Independent: omega = 2 pi per sidereal day, Omega = 0.00327 omega cos a,
  // phi_dot = omega sqrt(1 + (1.00327^2 - 1) cos^2 a); cos a = 1 - 5e-13.
  const double day = 86164.0905, a = 0.2 / 3600 * M_PI / 180, c = std::cos(a);
  const double body_days = day / (0.00327 * c) / 86400;
  const double space_days = day / std::sqrt(1 + (1.00327 * 1.00327 - 1) * c * c) / 86400;
  // 1e-9: the moments are 8e37 and 1.00327 times it, so (Is - I)/I carries ~1e-13 of rounding.
  CHECK(double(r["body_precession_period_days"]) == Approx(body_days).epsilon(1e-9));
  CHECK(double(r["space_precession_period_days"]) == Approx(space_days).epsilon(1e-12));
  CHECK(j["units"]["body_precession_period_days"] == "d");
  // The text's printed values, within the rounding of their last digit and of the day used.
  CHECK(std::abs(double(r["body_precession_period_days"]) - 305) < 0.5);
  CHECK(std::abs(double(r["space_precession_period_days"]) - 0.997) < 0.004);
  CHECK(j["textbook"]["body_precession_period_days"] == "305");
  CHECK(j["textbook"]["space_precession_period_days"] == "0.997");
  CHECK(r["cones_touch"] == "inside");
}

TEST_CASE("football: a sphere has no cones and no body period") {
  const auto run = run_lab("football", "--json --inertia 1,1 --omega 2 --alpha-deg 30");
  REQUIRE(run.status == 0);
  const auto j = run.json();
  const auto& r = j["results"];
  CHECK(r["cones_touch"] == "none");
  CHECK(r["body_precession_period_s"].is_null());
  CHECK(double(r["space_precession_rate_rad_s"]) == Approx(2.0).epsilon(1e-15));
}

TEST_CASE("football: bad input exits 2 with one line naming the option") {
  const std::pair<const char*, const char*> cases[] = {
      {"--alpha-deg 0", "--alpha-deg"},
      {"--alpha-deg 90", "--alpha-deg"},
      {"--alpha-deg nan", "--alpha-deg"},
      {"--inertia 1,3", "--inertia"},
      {"--inertia -1,1", "--inertia"},
      {"--inertia 1", "--inertia"},
      {"--preset moon", "--preset"},
      {"--omega 0", "--omega"},
      {"--preset earth --inertia 1,1", "--inertia"},
  };
  rigid::test::check_bad_inputs("football", cases);
}

TEST_CASE("football: the integrated cross-check agrees with the closed form for every preset") {
  for (const char* preset : {"football", "frisbee", "earth"}) {
    INFO(preset);
    const auto run = run_lab("football", std::string("--json --preset ") + preset);
    REQUIRE(run.status == 0);
    const auto j = run.json();
    const auto& r = j["results"];
    // dopri5 at tolerance 1e-12 for one period: the global error is far below 1e-9.
    CHECK(double(r["integrated_rate_error_rel"]) < 1e-9);
    CHECK(double(r["integrated_axis_return_rad"]) < 1e-9);
    CHECK(double(r["integrated_L_drift_rel"]) < 1e-9);
    CHECK(j["units"]["integrated_space_precession_rate_rad_s"] == "rad/s");
  }
}

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
}  // namespace

TEST_CASE("tennis_racquet: defaults reproduce eqs. 83-85 and the flip about axis 2") {
  const auto run = run_lab("tennis_racquet", "--json");
  REQUIRE(run.status == 0);
  const auto j = run.json();
  const auto& r = j["results"];
  const TextRacquet t;
  // The printed 0.175 m, 1.27, 11.81 and 13.08 x 10^-3 kg m^2, to their last digit.
  CHECK(prints_as(r["cm_offset_m"], 0.175, 3));
  CHECK(prints_as(double(r["principal_moments"][0]) * 1e3, 1.27, 2));
  CHECK(prints_as(double(r["principal_moments"][1]) * 1e3, 11.81, 2));
  CHECK(prints_as(double(r["principal_moments"][2]) * 1e3, 13.08, 2));
  // And to roundoff against the formulas written out.
  CHECK(double(r["cm_offset_m"]) == Approx(t.R).epsilon(1e-14));
  CHECK(double(r["principal_moments"][1]) == Approx(t.I2).epsilon(1e-14));
  CHECK(j["textbook"]["cm_offset_m"] == "0.175");
  // Linear rates: axis 2 grows at omega sqrt((I3 - I2)(I2 - I1)/(I1 I3)); eq. 92 says omega.
  const double omega = 10;
  const double growth = omega * std::sqrt((t.I3 - t.I2) * (t.I2 - t.I1) / (t.I1 * t.I3));
  CHECK(double(r["growth_rate_per_s"]) == Approx(growth).epsilon(1e-13));
  CHECK(double(r["growth_rate_textbook_per_s"]) == omega);
  CHECK(double(r["wobble_frequencies_rad_s"][0]) ==
        Approx(omega * std::sqrt((t.I3 - t.I1) * (t.I2 - t.I1) / (t.I2 * t.I3))).epsilon(1e-13));
  CHECK(double(r["wobble_frequencies_rad_s"][1]) == Approx(omega).epsilon(1e-13));
  CHECK(j["units"]["growth_rate_per_s"] == "1/s");
  CHECK(j["units"]["cm_offset_m"] == "m");
  // Measured on the exact motion up to a share of 0.1: below the linear rate by less
  // than 0.1^2 / 2 of it (the nonlinear terms, racquet.h).
  const double measured = r["growth_rate_measured_per_s"];
  CHECK(measured < growth);
  CHECK(measured > growth * (1 - 0.005));
  CHECK(double(r["growth_fit_shares"][1]) == Approx(0.1).epsilon(1e-9));
  // Wobbles measured from the exact polhode periods: O(p^2) = 1e-4 from the linear ones.
  CHECK(double(r["wobble_frequencies_measured_rad_s"][0]) ==
        Approx(double(r["wobble_frequencies_rad_s"][0])).epsilon(1e-4));
  CHECK(double(r["wobble_frequencies_measured_rad_s"][1]) ==
        Approx(double(r["wobble_frequencies_rad_s"][1])).epsilon(1e-4));
  // Flips every half-period of omega_2; the first a quarter-period after launch (omega_2 at its
  // peak).
  const double period = r["polhode_period_s"];
  CHECK(double(r["flip_interval_s"]) == Approx(period / 2).epsilon(1e-15));
  CHECK(double(r["first_flip_s"]) == Approx(period / 4).epsilon(1e-9));
  // The handle tilts out of the plane across L by at most asin(L1/|L|) at L_2 = 0:
  // L1^2 = I1 (2T I3 - L^2)/(I3 - I1), with omega0 = 10 (0, sqrt(1 - p^2), p).
  const double p = 0.01, w2 = omega * std::sqrt(1 - p * p), w3 = omega * p;
  const double T2 = t.I2 * w2 * w2 + t.I3 * w3 * w3;
  const double L2 = t.I2 * t.I2 * w2 * w2 + t.I3 * t.I3 * w3 * w3;
  const double excursion = std::asin(std::sqrt(t.I1 * (T2 * t.I3 - L2) / ((t.I3 - t.I1) * L2)));
  CHECK(double(r["handle_excursion_max_deg"]) == Approx(excursion * 180 / M_PI).epsilon(1e-9));
  // The cross-check: dopri5 at 1e-10 over one period stays within 1e-7 of the exact omega.
  CHECK(double(r["max_error_vs_exact"]) < 1e-7);
  CHECK(double(r["t_end_s"]) == period);
  bool errata = false;
  for (const auto& note : j["notes"])
    errata |= note.get<std::string>().rfind("errata: eq. 92", 0) == 0;
  CHECK(errata);
}

TEST_CASE("tennis_racquet: spins about axes 1 and 3 are stable and do not flip") {
  for (const char* axis : {"1", "3"}) {
    INFO("axis " << axis);
    const auto run = run_lab("tennis_racquet", std::string("--json --spin-axis ") + axis);
    REQUIRE(run.status == 0);
    const auto j = run.json();
    const auto& r = j["results"];
    CHECK(r["flip_interval_s"].is_null());
    CHECK(r["first_flip_s"].is_null());
    CHECK(r["stability"] == "stable: a wobble");
    // The launch (omega_1 = 0 about 3, omega_3 = 0 about 1) is where the handle is
    // furthest: about 1, from L by atan(I2 p / (I1 sqrt(1 - p^2))) (5.3 deg, as I2 >> I1);
    // about 3, out of the plane across L by atan(I1 p / (I3 sqrt(1 - p^2))).
    const TextRacquet t;
    const double p = 0.01, c = std::sqrt(1 - p * p);
    const double expected =
        axis[0] == '1' ? std::atan(t.I2 * p / (t.I1 * c)) : std::atan(t.I1 * p / (t.I3 * c));
    CHECK(double(r["handle_excursion_max_deg"]) == Approx(expected * 180 / M_PI).epsilon(1e-9));
    // The run spins about the axis asked: the polhode period is 2 pi over the measured wobble.
    const int k = axis[0] == '1' ? 0 : 1;
    CHECK(double(r["polhode_period_s"]) ==
          Approx(2 * M_PI / double(r["wobble_frequencies_measured_rad_s"][k])).epsilon(1e-14));
    // --spin-axis is physical: no textbook column.
    CHECK(j["textbook"].empty());
  }
}

TEST_CASE("tennis_racquet: --csv holds the exact motion and the integrator's omega beside it") {
  const std::string path = "/tmp/rigid_racquet_test_" + std::to_string(::getpid()) + ".csv";
  std::remove(path.c_str());
  const auto run =
      run_lab("tennis_racquet", "--json --method rkf78 --tolerance 1e-12 --csv " + path);
  REQUIRE(run.status == 0);
  const double t_end = run.json()["results"]["t_end_s"];
  const rigid::test::Csv csv = rigid::test::read_csv(path);
  CHECK(csv.header ==
        "t_s,omega1,omega2,omega3,qw,qx,qy,qz,omega1_integrated,omega2_integrated,"
        "omega3_integrated");
  std::size_t rows = 0;
  double last_t = -1, worst = 0, worst_norm = 0;
  for (const std::vector<double>& v : csv.rows) {
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
  CHECK(worst_norm < 1e-14);
  // rkf78 at 1e-12 over one period: the integrated omega within 1e-8 rad/s of the exact.
  CHECK(worst < 1e-8);
  std::remove(path.c_str());
}

TEST_CASE("tennis_racquet: bad input exits 2 with one line naming the option") {
  const std::pair<const char*, const char*> cases[] = {
      {"--spin-axis 4", "--spin-axis"},
      {"--spin-axis 0", "--spin-axis"},
      {"--perturbation 0", "--perturbation"},
      {"--perturbation 0.5", "--perturbation"},
      {"--perturbation nan", "--perturbation"},
      {"--perturbation -0.1", "--perturbation"},
      {"--head-mass -1", "--head-mass"},
      {"--head-radius 0", "--head-radius"},
      {"--handle-mass inf", "--handle-mass"},
      {"--handle-length x", "--handle-length"},
      {"--omega 0", "--omega"},
      {"--t-end -1", "--t-end"},
      {"--method dopri5 --project", "--project"},
      {"--method rk4 --step 1e-9", "--step"},
  };
  rigid::test::check_bad_inputs("tennis_racquet", cases);
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
    const auto run = run_lab("tennis_racquet", std::string("--json --method ") + method);
    REQUIRE(run.status == 0);
    const auto j = run.json();
    const auto& r = j["results"];
    CHECK(double(r["max_error_vs_exact"]) < bound);
    CHECK(double(r["energy_drift_rel"]) < bound);
  }
}

TEST_CASE("top_nutation: defaults reproduce section 8.1's numbers, exactly, with the errata") {
  const auto run = run_lab("top_nutation", "--json");
  REQUIRE(run.status == 0);
  const auto j = run.json();
  const auto& r = j["results"];
  // The disk written out: Is = m r^2/2, I = m r^2/4 + m l^2, m g l with g = 9.8.
  const double m = 2.0, rad = 0.05, l = 0.04, g = 9.8;
  const double Is = m * rad * rad / 2, I = m * rad * rad / 4 + m * l * l, mgl = m * g * l;
  CHECK(double(r["moment_symmetry_kg_m2"]) == Approx(Is).epsilon(1e-15));
  CHECK(double(r["moment_transverse_kg_m2"]) == Approx(I).epsilon(1e-15));
  // (a) S_min = sqrt(4 m g l I) / Is: the text's 47.3 rad/s, 7.52 rev/s, 451 rpm.
  const double S_min = std::sqrt(4 * mgl * I) / Is;
  CHECK(double(r["min_spin_rad_s"]) == Approx(S_min).epsilon(1e-15));
  CHECK(prints_as(r["min_spin_rad_s"], 47.3, 1));
  CHECK(prints_as(r["min_spin_rev_per_s"], 7.52, 2));
  CHECK(prints_as(r["min_spin_rpm"], 451, 0));
  // Its period 2 pi / S_min is 0.13297 s: the text's 0.132 is an erratum.
  CHECK(prints_as(r["min_spin_period_s"], 0.133, 3));
  // (b) 500 rpm: phi_dot = m g l / (Is S) = 5.989 rad/s (the text: 5.98, from S = 52.4).
  const double S = 500 * 2 * M_PI / 60;
  CHECK(double(r["horizontal_precession_rate_rad_s"]) == Approx(mgl / (Is * S)).epsilon(1e-15));
  CHECK(prints_as(r["horizontal_precession_rate_rad_s"], 5.99, 2));
  CHECK(prints_as(r["horizontal_precession_period_s"], 1.05, 2));
  // (c) at 30 deg: the roots of I cos(30) x^2 - Is S x + m g l = 0, by the quadratic formula
  // written out (no cancellation worth a digit here): 7.764 and 26.20 rad/s.
  const double c = std::cos(M_PI / 6), D = Is * Is * S * S - 4 * mgl * I * c;
  const double slow = (Is * S - std::sqrt(D)) / (2 * I * c),
               fast = (Is * S + std::sqrt(D)) / (2 * I * c);
  CHECK(double(r["steady_precession_rates_rad_s"][0]) == Approx(slow).epsilon(1e-12));
  CHECK(double(r["steady_precession_rates_rad_s"][1]) == Approx(fast).epsilon(1e-14));
  CHECK(prints_as(r["steady_precession_rates_rad_s"][1], 26.2, 1));
  CHECK(prints_as(r["steady_precession_periods_s"][0], 0.81, 2));
  CHECK(prints_as(r["steady_precession_periods_s"][1], 0.24, 2));
  CHECK(j["textbook"]["min_spin_rad_s"] == "47.3");
  int errata = 0;
  for (const auto& note : j["notes"]) errata += note.get<std::string>().rfind("errata:", 0) == 0;
  CHECK(errata == 3);
  // Released from rest at 30 deg: theta_min is the start, phi_dot = 0 there (cusps).
  CHECK(r["regime"] == "cusped");
  CHECK(double(r["theta_min_deg"]) == Approx(30).epsilon(1e-14));
  CHECK(double(r["phi_dot_turning_rad_s"][1]) == 0.0);
  // The exact sampling keeps E, p_phi, p_psi to roundoff.
  CHECK(double(r["energy_drift_rel"]) < 1e-14);
  CHECK(double(r["p_phi_drift_rel"]) < 1e-14);
  // Every integrator agrees with the exact theta within its tolerance's reach.
  for (const char* key : {"max_theta_error_dopri5_deg", "max_theta_error_rkf78_deg",
                          "max_theta_error_rk4_deg", "max_theta_error_splitting4_deg"}) {
    INFO(key);
    CHECK(double(r[key]) < 1e-5);
  }
  CHECK(j["units"]["min_spin_rev_per_s"] == "1/s");
}

TEST_CASE("top_nutation: integrated runs report their theta error and keep the invariants") {
  for (const char* method :
       {"splitting", "splitting4", "rk4", "dopri5", "rkf78", "bulirsch-stoer"}) {
    INFO(method);
    const auto run = run_lab("top_nutation",
                             std::string("--json --phidot0 3 --thetadot0 0.5 --method ") + method);
    REQUIRE(run.status == 0);
    const auto j = run.json();
    const auto& r = j["results"];
    // Tolerance 1e-10 or step period/2000 over three nutation periods: far below 1e-4 deg.
    CHECK(double(r["max_theta_error_deg"]) < 1e-4);
    CHECK(double(r["energy_drift_rel"]) < 1e-6);
    if (std::string(method).rfind("splitting", 0) == 0) {
      // A rotation or a torque normal to z and 3 at every sub-step: roundoff only, a
      // random walk of ~eps sqrt(30 n) = 1e-13 over n = 6000 steps of 15 sub-steps.
      CHECK(double(r["p_phi_drift_rel"]) < 1e-12);
      CHECK(double(r["p_psi_drift_rel"]) < 1e-12);
    }
  }
}

TEST_CASE("top_nutation: the sleeping top is stable above S_min and upright starts sleep") {
  const auto above = run_lab("top_nutation", "--json --theta0-deg 0 --spin-rpm 460");
  REQUIRE(above.status == 0);
  const auto j = above.json();
  CHECK(j["results"]["regime"] == "sleeping");
  CHECK(j["results"]["sleeping_stability"] == "stable (S >= S_min)");
  const auto below = run_lab("top_nutation", "--json --theta0-deg 0 --spin-rpm 440").json();
  CHECK(below["results"]["sleeping_stability"] == "unstable (S < S_min): a hair topples it");
  // From a hair off upright: a small nod above S_min, a fall below.
  const auto& check = j["results"]["sleeping_check_theta_max_deg"];
  CHECK(double(check[0]) < 1.0);
  CHECK(double(check[1]) > 10.0);
}

TEST_CASE("top_nutation: bad input exits 2 with one line naming the option") {
  const std::pair<const char*, const char*> cases[] = {
      {"--mass 0", "--mass"},
      {"--arm -1", "--arm"},
      {"--disk-radius nan", "--disk-radius"},
      {"--g inf", "--g"},
      {"--inertia 1,-1", "--inertia"},
      {"--inertia 0.00445,0.01", "--inertia"},  // I - m l^2 < Is/2: no body has these
      {"--inertia 0.00445,0.0025 --disk-radius 0.05", "--inertia"},
      {"--spin 50 --spin-rpm 500", "--spin"},
      {"--theta0-deg 180", "--theta0-deg"},
      {"--theta0-deg -1", "--theta0-deg"},
      {"--theta0-deg 0 --spin 0", "--theta0-deg"},
      {"--method rk4 --step 1e-12", "--step"},
      {"--method euler", "--method"},
  };
  rigid::test::check_bad_inputs("top_nutation", cases);
  // The text's thin disk sits exactly on I - m l^2 = Is / 2 and is accepted.
  CHECK(run_lab("top_nutation", "--json --inertia 0.00445,0.0025").status == 0);
}

TEST_CASE("top_nutation: --csv holds theta beside the exact theta, and a unit quaternion") {
  const std::string path = "/tmp/rigid_top_test_" + std::to_string(::getpid()) + ".csv";
  std::remove(path.c_str());
  const auto run = run_lab("top_nutation", "--json --method rkf78 --tolerance 1e-12 --csv " + path);
  REQUIRE(run.status == 0);
  const double t_end = run.json()["results"]["t_end_s"];
  const rigid::test::Csv csv = rigid::test::read_csv(path);
  CHECK(csv.header ==
        "t_s,theta_rad,theta_exact_rad,omega1,omega2,omega3,qw,qx,qy,qz,energy_error_rel");
  std::size_t rows = 0;
  double last_t = -1, worst = 0, worst_norm = 0, lowest = 10, highest = -10;
  for (const std::vector<double>& v : csv.rows) {
    REQUIRE(v.size() == 11);
    ++rows;
    last_t = v[0];
    worst = std::max(worst, std::abs(v[1] - v[2]));
    worst_norm = std::max(worst_norm,
                          std::abs(std::hypot(std::hypot(v[6], v[7]), std::hypot(v[8], v[9])) - 1));
    lowest = std::min(lowest, v[2]);
    highest = std::max(highest, v[2]);
  }
  CHECK(rows > 100);
  CHECK(last_t == t_end);
  CHECK(worst_norm < 1e-14);
  // rkf78 at 1e-12 over three nutation periods: theta within 1e-9 rad of the exact one.
  CHECK(worst < 1e-9);
  // The exact theta nods between 30 deg and theta_max = 52.36 deg (cusped release).
  CHECK(lowest == Approx(M_PI / 6).epsilon(1e-9));
  CHECK(highest > 0.9);
  std::remove(path.c_str());
}

TEST_CASE("labs: extreme but legal inputs end with finite numbers or one line, never a crash") {
  // Each was a crash or a message naming no option: odeint's dense-output steppers
  // failed for runs shorter than 1e-14 s (now run in scaled time), and the heavy
  // top's turning circles within roundoff of a pole (no spin, huge g) overflowed.
  const std::pair<const char*, const char*> cases[] = {
      {"poinsot", "--t-end 1e-60"},
      {"poinsot", "--t-end 1e-20 --method dopri5"},
      {"poinsot", "--t-end 1e-20 --method bulirsch-stoer"},
      {"poinsot", "--inertia 1,2,3 --omega 1e20,1e20,1e20"},
      {"tennis_racquet", "--t-end 1e-60"},
      {"tennis_racquet", "--omega 1e30"},
      // moments equal to double precision: no flip, no growth to measure
      {"tennis_racquet", "--head-mass 1e-60"},
      {"tennis_racquet", "--handle-length 1e60"},
      {"tennis_racquet", "--head-mass 1e60 --handle-mass 1e-60"},
      {"top_nutation", "--g 1e60"},
      {"top_nutation", "--spin 0"},
      {"top_nutation", "--spin 1e-60"},
      {"top_nutation", "--spin 1e60"},
      {"top_nutation", "--thetadot0 1e60"},
      {"top_nutation", "--t-end 1e-60"},
      {"top_nutation", "--spin 0 --theta0-deg 1e-10"},
      {"top_nutation", "--theta0-deg 0 --thetadot0 1"},
      {"top_nutation", "--theta0-deg 179.9999999"},
  };
  for (const auto& [lab, args] : cases) {
    INFO(lab << " " << args);
    const auto run = run_lab(lab, std::string("--json ") + args);
    CHECK((run.status == 0 || run.status == 2));
    if (run.status == 2) {
      CHECK(run.one_error_line());
      CHECK(run.err.find(": error: --") != std::string::npos);
    } else {
      CHECK(run.out.find("NaN") == std::string::npos);
      CHECK(run.json()["results"].is_object());
    }
  }
}

TEST_CASE(
    "lamina_tensor: the paddle and the block at other inputs, against eqs. 40-43 typed here") {
  const auto run = run_lab("lamina_tensor", "--json --mass 3 --a 0.4 --b 0.9 --c 0.25 --examples");
  REQUIRE(run.status == 0);
  const auto j = run.json();
  const auto& r = j["results"];
  const double m = 3, a = 0.4, b = 0.9, c = 0.25;
  // The model paddle (section 2.1): (1/8, 31/24, 17/12) m a^2 about its centre of mass.
  const double paddle[] = {m * a * a / 8, 31.0 / 24 * m * a * a, 17.0 / 12 * m * a * a};
  // The block a x b x c (eq. 40): m (b^2 + c^2)/12, m (a^2 + c^2)/12, m (a^2 + b^2)/12.
  const double block[] = {m * (b * b + c * c) / 12, m * (a * a + c * c) / 12,
                          m * (a * a + b * b) / 12};
  for (int i = 0; i < 3; ++i) {
    CHECK(double(r["paddle_principal_moments"][i]) == Approx(paddle[i]).epsilon(1e-14));
    CHECK(double(r["block_principal_moments"][i]) == Approx(block[i]).epsilon(1e-14));
  }
  // The cube of side a: m a^2 / 6 about any axis through its centre (the diagonal too).
  CHECK(double(r["cube_moment_about_axis"]) == Approx(m * a * a / 6).epsilon(1e-14));
  CHECK(double(r["cube_moment_about_diagonal"]) == Approx(m * a * a / 6).epsilon(1e-14));
}

TEST_CASE("tire_balancing: every CSV row's torque is dL/dt, normal to L, of the reported size") {
  const std::string path = "/tmp/rigid_tire_test_" + std::to_string(::getpid()) + ".csv";
  const auto run = run_lab("tire_balancing", "--json --csv " + path);
  REQUIRE(run.status == 0);
  const double torque = run.json()["results"]["torque_unbalanced_nm"];
  const rigid::test::Csv csv = rigid::test::read_csv(path);
  CHECK(csv.header == "t_s,Lx,Ly,Lz,Nx,Ny,Nz");
  REQUIRE(csv.rows.size() > 100);
  const double L0 = std::hypot(csv.rows[0][1], csv.rows[0][2], csv.rows[0][3]);
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    const auto& v = csv.rows[i];
    const double L = std::hypot(v[1], v[2], v[3]), N = std::hypot(v[4], v[5], v[6]);
    CHECK(L == Approx(L0).epsilon(1e-14));      // L turns, keeps its size
    CHECK(N == Approx(torque).epsilon(1e-14));  // the reported torque, every row
    CHECK(std::abs(v[1] * v[4] + v[2] * v[5] + v[3] * v[6]) <= 1e-12 * L * N);  // N normal to L
    if (i > 0 && i + 1 < csv.rows.size()) {
      // N = dL/dt by central differences: error (dt^2 / 6) |d^3 L / dt^3| = (w dt)^2 / 6 of N.
      const auto& p = csv.rows[i - 1];
      const auto& q = csv.rows[i + 1];
      const double dt = q[0] - p[0];
      for (int k = 1; k <= 3; ++k) {
        CHECK((q[k] - p[k]) / dt == Approx(v[k + 3]).margin(1e-3 * torque));
      }
    }
  }
  std::remove(path.c_str());
}

TEST_CASE("poinsot: the CSV's rows agree with the reported end state and drifts") {
  const std::string path = "/tmp/rigid_poinsot_rows_" + std::to_string(::getpid()) + ".csv";
  const auto run = run_lab("poinsot", "--json --method rk4 --csv " + path);
  REQUIRE(run.status == 0);
  const auto j = run.json();
  const auto& r = j["results"];
  const rigid::test::Csv csv = rigid::test::read_csv(path);
  REQUIRE(csv.rows.size() > 10);
  const auto& last = csv.rows.back();
  CHECK(last[0] == double(r["t_end_s"]));
  for (int i = 0; i < 3; ++i) CHECK(last[1 + i] == double(r["omega_end"][i]));
  double dE = 0, dL = 0;
  const double E0 = csv.rows[0][8], L0 = csv.rows[0][9];
  for (const auto& v : csv.rows) {
    CHECK(std::hypot(std::hypot(v[4], v[5]), std::hypot(v[6], v[7])) == Approx(1).epsilon(1e-15));
    dE = std::max(dE, std::abs(v[8] - E0) / E0);
    dL = std::max(dL, std::abs(v[9] - L0) / L0);
  }
  // The same maxima the run reported (the CSV prints 17 digits: equal to roundoff).
  CHECK(dE == Approx(double(r["energy_drift_rel"])).epsilon(1e-6).margin(1e-15));
  CHECK(dL == Approx(double(r["momentum_drift_rel"])).epsilon(1e-6).margin(1e-15));
  std::remove(path.c_str());
}

// Issue 13, item 3: every lab at inputs none of its defaults share, against the
// chapter's formulas typed here (or a quadrature / another library's elliptic
// integral), never against the lab's own output. Tolerances: the formulas are a
// few operations each, so a few ulps; 1e-13 relative leaves room for libm.
namespace {
constexpr double kDeg = M_PI / 180;
double value(const nlohmann::json& r, const char* key) {
  return r.at(key).get<double>();
}
}  // namespace

TEST_CASE("tire_balancing: another wheel against eqs. 55-61 typed here") {
  const double m = 12, a = 0.3, b = 0.08, theta = 3 * kDeg, omega = 50;
  const auto run = run_lab("tire_balancing",
                           "--json --mass 12 --radius 0.3 --offset 0.08 --tilt-deg 3 --omega 50");
  REQUIRE(run.status == 0);
  const auto j = run.json();
  const auto& r = j["results"];
  // The disk's symmetry axis is x, the axle (cos, sin, 0): L = omega (m a^2/2 cos, m a^2/4 sin, 0).
  const double Lx = m * a * a / 2 * std::cos(theta), Ly = m * a * a / 4 * std::sin(theta);
  CHECK(value(r, "angle_L_axle_deg") ==
        Approx(theta / kDeg - std::atan2(Ly, Lx) / kDeg).epsilon(1e-13));
  // |omega x L| = omega^2 m a^2 sin(2 theta) / 8.
  CHECK(value(r, "torque_unbalanced_nm") ==
        Approx(omega * omega * m * a * a * std::sin(2 * theta) / 8).epsilon(1e-13));
  // Eq. 60 solved for m0: tan 2theta (m a^2/4 + 2 m0 (a^2 - b^2)) = 4 a b m0.
  const double t = std::tan(2 * theta);
  CHECK(value(r, "balance_mass_kg") ==
        Approx(t * m * a * a / 4 / (4 * a * b - 2 * t * (a * a - b * b))).epsilon(1e-13));
  // Eq. 61: theta = 8 b m0 / (a m).
  CHECK(value(r, "balance_mass_small_angle_kg") == Approx(theta * a * m / (8 * b)).epsilon(1e-14));
  // Balanced exactly: the principal axis on the axle and no torque, to roundoff.
  CHECK(value(r, "residual_tilt_exact_deg") < 1e-12);
  CHECK(value(r, "torque_balanced_nm") <= 1e-13 * value(r, "torque_unbalanced_nm"));
  CHECK(value(r, "residual_tilt_small_angle_deg") > 1e-3);
}

TEST_CASE("poinsot: another body's period against Landau's formula and std::comp_ellint_1") {
  const double I[3] = {2, 3, 5}, w[3] = {1.2, -0.4, 0.3};
  const auto run = run_lab("poinsot", "--json --inertia 2,3,5 --omega 1.2,-0.4,0.3");
  REQUIRE(run.status == 0);
  const auto j = run.json();
  const auto& r = j["results"];
  double E2 = 0, L2 = 0;  // 2T and L^2
  for (int i = 0; i < 3; ++i) E2 += I[i] * w[i] * w[i], L2 += I[i] * I[i] * w[i] * w[i];
  CHECK(value(r, "energy") == Approx(E2 / 2).epsilon(1e-15));
  CHECK(value(r, "angular_momentum_magnitude") == Approx(std::sqrt(L2)).epsilon(1e-15));
  // Landau & Lifshitz, Mechanics, section 37: for L^2 < 2 E I2 (here 9.45 < 11.43) the
  // polhode circles the smallest axis: their formulas with I1 and I3 exchanged
  // (the racquet's test below takes the other family).
  REQUIRE(L2 < E2 * I[1]);
  CHECK(r["regime"] == "polhode about the smallest axis");
  const double I1 = I[2], I2 = I[1], I3 = I[0];
  const double rate = std::sqrt((I3 - I2) * (L2 - E2 * I1) / (I1 * I2 * I3));
  const double k2 = (I2 - I1) * (E2 * I3 - L2) / ((I3 - I2) * (L2 - E2 * I1));
  // libstdc++'s K(k) (Carlson's R_F of its own), a second implementation beside Boost's.
  CHECK(value(r, "polhode_period_s") ==
        Approx(4 * std::comp_ellint_1(std::sqrt(k2)) / rate).epsilon(1e-13));
  for (int i = 0; i < 3; ++i) {
    CHECK(double(r["energy_ellipsoid_semi_axes"][i]) ==
          Approx(std::sqrt(E2 / I[i])).epsilon(1e-15));
    CHECK(double(r["momentum_ellipsoid_semi_axes"][i]) ==
          Approx(std::sqrt(L2) / I[i]).epsilon(1e-15));
  }
  // Three periods later (the default t_end) omega is back where it started.
  for (int i = 0; i < 3; ++i) CHECK(double(r["omega_end"][i]) == Approx(w[i]).margin(1e-13));
}

TEST_CASE("football: an oblate body at another spin and angle against eqs. 109 and 143-147") {
  const double I = 0.3, Is = 0.5, omega = 7, alpha = 25 * kDeg;
  const auto run = run_lab("football", "--json --inertia 0.3,0.5 --omega 7 --alpha-deg 25");
  REQUIRE(run.status == 0);
  const auto j = run.json();
  const auto& r = j["results"];
  const double s = std::sin(alpha), c = std::cos(alpha);
  CHECK(value(r, "body_precession_rate_rad_s") == Approx(omega * c * (Is - I) / I).epsilon(1e-14));
  const double L = omega * std::sqrt(I * I * s * s + Is * Is * c * c);  // eq. 143
  CHECK(value(r, "space_precession_rate_rad_s") == Approx(L / I).epsilon(1e-14));
  const double theta = std::atan(I / Is * std::tan(alpha));  // eq. 144
  CHECK(value(r, "theta_deg") == Approx(theta / kDeg).epsilon(1e-14));
  CHECK(value(r, "space_cone_half_angle_deg") == Approx((alpha - theta) / kDeg).epsilon(1e-12));
  CHECK(r["cones_touch"] == "inside");  // oblate: theta < alpha
  CHECK(value(r, "body_precession_period_s") ==
        Approx(2 * M_PI * I / (omega * c * (Is - I))).epsilon(1e-14));
}

TEST_CASE("tennis_racquet: another racquet against eqs. 83-85 and 94-101 typed here") {
  const double ma = 0.2, a = 0.15, ml = 0.1, l = 0.3, omega = 7;
  const auto run = run_lab("tennis_racquet",
                           "--json --head-mass 0.2 --head-radius 0.15 "
                           "--handle-mass 0.1 --handle-length 0.3 --omega 7");
  REQUIRE(run.status == 0);
  const auto j = run.json();
  const auto& r = j["results"];
  const double R = ml * (a + l / 2) / (ma + ml);  // eq. 83: the centre of mass from the head's
  CHECK(value(r, "cm_offset_m") == Approx(R).epsilon(1e-15));
  const double I1 = ma * a * a / 2;  // eq. 84
  const double I2 = ma * a * a / 2 + ma * R * R + ml * l * l / 12 +
                    ml * (a + l / 2 - R) * (a + l / 2 - R);  // eq. 85
  const double I3 = I1 + I2;
  CHECK(double(r["principal_moments"][0]) == Approx(I1).epsilon(1e-14));
  CHECK(double(r["principal_moments"][1]) == Approx(I2).epsilon(1e-14));
  CHECK(double(r["principal_moments"][2]) == Approx(I3).epsilon(1e-14));
  // Linearised Euler equations about each axis (eqs. 94-101 without eq. 92's rounding).
  CHECK(value(r, "growth_rate_per_s") ==
        Approx(omega * std::sqrt((I2 - I1) * (I3 - I2) / (I1 * I3))).epsilon(1e-13));
  CHECK(double(r["wobble_frequencies_rad_s"][0]) ==
        Approx(omega * std::sqrt((I2 - I1) * (I3 - I1) / (I2 * I3))).epsilon(1e-13));
  CHECK(double(r["wobble_frequencies_rad_s"][1]) ==
        Approx(omega * std::sqrt((I3 - I1) * (I3 - I2) / (I1 * I2))).epsilon(1e-13));
  // The launch: omega = 7 (0, sqrt(1 - p^2), p), p = 0.01 along axis 3; its period by Landau.
  const double p = 0.01, w[3] = {0, omega * std::sqrt(1 - p * p), omega * p}, Is[3] = {I1, I2, I3};
  double E2 = 0, L2 = 0;
  for (int i = 0; i < 3; ++i) E2 += Is[i] * w[i] * w[i], L2 += Is[i] * Is[i] * w[i] * w[i];
  REQUIRE(L2 > E2 * I2);  // about the largest axis
  const double rate = std::sqrt((I3 - I2) * (L2 - E2 * I1) / (I1 * I2 * I3));
  const double k2 = (I2 - I1) * (E2 * I3 - L2) / ((I3 - I2) * (L2 - E2 * I1));
  // Near the separatrix (k'^2 ~ p^2) K is conditioned by ~1/k'^2 ~ 1e4: 1e-11.
  CHECK(value(r, "polhode_period_s") ==
        Approx(4 * std::comp_ellint_1(std::sqrt(k2)) / rate).epsilon(1e-11));
  // The spin flips every half period, the first a quarter period in (launched at sn = 0).
  CHECK(value(r, "flip_interval_s") == Approx(value(r, "polhode_period_s") / 2).epsilon(1e-12));
}

TEST_CASE("top_nutation: another top against eqs. 185-189 and a quadrature of the period") {
  const double m = 1.5, l = 0.06, rd = 0.04, g = 9.8, S = 1500 * 2 * M_PI / 60, theta0 = 50 * kDeg;
  const auto run = run_lab("top_nutation",
                           "--json --mass 1.5 --arm 0.06 --disk-radius 0.04 "
                           "--spin-rpm 1500 --theta0-deg 50");
  REQUIRE(run.status == 0);
  const auto j = run.json();
  const auto& r = j["results"];
  const double Is = m * rd * rd / 2, I = m * rd * rd / 4 + m * l * l, mgl = m * g * l;
  CHECK(value(r, "moment_symmetry_kg_m2") == Approx(Is).epsilon(1e-15));
  CHECK(value(r, "moment_transverse_kg_m2") == Approx(I).epsilon(1e-15));
  CHECK(value(r, "min_spin_rad_s") ==
        Approx(std::sqrt(4 * mgl * I) / Is).epsilon(1e-14));  // eq. 189
  CHECK(value(r, "horizontal_precession_rate_rad_s") ==
        Approx(mgl / (Is * S)).epsilon(1e-14));  // eq. 185
  // Eq. 187: I cos(theta) phi_dot^2 - Is S phi_dot + m g l = 0, the two roots.
  const double c = std::cos(theta0), D = std::sqrt(Is * Is * S * S - 4 * mgl * I * c);
  CHECK(double(r["steady_precession_rates_rad_s"][0]) ==
        Approx((Is * S - D) / (2 * I * c)).epsilon(1e-12));
  CHECK(double(r["steady_precession_rates_rad_s"][1]) ==
        Approx((Is * S + D) / (2 * I * c)).epsilon(1e-13));
  // Released at rest in theta and phi (a cusp): theta_min = theta0, and the period is
  // 2 int_{u1}^{u2} du / sqrt(f(u)), f = beta (u - u1)(u2 - u)(u3 - u), beta = 2 m g l / I;
  // with u = u1 + (u2 - u1) sin^2(x) it is 4 int_0^{pi/2} dx / sqrt(beta (u3 - u)), an
  // analytic periodic integrand for which the midpoint rule converges geometrically.
  CHECK(value(r, "theta_min_deg") == Approx(50).epsilon(1e-13));
  const double u1 = r["cubic_roots"][0], u2 = r["cubic_roots"][1], u3 = r["cubic_roots"][2];
  const double a = Is * S / I, b = a * c, beta = 2 * mgl / I, alpha = beta * c;  // eqs. 194-197
  for (double u : {u1, u2, u3}) {  // each a root of f(u) = (1 - u^2)(alpha - beta u) - (b - a u)^2
    CHECK(std::abs((1 - u * u) * (alpha - beta * u) - (b - a * u) * (b - a * u)) <
          1e-13 * (a * a + beta));
  }
  const int n = 400;
  double sum = 0;
  for (int k = 0; k < n; ++k) {
    const double x = (k + 0.5) * (M_PI / 2) / n, sx = std::sin(x);
    sum += 1 / std::sqrt(beta * (u3 - (u1 + (u2 - u1) * sx * sx)));
  }
  CHECK(value(r, "nutation_period_s") == Approx(4 * sum * (M_PI / 2) / n).epsilon(1e-12));
}

TEST_CASE("labs: which integrator drifts, answered by the table at equal cost, and --periods") {
  for (const char* lab : {"poinsot", "top_nutation"}) {
    INFO(lab);
    const auto run = run_lab(lab, "--json --method rk4 --periods 5");
    REQUIRE(run.status == 0);
    const auto j = run.json();
    const auto& r = j["results"];
    // --periods N ends at N of the motion's periods
    const double period = r.contains("polhode_period_s") ? value(r, "polhode_period_s")
                                                         : value(r, "nutation_period_s");
    CHECK(value(r, "t_end_s") == Approx(5 * period).epsilon(1e-15));
    CHECK(r["method_kind"] == "fixed-step Runge-Kutta, order 4");
    // Each invariant's largest error and its trend; the old key is the largest error.
    CHECK(r["energy_drift_rel"] == r["energy_error_max_rel"]);
    CHECK(std::abs(value(r, "energy_drift_per_period_rel")) <= value(r, "energy_error_max_rel"));
    // At equal cost a splitting drifts least, by at least ten times every other kind.
    const std::string least = r["least_energy_drift"];
    CHECK((least == "splitting" || least == "splitting4"));
    CHECK(r["least_energy_drift_kind"].get<std::string>().find("symplectic") == 0);
    const double split = std::abs(value(r, "equal_cost_energy_drift_per_period_rel_splitting"));
    for (const char* other : {"rk4", "dopri5", "rkf78", "bulirsch_stoer"}) {
      INFO(other);
      CHECK(10 * split <
            std::abs(value(
                r, ("equal_cost_energy_drift_per_period_rel_" + std::string(other)).c_str())));
    }
    CHECK(value(r, "equal_cost_evaluations_per_period") == 200);
  }
  // The table says which drifts, with the kind of each method in --help.
  const auto table = run_lab("poinsot", "");
  CHECK_THAT(table.out, Catch::Contains("least energy drift at equal cost"));
  CHECK_THAT(run_lab("poinsot", "--help").out, Catch::Contains("symplectic splitting, order 2"));
}

TEST_CASE("tire_balancing: a straight axle is a balanced wheel, and the spin comes from the road") {
  const auto run = run_lab("tire_balancing",
                           "--json --tilt-deg 0 --road-speed-m-s 27.8 "
                           "--tyre-radius-m 0.31");
  REQUIRE(run.status == 0);
  const auto j = run.json();
  const auto& r = j["results"];
  CHECK(value(r, "omega_rad_s") == Approx(27.8 / 0.31).epsilon(1e-15));
  CHECK(value(r, "road_speed_km_h") == Approx(100.08).epsilon(1e-15));
  // No tilt: L along the axle, no torque, no mass needed (all exactly: the disk's axis is x).
  CHECK(value(r, "angle_L_axle_deg") == 0.0);
  CHECK(value(r, "torque_unbalanced_nm") == 0.0);
  CHECK(value(r, "balance_mass_kg") == 0.0);
  CHECK(value(r, "balance_mass_small_angle_kg") == 0.0);
  CHECK(!j["inputs"].contains("omega"));
  // A road speed gives the same wheel as its omega.
  const auto same = run_lab("tire_balancing", "--json --road-speed-m-s 27.9 --tyre-radius-m 0.31");
  const auto direct = run_lab("tire_balancing", "--json --omega " + std::to_string(27.9 / 0.31));
  CHECK(value(same.json()["results"], "torque_unbalanced_nm") ==
        Approx(value(direct.json()["results"], "torque_unbalanced_nm")).epsilon(1e-12));
  // Roundoff is printed as 0 with its bound in the table; JSON keeps the number.
  const auto table = run_lab("tire_balancing", "");
  CHECK_THAT(table.out, Catch::Contains("(roundoff: |computed| <="));
}

TEST_CASE("lamina_tensor: the plate about its diagonal, or an axis by its angle in the plane") {
  // A 1 x 2 plate of mass 1 about its corner: I = (4/3, -1/2; -1/2, 1/3), Izz = 5/3 (eq. 20).
  const auto diag = run_lab("lamina_tensor", "--json --axis diagonal");
  REQUIRE(diag.status == 0);
  const auto j = diag.json();
  const auto& r = j["results"];
  const double n[2] = {1 / std::sqrt(5.0), 2 / std::sqrt(5.0)};
  CHECK(double(r["axis_unit"][0]) == Approx(n[0]).epsilon(1e-15));
  CHECK(double(r["axis_unit"][1]) == Approx(n[1]).epsilon(1e-15));
  // n.I.n = (4/3 - 2 + 4/3) / 5 = 2/15; L = I n; about the corner's diagonal the products
  // of inertia do not vanish, so L is off the axis.
  CHECK(value(r, "scalar_moment") == Approx(2.0 / 15).epsilon(1e-14));
  const double Lx = 4.0 / 3 * n[0] - 0.5 * n[1], Ly = -0.5 * n[0] + 1.0 / 3 * n[1];
  CHECK(double(r["angular_momentum"][0]) == Approx(Lx).epsilon(1e-14));
  CHECK(double(r["angular_momentum"][1]) == Approx(Ly).epsilon(1e-14));
  CHECK(
      value(r, "angle_L_omega_deg") ==
      Approx(std::acos((Lx * n[0] + Ly * n[1]) / std::hypot(Lx, Ly)) * 180 / M_PI).epsilon(1e-12));
  CHECK(j["inputs"]["axis"] == "diagonal");
  CHECK(!r.contains("paddle_principal_moments"));  // section 2.1 only when asked
  // About the centre the diagonal is no principal axis either (a != b), but Ixy = 0 there.
  const auto angle = run_lab("lamina_tensor", "--json --axis-deg 30");
  REQUIRE(angle.status == 0);
  CHECK(double(angle.json()["results"]["axis_unit"][0]) ==
        Approx(std::sqrt(3.0) / 2).epsilon(1e-15));
  CHECK(value(angle.json()["results"], "axis_angle_from_x_deg") == Approx(30).epsilon(1e-14));
}

TEST_CASE("labs: an option the method does not use is said so, once the run succeeds") {
  const auto run = run_lab("tennis_racquet", "--json --method rk4 --tolerance 1e-6");
  REQUIRE(run.status == 0);
  CHECK(run.err ==
        "tennis_racquet: warning: --tolerance: rk4 takes a fixed step; it is not used "
        "(--step sets it)\n");
  bool noted = false;
  const auto j = run.json();
  for (const auto& note : j["notes"]) noted |= note.get<std::string>().rfind("warning:", 0) == 0;
  CHECK(noted);
  // a fixed step that does not divide t_end: the shortened last step is reported
  const auto fixed = run_lab("poinsot", "--json --method rk4 --step 0.3 --t-end 10");
  REQUIRE(fixed.status == 0);
  CHECK(value(fixed.json()["results"], "last_step_s") == Approx(10 - 33 * 0.3).epsilon(1e-12));
  CHECK(fixed.err.empty());
  // --project with the closed form is refused, not ignored
  CHECK(run_lab("poinsot", "--project").status == 2);
}

TEST_CASE("poinsot: the motion in words, with its stability and how near the separatrix") {
  struct Case {
    const char* args;
    const char* stability;
    const char* words;  // a part of the sentence
  };
  for (const Case& c :
       {Case{"", "stable", "polhode about the largest axis: stable"},
        Case{"--inertia 1,2,3 --omega 1,0.1,0.05", "stable", "polhode about the smallest axis"},
        Case{"--inertia 3,3.75,5 --omega 5,1,3.0001", "unstable",
             "near the separatrix (k'^2 = 6.5e-05)"},
        Case{"--inertia 3,3.75,5 --omega 5,1,3", "unstable", "on the separatrix"},
        Case{"--inertia 1,2,3 --omega 0,1,0", "unstable", "intermediate axis 2: unstable"},
        Case{"--inertia 1,2,3 --omega 0,0,4", "stable", "largest axis 3: stable"},
        Case{"--inertia 1,2,3 --omega 4,0,0", "stable", "smallest axis 1: stable"},
        Case{"--inertia 2,2,3 --omega 1,1,0", "neutral", "plane of two equal moments"},
        Case{"--inertia 2,2,2 --omega 1,2,3", "neutral", "spherical"}}) {
    INFO(c.args);
    const auto run = run_lab("poinsot", std::string("--json ") + c.args);
    REQUIRE(run.status == 0);
    const auto j = run.json();
    CHECK(j["results"]["motion_stability"] == c.stability);
    CHECK_THAT(j["results"]["motion"].get<std::string>(), Catch::Contains(c.words));
  }
  // k'^2 against Landau's k^2 for the near-separatrix body (I = 3, 3.75, 5; omega0 = 5, 1, 3.0001):
  // k'^2 = 1 - k^2, k^2 = (I2 - I1)(2 E I3 - L^2) / ((I3 - I2)(L^2 - 2 E I1)).
  const double I[3] = {3, 3.75, 5}, w[3] = {5, 1, 3.0001};
  double E2 = 0, L2 = 0;
  for (int i = 0; i < 3; ++i) E2 += I[i] * w[i] * w[i], L2 += I[i] * I[i] * w[i] * w[i];
  const double kp2 = ((I[2] - I[1]) * (L2 - E2 * I[0]) - (I[1] - I[0]) * (E2 * I[2] - L2)) /
                     ((I[2] - I[1]) * (L2 - E2 * I[0]));
  const auto near = run_lab("poinsot", "--json --inertia 3,3.75,5 --omega 5,1,3.0001");
  // k'^2 is a difference of nearly equal products: conditioned by ~1/k'^2 ~ 1e4
  CHECK(value(near.json()["results"], "complementary_parameter") == Approx(kp2).epsilon(1e-10));
}

TEST_CASE("poinsot: a solid box (a phone) beside the ellipsoid, its moments by eq. 40") {
  const double m = 0.2, A = 0.16, B = 0.08, C = 0.008;
  const auto run = run_lab("poinsot", "--json --box 0.16,0.08,0.008 --mass 0.2 --omega 0,5,0.01");
  REQUIRE(run.status == 0);
  const auto j = run.json();
  const auto& I = j["results"]["principal_moments"];
  CHECK(double(I[0]) == Approx(m * (B * B + C * C) / 12).epsilon(1e-15));
  CHECK(double(I[1]) == Approx(m * (A * A + C * C) / 12).epsilon(1e-15));
  CHECK(double(I[2]) == Approx(m * (A * A + B * B) / 12).epsilon(1e-15));
  // spun about its middle axis, nudged: the tennis racquet theorem for a phone
  CHECK(j["results"]["motion_stability"] == "unstable");
  CHECK(!j["inputs"].contains("ellipsoid"));
  CHECK(run_lab("poinsot", "--box 1,1,1 --ellipsoid 1,2,3").status == 2);
  CHECK(run_lab("poinsot", "--box 1,1,1 --inertia 1,2,3").status == 2);
  CHECK(run_lab("poinsot", "--box 1,0,1").status == 2);
}

TEST_CASE("poinsot: --animate writes the motion as an MP4 or a WebP, and says so in the JSON") {
  const std::string dir = "/tmp/rigid_anim_test_" + std::to_string(::getpid());
  std::filesystem::create_directories(dir);
  for (const std::string ext : {"mp4", "webp"}) {
    const std::string path = dir + "/poinsot." + ext;
    const rigid::test::Run run = rigid::test::run_lab(
        "poinsot", "--json --animate " + path + " --duration 0.5 --fps 8 --animation-size 480x270");
    INFO(run.err);
    REQUIRE(run.status == 0);
    const nlohmann::json a = run.json()["animation"];
    // 0.5 s at 8 fps: 4 frames over three polhode periods (the default --t-end)
    CHECK(a["frames"] == 4);
    CHECK(a["width"] == 480);
    CHECK(a["height"] == 270);
    CHECK(a["duration_s"] == Approx(0.5));
    CHECK(a["motion_s"] == Approx(3 * run.json()["results"]["polhode_period_s"].get<double>()));
    CHECK(std::filesystem::file_size(path) == a["bytes"].get<std::size_t>());
    const auto outputs = run.json()["outputs"];
    CHECK(std::find(outputs.begin(), outputs.end(), std::filesystem::absolute(path).string()) !=
          outputs.end());
    // one final line on stderr (not a terminal: no progress line)
    CHECK(run.err.find("wrote " + path) != std::string::npos);
    CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);
  }
  // --quiet says nothing
  const rigid::test::Run quiet =
      rigid::test::run_lab("poinsot", "--quiet --animate " + dir + "/q.mp4 --duration 0.2 --fps 5");
  CHECK(quiet.status == 0);
  CHECK(quiet.err.empty());
  std::filesystem::remove_all(dir);
}

TEST_CASE("poinsot: bad animation options exit 2 with one line naming the option") {
  const std::string dir = "/tmp/rigid_anim_bad_" + std::to_string(::getpid());
  std::filesystem::create_directories(dir);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--animate " + dir + "/a.gif", "--animate"},
      {"--animate " + dir + "/no/such/dir/a.mp4", "--animate"},
      {"--animate " + dir, "--animate"},
      {"--animate " + dir + "/a.mp4 --fps 0", "--fps"},
      {"--animate " + dir + "/a.mp4 --fps nan", "--fps"},
      {"--animate " + dir + "/a.mp4 --duration 1e9", "--duration"},
      {"--animate " + dir + "/a.mp4 --animation-size 641x360", "--animation-size"},
      {"--fps 10", "--fps"},
      {"--duration 2", "--duration"},
      // where permission bits say yes and no file can be made: checked before any work,
      // so the CSV and figures asked beside it are not written either
      {"--csv " + dir + "/x.csv --figures " + dir + "/f --animate /proc/a.mp4", "--animate"},
      {"--animate " + dir + "/a.mp4 --figures /proc/f", "--figures"},
      {"--figures " + dir + "/f --csv /proc/x.csv", "--csv"},
  };
  for (const auto& [args, option] : cases) {
    const rigid::test::Run run = rigid::test::run_lab("poinsot", args);
    INFO(args << " -> " << run.err);
    CHECK(run.status == 2);
    CHECK(run.one_error_line());
    CHECK(run.err.find(option) != std::string::npos);
  }
  // nothing was written
  CHECK(std::filesystem::is_empty(dir));
  std::filesystem::remove_all(dir);
}

TEST_CASE("labs with motion: --animate writes a short animation of each") {
  const std::string dir = "/tmp/rigid_anim_labs_" + std::to_string(::getpid());
  std::filesystem::create_directories(dir);
  for (const std::string lab : {"poinsot", "tennis_racquet", "football", "top_nutation"}) {
    const std::string path = dir + "/" + lab + ".mp4";
    const rigid::test::Run run =
        rigid::test::run_lab(lab, "--json --animate " + path + " --duration 0.2 --fps 10");
    INFO(lab << ": " << run.err);
    REQUIRE(run.status == 0);
    CHECK(run.json()["animation"]["frames"] == 2);
    CHECK(std::filesystem::file_size(path) > 0);
  }
  // frames from an integrator, sampled at the frame times: a fixed step off their grid,
  // and an adaptive method with dense output
  for (const auto& [lab, method] :
       {std::pair<std::string, std::string>{"poinsot", "--method rk4 --step 0.37"},
        {"poinsot", "--method vern7"},
        {"top_nutation", "--method splitting4"},
        {"tennis_racquet", "--method rk4 --step 0.01"},
        {"top_nutation", "--method vern8"}}) {
    const rigid::test::Run run = rigid::test::run_lab(
        lab, method + " --json --animate " + dir + "/i.mp4 --duration 0.5 --fps 10");
    INFO(lab << " " << method << ": " << run.err);
    CHECK(run.status == 0);
    CHECK(run.json()["animation"]["frames"] == 5);
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("top_nutation: the fast-top estimates only for a fast top") {
  // their relative error is of order 2 m g l I / (Is S)^2: the text's top 0.41, printed;
  // at S = 30 rad/s 1.24 and at 1e-10 rad/s 1e23 (it read 3e24 deg), none
  const auto text = rigid::test::run_lab("top_nutation", "--json");
  REQUIRE(text.status == 0);
  CHECK(text.json()["results"]["fast_top_nutation_amplitude_deg"].is_number());
  for (const char* spin : {"30", "1e-10"}) {
    const auto slow = rigid::test::run_lab("top_nutation", std::string("--json --spin ") + spin);
    REQUIRE(slow.status == 0);
    CHECK(slow.json()["results"]["fast_top_nutation_amplitude_deg"].is_null());
    CHECK(slow.json()["results"]["fast_top_nutation_frequency_rad_s"].is_null());
  }
}

TEST_CASE("figures of extreme valid input are drawn, not an error") {
  // top_nutation at S = 1e20: theta flat at 30 deg, its axis range lo + 1 == lo (the
  // ticks threw); lamina_tensor at 1e60: |I n|^2 overflowed and L's arrow had no length
  const std::string dir = "/tmp/rigid_extreme_figures_" + std::to_string(::getpid());
  for (const auto& [lab, args] :
       {std::pair<std::string, std::string>{"top_nutation", "--spin 1e20"},
        {"lamina_tensor", "--a 1e60 --b 1e60 --mass 1e60"},
        {"lamina_tensor", "--a 1e-60 --b 1e-60 --mass 1e-60"}}) {
    const auto run = rigid::test::run_lab(lab, "--quiet " + args + " --figures " + dir);
    INFO(lab << " " << args << ": " << run.err);
    CHECK(run.status == 0);
    CHECK(run.err.empty());
  }
  std::filesystem::remove_all(dir);
}
