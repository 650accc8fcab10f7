#!/usr/bin/env python3
"""rigidlab's side of the figure-speed benchmark.

Runs the labs as a user does and times them from outside and inside:

- each figure: every lab (`rigidlab list --names`) runs with
  `--figures DIR --json --timing`, whose JSON holds the wall time of drawing and
  writing each PNG and where it went (setup, layout, draw, resolve, encode); the
  best of --repeats runs per figure, with that run's phases (the first figure of
  a process includes making the drawing buffers and first use of the shaders);
- the whole figure set of a lab: the wall time of the process
  `LAB --quiet --figures DIR`, from start to exit, best of --repeats;
- every lab's figure set side by side: all labs started at once, from the first
  start to the last exit, best of --repeats;
- `rigidlab figures --out DIR`, the instructor's "all figures": process wall time,
  best of --repeats (its labs drawn by one process a processor);
- the context: bench_figure_context makes one and reports
  ContextInfo::creation_seconds (loading the backend library, the context,
  the GL entry points), best of --repeats fresh processes;
- a run without figures: `LAB --json`, process wall time, in this build
  (renderer linked) and in a build configured with RIGID_BUILD_RENDER=OFF
  (--norender DIR), alternating the two, best of --json-repeats each;
- what a linked library costs a start: the bench_startup_* programs in --startup
  DIR (a process that starts and exits, linked with nothing more, with libcairo,
  with FFmpeg), alternating, best of --json-repeats each.

Rounds go over every lab in turn, so a burst of load on the shared machine
spoils one round, not one lab. Writes a JSON array of entries
  {"group": "figures", "case": ..., "tool": "rigidlab", "seconds": s, "kind": ...}
with kind "figure" (case = the PNG's name, "lab" = its lab, "first" = true for
the first figure of its process, "phases" = {phase: seconds}), "context", "set"
(case = the lab), "side_by_side" (case = "all labs"), "front_door" (case = "rigidlab
figures"), "json_run"
("build": "render" or "norender") and "startup" ("links": "bare", "cairo" or "ffmpeg").

Usage: figures_bench.py --labs DIR --context EXE --out FILE [--norender DIR]
                        [--startup DIR] [--repeats N] [--json-repeats N]
"""

import argparse
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from progress import Progress, add_arguments, configure, detail, duration  # noqa: E402

# Rough seconds of each kind of run on this machine, for the progress line's time left.
WEIGHT = {"figures": 0.6, "set": 0.3, "side_by_side": 1.1, "front_door": 1.0, "context": 0.05,
          "animation": 9.0, "json": 0.004}

def wall(cmd, stderr=None):
    """Seconds from spawning cmd to its exit (stdout discarded); raises if it fails."""
    t0 = time.perf_counter()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=stderr)
    return time.perf_counter() - t0


def side_by_side(labs_dir, labs, work):
    """Seconds from starting every lab's figure set at once to the last one's exit."""
    t0 = time.perf_counter()
    procs = [subprocess.Popen([os.path.join(labs_dir, lab), "--quiet", "--figures",
                               os.path.join(work, "all", lab)], stdout=subprocess.DEVNULL)
             for lab in labs]
    if any(p.wait() != 0 for p in procs):
        raise RuntimeError("a lab failed while drawing side by side")
    return time.perf_counter() - t0


def measure_context(args, tick):
    """The context, in fresh processes: the best creation time."""
    best = math.inf
    info = {}
    for _ in range(args.repeats):
        out = subprocess.run([args.context], check=True, capture_output=True, text=True)
        info = json.loads(out.stdout)
        best = min(best, info["creation_seconds"])
        tick("context", "GL context")
    return {"group": "figures", "case": "context creation", "tool": "rigidlab",
            "seconds": best, "kind": "context", "backend": info.get("backend", ""),
            "renderer": info.get("gl_renderer", "")}


def measure_figures(args, labs, work, tick):
    """Per figure (inside the process), the whole set (the process), all labs side by side."""
    figure_best, figure_phases, figure_lab, first = {}, {}, {}, {}
    set_best = {lab: math.inf for lab in labs}
    all_best = front_best = math.inf
    for _ in range(args.repeats):
        for lab in labs:
            exe = os.path.join(args.labs, lab)
            d = os.path.join(work, lab)
            os.makedirs(d, exist_ok=True)
            out = json.loads(subprocess.run([exe, "--figures", d, "--json", "--timing"],
                                            check=True, capture_output=True, text=True).stdout)
            order = out["figures"]
            for name, s in out["timing"]["figure_seconds"].items():
                if s < figure_best.get(name, math.inf):
                    figure_best[name] = s
                    figure_phases[name] = out["timing"]["figure_phases"][name]
                figure_lab[name] = lab
                first[name] = bool(order) and name == order[0]
            tick("figures", f"{lab} figures")
            set_best[lab] = min(set_best[lab], wall([exe, "--quiet", "--figures", d]))
            tick("set", f"{lab} figure set")
        all_best = min(all_best, side_by_side(args.labs, labs, work))
        tick("side_by_side", "all labs side by side")
        front_best = min(front_best, wall([os.path.join(args.labs, "rigidlab"), "figures",
                                           "--out", os.path.join(work, "front")],
                                          subprocess.DEVNULL))  # its lines, a lab each
        tick("front_door", "rigidlab figures")
    entries = [{"group": "figures", "case": name, "tool": "rigidlab", "seconds": s,
                "kind": "figure", "lab": figure_lab[name], "first": first[name],
                "phases": figure_phases[name]} for name, s in figure_best.items()]
    entries += [{"group": "figures", "case": lab, "tool": "rigidlab", "seconds": set_best[lab],
                 "kind": "set"} for lab in labs]
    entries.append({"group": "figures", "case": "all labs", "tool": "rigidlab",
                    "seconds": all_best, "kind": "side_by_side", "labs": labs,
                    "processors": os.cpu_count()})
    entries.append({"group": "figures", "case": "rigidlab figures", "tool": "rigidlab",
                    "seconds": front_best, "kind": "front_door", "labs": labs,
                    "processors": os.cpu_count()})
    return entries


