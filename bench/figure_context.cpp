// bench_figure_context: makes the process's GL context, as the first figure of
// a lab does, and prints how long that took (rigid::render::ContextInfo::
// creation_seconds: loading the backend library, making the context current,
// loading the GL entry points) with the process's wall time up to then, as one
// JSON object on stdout. figures_bench.py runs it several times, in fresh
// processes since a context is made once per process, and keeps the best.
#include <chrono>
#include <iostream>
#include <nlohmann/json.hpp>

#include "rigid/render/context.h"

int main() {
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
