// Verner's pairs (verner.h, verner_tableaus.h): every coefficient checked by the
// order conditions of Butcher's rooted trees rather than trusted as transcribed,
// then the orders observed by step halving on the free body against its exact
// solution, the interpolant's order the same way, and the PI controller.
#include "rigid/verner.h"

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cfloat>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "rigid/free_body.h"
#include "rigid/free_body_exact.h"
#include "rigid/ode.h"

using namespace rigid;

namespace {

// ---- Butcher's rooted trees ----------------------------------------------------

// A rooted tree: its order |t|, its density gamma(t) = |t| prod gamma(children), and
// its children (indices of smaller trees). Trees are listed by order.
struct Tree {
  int order = 1;
  double gamma = 1.0;
  std::vector<int> children;
};

// Every rooted tree up to `max_order` nodes, once each (children as a nonincreasing
// list of tree indices: the multiset of subtrees). Counts: 1, 1, 2, 4, 9, 20, 48,
// 115, 286, 719 (OEIS A000081), checked below.
std::vector<Tree> trees_up_to(int max_order) {
  std::vector<Tree> t{Tree{}};
  for (int n = 2; n <= max_order; ++n) {
    const int count_before = static_cast<int>(t.size());
    std::vector<int> picked;
    // children with orders summing to `rest`, indices at most `max_index`
    const auto extend = [&](auto&& self, int rest, int max_index) -> void {
      if (rest == 0) {
        Tree tree;
        tree.order = n;
        tree.children = picked;
        tree.gamma = n;
        for (int c : picked) tree.gamma *= t[c].gamma;
        t.push_back(tree);
        return;
      }
      for (int i = std::min(max_index, count_before - 1); i >= 0; --i) {
        if (t[i].order > rest) continue;
        picked.push_back(i);
        self(self, rest - t[i].order, i);
        picked.pop_back();
      }
    };
    extend(extend, n - 1, count_before - 1);
  }
  return t;
}

using Ld = long double;
using Matrix = std::vector<std::vector<Ld>>;
using Vector = std::vector<Ld>;

// The stage vector of every tree: Phi(leaf) = 1, Phi([t1..tm])_i = prod_k (A Phi(t_k))_i;
// with |A| it bounds the size of the terms summed, for the rounding tolerance.
std::vector<Vector> stage_vectors(const std::vector<Tree>& trees, const Matrix& A) {
  const std::size_t s = A.size();
  std::vector<Vector> phi;
  std::vector<Vector> a_phi;  // A Phi(t), per tree
  for (const Tree& tree : trees) {
    Vector v(s, 1.0L);
    for (int c : tree.children)
      for (std::size_t i = 0; i < s; ++i) v[i] *= a_phi[c][i];
    Vector av(s, 0.0L);
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t j = 0; j < s; ++j) av[i] += A[i][j] * v[j];
    phi.push_back(v);
    a_phi.push_back(av);
  }
  return phi;
}

Ld dot(const Vector& w, const Vector& v) {
  Ld sum = 0.0L;
  for (std::size_t i = 0; i < w.size(); ++i) sum += w[i] * v[i];
  return sum;
}

Vector absolute(Vector v) {
  for (Ld& x : v) x = std::fabs(x);
  return v;
}

// One tableau in long double: the first `stages` rows and columns, or all of them.
template <class T>
Matrix matrix(int n) {
  Matrix A(n, Vector(n, 0.0L));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) A[i][j] = T::a[i][j];
  return A;
}

// The rounding tolerance of a condition w . Phi(t) = value evaluated in long
// double: each term is a product of about |t| coefficients summed over the stages
// (Higham, Accuracy and Stability, 3.1: n u sum |terms| for a sum of n products of
// depth |t|), with the coefficients themselves rounded to long double (25 digits
// given, u = 2^-64 kept), so 4 s |t| u (|w| . |Phi|(t) + |value|), |w| the sizes
// of the weights (for the interpolant, sum_k |r_ik| theta^(k+1)).
Ld tolerance(const Vector& abs_w, const Vector& abs_phi, const Tree& t, Ld value) {
  const Ld u = LDBL_EPSILON / 2;
  return 4.0L * static_cast<Ld>(abs_w.size()) * t.order * u *
         (dot(abs_w, abs_phi) + std::fabs(value));
}

