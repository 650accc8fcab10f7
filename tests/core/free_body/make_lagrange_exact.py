#!/usr/bin/env python3
"""References for euler_lagrange_test.cpp's exact Lagrange terms (lagrange_terms_exact,
psi_terms), at 80 digits from the exact binary values of the double inputs, by a route
of their own: T(q, q_dot) = 1/2 sum I_i omega_i^2 with omega from eqs. 134-136, each
partial derivative by mpmath's diff of T itself (dT/dq_k, and dT/dq_dot_k for the
momentum), q_dot solved from omega = A(q) q_dot where omega is given, and d/dt
dT/dq_dot_k = (d/ds of dT/dq_dot_k along q + s q_dot, q_dot held) + (M q_ddot)_k, where
the mass matrix M = A^T I A makes M q_ddot = A^T I (omega_dot - (dA/dt) q_dot) with
omega_dot from Euler's equations with the torque (I omega_dot = N - omega x I omega): no
inverse of A, so a state at a pole with its rates given has its terms too. Q_k = N .
d omega/d q_dot_k. The residual d/dt dT/dq_dot - dT/dq - Q is 0 to the working
precision: the script checks it.

States given by omega: a generic one, theta within 1e-3 to 1e-12 rad of either pole
(the rates as 1/sin theta), moments spread over decades, with and without a torque. By
the rates: theta at either pole exactly, 1e-60 deg from one, and generic.

Run: python3 tests/core/free_body/make_lagrange_exact.py
"""
import os

import mpmath as mp

mp.mp.dps = 80

# I1, I2, I3; phi, theta, psi (rad); omega_body (rad/s); torque_body (N m)
OMEGA_CASES = [
    ((1.0, 2.0, 3.0), (0.4, 1.0, -0.7), (0.3, -1.2, 2.0), (0.0, 0.0, 0.0)),
    ((2.0, 3.0, 4.0), (0.4, 1.0, -0.7), (0.3, -1.2, 2.0), (0.5, -0.25, 1.0)),
    ((1.0, 2.0, 3.0), (0.5, 1e-3, -1.2), (1.0, 2.0, 3.0), (0.0, 0.0, 0.0)),
    ((1.0, 2.0, 3.0), (0.5, 1e-6, -1.2), (1.0, 2.0, 3.0), (-2.0, 3.0, 0.5)),
    ((1.0, 2.0, 3.0), (0.5, 1e-9, 2.2), (1.0, 2.0, 3.0), (0.0, 0.0, 0.0)),
    ((1.0, 2.0, 3.0), (-2.5, 1e-12, 0.3), (-0.4, 0.1, 5.0), (0.0, 0.0, 0.0)),
    ((1.0, 2.0, 3.0), (0.5, 3.141592653589793 - 1e-6, -1.2), (1.0, 2.0, 3.0), (0.0, 0.0, 1.0)),
    ((1.0, 2.0, 3.0), (0.5, 3.141592653589793 - 1e-12, 1.9), (1.0, -2.0, 0.5), (0.0, 0.0, 0.0)),
    ((1e-3, 1.0, 1.0005), (1.3, 0.03, -2.9), (7.0, -0.02, 0.6), (0.0, 0.0, 0.0)),
    ((3.383260344757347, 3.684594607682449, 3.7921672281973664),
     (2.6995, 2.3632, 1.4998), (0.9, -4.4, -7.1), (0.0, 0.0, 0.0)),
]
# the same with phi_dot, theta_dot, psi_dot (rad/s) for omega
RATE_CASES = [
    ((1.0, 2.0, 3.0), (0.5235987755982988, 0.0, 1.2217304763960306), (1.0, 0.5, 2.0), (0.0, 0.0, 0.0)),
    ((1.0, 2.0, 3.0), (0.5235987755982988, 3.141592653589793, 1.2217304763960306), (1.0, 0.5, 2.0),
     (0.5, -0.25, 1.0)),
    ((1.0, 2.0, 3.0), (0.5235987755982988, 1.7453292519943295e-62, 1.2217304763960306),
     (1.0, 0.5, 2.0), (0.0, 0.0, 0.0)),
    ((1.0, 2.0, 3.0), (0.5235987755982988, 0.03490658503988659, 1.2217304763960306),
     (8.0, -2.0, -8.0), (0.0, 0.0, 0.0)),
    ((2.0, 3.0, 4.0), (0.4, 1.0, -0.7), (-1.5, 0.25, 3.0), (0.5, -0.25, 1.0)),
]


