// bench_work_precision: run time against error for the torque-free rigid body,
// in one run:
//  - every rigidlab integrator through rigid::integrate (FreeBodyProblem), and the
//    peers of peers.h, on the two problems of problems.h, scored at t_end
//    against the exact solution rigid::FreeBodyExact;
//  - the cost of one sample of the exact solution beside GSL's and
//    Boost.Math's Jacobi elliptic functions;
//  - the splittings' invariants: |L| after 10^6 steps, and the energy error's
//    maximum over one polhode period against ten;
//  - each Verner pair under the PI controller and under odeint's default one,
//    on the same stepper: steps, rejections, evaluations, error and time.
// Writes OUT_DIR/work_precision.json (an array of entries, merged into
// results.json by the bench target) and OUT_DIR/reference.json (the exact end
// states, for scipy_work_precision.py).
//
// Usage: bench_work_precision [OUT_DIR] [--quick] [--verbose] [--quiet]
#include <algorithm>
#include <boost/math/policies/policy.hpp>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "entries.h"
#include "output.h"
#include "peers.h"
#include "problems.h"
#include "rigid/free_body_exact.h"
#include "rigid/free_body_integrate.h"
#include "rigid/ode.h"
#include "rigid/splitting.h"
#include "rigid/verner.h"
#include "timing.h"

