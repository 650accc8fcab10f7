// What a lab that ranks its integrators at equal cost (common/integrated_run.h:
// "which method to use") is held to, in-process: the ranking is by the error the
// lab reports, every run at the same cost, the method named the first, and the
// advice of --help and the user guide the ranking's own answer.
#pragma once

#include <fmt/format.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "common/integrated_run.h"
#include "lab_library.h"

namespace rigid::test {

/// The command line's choice a result key stands for: "vern8_project" -> "vern8
/// --project", "bulirsch_stoer" -> "bulirsch-stoer".
inline std::string choice_of(std::string key) {
  const std::string projected = "_project";
  const bool project = key.size() > projected.size() &&
                       key.compare(key.size() - projected.size(), projected.size(), projected) == 0;
  if (project) key.resize(key.size() - projected.size());
  for (char& c : key) c = c == '_' ? '-' : c;
  return key + (project ? " --project" : "");
}

/// The methods of the comparison at equal cost as result keys, by rank.
inline std::vector<std::string> ranked_methods(const rigid::lab::Json& r) {
  const std::string prefix = "equal_cost_rank_";
  std::vector<std::string> by_rank;
  for (const auto& [key, rank] : r.items()) {
    if (key.rfind(prefix, 0) != 0) continue;
    const auto at = rank.get<std::size_t>();
    REQUIRE(at >= 1);
    if (by_rank.size() < at) by_rank.resize(at);
    CHECK(by_rank[at - 1].empty());  // one method a rank
    by_rank[at - 1] = key.substr(prefix.size());
  }
  for (const std::string& m : by_rank) CHECK(!m.empty());  // no rank left out
  return by_rank;
}

/// The ranking of a report's results `r`, whose errors are keyed
/// equal_cost_<error_prefix><method><error_suffix>: every method ranked, the errors
/// in order, each run at kEqualCostEvaluations a period within `cost_slack` above (the
/// bisection's 5 % on the calibration periods) and 20 % below (the step control
/// jumps), the method to use the first, and its reason its error.
inline void check_ranking(const rigid::lab::Json& r, const std::string& error_prefix,
                          const std::string& error_suffix, double cost_slack) {
  const std::vector<std::string> ranked = ranked_methods(r);
  REQUIRE(!ranked.empty());
  const double periods = value(r, "equal_cost_periods");
  const double target = rigid::lab::kEqualCostEvaluations * periods;
  CHECK(value(r, "equal_cost_evaluations_per_period") == rigid::lab::kEqualCostEvaluations);
  double previous = 0.0;
  bool finished = true;  // the runs that could not finish come last
  for (const std::string& m : ranked) {
    INFO(m);
    const auto& error = r.at("equal_cost_" + error_prefix + m + error_suffix);
    if (error.is_null()) {
      finished = false;
      continue;
    }
    CHECK(finished);
    CHECK(error.get<double>() >= previous);
    previous = error.get<double>();
    const double evaluations = value(r, ("equal_cost_evaluations_" + m).c_str());
    // No method gets more work than the rest. Less only handicaps it; Bulirsch-Stoer's
    // cost jumps as its order changes with the tolerance, and the nearest it comes
    // from below was 0.71 of the target on a fast top (measured).
    CHECK(evaluations <= (1.0 + cost_slack) * target);
    CHECK(evaluations >= (m == "bulirsch_stoer" ? 0.6 : 0.8) * target);
    CHECK(value(r, ("equal_cost_steps_" + m).c_str()) > 0);
    CHECK(r.contains("equal_cost_energy_drift_per_period_rel_" + m));
  }
  const std::string first = ranked.front();
  CHECK(r.at("recommended_method").get<std::string>() == choice_of(first));
  const double best = value(r, ("equal_cost_" + error_prefix + first + error_suffix).c_str());
  CHECK_THAT(r.at("recommended_method_reason").get<std::string>(),
             Catch::Contains(fmt::format("{:.2g}", best)));
}

/// The method the lab names for `r`, less --project: "vern8".
inline std::string named_method(const rigid::lab::Json& r) {
  std::string name = r.at("recommended_method").get<std::string>();
  const std::size_t space = name.find(' ');
  return space == std::string::npos ? name : name.substr(0, space);
}

/// The user guide, where the advice is written for a reader.
inline std::string user_guide() {
  std::ifstream in(std::string(RIGID_SOURCE_DIR) + "/docs/guide.md");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace rigid::test
