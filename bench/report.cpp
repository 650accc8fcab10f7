// bench_report: merges the parts every benchmark wrote, DIR/<name>.json (each a
// JSON array of entries), into DIR/results.json, and turns that into
// DIR/results.md (work-precision tables at fixed error levels, the
// elliptic-function and invariants tables, the figure-speed tables, the issue-3
// and issue-4 targets met or not, and a generic table for any other group),
// drawing one work-precision diagram per problem with rigid::render when it is
// built.
//
// Usage: bench_report DIR
//
// "Time to reach an error level": for each solver its measurements are
// ordered from the loosest tolerance (or largest step) to the tightest, and
// log(seconds) is interpolated linearly in log(error) between the two
// neighbouring measurements whose errors bracket the level, which is linear
// interpolation in log(tolerance) of both. A measurement already below the
// level also counts; the fastest of these candidates is the solver's time.
// Levels a solver never reaches are shown as "not reached".
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "output.h"
#ifdef RIGID_BENCH_HAVE_RENDER
#include "rigid/render/draw.h"
#include "rigid/render/plot2d.h"
#endif

namespace {

using Json = nlohmann::ordered_json;  // keeps each entry's key order for generic tables

constexpr double kLevels[] = {1e-4, 1e-6, 1e-8, 1e-10, 1e-12};

struct Point {
  double param = 0, error = 0, seconds = 0;
  long long steps = 0, evaluations = 0;
};

struct SolverCurve {
  std::string solver;
  bool peer = false;
  std::vector<Point> points;  // loosest first
};

struct Reach {
  double seconds = std::numeric_limits<double>::infinity();
  std::string solver;
  bool reached() const { return std::isfinite(seconds); }
};

double number(const Json& e, const char* key, double fallback = std::nan("")) {
  auto it = e.find(key);
  return (it != e.end() && it->is_number()) ? it->get<double>() : fallback;
}

std::string text(const Json& e, const char* key, const std::string& fallback = {}) {
  auto it = e.find(key);
  return (it != e.end() && it->is_string()) ? it->get<std::string>() : fallback;
}

// Seconds a solver needs to reach error <= level (see the header comment).
double time_to_reach(const SolverCurve& c, double level) {
  double best = std::numeric_limits<double>::infinity();
  const double ll = std::log(level);
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    const Point& a = c.points[i];
    if (a.error <= level) best = std::min(best, a.seconds);
    if (i + 1 == c.points.size()) continue;
    const Point& b = c.points[i + 1];
    const double la = std::log(a.error), lb = std::log(b.error);
    if ((la - ll) * (lb - ll) > 0 || la == lb) continue;
    const double f = (ll - la) / (lb - la);
    best = std::min(
        best, std::exp(std::log(a.seconds) + f * (std::log(b.seconds) - std::log(a.seconds))));
  }
  return best;
}

std::map<std::string, std::vector<SolverCurve>> work_precision_curves(const Json& all) {
  std::map<std::string, std::map<std::string, SolverCurve>> by_problem;
  for (const Json& e : all) {
    if (text(e, "group") != "work_precision") continue;
    const double error = number(e, "error"), seconds = number(e, "seconds");
    if (!(error > 0) || !(seconds > 0)) continue;
    const double tol = number(e, "tolerance"), step = number(e, "step");
    SolverCurve& c = by_problem[text(e, "problem")][text(e, "solver")];
    c.solver = text(e, "solver");
    c.peer = e.value("peer", false);
    c.points.push_back({std::isfinite(tol) ? tol : step, error, seconds,
                        static_cast<long long>(number(e, "steps", 0)),
                        static_cast<long long>(number(e, "evaluations", 0))});
  }
  std::map<std::string, std::vector<SolverCurve>> out;
  for (auto& [problem, solvers] : by_problem) {
    for (auto& [name, c] : solvers) {
      std::sort(c.points.begin(), c.points.end(),
                [](const Point& a, const Point& b) { return a.param > b.param; });
      out[problem].push_back(c);
    }
    // rigidlab first, then peers, each alphabetical
    std::stable_sort(out[problem].begin(), out[problem].end(),
                     [](const SolverCurve& a, const SolverCurve& b) { return a.peer < b.peer; });
  }
  return out;
}

std::string seconds_text(double s) {
  if (!std::isfinite(s)) return "not reached";
  if (s < 1e-3) return fmt::format("{:.1f} µs", s * 1e6);
  if (s < 1.0) return fmt::format("{:.2f} ms", s * 1e3);
  return fmt::format("{:.2f} s", s);
}

struct Targets {
  std::vector<std::string> lines;
  void add(bool met, const std::string& what) {
    lines.push_back(fmt::format("- **{}** {}", met ? "met" : "NOT met", what));
  }
};

// The right-hand-side evaluations of the loosest measurement of a solver that reaches
// `level` (0 if none does, or it did not count them).
long long evaluations_at(const SolverCurve& c, double level) {
  for (const Point& p : c.points)
    if (p.error <= level) return p.evaluations;
  return 0;
}

