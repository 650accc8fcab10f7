#include "rigid/ode.h"

#include <limits>
#include <sstream>

#include "rigid/format.h"

namespace rigid {

namespace {

// Every method's facts in one table, in the order of Method.
struct MethodFacts {
  std::string_view name, kind;
  int fixed_step_order;      // 0: adaptive
  int evaluations_per_step;  // 0: counted as they happen (adaptive)
  bool adaptive, after_step;
};
constexpr std::array<MethodFacts, kAllMethods.size()> kFacts = {{
    {"splitting", "symplectic splitting, order 2", 2, 1, false, false},
    {"splitting4", "symplectic splitting, order 4", 4, 5, false, false},
    {"rk4", "fixed-step Runge-Kutta, order 4", 4, 4, false, true},
    {"dopri5", "adaptive Runge-Kutta, order 5(4)", 0, 0, true, false},
    {"rkf78", "adaptive Runge-Kutta-Fehlberg, order 7(8)", 0, 0, true, true},
    {"bulirsch-stoer", "adaptive extrapolation (Bulirsch-Stoer)", 0, 0, true, false},
    {"vern6", "adaptive Runge-Kutta (Verner), order 6(5)", 0, 0, true, true},
    {"vern7", "adaptive Runge-Kutta (Verner), order 7(6)", 0, 0, true, true},
    {"vern8", "adaptive Runge-Kutta (Verner), order 8(7)", 0, 0, true, true},
    {"vern9", "adaptive Runge-Kutta (Verner), order 9(8)", 0, 0, true, true},
}};

const MethodFacts& facts(Method m) {
  return kFacts[static_cast<std::size_t>(m)];
}

// The one wording of "this run needs too many steps", fixed-step (step > 0) or adaptive.
std::string too_many_steps(Method m, std::size_t max_steps, double t_end, double step) {
  std::ostringstream os;
  os << method_name(m);
  if (step > 0.0) os << " with step " << format_number(step) << " s";
  os << " needs more than " << max_steps << " steps to reach t = " << format_number(t_end) << " s; "
     << (step > 0.0 ? "lengthen the step" : "loosen the tolerance") << " or shorten the run";
  return os.str();
}

}  // namespace

std::string_view method_name(Method m) {
  return facts(m).name;
}

Method method_from_name(std::string_view name) {
  for (Method m : kAllMethods) {
    if (method_name(m) == name) return m;
  }
  std::string list;
  for (const MethodFacts& f : kFacts) list += (list.empty() ? "" : ", ") + std::string(f.name);
  throw std::invalid_argument("unknown method '" + std::string(name) + "'; expected one of " +
                              list);
}

bool is_adaptive(Method m) {
  return facts(m).adaptive;
}

bool takes_after_step(Method m) {
  return facts(m).after_step;
}

int fixed_step_order(Method m) {
  return facts(m).fixed_step_order;
}

std::string_view method_kind(Method m) {
  return facts(m).kind;
}

int evaluations_per_step(Method m) {
  return facts(m).evaluations_per_step;
}

double evaluation_work(Method m) {
  const bool weighty =
      m == Method::kSplitting || m == Method::kSplitting4 || m == Method::kBulirschStoer;
  return weighty ? 4.0 : 1.0;
}

namespace {
thread_local double t_work_done = 0.0;
}  // namespace

double work_done() {
  return t_work_done;
}

void detail::add_work(Method m, std::size_t evaluations) {
  t_work_done += static_cast<double>(evaluations) * evaluation_work(m);
}

void validate_run(const OdeOptions& o, const std::vector<double>& times, bool after_step) {
  if (times.empty()) throw std::invalid_argument("sample times must not be empty");
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (!std::isfinite(times[i])) throw std::invalid_argument("sample times must be finite");
    if (i > 0 && times[i] < times[i - 1])
      throw std::invalid_argument("sample times must be nondecreasing");
  }
  if (is_adaptive(o.method)) {
    const auto bad = [](double tol) { return !(tol >= 0.0 && tol < 1.0); };
    if (bad(o.abs_tol) || bad(o.rel_tol) || (o.abs_tol == 0.0 && o.rel_tol == 0.0)) {
      std::ostringstream os;
      os << method_name(o.method) << ": tolerances must lie in [0, 1) and not both be 0, got abs "
         << format_number(o.abs_tol) << ", rel " << format_number(o.rel_tol);
      throw std::invalid_argument(os.str());
    }
  } else if (!(o.step > 0.0) || !std::isfinite(o.step)) {
    std::ostringstream os;
    os << method_name(o.method) << ": step must be positive and finite, got "
       << format_number(o.step);
    throw std::invalid_argument(os.str());
  }
  if (after_step && !takes_after_step(o.method)) {
    std::string can;
    for (const MethodFacts& f : kFacts) {
      if (f.after_step) can += (can.empty() ? "" : ", ") + std::string(f.name);
    }
    throw std::invalid_argument(std::string(method_name(o.method)) +
                                " cannot apply an after-step projection: only " + can + " can");
  }
}

