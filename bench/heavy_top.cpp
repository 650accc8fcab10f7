// bench_heavy_top: run time against error for the heavy symmetric top,
// in one run, on two problems:
//  - "top_text": section 8.1's top (a 2.00 kg disk of radius 5 cm, 4 cm above the
//    tip, g = 9.8) at 500 rpm released from rest at 30 deg;
//  - "top_fast": Simo & Wong's fast top (I = 5, Is = 1 about the pivot, m g l =
//    20, S = 50, theta0 = 0.05 rad, released from rest);
// each to t_end = 20 nutation periods, the error |theta(t_end) - theta_exact|
// against rigid::HeavyTopExact. Every rigidlab method (rigid::integrate of a
// HeavyTopProblem) beside Boost.Odeint with std::vector state and GSL
// gsl_odeiv2_driver on the same seven equations (omega_body with the gravity
// torque, the attitude quaternion);
// and the cost of one exact theta sample beside one gsl_sf_elljac_e call.
// Writes OUT_DIR/heavy_top.json (entries for the report) and
// OUT_DIR/heavy_top_reference.json (for scipy_heavy_top.py).
//
// Usage: bench_heavy_top [OUT_DIR] [--quick] [--verbose] [--quiet]
#include "rigid/heavy_top.h"

#include <algorithm>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "entries.h"
#include "output.h"
#include "rigid/heavy_top_integrate.h"
#include "timing.h"

#ifdef RIGID_BENCH_HAVE_GSL
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_sf_elljac.h>
#endif

