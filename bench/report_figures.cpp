// bench_report's figure-speed section: rigidlab against matplotlib per figure with
// where rigidlab's time went, the context, the import, each lab's whole figure set,
// every lab's set side by side, a run without figures against a build without the
// renderer, an animation; the issues' targets.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "report.h"

namespace bench::report {

namespace {

constexpr double kFigureSpeedup = 4.0;    // matplotlib / rigidlab, per figure
constexpr double kSetBudget = 0.5;        // s, lamina_tensor + tire_balancing figure sets
constexpr double kAllSetsBudget = 1.0;    // s, every lab's figure set side by side
constexpr double kFrontDoorBudget = 0.7;  // s, rigidlab figures: every lab's figures
constexpr double kNoFigureSlack = 1.05;   // renderer linked / not, --json run (timer noise)
constexpr const char* kPhases[] = {"setup", "layout", "draw", "resolve", "encode"};

struct Figure {
  double ours = NAN, peer = NAN;
  bool first = false;
  std::string lab;
  std::map<std::string, double> phases;
};

// The "figures" entries, by kind.
struct FigureRuns {
  std::vector<std::string> order;  // the figures, as they came
  std::map<std::string, Figure> figures;
  std::map<std::string, double> set_wall, json_render, json_norender;
  std::vector<std::string> labs;
  double context = NAN, import = NAN, side_by_side = NAN, front_door = NAN;
  std::string renderer, side_by_side_labs, front_door_labs;
  const Json* animation = nullptr;  // rigidlab's animation entry
  double animation_peer = NAN;
};

// What the table of figures adds up: each lab's figures, and the per-figure target.
struct FigureSums {
  std::map<std::string, double> lab_ours, lab_peer;
  std::vector<std::string> misses;
  double worst = INFINITY;
};

// A lab's sum, 0 if none of its figures was timed.
double or_zero(const std::map<std::string, double>& sums, const std::string& lab) {
  const auto it = sums.find(lab);
  return it != sums.end() ? it->second : 0.0;
}

std::string ms(double s) {
  return std::isfinite(s) ? fmt::format("{:.1f} ms", s * 1e3) : "—";
}

// "7 labs on 2 processors": what a run of every lab's figures had.
std::string labs_on_processors(const Json& e) {
  return fmt::format("{} labs on {} processors", e.value("labs", Json::array()).size(),
                     e.value("processors", 0));
}

FigureRuns read_figure_runs(const Json& all) {
  FigureRuns r;
  for (const Json& e : all) {
    if (text(e, "group") != "figures") continue;
    const std::string kind = text(e, "kind"), name = text(e, "case"), tool = text(e, "tool");
    const double s = number(e, "seconds");
    if (kind == "figure") {
      if (!r.figures.count(name)) r.order.push_back(name);
      Figure& f = r.figures[name];
      (tool == "matplotlib" ? f.peer : f.ours) = s;
      if (tool == "rigidlab") {
        f.first = e.value("first", false);
        f.lab = text(e, "lab");
        if (e.contains("phases"))
          for (const char* phase : kPhases) f.phases[phase] = number(e["phases"], phase);
      }
    } else if (kind == "context") {
      r.context = s;
      r.renderer = text(e, "backend") + ", " + text(e, "renderer");
    } else if (kind == "import") {
      r.import = s;
    } else if (kind == "set") {
      r.set_wall[name] = s;
      r.labs.push_back(name);
    } else if (kind == "side_by_side") {
      r.side_by_side = s;
      r.side_by_side_labs = labs_on_processors(e);
    } else if (kind == "front_door") {
      r.front_door = s;
      r.front_door_labs = labs_on_processors(e);
    } else if (kind == "animation") {
      if (tool == "rigidlab")
        r.animation = &e;
      else
        r.animation_peer = s;
    } else if (kind == "json_run") {
      const std::string lab = name.substr(0, name.find(' '));
      (text(e, "build") == "norender" ? r.json_norender : r.json_render)[lab] = s;
    }
  }
  return r;
}

// Every figure: rigidlab's time, its phases and matplotlib's; then the fixed costs.
FigureSums figure_table(std::ostream& md, const FigureRuns& r) {
  FigureSums sums;
  md << "\n## Figures: rigidlab against matplotlib\n\n"
        "Each figure at 1600×1200, drawn and written as PNG. rigidlab: the lab's own timing "
        "(`--figures DIR --json --timing`: wall time of drawing and PNG encoding of that "
        "figure; a lab encodes one figure on a second thread while it draws the next, so a "
        "process takes less than the sum), best of several runs of the lab. A 3D scene is "
        "drawn with OpenGL (4× MSAA, resolved and read back); a plot by cairo's rasteriser on "
        "the CPU. A lab loads the GL library and makes the context before its first figure "
        "(reported below, as matplotlib's import is); the first scene of a process (marked ¹ "
        "where it is the first figure) still pays the first use of its shaders and of the "
        "1600×1200 multisampled buffers. "
        "matplotlib (Agg, Debian's python3-matplotlib): the same plot from figure creation to the "
        "PNG "
        "on disk, after import, best of several; 3D scenes with mplot3d.\n\n"
        "Where rigidlab's time went (the run that gave its best time; `--timing`, each GL "
        "phase waited for with glFinish): **setup** for a scene binding and clearing the "
        "1600×1200 buffers with 4 samples a pixel (the first scene of a process makes them: "
        "llvmpipe zeroes 69 MB of fresh pages), for a plot making cairo's image; **layout** "
        "placing text, legend and the fit (CPU); **draw** until the rasteriser finished (the "
        "first scene also loads its shaders from Mesa's cache); **resolve** averaging a "
        "scene's samples and reading the pixels back, or a plot's pixels copied out of "
        "cairo's image; **encode** PNG and the atomic write.\n\n"
        "| figure | rigidlab | setup | layout | draw | resolve | encode | matplotlib | "
        "matplotlib / rigidlab |\n|---|---|---|---|---|---|---|---|---|\n";
  double sum_ours = 0, sum_peer = 0;
  double floor_later = INFINITY;  // the least setup + resolve + encode of a figure not first
  for (const std::string& name : r.order) {
    const Figure& f = r.figures.at(name);
    const double ratio = f.peer / f.ours;
    std::string phases;
    for (const char* phase : kPhases)
      phases += " " + (f.phases.count(phase) ? ms(f.phases.at(phase)) : std::string("—")) + " |";
    if (!f.first && f.phases.size() == std::size(kPhases))
      floor_later = std::min(floor_later,
                             f.phases.at("setup") + f.phases.at("resolve") + f.phases.at("encode"));
    md << fmt::format("| {}{} | {} |{} {} | {} |\n", name, f.first ? " ¹" : "", ms(f.ours), phases,
                      ms(f.peer), std::isfinite(ratio) ? fmt::format("{:.2f}×", ratio) : "—");
    if (std::isfinite(f.ours)) sums.lab_ours[f.lab] += f.ours;
    if (std::isfinite(f.peer)) sums.lab_peer[f.lab] += f.peer;
    if (!std::isfinite(ratio)) continue;
    sums.worst = std::min(sums.worst, ratio);
    sum_ours += f.ours;  // both sums over the r.figures both tools drew
    sum_peer += f.peer;
    if (ratio < kFigureSpeedup) sums.misses.push_back(fmt::format("{} {:.2f}×", name, ratio));
  }
  md << fmt::format("| **all figures** | {} | | | | | | {} | {} |\n", ms(sum_ours), ms(sum_peer),
                    sum_ours > 0 ? fmt::format("{:.2f}×", sum_peer / sum_ours) : "—");
  md << "\n";
  if (std::isfinite(floor_later))
    md << "- the least setup + resolve + encode of a figure that is not its process's first: "
       << ms(floor_later)
       << " (what any figure costs before anything is drawn in it, on this renderer)\n";
  if (std::isfinite(r.context))
    md << "- context creation (rigidlab, " << r.renderer << "): " << ms(r.context)
       << " (bench_figure_context, best of fresh processes)\n";
  if (std::isfinite(r.import))
    md << "- matplotlib import (matplotlib, pyplot, mplot3d, numpy; once per process, not in "
          "the figure times): "
       << ms(r.import) << "\n";
  return sums;
}

// Each lab's whole figure set, every lab's side by side, a run without figures.
void lab_tables(std::ostream& md, const FigureRuns& r, const FigureSums& sums) {
  if (!r.labs.empty()) {
    md << "\n**Whole figure set per lab.** rigidlab: wall time of the process "
          "`LAB --quiet --figures DIR`, start to exit (best of runs); matplotlib: its figures "
          "plus its import, as one fresh process would pay.\n\n"
          "| lab | rigidlab process | rigidlab figures | matplotlib figures + import |\n"
          "|---|---|---|---|\n";
    for (const std::string& lab : r.labs)
      md << fmt::format("| {} | {} | {} | {} |\n", lab, ms(r.set_wall.at(lab)),
                        ms(or_zero(sums.lab_ours, lab)),
                        sums.lab_peer.count(lab) ? ms(sums.lab_peer.at(lab) + r.import) : "—");
  }
  if (std::isfinite(r.side_by_side))
    md << "\n**Every lab's figure set side by side** (all started at once, first start to last "
          "exit, best of runs; "
       << r.side_by_side_labs << "): " << ms(r.side_by_side) << "\n";
  if (std::isfinite(r.front_door))
    md << "\n**`rigidlab figures --out DIR`** (every lab's figures as an instructor draws them: "
          "one drawing process a processor, best of runs): "
       << ms(r.front_door) << "\n";
  if (!r.json_render.empty()) {
    md << "\n**A run without figures** (`LAB --json`, process wall time, best of many, the two "
          "builds alternating): this build against one configured with "
          "`-DRIGID_BUILD_RENDER=OFF`.\n\n"
          "| lab | renderer linked | no renderer | ratio |\n|---|---|---|---|\n";
    for (const auto& [lab, s] : r.json_render) {
      const double other = r.json_norender.count(lab) ? r.json_norender.at(lab) : NAN;
      md << fmt::format("| {} | {} | {} | {} |\n", lab, ms(s), ms(other),
                        std::isfinite(other) ? fmt::format("{:.2f}", s / other) : "—");
    }
  }
}

// An animation, with its target.
void animation_paragraph(std::ostream& md, const FigureRuns& r, Targets& targets) {
  if (r.animation != nullptr) {
    const double s = number(*r.animation, "seconds"), video = number(*r.animation, "video_seconds");
    md << fmt::format(
        "\n**An animation**: `poinsot --animate FILE.mp4` with its defaults, {} frames "
        "at {} and {:g} fps ({:g} s of video), process wall time, best of 2: **{:.2f} s** ({:.2f}× "
        "real time); matplotlib's FuncAnimation drawing the same scene each frame through its "
        "ffmpeg writer (H.264, the same preset and CRF): {}.\n",
        number(*r.animation, "frames"), text(*r.animation, "size"), number(*r.animation, "fps"),
        video, s, s / video,
        std::isfinite(r.animation_peer)
            ? fmt::format("{:.1f} s ({:.1f}× rigidlab's)", r.animation_peer, r.animation_peer / s)
            : std::string("not measured (ffmpeg not installed)"));
    if (r.animation->contains("phases")) {
      md << "Where the frames' time went (`--timing`, each GL phase waited for, so the sum "
            "exceeds the untimed run): ";
      std::vector<std::string> parts;
      for (const auto& [phase, v] : (*r.animation)["phases"].items())
        parts.push_back(fmt::format("{} {:.2f} s", phase, v.get<double>()));
      md << fmt::format("{}", fmt::join(parts, ", "))
         << ". Encoding runs on a second thread: "
            "'encoder_wait' is the time drawing waited for it.\n";
    }
    targets.add(s <= video,
                fmt::format("animation: rendering and encoding {:g} s of 1280x720 30 fps "
                            "video in at most {:g} s: {:.2f} s",
                            video, video, s));
  }
}

// The other figure targets, after the animation's.
void figure_targets(const FigureRuns& r, const FigureSums& sums, Targets& targets) {
  if (std::isfinite(sums.worst))
    targets.add(sums.misses.empty(),
                fmt::format("figures: every figure at least {:.0f}× faster than "
                            "matplotlib, PNG encoding included (worst {:.2f}×{}{})",
                            kFigureSpeedup, sums.worst, sums.misses.empty() ? "" : "; below: ",
                            fmt::format("{}", fmt::join(sums.misses, ", "))));
  if (r.set_wall.count("lamina_tensor") && r.set_wall.count("tire_balancing")) {
    const double both = r.set_wall.at("lamina_tensor") + r.set_wall.at("tire_balancing");
    targets.add(
        both < kSetBudget,
        fmt::format(
            "figures: whole figure set of lamina_tensor + "
            "tire_balancing under {:.1f} s: {:.3f} s (process wall time, "
            "{:.3f} s + {:.3f} s; figures alone {:.3f} s)",
            kSetBudget, both, r.set_wall.at("lamina_tensor"), r.set_wall.at("tire_balancing"),
            or_zero(sums.lab_ours, "lamina_tensor") + or_zero(sums.lab_ours, "tire_balancing")));
  }
  if (std::isfinite(r.side_by_side))
    targets.add(r.side_by_side < kAllSetsBudget,
                fmt::format("figures: every lab's whole figure set, side by side, "
                            "under {:.1f} s: {:.3f} s ({})",
                            kAllSetsBudget, r.side_by_side, r.side_by_side_labs));
  if (std::isfinite(r.front_door))
    targets.add(r.front_door <= kFrontDoorBudget,
                fmt::format("figures: rigidlab figures, every lab's figures, within {:.1f} s: "
                            "{:.3f} s ({})",
                            kFrontDoorBudget, r.front_door, r.front_door_labs));
  for (const auto& [lab, s] : r.json_render) {
    if (!r.json_norender.count(lab)) continue;
    const double ratio = s / r.json_norender.at(lab);
    targets.add(ratio <= kNoFigureSlack,
                fmt::format("figures: {} --json with the renderer linked no slower "
                            "than without ({} against {}, ratio {:.2f}; ≤ {:.2f} allowed for "
                            "timer noise)",
                            lab, ms(s), ms(r.json_norender.at(lab)), ratio, kNoFigureSlack));
  }
}

}  // namespace

void figures_section(std::ostream& md, const Json& all, Targets& targets) {
  const FigureRuns r = read_figure_runs(all);
  if (r.figures.empty()) return;
  const FigureSums sums = figure_table(md, r);
  lab_tables(md, r, sums);
  animation_paragraph(md, r, targets);
  figure_targets(r, sums, targets);
}

}  // namespace bench::report