// c_i = sum_j a_ij: the nodes are the row sums.
template <class T>
void check_nodes(const std::string& name) {
  const int n = T::kTotalStages;
  for (int i = 0; i < n; ++i) {
    Ld sum = 0.0L, size = 0.0L;
    for (int j = 0; j < n; ++j) sum += T::a[i][j], size += std::fabs(T::a[i][j]);
    INFO(name << " row " << i);
    CHECK(std::fabs(sum - T::c[i]) <= 4.0L * n * LDBL_EPSILON * (size + std::fabs(T::c[i])));
  }
}

// The interpolant's weights b_i(theta) = sum_d r_id theta^(d+1), and their sizes (sum_d
// |r_id| theta^(d+1)), by Horner's rule.
template <class T>
std::pair<Vector, Vector> interpolant_weights(Ld theta) {
  const int n = T::kTotalStages;
  Vector w(n, 0.0L), abs_w(n, 0.0L);
  for (int i = 0; i < n; ++i)
    for (int d = static_cast<int>(sizeof(T::r[0]) / sizeof(T::r[0][0])) - 1; d >= 0; --d) {
      w[i] = (w[i] + T::r[i][d]) * theta;
      abs_w[i] = (abs_w[i] + std::fabs(T::r[i][d])) * theta;
    }
  return {w, abs_w};
}

// The interpolant at theta = 1 is the step's own solution, and its extra stages drop out.
template <class T>
void check_interpolant_at_one(const std::string& name) {
  for (int i = 0; i < T::kTotalStages; ++i) {
    Ld at_one = 0.0L, size = 0.0L;
    for (const Ld r : T::r[i]) at_one += r, size += std::fabs(r);
    const Ld want = i < T::kStages ? T::b[i] : 0.0L;
    INFO(name << " b_" << i << "(1)");
    CHECK(std::fabs(at_one - want) <= 8.0L * LDBL_EPSILON * (size + std::fabs(want)));
  }
}

template <class T>
void check_order_conditions(const std::string& name) {
  const std::vector<Tree> trees = trees_up_to(T::kOrder + 1);
  const int s = T::kStages, n = T::kTotalStages;
  const Matrix A = matrix<T>(s), A_all = matrix<T>(n);
  const std::vector<Vector> phi = stage_vectors(trees, A), phi_all = stage_vectors(trees, A_all);
  Matrix A_abs = A, A_all_abs = A_all;
  for (Vector& row : A_abs) row = absolute(row);
  for (Vector& row : A_all_abs) row = absolute(row);
  const std::vector<Vector> abs_phi = stage_vectors(trees, A_abs),
                            abs_phi_all = stage_vectors(trees, A_all_abs);
  const Vector b(T::b, T::b + s), e(T::e, T::e + s);

  check_nodes<T>(name);

  // the largest residual of a condition that holds, and of one order up
  Ld b_held = 0.0L, b_next = 0.0L, e_held = 0.0L, e_next = 0.0L;
  int checked = 0;
  for (std::size_t k = 0; k < trees.size(); ++k) {
    const Tree& t = trees[k];
    const Ld exact = 1.0L / static_cast<Ld>(t.gamma);
    const Ld rb = std::fabs(dot(b, phi[k]) - exact);
    const Ld tb = tolerance(absolute(b), abs_phi[k], t, exact);
    const Ld re = std::fabs(dot(e, phi[k])), te = tolerance(absolute(e), abs_phi[k], t, 0.0L);
    INFO(name << ": tree " << k << " of order " << t.order << ", b residual "
              << static_cast<double>(rb) << " (tolerance " << static_cast<double>(tb)
              << "), e residual " << static_cast<double>(re));
    if (t.order <= T::kOrder) {
      CHECK(rb <= tb);  // b: order p
      b_held = std::max(b_held, rb);
      ++checked;
    } else {
      b_next = std::max(b_next, rb);
    }
    if (t.order <= T::kErrorOrder) {
      CHECK(re <= te);  // bhat = b - e: order p - 1
      e_held = std::max(e_held, re);
    } else if (t.order == T::kErrorOrder + 1) {
      e_next = std::max(e_next, re);
    }
    // the interpolant: sum_i b_i(theta) Phi_i(t) = theta^|t| / gamma(t) to its order
    if (t.order <= T::kInterpolantOrder) {
      for (const Ld theta : {0.2L, 0.5L, 0.9L}) {
        const auto [w, abs_w] = interpolant_weights<T>(theta);
        const Ld want = std::pow(theta, static_cast<Ld>(t.order)) * exact;
        CHECK(std::fabs(dot(w, phi_all[k]) - want) <= tolerance(abs_w, abs_phi_all[k], t, want));
      }
    }
  }
  INFO(name << ": " << checked << " conditions of b, largest residual "
            << static_cast<double>(b_held) << ", one order up " << static_cast<double>(b_next)
            << "; of e " << static_cast<double>(e_held) << ", one order up "
            << static_cast<double>(e_next));
  CHECK(checked == static_cast<int>(std::count_if(trees.begin(), trees.end(), [](const Tree& t) {
          return t.order <= T::kOrder;
        })));
  // the orders are exactly p and p - 1: some condition one order up misses by a
  // million times more than any that holds (else the pair would be mislabelled, or
  // its error estimate of a higher order than claimed)
  CHECK(b_next > 1e6L * b_held);
  CHECK(e_next > 1e6L * e_held);
  check_interpolant_at_one<T>(name);
}