def axes(q):
    """The axes of the three rates in the body, columns of A (eqs. 131-133)."""
    _, t, p = q
    return [[mp.sin(t) * mp.sin(p), mp.sin(t) * mp.cos(p), mp.cos(t)],
            [mp.cos(p), -mp.sin(p), mp.mpf(0)],
            [mp.mpf(0), mp.mpf(0), mp.mpf(1)]]


def omega_of(q, qd):
    a = axes(q)
    return [sum(qd[k] * a[k][i] for k in range(3)) for i in range(3)]


def kinetic(I, q, qd):
    w = omega_of(q, qd)
    return sum(I[i] * w[i] ** 2 for i in range(3)) / 2


def replaced(v, k, x):
    v = list(v)
    v[k] = x
    return v


def terms(I, q, v, N, given_rates):
    I, q, v, N = ([mp.mpf(x) for x in u] for u in (I, q, v, N))
    A = mp.matrix(3, 3)
    a = axes(q)
    for i in range(3):
        for k in range(3):
            A[i, k] = a[k][i]
    qd = v if given_rates else list(mp.lu_solve(A, mp.matrix(v)))
    w = omega_of(q, qd) if given_rates else v
    L = [I[i] * w[i] for i in range(3)]
    wdot = [(N[i] - (w[(i + 1) % 3] * L[(i + 2) % 3] - w[(i + 2) % 3] * L[(i + 1) % 3])) / I[i]
            for i in range(3)]
    # M q_ddot = A^T I (omega_dot - (d/ds A(q + s q_dot)) q_dot)
    Adot_qd = [mp.diff(lambda s, i=i: omega_of([q[j] + s * qd[j] for j in range(3)], qd)[i], 0)
               for i in range(3)]
    M_qdd = [sum(A[i, k] * I[i] * (wdot[i] - Adot_qd[i]) for i in range(3)) for k in range(3)]
    rows = []
    for k in range(3):
        def momentum(qq, qqd, k=k):
            return mp.diff(lambda x: kinetic(I, qq, replaced(qqd, k, x)), qqd[k])
        p = momentum(q, qd)
        p_rate = mp.diff(lambda s: momentum([q[j] + s * qd[j] for j in range(3)], qd), 0) + M_qdd[k]
        dT = mp.diff(lambda x: kinetic(I, replaced(q, k, x), qd), q[k])
        Q = sum(N[i] * a[k][i] for i in range(3))
        residual = p_rate - dT - Q
        scale = abs(p_rate) + abs(dT) + abs(Q) + 1
        assert abs(residual) < mp.mpf(10) ** -50 * scale, (k, residual)
        rows.append((p, p_rate, dT, Q))
    return rows


def main():
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "reference_lagrange_exact.inc")
    with open(out, "w") as f:
        f.write("// generated by make_lagrange_exact.py: whether the rates are given (else omega); I1, "
                "I2, I3; phi, theta, psi (rad); omega_body or the rates (rad/s); torque_body (N m); "
                "for phi, theta, psi: {dT/dq_dot, d/dt dT/dq_dot, dT/dq, Q}\n")
        for given_rates, cases in ((False, OMEGA_CASES), (True, RATE_CASES)):
            for I, q, v, N in cases:
                rows = terms(I, q, v, N, given_rates)
                vec = lambda u: "{" + ", ".join(repr(float(x)) for x in u) + "}"
                cells = ", ".join("{" + ", ".join(mp.nstr(x, 25, min_fixed=1, max_fixed=0) for x in r) + "}"
                                  for r in rows)
                f.write("{" + ", ".join(["true" if given_rates else "false", vec(I), vec(q), vec(v), vec(N)])
                        + ", {" + cells + "}},\n")
    print("wrote", out)


if __name__ == "__main__":
    main()
