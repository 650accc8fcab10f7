// Verner's "most efficient" embedded Runge-Kutta pairs 6(5), 7(6), 8(7) and
// 9(8) (coefficients in verner_tableaus.h, with their source) as Boost.Odeint
// error steppers on fixed-size state, a PI step-size controller, and a
// dense-output stepper with Verner's interpolants.
//
//  - VernerStepper<Tableau, State>: an odeint ErrorStepper (explicit, or
//    explicit FSAL for the 6(5) pair, whose last stage is f at the new state),
//    built on odeint's explicit_error_stepper_base / _fsal_base, so odeint's
//    controlled_runge_kutta, error checker and integrate functions drive it.
//    Each stage sums only the nonzero a(i, j): the tableau is a compile-time
//    constant and a zero coefficient costs nothing.
//  - PiStepAdjuster: odeint's StepAdjuster concept with the PI controller of
//    Gustafsson (Hairer & Wanner, Solving ODEs II, IV.2, eq. 2.43c):
//    h_new = h * safety * err^-alpha * err_prev^beta, alpha = 0.7 / k,
//    beta = 0.4 / k, k = the error estimate's order + 1; the factor kept in
//    [0.2, 10], and not above 1 right after a rejection.
//  - VernerDenseOutput<Tableau, State>: odeint's DenseOutputStepper concept
//    (initialize, do_step, calc_state, ...), the same step and control, and
//    Verner's interpolant between steps; its extra stages are computed once
//    per step, and only when a time inside the step is asked for.
#pragma once

#include <algorithm>
#include <array>
#include <boost/numeric/odeint/algebra/algebra_dispatcher.hpp>
#include <boost/numeric/odeint/algebra/operations_dispatcher.hpp>
#include <boost/numeric/odeint/integrate/max_step_checker.hpp>
#include <boost/numeric/odeint/stepper/base/explicit_error_stepper_base.hpp>
#include <boost/numeric/odeint/stepper/base/explicit_error_stepper_fsal_base.hpp>
#include <boost/numeric/odeint/stepper/controlled_runge_kutta.hpp>
#include <boost/numeric/odeint/stepper/stepper_categories.hpp>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <functional>
#include <type_traits>
#include <utility>

#include "rigid/verner_tableaus.h"
#include "rigid/wide.h"

// A step inlines everything it calls, the right-hand side included: its stages are
// one long function, and without this GCC stops inlining into it (measured: the
// free body's right-hand side then costs half of a Verner step).
// Under AddressSanitizer flattening makes one instrumented function of every
// Verner step and its callers, which GCC compiles for tens of minutes; a
// sanitizer build checks memory, not speed, so it goes without.
#if defined(__GNUC__) && !defined(__SANITIZE_ADDRESS__)
#define RIGID_FLATTEN __attribute__((flatten))
#else
#define RIGID_FLATTEN
#endif