namespace {

using Json = nlohmann::ordered_json;
using bench::Problem;
using bench::RunResult;

constexpr rigid::MomentsRule kRule = rigid::MomentsRule::kPositiveOnly;  // HLW breaks I2+I3 >= I1

// Stop a solver's sweep once one run costs this much: tighter settings cost more.
constexpr double kMaxRunSeconds = 1.0;

struct Settings {
  bool quick = false;
};

// Timing rounds over every setting (the first is the sweep itself).
int rounds(const Settings& cfg) {
  return cfg.quick ? 1 : 3;
}

// The work, counted for the progress line: per problem its reference, each solver's
// sweep and later rounds, the four controller comparisons, elliptic functions and
// invariants.
int units_per_problem(std::size_t solvers, const Settings& cfg) {
  return 1 + rounds(cfg) * static_cast<int>(solvers) + 4 + 2;
}

// One rigidlab run through the core's integrate API: the state at t_end.
RunResult rigidlab_run(const Problem& p, rigid::Method m, double param, bool project = false) {
  rigid::OdeOptions o;
  o.method = m;
  o.project_invariants = project;
  if (rigid::is_adaptive(m)) {
    o.abs_tol = o.rel_tol = param;
  } else {
    o.step = param;
  }
  const rigid::FreeBodyRun r =
      rigid::integrate(rigid::FreeBodyProblem(p.I, kRule), p.initial_state(), {0.0, p.t_end}, o);
  return {r.samples.back().x, static_cast<long long>(r.steps),
          static_cast<long long>(r.evaluations)};
}

struct Solver {
  std::string name;
  bool peer = false;
  bool adaptive = true;
  int order = 0;  // fixed-step methods: sets the step ratio between points
  std::function<RunResult(const Problem&, double)> run;
};

std::vector<Solver> solvers() {
  std::vector<Solver> s;
  for (rigid::Method m : rigid::kAllMethods) {
    s.push_back({"rigidlab:" + std::string(rigid::method_name(m)), false, rigid::is_adaptive(m),
                 rigid::fixed_step_order(m),
                 [m](const Problem& p, double param) { return rigidlab_run(p, m, param); }});
  }
  // The same methods with omega projected back onto T and |L| after each step.
  for (rigid::Method m : {rigid::Method::kRk4, rigid::Method::kRkf78, rigid::Method::kVern7,
                          rigid::Method::kVern8, rigid::Method::kVern9}) {
    s.push_back({"rigidlab:" + std::string(rigid::method_name(m)) + "+proj", false,
                 rigid::is_adaptive(m), rigid::fixed_step_order(m),
                 [m](const Problem& p, double param) { return rigidlab_run(p, m, param, true); }});
  }
  s.push_back({"odeint:dopri5", true, true, 0, bench::odeint_vector_dopri5});
  s.push_back({"odeint:rkf78", true, true, 0, bench::odeint_vector_rkf78});
#ifdef RIGID_BENCH_HAVE_GSL
  s.push_back({"gsl:rk8pd", true, true, 0, bench::gsl_rk8pd});
  s.push_back({"gsl:rkf45", true, true, 0, bench::gsl_rkf45});
#endif
  return s;
}

Json vec(const Eigen::Vector3d& v) {
  return Json::array({v.x(), v.y(), v.z()});
}

// One measured setting of one solver.
struct Measurement {
  const Solver* solver = nullptr;
  double param = 0.0;
  RunResult result;
  double seconds = 0.0;
  double error = 0.0;
};

// Best of a few repeats within one round; rounds are taken apart in time.
constexpr bench::TimingPolicy kRoundPolicy{0.02, 3, 0.3};

// Runs and times one setting; false if the solver failed.
bool measure(const Problem& p, const Solver& s, double param, const rigid::RotationState& exact,
             Measurement& m) {
  m.solver = &s;
  m.param = param;
  try {
    m.seconds = bench::best_seconds([&] { m.result = s.run(p, param); }, kRoundPolicy);
  } catch (const std::exception& e) {
    bench::detail("  %-24s %s %.3g: failed (%s)\n", s.name.c_str(), s.adaptive ? "tol" : "h", param,
                  e.what());
    return false;
  }
  m.error = bench::omega_error(m.result.x, exact);
  return std::isfinite(m.error);
}

Json entry(const Problem& p, const Measurement& m, const rigid::RotationState& exact) {
  const Solver& s = *m.solver;
  const double att = bench::attitude_error(m.result.x, exact);
  bench::detail("  %-24s %s %-9.3g error %-9.2e attitude %-9.2e %9.3f ms %9lld steps\n",
                s.name.c_str(), s.adaptive ? "tol" : "h  ", m.param, m.error, att, m.seconds * 1e3,
                m.result.steps);
  Json e;
  e["group"] = "work_precision";
  e["problem"] = p.name;
  e["solver"] = s.name;
  e["peer"] = s.peer;
  e[s.adaptive ? "tolerance" : "step"] = m.param;
  e["error"] = m.error;
  e["attitude_error"] = att;
  e["seconds"] = m.seconds;
  e["steps"] = m.result.steps;
  e["evaluations"] = m.result.evaluations;
  return e;
}

// The settings of one solver's sweep, measured once (the first round).
void sweep(const Problem& p, const Solver& s, const rigid::RotationState& exact,
           const Settings& cfg, std::vector<Measurement>& out) {
  Measurement m;
  if (s.adaptive) {
    // tolerances 1e-3 .. 1e-13, one per decade; stop when the next would cost too much
    const double growth = 1.6;  // typical cost per decade of tolerance at order 5..8
    for (int k = 3; k <= (cfg.quick ? 9 : 13); ++k) {
      if (!measure(p, s, std::pow(10.0, -k), exact, m)) break;
      out.push_back(m);
      if (m.seconds * growth > kMaxRunSeconds) break;
    }
    return;
  }
  // fixed step: from about 1/2 rad of rotation per step (1/10 for order 2) down by
  // 10^(-1/order), each point about a decade of error better, until roundoff
  // (1e-13), an error floor, or the predicted cost of the next point passes the cap
  const double ratio = std::pow(10.0, -1.0 / s.order);
  double h = (s.order == 2 ? 0.1 : 0.5) / p.omega0_body().norm();
  double prev_error = INFINITY;
  int stalls = 0;
  for (int k = 0; k < (cfg.quick ? 6 : 16); ++k, h *= ratio) {
    if (!measure(p, s, h, exact, m)) break;
    out.push_back(m);
    if (m.error < 1e-13 || m.seconds / ratio > kMaxRunSeconds) break;
    stalls = m.error > 0.5 * prev_error ? stalls + 1 : 0;
    if (stalls >= 2) break;  // roundoff floor reached
    prev_error = m.error;
  }
}

void work_precision(const Problem& p, const std::vector<Solver>& all,
                    const rigid::RotationState& exact, const Settings& cfg, Json& out,
                    const std::function<void(const std::string&)>& tick) {
  std::vector<Measurement> ms;
  bench::measure_in_rounds<Solver, Measurement>(
      all, ms, rounds(cfg), [&](const Solver& s) { sweep(p, s, exact, cfg, ms); },
      [&](const Measurement& m) {
        Measurement again;
        return measure(p, *m.solver, m.param, exact, again) ? again.seconds : -1.0;
      },
      [&](const std::string& what) { tick(p.name + ", " + what); });
  for (const Measurement& m : ms) out.push_back(entry(p, m, exact));
  std::fflush(stdout);
}

// The exact end state, cross-checked against a very tight rkf78 run.
rigid::RotationState reference(const Problem& p, const rigid::FreeBodyExact& exact, Json& out) {
  const rigid::RotationState x = exact.state(p.t_end);
  const double tol = 1e-15;
  const RunResult r = rigidlab_run(p, rigid::Method::kRkf78, tol);
  Json e;
  e["group"] = "reference";
  e["problem"] = p.name;
  e["check"] = "FreeBodyExact vs rigidlab:rkf78 at tol 1e-15";
  e["omega_diff"] = bench::omega_error(r.x, x);
  e["attitude_diff"] = bench::attitude_error(r.x, x);
  e["polhode_period"] = exact.period();
  e["k2"] = 1.0 - exact.complementary_parameter();
  bench::detail(
      "%s: exact vs rkf78(1e-15) at t_end: omega %.2e, attitude %.2e rad; T = %.6g s, "
      "k'^2 = %.3e\n",
      p.name.c_str(), e["omega_diff"].get<double>(), e["attitude_diff"].get<double>(),
      exact.period(), exact.complementary_parameter());
  out.push_back(e);

  // and against an integration in long double, which sits below double's roundoff
  const rigid::RotationState xl = bench::long_double_rkf78(p, 1e-17);
  Json l;
  l["group"] = "reference";
  l["problem"] = p.name;
  l["check"] = "FreeBodyExact vs long-double odeint rkf78 at tol 1e-17";
  l["omega_diff"] = bench::omega_error(xl, x);
  l["attitude_diff"] = bench::attitude_error(xl, x);
  bench::detail("%s: exact vs long-double rkf78(1e-17): omega %.2e, attitude %.2e rad\n",
                p.name.c_str(), l["omega_diff"].get<double>(), l["attitude_diff"].get<double>());
  out.push_back(l);
  return x;
}

// Cost per sample of the exact solution and of the peers' elliptic functions.
void elliptic(const Problem& p, const rigid::FreeBodyExact& exact, Json& out) {
  constexpr int kSamples = 1 << 14;
  const double dt = p.t_end / kSamples;
  const double kp2 = exact.complementary_parameter(), m = 1.0 - kp2, k = std::sqrt(m);
  // the same number of quarter periods in u as the omega samples cover in t
  const double K = boost::math::ellint_1(k);
  const double periods = std::isfinite(exact.period()) ? p.t_end / exact.period() : 4.0;
  const double du = periods * 4.0 * K / kSamples;
  const bench::TimingPolicy policy{0.05, 5, 0.5};

  const auto add = [&](const char* tool, const char* what, double seconds) {
    Json e = bench::elliptic_entry(p.name, tool, what, seconds, kSamples);
    e["k2"] = m;
    out.push_back(e);
  };
  add("rigidlab", "omega",
      bench::best_sum_seconds(
          kSamples, [&](int i) { return exact.omega_body(i * dt).sum(); }, policy));
  add("rigidlab", "omega+attitude",
      bench::best_sum_seconds(
          kSamples,
          [&](int i) {
            const rigid::RotationState x = exact.state(i * dt);
            return x[0] + x[3];
          },
          policy));
#ifdef RIGID_BENCH_HAVE_GSL
  add("gsl", "elljac",
      bench::best_seconds(
          [&] { bench::do_not_optimize(bench::gsl_elljac_sum(0.0, du, kSamples, m)); }, policy));
#endif
  add("boost-default", "jacobi_elliptic",
      bench::best_sum_seconds(
          kSamples,
          [&](int i) {
            double cn, dn;
            return boost::math::jacobi_elliptic(k, i * du, &cn, &dn) + cn + dn;
          },
          policy));
  using NoPromote = boost::math::policies::policy<boost::math::policies::promote_double<false>>;
  add("boost-nopromote", "jacobi_elliptic",
      bench::best_sum_seconds(
          kSamples,
          [&](int i) {
            double cn, dn;
            return boost::math::jacobi_elliptic(k, i * du, &cn, &dn, NoPromote()) + cn + dn;
          },
          policy));
}

// One run of a Verner pair under a step controller, directly on the free body's
// right-hand side (the same starting step for every controller).
template <class Tableau, class Adjuster>
Json controller_run(const Problem& p, const rigid::RotationState& exact, double tol,
                    const char* controller, Adjuster adjuster) {
  namespace odeint = boost::numeric::odeint;
  long long evaluations = 0;
  std::size_t steps = 0, rejected = 0;
  rigid::RotationState x;
  const rigid::EulerRhs rhs{p.I};
  const auto counted = [&](const rigid::RotationState& xs, rigid::RotationState& d, double t) {
    ++evaluations;
    rhs(xs, d, t);
  };
  rigid::OdeOptions o;
  o.abs_tol = o.rel_tol = tol;
  const double dt0 =
      rigid::detail::starting_step(rhs, p.initial_state(), 0.0, p.t_end, Tableau::kOrder, o);
  const std::vector<double> times = {0.0, p.t_end};
  const double seconds = bench::best_seconds(
      [&] {
        rigid::VernerDenseOutput<Tableau, rigid::RotationState, Adjuster> stepper(tol, tol,
                                                                                  adjuster);
        evaluations = 0;
        x = p.initial_state();
        steps = odeint::integrate_times(std::ref(stepper), counted, x, times.begin(), times.end(),
                                        dt0, [](const auto&, double) {});
        rejected = stepper.rejected_steps();
      },
      kRoundPolicy);
  Json e;
  e["group"] = "controller";
  e["problem"] = p.name;
  e["method"] = std::string("vern") + std::to_string(Tableau::kOrder);
  e["controller"] = controller;
  e["tolerance"] = tol;
  e["steps"] = steps;
  e["rejected"] = rejected;
  e["evaluations"] = evaluations;
  e["error"] = bench::omega_error(x, exact);
  e["seconds"] = seconds;
  bench::detail(
      "  %-6s %-15s tol %-7.0e %6zu steps %5zu rejected %7lld evaluations error %.2e %8.3f ms\n",
      e["method"].get<std::string>().c_str(), controller, tol, steps, rejected, evaluations,
      e["error"].get<double>(), seconds * 1e3);
  return e;
}

// The PI controller against odeint's default one on the same stepper.
template <class Tableau>
void controllers(const Problem& p, const rigid::RotationState& exact, Json& out) {
  namespace odeint = boost::numeric::odeint;
  for (int k = 4; k <= 12; k += 2) {
    const double tol = std::pow(10.0, -k);
    out.push_back(
        controller_run<Tableau>(p, exact, tol, "PI", rigid::PiStepAdjuster(Tableau::kErrorOrder)));
    out.push_back(controller_run<Tableau>(p, exact, tol, "odeint default",
                                          odeint::default_step_adjuster<double, double>()));
  }
}

// The splittings' invariants: |L| after 10^6 steps; energy error over [0, T] vs [0, 10T].
void invariants(const Problem& p, const rigid::FreeBodyExact& exact, const Settings& cfg,
                Json& out) {
  const double T = exact.period();
  if (!std::isfinite(T)) return;
  const long long n_long = cfg.quick ? 100'000 : 1'000'000;
  for (rigid::Method m : {rigid::Method::kSplitting, rigid::Method::kSplitting4}) {
    rigid::OdeOptions o;
    o.method = m;
    const rigid::FreeBodyProblem problem(p.I, kRule);
    // about 100 (order 2) or 50 (order 4) steps per polhode period: the energy
    // error is then well above roundoff, so its growth (or not) is visible
    const int per_period = m == rigid::Method::kSplitting ? 100 : 50;
    o.step = T / per_period;

    // |L| after 10^6 steps (relative change, end against start)
    const auto long_run = rigid::integrate(problem, p.initial_state(), {0.0, n_long * o.step}, o);
    const double L0 = exact.angular_momentum_magnitude();
    const Eigen::Vector3d w_end = rigid::omega_body(long_run.samples.back().x);
    const double dL = std::abs(rigid::angular_momentum_magnitude(p.I, w_end) - L0) / L0;

    // energy error at every step over one period and over ten
    const auto energy_max = [&](int periods) {
      const auto times = rigid::uniform_times(0.0, periods * T,
                                              static_cast<std::size_t>(periods) * per_period + 1);
      return rigid::integrate(problem, p.initial_state(), times, o)
          .max_invariant_error[rigid::FreeBodyProblem::kEnergy];
    };
    const double e1 = energy_max(1), e10 = energy_max(10);

    Json e;
    e["group"] = "invariants";
    e["problem"] = p.name;
    e["solver"] = "rigidlab:" + std::string(rigid::method_name(m));
    e["step"] = o.step;
    e["steps"] = static_cast<long long>(long_run.steps);
    e["L_rel_change"] = dL;
    e["L_rel_drift_max"] = long_run.max_invariant_error[rigid::FreeBodyProblem::kMomentum];
    e["polhode_period"] = T;
    e["energy_err_max_T"] = e1;
    e["energy_err_max_10T"] = e10;
    bench::detail(
        "  %-22s h = T/%d: |L| change after %lld steps %.2e; max |dE|/E [0,T] %.2e, "
        "[0,10T] %.2e (x%.2f)\n",
        e["solver"].get<std::string>().c_str(), per_period, static_cast<long long>(long_run.steps),
        dL, e1, e10, e10 / e1);
    out.push_back(e);

    // the bare LiePoissonSplitting::step for comparison: the free body's run projects
    // L back onto |L| = |L0| after each step, the class alone does not
    const rigid::LiePoissonSplitting split(p.I, rigid::fixed_step_order(m));
    Eigen::Vector3d L = p.L0_body;
    Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
    for (long long i = 0; i < n_long; ++i) split.step(L, q, o.step);
    Json raw;
    raw["group"] = "invariants";
    raw["problem"] = p.name;
    raw["solver"] =
        "LiePoissonSplitting::step, order " + std::to_string(split.order()) + " (no projection)";
    raw["target"] = false;
    raw["step"] = o.step;
    raw["steps"] = n_long;
    raw["L_rel_change"] = std::abs(L.norm() - p.L0_body.norm()) / p.L0_body.norm();
    raw["quaternion_norm_change"] = std::abs(q.norm() - 1.0);
    bench::detail("  %-22s |L| change after %lld steps %.2e, |q| - 1 %.2e\n",
                  raw["solver"].get<std::string>().c_str(), n_long,
                  raw["L_rel_change"].get<double>(), raw["quaternion_norm_change"].get<double>());
    out.push_back(raw);
  }
}

// Problem p as the report titles it (an entry of group "problem") and as the SciPy run
// starts from it (reference.json), with its exact end state.
void describe(const Problem& p, const rigid::FreeBodyExact& exact,
              const rigid::RotationState& x_end, Json& entries, Json& ref) {
  Json desc;
  desc["group"] = "problem";
  desc["problem"] = p.name;
  desc["title"] = p.title;
  desc["I"] = vec(p.I.vector());
  desc["L0_body"] = vec(p.L0_body);
  desc["t_end"] = p.t_end;
  desc["polhode_period"] = exact.period();
  entries.push_back(desc);
  Json jp;
  jp["name"] = p.name;
  jp["I"] = vec(p.I.vector());
  jp["L0_body"] = vec(p.L0_body);
  jp["omega0_body"] = vec(p.omega0_body());
  jp["t_end"] = p.t_end;
  jp["state_end"] = Json(std::vector<double>(x_end.begin(), x_end.end()));
  jp["polhode_period"] = exact.period();
  ref["problems"].push_back(jp);
}

void write_json(const std::filesystem::path& path, const Json& j) {
  const std::filesystem::path tmp = path.string() + ".tmp";
  {
    std::ofstream f(tmp);
    f << j.dump(1) << "\n";
    if (!f) throw std::runtime_error("cannot write " + tmp.string());
  }
  std::filesystem::rename(tmp, path);
}

}  // namespace

