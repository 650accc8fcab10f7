// Each lab's own contract: its JSON keys, the text's numbers at its defaults,
// and exit status 2 with one line naming the option for its own bad input
// (what every lab shares is in contract_test.cpp).
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>

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
      {"tire_balancing", "--tilt-deg 0", "--tilt-deg"},
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
  };
  for (const auto& [args, option] : cases) {
    INFO(args);
    const auto run = run_lab("poinsot", args);
    CHECK(run.status == 2);
    CHECK(run.one_error_line());
    CHECK(run.err.rfind(std::string("poinsot: error: ") + option, 0) == 0);
    CHECK(run.out.empty());
  }
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
                                       "--t-end 37.5 ") + c);
    REQUIRE(run.status == 0);
    const auto j = run.json();
    CHECK(double(j["results"]["t_end_s"]) == 37.5);
  }
}

TEST_CASE("poinsot: stress - nearly spherical, flat, fast and near-separatrix bodies") {
  const char* cases[] = {
      "--inertia 1,1.000000001,1.000000002 --omega 1,1,1",  // nearly spherical: k' -> 0
      "--inertia 1,2,3 --omega 0.3,1,0.2",                   // a lamina, I3 = I1 + I2
      "--omega 1e6,1e6,1e6",                                 // huge spin
      "--inertia 3,5,7 --omega 0,0.4,0.00111",               // next to the separatrix
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
  for (const char* key :
       {"body_precession_rate_rad_s", "space_precession_rate_rad_s", "theta_deg",
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
      {"--alpha-deg 0", "--alpha-deg"},   {"--alpha-deg 90", "--alpha-deg"},
      {"--alpha-deg nan", "--alpha-deg"}, {"--inertia 1,3", "--inertia"},
      {"--inertia -1,1", "--inertia"},    {"--inertia 1", "--inertia"},
      {"--preset moon", "--preset"},      {"--omega 0", "--omega"},
      {"--preset earth --inertia 1,1", "--inertia"},
  };
  for (const auto& [args, option] : cases) {
    INFO(args);
    const auto run = run_lab("football", args);
    CHECK(run.status == 2);
    CHECK(run.one_error_line());
    CHECK(run.err.rfind(std::string("football: error: ") + option, 0) == 0);
    CHECK(run.out.empty());
  }
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