TotalStepCap::TotalStepCap(Method m, std::size_t max_steps, double t_end)
    : method_(m), max_steps_(max_steps), t_end_(t_end) {}

void TotalStepCap::operator()() {
  if (++steps_ > max_steps_) {
    throw std::runtime_error(too_many_steps(method_, max_steps_, t_end_, 0.0));
  }
}

namespace detail {

std::string too_many_evaluations(const OdeOptions& o) {
  std::ostringstream os;
  os << method_name(o.method) << " needs more than "
     << format_number(static_cast<double>(o.max_evaluations))
     << " right-hand-side evaluations, the budget of a run; "
     << (is_adaptive(o.method) ? "loosen the tolerance" : "lengthen the step")
     << " or shorten the run";
  return os.str();
}

std::vector<GridSample> plan_grid(const std::vector<double>& times, const OdeOptions& o) {
  validate_run(o, times);
  if (is_adaptive(o.method)) {
    throw std::invalid_argument(std::string(method_name(o.method)) +
                                " is error-controlled: it has no step grid");
  }
  const double t0 = times.front(), h = o.step;
  const auto grid = [&](std::size_t n) { return t0 + static_cast<double>(n) * h; };
  std::vector<GridSample> plan;
  plan.reserve(times.size());
  std::size_t n = 0, steps = 0;
  double t_prev = t0;
  for (const double ts : times) {
    // at least floor((ts - t0) / h) steps: refuse a hopeless run before the cast
    const double whole = std::floor((ts - t0) / h);
    if (whole > static_cast<double>(o.max_steps)) {
      throw std::invalid_argument(too_many_steps(o.method, o.max_steps, times.back(), h));
    }
    // A time within a few ulps of a grid point is that grid point: sample times
    // computed another way (t0 + (t1 - t0) i / n) must not cost a roundoff-sized step.
    const double snap =
        8.0 * std::numeric_limits<double>::epsilon() * (std::abs(t0) + std::abs(ts));
    GridSample s{static_cast<std::size_t>(whole), false};
    if (std::abs(grid(s.n + 1) - ts) <= snap) {
      s = {s.n + 1, true};
    } else if (std::abs(grid(s.n) - ts) <= snap) {
      s.on_grid = true;
    } else if (s.n > 0 && grid(s.n) > ts) {
      --s.n;  // the quotient rounded up to the next integer
    }
    s.n = std::max(s.n, n);
    steps += (s.n - n) + (!s.on_grid && ts != t_prev ? 1 : 0);
    n = s.n;
    t_prev = ts;
    plan.push_back(s);
  }
  if (steps > o.max_steps) {
    throw std::invalid_argument(too_many_steps(o.method, o.max_steps, times.back(), h));
  }
  return plan;
}

}  // namespace detail

}  // namespace rigid
