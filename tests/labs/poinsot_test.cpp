// poinsot's library in-process: the text's ellipsoid at its defaults, every
// integrator against the closed form, other bodies against Landau's formulas
// typed here, the motion in words, the box and the rules compute() checks. The
// figures handed over and the motion: poinsot_motion_test.cpp.
#include "poinsot/poinsot.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>

#include "equal_cost_checks.h"
#include "lab_library.h"
#include "poinsot_inputs.h"
#include "rigid/format.h"

using Catch::Matchers::WithinAbs;
using rigid::lab::InputError;
using rigid::lab::poinsot::compute;
using rigid::lab::poinsot::Inputs;
using rigid::lab::poinsot::Report;
using rigid::test::check_ranking;
using rigid::test::given;
using rigid::test::kRoundoff;
using rigid::test::named_method;
using rigid::test::names_input;
using rigid::test::prints_as;
using rigid::test::ranked_methods;
using rigid::test::user_guide;
using rigid::test::value;

TEST_CASE("poinsot: defaults reproduce the text's ellipsoid of section 5.1") {
  const Report report = compute(Inputs{});
  const auto& r = report.results();
  for (const char* key : {"principal_moments", "omega_end", "energy", "angular_momentum_magnitude",
                          "polhode_period_s", "method", "energy_drift_rel", "momentum_drift_rel"}) {
    CHECK(r.contains(key));
  }
  const double pi = 3.14159265358979323846;
  CHECK_THAT(double(r["principal_moments"][0]), WithinAbs(pi, kRoundoff));
  CHECK_THAT(double(r["principal_moments"][1]), WithinAbs(2 * pi, kRoundoff));
  CHECK(prints_as(r["principal_moments"][2], 8.168, 3));
  CHECK(r["method"] == "exact");
  // The closed form keeps T and |L| to roundoff: a few ulps per sample.
  CHECK(value(r, "energy_drift_rel") < 12 * DBL_EPSILON);
  CHECK(value(r, "momentum_drift_rel") < 12 * DBL_EPSILON);
  CHECK(value(r, "L_space_drift_rel") < 12 * DBL_EPSILON);
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
    const Report report = compute(given(std::string("--method ") + c.method));
    CHECK(value(report.results(), "max_error_vs_exact") < c.bound);
  }
}

TEST_CASE("poinsot: the time series has t, omega, the quaternion, energy and |L|") {
  // (the file --csv writes from it stays a test of the command)
  const Report report = compute(given("--method splitting"));
  CHECK(report.time_series().names() == std::vector<std::string>{"t_s", "omega1", "omega2",
                                                                 "omega3", "qw", "qx", "qy", "qz",
                                                                 "energy_J", "L_kg_m2_s"});
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
    const Report report = compute(given(c.args));
    const auto& r = report.results();
    CHECK(r["polhode_period_s"].is_null());
    CHECK(r["regime"] == c.regime);
    CHECK(value(r, "energy_drift_rel") < 12 * DBL_EPSILON);
  }
}

TEST_CASE("poinsot: a fixed step is taken as given, only the last shortened to end at t_end") {
  // h = 1 s on a 10.3 s polhode period: rk4's error is large, as it must be.
  const Report report = compute(given("--method rk4 --step 1"));
  const auto& r = report.results();
  CHECK(value(r, "step_s") == 1.0);
  // t_end is three periods, reached by whole steps and one shortened last step.
  CHECK(value(r, "t_end_s") == 3 * value(r, "polhode_period_s"));
  CHECK(value(r, "steps") == std::ceil(value(r, "t_end_s")));
  CHECK(value(r, "max_error_vs_exact") > 1e-3);
  CHECK(!report.inputs().contains("inertia"));
}

TEST_CASE("poinsot: omega is reported at exactly the t_end asked for, by every fixed-step method") {
  // 37.5 s is no whole number of steps of period / 2000 nor of 0.00125 s (to roundoff).
  const char* cases[] = {"--method rk4", "--method rk4 --step 0.00125", "--method splitting",
                         "--method splitting4"};
  for (const char* c : cases) {
    INFO(c);
    const Report report =
        compute(given(std::string("--inertia 1.2,2.3,3.1 --omega 0.3,1.7,-0.4 --t-end 37.5 ") + c));
    CHECK(value(report.results(), "t_end_s") == 37.5);
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
    const Report report = compute(given(args));
    const auto& r = report.results();
    // Any NaN would have been refused; both invariants hold to roundoff
    // (a few ulps per sample for the closed form and for the projected rkf78).
    CHECK(value(r, "energy_drift_rel") < 12 * DBL_EPSILON);
    CHECK(value(r, "momentum_drift_rel") < 12 * DBL_EPSILON);
  }
}

