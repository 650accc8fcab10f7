#!/usr/bin/env python3
"""top_nutation at the edges, by an adversary: random starts within 1e-12..1e-6 deg of
each pole and within 1e-12..1e-6 (relative) of the separatrix (a turning circle at
upright: b - a and the energy's margin over the pole both near 0), each lab run's JSON
held to mpmath at 120 digits from the exact binary values of its double inputs (theta0
in exact degrees): the turning angles, the nutation period 2 K(k) / lambda, and the mean
precession as the two complete integrals of the third kind (mpmath's ellippi: nothing of
the lab's Carlson forms). Deterministic: a fixed seed.

The bounds, measured over 1000 cases (five seeds) and set with room from the method:
  angles         1.2e-13 deg absolute (4 ulps of 180 deg; near 0 far less)
  period         1e-13 relative (K and lambda a few ulps each, the roots from the pole)
  mean phi_dot   1e-10 of max(|mean|, 1e-3 * 2 pi / period) (worst seen 1.9e-11: a turn
                 about the bottom as a difference of two complete integrals)
A mean that the lab leaves undefined (through a pole, or below its roundoff), or whose
pass side the inputs' rounding decides, is not compared; the lab's reason is its answer.

Run: edges_adversary.py LAB [--cases N] [--seed S]
"""
import argparse
import json
import math
import os
import random
import subprocess
import sys

import mpmath as mp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_lab_edges  # noqa: E402  (its cubic and roots)

mp.mp.dps = 120


def reference(I, Is, mgl, th_deg, thd0, phd0, S):
    a, b, beta, u0, s2, (u1, u2, u3) = make_lab_edges.cubic((I, Is, mgl), th_deg, thd0, phd0, S)
    phd0 = mp.mpf(phd0)
    lam = mp.sqrt(beta * (u3 - u1)) / 2
    k2 = (u2 - u1) / (u3 - u1)
    T = 2 * mp.ellipk(k2) / lam
    mean = None
    if u2 - u1 > 0 and u1 > -1 and u2 < 1:
        north = (b - a) / (1 - u1) * mp.ellippi((u2 - u1) / (1 - u1), k2) / lam if b != a else 0
        south = (b + a) / (1 + u1) * mp.ellippi(-(u2 - u1) / (1 + u1), k2) / lam if b != -a else 0
        mean = (north + south) / T
    eps = mp.mpf(2) ** -52
    sensitive = (abs(b - a) < 1e3 * eps * (abs(phd0 * s2) + abs(a) * (1 - u0)) or
                 abs(b + a) < 1e3 * eps * (abs(phd0 * s2) + abs(a) * (1 + u0)))
    return dict(theta_min=mp.degrees(mp.acos(min(u2, 1))), theta_max=mp.degrees(mp.acos(max(u1, -1))),
                period=T, mean=mean, sensitive=sensitive)


def start(rng):
    """A random top and a start near a pole or the separatrix; None where the draw fails."""
    I = rng.uniform(0.5, 3.0)
    Is = rng.uniform(0.05, 0.95) * I
    mgl = rng.uniform(0.01, 0.5)  # with --mass 1 --arm 0.1: I - m l^2 >= Is / 2 holds
    kind = rng.choice(["north", "south", "separatrix"])
    S = rng.choice([0.0, rng.uniform(0, 30)])
    thd = rng.choice([0.0, rng.uniform(-3, 3)])
    phd = rng.choice([0.0, rng.uniform(-5, 5)])
    if kind == "north":
        th = 10 ** rng.uniform(-12, -6)
    elif kind == "south":
        th = 180 - 10 ** rng.uniform(-12, -6)
    else:
        th, S = rng.uniform(20, 150), rng.uniform(1, 30)
        t = math.radians(th)
        a, beta = Is * S / I, 2 * mgl / I
        phd = a * (1 - math.cos(t)) / math.sin(t) ** 2 * (1 + rng.choice([1, -1]) * 10 ** rng.uniform(-12, -6))
        q = beta * (1 - math.cos(t)) - phd ** 2 * math.sin(t) ** 2
        if q <= 0:
            return None
        thd = math.sqrt(q) * (1 + rng.choice([1, -1]) * 10 ** rng.uniform(-12, -6))
    return kind, (I, Is, mgl, th, thd, phd, S)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("lab")
    parser.add_argument("--cases", type=int, default=150)
    parser.add_argument("--seed", type=int, default=20261128)
    args = parser.parse_args()
    rng = random.Random(args.seed)
    worst, failures, count = {}, [], 0
    while count < args.cases:
        drawn = start(rng)
        if drawn is None:
            continue
        kind, (I, Is, mgl, th, thd, phd, S) = drawn
        cmd = [args.lab, "--json", "--inertia", f"{I!r},{Is!r}", "--mass", "1", "--arm", "0.1",
               "--g", repr(mgl / 0.1), "--theta0-deg", repr(th), "--thetadot0", repr(thd),
               "--phidot0", repr(phd), "--spin", repr(S), "--periods", "1"]
        run = subprocess.run(cmd, capture_output=True, text=True)
        count += 1
        if run.returncode != 0:
            failures.append(f"refused: {' '.join(cmd[1:])}: {run.stderr.strip()}")
            continue
        r = json.loads(run.stdout)["results"]
        # the lab's g is mgl / (m l), rounded: the reference takes the lab's own m g l
        ref = reference(r["moment_transverse_kg_m2"], r["moment_symmetry_kg_m2"], r["mgl_n_m"],
                        th, thd, phd, S)
        errors = {"theta_min deg": (abs(r["theta_min_deg"] - ref["theta_min"]), 1.2e-13),
                  "theta_max deg": (abs(r["theta_max_deg"] - ref["theta_max"]), 1.2e-13)}
        if r.get("nutation_period_s") is not None:
            errors["period rel"] = (abs(r["nutation_period_s"] / ref["period"] - 1), 1e-13)
        mean = r.get("mean_precession_rate_rad_s")
        if mean is not None and ref["mean"] is not None and not ref["sensitive"]:
            scale = max(abs(ref["mean"]), 2 * mp.pi / ref["period"] * 1e-3)
            errors["mean rel"] = (abs(mean - ref["mean"]) / scale, 1e-10)
        for name, (error, bound) in errors.items():
            error = float(error)
            key = f"{kind} {name}"
            if error > worst.get(key, (-1, ""))[0]:
                worst[key] = (error, " ".join(cmd[1:]))
            if not error <= bound:
                failures.append(f"{key}: {error:.3g} > {bound:g}: {' '.join(cmd[1:])}")
    print(f"{count} cases (seed {args.seed})")
    for key, (error, cmd) in sorted(worst.items()):
        print(f"  worst {key:24s} {error:.3g}")
    for f in failures:
        print("FAIL", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