namespace {

using Json = nlohmann::ordered_json;
namespace odeint = boost::numeric::odeint;
constexpr double kMaxRunSeconds = 1.0;

struct TopProblem {
  std::string name, title;
  rigid::HeavyTop top;
  rigid::TopStart start;
  double t_end = 0.0;  // set from the nutation period
};

std::vector<TopProblem> problems() {
  const double I = 0.25 * 2.0 * 0.05 * 0.05 + 2.0 * 0.04 * 0.04, Is = 0.5 * 2.0 * 0.05 * 0.05;
  return {
      {"top_text",
       "section 8.1's top: 500 rpm, released at 30\\deg, 20 nutation periods",
       {I, Is, 2.0 * 9.8 * 0.04},
       {M_PI / 6, 0.0, 0.0, 500.0 * 2 * M_PI / 60}},
      {"top_fast",
       "Simo-Wong fast top: I = 5, I_s = 1, mgl = 20, S = 50, \\theta_0 = 0.05, "
       "20 nutation periods",
       {5.0, 1.0, 20.0},
       {0.05, 0.0, 0.0, 50.0}},
  };
}

struct RunResult {
  rigid::RotationState x{};
  long long steps = 0;
  long long evaluations = 0;  ///< right-hand-side evaluations (a counter in the system)
};

// The heavy top written the way a user writes it for odeint: std::vector state.
struct VectorTopRhs {
  double I, Is, mgl;
  long long* evaluations;  // counted for the report's cost column
  void operator()(const std::vector<double>& x, std::vector<double>& dxdt, double /*t*/) const {
    ++*evaluations;
    const double w1 = x[0], w2 = x[1], w3 = x[2], qw = x[3], qx = x[4], qy = x[5], qz = x[6];
    const double n2 = qw * qw + qx * qx + qy * qy + qz * qz;
    const double ux = 2 * (qx * qz - qw * qy) / n2, uy = 2 * (qy * qz + qw * qx) / n2;
    dxdt[0] = (mgl * uy - w2 * w3 * (Is - I)) / I;
    dxdt[1] = (-mgl * ux - w3 * w1 * (I - Is)) / I;
    dxdt[2] = 0.0;
    dxdt[3] = 0.5 * (-qx * w1 - qy * w2 - qz * w3);
    dxdt[4] = 0.5 * (qw * w1 + qy * w3 - qz * w2);
    dxdt[5] = 0.5 * (qw * w2 + qz * w1 - qx * w3);
    dxdt[6] = 0.5 * (qw * w3 + qx * w2 - qy * w1);
  }
};

template <class Stepper>
RunResult odeint_run(const TopProblem& p, double tol) {
  const rigid::RotationState x0 =
      rigid::heavy_top_state(rigid::HeavyTopExact(p.top, p.start).angles(0));
  std::vector<double> x(x0.begin(), x0.end());
  RunResult r;
  const auto steps = odeint::integrate_adaptive(
      odeint::make_controlled<Stepper>(tol, tol),
      VectorTopRhs{p.top.I, p.top.Is, p.top.mgl, &r.evaluations}, x, 0.0, p.t_end, 1e-3);
  std::copy(x.begin(), x.end(), r.x.begin());
  r.steps = static_cast<long long>(steps);
  return r;
}

#ifdef RIGID_BENCH_HAVE_GSL
int gsl_rhs(double t, const double y[], double f[], void* params) {
  const VectorTopRhs& rhs = *static_cast<const VectorTopRhs*>(params);
  std::vector<double> x(y, y + 7), dx(7);
  rhs(x, dx, t);
  std::copy(dx.begin(), dx.end(), f);
  return GSL_SUCCESS;
}

RunResult gsl_run(const TopProblem& p, double tol, const gsl_odeiv2_step_type* type) {
  RunResult r;
  VectorTopRhs rhs{p.top.I, p.top.Is, p.top.mgl, &r.evaluations};
  gsl_odeiv2_system sys{gsl_rhs, nullptr, 7, &rhs};
  gsl_odeiv2_driver* d = gsl_odeiv2_driver_alloc_y_new(&sys, type, 1e-3, tol, tol);
  const rigid::RotationState x0 =
      rigid::heavy_top_state(rigid::HeavyTopExact(p.top, p.start).angles(0));
  r.x = x0;
  double t = 0.0;
  const int status = gsl_odeiv2_driver_apply(d, &t, p.t_end, r.x.data());
  r.steps = static_cast<long long>(d->n);
  gsl_odeiv2_driver_free(d);
  if (status != GSL_SUCCESS) throw std::runtime_error("gsl_odeiv2_driver_apply failed");
  return r;
}
#endif

RunResult rigidlab_run(const TopProblem& p, rigid::Method m, double param) {
  rigid::OdeOptions o;
  o.method = m;
  if (rigid::is_adaptive(m)) {
    o.abs_tol = o.rel_tol = param;
  } else {
    o.step = param;
  }
  const rigid::HeavyTopExact exact(p.top, p.start);
  const rigid::HeavyTopRun run = rigid::integrate(
      rigid::HeavyTopProblem(p.top), rigid::heavy_top_state(exact.angles(0)), {0.0, p.t_end}, o);
  return {run.samples.back().x, static_cast<long long>(run.steps),
          static_cast<long long>(run.evaluations)};
}

struct Solver {
  std::string name;
  bool peer = false, adaptive = true;
  int order = 0;
  std::function<RunResult(const TopProblem&, double)> run;
};

std::vector<Solver> solvers() {
  std::vector<Solver> s;
  for (const rigid::Method m : rigid::kAllMethods) {
    s.push_back({"rigidlab:" + std::string(rigid::method_name(m)), false, rigid::is_adaptive(m),
                 rigid::fixed_step_order(m),
                 [m](const TopProblem& p, double param) { return rigidlab_run(p, m, param); }});
  }
  s.push_back({"odeint:dopri5", true, true, 0,
               odeint_run<odeint::runge_kutta_dopri5<std::vector<double>>>});
  s.push_back({"odeint:rkf78", true, true, 0,
               odeint_run<odeint::runge_kutta_fehlberg78<std::vector<double>>>});
#ifdef RIGID_BENCH_HAVE_GSL
  s.push_back({"gsl:rk8pd", true, true, 0, [](const TopProblem& p, double tol) {
                 return gsl_run(p, tol, gsl_odeiv2_step_rk8pd);
               }});
  s.push_back({"gsl:rkf45", true, true, 0, [](const TopProblem& p, double tol) {
                 return gsl_run(p, tol, gsl_odeiv2_step_rkf45);
               }});
#endif
  return s;
}

struct Measurement {
  const Solver* solver = nullptr;
  double param = 0.0, seconds = 0.0, error = 0.0;
  long long steps = 0, evaluations = 0;
};

constexpr bench::TimingPolicy kRoundPolicy{0.02, 3, 0.3};

bool measure(const TopProblem& p, const Solver& s, double param, double theta_exact,
             Measurement& m) {
  m.solver = &s;
  m.param = param;
  RunResult r;
  try {
    m.seconds = bench::best_seconds([&] { r = s.run(p, param); }, kRoundPolicy);
  } catch (const std::exception& e) {
    bench::detail("  %-24s %.3g: failed (%s)\n", s.name.c_str(), param, e.what());
    return false;
  }
  m.steps = r.steps;
  m.evaluations = r.evaluations;
  m.error = std::abs(rigid::tilt_of(rigid::attitude(r.x).normalized()) - theta_exact);
  return std::isfinite(m.error);
}

void sweep(const TopProblem& p, const Solver& s, double theta_exact, double nutation_period,
           bool quick, std::vector<Measurement>& out) {
  Measurement m;
  if (s.adaptive) {
    for (int k = 3; k <= (quick ? 9 : 13); ++k) {
      if (!measure(p, s, std::pow(10.0, -k), theta_exact, m)) break;
      out.push_back(m);
      if (m.seconds * 1.6 > kMaxRunSeconds) break;
    }
    return;
  }
  // Fixed steps from a quarter of the nutation period down by 10^(-1/order): the
  // splittings follow the spin exactly, so their error is set by the slower
  // nodding and they take steps far longer than 1/|omega|; a step too long for
  // a method (it blows up, or misses by more than 0.1 rad) is skipped, not the end.
  const double ratio = std::pow(10.0, -1.0 / s.order);
  double h = 0.25 * nutation_period;
  double previous = INFINITY;
  int stalls = 0;
  bool any = false;
  for (int k = 0; k < (quick ? 14 : 40); ++k, h *= ratio) {
    if (!measure(p, s, h, theta_exact, m) || m.error > 0.1) {
      if (any) break;
      continue;
    }
    any = true;
    out.push_back(m);
    if (m.error < 1e-13 || m.seconds / ratio > kMaxRunSeconds) break;
    stalls = m.error > 0.5 * previous ? stalls + 1 : 0;
    if (stalls >= 2) break;
    previous = m.error;
  }
}

// Every solver's sweep on problem p, timed in rounds: an entry a measurement.
void work_precision_entries(const TopProblem& p, const std::vector<Solver>& all,
                            const rigid::HeavyTopExact& exact, double theta_exact, int rounds,
                            bool quick, const std::function<void(const std::string&)>& tick,
                            Json& entries) {
  std::vector<Measurement> ms;
  bench::measure_in_rounds<Solver, Measurement>(
      all, ms, rounds,
      [&](const Solver& s) { sweep(p, s, theta_exact, exact.nutation_period(), quick, ms); },
      [&](const Measurement& m) {
        Measurement again;
        return measure(p, *m.solver, m.param, theta_exact, again) ? again.seconds : -1.0;
      },
      [&](const std::string& what) { tick(p.name + ", " + what); });
  for (const Measurement& m : ms) {
    bench::detail("  %-24s %s %-9.3g theta error %-9.2e %9.3f ms %9lld steps\n",
                  m.solver->name.c_str(), m.solver->adaptive ? "tol" : "h  ", m.param, m.error,
                  m.seconds * 1e3, m.steps);
    Json e;
    e["group"] = "work_precision";
    e["problem"] = p.name;
    e["solver"] = m.solver->name;
    e["peer"] = m.solver->peer;
    e[m.solver->adaptive ? "tolerance" : "step"] = m.param;
    e["error"] = m.error;
    e["seconds"] = m.seconds;
    e["steps"] = m.steps;
    e["evaluations"] = m.evaluations;
    entries.push_back(e);
  }
}

void elliptic_entries(const TopProblem& p, const rigid::HeavyTopExact& exact, Json& entries) {
  // One exact theta sample against one gsl_sf_elljac_e call at the same k^2.
  constexpr int kSamples = 1 << 14;
  const double dt = p.t_end / kSamples;
  const bench::TimingPolicy policy{0.05, 5, 0.5};
  const auto add = [&](const char* tool, const char* what, double seconds) {
    entries.push_back(bench::elliptic_entry(p.name, tool, what, seconds, kSamples));
  };
  add("rigidlab", "theta",
      bench::best_sum_seconds(
          kSamples, [&](int i) { return exact.theta(i * dt); }, policy));
  add("rigidlab", "theta+phi+psi",
      bench::best_sum_seconds(
          kSamples,
          [&](int i) {
            const rigid::TopAngles a = exact.angles(i * dt);
            return a.theta + a.phi + a.psi;
          },
          policy));
#ifdef RIGID_BENCH_HAVE_GSL
  const double m2 = (exact.u2() - exact.u1()) / (exact.u3() - exact.u1());
  const double du = 2 * M_PI / kSamples * 20;  // about as many periods as the samples cover
  add("gsl", "elljac",
      bench::best_sum_seconds(
          kSamples,
          [&](int i) {
            double s, c, d;
            gsl_sf_elljac_e(i * du, m2, &s, &c, &d);
            return s + c + d;
          },
          policy));
#endif
}

void write_json(const std::filesystem::path& path, const Json& j) {
  const auto tmp = path.string() + ".tmp";
  std::ofstream(tmp) << j.dump(1) << "\n";
  std::filesystem::rename(tmp, path);
}

}  // namespace