// Issue 12's target: at every level from 1e-4 down to ten times the best error any
// solver reaches on the problem, by half decades (and that floor itself), the fastest
// rigidlab solver takes at most kIssue12Ratio of the fastest peer's time; beside each
// time, the evaluations of the measurement that reached the level, to say where a gain
// or a miss comes from.
constexpr double kIssue12Ratio = 0.75;
std::string count_text(const SolverCurve* c, double level) {
  const long long n = c ? evaluations_at(*c, level) : 0;
  return n > 0 ? fmt::format("{}", n) : "—";  // SciPy's runs are not counted
}
void issue12_levels(std::ostream& md, const std::string& problem,
                    const std::vector<SolverCurve>& curves, Targets& targets) {
  double best = std::numeric_limits<double>::infinity();
  for (const SolverCurve& c : curves)
    for (const Point& p : c.points) best = std::min(best, p.error);
  if (!std::isfinite(best)) return;
  const double floor = 10.0 * best;
  std::vector<double> levels;
  for (int k = 8; std::pow(10.0, -0.5 * k) > floor * (1 + 1e-9); ++k)
    levels.push_back(std::pow(10.0, -0.5 * k));
  if (floor < 1e-4) levels.push_back(floor);
  md << fmt::format(
      "\nIssue 12: every level from 1e-4 down to ten times the best error any "
      "solver reached ({:.1e}, so {:.1e}), by half decades; evaluations of the "
      "loosest measured run that reached the level.\n\n",
      best, floor);
  md << "| error ≤ | fastest rigidlab | time | evaluations | fastest peer | time | evaluations "
        "| rigidlab / peer |\n|---|---|---|---|---|---|---|---|\n";
  double worst = 0.0;
  std::vector<std::string> misses;
  for (const double level : levels) {
    const SolverCurve *ours = nullptr, *peer = nullptr;
    double s_ours = std::numeric_limits<double>::infinity(), s_peer = s_ours;
    for (const SolverCurve& c : curves) {
      const double t = time_to_reach(c, level);
      if (c.peer ? t < s_peer : t < s_ours)
        (c.peer ? peer : ours) = &c, (c.peer ? s_peer : s_ours) = t;
    }
    const double ratio = s_ours / s_peer;
    const bool both = ours != nullptr && peer != nullptr;
    md << fmt::format("| {:.1e} | {} | {} | {} | {} | {} | {} | {} |\n", level,
                      ours ? ours->solver : "—", seconds_text(s_ours), count_text(ours, level),
                      peer ? peer->solver : "—", seconds_text(s_peer), count_text(peer, level),
                      both ? fmt::format(ratio < 0.01 ? "{:.1e}" : "{:.2f}", ratio)
                           : (ours ? "peers do not reach it" : "not reached by rigidlab"));
    if (both) worst = std::max(worst, ratio);
    if (!ours || (both && ratio > kIssue12Ratio))
      misses.push_back(
          fmt::format("{:.1e} ({})", level, both ? fmt::format("{:.2f}", ratio) : "not reached"));
  }
  targets.add(
      misses.empty(),
      fmt::format("{}: fastest rigidlab at most {:.2f}× the fastest peer at "
                  "every level 1e-4..{:.1e} (worst ratio {:.2f}{}{})",
                  problem, kIssue12Ratio, floor, worst, misses.empty() ? "" : "; missed at ",
                  fmt::format("{}", fmt::join(misses, ", "))));
}

// The PI controller against odeint's default one on the same Verner stepper: the
// time each takes to reach an error level (time_to_reach over its tolerances), and
// what its runs cost in steps, rejections and evaluations.
void controller_section(std::ostream& md, const Json& all) {
  // problem -> pair -> controller -> curve
  std::map<std::string, std::map<std::string, std::map<std::string, SolverCurve>>> curves;
  std::map<std::string, std::map<std::string, std::map<std::string, long long>>> rejected;
  for (const Json& e : all) {
    if (text(e, "group") != "controller") continue;
    SolverCurve& c = curves[text(e, "problem")][text(e, "method")][text(e, "controller")];
    c.solver = text(e, "controller");
    c.points.push_back({number(e, "tolerance"), number(e, "error"), number(e, "seconds"),
                        static_cast<long long>(number(e, "steps", 0)),
                        static_cast<long long>(number(e, "evaluations", 0))});
    rejected[text(e, "problem")][text(e, "method")][text(e, "controller")] +=
        static_cast<long long>(number(e, "rejected", 0));
  }
  if (curves.empty()) return;
  md << "\n## Step-size control: PI against odeint's default\n\n"
        "The same Verner stepper and starting step, run directly on the free body's "
        "right-hand side to t_end at tolerances 1e-4, 1e-6, .., 1e-12: rigidlab's PI "
        "controller (Gustafsson; Hairer & Wanner II, IV.2: α = 0.7/k, β = 0.4/k, factor in "
        "[0.2, 10], safety 0.9) against odeint's default_step_adjuster (grows the step only "
        "when the error is below 1/2, by at most 5×; shrinks it by err^(-1/(q-1))). At one "
        "tolerance the PI controller takes more, smaller steps and reaches a smaller error, so "
        "the two are compared at equal error: the time to reach each level (interpolated as in "
        "the work-precision tables), the steps rejected over the five runs, and the "
        "evaluations of the run at the tightest tolerance.\n\n"
        "| problem | pair | controller | rejected (5 runs) | evaluations at 1e-12 |";
  for (double level : kLevels) md << fmt::format(" {:.0e} |", level);
  md << "\n|---|---|---|---|---|";
  for (std::size_t i = 0; i < std::size(kLevels); ++i) md << "---|";
  md << "\n";
  for (auto& [problem, pairs] : curves) {
    for (auto& [pair, by] : pairs) {
      for (auto& [controller, c] : by) {
        std::sort(c.points.begin(), c.points.end(),
                  [](const Point& a, const Point& b) { return a.param > b.param; });
        md << fmt::format("| {} | {} | {} | {} | {} |", problem, pair, controller,
                          rejected[problem][pair][controller], c.points.back().evaluations);
        for (double level : kLevels) md << " " << seconds_text(time_to_reach(c, level)) << " |";
        md << "\n";
      }
      if (by.count("PI") && by.count("odeint default")) {
        md << fmt::format("| {} | {} | PI / odeint time | | |", problem, pair);
        for (double level : kLevels) {
          const double pi = time_to_reach(by["PI"], level),
                       od = time_to_reach(by["odeint default"], level);
          md << (std::isfinite(pi) && std::isfinite(od) ? fmt::format(" {:.2f} |", pi / od)
                 : std::isfinite(pi)                    ? std::string(" only PI reaches it |")
                                                        : std::string(" — |"));
        }
        md << "\n";
      }
    }
  }
}