TEST_CASE("poinsot: the integrator comparison is each method's own run") {
  // The comparison runs every method at the lab's settings: its number for a
  // method is the one that method gives as the lab's --method, bit for bit.
  const Report exact = compute(given("--method exact"));
  const auto& all = exact.results();
  for (const char* method : {"splitting", "rk4", "dopri5", "rkf78", "bulirsch-stoer"}) {
    INFO(method);
    std::string key = std::string("max_error_") + method;
    std::replace(key.begin(), key.end(), '-', '_');
    const Report own = compute(given(std::string("--method ") + method));
    CHECK(value(all, key.c_str()) == value(own.results(), "max_error_vs_exact"));
    CHECK(value(own.results(), key.c_str()) == value(own.results(), "max_error_vs_exact"));
  }
  CHECK(compute(Inputs{}).units()["polhode_period_s"] == "s");
}

TEST_CASE("poinsot: a method the comparison cannot afford is reported as not run") {
  // I nearly spherical: the polhode period is ~1e10 s and the adaptive methods
  // would need millions of steps; the lab still answers, quickly, with nulls.
  const Report report = compute(given("--inertia 1,1.000000001,1.000000002 --omega 1,1,1"));
  const auto& r = report.results();
  CHECK(r["max_error_dopri5"].is_null());
  CHECK(r["max_error_rk4"].is_number());
}

TEST_CASE("poinsot: the CSV's rows agree with the reported end state and drifts") {
  // The rows --csv writes are the report's time series.
  const Report report = compute(given("--method rk4"));
  const auto& r = report.results();
  const auto& rows = report.time_series().rows;
  REQUIRE(rows.size() > 10);
  const auto& last = rows.back();
  CHECK(last[0] == value(r, "t_end_s"));
  for (int i = 0; i < 3; ++i) CHECK(last[1 + i] == double(r["omega_end"][i]));
  double dE = 0, dL = 0;
  const double E0 = rows[0][8], L0 = rows[0][9];
  for (const auto& v : rows) {
    CHECK(std::hypot(std::hypot(v[4], v[5]), std::hypot(v[6], v[7])) == Approx(1).epsilon(1e-15));
    dE = std::max(dE, std::abs(v[8] - E0) / E0);
    dL = std::max(dL, std::abs(v[9] - L0) / L0);
  }
  // The same maxima the run reported (the CSV prints 17 digits: equal to roundoff).
  CHECK(dE == Approx(value(r, "energy_drift_rel")).epsilon(kRoundoff));
  CHECK(dL == Approx(value(r, "momentum_drift_rel")).epsilon(kRoundoff));
}

