// bench_report's web section: the page in headless Chromium on SwiftShader beside the
// native build in the same run (bench/web_bench.py): each lab's compute() in
// WebAssembly against natively, the frame interval while a motion plays, an input to
// its frame, the first frame and what the page downloads.
#include <fmt/format.h>

#include <string>
#include <vector>

#include "report.h"

namespace bench::report {

namespace {

std::string ms_text(double ms) {
  return std::isnan(ms) ? "no motion" : fmt::format("{:.1f} ms", ms);
}

}  // namespace

void web_section(std::ostream& md, const Json& all, Targets& targets) {
  std::vector<const Json*> compute, interaction, page;
  for (const Json& e : all) {
    if (text(e, "group") != "web") continue;
    const std::string kind = text(e, "kind");
    (kind == "compute" ? compute : kind == "interaction" ? interaction : page).push_back(&e);
  }
  if (compute.empty() || compute.size() != interaction.size() || page.size() != 1) return;
  md << "\n## The web page: WebAssembly beside native, and a person's waits\n\n"
        "In Debian's headless Chromium on SwiftShader at 1280x720 (bench/web_bench.py). "
        "compute(): a lab's whole report at its defaults, in the page (a batch of at least "
        "2 ms a sample: a browser's clock ticks in 0.1 ms) and natively (the same "
        "`session_at` loop), medians, and the ratio of the least of each (on 2 cores "
        "Chromium's other processes share the page's, and the least is the one they "
        "disturbed least). Frames: the interval between frames while the "
        "motion plays. Input: a number typed in a field to the frame that shows it, and to "
        "the whole report's, p95 of 12 after two (the first input apart: it runs code the "
        "browser has not compiled yet).\n\n"
        "| lab | compute() wasm | native | ratio | least's ratio | frames median | p95 | "
        "input to frame p95 | to the whole report p95 | the first input |\n"
        "|---|---|---|---|---|---|---|---|---|---|\n";
  double worst_ratio = 0, worst_frame = 0, worst_input = 0;
  for (std::size_t k = 0; k < compute.size(); ++k) {
    const Json& c = *compute[k];
    const Json& i = *interaction[k];
    const double ratio = number(c, "seconds") / number(c, "native_seconds");
    worst_ratio = std::max(worst_ratio, ratio);
    const double frame_p95 = number(i, "frame_p95_ms");
    if (!std::isnan(frame_p95)) worst_frame = std::max(worst_frame, number(i, "frame_median_ms"));
    worst_input = std::max(worst_input, number(i, "input_to_frame_p95_ms"));
    md << fmt::format(
        "| {} | {} | {} | {:.2f} | {:.2f} | {} | {} | {:.0f} ms | {:.0f} ms | "
        "{:.0f} ms |\n",
        text(c, "case"), seconds_text(number(c, "seconds")),
        seconds_text(number(c, "native_seconds")), ratio,
        number(c, "least_seconds") / number(c, "native_least_seconds"),
        ms_text(number(i, "frame_median_ms")), ms_text(frame_p95),
        number(i, "input_to_frame_p95_ms"), number(i, "input_to_whole_p95_ms"),
        number(i, "first_input_ms"));
  }
  const Json& p = *page[0];
  const double first = number(p, "first_frame_ms"), bytes = number(p, "download_bytes");
  md << fmt::format(
      "\nThe first frame from navigation, the page reloaded with a warm cache: {:.0f} ms "
      "(median of 5). What the page downloads, compressed (gzip -9): {:.2f} MB.\n",
      first, bytes / 1e6);
  targets.add(worst_ratio <= 2.0,
              fmt::format("web: compute() in WebAssembly at most 2× native, every lab "
                          "(the worst {:.2f}×)",
                          worst_ratio));
  targets.add(first <= 2000.0, fmt::format("web: the first frame within 2 s ({:.0f} ms)", first));
  // 30 fps is every other frame of the browser's 60 Hz clock: 33.33 ms, measured in its
  // 0.1 ms ticks
  targets.add(worst_frame <= 2 * 1000.0 / 60.0 + 0.1,
              fmt::format("web: 30 fps while a motion plays, every lab, the median interval "
                          "(the worst {:.1f} ms)",
                          worst_frame));
  targets.add(worst_input <= 100.0,
              fmt::format("web: an input to its frame within 100 ms at p95, every lab "
                          "(the worst {:.0f} ms)",
                          worst_input));
  targets.add(bytes <= 6e6, fmt::format("web: the page downloads at most 6 MB compressed "
                                        "({:.2f} MB)",
                                        bytes / 1e6));
}

}  // namespace bench::report
