// bench_report's tables of the exact solution's checks: the roundoff floor and the
// cross-check against a tight integration, the cost of one exact sample, the splitting
// methods' invariants; and a generic table for any group this report does not know.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "report.h"

namespace bench::report {

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
  const std::set<std::string> known = {"work_precision", "elliptic", "invariants",
                                       "reference",      "problem",  "figures",
                                       "controller",     "python",   "web"};
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

}  // namespace bench::report
