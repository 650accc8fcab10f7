#!/usr/bin/env python3
"""References for the heavy top's edge cases (heavy_top_test.cpp), the text's top
released from rest, at 60 digits from the exact binary values of the double inputs.
Released from rest, u0 is a root of f(u) = (1 - u^2)(alpha - beta u) - (b - a u)^2:
f(u)/(u - u0) by synthetic division leaves a quadratic for the other two roots (a
general root finder lost half its digits on the cluster u0, u3 within 1e-20 of 1).

- reference_near_upright.inc: theta0 a hair from upright (1 - u0 below double's
  roundoff of 1): the nutation period 2 K(k) / lambda, k^2 = (u2 - u1)/(u3 - u1),
  lambda = sqrt(beta (u3 - u1)) / 2.
- reference_passages.inc: tops whose axis passes a hair from a pole, straight up
  (started a hair from upright with theta_dot) or straight down (spinning barely or
  against phi_dot), 1 - u2 or 1 + u1 from 1e-6 down to 1e-62, with b - a and b + a of
  either sign: the period 2K/lambda, the mean of phi_dot (b - a u)/(1 - u^2) over the
  phase and phi, psi at two times by quad of phi_dot and of S - u phi_dot, split at
  decades about each pole's spike (phi turns by nearly pi within sqrt(distance)).
- reference_fast_top.inc: spins up to 1e10 rad/s at 30 deg, where the mean precession
  ~mgl/(Is S) is a tiny difference of the partial fractions' two terms: mean phi_dot =
  (1/2K) int_0^2K a (u0 - u)/(1 - u^2) dv, u = u1 + (u0 - u1) sn^2(v | k^2), by quad.

Run: python3 tests/core/heavy_top/make_edge_cases.py
"""
import math
import os

import mpmath as mp

mp.mp.dps = 60

M, L, R, G = 2.0, 0.04, 0.05, 9.8
I = 0.25 * M * R * R + M * L * L     # as heavy_top_test.cpp's kText, in double
IS = 0.5 * M * R * R
MGL = M * G * L
NEAR_UPRIGHT = [(1e-6, 10.0), (1e-6, 1e-60), (1e-5, 40.0), (1e-7, 47.0), (1e-3, 10.0),
                (1e-8, 20.0)]
FAST_SPINS = [1e3, 3e3, 1e4, 3e4, 1e5, 1e6, 1e8, 1e10]
S500 = 500.0 * 2 * math.pi / 60.0
D30 = math.pi / 6
# theta0, theta_dot0, phi_dot0, spin: a hair from upright with theta_dot (b - a =
# -a (1 - u0), against b + a) or with phi_dot too (both one sign); released at 30 deg
# with a spin that barely turns (through the bottom the spin's way, b - a the other), or
# with phi_dot0 a hair above -a (1 + u0)/sin^2 against a negative spin (both one sign).
PASSAGES = [(1e-2, 1.0, 0.0, S500), (1e-4, 1.0, 0.0, -S500), (1e-6, 1.0, 0.0, S500),
            (1e-9, 1.0, 0.0, -S500), (1e-4, 1.0, 100.0, S500),
            (D30, 0.0, 0.0, 1e-3), (D30, 0.0, 0.0, -1e-5), (D30, 0.0, 0.0, 1e-6),
            (D30, 0.0, 0.0, -1e-9), (D30, 0.0, 0.0, 1e-30),
            (D30, 0.0, 4.1933155, -1.0), (D30, 0.0, 4.19331551412, -1.0)]
PASSAGE_TIMES = [0.3, 1.7]  # of the period


def released_from_rest(theta0, spin):
    """u0, (u1, u2, u3) sorted, a and beta for the double theta0 (rad) and spin."""
    i, i_s, mgl = mp.mpf(I), mp.mpf(IS), mp.mpf(MGL)
    u0 = mp.cos(mp.mpf(theta0))
    a, beta = i_s * mp.mpf(spin) / i, 2 * mgl / i
    b, alpha = a * u0, beta * u0
    c3, c2, c1 = beta, -(alpha + a * a), 2 * a * b - beta  # f = c3 u^3 + c2 u^2 + c1 u + c0
    q2, q1 = c3, c2 + c3 * u0                                # f / (u - u0) = q2 u^2 + q1 u + q0
    q0 = c1 + q1 * u0
    root = mp.sqrt(q1 * q1 - 4 * q2 * q0)
    roots = sorted([(-q1 - root) / (2 * q2), (-q1 + root) / (2 * q2), u0])
    return u0, roots, a, beta


def period(theta0_deg, spin):
    _, (u1, u2, u3), _, beta = released_from_rest(theta0_deg * math.pi / 180.0, spin)
    return 2 * mp.ellipk((u2 - u1) / (u3 - u1)) / (mp.sqrt(beta * (u3 - u1)) / 2)