// ---- observed orders -------------------------------------------------------------

// Hairer, Lubich & Wanner's free body (GNI I.5.3): I = (2, 1, 2/3), L0 = (cos 1.1, 0, sin 1.1).
const PrincipalMoments kHlw{2.0, 1.0, 2.0 / 3.0};
const Eigen::Vector3d kOmega0 =
    Eigen::Vector3d(std::cos(1.1), 0.0, std::sin(1.1)).cwiseQuotient(kHlw.vector());

double state_error(const RotationState& x, const RotationState& exact) {
  double worst = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) worst = std::max(worst, std::abs(x[i] - exact[i]));
  return worst;
}

// The error at t = 10 s after n fixed steps of the pair.
template <class T>
double fixed_step_error(int n) {
  const FreeBodyExact exact(kHlw, kOmega0, Eigen::Quaterniond::Identity(),
                            MomentsRule::kPositiveOnly);
  const double t_end = 10.0, h = t_end / n;
  VernerStepper<T, RotationState> stepper;
  RotationState x = exact.state(0.0);
  const EulerRhs rhs{kHlw};
  for (int k = 0; k < n; ++k) stepper.do_step(rhs, x, k * h, h);
  return state_error(x, exact.state(t_end));
}

// The interpolant's error at the middle of one step of length h from the exact state.
template <class T>
double interpolant_error(double h) {
  const FreeBodyExact exact(kHlw, kOmega0, Eigen::Quaterniond::Identity(),
                            MomentsRule::kPositiveOnly);
  // a tolerance that accepts the step as given: one step of length h, then the interpolant
  VernerDenseOutput<T, RotationState> dense(0.5, 0.5);
  dense.initialize(exact.state(0.0), 0.0, h);
  dense.do_step(EulerRhs{kHlw});
  REQUIRE(dense.previous_time() == 0.0);
  REQUIRE(dense.current_time() == h);
  RotationState x;
  dense.calc_state(0.5 * h, x);
  return state_error(x, exact.state(0.5 * h));
}

}  // namespace

TEST_CASE("verner: the rooted trees are counted as OEIS A000081") {
  const std::vector<Tree> trees = trees_up_to(10);
  std::array<int, 11> count{};
  for (const Tree& t : trees) ++count[t.order];
  CHECK(count == std::array<int, 11>{0, 1, 1, 2, 4, 9, 20, 48, 115, 286, 719});
}

TEST_CASE(
    "verner: every coefficient of the 6(5) pair and its interpolant meets its order conditions") {
  check_order_conditions<verner::Vern6>("vern6");
}
TEST_CASE(
    "verner: every coefficient of the 7(6) pair and its interpolant meets its order conditions") {
  check_order_conditions<verner::Vern7>("vern7");
}
TEST_CASE(
    "verner: every coefficient of the 8(7) pair and its interpolant meets its order conditions") {
  check_order_conditions<verner::Vern8>("vern8");
}
TEST_CASE(
    "verner: every coefficient of the 9(8) pair and its interpolant meets its order conditions") {
  check_order_conditions<verner::Vern9>("vern9");
}