int main(int argc, char** argv) {
  bench::Arguments args;
  if (const int status =
          bench::parse_arguments(argc, argv, "bench_work_precision",
                                 "run time against error of every free-body integrator and its "
                                 "peers (Boost.Odeint, GSL, SciPy), written as JSON into DIR",
                                 args);
      status >= 0) {
    return status;
  }
  const std::filesystem::path dir = args.dir;
  Settings cfg;
  cfg.quick = args.quick;
  std::filesystem::create_directories(dir);
  const std::vector<Solver> all_solvers = solvers();
  const std::vector<Problem> problems = bench::problems();
  rigid::support::Progress progress(
      "bench work_precision", "parts",
      static_cast<int>(problems.size()) * units_per_problem(all_solvers.size(), cfg),
      bench::output().quiet);
  int done = 0;
  const auto tick = [&](const std::string& now) { progress.update(++done, now); };

  Json entries = Json::array(), ref;
  ref["note"] =
      "exact end states from rigid::FreeBodyExact; state = omega_body, then the "
      "body-to-space quaternion (w, x, y, z); initial attitude identity";
  std::vector<std::pair<Problem, rigid::RotationState>> exact_ends;
  for (const Problem& p : problems) {
    const rigid::FreeBodyExact exact(p.I, p.omega0_body(), Eigen::Quaterniond::Identity(), kRule);
    const rigid::RotationState x_end = reference(p, exact, entries);
    exact_ends.push_back({p, x_end});
    tick(p.name + ", reference");
    describe(p, exact, x_end, entries, ref);
  }
  // the reference first, so the SciPy run can start from it whatever happens below
  write_json(dir / "reference.json", ref);

  for (const auto& [p, x_end] : exact_ends) {
    bench::detail("work-precision, problem %s (t_end = %g s)\n", p.name.c_str(), p.t_end);
    work_precision(p, all_solvers, x_end, cfg, entries, tick);
  }
  for (const auto& [p, x_end] : exact_ends) {
    bench::detail("step controllers, problem %s\n", p.name.c_str());
    controllers<rigid::verner::Vern6>(p, x_end, entries);
    tick(p.name + ", controllers vern6");
    controllers<rigid::verner::Vern7>(p, x_end, entries);
    tick(p.name + ", controllers vern7");
    controllers<rigid::verner::Vern8>(p, x_end, entries);
    tick(p.name + ", controllers vern8");
    controllers<rigid::verner::Vern9>(p, x_end, entries);
    tick(p.name + ", controllers vern9");
  }
  for (const Problem& p : problems) {
    const rigid::FreeBodyExact exact(p.I, p.omega0_body(), Eigen::Quaterniond::Identity(), kRule);
    bench::detail("elliptic functions, problem %s (k^2 = %.12g)\n", p.name.c_str(),
                  1.0 - exact.complementary_parameter());
    elliptic(p, exact, entries);
    tick(p.name + ", elliptic functions");
    bench::detail("splitting invariants, problem %s\n", p.name.c_str());
    invariants(p, exact, cfg, entries);
    tick(p.name + ", invariants");
  }
  write_json(dir / "work_precision.json", entries);
  progress.finish(fmt::format("{} problems, {} solvers: {} entries in {}; wrote {}",
                              problems.size(), all_solvers.size(), entries.size(),
                              rigid::support::Progress::duration(progress.seconds()),
                              (dir / "work_precision.json").string()));
  return 0;
}
