// euler_angles' library in-process at and near the poles: omega, L, T and psi's terms
// against 40-digit references (make_edge_cases.py), --from-omega at a pole, the errata
// and section 7.2's remarks on each side of their thresholds, and the figures' numbers.
#include <fmt/format.h>

#include <catch2/catch.hpp>
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "euler_angles/euler_angles.h"
#include "lab_library.h"

using rigid::lab::euler_angles::compute;
using rigid::lab::euler_angles::Inputs;
using rigid::test::contains;
using rigid::test::element;
using rigid::test::kRoundoff;
using rigid::test::notes_starting;
using rigid::test::value;

namespace {

// An edge case at 40 digits (tests/labs/references/euler_angles/make_edge_cases.py).
struct EdgeCase {
  const char* name;
  double angles_deg[3];
  bool omega_given;
  double velocity[3], moments[3];
  double omega_body[3], omega_space[3], omega_intermediate[3], printed[2], L_space[3];
  double T, p_psi, force_psi;
  bool pole;
  double rates[3], theta_dot;
};
const EdgeCase kEdgeCases[] = {
#include "references/euler_angles/reference_edge_cases.inc"
};

Inputs inputs_of(const EdgeCase& c) {
  Inputs in;
  in.phi_deg = c.angles_deg[0], in.theta_deg = c.angles_deg[1], in.psi_deg = c.angles_deg[2];
  const Eigen::Vector3d v(c.velocity[0], c.velocity[1], c.velocity[2]);
  if (c.omega_given) {
    in.from_omega = v;
  } else {
    in.phi_dot = v(0), in.theta_dot = v(1), in.psi_dot = v(2);
  }
  in.moments = Eigen::Vector3d(c.moments[0], c.moments[1], c.moments[2]);
  return in;
}

// The number printed right after `marker` in `text` (throws if there is none).
double number_after(const std::string& text, const std::string& marker) {
  const std::size_t at = text.find(marker);
  if (at == std::string::npos) throw std::runtime_error("no '" + marker + "' in: " + text);
  const char* start = text.c_str() + at + marker.size();
  char* end = nullptr;
  const double x = std::strtod(start, &end);
  if (end == start) throw std::runtime_error("no number after '" + marker + "' in: " + text);
  return x;
}

// The table's row whose label starts with `label` (a result that is none says why in its
// textbook column).
const rigid::lab::TableRow& row(const rigid::lab::Report& report, const std::string& label) {
  for (const auto& r : report.rows()) {
    if (r.label.rfind(label, 0) == 0) return r;
  }
  throw std::runtime_error("no row " + label);
}

const rigid::lab::Erratum& erratum(const rigid::lab::Report& report, const std::string& where) {
  for (const auto& e : report.errata()) {
    if (e.where == where) return e;
  }
  throw std::runtime_error("no erratum at " + where);
}

// Six significant digits, as the notes print them.
bool six_digits(double printed, double exact) {
  return std::abs(printed - exact) <= 5e-6 * std::abs(exact) + 1e-300;
}

}  // namespace

