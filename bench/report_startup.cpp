// bench_report's start-up section: what linking a library would add to every start of
// a process that links the renderer. The bench_startup_* programs (startup.cpp) start
// and exit, linked with nothing more, with libcairo, with FFmpeg; figures_bench.py
// times them alternating, best of its runs. These rows are why the renderer opens
// libcairo and FFmpeg with dlopen on first use (render/src/vector.cpp, video.cpp).
#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <utility>

#include "report.h"

namespace bench::report {

void startup_section(std::ostream& md, const Json& all) {
  std::map<std::string, double> start;  // what it links -> process wall time
  double lab_run = std::numeric_limits<double>::infinity();
  std::string lab_case;  // the fastest lab run without figures, renderer linked
  for (const Json& e : all) {
    if (text(e, "group") != "figures") continue;
    const double s = number(e, "seconds");
    if (text(e, "kind") == "startup") {
      start[text(e, "links")] = s;
    } else if (text(e, "kind") == "json_run" && text(e, "build") == "render" && s < lab_run) {
      lab_run = s;
      lab_case = text(e, "case");
    }
  }
  if (!start.count("bare")) return;
  const double bare = start["bare"];
  md << "\n## Start-up: what a linked library costs\n\n"
        "A process that reads its command line and exits (`bench_startup_*`), linked with "
        "nothing more, with libcairo, and with FFmpeg's libavcodec, libavformat, libavutil "
        "and libswscale: process wall time, best of runs, the three alternating. What a "
        "library adds here, linked, it would add to every process that links the renderer, a "
        "lab's run without figures included; so the renderer opens libcairo on its first "
        "plot and FFmpeg on its first MP4 (dlopen) instead.\n\n";
  const bool with_lab = std::isfinite(lab_run);
  md << "| links | process | added to a bare start | linked / bare |"
     << (with_lab ? fmt::format(" `{}` ({:.2f} ms) with it |", lab_case, lab_run * 1e3) : "")
     << "\n|---|---|---|---|" << (with_lab ? "---|" : "") << "\n";
  const std::pair<const char*, const char*> rows[] = {
      {"bare", "nothing more"}, {"cairo", "libcairo"}, {"ffmpeg", "FFmpeg"}};
  for (const auto& [key, name] : rows) {
    if (!start.count(key)) continue;
    const double s = start[key], added = s - bare;
    md << fmt::format("| {} | {:.2f} ms | {:+.2f} ms | {:.2f} |", name, s * 1e3, added * 1e3,
                      s / bare);
    if (with_lab)
      md << fmt::format(" {:.2f} ms ({:.2f}×) |", (lab_run + added) * 1e3,
                        (lab_run + added) / lab_run);
    md << "\n";
  }
}

}  // namespace bench::report