namespace rigid {

namespace detail {

// A tableau's coefficients rounded to double at compile time (the interpolant's stay in
// long double: see VernerDenseOutput::calc_state).
template <class T>
struct DoubleTableau {
  static constexpr int kTotal = T::kTotalStages;
  static constexpr int kDegree = T::kInterpolantOrder > 0 ? sizeof(T::r[0]) / sizeof(T::r[0][0])
                                                          : 0;
  using Row = std::array<double, kTotal>;
  static constexpr std::array<Row, kTotal> a_() {
    std::array<Row, kTotal> out{};
    for (int i = 0; i < kTotal; ++i)
      for (int j = 0; j < kTotal; ++j) out[i][j] = static_cast<double>(T::a[i][j]);
    return out;
  }
  template <std::size_t N>
  static constexpr std::array<double, N> vec_(const long double (&v)[N]) {
    std::array<double, N> out{};
    for (std::size_t i = 0; i < N; ++i) out[i] = static_cast<double>(v[i]);
    return out;
  }
  static constexpr std::array<Row, kTotal> a = a_();
  static constexpr std::array<double, kTotal> c = vec_(T::c);
  static constexpr std::array<double, T::kStages> b = vec_(T::b);
  static constexpr std::array<double, T::kStages> e = vec_(T::e);
};

// out = x + h * sum_j w[j] k[j] over the j of Js with w[j] != 0, component by component.
template <class State, class Stages, class Weights, std::size_t... Js>
inline void combine(State& out, const State& x, double h, const Stages& k, const Weights& w,
                    std::index_sequence<Js...>) {
  for (std::size_t n = 0; n < static_cast<std::size_t>(x.size()); ++n) {
    double sum = 0.0;
    ((w[Js] != 0.0 ? void(sum += w[Js] * k[Js][n]) : void()), ...);
    out[n] = x[n] + h * sum;
  }
}

}  // namespace detail

namespace odeint_base {
namespace odeint = boost::numeric::odeint;
template <class Derived, class Tableau, class State>
using VernerBase = std::conditional_t<
    Tableau::kFsal,
    odeint::explicit_error_stepper_fsal_base<
        Derived, Tableau::kOrder, Tableau::kOrder, Tableau::kErrorOrder, State, double, State,
        double, typename odeint::algebra_dispatcher<State>::algebra_type,
        typename odeint::operations_dispatcher<State>::operations_type, odeint::initially_resizer>,
    odeint::explicit_error_stepper_base<
        Derived, Tableau::kOrder, Tableau::kOrder, Tableau::kErrorOrder, State, double, State,
        double, typename odeint::algebra_dispatcher<State>::algebra_type,
        typename odeint::operations_dispatcher<State>::operations_type, odeint::initially_resizer>>;
}  // namespace odeint_base

/// One step of a Verner pair with its error estimate, as an odeint error stepper on
/// fixed-size State (std::array<double, N>). The stages of the last step stay in
/// the stepper (stages()), for the interpolant.
template <class Tableau, class State>
class VernerStepper
    : public odeint_base::VernerBase<VernerStepper<Tableau, State>, Tableau, State> {
  using D = detail::DoubleTableau<Tableau>;
  static constexpr int kS = Tableau::kStages;

 public:
  using Stages = std::array<State, Tableau::kTotalStages>;

  /// odeint's error stepper (non-FSAL): out, and the error estimate in xerr.
  template <class System, class StateIn, class DerivIn, class StateOut, class Err>
  RIGID_FLATTEN void do_step_impl(System system, const StateIn& in, const DerivIn& dxdt, double t,
                                  StateOut& out, double dt, Err& xerr) {
    static_assert(!Tableau::kFsal, "an FSAL pair steps through the FSAL overload");
    stages(system, in, dxdt, t, dt, std::make_index_sequence<kS - 1>{});
    finish(in, out, dt, xerr, std::make_index_sequence<kS>{});
  }
  template <class System, class StateIn, class DerivIn, class StateOut>
  void do_step_impl(System system, const StateIn& in, const DerivIn& dxdt, double t, StateOut& out,
                    double dt) {
    State err;
    do_step_impl(system, in, dxdt, t, out, dt, err);
  }

  /// odeint's FSAL error stepper: out, f(out) in dxdt_out, the error estimate in xerr.
  template <class System, class StateIn, class DerivIn, class StateOut, class DerivOut, class Err>
  RIGID_FLATTEN void do_step_impl(System system, const StateIn& in, const DerivIn& dxdt_in,
                                  double t, StateOut& out, DerivOut& dxdt_out, double dt,
                                  Err& xerr) {
    static_assert(Tableau::kFsal, "only an FSAL pair steps through the FSAL overload");
    // the last stage is f(out): out from the others, then that stage, then the error
    stages(system, in, dxdt_in, t, dt, std::make_index_sequence<kS - 2>{});
    State sum;
    detail::combine(sum, in, dt, k_, D::b, std::make_index_sequence<kS - 1>{});
    system(sum, k_[kS - 1], t + dt);
    for (std::size_t n = 0; n < static_cast<std::size_t>(in.size()); ++n) {
      double e = 0.0;
      for (int j = 0; j < kS; ++j) e += D::e[j] * k_[j][n];
      xerr[n] = dt * e;
      out[n] = sum[n];
      dxdt_out[n] = k_[kS - 1][n];
    }
  }
  template <class System, class StateIn, class DerivIn, class StateOut, class DerivOut>
  void do_step_impl(System system, const StateIn& in, const DerivIn& dxdt_in, double t,
                    StateOut& out, DerivOut& dxdt_out, double dt) {
    State err;
    do_step_impl(system, in, dxdt_in, t, out, dxdt_out, dt, err);
  }

  /// The stages of the last step (the first kStages), and room for the extra ones.
  Stages& stage_values() { return k_; }

 private:
  // k_[0] = dxdt, then k_[i] for each i of Is + 1.
  template <class System, class StateIn, class DerivIn, std::size_t... Is>
  void stages(System& system, const StateIn& in, const DerivIn& dxdt, double t, double dt,
              std::index_sequence<Is...>) {
    for (std::size_t n = 0; n < static_cast<std::size_t>(in.size()); ++n) k_[0][n] = dxdt[n];
    (stage<Is + 1>(system, in, t, dt), ...);
  }
  template <std::size_t I, class System, class StateIn>
  void stage(System& system, const StateIn& in, double t, double dt) {
    State xi;
    detail::combine(xi, in, dt, k_, D::a[I], std::make_index_sequence<I>{});
    system(xi, k_[I], t + D::c[I] * dt);
  }
  template <class StateIn, class StateOut, class Err, std::size_t... Js>
  void finish(const StateIn& in, StateOut& out, double dt, Err& xerr, std::index_sequence<Js...>) {
    for (std::size_t n = 0; n < static_cast<std::size_t>(in.size()); ++n) {
      double b = 0.0, e = 0.0;
      ((D::b[Js] != 0.0 ? void(b += D::b[Js] * k_[Js][n]) : void()), ...);
      ((D::e[Js] != 0.0 ? void(e += D::e[Js] * k_[Js][n]) : void()), ...);
      xerr[n] = dt * e;
      out[n] = in[n] + dt * b;  // after reading in[n]: in and out may be one state
    }
  }

  Stages k_{};
};

/// odeint's StepAdjuster concept with a PI controller (see the header comment).
class PiStepAdjuster {
 public:
  /// error_order: the order of the lower-order solution of the pair (p - 1).
  explicit PiStepAdjuster(int error_order = 4)
      : k_(error_order + 1.0), alpha_(0.7 / k_), beta_(0.4 / k_) {}

