// bench_figure_context: makes the process's GL context, as the first figure of
// a lab does, and prints how long that took (rigid::render::ContextInfo::
// creation_seconds: loading the backend library, making the context current,
// loading the GL entry points) with the process's wall time up to then, as one
// JSON object on stdout. figures_bench.py runs it several times, in fresh
// processes since a context is made once per process, and keeps the best.
#include <chrono>
#include <iostream>
#include <nlohmann/json.hpp>

#include "output.h"
#include "rigid/render/context.h"

int main(int argc, char** argv) {
  bench::Arguments args;
  if (const int status = bench::parse_arguments(
          argc, argv, "bench_figure_context",
          "the time to make the renderer's GL context, as one JSON line on stdout", args,
          /*takes_dir=*/false, /*takes_quick=*/false);
      status >= 0) {
    return status;
  }
  const auto t0 = std::chrono::steady_clock::now();
  try {
    const rigid::render::ContextInfo& info = rigid::render::context();
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::cout << nlohmann::json{{"backend", rigid::render::backend_name(info.backend)},
                                {"gl_renderer", info.gl_renderer},
                                {"samples", info.samples},
                                {"creation_seconds", info.creation_seconds},
                                {"call_seconds", wall}}
              << "\n";
  } catch (const rigid::render::Unavailable& e) {
    std::cerr << "bench_figure_context: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
