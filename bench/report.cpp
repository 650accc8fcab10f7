// bench_report: merges the parts every benchmark wrote, DIR/<name>.json (each a
// JSON array of entries), into DIR/results.json, and turns that into
// DIR/results.md: work-precision tables at fixed error levels
// (report_work_precision.cpp), the elliptic-function and invariants tables
// (report_tables.cpp), the figure-speed tables (report_figures.cpp), what a linked
// library costs a start (report_startup.cpp), import rigidlab's cost (report_python.cpp),
// the issues' targets met or not, and a
// generic table for any other group; with one work-precision diagram per problem
// drawn with rigid::render when it is built.
//
// Usage: bench_report DIR
#include "report.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "output.h"

namespace {

using bench::report::Json;

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
  using namespace bench::report;
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

  work_precision_sections(md, all, out_dir, targets);
  reference_section(md, all);
  elliptic_section(md, all, targets);
  invariants_section(md, all, targets);
  controller_section(md, all);
  figures_section(md, all, targets);
  startup_section(md, all);
  python_section(md, all, targets);
  web_section(md, all, targets);
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
