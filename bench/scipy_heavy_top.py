#!/usr/bin/env python3
"""SciPy peers for the heavy-top work-precision benchmark.

Integrates the same 7-dimensional system as bench_heavy_top (Euler's equations
about the pivot with the gravity torque -mgl e3 x (R^T z), and the body-to-space
quaternion kinematics) with scipy.integrate.solve_ivp, methods DOP853 and RK45,
as the SciPy documentation shows: a plain Python right-hand side, rtol = tol and
atol = 1e-3 * tol for tol = 1e-3 .. 1e-13. The problems, their start states and
the exact theta(t_end) come from heavy_top_reference.json (rigid::HeavyTopExact).
Each solve is timed after import, best of a few repeats; a sweep stops once one
solve takes more than MAX_SOLVE_SECONDS. The error is |theta(t_end) - theta_exact|,
theta the tilt of the symmetry axis R e3 from z.

Usage: scipy_heavy_top.py --reference heavy_top_reference.json --out scipy_heavy_top.json
"""
import argparse
import json
import math
import os
import time

from scipy.integrate import solve_ivp

from progress import Progress, add_arguments, configure, detail, duration
from scipy_work_precision import best_time  # the same timing as the free body's peers

MAX_SOLVE_SECONDS = 4.0
ATOL_FACTOR = 1e-3


def top_rhs(I, Is, mgl):
    def rhs(t, x):
        w1, w2, w3, qw, qx, qy, qz = x
        n2 = qw * qw + qx * qx + qy * qy + qz * qz
        ux = 2 * (qx * qz - qw * qy) / n2
        uy = 2 * (qy * qz + qw * qx) / n2
        return [
            (mgl * uy - w2 * w3 * (Is - I)) / I,
            (-mgl * ux - w3 * w1 * (I - Is)) / I,
            0.0,
            0.5 * (-qx * w1 - qy * w2 - qz * w3),
            0.5 * (qw * w1 + qy * w3 - qz * w2),
            0.5 * (qw * w2 + qz * w1 - qx * w3),
            0.5 * (qw * w3 + qx * w2 - qy * w1),
        ]
    return rhs


def tilt(x):
    qw, qx, qy, qz = x[3:7]
    n2 = qw * qw + qx * qx + qy * qy + qz * qz
    ex, ey = 2 * (qx * qz + qw * qy) / n2, 2 * (qy * qz - qw * qx) / n2
    ez = (qw * qw - qx * qx - qy * qy + qz * qz) / n2
    return math.atan2(math.hypot(ex, ey), ez)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--reference", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--quick", action="store_true", help="tolerances down to 1e-9 only")
    add_arguments(ap)
    args = ap.parse_args()
    configure(args)
    with open(args.reference) as f:
        ref = json.load(f)
    entries = []
    methods = ("DOP853", "RK45")
    tolerances = range(3, 10 if args.quick else 14)
    progress = Progress("bench scipy_heavy_top", "sweep points",
                        len(ref["problems"]) * len(methods) * len(tolerances), args.quiet)
    for p in ref["problems"]:
        rhs = top_rhs(p["I"], p["Is"], p["mgl"])
        x0, t_end, theta_end = p["x0"], p["t_end"], p["theta_end"]
        detail(f"scipy heavy top, problem {p['name']} (t_end = {t_end:g} s)")
        for method in methods:
            start = progress.done
            for k in tolerances:
                tol = 10.0 ** -k
                atol = ATOL_FACTOR * tol

                def solve():
                    return solve_ivp(rhs, (0.0, t_end), x0, method=method, rtol=tol, atol=atol)

                seconds, sol = best_time(solve)
                if not sol.success:
                    detail(f"  scipy:{method} tol {tol:.0e}: failed ({sol.message})")
                    break
                err = abs(tilt(sol.y[:, -1]) - theta_end)
                steps = int(sol.t.size - 1)
                detail(f"  scipy:{method:8s} tol {tol:.0e} theta error {err:.2e} "
                       f"{seconds * 1e3:9.2f} ms {steps:8d} steps")
                entries.append({"group": "work_precision", "problem": p["name"],
                                "solver": f"scipy:{method}", "peer": True, "tolerance": tol,
                                "atol": atol, "error": err, "seconds": seconds, "steps": steps})
                progress.update(now=f"{p['name']}, scipy:{method}, tol {tol:.0e}")
                if seconds > MAX_SOLVE_SECONDS:
                    break
            progress.update(start + len(tolerances))
    with open(args.out + ".tmp", "w") as f:
        json.dump(entries, f, indent=1)
    os.replace(args.out + ".tmp", args.out)
    progress.finish(f"{len(ref['problems'])} problems, {len(methods)} methods: {len(entries)} "
                    f"entries in {duration(progress.seconds())}; wrote {args.out}")


if __name__ == "__main__":
    main()