TEST_CASE("euler_angles: omega, L, T and psi's terms at and near the poles, to 40 digits") {
  // Roundoff's share: omega from the angles' sines and cosines (a few eps of the sizes
  // that meet: |omega|, and the rates where they were given), T and L from omega.
  for (const EdgeCase& c : kEdgeCases) {
    INFO(c.name);
    const auto report = compute(inputs_of(c));
    const auto& r = report.results();
    const Eigen::Vector3d v(c.velocity[0], c.velocity[1], c.velocity[2]);
    const double size = Eigen::Vector3d(c.omega_body[0], c.omega_body[1], c.omega_body[2]).norm() +
                        (c.omega_given ? 0.0 : v.lpNorm<1>());
    const double tol = 16 * DBL_EPSILON * size;
    for (int i = 0; i < 3; ++i) {
      INFO("component " << i);
      CHECK(std::abs(element(r, "omega_body_rad_s", i) - c.omega_body[i]) <= tol);
      CHECK(std::abs(element(r, "omega_space_rad_s", i) - c.omega_space[i]) <= tol);
      CHECK(std::abs(element(r, "omega_intermediate_rad_s", i) - c.omega_intermediate[i]) <= tol);
      CHECK(std::abs(element(r, "angular_momentum_space", i) - c.L_space[i]) <= 3 * tol * size);
    }
    for (int i = 0; i < 2; ++i) {
      CHECK(std::abs(element(r, "omega_space_printed_rad_s", i) - c.printed[i]) <= tol);
    }
    CHECK(std::abs(value(r, "kinetic_energy_j") - c.T) <= 3 * tol * size);
    // psi's two terms, defined at the poles too: within their stated rounding and omega's
    CHECK(std::abs(value(r, "lagrange_psi_momentum") - c.p_psi) <=
          value(r, "lagrange_psi_momentum_error") + c.moments[2] * tol);
    CHECK(std::abs(value(r, "lagrange_psi_force") - c.force_psi) <=
          value(r, "lagrange_psi_force_error") + 2 * (c.moments[0] + c.moments[1]) * tol * size);
    if (c.omega_given) {
      if (c.pole) {
        CHECK(r.at("rates_rad_s").is_null());
        CHECK(value(r, "rates_sum_rad_s") == (c.angles_deg[1] == 0 ? v(2) : -v(2)));
        CHECK(std::abs(value(r, "theta_dot_rad_s") - c.theta_dot) <= tol);
      } else {
        for (int i = 0; i < 3; ++i) {
          // phi_dot and psi_dot as 1/sin(theta), each to a few eps of its size
          CHECK(std::abs(element(r, "rates_rad_s", i) - c.rates[i]) <=
                16 * DBL_EPSILON * (std::abs(c.rates[i]) + size));
        }
      }
    }
  }
  // the 1e-9 deg example: dT/dpsi_dot = 9 and dT/dpsi = 0.0803484512175
  Inputs near;
  near.theta_deg = 1e-9;
  near.moments = Eigen::Vector3d(1, 2, 3);
  const auto r = compute(near).results();
  CHECK(std::abs(value(r, "lagrange_psi_momentum") - 9) < 1e-9);
  CHECK(std::abs(value(r, "lagrange_psi_force") - 0.0803484512175) < 1e-12);
  // and 1e-6 deg from omega (1, 2, 3): dT/dpsi = (1 - 2) 1 2 = -2 exactly, with its bound
  Inputs given;
  given.theta_deg = 1e-6;
  given.from_omega = Eigen::Vector3d(1, 2, 3);
  given.moments = Eigen::Vector3d(1, 2, 3);
  const auto g = compute(given).results();
  CHECK(value(g, "lagrange_psi_force") == -2.0);
  CHECK(value(g, "lagrange_psi_force_error") < 4 * DBL_EPSILON * 2);
}

