"""r.motion().at(t): the lab's body at any time, exact or integrated, and at the times its
CSV samples, the CSV's rows. Each lab is held to what its CSV holds of the body."""

import numpy as np
import pytest

import rigidlab as rl

EPS = np.finfo(float).eps


def wrapped(a):
    """An angle in (-pi, pi]."""
    return np.pi - np.mod(np.pi - a, 2 * np.pi)


def quaternion_rotate(q, v):
    """Each vector of v (n x 3) turned by each unit quaternion of q (n x 4, scalar first)."""
    w, u = q[:, :1], q[:, 1:]
    t = 2 * np.cross(u, v)
    return v + w * t + np.cross(u, t)


def columns(d, names):
    return np.column_stack([d[n] for n in names])


Q = ["qw", "qx", "qy", "qz"]
W = ["omega1", "omega2", "omega3"]


@pytest.mark.parametrize("lab, kwargs, omega_columns, q_in_csv", [
    ("poinsot", {}, W, True),
    ("poinsot", {"method": "rk4"}, W, True),
    ("tennis_racquet", {}, W, True),
    # the film draws the method asked for: its omega is the CSV's integrated columns
    ("tennis_racquet", {"method": "rkf78"}, [w + "_integrated" for w in W], False),
    ("top_nutation", {}, W, True),
    ("top_nutation", {"method": "rk4"}, W, True),
])
def test_the_motion_at_the_csvs_times_is_the_csvs_rows(lab, kwargs, omega_columns, q_in_csv):
    r = getattr(rl, lab)(**kwargs)
    at = r.motion().at(r.series["t_s"])
    # the same state, kept or computed by the same closed form: the same doubles
    assert np.array_equal(at["t_s"], r.series["t_s"])
    assert np.array_equal(columns(at, W), columns(r.series, omega_columns))
    if q_in_csv:
        assert np.array_equal(columns(at, Q), columns(r.series, Q))


def test_between_the_samples_an_integrated_motion_follows_the_closed_form():
    # rkf78 at a tolerance of 1e-12 between its samples, integrated on from the nearest:
    # the exact motion to ten times the tolerance over this third of a polhode period
    # (measured 1.9e-15 rad/s on omega of about 1 rad/s, 1.4e-15 on q)
    t = np.linspace(0, 3, 77)[1:] + 0.0123
    exact = rl.poinsot().motion().at(t)
    run = rl.poinsot(method="rkf78", tolerance=1e-12).motion().at(t)
    assert not np.array_equal(columns(run, W), columns(exact, W))
    assert np.abs(columns(run, W) - columns(exact, W)).max() < 1e-11
    assert np.abs(columns(run, Q) - columns(exact, Q)).max() < 1e-11


def check_angles(at, series):
    """The motion's Euler angles against the CSV's: theta from the same attitude by two
    routes to a few ulps; phi and psi (the CSV's may run on continuously) modulo 2 pi."""
    assert np.abs(at["theta_rad"] - series["theta_rad"]).max() < 16 * EPS
    for name in ("phi_rad", "psi_rad"):
        assert np.abs(wrapped(at[name] - series[name])).max() < 64 * EPS * np.pi, name


def test_top_nutation_angles_are_the_csvs():
    r = rl.top_nutation()
    check_angles(r.motion().at(r.series["t_s"]), r.series)


def test_euler_angles_motion_is_its_csv():
    r = rl.euler_angles()
    at = r.motion().at(r.series["t_s"])
    scale = np.abs(columns(r.series, ["omega_1", "omega_2", "omega_3"])).max()
    for mine, csv in zip(W + ["omega_x", "omega_y", "omega_z"],
                         ["omega_1", "omega_2", "omega_3", "omega_x", "omega_y", "omega_z"]):
        # the same closed form; space omega by a rotation of its own: a few ulps of |omega|
        assert np.abs(at[mine] - r.series[csv]).max() <= 8 * EPS * scale, mine
    check_angles(at, r.series)


def test_the_wheel_turns_its_L_round_the_axle():
    r = rl.tire_balancing()
    at = r.motion().at(r.series["t_s"])
    L = columns(r.series, ["Lx", "Ly", "Lz"])
    turned = quaternion_rotate(columns(at, Q), np.repeat(L[:1], len(L), axis=0))
    assert np.abs(turned - L).max() <= 16 * EPS * np.linalg.norm(L[0])
    # omega along the axle at the spin given, the same in body and space; the axle in
    # the x-y plane at the tilt from the symmetry axis x
    omega, tilt = r.inputs["omega"], np.radians(r.inputs["tilt_deg"])
    axle = omega * np.array([np.cos(tilt), np.sin(tilt), 0.0])
    assert np.abs(columns(at, W) - axle).max() <= 4 * EPS * omega
    assert np.abs(columns(at, ["omega_x", "omega_y", "omega_z"]) - axle).max() <= 16 * EPS * omega


def test_the_football_precesses_at_the_labs_rates():
    r = rl.football()
    m = r.motion()
    body_rate, T_space = r["body_precession_rate_rad_s"], r["space_precession_period_s"]
    t = np.linspace(0, 2 * T_space, 41)
    at = m.at(t)
    # omega turns about 3 in the body at Omega (eq. 109), omega_3 constant: the closed
    # form's phase to rounding (measured 1.7e-16 of the whole turn)
    turn = np.unwrap(np.arctan2(at["omega2"], at["omega1"]))
    assert np.abs(turn - turn[0] - body_rate * t).max() < 64 * EPS * abs(body_rate) * t[-1]
    assert np.ptp(at["omega3"]) <= 4 * EPS * abs(at["omega3"][0])
    # 3 goes round L in space once a space period (eq. 147)
    e3 = quaternion_rotate(columns(m.at(np.array([0.0, T_space, 2 * T_space])), Q),
                           np.array([[0.0, 0.0, 1.0]] * 3))
    assert np.abs(e3[1:] - e3[0]).max() < 1e-12


def test_at_takes_numbers_and_arrays_and_refuses_what_is_no_time():
    m = rl.top_nutation().motion()
    one = m.at(0.25)
    assert one["qw"].shape == () and set(one) == set(rl.Motion.columns)
    grid = m.at(np.full((2, 3), 0.25))
    assert grid["omega3"].shape == (2, 3) and np.all(grid["omega3"] == one["omega3"])
    for bad, rule in ((-1.0, "starts at t = 0"), (float("nan"), "finite"), (float("inf"), "finite")):
        with pytest.raises(ValueError, match=rule):
            m.at(bad)
    with pytest.raises(ValueError, match="lamina_tensor has no motion"):
        rl.lamina_tensor().motion()
    for name, c in rl.Motion.columns.items():
        assert c.unit and c.meaning, name