  /// After a rejected step: the elementary controller, no smaller than 1/5 of dt.
  double decrease_step(double dt, double error, int /*error_order*/) {
    just_rejected_ = true;
    return dt * std::max(kFacMin, kSafety * std::pow(error, -1.0 / k_));
  }
  /// After an accepted step: the PI factor, kept in [1/5, 10] (at most 1 right after a
  /// rejection), and this error remembered.
  double increase_step(double dt, double error, int /*stepper_order*/) {
    // a zero error would ask for an infinite step
    const double log_err = std::log(std::max(error, 1e-10));
    // err^-alpha err_prev^beta as one exp: a step's control costs one log and one exp
    double fac = kSafety * std::exp(beta_ * log_previous_ - alpha_ * log_err);
    fac = std::clamp(fac, kFacMin, just_rejected_ ? 1.0 : kFacMax);
    log_previous_ = std::max(log_err, kLogFloor);  // Hairer's floor 1e-4 on the remembered error
    just_rejected_ = false;
    return dt * fac;
  }
  bool check_step_size_limit(double /*dt*/) const { return true; }
  double get_max_dt() const { return 0.0; }

 private:
  static constexpr double kSafety = 0.9, kFacMin = 0.2, kFacMax = 10.0;
  double k_, alpha_, beta_;
  static constexpr double kLogFloor = -9.210340371976184;  // log(1e-4)
  double log_previous_ = kLogFloor;
  bool just_rejected_ = false;
};

/// A Verner pair under error control with its interpolant, as an odeint dense-output
/// stepper on fixed-size State. The error of a step is odeint's default_error_checker
/// (abs_tol + rel_tol (|x| + dt |dx/dt|), max norm); the step is controlled by Adjuster.
template <class Tableau, class State, class Adjuster = PiStepAdjuster>
class VernerDenseOutput {
  using D = detail::DoubleTableau<Tableau>;
  using Stepper = VernerStepper<Tableau, State>;
  static constexpr int kS = Tableau::kStages, kTotal = Tableau::kTotalStages;
  static_assert(Tableau::kInterpolantOrder > 0, "the pair has no interpolant");

 public:
  using stepper_category = boost::numeric::odeint::dense_output_stepper_tag;
  using state_type = State;
  using value_type = double;
  using deriv_type = State;
  using time_type = double;
  using order_type = unsigned short;

  /// Tolerances as odeint's default_error_checker takes them; the controller (odeint's
  /// default_step_adjuster may be given for comparison).
  VernerDenseOutput(double abs_tol, double rel_tol,
                    Adjuster adjuster = Adjuster(Tableau::kErrorOrder))
      : checker_(abs_tol, rel_tol), adjuster_(std::move(adjuster)) {}

  /// odeint: start from x0 at t0 with the trial step dt0.
  void initialize(const State& x0, double t0, double dt0) {
    x_ = x_old_ = x0;
    t_ = t_old_ = t0;
    h_ = 0.0;  // no step yet: the state at t0 is x0 itself
    dt_ = dt0;
    have_deriv_ = false;
  }

  /// odeint: one accepted step (retrying with smaller steps until the error is within
  /// the tolerance); returns the interval it covered.
  template <class System>
  std::pair<double, double> do_step(System system) {
    if (!system_) system_ = system;  // for the extra stages: one system per stepper
    if (!have_deriv_) {
      system(x_, dxdt_, t_);
      have_deriv_ = true;
    }
    boost::numeric::odeint::failed_step_checker fail;
    State err;
    for (;;) {
      step(system, err);
      const double e = checker_.error(stepper_.algebra(), x_, dxdt_, err, dt_);
      if (e <= 1.0) {
        next_dt_ = adjuster_.increase_step(dt_, e, Tableau::kOrder);
        break;
      }
      dt_ = adjuster_.decrease_step(dt_, e, Tableau::kErrorOrder);
      ++rejected_;
      fail();  // throws after odeint's limit of failed steps in a row
    }
    x_old_ = x_;
    t_old_ = t_;
    h_ = dt_;
    x_ = x_new_;
    t_ = t_old_ + h_;
    dt_ = next_dt_;
    extra_done_ = false;
    if constexpr (Tableau::kFsal) {
      dxdt_ = dxdt_new_;
    } else {
      have_deriv_ = false;
    }
    return {t_old_, t_};
  }