TEST_CASE("euler_angles: at a pole --from-omega gives all but the split of phi_dot and psi_dot") {
  for (const double pole : {0.0, 180.0}) {
    INFO("theta " << pole << " deg");
    Inputs in;
    in.theta_deg = pole;
    in.from_omega = Eigen::Vector3d(1, 2, 3);
    in.moments = Eigen::Vector3d(1, 2, 3);
    const auto report = compute(in);
    const auto& r = report.results();
    CHECK_FALSE(report.rates_defined);
    CHECK(r.at("rates_rad_s").is_null());
    // everything else is there: omega in three frames, L, T, psi's terms, section 7.2
    for (const char* key :
         {"omega_body_rad_s", "omega_space_rad_s", "omega_intermediate_rad_s",
          "omega_space_printed_rad_s", "angular_momentum_body", "angular_momentum_space",
          "kinetic_energy_j", "lagrange_psi_momentum", "lagrange_psi_force", "euler_psi_rate",
          "generalized_force", "torque_lagrange_residual_theta", "euler_torque_residual_3"}) {
      INFO(key);
      CHECK_FALSE(r.at(key).is_null());
    }
    // the angles' own equations at t = 0 need the split: none, saying why
    CHECK(r.at("lagrange_residual_theta").is_null());
    CHECK(contains(row(report, "d/dt dT/dtheta_dot - dT/dtheta at t = 0").textbook,
                   pole == 0 ? "only phi_dot + psi_dot is" : "only phi_dot - psi_dot is"));
    // every erratum of the run away from the pole
    for (const char* where :
         {"eqs. 137-138", "eqs. 154-156", "eq. 150", "section 7.2, after eq. 165"}) {
      INFO(where);
      CHECK_NOTHROW(erratum(report, where));
    }
    // the answer: the sum (or difference) and theta_dot, omega in space
    const std::string answer = r.at("answer");
    const std::string sum = pole == 0 ? "phi_dot + psi_dot = " : "phi_dot - psi_dot = ";
    CHECK(number_after(answer, sum) == (pole == 0 ? 3 : -3));
    // four significant digits
    CHECK(std::abs(number_after(answer, "theta_dot = ") - value(r, "theta_dot_rad_s")) <= 5e-4 * 2);
    CHECK(std::abs(number_after(answer, "omega is (") - element(r, "omega_space_rad_s", 0)) <=
          5e-4 * 3);
  }
}

TEST_CASE("euler_angles: the errata say their numbers the right way round") {
  for (const bool moments : {false, true}) {
    INFO((moments ? "--moments 2,3,4" : "the defaults"));
    Inputs in;
    if (moments) in.moments = Eigen::Vector3d(2, 3, 4);
    const auto report = compute(in);
    const auto& r = report.results();
    // eq. 150: the print's sum I_i omega_i^2 is 2T, the kinetic energy T; for the body of
    // section 7 (the lab's I = 1, 2, 3 without --moments)
    const Eigen::Vector3d I = moments ? *in.moments : Eigen::Vector3d(1, 2, 3);
    double T = 0;
    for (int i = 0; i < 3; ++i) {
      T += 0.5 * I(i) * std::pow(element(r, "omega_body_rad_s", i), 2);
    }
    const auto& eq150 = erratum(report, "eq. 150");
    CHECK(eq150.printed == "T = sum_{i=1}^{3} I_i omega_i^2");
    CHECK(six_digits(number_after(eq150.correction, "the print gives "), 2 * T));
    CHECK(six_digits(number_after(eq150.correction, "twice the kinetic energy T = "), T));
    if (moments) CHECK(value(r, "kinetic_energy_j") == Approx(T).epsilon(kRoundoff));
    // eqs. 137-138: the corrected x and y, then the print's x and y
    const auto& eqs137 = erratum(report, "eqs. 137-138");
    CHECK(six_digits(number_after(eqs137.correction, "psi_dot sin theta sin phi = "),
                     element(r, "omega_space_rad_s", 0)));
    CHECK(six_digits(number_after(eqs137.correction, "psi_dot sin theta cos phi = "),
                     element(r, "omega_space_rad_s", 1)));
    CHECK(six_digits(number_after(eqs137.correction, "where the print gives "),
                     element(r, "omega_space_printed_rad_s", 0)));
    CHECK(six_digits(
        number_after(eqs137.correction,
                     "where the print gives " +
                         fmt::format("{:.6g}", element(r, "omega_space_printed_rad_s", 0)) +
                         " and "),
        element(r, "omega_space_printed_rad_s", 1)));
    // each erratum is also its note, quoting the print
    for (const auto& e : report.errata()) {
      INFO(e.where);
      CHECK(notes_starting(report, "errata: " + e.where + ": the text prints \"" + e.printed +
                                       "\"; " + e.correction)
                .size() == 1);
    }
  }
}

TEST_CASE("euler_angles: section 7.2's 'perturbation symbol' is the permutation symbol") {
  // the text defines epsilon_ijk as the permutation symbol at eqs. 159-162 and, after eq.
  // 165, calls it the perturbation symbol
  const auto report = compute(Inputs{});
  const auto& e = erratum(report, "section 7.2, after eq. 165");
  CHECK(e.printed == "the sign of the last terms depends on the perturbation symbol");
  CHECK(contains(e.correction, "the permutation symbol epsilon_ijk of eqs. 159-162"));
}