int main(int argc, char** argv) {
  bench::Arguments args;
  if (const int status = bench::parse_arguments(
          argc, argv, "bench_heavy_top",
          "run time against error on the heavy top (section 8.1 and a fast top) beside "
          "Boost.Odeint and GSL, and the cost of an exact sample, written as JSON into DIR",
          args);
      status >= 0) {
    return status;
  }
  const std::filesystem::path dir = args.dir;
  const bool quick = args.quick;
  // the work, counted for the progress line: each problem's solver sweeps, their
  // later timing rounds, and the elliptic functions
  const std::vector<TopProblem> all_problems = problems();
  const std::vector<Solver> all = solvers();
  const int rounds = quick ? 1 : 3;
  rigid::support::Progress progress(
      "bench heavy_top", "parts",
      static_cast<int>(all_problems.size()) * (rounds * static_cast<int>(all.size()) + 1),
      bench::output().quiet);
  int done = 0;
  const auto tick = [&](const std::string& now) { progress.update(++done, now); };
  Json entries = Json::array(), ref;
  ref["problems"] = Json::array();
  for (TopProblem p : all_problems) {
    const rigid::HeavyTopExact exact(p.top, p.start);
    p.t_end = 20 * exact.nutation_period();
    const double theta_exact = exact.theta(p.t_end);
    const rigid::RotationState x0 = rigid::heavy_top_state(exact.angles(0));
    bench::detail("heavy top work-precision, problem %s (t_end = %g s)\n", p.name.c_str(), p.t_end);
    entries.push_back({{"group", "problem"}, {"problem", p.name}, {"title", p.title}});
    ref["problems"].push_back({{"name", p.name},
                               {"I", p.top.I},
                               {"Is", p.top.Is},
                               {"mgl", p.top.mgl},
                               {"x0", x0},
                               {"t_end", p.t_end},
                               {"theta_end", theta_exact}});
    work_precision_entries(p, all, exact, theta_exact, rounds, quick, tick, entries);
    elliptic_entries(p, exact, entries);
    std::fflush(stdout);
    tick(p.name + ", elliptic functions");
  }
  write_json(dir / "heavy_top.json", entries);
  write_json(dir / "heavy_top_reference.json", ref);
  progress.finish(fmt::format("{} problems, {} solvers: {} entries in {}; wrote {}",
                              all_problems.size(), all.size(), entries.size(),
                              rigid::support::Progress::duration(progress.seconds()),
                              (dir / "heavy_top.json").string()));
  return 0;
}