// Table: per error level, the fastest rigidlab solver vs the fastest peer.
void work_precision_section(std::ostream& md, const std::string& problem, const std::string& title,
                            const std::vector<SolverCurve>& curves, Targets& targets) {
  std::string plain;  // the title without text.h markup
  for (char ch : title)
    if (ch != '{' && ch != '}' && ch != '\\') plain += ch;
  md << "\n## Work-precision: " << problem << "\n\n" << plain << "\n\n";
  md << "| error ≤ | fastest rigidlab | time | fastest peer | time | rigidlab / peer |\n";
  md << "|---|---|---|---|---|---|\n";
  bool all_met = true;
  std::vector<std::string> misses, unreachable;
  double worst_ratio = 0;
  for (double level : kLevels) {
    Reach ours, peer;
    for (const SolverCurve& c : curves) {
      const double s = time_to_reach(c, level);
      Reach& r = c.peer ? peer : ours;
      if (s < r.seconds) r = {s, c.solver};
    }
    const double ratio = ours.seconds / peer.seconds;
    std::string ratio_text = "—";
    if (ours.reached() && peer.reached())
      ratio_text = fmt::format("{:.2f}", ratio);
    else if (ours.reached())
      ratio_text = "peers do not reach it";
    else if (!peer.reached())
      ratio_text = "no solver reaches it";
    md << fmt::format("| {:.0e} | {} | {} | {} | {} | {} |\n", level,
                      ours.reached() ? ours.solver : "—", seconds_text(ours.seconds),
                      peer.reached() ? peer.solver : "—", seconds_text(peer.seconds), ratio_text);
    const bool met = ours.reached() && (!peer.reached() || ours.seconds <= peer.seconds);
    if (ours.reached() && peer.reached()) worst_ratio = std::max(worst_ratio, ratio);
    if (!ours.reached() && !peer.reached()) {
      // below what double precision can deliver on this problem: nobody to compare
      unreachable.push_back(fmt::format("{:.0e}", level));
      continue;
    }
    if (!met) {
      all_met = false;
      misses.push_back(fmt::format(
          "{:.0e} ({})", level,
          ours.reached() ? fmt::format("ratio {:.2f}", ratio) : std::string("not reached")));
    }
  }
  targets.add(all_met,
              fmt::format("{}: fastest rigidlab at least as fast as the fastest peer at every "
                          "level 1e-4..1e-12 (worst ratio rigidlab/peer {:.2f}{}{}{}{})",
                          problem, worst_ratio, misses.empty() ? "" : "; missed at ",
                          fmt::format("{}", fmt::join(misses, ", ")),
                          unreachable.empty() ? "" : "; reached by no solver, rigidlab or peer: ",
                          fmt::format("{}", fmt::join(unreachable, ", "))));

  issue12_levels(md, problem, curves, targets);

  // every solver at every level
  md << "\n<details><summary>every solver (time to reach each error level)</summary>\n\n";
  md << "| solver | peer |";
  for (double level : kLevels) md << fmt::format(" {:.0e} |", level);
  md << " points | best error |\n|---|---|";
  for (std::size_t i = 0; i < std::size(kLevels); ++i) md << "---|";
  md << "---|---|\n";
  for (const SolverCurve& c : curves) {
    md << "| " << c.solver << " | " << (c.peer ? "yes" : "no") << " |";
    for (double level : kLevels) md << " " << seconds_text(time_to_reach(c, level)) << " |";
    double best_error = std::numeric_limits<double>::infinity();
    for (const Point& p : c.points) best_error = std::min(best_error, p.error);
    md << fmt::format(" {} | {:.1e} |\n", c.points.size(), best_error);
  }
  md << "\n</details>\n";
}

#ifdef RIGID_BENCH_HAVE_RENDER
namespace rr = rigid::render;

// One look per solver: the same algorithm has the same colour whoever wrote it
// (rigidlab solid with circles, peers dashed with squares or triangles), so a
// method and its peer sit side by side; the Okabe-Ito palette has only eight.
struct SolverStyle {
  rr::Color color = rr::kGray;
  rr::Dash dash = rr::Dash::kSolid;
  rr::Marker marker = rr::Marker::kCircle;
};

