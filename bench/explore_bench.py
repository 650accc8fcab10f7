#!/usr/bin/env python3
"""The explorer's speed, every lab, at the window size a student opens (1280x720).

Each lab's explorer runs under xvfb-run (Mesa's llvmpipe, this machine's cores)
with a script (rigidlab-explore --script) and --frame-log, which records each
frame's wall time from the end of waiting for events to the end of the buffer
swap:

- frame: the motion played (or, for a lab without one, the view turned a few
  degrees a frame, so every frame redraws the scene) for --frames frames,
  unpaced: median and 95th percentile of the frame time. Done with 4x MSAA (the
  explorer's default) and with 2x2 supersampling (RIGID_GL_SAMPLES=0), to say
  which antialiasing reaches 60 fps;
- latency: an input moved to a new value each frame, alternating between two
  values on its slider (--moves times): the frame time of the frames in which
  the inputs changed, which holds the recomputation (the lab's preview),
  figures described again, the scene and the plot redrawn and the frame shown:
  the time from a slider change to the frame that shows it. Twice: dragged
  (the slider held, the camera kept) and typed (a value entered, after which
  the camera is fitted to the motion's 16 frames again, as --animate fits it);
  football's input is a choice, a click, so both are its typed case;
- phases: the motion played again with --frame-phases, which waits for the GL at
  the end of each phase (so these frames are a little slower than the unpaced ones):
  the median of each phase, where a frame's time goes;
- idle: the explorer opened with no script and paused (space sent with
  xdotool), its CPU time (utime + stime from /proc) over --idle seconds, as a
  share of one core.

Writes a JSON array of entries {"group": "explore", "case": LAB, "kind": ...,
"tool": "rigidlab", "seconds": median, "p95": ..., ...} and prints a markdown
table. Usage: explore_bench.py --explorer EXE --out FILE [--frames N] [--moves N]
"""

import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

# A change a student makes on each lab's slider, and back (two values of one input).
MOVES = {
    "lamina_tensor": ("--axis-deg", "20", "40"),
    "tire_balancing": ("--tilt-deg", "1", "2"),
    "poinsot": ("--mass", "3", "4"),
    "tennis_racquet": ("--omega", "10", "12"),
    "football": ("--preset", "football", "frisbee"),
    "top_nutation": ("--mass", "2", "2.5"),
}
XVFB = ["xvfb-run", "-a", "-s", "-screen 0 1280x800x24"]


def percentile(values, p):
    v = sorted(values)
    return v[min(len(v) - 1, int(round(p / 100 * (len(v) - 1))))]


def run_script(explorer, lab, script, env_extra=None, phases=False):
    """Runs the explorer on `lab` with `script`; returns its frame log."""
    with tempfile.TemporaryDirectory() as d:
        script_file = os.path.join(d, "script.txt")
        log = os.path.join(d, "frames.json")
        with open(script_file, "w") as f:
            f.write(script)
        env = dict(os.environ, **(env_extra or {}))
        subprocess.run(XVFB + [explorer, lab, "--script", script_file, "--frame-log", log]
                       + (["--frame-phases"] if phases else []),
                       check=True, env=env, stdout=subprocess.DEVNULL, timeout=600)
        with open(log) as f:
            return json.load(f)


def frame_times(explorer, lab, frames, env_extra=None, phases=False):
    # the first frames build fonts, shaders and buffers: left out
    warm = 10
    if lab in ("lamina_tensor", "tire_balancing"):
        body = "".join("turn 2 0\nframes 1\n" for _ in range(frames + warm))
    else:
        body = f"play {(frames + warm) / 30:.4f}\n"
    log = run_script(explorer, lab, body + "quit\n", env_extra, phases)
    t = [f["seconds"] for f in log["frames"]][warm:]
    return log, t


# A frame's phases, as --frame-phases names them, in the order a frame goes through them.
PHASES = ("actions", "scene", "scene_setup", "scene_layout", "scene_draw", "scene_resolve", "plot",
          "widgets", "widgets_drawn", "shown")


def frame_phases(explorer, lab, frames):
    """The median of each phase over the motion played with --frame-phases."""
    log, t = frame_times(explorer, lab, frames, phases=True)
    timed = log["frames"][10:]
    out = {p: statistics.median(f["phases"][p] for f in timed) for p in PHASES}
    out["frame"] = statistics.median(t)
    return out


def latencies(explorer, lab, moves, how):
    """`how` "drag": the slider held and moved a step each frame (the camera holds
    still); "set": a value typed and entered (the view is fitted to it again)."""
    flag, a, b = MOVES[lab]
    step = "" if how == "drag" else "frames 1\n"
    body = "frames 10\n" + "".join(
        f"{how} {flag} {b if k % 2 == 0 else a}\n{step}" for k in range(moves))
    log = run_script(explorer, lab, body + "quit\n")
    return [f["seconds"] for f in log["frames"] if f["changed"]]