TEST_CASE("poinsot: another body's period against Landau's formula and std::comp_ellint_1") {
  const double I[3] = {2, 3, 5}, w[3] = {1.2, -0.4, 0.3};
  const Report report = compute(given("--inertia 2,3,5 --omega 1.2,-0.4,0.3"));
  const auto& r = report.results();
  double E2 = 0, L2 = 0;  // 2T and L^2
  for (int i = 0; i < 3; ++i) E2 += I[i] * w[i] * w[i], L2 += I[i] * I[i] * w[i] * w[i];
  CHECK(value(r, "energy") == Approx(E2 / 2).epsilon(kRoundoff));
  CHECK(value(r, "angular_momentum_magnitude") == Approx(std::sqrt(L2)).epsilon(kRoundoff));
  // Landau & Lifshitz, Mechanics, section 37: for L^2 < 2 E I2 (here 9.45 < 11.43) the
  // polhode circles the smallest axis: their formulas with I1 and I3 exchanged
  // (the racquet's test takes the other family).
  REQUIRE(L2 < E2 * I[1]);
  CHECK(r["regime"] == "polhode about the smallest axis");
  const double I1 = I[2], I2 = I[1], I3 = I[0];
  const double rate = std::sqrt((I3 - I2) * (L2 - E2 * I1) / (I1 * I2 * I3));
  const double k2 = (I2 - I1) * (E2 * I3 - L2) / ((I3 - I2) * (L2 - E2 * I1));
  // libstdc++'s K(k) (Carlson's R_F of its own), a second implementation beside Boost's.
  CHECK(value(r, "polhode_period_s") ==
        Approx(4 * std::comp_ellint_1(std::sqrt(k2)) / rate).epsilon(kRoundoff));
  for (int i = 0; i < 3; ++i) {
    CHECK(double(r["energy_ellipsoid_semi_axes"][i]) ==
          Approx(std::sqrt(E2 / I[i])).epsilon(1e-15));
    CHECK(double(r["momentum_ellipsoid_semi_axes"][i]) ==
          Approx(std::sqrt(L2) / I[i]).epsilon(1e-15));
  }
  // Three periods later (the default t_end) omega is back where it started.
  // The period carries a few ulps, and so omega at 3T a few ulps of |omega| ~ 1
  // (measured 4.4e-16); epsilon(0): Approx's default adds 1e-5 relative to any margin.
  for (int i = 0; i < 3; ++i)
    CHECK(double(r["omega_end"][i]) == Approx(w[i]).epsilon(0).margin(8 * DBL_EPSILON));
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
    const Report report = compute(given(c.args));
    CHECK(report.results()["motion_stability"] == c.stability);
    CHECK_THAT(report.results()["motion"].get<std::string>(), Catch::Contains(c.words));
  }
  // k'^2 against Landau's k^2 for the near-separatrix body (I = 3, 3.75, 5; omega0 = 5, 1, 3.0001):
  // k'^2 = 1 - k^2, k^2 = (I2 - I1)(2 E I3 - L^2) / ((I3 - I2)(L^2 - 2 E I1)).
  const double I[3] = {3, 3.75, 5}, w[3] = {5, 1, 3.0001};
  double E2 = 0, L2 = 0;
  for (int i = 0; i < 3; ++i) E2 += I[i] * w[i] * w[i], L2 += I[i] * I[i] * w[i] * w[i];
  const double kp2 = ((I[2] - I[1]) * (L2 - E2 * I[0]) - (I[1] - I[0]) * (E2 * I[2] - L2)) /
                     ((I[2] - I[1]) * (L2 - E2 * I[0]));
  const Report near = compute(given("--inertia 3,3.75,5 --omega 5,1,3.0001"));
  // k'^2 is a difference of nearly equal products: conditioned by ~1/k'^2 ~ 1e4
  CHECK(value(near.results(), "complementary_parameter") == Approx(kp2).epsilon(1e-10));
}

TEST_CASE("poinsot: a solid box (a phone) beside the ellipsoid, its moments by eq. 40") {
  // (--box with --ellipsoid, both given, is the command line's to refuse: in-process the
  // ellipsoid is a value, its default when not set)
  const double m = 0.2, A = 0.16, B = 0.08, C = 0.008;
  const Report report = compute(given("--box 0.16,0.08,0.008 --mass 0.2 --omega 0,5,0.01"));
  const auto& I = report.results()["principal_moments"];
  CHECK(double(I[0]) == Approx(m * (B * B + C * C) / 12).epsilon(kRoundoff));
  CHECK(double(I[1]) == Approx(m * (A * A + C * C) / 12).epsilon(kRoundoff));
  CHECK(double(I[2]) == Approx(m * (A * A + B * B) / 12).epsilon(kRoundoff));
  // spun about its middle axis, nudged: the tennis racquet theorem for a phone
  CHECK(report.results()["motion_stability"] == "unstable");
  CHECK(!report.inputs().contains("ellipsoid"));
  CHECK_THROWS_MATCHES(compute(given("--box 1,1,1 --inertia 1,2,3")), InputError,
                       names_input("--inertia"));
  CHECK_THROWS_MATCHES(compute(given("--box 1,0,1")), InputError, names_input("--box"));
}

