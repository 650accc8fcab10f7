// A problem with no closed form, integrated and its methods ranked through the one
// integration layer (compare.h): a free body slowed by a viscous torque N = -c omega (a
// body turning in a viscous fluid, a gyroscope with friction in its bearings). Euler's
// equations (eq. 73) with that torque, I1 w1_dot = (I2 - I3) w2 w3 - c w1 and
// cyclically, and the quaternion kinematics. The energy is not kept but balanced: W_dot
// = c |omega|^2, the work the torque has taken, rides in the state, and T + W is the
// invariant an integrator's error shows in.
//
// An asymmetric body has no closed form; a symmetric one (I1 = I2 = I) has: omega_3 =
// omega_30 e^(-c t / I3) and omega_1 + i omega_2 = (omega_10 + i omega_20) e^(-c t / I)
// e^(i lambda omega_30 I3 (1 - e^(-c t / I3)) / c) with lambda = (I3 - I) / I, against
// which the reference run is checked.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <vector>

#include "rigid/compare_impl.h"
#include "rigid/free_body.h"
#include "rigid/free_body_exact.h"
#include "rigid/free_body_integrate.h"

using Catch::Matchers::Contains;
using rigid::Method;
using rigid::MethodComparison;
using rigid::OdeOptions;

namespace {

// omega_body, the attitude quaternion (w, x, y, z) and W.
using DampedState = std::array<double, 8>;

Eigen::Vector3d omega_of(const DampedState& x) {
  return {x[0], x[1], x[2]};
}

class DampedBody {
 public:
  using State = DampedState;
  /// (T + W - T0) / T0, and |q| - 1 before the sample normalises q.
  enum Invariant : std::size_t { kEnergyBalance, kQuaternionNorm };
  static constexpr std::size_t kInvariantCount = 2;
  using Sample = rigid::RunSample<State, kInvariantCount>;

  DampedBody(const rigid::PrincipalMoments& I, double c) : I_(I), c_(c) {}

  void validate(const State& x0) const {
    rigid::validate(I_);
    if (!(c_ >= 0.0)) throw std::invalid_argument("the damping must be at least 0");
    for (const double v : x0) {
      if (!std::isfinite(v)) throw std::invalid_argument("the start must be finite");
    }
  }

  struct Rhs {
    rigid::PrincipalMoments I;
    double c;
    void operator()(const State& x, State& dxdt, double /*t*/) const {
      const double w1 = x[0], w2 = x[1], w3 = x[2];
      const double qw = x[3], qx = x[4], qy = x[5], qz = x[6];
      dxdt[0] = ((I.I2 - I.I3) * w2 * w3 - c * w1) / I.I1;
      dxdt[1] = ((I.I3 - I.I1) * w3 * w1 - c * w2) / I.I2;
      dxdt[2] = ((I.I1 - I.I2) * w1 * w2 - c * w3) / I.I3;
      // q_dot = 1/2 q (x) (0, omega_body)
      dxdt[3] = 0.5 * (-qx * w1 - qy * w2 - qz * w3);
      dxdt[4] = 0.5 * (qw * w1 + qy * w3 - qz * w2);
      dxdt[5] = 0.5 * (qw * w2 + qz * w1 - qx * w3);
      dxdt[6] = 0.5 * (qw * w3 + qx * w2 - qy * w1);
      dxdt[7] = c * (w1 * w1 + w2 * w2 + w3 * w3);
    }
  };
  Rhs rhs() const { return {I_, c_}; }

  class Invariants {
   public:
    Invariants(const rigid::PrincipalMoments& I, const State& x0)
        : I_(I), E0_(rigid::kinetic_energy(I, omega_of(x0)) + x0[7]) {}
    std::array<double, kInvariantCount> operator()(const State& x) const {
      const double E = rigid::kinetic_energy(I_, omega_of(x)) + x[7];
      return {(E - E0_) / E0_,
              std::sqrt(x[3] * x[3] + x[4] * x[4] + x[5] * x[5] + x[6] * x[6]) - 1};
    }

   private:
    rigid::PrincipalMoments I_;
    double E0_;
  };
  Invariants invariants(const State& x0) const { return {I_, x0}; }

  State sampled(const State& x) const {
    State s = x;
    const double n = std::sqrt(x[3] * x[3] + x[4] * x[4] + x[5] * x[5] + x[6] * x[6]);
    for (int i = 3; i < 7; ++i) s[i] /= n;
    return s;
  }