template <class T>
void check_observed_order(const char* name) {
  // Step halving from n steps over 10 s where the error is well above roundoff
  // (1e-11: the 6(5) pair's large coefficients leave ~1e-12 of roundoff over a run)
  // and below 1e-3: at least order p. The order conditions show it is exactly p;
  // at these steps the observed rate is up to p + 2, since Verner chose the pairs
  // for small leading error coefficients and the next term is comparable (seen:
  // 6.8-7.4 for the 6(5) pair, 8.1-8.4, 9.1-10.1, 9.9-10.8).
  std::vector<double> errors;
  for (int n = 4; n <= 64; n *= 2) errors.push_back(fixed_step_error<T>(n));
  int pairs = 0;
  for (std::size_t k = 0; k + 1 < errors.size(); ++k) {
    if (errors[k] > 1e-3 || errors[k + 1] < 1e-11) continue;
    const double p = std::log2(errors[k] / errors[k + 1]);
    INFO(name << ": errors " << errors[k] << " -> " << errors[k + 1] << ", observed order " << p);
    CHECK(p >= T::kOrder - 0.3);
    ++pairs;
  }
  CHECK(pairs >= 2);
  // the interpolant: its local error at theta = 1/2 is O(h^(q+1)), the same window
  std::vector<double> local;
  for (const double h : {1.6, 0.8, 0.4}) local.push_back(interpolant_error<T>(h));
  int interpolant_pairs = 0;
  for (std::size_t k = 0; k + 1 < local.size(); ++k) {
    if (local[k] > 1e-3 || local[k + 1] < 1e-11) continue;
    const double q = std::log2(local[k] / local[k + 1]) - 1.0;
    INFO(name << ": interpolant errors " << local[k] << " -> " << local[k + 1]
              << ", observed order " << q);
    CHECK(q >= T::kInterpolantOrder - 0.3);
    ++interpolant_pairs;
  }
  CHECK(interpolant_pairs >= 1);
}

TEST_CASE("verner: each pair's order and its interpolant's are observed by step halving") {
  check_observed_order<verner::Vern6>("vern6");
  check_observed_order<verner::Vern7>("vern7");
  check_observed_order<verner::Vern8>("vern8");
  check_observed_order<verner::Vern9>("vern9");
}

TEST_CASE("verner: the PI controller holds the error with fewer rejections than odeint's") {
  namespace odeint = boost::numeric::odeint;
  const FreeBodyExact exact(kHlw, kOmega0, Eigen::Quaterniond::Identity(),
                            MomentsRule::kPositiveOnly);
  const std::vector<double> times = {0.0, 100.0};
  for (const double tol : {1e-6, 1e-10}) {
    VernerDenseOutput<verner::Vern7, RotationState> pi(tol, tol);
    VernerDenseOutput<verner::Vern7, RotationState, odeint::default_step_adjuster<double, double>>
        elementary(tol, tol, odeint::default_step_adjuster<double, double>());
    RotationState x1 = exact.state(0.0), x2 = x1;
    const auto none = [](const RotationState&, double) {};
    const std::size_t s1 = odeint::integrate_times(std::ref(pi), EulerRhs{kHlw}, x1, times.begin(),
                                                   times.end(), 0.01, none);
    const std::size_t s2 = odeint::integrate_times(std::ref(elementary), EulerRhs{kHlw}, x2,
                                                   times.begin(), times.end(), 0.01, none);
    const double e1 = state_error(x1, exact.state(100.0)), e2 = state_error(x2, exact.state(100.0));
    INFO("tol " << tol << ": PI " << s1 << " steps, " << pi.rejected_steps() << " rejected, error "
                << e1 << "; odeint's " << s2 << " steps, " << elementary.rejected_steps()
                << " rejected, error " << e2);
    // both hold the error to the tolerance's scale over ~100 steps' worth of growth
    CHECK(e1 < 1e3 * tol);
    CHECK(e2 < 1e3 * tol);
    CHECK(pi.rejected_steps() <= elementary.rejected_steps());
  }
}