TEST_CASE("euler_angles: section 7.2's remark judges N_3, on both sides of its threshold") {
  // without Q_psi, psi's equation misses by exactly N_3: the remark says so where N_3 is
  // above 10 times the exact terms' rounding, and that it cannot tell below; N_1 and N_2
  // large either way do not change it
  const char label[] = "  d/dt dT/dpsi_dot - dT/dpsi without Q_psi";
  for (const auto& [torque, misses] :
       {std::pair{Eigen::Vector3d(0, 0, 1), true}, std::pair{Eigen::Vector3d(5, -5, 1e-9), true},
        std::pair{Eigen::Vector3d(1, 0, 0), false}, std::pair{Eigen::Vector3d(5, 5, 1e-20), false},
        std::pair{Eigen::Vector3d(0, 3, -2), true}}) {
    INFO("N = " << torque.transpose());
    Inputs in;
    in.torque = torque;
    const auto report = compute(in);
    const auto& r = report.results();
    const double error = value(r, "torque_free_residual_psi_error");
    CHECK(std::abs(value(r, "torque_free_residual_psi") - torque(2)) <= error);
    const std::string remark = row(report, label).remark;
    CHECK(contains(remark, "misses by N_3") == misses);
    CHECK(contains(remark, "this cannot tell") == !misses);
    CHECK((std::abs(torque(2)) > 10 * error) == misses);
    CHECK(number_after(remark, "N_3 = ") == Approx(torque(2)).epsilon(1e-5));
  }
}

TEST_CASE("euler_angles: residuals resolved or not on each side of 1e-3 of T") {
  // from omega (1, 2, 3) near the pole theta's terms grow as 1 / sin(theta): its bound
  // passes 1e-3 of T = 18 J between 1e-10 and 1e-11 deg; phi's and psi's stay at eps
  for (const auto& [theta_deg, resolved] : {std::pair{1e-10, true}, std::pair{1e-11, false}}) {
    INFO("theta " << theta_deg << " deg");
    Inputs in;
    in.theta_deg = theta_deg;
    in.from_omega = Eigen::Vector3d(1, 2, 3);
    in.moments = Eigen::Vector3d(1, 2, 3);
    const auto report = compute(in);
    const auto& r = report.results();
    CHECK(r.at("lagrange_residual_theta").is_null() == !resolved);
    if (resolved) {
      CHECK(std::abs(value(r, "lagrange_residual_theta")) <=
            value(r, "lagrange_residual_theta_error"));
      CHECK(value(r, "lagrange_residual_theta_error") <= 1e-3 * 18);
    } else {
      const std::string why = row(report, "d/dt dT/dtheta_dot - dT/dtheta at t = 0").textbook;
      CHECK(contains(why, "exceeds 1e-3 of T, 18 J"));
    }
    for (const char* key : {"lagrange_residual_phi", "lagrange_residual_psi"}) {
      CHECK(std::abs(value(r, key)) <= value(r, (std::string(key) + "_error").c_str()));
      CHECK(value(r, (std::string(key) + "_error").c_str()) < 1e-13);
    }
  }
  // the differences along the motion beside them: fine at the defaults, too coarse for
  // theta at 2 deg with fast rates, where the exact terms still hold to eps
  Inputs two;
  two.theta_deg = 2, two.phi_dot = 8, two.theta_dot = -2, two.psi_dot = -8;
  for (const auto& [in, coarse] : {std::pair{Inputs{}, false}, std::pair{two, true}}) {
    const auto report = compute(in);
    const auto& r = report.results();
    const double T = 0.5 * (std::pow(element(r, "omega_body_rad_s", 0), 2) +
                            2 * std::pow(element(r, "omega_body_rad_s", 1), 2) +
                            3 * std::pow(element(r, "omega_body_rad_s", 2), 2));
    INFO("theta " << in.theta_deg << " deg, T " << T);
    CHECK((value(r, "lagrange_residual_theta_differences_error") > 1e-3 * T) == coarse);
    CHECK(contains(row(report, "d/dt dT/dtheta_dot - dT/dtheta at t = 0").remark,
                   "too coarse to tell") == coarse);
    CHECK(std::abs(value(r, "lagrange_residual_theta_differences")) <=
          value(r, "lagrange_residual_theta_differences_error"));
    CHECK(value(r, "lagrange_residual_theta_error") < 1e-12 * T);
  }
}

