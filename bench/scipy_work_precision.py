#!/usr/bin/env python3
"""SciPy peers for the free-body work-precision benchmark.

Integrates the same 7-dimensional system as the C++ bench (Euler's equations
for omega_body plus the body-to-space quaternion kinematics) with
scipy.integrate.solve_ivp, methods DOP853 and RK45, as the SciPy documentation
shows: a plain Python right-hand side, rtol = tol and atol = 1e-3 * tol for
tol = 1e-3 .. 1e-13. The problems and their exact end states come from the
reference.json that bench_work_precision writes (rigid::FreeBodyExact at
t_end). Each solve is timed after import with time.perf_counter, best of a
few repeats (at least 3 and 50 ms unless one solve is long). A sweep stops
once a single solve takes more than MAX_SOLVE_SECONDS (tighter tolerances only
cost more), which keeps the whole bench target within a few minutes.

Writes a JSON array of entries like the C++ bench:
  {"group": "work_precision", "problem": ..., "solver": "scipy:DOP853",
   "peer": true, "tolerance": tol, "atol": atol, "error": ..., "attitude_error": ...,
   "seconds": ..., "steps": ...}

Usage: scipy_work_precision.py --reference reference.json --out scipy_work_precision.json
"""

import argparse
import json
import math
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from progress import Progress, add_arguments, configure, detail, duration  # noqa: E402
from scipy.integrate import solve_ivp

MAX_SOLVE_SECONDS = 4.0
ATOL_FACTOR = 1e-3


def euler_rhs(I1, I2, I3):
    """Euler's equations (torque-free) and q_dot = 1/2 q (x) (0, omega)."""

    def rhs(t, x):
        w1, w2, w3, qw, qx, qy, qz = x
        return [
            -w2 * w3 * (I3 - I2) / I1,
            -w3 * w1 * (I1 - I3) / I2,
            -w1 * w2 * (I2 - I1) / I3,
            0.5 * (-qx * w1 - qy * w2 - qz * w3),
            0.5 * (qw * w1 + qy * w3 - qz * w2),
            0.5 * (qw * w2 + qz * w1 - qx * w3),
            0.5 * (qw * w3 + qx * w2 - qy * w1),
        ]

    return rhs


def omega_error(x, exact):
    """Max-norm of the omega error relative to |omega_exact|."""
    w, we = np.asarray(x[:3]), np.asarray(exact[:3])
    return float(np.max(np.abs(w - we)) / np.linalg.norm(we))


def attitude_error(x, exact):
    """Angle of the rotation between two attitudes, sign-blind."""
    q = np.asarray(x[3:7]) / np.linalg.norm(x[3:7])
    qe = np.asarray(exact[3:7])
    # d = conj(q) * qe
    w = q[0] * qe[0] + np.dot(q[1:], qe[1:])
    v = q[0] * qe[1:] - qe[0] * q[1:] - np.cross(q[1:], qe[1:])
    return float(2.0 * math.atan2(np.linalg.norm(v), abs(w)))


def best_time(solve):
    best, total, reps, result = math.inf, 0.0, 0, None
    while True:
        t0 = time.perf_counter()
        result = solve()
        s = time.perf_counter() - t0
        best, total, reps = min(best, s), total + s, reps + 1
        if total >= 0.6 or (reps >= 3 and total >= 0.05):
            return best, result


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
    progress = Progress("bench scipy_work_precision", "sweep points",
                        len(ref["problems"]) * len(methods) * len(tolerances), args.quiet)
    for p in ref["problems"]:
        I1, I2, I3 = p["I"]
        x0 = list(p["omega0_body"]) + [1.0, 0.0, 0.0, 0.0]
        t_end, exact = p["t_end"], p["state_end"]
        rhs = euler_rhs(I1, I2, I3)
        detail(f"scipy work-precision, problem {p['name']} (t_end = {t_end:g} s)")
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
                x = sol.y[:, -1]
                err, att = omega_error(x, exact), attitude_error(x, exact)
                steps = int(sol.t.size - 1)
                detail(f"  scipy:{method:8s} tol {tol:.0e} error {err:.2e} attitude {att:.2e} "
                       f"{seconds * 1e3:9.2f} ms {steps:8d} steps")
                entries.append({
                    "group": "work_precision", "problem": p["name"],
                    "solver": f"scipy:{method}", "peer": True, "tolerance": tol,
                    "atol": atol, "error": err, "attitude_error": att,
                    "seconds": seconds, "steps": steps,
                })
                progress.update(now=f"{p['name']}, scipy:{method}, tol {tol:.0e}")
                if seconds > MAX_SOLVE_SECONDS:
                    detail(f"  scipy:{method}: stopping the sweep, one solve took {seconds:.1f} s")
                    break
            progress.update(start + len(tolerances))

    tmp = args.out + ".tmp"
    with open(tmp, "w") as f:
        json.dump(entries, f, indent=1)
    os.replace(tmp, args.out)
    progress.finish(f"{len(ref['problems'])} problems, {len(methods)} methods: {len(entries)} "
                    f"entries in {duration(progress.seconds())}; wrote {args.out}")


if __name__ == "__main__":
    sys.exit(main())
