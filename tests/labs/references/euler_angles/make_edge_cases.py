#!/usr/bin/env python3
"""References for euler_angles_test.cpp's edge cases (issue "right at the edges"), at 40
digits from the exact binary values of the double inputs, the angles in degrees turned
into radians in mpmath (as the lab keeps sin(theta) from degrees):

- omega in the body, in space (lambda^T omega_123, lambda of eq. 122) and in x'y'z'
  (lambda_theta lambda_phi omega_xyz); given the rates, omega_123 by eqs. 134-136; given
  omega (--from-omega), the rates by eqs. 134-136 inverted, and at a pole only
  phi_dot +- psi_dot = +-omega_3 and theta_dot = omega_1 cos psi - omega_2 sin psi;
- eqs. 137-138 as printed, omega_x = theta_dot cos psi - psi_dot sin theta cos phi and
  omega_y = theta_dot sin psi - psi_dot sin theta sin phi, with psi_dot sin theta =
  omega_3 sin theta - (omega_1 sin psi + omega_2 cos psi) cos theta (its limit at a pole);
- L in space, T = 1/2 sum I_i omega_i^2, dT/dpsi_dot = I3 omega_3 and dT/dpsi = (I1 - I2)
  omega_1 omega_2 (eqs. 154-157).

Run: python3 tests/labs/references/euler_angles/make_edge_cases.py
"""
import math
import os

import mpmath as mp

mp.mp.dps = 40

RATES = (1.0, 0.5, 2.0)     # the lab's default rates
ANGLES = (30.0, 70.0)       # the lab's default phi and psi, deg
LONG = dict(phi=541.66826396323, theta=135.40272805339464, psi=-463.05982509111584,
            rates=(-5.833921488427767, 0.7919308047775093, -9.338185730543904),
            moments=(3.383260344757347, 3.684594607682449, 3.7921672281973664))
# name, phi_deg, theta_deg, psi_deg, given omega (else None: the rates), the rates, moments
CASES = [
    ("north pole, omega given", 30.0, 0.0, 70.0, (1.0, 2.0, 3.0), None, (1.0, 2.0, 3.0)),
    ("south pole, omega given", 30.0, 180.0, 70.0, (1.0, 2.0, 3.0), None, (1.0, 2.0, 3.0)),
    ("1e-6 deg, omega given", 30.0, 1e-6, 70.0, (1.0, 2.0, 3.0), None, (1.0, 2.0, 3.0)),
    ("1e-9 deg, omega given", 30.0, 1e-9, 70.0, (1.0, 2.0, 3.0), None, (1.0, 2.0, 3.0)),
    ("north pole", 30.0, 0.0, 70.0, None, RATES, (1.0, 2.0, 3.0)),
    ("south pole", 30.0, 180.0, 70.0, None, RATES, (1.0, 2.0, 3.0)),
    ("1e-60 deg", 30.0, 1e-60, 70.0, None, RATES, (1.0, 2.0, 3.0)),
    ("1e-9 deg", 30.0, 1e-9, 70.0, None, RATES, (1.0, 2.0, 3.0)),
    ("179.9999999 deg", 30.0, 179.9999999, 70.0, None, RATES, (1.0, 2.0, 3.0)),
    ("180 - 1e-13 deg", 30.0, 180.0 - 1e-13, 70.0, None, RATES, (1.0, 2.0, 3.0)),
    ("2 deg", 30.0, 2.0, 70.0, None, (8.0, -2.0, -8.0), (1.0, 2.0, 3.0)),
    ("defaults", 30.0, 50.0, 70.0, None, RATES, (1.0, 2.0, 3.0)),
    ("the long input", LONG["phi"], LONG["theta"], LONG["psi"], None, LONG["rates"],
     LONG["moments"]),
]


def radians(deg):
    return mp.mpf(deg) * mp.pi / 180


def turn_z(a):
    """The passive turn about z (eq. 121's lambda_phi, lambda_psi)."""
    c, s = mp.cos(a), mp.sin(a)
    return mp.matrix([[c, s, 0], [-s, c, 0], [0, 0, 1]])