def mean_phi_dot(spin):
    u0, (u1, u2, u3), a, _ = released_from_rest(math.pi / 6, spin)  # the test's k30
    m = (u2 - u1) / (u3 - u1)

    def phi_dot(v):
        u = u1 + (u2 - u1) * mp.ellipfun("sn", v, m=m) ** 2
        return a * (u0 - u) / (1 - u * u)
    K = mp.ellipk(m)
    return mp.quad(phi_dot, [0, K]) / K


def passage(theta0, theta_dot0, phi_dot0, spin):
    """The period, the mean of phi_dot, and (t, phi - phi0, psi - psi0) at the double t
    nearest each PASSAGE_TIMES fraction of the period, for a general start."""
    dps = 140  # 1 +- u down to 1e-62 with 60 digits to spare
    with mp.workdps(dps):
        i, i_s, mgl = mp.mpf(I), mp.mpf(IS), mp.mpf(MGL)
        u0, s0 = mp.cos(mp.mpf(theta0)), mp.sin(mp.mpf(theta0))
        a, beta = i_s * mp.mpf(spin) / i, 2 * mgl / i
        b = mp.mpf(phi_dot0) * s0 * s0 + a * u0
        alpha = mp.mpf(theta_dot0) ** 2 + (mp.mpf(phi_dot0) * s0) ** 2 + beta * u0
        u1, u2, u3 = sorted(mp.re(x) for x in mp.polyroots(
            [beta, -(alpha + a * a), 2 * a * b - beta, alpha - b * b],
            maxsteps=1000, extraprec=4 * dps))
        m = (u2 - u1) / (u3 - u1)
        K, lam = mp.ellipk(m), mp.sqrt(beta * (u3 - u1)) / 2
        # u = u1 + (u2 - u1) sn^2(v), v = lambda t + v0, v0 < 0 while u falls
        v0 = mp.ellipf(mp.asin(mp.sqrt(min(max((u0 - u1) / (u2 - u1), 0), 1))), m)
        if theta_dot0 > 0:
            v0 = -v0

        def u_of(v):
            return u1 + (u2 - u1) * mp.ellipfun("sn", v, m=m) ** 2

        def phi_dot(v):
            u = u_of(v)
            return (b - a * u) / ((1 - u) * (1 + u))

        def cuts(lo, hi):
            """lo, hi and decades about each narrow spike (south at v = 2Kj, north at K + 2Kj)."""
            pts = {lo, hi}
            for centre, distance in ((0, 1 + u1), (K, 1 - u2)):
                if distance > mp.mpf("0.1"):  # no spike: phi_dot is smooth there
                    continue
                j = mp.floor((lo - centre) / (2 * K))
                while centre + 2 * K * j <= hi:
                    c = centre + 2 * K * j
                    for k in range(int(-mp.log10(mp.sqrt(distance))) + 4):
                        pts.update(p for p in (c - mp.mpf(10) ** -k, c + mp.mpf(10) ** -k, c)
                                   if lo < p < hi)
                    j += 1
            return sorted(pts)

        period = 2 * K / lam
        mean = mp.quad(phi_dot, cuts(mp.mpf(0), K)) / K
        rows = []
        for f in PASSAGE_TIMES:
            t = mp.mpf(float(f * period))
            pts = cuts(v0, v0 + lam * t)
            phi = mp.quad(phi_dot, pts) / lam
            psi = mp.mpf(spin) * t - mp.quad(lambda v: u_of(v) * phi_dot(v), pts) / lam
            rows.append((t, phi, psi))
        return period, mean, rows


def write(name, header, lines):
    with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), name), "w") as f:
        f.write(f"// generated by make_edge_cases.py: {header}\n" + "\n".join(lines) + "\n")
    print("\n".join(lines))


def main():
    write("reference_near_upright.inc", "theta0 (deg), spin (rad/s), period (s)",
          ["{%r, %r, %s}," % (th, s, mp.nstr(period(th, s), 20)) for th, s in NEAR_UPRIGHT])
    lines = []
    for start in PASSAGES:
        T, mean, rows = passage(*start)
        lines.append("{%r, %r, %r, %r, %s, %s, {%s}}," % (
            *start, mp.nstr(T, 20), mp.nstr(mean, 20),
            ", ".join("{%r, %s, %s}" % (float(t), mp.nstr(phi, 20), mp.nstr(psi, 20))
                      for t, phi, psi in rows)))
    write("reference_passages.inc", "theta0 (rad), theta_dot0, phi_dot0, spin (rad/s), "
          "period (s), mean phi_dot (rad/s), {t (s), phi - phi0, psi - psi0 (rad)}", lines)
    write("reference_fast_top.inc", "spin (rad/s), mean phi_dot (rad/s)",
          ["{%r, %s}," % (s, mp.nstr(mean_phi_dot(s), 20)) for s in FAST_SPINS])


if __name__ == "__main__":
    main()