TEST_CASE("euler_angles: the long input's residuals hold to eps, theta's as tight as the others") {
  // T = 80.8 J; differences gave theta's residual +- 2.2e-4 J against 1e-8 for phi and psi;
  // the exact terms' bound is a few eps of |L| (|omega| + the rates), about 450 N m
  Inputs in;
  in.phi_deg = 541.66826396323, in.theta_deg = 135.40272805339464, in.psi_deg = -463.05982509111584;
  in.phi_dot = -5.833921488427767, in.theta_dot = 0.7919308047775093;
  in.psi_dot = -9.338185730543904;
  in.moments = Eigen::Vector3d(3.383260344757347, 3.684594607682449, 3.7921672281973664);
  const auto r = compute(in).results();
  const double T = value(r, "kinetic_energy_j");
  CHECK(T == Approx(80.8).epsilon(1e-3));
  for (const char* angle : {"phi", "theta", "psi"}) {
    INFO(angle);
    const std::string key = std::string("lagrange_residual_") + angle;
    CHECK(std::abs(value(r, key.c_str())) <= value(r, (key + "_error").c_str()));
    CHECK(value(r, (key + "_error").c_str()) < 1e-13 * T);
  }
}

TEST_CASE("euler_angles: torques, generalized forces and residuals are in N m, T in J") {
  const auto report = compute(Inputs{});
  const auto& units = report.units();
  for (const auto& [key, unit] : units.items()) {
    const bool torque_like =
        contains(key, "residual") || contains(key, "force") || contains(key, "euler_psi_rate");
    if (torque_like) {
      INFO(key);
      CHECK(unit == "N m");
    }
  }
  CHECK(units.at("generalized_force") == "N m");
  CHECK(units.at("lagrange_psi_force") == "N m");
  CHECK(units.at("lagrange_psi_momentum") == "kg m^2/s");
  Inputs with;
  with.moments = Eigen::Vector3d(1, 2, 3);
  CHECK(compute(with).units().at("kinetic_energy_j") == "J");
}

TEST_CASE("euler_angles: the answer to --from-omega gives the rates it was asked for") {
  Inputs in;
  in.from_omega = Eigen::Vector3d(0.3, -1.2, 2.0);
  const auto r = compute(in).results();
  const std::string answer = r.at("answer");
  const std::string marker = "phi_dot, theta_dot, psi_dot = (";
  // four significant digits each, in order
  CHECK(std::abs(number_after(answer, marker) - element(r, "rates_rad_s", 0)) <=
        5e-4 * std::abs(element(r, "rates_rad_s", 0)));
  const std::size_t at = answer.find(marker) + marker.size();
  const std::string rest = answer.substr(answer.find(", ", at) + 2);
  CHECK(std::abs(std::stod(rest) - element(r, "rates_rad_s", 1)) <=
        5e-4 * std::abs(element(r, "rates_rad_s", 1)));
  CHECK(std::abs(std::stod(rest.substr(rest.find(", ") + 2)) - element(r, "rates_rad_s", 2)) <=
        5e-4 * std::abs(element(r, "rates_rad_s", 2)));
}

namespace {

double angle_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

// The direction of the arrow labelled `label` (its shaft, a cylinder from the tail).
Eigen::Vector3d arrow_direction(const rigid::render::Scene3D& scene, const std::string& label) {
  for (const auto& object : scene.objects()) {
    if (object.label.rfind(label, 0) == 0) return object.transform.linear().col(2).normalized();
  }
  throw std::runtime_error("no arrow " + label);
}

}  // namespace