SolverStyle solver_style(const std::string& solver, bool peer) {
  // a method and its projected twin share a colour (the twin dashed); the peers are
  // dashed with squares (odeint) or triangles (GSL; SciPy dash-dot)
  static const std::map<std::string, rr::Color> colors = {{"rkf78", rr::kBlue},
                                                          {"dopri5", rr::kOrange},
                                                          {"bulirsch-stoer", rr::kReddishPurple},
                                                          {"rk4", rr::kVermillion},
                                                          {"splitting", rr::kGray},
                                                          {"splitting4", rr::kBlack},
                                                          {"vern6", rr::kBluishGreen},
                                                          {"vern7", rr::kSkyBlue},
                                                          {"vern8", rr::kVermillion},
                                                          {"vern9", rr::kReddishPurple},
                                                          {"rk8pd", rr::kBlack},
                                                          {"rkf45", rr::kGray},
                                                          {"DOP853", rr::kReddishPurple},
                                                          {"RK45", rr::kVermillion}};
  const std::string method = solver.substr(solver.find(':') + 1);
  const bool projected = method.size() > 5 && method.substr(method.size() - 5) == "+proj";
  SolverStyle style;
  if (const auto it = colors.find(projected ? method.substr(0, method.size() - 5) : method);
      it != colors.end())
    style.color = it->second;
  if (projected) style.dash = rr::Dash::kDashed;
  if (peer) {
    const bool scipy = solver.rfind("scipy:", 0) == 0, gsl = solver.rfind("gsl:", 0) == 0;
    style.dash = scipy ? rr::Dash::kDashDot : rr::Dash::kDashed;
    style.marker = gsl || scipy ? rr::Marker::kTriangle : rr::Marker::kSquare;
  }
  return style;
}

bool is_verner(const SolverCurve& c) {
  return c.solver.rfind("rigidlab:vern", 0) == 0;
}

// Two panels on the same axes, each with every peer: rigidlab's other methods on the
// left, Verner's pairs on the right; fifteen rigidlab curves in one panel
// would hide each other.
void draw_work_precision(const std::string& problem, const std::string& title,
                         const std::vector<SolverCurve>& curves, const std::string& path) {
  // the heavy-top problems (top_*) score theta at t_end, the free body omega
  const bool top = problem.rfind("top_", 0) == 0;
  rr::Plot2D plot(1, 2);
  plot.title = (top ? "Work-precision, heavy top " : "Work-precision, free body ") + title;
  // two decades of headroom above the slowest point leave a corner for the legend
  double y_lo = INFINITY, y_hi = 0, x_lo = INFINITY;
  for (const SolverCurve& c : curves)
    for (const Point& pt : c.points)
      if (pt.error <= 1.0)
        y_lo = std::min(y_lo, pt.seconds), y_hi = std::max(y_hi, pt.seconds),
        x_lo = std::min(x_lo, pt.error);
  for (int side = 0; side < 2; ++side) {
    rr::Panel& p = plot.panel(0, side);
    p.title = side == 0 ? "rigidlab's other methods and the peers"
                        : "Verner's pairs (rigidlab) and the peers";
    p.x.label = top ? "|\\theta(t_{end}) - \\theta_{exact}| (rad)"
                    : "relative error of \\omega_{body} at t_{end}";
    p.y.label = "run time (s), best of repeats";
    p.x.scale = rr::Scale::kLog10;
    p.y.scale = rr::Scale::kLog10;
    if (y_hi > 0) {
      p.y.min = y_lo / 2;
      p.y.max = y_hi * 100;
      p.x.min = x_lo / 2;
    }
    p.x.max = 1.0;
    p.legend = rr::LegendPlace::kAuto;
    for (const SolverCurve& c : curves) {
      if (!c.peer && is_verner(c) != (side == 1)) continue;
      std::vector<double> x, y;
      for (const Point& pt : c.points) {
        if (pt.error > 1.0) continue;  // no digit correct: off the plot, kept in the tables
        x.push_back(pt.error);
        y.push_back(pt.seconds);
      }
      rr::Series& s = p.add_line(x, y, c.solver);
      const SolverStyle style = solver_style(c.solver, c.peer);
      s.color = style.color;
      s.marker = style.marker;
      s.dash = style.dash;
      s.width = 3.0;
    }
    for (double level : kLevels) {
      rr::RefLine& r = p.add_ref_line(level, true);
      r.width = 1.5;
      r.color = rr::kLightGray;
    }
  }
  rr::save_png(plot, path);
}
#endif

void elliptic_section(std::ostream& md, const Json& all, Targets& targets) {
  std::vector<const Json*> rows;
  for (const Json& e : all)
    if (text(e, "group") == "elliptic") rows.push_back(&e);
  if (rows.empty()) return;
  md << "\n## Exact solution: cost per sample\n\n";
  md << "| problem | tool | what | ns / sample | vs gsl elljac |\n|---|---|---|---|---|\n";
  std::map<std::string, double> gsl;
  for (const Json* e : rows)
    if (text(*e, "tool") == "gsl") gsl[text(*e, "problem")] = number(*e, "ns_per_sample");
  for (const Json* e : rows) {
    const std::string problem = text(*e, "problem");
    const double ns = number(*e, "ns_per_sample");
    std::string ratio = "—";
    if (gsl.count(problem)) ratio = fmt::format("{:.2f}×", ns / gsl[problem]);
    md << fmt::format("| {} | {} | {} | {:.1f} | {} |\n", problem, text(*e, "tool"),
                      text(*e, "what"), ns, ratio);
    // the target: one exact sample of omega (free body) or theta (heavy top)
    const std::string what = text(*e, "what");
    if (text(*e, "tool") == "rigidlab" && (what == "omega" || what == "theta") &&
        gsl.count(problem)) {
      const double r = ns / gsl[problem];
      targets.add(r <= 1.5, fmt::format("{}: exact {} sample {:.1f} ns ≤ 1.5× GSL elljac "
                                        "({:.1f} ns): ratio {:.2f}",
                                        problem, what == "omega" ? "ω" : "θ", ns, gsl[problem], r));
    }
  }
}