  /// odeint: the state at t in the last step, from the interpolant.
  void calc_state(double t, State& x) {
    // the step's ends exactly (before any step, both are the initial state)
    if (h_ == 0.0 || t >= t_) {
      x = x_;
      return;
    }
    const double theta = (t - t_old_) / h_;
    if (theta <= 0.0) {
      x = x_old_;
      return;
    }
    if (!extra_done_) extra_stages();
    auto& k = stepper_.stage_values();
    // The weights b_i(theta) are large and cancel (up to 1.2e5 in the 6(5) pair's
    // polynomial coefficients, 1.35e6 in the 8(7) pair's): in double, their rounding
    // alone would cost ~1e-10 h |f| at every sample. They and the sum are formed in
    // long double from the long double coefficients where long double is the x87's
    // 64-bit significand, else in two doubles (wide.h) from their first 106 bits.
#if LDBL_MANT_DIG == 64
    using Extended = long double;
    const auto& r = Tableau::r;
#else
    using Extended = Wide;
    static const auto r = wide_interpolant();
#endif
    std::array<Extended, kTotal> w{};
    const Extended th = theta;
    for (int i = 0; i < kTotal; ++i) {
      Extended p = 0.0;  // b_i(theta) by Horner
      for (int d = D::kDegree - 1; d >= 0; --d) p = p * th + r[i][d];
      w[i] = p * th;
    }
    for (std::size_t n = 0; n < static_cast<std::size_t>(x.size()); ++n) {
      Extended sum = 0.0;
      for (int i = 0; i < kTotal; ++i) sum = sum + w[i] * Extended(k[i][n]);
      x[n] = x_old_[n] + h_ * value_of(sum);
    }
  }

  static double value_of(long double v) {
    return static_cast<double>(v);
  }
  static double value_of(const Wide& v) {
    return v.value();
  }
  // The interpolant's coefficients as two doubles each.
  static std::array<std::array<Wide, D::kDegree>, kTotal> wide_interpolant() {
    std::array<std::array<Wide, D::kDegree>, kTotal> out{};
    for (int i = 0; i < kTotal; ++i)
      for (int d = 0; d < D::kDegree; ++d) out[i][d] = Wide::of(Tableau::r[i][d]);
    return out;
  }

  const State& current_state() const {
    return x_;
  }
  double current_time() const {
    return t_;
  }
  double current_time_step() const {
    return dt_;
  }
  const State& previous_state() const {
    return x_old_;
  }
  double previous_time() const {
    return t_old_;
  }
  /// Steps rejected by the error control so far.
  std::size_t rejected_steps() const {
    return rejected_;
  }

 private:
  template <class System>
  void step(System& system, State& err) {
    if constexpr (Tableau::kFsal) {
      stepper_.do_step(system, x_, dxdt_, t_, x_new_, dxdt_new_, dt_, err);
    } else {
      stepper_.do_step(system, x_, dxdt_, t_, x_new_, dt_, err);
    }
  }

  // The interpolant's extra stages of the last step.
  void extra_stages() {
    auto& k = stepper_.stage_values();
    for (int i = kS; i < kTotal; ++i) {
      State xi;
      for (std::size_t n = 0; n < static_cast<std::size_t>(xi.size()); ++n) {
        double sum = 0.0;
        for (int j = 0; j < i; ++j) sum += D::a[i][j] * k[j][n];
        xi[n] = x_old_[n] + h_ * sum;
      }
      system_(xi, k[i], t_old_ + D::c[i] * h_);
    }
    extra_done_ = true;
  }

  Stepper stepper_;
  boost::numeric::odeint::default_error_checker<double, typename Stepper::algebra_type,
                                                typename Stepper::operations_type>
      checker_;
  Adjuster adjuster_;
  State x_{}, x_new_{}, x_old_{}, dxdt_{}, dxdt_new_{};
  double t_ = 0.0, t_old_ = 0.0, dt_ = 0.0, h_ = 0.0, next_dt_ = 0.0;
  bool have_deriv_ = false;
  bool extra_done_ = false;
  std::size_t rejected_ = 0;
  std::function<void(const State&, State&, double)> system_;
};

}  // namespace rigid