  /// Each sample's |omega - omega_ref| / |omega_ref(0)| and |T / T_ref - 1|.
  rigid::ExactErrors errors_against(const std::vector<Sample>& reference,
                                    const std::vector<Sample>& samples) const {
    const double scale = omega_of(reference.front().x).norm();
    rigid::ExactErrors errors;
    for (std::size_t k = 0; k < samples.size(); ++k) {
      const Eigen::Vector3d w = omega_of(samples[k].x), w_ref = omega_of(reference[k].x);
      errors.error.push_back((w - w_ref).norm() / scale);
      errors.energy_error.push_back(
          std::abs(rigid::kinetic_energy(I_, w) / rigid::kinetic_energy(I_, w_ref) - 1.0));
    }
    return errors;
  }

 private:
  rigid::PrincipalMoments I_;
  double c_;
};

DampedState start(const Eigen::Vector3d& omega0) {
  return {omega0.x(), omega0.y(), omega0.z(), 1.0, 0.0, 0.0, 0.0, 0.0};
}

// The comparison of `method`, which must be there.
const MethodComparison& of(const std::vector<MethodComparison>& comparisons, Method method) {
  for (const MethodComparison& c : comparisons) {
    if (c.options.method == method && !c.options.project_invariants) return c;
  }
  throw std::logic_error("no comparison of " + std::string(rigid::method_name(method)));
}

}  // namespace

// Compiled here, once, as a problem of core's is in its own .cpp.
template struct rigid::detail::ProblemCode<DampedBody>;

TEST_CASE("damped body: with no closed form it integrates, an exact comparison is refused") {
  const DampedBody body({1.0, 2.0, 3.0}, 0.1);
  const DampedState x0 = start({0.3, 1.0, 0.4});
  const std::vector<double> times = rigid::uniform_times(0.0, 20.0, 41);
  const auto run = rigid::integrate(body, x0, times, rigid::reference_options());
  REQUIRE(run.samples.size() == times.size());
  // T + W kept to the tolerance's order over 20 s (T falls to a few per cent of T0)
  CHECK(run.max_invariant_error[DampedBody::kEnergyBalance] < 1e-11);
  CHECK(rigid::kinetic_energy({1.0, 2.0, 3.0}, omega_of(run.samples.back().x)) <
        0.5 * rigid::kinetic_energy({1.0, 2.0, 3.0}, omega_of(x0)));
  // only the comparisons with the exact motion are refused, naming the rule
  const rigid::NoExact none;
  const OdeOptions settings;
  CHECK_THROWS_WITH(rigid::sample_exact(body, none, times), Contains("no exact solution"));
  CHECK_THROWS_WITH(rigid::compare_methods(body, none, times, 5.0, settings, 1000),
                    Contains("no exact solution"));
  CHECK_THROWS_AS(rigid::compare_methods_at_cost(body, none, 5.0, 2.0, 1000.0),
                  std::invalid_argument);
  // it has no splitting of its own: not a method it runs, nor one it is compared by
  OdeOptions split;
  split.method = Method::kSplitting;
  CHECK_THROWS_WITH(rigid::integrate(body, x0, times, split), Contains("no splitting"));
  const auto compared =
      rigid::compare_methods(body, rigid::Reference<DampedState>{x0}, times, 5.0, settings, 1000);
  CHECK(compared.size() == rigid::kAllMethods.size() - 2);
  for (const MethodComparison& c : compared) {
    CHECK(c.options.method != Method::kSplitting);
    CHECK(c.options.method != Method::kSplitting4);
  }
}

TEST_CASE("damped body: a symmetric body's reference run is its closed form") {
  const double I = 2.0, I3 = 3.0, c = 0.3, lambda = (I3 - I) / I;
  const Eigen::Vector3d w0(1.0, 0.5, 2.0);
  const DampedBody body({I, I, I3}, c);
  const std::vector<double> times = rigid::uniform_times(0.0, 10.0, 101);
  const auto run = rigid::integrate(body, start(w0), times, rigid::reference_options());
  const double T0 = 0.5 * I * (w0.x() * w0.x() + w0.y() * w0.y()) + 0.5 * I3 * w0.z() * w0.z();
  for (const auto& s : run.samples) {
    INFO("t = " << s.t);
    const double t = s.t;
    const double w3 = w0.z() * std::exp(-c * t / I3);
    const std::complex<double> w12 =
        std::complex<double>(w0.x(), w0.y()) * std::exp(-c * t / I) *
        std::exp(std::complex<double>(0.0, lambda * w0.z() * I3 * (1 - std::exp(-c * t / I3)) / c));
    const Eigen::Vector3d w = omega_of(s.x);
    // Verner 9(8) at 1e-13: within 1e-12 of |omega0| over 10 s (three e-foldings of T)
    CHECK((w - Eigen::Vector3d(w12.real(), w12.imag(), w3)).norm() < 1e-12 * w0.norm());
    // the energy as its closed form, T0's two parts each decaying at its own rate
    const double T = 0.5 * I * std::norm(w12) + 0.5 * I3 * w3 * w3;
    CHECK(rigid::kinetic_energy({I, I, I3}, w) == Approx(T).epsilon(1e-12));
    // and the work the torque has taken: all that T has lost
    CHECK(s.x[7] == Approx(T0 - T).margin(1e-12 * T0));
  }
}