void invariants_section(std::ostream& md, const Json& all, Targets& targets) {
  std::vector<const Json*> rows;
  for (const Json& e : all)
    if (text(e, "group") == "invariants") rows.push_back(&e);
  if (rows.empty()) return;
  md << "\n## Splitting invariants\n\n";
  md << "| problem | solver | step (s) | steps | \\|L\\| rel. change | max \\|ΔE\\|/E on [0,T] "
        "| on [0,10T] | ratio |\n|---|---|---|---|---|---|---|---|\n";
  for (const Json* e : rows) {
    const double dL = number(*e, "L_rel_change"), e1 = number(*e, "energy_err_max_T"),
                 e10 = number(*e, "energy_err_max_10T");
    md << fmt::format("| {} | {} | {:.4g} | {} | {} | {} | {} | {} |\n", text(*e, "problem"),
                      text(*e, "solver"), number(*e, "step"),
                      static_cast<long long>(number(*e, "steps", 0)),
                      std::isfinite(dL) ? fmt::format("{:.2e}", dL) : "",
                      std::isfinite(e1) ? fmt::format("{:.2e}", e1) : "",
                      std::isfinite(e10) ? fmt::format("{:.2e}", e10) : "",
                      std::isfinite(e1) ? fmt::format("{:.2f}", e10 / e1) : "");
    if (!e->value("target", true)) continue;  // shown for comparison only
    if (std::isfinite(dL))
      targets.add(dL <= 1e-13, fmt::format("{} {}: |L| relative change {:.2e} ≤ 1e-13 after {} "
                                           "steps",
                                           text(*e, "problem"), text(*e, "solver"), dL,
                                           static_cast<long long>(number(*e, "steps", 0))));
    if (std::isfinite(e1))
      targets.add(e10 <= 1.5 * e1,
                  fmt::format("{} {}: energy error max over [0,10T] {:.2e} within 1.5× of max "
                              "over [0,T] {:.2e} (ratio {:.2f})",
                              text(*e, "problem"), text(*e, "solver"), e10, e1, e10 / e1));
  }
}

void reference_section(std::ostream& md, const Json& all) {
  // roundoff floor: a tight double-precision run far from the exact solution,
  // while a long-double run agrees with it, says the double runs are the limit
  std::map<std::string, double> tight_double, long_double;
  for (const Json& e : all) {
    if (text(e, "group") != "reference") continue;
    const bool is_long = text(e, "check").find("long-double") != std::string::npos;
    (is_long ? long_double : tight_double)[text(e, "problem")] = number(e, "omega_diff");
  }
  std::vector<std::string> notes;
  for (const auto& [problem, d] : tight_double)
    if (long_double.count(problem) && d > 100 * long_double[problem])
      notes.push_back(fmt::format(
          "- **{}**: the exact solution agrees with a long-double integration to {:.1e}, but "
          "even rkf78 at tol 1e-15 in double precision misses it by {:.1e}: errors near that "
          "level are amplified roundoff of the integration, not truncation error, so whichever "
          "solver reaches them does so partly by chance (the same method at the same tolerance "
          "can differ by 10× there).",
          problem, long_double[problem], d));
  if (!notes.empty()) {
    md << "\n## Roundoff floor\n\n";
    for (const auto& n : notes) md << n << "\n";
  }
  bool any = false;
  for (const Json& e : all) {
    if (text(e, "group") != "reference") continue;
    if (!any) {
      md << "\n## Reference cross-check (exact solution vs a tight integration)\n\n"
            "| problem | check | ω difference (rel. max-norm) | attitude difference (rad) |\n"
            "|---|---|---|---|\n";
      any = true;
    }
    md << fmt::format("| {} | {} | {:.2e} | {:.2e} |\n", text(e, "problem"), text(e, "check"),
                      number(e, "omega_diff"), number(e, "attitude_diff"));
  }
}

// Groups this report does not know: one generic table each.
void other_groups(std::ostream& md, const Json& all) {
  const std::set<std::string> known = {"work_precision", "elliptic", "invariants", "reference",
                                       "problem",        "figures",  "controller"};
  std::map<std::string, std::vector<const Json*>> groups;
  for (const Json& e : all)
    if (!known.count(text(e, "group"))) groups[text(e, "group", "(no group)")].push_back(&e);
  for (const auto& [group, rows] : groups) {
    std::vector<std::string> keys;
    for (const Json* e : rows)
      for (auto it = e->begin(); it != e->end(); ++it)
        if (it.key() != "group" && std::find(keys.begin(), keys.end(), it.key()) == keys.end())
          keys.push_back(it.key());
    md << "\n## " << group << "\n\n|";
    for (const auto& k : keys) md << " " << k << " |";
    md << "\n|";
    for (std::size_t i = 0; i < keys.size(); ++i) md << "---|";
    md << "\n";
    for (const Json* e : rows) {
      md << "|";
      for (const auto& k : keys) {
        auto it = e->find(k);
        std::string cell;
        if (it == e->end())
          cell = "";
        else if (it->is_string())
          cell = it->get<std::string>();
        else if (it->is_number_float())
          cell = fmt::format("{:.4g}", it->get<double>());
        else
          cell = it->dump();
        md << " " << cell << " |";
      }
      md << "\n";
    }
  }
}

