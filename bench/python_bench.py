#!/usr/bin/env python3
"""import rigidlab's speed: what a Python call costs beyond the lab's own computation,
and a sweep from Python against the same sweep as processes of the command line.

- overhead: for each lab at its defaults, --repeats calls from Python (rl.LAB(), the
  Result built: JSON parsed, results, series, figures listed) and --repeats of the same
  computation timed in C++ alone (_rigidlab._compute_seconds: session_at in a loop, the
  GIL released). The overhead is Python's median (p95) less C++'s median (p95); the goal
  is at most 10 % of the computation or 20 us, whichever is larger.
- sweep: --bodies tennis_racquet bodies (I1 = 1, I3 = 2, I2 spread between them; the
  growth rate and the first flip read from each) on a thread pool of --threads, against
  --processes runs of the lab's program with --json (the same bodies, one at a time,
  as a shell loop would), scaled to --bodies: the ratio is the Python sweep's speed-up.

Writes a JSON array of entries {"group": "python", "case": ..., "kind": ..., "tool":
..., "seconds": ..., ...} and prints a markdown table. Usage: python_bench.py --labs DIR
--out FILE (PYTHONPATH at the build's python/).
"""

import argparse
import json
import os
import statistics
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

rl = None  # import rigidlab, once the arguments are read (--help needs no module)


def p95(values):
    return sorted(values)[min(len(values) - 1, int(0.95 * len(values)))]


def overhead(lab, repeats):
    fn = getattr(rl, lab)
    fn()  # warm: the first call loads what a lab's figures need
    python = []
    for _ in range(repeats):
        start = time.perf_counter()
        fn()
        python.append(time.perf_counter() - start)
    cpp = rl._rigidlab._compute_seconds(lab, [], repeats)
    med = statistics.median(python) - statistics.median(cpp)
    tail = p95(python) - p95(cpp)
    goal = max(0.10 * statistics.median(cpp), 20e-6)
    return {"group": "python", "case": lab, "kind": "overhead", "tool": "rigidlab",
            "seconds": med, "p95": tail, "compute_seconds": statistics.median(cpp),
            "compute_p95": p95(cpp), "python_seconds": statistics.median(python),
            "goal_seconds": goal, "repeats": repeats}


def bodies(count):
    return [1.0 + (k + 0.5) / count for k in range(count)]


def racquet(i2):
    r = rl.tennis_racquet(inertia=(1.0, i2, 2.0))
    return r["growth_rate_per_s"], r["first_flip_s"]


def sweep(count, threads, processes, labs_dir):
    i2s = bodies(count)
    start = time.perf_counter()
    with ThreadPoolExecutor(threads) as pool:
        python_results = list(pool.map(racquet, i2s))
    python_seconds = time.perf_counter() - start
    # the same bodies as processes, one at a time: a sample of `processes`, scaled
    sample = i2s[:: max(1, count // processes)][:processes]
    program = os.path.join(labs_dir, "tennis_racquet")
    start = time.perf_counter()
    for k, i2 in enumerate(sample):
        out = subprocess.run([program, "--json", f"--inertia=1,{i2!r},2"], check=True,
                             capture_output=True, text=True).stdout
        results = json.loads(out)["results"]
        index = i2s.index(i2)
        if (results["growth_rate_per_s"], results["first_flip_s"]) != python_results[index]:
            raise SystemExit(f"the program and Python disagree at I2 = {i2}")
    process_seconds = (time.perf_counter() - start) * count / len(sample)
    return [
        {"group": "python", "case": f"sweep of {count} racquet bodies", "kind": "sweep",
         "tool": f"rigidlab from Python, {threads} threads", "seconds": python_seconds},
        {"group": "python", "case": f"sweep of {count} racquet bodies", "kind": "sweep",
         "tool": "the command line, one process a body",
         "seconds": process_seconds, "measured_processes": len(sample)},
    ]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--labs", required=True, help="the folder of the lab programs")
    parser.add_argument("--out", required=True)
    parser.add_argument("--repeats", type=int, default=200)
    parser.add_argument("--bodies", type=int, default=10000)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--processes", type=int, default=500)
    args = parser.parse_args()
    global rl
    import rigidlab as rl
    entries = [overhead(lab, args.repeats) for lab in rl.labs()]
    entries += sweep(args.bodies, args.threads, args.processes, args.labs)
    with open(args.out, "w") as f:
        json.dump(entries, f, indent=1)
    print("| lab | compute median | p95 | Python call's own median | p95 | goal |")
    print("|---|---|---|---|---|---|")
    for e in entries:
        if e["kind"] == "overhead":
            print(f"| {e['case']} | {e['compute_seconds'] * 1e3:.3f} ms | "
                  f"{e['compute_p95'] * 1e3:.3f} ms | {e['seconds'] * 1e6:.1f} us | "
                  f"{e['p95'] * 1e6:.1f} us | {e['goal_seconds'] * 1e6:.0f} us |")
    python, process = (e for e in entries if e["kind"] == "sweep")
    print(f"\n{python['case']}: {python['tool']} {python['seconds']:.2f} s; "
          f"{process['tool']} {process['seconds']:.1f} s (from {process['measured_processes']} "
          f"processes); ratio {process['seconds'] / python['seconds']:.0f}x")
    return 0


if __name__ == "__main__":
    sys.exit(main())
