// The JSON entries that more than one bench program writes, each as bench_report
// reads it (report.h).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "output.h"

namespace bench {

/// An entry of group "elliptic": what one exact sample, or one call of a peer's elliptic
/// functions, costs on `problem`, from the best time of `samples` of them (said on
/// stdout with --verbose).
inline nlohmann::ordered_json elliptic_entry(const std::string& problem, const char* tool,
                                             const char* what, double seconds, int samples) {
  nlohmann::ordered_json e;
  e["group"] = "elliptic";
  e["problem"] = problem;
  e["tool"] = tool;
  e["what"] = what;
  e["ns_per_sample"] = seconds / samples * 1e9;
  detail("  %-16s %-16s %8.1f ns/sample\n", tool, what, e["ns_per_sample"].get<double>());
  return e;
}

}  // namespace bench