TEST_CASE("damped body: methods ranked against a reference run, each error by its order") {
  const DampedBody body({1.0, 2.0, 3.0}, 0.05);
  const DampedState x0 = start({0.3, 1.0, 0.4});
  const rigid::Reference<DampedState> reference{x0};
  const double period = 2 * M_PI / omega_of(x0).norm();
  // rk4 at h and h/2 over 5 periods: its error falls 2^4-fold
  OdeOptions settings;
  settings.abs_tol = settings.rel_tol = 1e-9;
  const std::vector<double> times = rigid::sample_times(5 * period, period);
  std::vector<double> rk4_errors;
  for (const double h : {period / 50, period / 100}) {
    settings.step = h;
    const auto compared = rigid::compare_methods(body, reference, times, period, settings, 100000);
    const MethodComparison& rk4 = of(compared, Method::kRk4);
    REQUIRE(rk4.completed);
    rk4_errors.push_back(rk4.max_error);
    // every method finished, each adaptive one near its tolerance
    for (const MethodComparison& c : compared) {
      INFO(rigid::method_name(c.options.method));
      CHECK(c.completed);
      if (rigid::is_adaptive(c.options.method)) CHECK(c.max_error < 1e-6);
    }
  }
  INFO("rk4: " << rk4_errors[0] << " at h, " << rk4_errors[1] << " at h/2");
  CHECK(rk4_errors[0] / rk4_errors[1] == Approx(16.0).epsilon(0.15));

  // At equal cost the higher order wins: Verner 9(8) ahead of 6(5), both far ahead of rk4.
  const auto at_cost = rigid::compare_methods_at_cost(body, reference, period, 10.0, 1000.0);
  // Its bound, without the reference runs: no splitting, no projection, so rk4 at 1.25
  // times its 1e4 evaluations, each adaptive method (Bulirsch-Stoer's counting 4) that
  // and its search's 16 times.
  CHECK(rigid::work_at_cost<DampedBody>(10.0, 1000.0) == Approx(12500.0 + 10 * 172500.0));
  const double rk4 = of(at_cost, Method::kRk4).max_error;
  const double vern6 = of(at_cost, Method::kVern6).max_error;
  const double vern9 = of(at_cost, Method::kVern9).max_error;
  INFO("rk4 " << rk4 << ", vern6 " << vern6 << ", vern9 " << vern9);
  CHECK(vern9 < vern6);
  CHECK(vern6 < 1e-2 * rk4);
  // the energy balance's drift is a run's own: T + W kept by the best to 1e-10
  CHECK(of(at_cost, Method::kVern9).invariants.at(DampedBody::kEnergyBalance).max_rel < 1e-10);
}

TEST_CASE("damped body: against a reference run, the free body's errors are those against exact") {
  // Where both exist the two comparisons agree: the reference (1e-13) moves each
  // method's largest error by no more than its own error, 1e-11 of |omega0|.
  const rigid::PrincipalMoments I{1.0, 2.0, 3.0};
  const rigid::FreeBodyExact exact(I, Eigen::Vector3d(0.3, 1.0, 0.4));
  const rigid::FreeBodyProblem problem(I);
  const double period = exact.period();
  OdeOptions settings;
  settings.step = period / 200;
  settings.abs_tol = settings.rel_tol = 1e-8;
  const std::vector<double> times = rigid::sample_times(3 * period, period);
  const auto against_exact = rigid::compare_methods(problem, exact, times, period, settings, 20000);
  const auto against_reference =
      rigid::compare_methods(problem, rigid::Reference<rigid::RotationState>{exact.state(0.0)},
                             times, period, settings, 20000);
  REQUIRE(against_exact.size() == against_reference.size());
  for (std::size_t k = 0; k < against_exact.size(); ++k) {
    const MethodComparison &a = against_exact[k], &b = against_reference[k];
    INFO(rigid::method_name(a.options.method) << ": " << a.max_error << " vs " << b.max_error);
    REQUIRE(a.completed);
    REQUIRE(b.completed);
    CHECK(a.options.method == b.options.method);
    CHECK(std::abs(a.max_error - b.max_error) < 1e-11);
    // a method's own error, where well above the reference's, to a thousandth of itself
    if (a.max_error > 1e-8) CHECK(std::abs(a.max_error - b.max_error) < 1e-3 * a.max_error);
    CHECK(a.t == b.t);
  }
}