TEST_CASE("poinsot: a broken rule is an InputError naming the input") {
  const std::pair<const char*, const char*> cases[] = {
      {"--inertia 1,1,3", "--inertia"},  // the triangle inequality
      {"--inertia -1,1,1", "--inertia"},
      {"--inertia 0,1,1", "--inertia"},
      {"--ellipsoid 0,1,1", "--ellipsoid"},
      {"--mass -1", "--mass"},
      {"--omega 0,0,0", "--omega"},
      {"--omega nan,1,1", "--omega"},
      {"--omega 1e200,1,1", "--omega"},
      {"--t-end -1", "--t-end"},
      {"--t-end 0", "--t-end"},
      {"--t-end 1e300", "--t-end"},
      {"--t-end 1e59", "--t-end"},  // beyond the phase's digits
      {"--periods 0", "--periods"},
      {"--periods 2 --t-end 3", "--periods"},
      {"--method euler", "--method"},
      {"--tolerance 0", "--tolerance"},
      {"--tolerance 1", "--tolerance"},
      // below double precision's reach no step meets a tolerance
      {"--method dopri5 --tolerance 1e-17", "--tolerance"},
      {"--tolerance 1e-300", "--tolerance"},
      {"--tolerance 1e-183", "--tolerance"},
      {"--step -1", "--step"},
      {"--step 0", "--step"},
      {"--method rk4 --step 1e-9 --t-end 100", "--step"},  // too many steps
      {"--method rk4 --step 10", "--step"},                // diverges
      {"--method dopri5 --project", "--project"},
      {"--project", "--project"},  // the closed form has nothing to project
      {"--box 1,1,1 --inertia 1,2,3", "--inertia"},
  };
  for (const auto& [args, input] : cases) {
    INFO(args);
    CHECK_THROWS_MATCHES(compute(given(args)), InputError, names_input(input));
  }
  // The rule's own words, as the command line prints them after the input.
  try {
    compute(given("--method rk4 --step 100 --t-end 1"));
    FAIL("a step longer than the run was taken");
  } catch (const InputError& e) {
    CHECK(e.input == "--step");
    CHECK(e.rule.rfind("100 s is longer than the run", 0) == 0);
  }
}

TEST_CASE("poinsot: a run too long for the budget is refused naming the tolerance") {
  // Bulirsch-Stoer over 1e7 s: the work budget of a lab's run refuses it; vern9 over
  // 1e9 s meets the same budget, four times as many of its cheaper evaluations.
  using rigid::Method;
  using rigid::lab::max_run_evaluations;
  for (const auto& [args, budget] :
       {std::pair{"--method bulirsch-stoer --t-end 1e7",
                  max_run_evaluations(Method::kBulirschStoer)},
        std::pair{"--method vern9 --t-end 1e9", max_run_evaluations(Method::kVern9)}}) {
    INFO(args);
    try {
      compute(given(args));
      FAIL("the run was not refused");
    } catch (const InputError& e) {
      CHECK(e.input == "--tolerance");
      CHECK(e.rule.find("needs more than " + rigid::format_number(static_cast<double>(budget)) +
                        " right-hand-side evaluations") != std::string::npos);
    }
  }
}

TEST_CASE("poinsot: extreme but legal inputs end with finite numbers or an InputError") {
  // odeint's dense-output steppers failed for runs shorter than 1e-14 s (now run in
  // scaled time)
  for (const char* args :
       {"--t-end 1e-60", "--t-end 1e-20 --method dopri5", "--t-end 1e-20 --method bulirsch-stoer",
        "--inertia 1,2,3 --omega 1e20,1e20,1e20"}) {
    INFO(args);
    try {
      const Report report = compute(given(args));
      CHECK(report.results().is_object());
      std::function<bool(const rigid::lab::Json&)> finite = [&](const rigid::lab::Json& v) {
        if (v.is_number()) return std::isfinite(v.get<double>());
        if (v.is_structured()) return std::all_of(v.begin(), v.end(), finite);
        return true;
      };
      for (const auto& [key, v] : report.results().items()) {
        INFO(key);
        CHECK(finite(v));
      }
    } catch (const InputError& e) {
      // an input named, or none (the command line then names the first given)
      CHECK((e.input.empty() || e.input.rfind("--", 0) == 0));
    }
  }
}