def measure_animation(args, work, tick):
    """An animation as a user makes one: poinsot --animate, the defaults (1280x720, 30 fps,
    10 s of video), process wall time, best of 2; and where its time went."""
    best = math.inf
    for _ in range(2):
        best = min(best, wall([os.path.join(args.labs, "poinsot"), "--quiet",
                               "--animate", os.path.join(work, "poinsot.mp4")]))
        tick("animation", "poinsot --animate")
    out = subprocess.run([os.path.join(args.labs, "poinsot"), "--json", "--timing", "--animate",
                          os.path.join(work, "poinsot.mp4")], check=True, capture_output=True,
                         text=True)
    tick("animation", "poinsot --animate --timing")
    anim = json.loads(out.stdout)["animation"]
    return {"group": "figures", "case": "poinsot animation", "tool": "rigidlab",
            "seconds": best, "kind": "animation", "frames": anim["frames"],
            "fps": anim["fps"], "size": f"{anim['width']}x{anim['height']}",
            "video_seconds": anim["duration_s"], "phases": anim["phases"]}


def alternating_best(commands, rounds, tick):
    """{name: best process wall time} of the named commands, run in turn for rounds rounds,
    the order reversed every other round: in a fixed order the first was slower
    (tennis_racquet --json 3.14 against 2.69 ms, best of 30; alternating, 2.69 against
    2.65)."""
    best = {name: math.inf for name, _ in commands}
    for r in range(rounds):
        for name, cmd in (commands if r % 2 == 0 else commands[::-1]):
            best[name] = min(best[name], wall(cmd))
            tick("json", " ".join(os.path.basename(c) for c in cmd))
    return best


def measure_json_runs(args, labs, builds, tick):
    """--json without figures: renderer linked against not built, every lab in each round."""
    best = alternating_best([((b, lab), [os.path.join(d, lab), "--json"])
                             for lab in labs for b, d in builds], args.json_repeats, tick)
    return [{"group": "figures", "case": f"{lab} --json", "tool": "rigidlab",
             "seconds": best[(b, lab)], "kind": "json_run", "build": b}
            for b, _ in builds for lab in labs]


def measure_startup(args, tick):
    """A process that starts and exits, linked with nothing more, with libcairo and with
    FFmpeg (bench_startup_*): what linking each would add to every start."""
    links = ["bare", "cairo", "ffmpeg"]
    best = alternating_best([(f"start-up ({x})",
                              [os.path.join(args.startup, f"bench_startup_{x}")]) for x in links],
                            args.json_repeats, tick)
    return [{"group": "figures", "case": f"start-up ({x})", "tool": "rigidlab",
             "seconds": best[f"start-up ({x})"], "kind": "startup", "links": x} for x in links]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--labs", required=True, help="directory with the lab executables")
    ap.add_argument("--context", required=True, help="the bench_figure_context executable")
    ap.add_argument("--norender", help="labs directory of a build without the renderer")
    ap.add_argument("--startup", help="directory with the bench_startup_* programs")
    ap.add_argument("--out", required=True)
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--json-repeats", type=int, default=30)
    add_arguments(ap)
    args = ap.parse_args()
    configure(args)

    labs = subprocess.run([os.path.join(args.labs, "rigidlab"), "list", "--names"], check=True,
                          capture_output=True, text=True).stdout.split()
    builds = [("render", args.labs)] + ([("norender", args.norender)] if args.norender else [])
    json_runs = len(labs) * len(builds) + (3 if args.startup else 0)
    progress = Progress("bench figures", None,
                        args.repeats * (WEIGHT["context"] + WEIGHT["side_by_side"]
                                        + WEIGHT["front_door"] + len(labs) * (WEIGHT["figures"] + WEIGHT["set"]))
                        + 3 * WEIGHT["animation"] + args.json_repeats * json_runs * WEIGHT["json"],
                        args.quiet)
    done = 0.0

    def tick(kind, now):
        nonlocal done
        done += WEIGHT[kind]
        progress.update(done, now)

    work = tempfile.mkdtemp(prefix="rigid_figbench_")
    try:
        entries = [measure_context(args, tick)] + measure_figures(args, labs, work, tick)
        animation = measure_animation(args, work, tick)
        entries.append(animation)
        entries += measure_json_runs(args, labs, builds, tick)
        if args.startup:
            entries += measure_startup(args, tick)
    finally:
        shutil.rmtree(work, ignore_errors=True)

    for e in entries:
        detail(f"figures_bench: {e['case']} ({e['kind']}{', ' + e['build'] if 'build' in e else ''})"
               f": {e['seconds'] * 1e3:.2f} ms")
    with open(args.out + ".tmp", "w") as f:
        json.dump(entries, f, indent=1)
    os.replace(args.out + ".tmp", args.out)
    progress.finish(f"{len(labs)} labs, {len(entries)} entries in {duration(progress.seconds())} "
                    f"(the poinsot animation: {animation['seconds']:.2f} s for "
                    f"{animation['video_seconds']:g} s of video); wrote {args.out}")


if __name__ == "__main__":
    main()
