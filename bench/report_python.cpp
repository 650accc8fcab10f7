// bench_report's Python section: what a call of import rigidlab costs over the lab's
// computation in C++ (bench/python_bench.py: the same lab at its defaults, timed from
// Python and in C++ alone, medians and 95th percentiles), and a sweep of racquet
// bodies from Python on a thread pool against one process of the command line a body.
#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <vector>

#include "report.h"

namespace bench::report {

void python_section(std::ostream& md, const Json& all, Targets& targets) {
  std::vector<const Json*> calls, sweep;
  for (const Json& e : all) {
    if (text(e, "group") != "python") continue;
    (text(e, "kind") == "overhead" ? calls : sweep).push_back(&e);
  }
  if (calls.empty() && sweep.empty()) return;
  md << "\n## import rigidlab: a call's own cost, and a sweep\n\n"
        "Each lab at its defaults, called from Python and computed in C++ alone (the same "
        "`session_at`, nothing of Python's in the loop): the call's own cost is the "
        "difference of the medians, and of the 95th percentiles. Goal: at most 10 % of the "
        "computation or 20 µs, whichever is larger. On a computation of milliseconds the "
        "difference is within the timing's noise, which a negative cost shows.\n\n"
        "| lab | compute() in C++, median | p95 | a call's own cost, median | p95 | goal | "
        "median within it |\n|---|---|---|---|---|---|---|\n";
  bool all_met = true;
  for (const Json* e : calls) {
    const double own = number(*e, "seconds"), goal = number(*e, "goal_seconds");
    const bool met = own <= goal;
    all_met = all_met && met;
    md << fmt::format("| {} | {} | {} | {} | {} | {} | {} |\n", text(*e, "case"),
                      seconds_text(number(*e, "compute_seconds")),
                      seconds_text(number(*e, "compute_p95")), seconds_text(own),
                      seconds_text(number(*e, "p95")), seconds_text(goal), met ? "yes" : "no");
  }
  if (!calls.empty()) {
    targets.add(all_met,
                "import rigidlab: a call's own cost at most 10 % of compute() or 20 µs "
                "(the median, every lab)");
  }
  if (sweep.size() != 2) return;
  const auto python = std::find_if(sweep.begin(), sweep.end(), [](const Json* e) {
    return text(*e, "tool").find("Python") != std::string::npos;
  });
  if (python == sweep.end()) return;
  const Json& p = **python;
  const Json& c = *sweep[python == sweep.begin() ? 1 : 0];
  const double ratio = number(c, "seconds") / number(p, "seconds");
  md << fmt::format(
      "\n{}: growth rate and first flip of each, I1 = 1, I3 = 2, I2 spread between them; the "
      "processes timed on {:.0f} of the bodies and scaled, their results compared equal.\n\n"
      "| how | time | against the processes |\n|---|---|---|\n| {} | {} | {:.1f}× faster |\n"
      "| {} | {} | 1 |\n",
      text(p, "case"), number(c, "measured_processes"), text(p, "tool"),
      seconds_text(number(p, "seconds")), ratio, text(c, "tool"),
      seconds_text(number(c, "seconds")));
  targets.add(ratio >= 100.0,
              fmt::format("import rigidlab: the racquet sweep at least 100× faster than a "
                          "process a body ({:.1f}×)",
                          ratio));
}

}  // namespace bench::report