// Figure speed: rigidlab against matplotlib per figure with
// where rigidlab's time went, the context, the import, each lab's whole figure
// set, every lab's set side by side, and a run without figures against a build
// without the renderer; the issues' targets.
constexpr double kFigureSpeedup = 4.0;   // matplotlib / rigidlab, per figure
constexpr double kSetBudget = 0.5;       // s, lamina_tensor + tire_balancing figure sets
constexpr double kAllSetsBudget = 1.0;   // s, every lab's figure set side by side
constexpr double kNoFigureSlack = 1.05;  // renderer linked / not, --json run (timer noise)
constexpr const char* kPhases[] = {"setup", "layout", "draw", "resolve", "encode"};

void figures_section(std::ostream& md, const Json& all, Targets& targets) {
  struct Figure {
    double ours = NAN, peer = NAN;
    bool first = false;
    std::string lab;
    std::map<std::string, double> phases;
  };
  std::vector<std::string> order;
  std::map<std::string, Figure> figures;
  std::map<std::string, double> set_wall, json_render, json_norender;
  std::vector<std::string> labs;
  double context = NAN, import = NAN, side_by_side = NAN;
  std::string renderer, side_by_side_labs;
  const Json* animation = nullptr;  // rigidlab's animation entry
  double animation_peer = NAN;
  for (const Json& e : all) {
    if (text(e, "group") != "figures") continue;
    const std::string kind = text(e, "kind"), name = text(e, "case"), tool = text(e, "tool");
    const double s = number(e, "seconds");
    if (kind == "figure") {
      if (!figures.count(name)) order.push_back(name);
      Figure& f = figures[name];
      (tool == "matplotlib" ? f.peer : f.ours) = s;
      if (tool == "rigidlab") {
        f.first = e.value("first", false);
        f.lab = text(e, "lab");
        if (e.contains("phases"))
          for (const char* phase : kPhases) f.phases[phase] = number(e["phases"], phase);
      }
    } else if (kind == "context") {
      context = s;
      renderer = text(e, "backend") + ", " + text(e, "renderer");
    } else if (kind == "import") {
      import = s;
    } else if (kind == "set") {
      set_wall[name] = s;
      labs.push_back(name);
    } else if (kind == "side_by_side") {
      side_by_side = s;
      side_by_side_labs =
          fmt::format("{} labs on {} processors", e.value("labs", Json::array()).size(),
                      e.value("processors", 0));
    } else if (kind == "animation") {
      if (tool == "rigidlab")
        animation = &e;
      else
        animation_peer = s;
    } else if (kind == "json_run") {
      const std::string lab = name.substr(0, name.find(' '));
      (text(e, "build") == "norender" ? json_norender : json_render)[lab] = s;
    }
  }
  if (figures.empty()) return;
  const auto ms = [](double s) {
    return std::isfinite(s) ? fmt::format("{:.1f} ms", s * 1e3) : "—";
  };

  md << "\n## Figures: rigidlab against matplotlib\n\n"
        "Each figure at 1600×1200, drawn and written as PNG. rigidlab: the lab's own timing "
        "(`--figures DIR --json --timing`: wall time of drawing and PNG encoding of that "
        "figure; a lab encodes one figure on a second thread while it draws the next, so a "
        "process takes less than the sum), best of several runs of the lab. A 3D scene is "
        "drawn with OpenGL (4× MSAA, resolved and read back); a plot by cairo's rasteriser on "
        "the CPU. A lab loads the GL library and makes the context before its first figure "
        "(reported below, as matplotlib's import is); the first scene of a process (marked ¹ "
        "where it is the first figure) still pays the first use of its shaders and of the "
        "1600×1200 multisampled buffers. "
        "matplotlib (Agg, `/usr/bin/python3`): the same plot from figure creation to the PNG "
        "on disk, after import, best of several; 3D scenes with mplot3d.\n\n"
        "Where rigidlab's time went (the run that gave its best time; `--timing`, each GL "
        "phase waited for with glFinish): **setup** for a scene binding and clearing the "
        "1600×1200 buffers with 4 samples a pixel (the first scene of a process makes them: "
        "llvmpipe zeroes 69 MB of fresh pages), for a plot making cairo's image; **layout** "
        "placing text, legend and the fit (CPU); **draw** until the rasteriser finished (the "
        "first scene also loads its shaders from Mesa's cache); **resolve** averaging a "
        "scene's samples and reading the pixels back, or a plot's pixels copied out of "
        "cairo's image; **encode** PNG and the atomic write.\n\n"
        "| figure | rigidlab | setup | layout | draw | resolve | encode | matplotlib | "
        "matplotlib / rigidlab |\n|---|---|---|---|---|---|---|---|---|\n";
  std::vector<std::string> misses;
  double worst = INFINITY, sum_ours = 0, sum_peer = 0;
  double floor_later = INFINITY;  // the least setup + resolve + encode of a figure not first
  std::map<std::string, double> lab_ours, lab_peer;
  for (const std::string& name : order) {
    const Figure& f = figures[name];
    const double ratio = f.peer / f.ours;
    std::string phases;
    for (const char* phase : kPhases)
      phases += " " + (f.phases.count(phase) ? ms(f.phases.at(phase)) : std::string("—")) + " |";
    if (!f.first && f.phases.size() == std::size(kPhases))
      floor_later = std::min(floor_later,
                             f.phases.at("setup") + f.phases.at("resolve") + f.phases.at("encode"));
    md << fmt::format("| {}{} | {} |{} {} | {} |\n", name, f.first ? " ¹" : "", ms(f.ours), phases,
                      ms(f.peer), std::isfinite(ratio) ? fmt::format("{:.2f}×", ratio) : "—");
    if (std::isfinite(f.ours)) lab_ours[f.lab] += f.ours;
    if (std::isfinite(f.peer)) lab_peer[f.lab] += f.peer;
    if (!std::isfinite(ratio)) continue;
    worst = std::min(worst, ratio);
    sum_ours += f.ours;  // both sums over the figures both tools drew
    sum_peer += f.peer;
    if (ratio < kFigureSpeedup) misses.push_back(fmt::format("{} {:.2f}×", name, ratio));
  }
  md << fmt::format("| **all figures** | {} | | | | | | {} | {} |\n", ms(sum_ours), ms(sum_peer),
                    sum_ours > 0 ? fmt::format("{:.2f}×", sum_peer / sum_ours) : "—");
  md << "\n";
  if (std::isfinite(floor_later))
    md << "- the least setup + resolve + encode of a figure that is not its process's first: "
       << ms(floor_later)
       << " (what any figure costs before anything is drawn in it, on this renderer)\n";
  if (std::isfinite(context))
    md << "- context creation (rigidlab, " << renderer << "): " << ms(context)
       << " (bench_figure_context, best of fresh processes)\n";
  if (std::isfinite(import))
    md << "- matplotlib import (matplotlib, pyplot, mplot3d, numpy; once per process, not in "
          "the figure times): "
       << ms(import) << "\n";

  if (!labs.empty()) {
    md << "\n**Whole figure set per lab.** rigidlab: wall time of the process "
          "`LAB --quiet --figures DIR`, start to exit (best of runs); matplotlib: its figures "
          "plus its import, as one fresh process would pay.\n\n"
          "| lab | rigidlab process | rigidlab figures | matplotlib figures + import |\n"
          "|---|---|---|---|\n";
    for (const std::string& lab : labs)
      md << fmt::format("| {} | {} | {} | {} |\n", lab, ms(set_wall[lab]), ms(lab_ours[lab]),
                        lab_peer.count(lab) ? ms(lab_peer[lab] + import) : "—");
  }
  if (std::isfinite(side_by_side))
    md << "\n**Every lab's figure set side by side** (all started at once, first start to last "
          "exit, best of runs; "
       << side_by_side_labs << "): " << ms(side_by_side) << "\n";
  if (!json_render.empty()) {
    md << "\n**A run without figures** (`LAB --json`, process wall time, best of many, the two "
          "builds alternating): this build against one configured with "
          "`-DRIGID_BUILD_RENDER=OFF`.\n\n"
          "| lab | renderer linked | no renderer | ratio |\n|---|---|---|---|\n";
    for (const auto& [lab, s] : json_render) {
      const double other = json_norender.count(lab) ? json_norender[lab] : NAN;
      md << fmt::format("| {} | {} | {} | {} |\n", lab, ms(s), ms(other),
                        std::isfinite(other) ? fmt::format("{:.2f}", s / other) : "—");
    }
  }

  if (animation != nullptr) {
    const double s = number(*animation, "seconds"), video = number(*animation, "video_seconds");
    md << fmt::format(
        "\n**An animation**: `poinsot --animate FILE.mp4` with its defaults, {} frames "
        "at {} and {:g} fps ({:g} s of video), process wall time, best of 2: **{:.2f} s** ({:.2f}× "
        "real time); matplotlib's FuncAnimation drawing the same scene each frame through its "
        "ffmpeg writer (H.264, the same preset and CRF): {}.\n",
        number(*animation, "frames"), text(*animation, "size"), number(*animation, "fps"), video, s,
        s / video,
        std::isfinite(animation_peer)
            ? fmt::format("{:.1f} s ({:.1f}× rigidlab's)", animation_peer, animation_peer / s)
            : std::string("not measured (ffmpeg not installed)"));
    if (animation->contains("phases")) {
      md << "Where the frames' time went (`--timing`, each GL phase waited for, so the sum "
            "exceeds the untimed run): ";
      std::vector<std::string> parts;
      for (const auto& [phase, v] : (*animation)["phases"].items())
        parts.push_back(fmt::format("{} {:.2f} s", phase, v.get<double>()));
      md << fmt::format("{}", fmt::join(parts, ", "))
         << ". Encoding runs on a second thread: "
            "'encoder_wait' is the time drawing waited for it.\n";
    }
    targets.add(s <= video,
                fmt::format("animation: rendering and encoding {:g} s of 1280x720 30 fps "
                            "video in at most {:g} s: {:.2f} s",
                            video, video, s));
  }

  // the targets
  if (std::isfinite(worst))
    targets.add(misses.empty(),
                fmt::format("figures: every figure at least {:.0f}× faster than "
                            "matplotlib, PNG encoding included (worst {:.2f}×{}{})",
                            kFigureSpeedup, worst, misses.empty() ? "" : "; below: ",
                            fmt::format("{}", fmt::join(misses, ", "))));
  if (set_wall.count("lamina_tensor") && set_wall.count("tire_balancing")) {
    const double both = set_wall["lamina_tensor"] + set_wall["tire_balancing"];
    targets.add(both < kSetBudget,
                fmt::format("figures: whole figure set of lamina_tensor + "
                            "tire_balancing under {:.1f} s: {:.3f} s (process wall time, "
                            "{:.3f} s + {:.3f} s; figures alone {:.3f} s)",
                            kSetBudget, both, set_wall["lamina_tensor"], set_wall["tire_balancing"],
                            lab_ours["lamina_tensor"] + lab_ours["tire_balancing"]));
  }
  if (std::isfinite(side_by_side))
    targets.add(side_by_side < kAllSetsBudget,
                fmt::format("figures: every lab's whole figure set, side by side, "
                            "under {:.1f} s: {:.3f} s ({})",
                            kAllSetsBudget, side_by_side, side_by_side_labs));
  for (const auto& [lab, s] : json_render) {
    if (!json_norender.count(lab)) continue;
    const double r = s / json_norender[lab];
    targets.add(r <= kNoFigureSlack,
                fmt::format("figures: {} --json with the renderer linked no slower "
                            "than without ({} against {}, ratio {:.2f}; ≤ {:.2f} allowed for "
                            "timer noise)",
                            lab, ms(s), ms(json_norender[lab]), r, kNoFigureSlack));
  }
}

