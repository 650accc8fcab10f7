// bench_report's pieces: the entries every benchmark wrote, read by key, and one
// function per section of results.md, each writing its Markdown and adding the
// targets it checks, in the order the report lists them.
#pragma once

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

namespace bench::report {

using Json = nlohmann::ordered_json;  // keeps each entry's key order for generic tables

/// The number under `key` of an entry, or `fallback` if it has none.
inline double number(const Json& e, const char* key, double fallback = std::nan("")) {
  auto it = e.find(key);
  return (it != e.end() && it->is_number()) ? it->get<double>() : fallback;
}

/// The text under `key` of an entry, or `fallback` if it has none.
inline std::string text(const Json& e, const char* key, const std::string& fallback = {}) {
  auto it = e.find(key);
  return (it != e.end() && it->is_string()) ? it->get<std::string>() : fallback;
}

/// A time in µs, ms or s, as it reads best; "not reached" if infinite.
inline std::string seconds_text(double s) {
  if (!std::isfinite(s)) return "not reached";
  if (s < 1e-3) return fmt::format("{:.1f} µs", s * 1e6);
  if (s < 1.0) return fmt::format("{:.2f} ms", s * 1e3);
  return fmt::format("{:.2f} s", s);
}

/// The issues' targets, one line each, met or not, for the report's last section.
struct Targets {
  std::vector<std::string> lines;
  void add(bool met, const std::string& what) {
    lines.push_back(fmt::format("- **{}** {}", met ? "met" : "NOT met", what));
  }
};

/// Per problem, the time each solver takes to reach each error level, fastest rigidlab
/// against fastest peer; and its diagram DIR/work_precision_<problem>.png where the
/// renderer is built (report_work_precision.cpp).
void work_precision_sections(std::ostream& md, const Json& all, const std::string& dir,
                             Targets& targets);
/// The PI step-size controller against odeint's default on the same stepper.
void controller_section(std::ostream& md, const Json& all);
/// The roundoff floor and the exact solution against a tight integration (report_tables.cpp).
void reference_section(std::ostream& md, const Json& all);
/// The cost of one exact sample against GSL's elliptic functions.
void elliptic_section(std::ostream& md, const Json& all, Targets& targets);
/// What the splitting methods keep: |L| and the energy over long runs.
void invariants_section(std::ostream& md, const Json& all, Targets& targets);
/// Groups this report does not know: one generic table each.
void other_groups(std::ostream& md, const Json& all);
/// Figure speed against matplotlib, the figure sets, a run without figures, an
/// animation (report_figures.cpp).
void figures_section(std::ostream& md, const Json& all, Targets& targets);
/// What linking libcairo or FFmpeg would add to every process's start (report_startup.cpp).
void startup_section(std::ostream& md, const Json& all);
/// import rigidlab: a call's own cost per lab, and the sweep (report_python.cpp).
void python_section(std::ostream& md, const Json& all, Targets& targets);
/// The web page: WebAssembly beside native, frames, an input's wait (report_web.cpp).
void web_section(std::ostream& md, const Json& all, Targets& targets);

}  // namespace bench::report
