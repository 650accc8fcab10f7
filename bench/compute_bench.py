#!/usr/bin/env python3
"""A lab's answer against its compute budget: what the dearest inputs cost in time.

The budget is counted, never timed (labs/common/integrated_run.h: kMaxRunWork for a
lab's own run, kMaxComputeWork for the whole answer, in Runge-Kutta evaluations'
worth, rigid::work_done), so every machine gives the same answer; this bench says
what it buys here. Each case runs the lab's command line with --json (best wall time
of --repeats), and reads the work the answer reports ("work") and the periods the
comparison at equal cost ranked over: the lab's defaults, a run of 1000 periods (the
most the comparison ranks), and the dearest inputs each lab accepts (its own run
near its cap beside the comparison, the tightest tolerance, 1e8 and 1e9 periods).

Writes a JSON array of entries {"group": "compute", "case": ..., "tool": "rigidlab",
"seconds": best, "work": ..., "ranked_periods": ...} and prints a markdown table
with the wall time per million units of work. Usage:
compute_bench.py --labs DIR --out FILE [--repeats N]
"""

import argparse
import json
import subprocess
import sys
import time

CASES = [
    ("poinsot", []),
    ("poinsot", ["--periods", "1000"]),
    ("poinsot", ["--periods", "1e8"]),
    ("poinsot", ["--method", "rk4", "--periods", "1999"]),
    ("poinsot", ["--method", "splitting", "--periods", "1999"]),
    ("poinsot", ["--method", "splitting4", "--periods", "399"]),
    ("poinsot", ["--method", "vern9", "--tolerance", "1e-14", "--periods", "8000"]),
    ("poinsot", ["--method", "bulirsch-stoer", "--tolerance", "1e-14", "--periods", "2000"]),
    ("poinsot", ["--method", "rkf78", "--project", "--tolerance", "1e-14", "--periods", "3000"]),
    ("top_nutation", []),
    ("top_nutation", ["--periods", "1000"]),
    ("top_nutation", ["--arm", "1e12", "--periods", "1e9"]),
    ("top_nutation", ["--arm", "1e6", "--periods", "1000"]),
    ("top_nutation", ["--method", "rk4", "--periods", "1999"]),
    ("top_nutation", ["--method", "splitting4", "--periods", "399"]),
    ("top_nutation", ["--method", "vern9", "--tolerance", "1e-14", "--periods", "8000"]),
    ("top_nutation", ["--method", "bulirsch-stoer", "--tolerance", "1e-14", "--periods", "2000"]),
    ("tennis_racquet", []),
    ("tennis_racquet", ["--method", "rk4", "--periods", "1999"]),
    ("tennis_racquet", ["--method", "splitting", "--periods", "1999"]),
    ("tennis_racquet", ["--method", "splitting4", "--periods", "399"]),
]


def run(labs, lab, args, repeats):
    best, results, status = float("inf"), {}, 0
    for _ in range(repeats):
        start = time.perf_counter()
        done = subprocess.run([f"{labs}/{lab}", *args, "--json"], capture_output=True, text=True)
        best = min(best, time.perf_counter() - start)
        status = done.returncode
        if status == 0:
            results = json.loads(done.stdout)["results"]
    return best, results, status


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--labs", required=True, help="the directory of the lab programs")
    parser.add_argument("--out", required=True, help="the JSON entries to write")
    parser.add_argument("--repeats", type=int, default=3)
    a = parser.parse_args()
    entries = []
    print("| lab | inputs | wall (best) | work | per 1M work | ranked periods |")
    print("|---|---|---|---|---|---|")
    for lab, args in CASES:
        seconds, results, status = run(a.labs, lab, args, a.repeats)
        work = results.get("work")
        ranked = results.get("equal_cost_periods")
        entries.append({"group": "compute", "case": " ".join([lab, *args]), "tool": "rigidlab",
                        "seconds": seconds, "work": work, "ranked_periods": ranked,
                        "status": status})
        per = f"{seconds / work * 1e6 * 1e3:.1f} ms" if work else "-"
        shown = "refused" if status else (f"{work / 1e6:.1f}M" if work is not None else "-")
        print(f"| {lab} | `{' '.join(args) or '(defaults)'}` | {seconds:.3f} s | {shown} | {per} "
              f"| {'-' if ranked is None else f'{ranked:.0f}'} |")
    with open(a.out, "w") as f:
        json.dump(entries, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