TEST_CASE("poinsot: which method to use - every method ranked by its error at equal cost") {
  const Report report = compute(given("--method rk4 --periods 5"));
  const auto& r = report.results();
  // --periods N ends at N of the motion's periods
  CHECK(value(r, "t_end_s") == Approx(5 * value(r, "polhode_period_s")).epsilon(kRoundoff));
  CHECK(r["method_kind"] == "fixed-step Runge-Kutta, order 4");
  // Each invariant's largest error and its trend; the old key is the largest error.
  CHECK(r["energy_drift_rel"] == r["energy_error_max_rel"]);
  CHECK(std::abs(value(r, "energy_drift_per_period_rel")) <= value(r, "energy_error_max_rel"));
  // Every method at the lab's settings with what it cost.
  for (const rigid::Method m : rigid::kAllMethods) {
    const std::string key = rigid::lab::json_key(std::string(rigid::method_name(m)));
    INFO(key);
    CHECK(value(r, ("evaluations_" + key).c_str()) >= value(r, ("steps_" + key).c_str()));
  }
  // At equal cost over the run's 5 periods (its whole length calibrates the cost):
  // every method, and each that projects once more with --project.
  CHECK(value(r, "equal_cost_periods") == Approx(5).epsilon(kRoundoff));
  check_ranking(r, "max_error_", "", 0.05);
  CHECK(ranked_methods(r).size() == rigid::kAllMethods.size() + 6);
  // projected onto T and |L| after every step: the energy to roundoff
  CHECK(value(r, "equal_cost_energy_error_max_rel_vern8_project") < 1e-13);
}

TEST_CASE("poinsot: the method advised in --help and the user guide is the ranking's own") {
  const auto* method = rigid::lab::poinsot::input_table().find("--method");
  REQUIRE(method != nullptr);
  CHECK_THAT(method->rule.description(), Catch::Contains("symplectic splitting, order 2"));
  CHECK_THAT(method->rule.description(), Catch::Contains(rigid::lab::kMethodAdvice));
  CHECK_THAT(user_guide(), Catch::Contains(rigid::lab::kMethodAdvice));
  // The text's ellipsoid, the book spun about its middle axis (near the separatrix:
  // k'^2 = 1.4e-4) and a body nearer still, over 10 and 1000 periods.
  for (const char* body : {"", "--box 0.24,0.16,0.04 --mass 0.8 --omega 0.06,6,0.06",
                           "--inertia 1,2,3 --omega 0.001,1,0.001"}) {
    for (const char* periods : {" --periods 10", " --periods 1000"}) {
      const Report report = compute(given(std::string(body) + periods));
      const auto& r = report.results();
      INFO(body << periods << ": " << r["recommended_method"] << ", "
                << r["recommended_method_reason"]);
      // a longer run calibrates on its first 10 periods; Bulirsch-Stoer's cost a
      // period then varies by up to 8 % (measured), the others' by less
      check_ranking(r, "max_error_", "", 0.1);
      CHECK_THAT(rigid::lab::kMethodAdvice, Catch::Contains(named_method(r)));
    }
  }
  // The table says which to use, and why.
  const Report defaults = compute(Inputs{});
  bool said = false;
  for (const auto& row : defaults.rows()) said = said || row.label == "use";
  CHECK(said);
}

TEST_CASE("poinsot: an option the method does not use is said so, the shortened last step") {
  // a fixed step that does not divide t_end: the shortened last step is reported
  const Report fixed = compute(given("--method rk4 --step 0.3 --t-end 10"));
  CHECK(value(fixed.results(), "last_step_s") == Approx(10 - 33 * 0.3).epsilon(kRoundoff));
  CHECK(fixed.warnings().empty());
  // rk4 takes no tolerance: a warning, and a note starting "warning:"
  const Report unused = compute(given("--method rk4 --tolerance 1e-6"));
  REQUIRE(unused.warnings().size() == 1);
  CHECK(unused.warnings()[0].rfind("--tolerance: rk4 takes a fixed step", 0) == 0);
  bool noted = false;
  for (const auto& note : unused.notes()) noted |= note.rfind("warning:", 0) == 0;
  CHECK(noted);
}

TEST_CASE("poinsot: the textbook's values stand while only numerical inputs change") {
  // A numerical option (how, not what) keeps the textbook's values.
  const Report numerical = compute(given("--method rk4"));
  CHECK(numerical.textbook_printed().contains("principal_moments"));
  // Any physical one takes them away.
  CHECK(!compute(given("--mass 2")).textbook_printed().contains("principal_moments"));
  // a list of numbers, and an expression (no number of its own)
  const auto values = compute(Inputs{}).textbook_values();
  CHECK(values["ratios_energy"]["value"] == rigid::lab::Json({0.44, 0.50, 0.58}));
  CHECK(values["principal_moments"]["value"].is_null());
  // Counts are integers.
  CHECK(numerical.results()["steps"].is_number_integer());
}