def turn_x_sc(s, c):
    """The passive turn about x by the angle of sine s and cosine c (eq. 121's lambda_theta)."""
    return mp.matrix([[1, 0, 0], [0, c, s], [0, -s, c]])


def case(name, phi_deg, theta_deg, psi_deg, omega, rates, moments):
    # phi and psi by whole turns in degrees first, as the lab takes them
    phi = radians(math.remainder(phi_deg, 360.0))
    psi = radians(math.remainder(psi_deg, 360.0))
    theta = radians(theta_deg)
    # sin theta from the nearer pole, 0 at either
    st = mp.sin(radians(theta_deg) if theta_deg <= 90 else radians(180 - mp.mpf(theta_deg)))
    ct, sp, cp = mp.cos(theta), mp.sin(psi), mp.cos(psi)
    lam = turn_z(psi) * turn_x_sc(st, ct) * turn_z(phi)
    pole = omega is not None and st == 0
    if omega is None:
        pd, td, sd = (mp.mpf(x) for x in rates)
        w = mp.matrix([pd * st * sp + td * cp, pd * st * cp - td * sp, pd * ct + sd])
    else:
        w = mp.matrix([mp.mpf(x) for x in omega])
        td = w[0] * cp - w[1] * sp
        if not pole:
            pd = (w[0] * sp + w[1] * cp) / st
            sd = w[2] - pd * ct
    w_space = lam.T * w
    w_int = turn_x_sc(st, ct) * turn_z(phi) * w_space
    psi_dot_sin = w[2] * st - (w[0] * sp + w[1] * cp) * ct
    printed = (td * cp - psi_dot_sin * mp.cos(phi), td * sp - psi_dot_sin * mp.sin(phi))
    I = [mp.mpf(x) for x in moments]
    L = mp.matrix([I[i] * w[i] for i in range(3)])
    L_space = lam.T * L
    T = sum(I[i] * w[i] ** 2 for i in range(3)) / 2
    rates_out = (0, 0, 0) if pole else (pd, td, sd)
    return dict(name=name, inputs=(phi_deg, theta_deg, psi_deg), omega_given=omega is not None,
                velocity=omega if omega is not None else rates, moments=moments,
                omega_body=list(w), omega_space=list(w_space), omega_int=list(w_int),
                printed=printed, L_space=list(L_space), T=T, p_psi=I[2] * w[2],
                force_psi=(I[0] - I[1]) * w[0] * w[1], pole=pole, rates=rates_out, theta_dot=td)


def main():
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "reference_edge_cases.inc")
    num = lambda x: mp.nstr(mp.mpf(x), 20, min_fixed=1, max_fixed=0)
    vec = lambda v: "{" + ", ".join(num(x) for x in v) + "}"
    inp = lambda v: "{" + ", ".join(repr(float(x)) for x in v) + "}"
    with open(out, "w") as f:
        f.write("// generated by make_edge_cases.py: name; phi, theta, psi (deg); omega given (else "
                "the rates); omega or the rates (rad/s); moments (kg m^2); omega_123, omega_xyz, "
                "omega_x'y'z' (rad/s); eqs. 137-138 as printed (rad/s); L_xyz (kg m^2/s); T (J); "
                "I3 omega_3 (kg m^2/s); (I1 - I2) omega_1 omega_2 (N m); at a pole; the rates "
                "(rad/s, 0 at a pole); theta_dot (rad/s)\n")
        for c in CASES:
            r = case(*c)
            f.write("{" + ", ".join([
                '"%s"' % r["name"], inp(r["inputs"]), "true" if r["omega_given"] else "false",
                inp(r["velocity"]), inp(r["moments"]), vec(r["omega_body"]), vec(r["omega_space"]),
                vec(r["omega_int"]), vec(r["printed"]), vec(r["L_space"]), num(r["T"]),
                num(r["p_psi"]), num(r["force_psi"]), "true" if r["pole"] else "false",
                vec(r["rates"]), num(r["theta_dot"])]) + "},\n")
    print("wrote", out)


if __name__ == "__main__":
    main()