TEST_CASE(
    "verner: through integrate_sampled every pair lands on the samples, with or without a hook") {
  const FreeBodyExact exact(kHlw, kOmega0, Eigen::Quaterniond::Identity(),
                            MomentsRule::kPositiveOnly);
  std::vector<double> times;
  for (int k = 0; k <= 400; ++k) times.push_back(0.05 * k);  // many samples a step
  for (const Method m : {Method::kVern6, Method::kVern7, Method::kVern8, Method::kVern9}) {
    OdeOptions o;
    o.method = m;
    o.abs_tol = o.rel_tol = 1e-10;
    double worst = 0.0, worst_hooked = 0.0;
    std::size_t seen = 0;
    const OdeStats dense = integrate_sampled(
        EulerRhs{kHlw}, exact.state(0.0), times, o, [&](const RotationState& x, double t) {
          CHECK(t == times[seen++]);
          worst = std::max(worst, state_error(x, exact.state(t)));
        });
    const auto normalize = [](RotationState& x) {
      const double n = std::sqrt(x[3] * x[3] + x[4] * x[4] + x[5] * x[5] + x[6] * x[6]);
      for (int i = 3; i < 7; ++i) x[i] /= n;
    };
    const OdeStats hooked = integrate_sampled(
        EulerRhs{kHlw}, exact.state(0.0), times, o,
        [&](const RotationState& x, double t) {
          worst_hooked = std::max(worst_hooked, state_error(x, exact.state(t)));
        },
        normalize);
    INFO(method_name(m) << ": dense " << dense.steps << " steps, " << dense.evaluations
                        << " evaluations, worst " << worst << "; hooked " << hooked.steps
                        << " steps, worst " << worst_hooked);
    CHECK(seen == times.size());
    // 20 s at tolerance 1e-10: the error of a well-conditioned run stays within 1e3 tol
    CHECK(worst < 1e-7);
    CHECK(worst_hooked < 1e-7);
    // the interpolant serves the samples: fewer steps than samples, unlike the hooked run
    CHECK(dense.steps < times.size() / 2);
    CHECK(hooked.steps >= times.size() - 1);
  }
}

TEST_CASE("verner: between steps the interpolant is as accurate as the steps, not its roundoff") {
  // The interpolants' weights b_i(theta) are large and cancel (coefficients up to 1.35e6
  // in the 8(7) pair): formed in double, their rounding cost ~3e-11 at every sample of
  // the text's ellipsoid at tolerance 1e-12 (measured: 6e-11 in |omega|), far above the
  // steps' own error. Formed in long double they stay at the tolerance's scale: 10 tol.
  const PrincipalMoments I{M_PI, 2 * M_PI, 8.168140899333462};
  const Eigen::Vector3d w0(1, 1, 1);
  const FreeBodyExact exact(I, w0, Eigen::Quaterniond::Identity());
  std::vector<double> times;
  for (int k = 0; k <= 600; ++k) times.push_back(3 * exact.period() * k / 600);
  for (const Method m : {Method::kVern6, Method::kVern7, Method::kVern8, Method::kVern9}) {
    OdeOptions o;
    o.method = m;
    o.abs_tol = o.rel_tol = 1e-12;
    double worst = 0.0;
    integrate_sampled(EulerRhs{I}, exact.state(0.0), times, o,
                      [&](const RotationState& x, double t) {
                        worst = std::max(worst, (omega_body(x) - exact.omega_body(t)).norm());
                      });
    INFO(method_name(m) << ": worst sample error " << worst);
    // measured: 5.4e-12 (the 6(5) pair's steps' own error), 4.3e-13, 1.2e-12, 3.4e-14
    CHECK(worst < 1e-11);
  }
}

// Where long double is not the x87's (WebAssembly, AArch64), the interpolant's weights
// and sums are formed in two doubles (wide.h) instead: they must keep the digits the
// cancellation costs. The 8(7) pair's weights, whose coefficients reach 1.35e6 and
// cancel, formed in two doubles from the coefficients' first 106 bits against the same
// in long double: within a few of long double's own roundings of their size.
TEST_CASE("Wide forms the 8(7) interpolant's weights as long double does") {
  using T = verner::Vern8;
  constexpr int kDegree = sizeof(T::r[0]) / sizeof(T::r[0][0]);
  double worst = 0;
  for (const double theta : {0.1, 0.37, 0.5, 0.81, 0.999}) {
    for (int i = 0; i < T::kTotalStages; ++i) {
      long double exact = 0.0L, scale = 0.0L;
      Wide wide = 0.0;
      for (int d = kDegree - 1; d >= 0; --d) {
        exact = exact * theta + T::r[i][d];
        scale = scale * theta + std::fabs(T::r[i][d]);
        wide = wide * Wide(theta) + Wide::of(T::r[i][d]);
      }
      const long double gap = std::fabs(static_cast<long double>(wide.hi) + wide.lo - exact);
      worst = std::max(worst, static_cast<double>(gap / (scale * LDBL_EPSILON)));
    }
  }
  // Horner's bound in long double: a rounding of the scale at each of its steps
  CHECK(worst <= kDegree);
}