TEST_CASE("euler_angles: the figures' numbers - the arcs' angles, gimbal lock's rates") {
  using rigid::lab::euler_angles::figures;
  const auto report = compute(Inputs{});
  rigid::test::KeptFigures kept;
  figures(report, kept);
  REQUIRE(kept.scenes.count("rotations") == 1);
  REQUIRE(kept.scenes.count("gimbal_lock") == 1);
  // the rotations: arcs of phi, theta, psi = 30, 50, 70 deg, in that order
  const auto& rotations = kept.scenes.at("rotations");
  REQUIRE(rotations.polylines().size() == 3);
  const double angles[3] = {30, 50, 70};
  for (int k = 0; k < 3; ++k) {
    const auto& points = rotations.polylines()[k].points;
    CHECK(angle_between(points.front(), points.back()) * 180 / M_PI ==
          Approx(angles[k]).epsilon(1e-12));
  }
  // omega at the chain's end: along omega in space
  const Eigen::Vector3d w(element(report.results(), "omega_space_rad_s", 0),
                          element(report.results(), "omega_space_rad_s", 1),
                          element(report.results(), "omega_space_rad_s", 2));
  CHECK(angle_between(arrow_direction(rotations, "\\omega = "), w) < 1e-12);
  // gimbal lock at theta = 8 deg: 1 rad/s about n = z x x' takes phi_dot = cot(theta) and
  // psi_dot = -1 / sin(theta), printed to 3 digits, and theta's arc is 8 deg
  const auto& gimbal = kept.scenes.at("gimbal_lock");
  CHECK(contains(gimbal.title, "\\theta = 8\u00b0"));
  const double theta = 8 * M_PI / 180;
  std::string legend;
  for (const auto& object : gimbal.objects()) {
    if (object.label.rfind("1 rad/s about n", 0) == 0) legend = object.label;
  }
  CHECK(number_after(legend, "\\phi-dot = ") == Approx(1 / std::tan(theta)).epsilon(1e-3));
  CHECK(number_after(legend, "\\psi-dot = ") == Approx(-1 / std::sin(theta)).epsilon(1e-3));
  REQUIRE(gimbal.polylines().size() == 1);
  CHECK(angle_between(gimbal.polylines()[0].points.front(), gimbal.polylines()[0].points.back()) ==
        Approx(theta).epsilon(1e-12));
  // the animation's titles: each turn's angle so far (eased: halfway at the half second)
  const auto animation = rigid::lab::euler_angles::animation(report, [](double seconds) {
    return std::vector<double>{0.0, seconds};
  });
  CHECK(contains(animation.scene(0.5).title, "\\phi = 15\u00b0, \\theta = 0\u00b0"));
  CHECK(contains(animation.scene(1.5).title,
                 "\\phi = 30\u00b0, \\theta = 25\u00b0, \\psi = 0\u00b0"));
  CHECK(contains(animation.scene(2.5).title, "\\theta = 50\u00b0, \\psi = 35\u00b0"));
}

TEST_CASE("euler_angles: at a pole the figure shows omega alone, its split undefined") {
  Inputs in;
  in.theta_deg = 0;
  in.from_omega = Eigen::Vector3d(1, 2, 3);
  const auto report = compute(in);
  rigid::test::KeptFigures kept;
  rigid::lab::euler_angles::figures(report, kept);
  const auto& rotations = kept.scenes.at("rotations");
  const Eigen::Vector3d w(element(report.results(), "omega_space_rad_s", 0),
                          element(report.results(), "omega_space_rad_s", 1),
                          element(report.results(), "omega_space_rad_s", 2));
  CHECK(angle_between(arrow_direction(rotations, "\\omega (at the pole"), w) < 1e-12);
  CHECK(contains(rotations.title, "whose parts a pole leaves undefined"));
  for (const auto& object : rotations.objects()) CHECK_FALSE(contains(object.label, "\\phi-dot z"));
}
