// bench_report's work-precision sections: per problem, the time each solver needs to
// reach an error level, fastest rigidlab against fastest peer, with the finer
// levels and a diagram; and the PI step-size controller against odeint's default.
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
#include <iostream>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "report.h"
#ifdef RIGID_BENCH_HAVE_RENDER
#include "rigid/render/draw.h"
#include "rigid/render/plot2d.h"
#endif

namespace bench::report {

namespace {

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

// The right-hand-side evaluations of the loosest measurement of a solver that reaches
// `level` (0 if none does, or it did not count them).
long long evaluations_at(const SolverCurve& c, double level) {
  for (const Point& p : c.points)
    if (p.error <= level) return p.evaluations;
  return 0;
}

// The finer levels' target: at every level from 1e-4 down to ten times the best error any
// solver reaches on the problem, by half decades (and that floor itself), the fastest
// rigidlab solver takes at most kFinerLevelsRatio of the fastest peer's time; beside each
// time, the evaluations of the measurement that reached the level, to say where a gain
// or a miss comes from.
constexpr double kFinerLevelsRatio = 0.75;
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
      "\nThe finer levels: every level from 1e-4 down to ten times the best error any "
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
    if (!ours || (both && ratio > kFinerLevelsRatio))
      misses.push_back(
          fmt::format("{:.1e} ({})", level, both ? fmt::format("{:.2f}", ratio) : "not reached"));
  }
  targets.add(
      misses.empty(),
      fmt::format("{}: fastest rigidlab at most {:.2f}× the fastest peer at "
                  "every level 1e-4..{:.1e} (worst ratio {:.2f}{}{})",
                  problem, kFinerLevelsRatio, floor, worst, misses.empty() ? "" : "; missed at ",
                  fmt::format("{}", fmt::join(misses, ", "))));
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

}  // namespace

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

void work_precision_sections(std::ostream& md, const Json& all,
                             [[maybe_unused]] const std::string& dir, Targets& targets) {
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
      draw_work_precision(problem, title, c, dir + "/" + png);
      md << "\n![work-precision " << problem << "](" << png << ")\n";
    } catch (const std::exception& e) {
      std::cerr << "bench_report: plot " << png << " not drawn: " << e.what() << "\n";
    }
#endif
  }
}

}  // namespace bench::report