def idle_cpu(explorer, lab, seconds):
    proc = subprocess.Popen(XVFB + [explorer, lab], stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL, start_new_session=True)
    try:
        # the explorer's own pid: the newest rigidlab-explore child
        pid = None
        for _ in range(100):
            time.sleep(0.1)
            out = subprocess.run(["pgrep", "-n", "-f", f"{explorer} {lab}"],
                                 capture_output=True, text=True).stdout.split()
            if out:
                pid = int(out[0])
                break
        if pid is None:
            return None
        time.sleep(2.0)
        # the display and its key, as xvfb-run gave them to the explorer
        env = dict(os.environ)
        with open(f"/proc/{pid}/environ", "rb") as f:
            for item in f.read().split(b"\0"):
                for name in (b"DISPLAY=", b"XAUTHORITY="):
                    if item.startswith(name):
                        env[name[:-1].decode()] = item[len(name):].decode()
        if lab not in ("lamina_tensor", "tire_balancing"):
            # the Pause button clicked (the time bar under the scene, at 1280x720), the
            # pointer then moved off the window's widgets
            subprocess.run(["sh", "-c", "W=$(xdotool search --sync --name 'rigidlab explore') && "
                            "xdotool mousemove --window $W 377 451 sleep 0.2 click 1 sleep 0.2 "
                            "mousemove --window $W 600 200"], env=env, timeout=20,
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        time.sleep(1.0)
        tick = os.sysconf("SC_CLK_TCK")

        def cpu():
            with open(f"/proc/{pid}/stat") as f:
                fields = f.read().rsplit(")", 1)[1].split()
            return (int(fields[11]) + int(fields[12])) / tick

        c0, t0 = cpu(), time.monotonic()
        time.sleep(seconds)
        c1, t1 = cpu(), time.monotonic()
        return (c1 - c0) / (t1 - t0)
    finally:
        os.killpg(proc.pid, 15)
        proc.wait()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--explorer", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--frames", type=int, default=120)
    ap.add_argument("--moves", type=int, default=40)
    ap.add_argument("--idle", type=float, default=5.0)
    ap.add_argument("--labs", default=",".join(MOVES),
                    help="the labs, comma-separated (default: every lab)")
    args = ap.parse_args()
    labs = [lab for lab in args.labs.split(",") if lab]
    if unknown := [lab for lab in labs if lab not in MOVES]:
        ap.error(f"--labs: unknown lab {unknown[0]!r} (one of {', '.join(MOVES)})")
    if shutil.which("xvfb-run") is None:
        print("explore_bench: xvfb-run not found: skipped", file=sys.stderr)
        json.dump([], open(args.out, "w"))
        return
    entries, rows, phase_rows = [], [], []
    renderer = ""
    for lab in labs:
        log, msaa = frame_times(args.explorer, lab, args.frames)
        renderer = log["gl_renderer"]
        _, ssaa = frame_times(args.explorer, lab, args.frames, {"RIGID_GL_SAMPLES": "0"})
        lat = latencies(args.explorer, lab, args.moves,
                        "set" if MOVES[lab][0] == "--preset" else "drag")
        typed = latencies(args.explorer, lab, args.moves, "set")
        idle = idle_cpu(args.explorer, lab, args.idle)
        phases = frame_phases(args.explorer, lab, args.frames)
        entries.append({"group": "explore", "case": lab, "kind": "frame_phases",
                        "tool": "rigidlab", "seconds": phases["frame"], "phases": phases,
                        "size": "1280x720", "renderer": renderer})
        phase_rows.append((lab, phases))
        for kind, t in (("frame_msaa4", msaa), ("frame_ssaa2x2", ssaa), ("latency_drag", lat),
                        ("latency_typed", typed)):
            entries.append({"group": "explore", "case": lab, "kind": kind, "tool": "rigidlab",
                            "seconds": statistics.median(t), "p95": percentile(t, 95),
                            "n": len(t), "size": "1280x720", "renderer": renderer})
        entries.append({"group": "explore", "case": lab, "kind": "idle_cpu", "tool": "rigidlab",
                        "share_of_core": idle})
        rows.append((lab, statistics.median(msaa), percentile(msaa, 95), statistics.median(ssaa),
                     percentile(ssaa, 95), statistics.median(lat), percentile(lat, 95),
                     statistics.median(typed), percentile(typed, 95), idle))
    with open(args.out, "w") as f:
        json.dump(entries, f, indent=1)
    print(f"explorer at 1280x720 on {renderer}, {os.cpu_count()} cores (ms; idle: CPU share)")
    print("| lab | frame, 4x MSAA: median | p95 | frame, 2x2 SSAA: median | p95 | "
          "slider dragged to frame: median | p95 | value typed to frame: median | p95 | "
          "idle, paused: CPU |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for lab, a, b, c, d, e, f, g, h, idle in rows:
        idle_text = "n/a" if idle is None else f"{100 * idle:.1f} %"
        print(f"| {lab} | {1e3 * a:.1f} | {1e3 * b:.1f} | {1e3 * c:.1f} | {1e3 * d:.1f} | "
              f"{1e3 * e:.1f} | {1e3 * f:.1f} | {1e3 * g:.1f} | {1e3 * h:.1f} | {idle_text} |")
    print("\nwhere a frame's time goes, 4x MSAA (ms, medians; each phase waited for)")
    print("| lab | " + " | ".join(PHASES) + " | frame |")
    print("|---|" + "---|" * (len(PHASES) + 1))
    for lab, p in phase_rows:
        print(f"| {lab} | " + " | ".join(f"{1e3 * p[k]:.2f}" for k in PHASES)
              + f" | {1e3 * p['frame']:.1f} |")


if __name__ == "__main__":
    main()