// Merges every part DIR/<name>.json that holds a JSON array (one per benchmark
// program; reference.json is an object and is skipped) into one array, in file
// name order, keeping each entry's keys in their order.
Json merge_parts(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> parts;
  for (const auto& f : std::filesystem::directory_iterator(dir))
    if (f.path().extension() == ".json" && f.path().filename() != "results.json")
      parts.push_back(f.path());
  std::sort(parts.begin(), parts.end());
  Json all = Json::array();
  for (const auto& part : parts) {
    std::ifstream in(part);
    const Json j = Json::parse(in, nullptr, /*allow_exceptions=*/false);
    if (!j.is_array()) continue;
    for (const Json& e : j) all.push_back(e);
    std::cout << "bench_report: " << j.size() << " entries from " << part.filename().string()
              << "\n";
  }
  return all;
}

}  // namespace

int main(int argc, char** argv) {
  bench::Arguments args;
  if (const int status = bench::parse_arguments(
          argc, argv, "bench_report",
          "merges DIR/*.json into DIR/results.json, writes DIR/results.md and "
          "DIR/work_precision_<problem>.png",
          args, /*takes_dir=*/true, /*takes_quick=*/false, /*needs_dir=*/true);
      status >= 0) {
    return status;
  }
  const std::string out_dir = args.dir.string();
  Json all;
  try {
    all = merge_parts(out_dir);
    const std::string tmp = out_dir + "/results.json.tmp";
    {
      std::ofstream f(tmp);
      f << all.dump(1) << "\n";
      if (!f) throw std::runtime_error("cannot write " + tmp);
    }
    std::filesystem::rename(tmp, out_dir + "/results.json");
  } catch (const std::exception& e) {
    std::cerr << "bench_report: " << e.what() << "\n";
    return 1;
  }

  std::ostringstream md;
  Targets targets;
  md << "# rigidlab benchmarks\n\n"
        "Wall time (steady_clock) is the fastest of many repeats: each setting is timed in 3 "
        "rounds spread over the run, each round repeating it at least 3 times and for at least "
        "20 ms (one run if it takes longer than 0.3 s). The machine is shared "
        "(2 cores, other jobs running), so timings are noisy: read ratios within ~1.5× as ties. "
        "Error is the max-norm of the ω_body error at t_end relative to |ω|, against the exact "
        "Jacobi-elliptic solution (rigid::FreeBodyExact). Every solver integrates the same "
        "7-dimensional state (ω_body and the attitude quaternion). Peers: Boost.Odeint with "
        "std::vector<double> state and make_controlled(tol, tol); GSL gsl_odeiv2_driver with "
        "epsabs = epsrel = tol; SciPy solve_ivp with rtol = tol, atol = 1e-3 tol (timed in "
        "CPython, after import). The heavy-top problems (top_*) score |θ(t_end) − θ_exact| in "
        "rad against rigid::HeavyTopExact instead, on the same 7-dimensional state with the "
        "gravity torque.\n";

  std::map<std::string, std::string> titles;
  for (const Json& e : all)
    if (text(e, "group") == "problem") titles[text(e, "problem")] = text(e, "title");
  const auto curves = work_precision_curves(all);
  for (const auto& [problem, c] : curves) {
    const std::string title = titles.count(problem) ? titles[problem] : problem;
    work_precision_section(md, problem, title, c, targets);
    const std::string png = "work_precision_" + problem + ".png";
#ifdef RIGID_BENCH_HAVE_RENDER
    try {
      draw_work_precision(problem, title, c, out_dir + "/" + png);
      md << "\n![work-precision " << problem << "](" << png << ")\n";
    } catch (const std::exception& e) {
      std::cerr << "bench_report: plot " << png << " not drawn: " << e.what() << "\n";
    }
#endif
  }
  reference_section(md, all);
  elliptic_section(md, all, targets);
  invariants_section(md, all, targets);
  controller_section(md, all);
  figures_section(md, all, targets);
  other_groups(md, all);

  md << "\n## Targets\n\n";
  for (const auto& line : targets.lines) md << line << "\n";

  const std::string path = out_dir + "/results.md";
  std::ofstream out(path);
  out << md.str();
  if (!out) {
    std::cerr << "bench_report: cannot write " << path << "\n";
    return 1;
  }
  std::cout << md.str();
  return 0;
}
