#!/usr/bin/python3
"""Long-time reference for the exact free body (issue 13, item 4): omega and the
attitude at 10, 100 and 1000 polhode periods, at 30 digits, by a route that
shares nothing with the C++ closed form.

1. The polhode period T = 4 K(k) / rate from Landau & Lifshitz, Mechanics,
   section 37 (their tau and k^2, axes sorted I1 < I2 < I3, with I1 and I3
   exchanged when L^2 < 2 E I2): written here from the book, not from the C++.
2. mpmath's Taylor ODE solver integrates Euler's equations and the quaternion
   kinematics over one period; omega(T) = omega(0) to 1e-20 checks T itself.
3. Since omega is T-periodic, q(t + T) = R q(t) with R = q(T) q(0)^-1 a fixed
   rotation about L, so q(n T + s) = R^n q(s) and omega(n T + s) = omega(s):
   R^n is the rotation by n times R's angle, formed at 30 digits.

The times n T + s are rounded to doubles and the reference is taken at those
doubles (s recomputed as t - n T at 30 digits), so the test asks the C++ for
exactly the instants the reference holds. Writes reference_free_body_long.inc.

Run: /usr/bin/python3 tests/free_body/make_free_body_long.py   (about a minute)
"""
import math
import os

import mpmath as mp

mp.mp.dps = 30


def qmul(a, b):
    aw, ax, ay, az = a
    bw, bx, by, bz = b
    return [aw * bw - ax * bx - ay * by - az * bz, aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx, aw * bz + ax * by - ay * bx + az * bw]


def qconj(a):
    return [a[0], -a[1], -a[2], -a[3]]


def qpow(r, n):
    """R^n for a unit quaternion R: the rotation by n times its angle about its axis."""
    v = mp.sqrt(r[1] ** 2 + r[2] ** 2 + r[3] ** 2)
    half = mp.atan2(v, r[0])
    return [mp.cos(n * half)] + [mp.sin(n * half) * c / v for c in r[1:]]


def landau_period(I, w):
    """T = 4 K(k) / rate of Landau & Lifshitz section 37, for any order of the axes."""
    E2 = sum(I[i] * w[i] ** 2 for i in range(3))          # 2E
    L2 = sum((I[i] * w[i]) ** 2 for i in range(3))        # L^2
    I1, I2, I3 = sorted(I)
    if L2 < E2 * I2:  # about the smallest axis: the book's formulas with I1 and I3 exchanged
        I1, I3 = I3, I1
    rate = mp.sqrt((I3 - I2) * (L2 - E2 * I1) / (I1 * I2 * I3))
    k2 = (I2 - I1) * (E2 * I3 - L2) / ((I3 - I2) * (L2 - E2 * I1))
    return 4 * mp.ellipk(k2) / rate


def rhs(I):
    I1, I2, I3 = I

    def F(t, y):
        w1, w2, w3, qw, qx, qy, qz = y
        return [-(w2 * w3 * (I3 - I2)) / I1, -(w3 * w1 * (I1 - I3)) / I2,
                -(w1 * w2 * (I2 - I1)) / I3,
                (-qx * w1 - qy * w2 - qz * w3) / 2, (qw * w1 + qy * w3 - qz * w2) / 2,
                (qw * w2 + qz * w1 - qx * w3) / 2, (qw * w3 + qx * w2 - qy * w1) / 2]
    return F


def axis_angle(axis, angle):
    n = math.sqrt(sum(a * a for a in axis))
    s = math.sin(angle / 2)
    return [math.cos(angle / 2)] + [s * a / n for a in axis]


Q0 = axis_angle([1.0, 2.0, 3.0], 0.3)
PI = math.pi
# name, (I1, I2, I3), omega0_body: k'^2 from about 1 down to 1e-6, both families,
# unsorted axes and the near-symmetric limits.
CASES = [
    ("textbook ellipsoid, omega0 = (1, 1, 1)", (PI, 2 * PI, 13 * PI / 5), (1.0, 1.0, 1.0)),
    ("polhode about the largest axis, small amplitude", (1.0, 2.0, 3.0), (0.05, 0.1, 1.0)),
    ("polhode about the smallest axis", (1.0, 2.0, 3.0), (1.0, 0.1, 0.05)),
    ("unsorted moments, signed omega", (2.0, 3.0, 1.0), (-0.5, 0.3, -1.0)),
    ("near the separatrix (k'^2 = 6.5e-4), about the largest axis", (3.0, 3.75, 5.0),
     (5.0, 1.0, 3.0001)),
    ("near the separatrix (k'^2 = 6.5e-4), about the smallest axis", (3.0, 3.75, 5.0),
     (5.0, 1.0, 2.9999)),
    ("close to the separatrix (k'^2 = 6.5e-7)", (3.0, 3.75, 5.0), (5.0, 1.0, 3.000001)),
    ("near the oblate symmetric limit I1 ~ I2", (1.0, 1.000001, 2.0), (0.5, 0.3, -1.0)),
]
PERIODS = [10, 100, 1000]
FRACTIONS = [0.0, 0.31, 0.77]  # s / T within the period


def main():
    out, worst_closure = [], mp.mpf(0)
    for name, I, w0 in CASES:
        Im = [mp.mpf(v) for v in I]
        wm = [mp.mpf(v) for v in w0]
        qm = [mp.mpf(v) for v in Q0]
        qn = mp.sqrt(sum(v * v for v in qm))
        qm = [v / qn for v in qm]
        T = landau_period(Im, wm)
        f = mp.odefun(rhs(Im), 0, wm + qm)
        yT = f(T)
        closure = mp.sqrt(sum((yT[i] - wm[i]) ** 2 for i in range(3)) / sum(v * v for v in wm))
        worst_closure = max(worst_closure, closure)
        assert closure < mp.mpf("1e-20"), (name, closure)  # T is the period
        R = qmul(yT[3:], qconj(qm))
        rows = []
        for n in PERIODS:
            for frac in FRACTIONS:
                t = float(n * T + frac * T)  # the double the test will ask for
                tm = mp.mpf(t)
                k = int(mp.floor(tm / T))
                s = tm - k * T
                y = f(s)
                q = qmul(qpow(R, k), y[3:])
                rows.append((t, n, y[:3] + q))
        out.append((name, I, w0, float(T), rows))
        print(f"{name}: T = {mp.nstr(T, 12)}, closure {mp.nstr(closure, 3)}")
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "reference_free_body_long.inc")
    with open(path, "w") as fh:
        fh.write("// Generated by make_free_body_long.py (mpmath %s, %d digits: Landau's period,\n"
                 "// one period by the Taylor ODE solver, q(nT + s) = R^n q(s)). Do not edit.\n"
                 "// Worst |omega(T) - omega(0)| / |omega0| of the reference: %s\n"
                 % (mp.__version__, mp.mp.dps, mp.nstr(worst_closure, 3)))
        fh.write("// {name, I, omega0, q0, period, {{t, periods, {w1, w2, w3, qw, qx, qy, qz}}}}\n")
        for name, I, w0, T, rows in out:
            fh.write("{\"%s\",\n {%r, %r, %r},\n {%r, %r, %r},\n {%r, %r, %r, %r},\n %r,\n {\n"
                     % ((name,) + tuple(I) + tuple(w0) + tuple(Q0) + (T,)))
            for t, n, y in rows:
                fh.write("  {%r, %d, {%s}},\n" % (t, n, ", ".join(mp.nstr(v, 22, strip_zeros=False)
                                                               for v in y)))
            fh.write(" }},\n")
    print("wrote", path)


if __name__ == "__main__":
    main()
