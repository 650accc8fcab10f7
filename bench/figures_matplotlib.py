#!/usr/bin/env python3
"""matplotlib peer for the figure-speed benchmark.

Draws the same figures as the labs (same data or data of the same size and
shape, 1600x1200 pixels: figsize 16x12 inches at 100 dpi, similar elements:
lines, markers, legends, labels, titles, grids; 3D scenes with
mpl_toolkits.mplot3d, plot_surface for ellipsoids, spheres, disks, cones,
cylinders and tori, lines and quiver for arrows, tubes, thin rods and axes)
with the Agg backend and saves each as PNG. Each figure is timed from creating
it to the PNG on disk and the figure closed, after import (the import time of
matplotlib, pyplot, mplot3d and numpy is measured on its own, once, at the
start of this process), the best of --repeats.

Data: tire_balancing and poinsot series come from the labs' --csv output
(the axle-tilt sweep of the balancing mass is recomputed from eqs. 60 and 61
as the lab does). football's cones come from its --json results, the contrast
body's from a second run with Is/I = 2 (a thin disk) at the same alpha, the
rates against alpha from eqs. 109 and 147. tennis_racquet's flip instants come
from its --csv attitudes; omega(t) for a spin about each axis, the growth of
the disturbance and this racquet's polhode are Euler's equations integrated
in numpy (RK4) from the lab's moments and launch. top_nutation's potential,
turning points and top come from its --json results and --csv, theta(t) exact
beside integrated from a --method splitting4 run, and the paths on the sphere
from three runs with phi_dot0 = +1/2, 0 and -1/2 of the slow steady rate. The
rest (polhodes on the energy ellipsoid, the integrators' error traces at equal
cost, whose final energy errors are the labs' --json ones) is regenerated in
numpy with the same number of curves and points, since what is measured is
drawing, not physics. The labs' runs and the integrations are done once,
before any figure is timed.

Writes a JSON array of entries
  {"group": "figures", "case": "<lab>_<what>.png", "tool": "matplotlib", "seconds": s,
   "kind": "figure"}
plus {"case": "import", ..., "kind": "import"} for the import time.

Usage: figures_matplotlib.py --labs DIR --out figures_matplotlib.json [--repeats N] [--keep DIR]
"""

import time

_t0 = time.perf_counter()
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d import Axes3D  # noqa: E402,F401  (registers the 3d projection)
from mpl_toolkits.mplot3d.art3d import Line3DCollection  # noqa: E402

IMPORT_SECONDS = time.perf_counter() - _t0

import argparse  # noqa: E402
import csv  # noqa: E402
import json  # noqa: E402
import math  # noqa: E402
import os  # noqa: E402
import shutil  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import tempfile  # noqa: E402
import textwrap  # noqa: E402
import types  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from progress import Progress, add_arguments, configure, detail, duration  # noqa: E402

# Rough seconds of a figure and of an animation frame, for the progress line's time left.
WEIGHT = {"figure": 0.17, "frame": 0.1}

# Okabe-Ito, as rigid::render's palette
BLACK, ORANGE, SKY, GREEN, YELLOW, BLUE, VERMILLION, PURPLE = (
    "#000000", "#E69F00", "#56B4E9", "#009E73", "#F0E442", "#0072B2", "#D55E00", "#CC79A7")
GRAY, LIGHT = "#808080", "#C8C8C8"
PALETTE = [BLUE, ORANGE, GREEN, VERMILLION, PURPLE, SKY, YELLOW, BLACK]
DASHES = ["-", "--", "-", "-.", "-", ":"]  # the integrators' lines, as the labs' integrators_plot

plt.rcParams.update({
    "font.size": 20, "axes.titlesize": 24, "axes.labelsize": 22, "legend.fontsize": 18,
    "lines.linewidth": 3, "axes.grid": True, "grid.color": "#E6E6E6",
})

SIZE = dict(figsize=(16, 12), dpi=100)
SURFACE = dict(rcount=48, ccount=48, linewidth=0, antialiased=True, shade=True)

# The labs' title prefixes (the lab's name and its inputs), as their default runs print them
POINSOT = "poinsot: A, B, C = (3, 2, 1) m, M = 3.14159 kg, ω₀ = (1, 1, 1) rad/s"
FOOTBALL = "football: body = football"
TENNIS = ("tennis_racquet: mₐ = 0.15 kg, a = 0.13 m, mₗ = 0.18 kg, l = 0.38 m, axis = 2, "
          "ω = 10 rad/s, ε = 0.01")
TOP = ("top_nutation: m = 2 kg, l = 0.04 m, r = 0.05 m, g = 9.8 m/s², S = 500 rpm, θ₀ = 30°, "
       "θ-dot₀ = 0 rad/s, φ-dot₀ = 0 rad/s")
# The labs' comparison of every integrator at equal cost: samples a period of each run
EQUAL_COST_SAMPLES = 8


def read_csv(path):
    """A lab's CSV: the comment lines (# ...) that say what each column is, then a header."""
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
    head, data = rows[0], np.array(rows[1:], dtype=float)
    return {h: data[:, i] for i, h in enumerate(head)}


def run_lab(labs, name, *args):
    out = subprocess.run([os.path.join(labs, name), "--json", *args], check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out)


def lab_title(*parts):
    """A lab's figure title, 'lab: inputs: own', in lines as the lab's renderer breaks it."""
    return textwrap.fill(": ".join(parts), 80)


def resample(t, columns, t_end, n):
    """Columns sampled at t, at n evenly spaced times over [0, t_end]: (times, (n, k) array)."""
    times = np.linspace(0.0, t_end, n)
    return times, np.stack([np.interp(times, t, c) for c in columns], axis=1)


def euler_omega(moments, w0, t_end, n, substeps=2):
    """omega in body axes of the free body at n evenly spaced times over [0, t_end], from
    each start in w0 (its last axis omega): Euler's equations, RK4."""
    I1, I2, I3 = moments
    c = np.array([(I2 - I3) / I1, (I3 - I1) / I2, (I1 - I2) / I3])

    def rate(w):
        return c * np.stack([w[..., 1] * w[..., 2], w[..., 2] * w[..., 0], w[..., 0] * w[..., 1]],
                            axis=-1)

    h = t_end / (n - 1) / substeps
    w = np.array(w0, dtype=float)
    out = np.empty((n,) + w.shape)
    out[0] = w
    for i in range(1, n):
        for _ in range(substeps):
            k1 = rate(w)
            k2 = rate(w + 0.5 * h * k1)
            k3 = rate(w + 0.5 * h * k2)
            k4 = rate(w + h * k3)
            w = w + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        out[i] = w
    return out


def rotation(q):
    """The rotation matrix of the quaternion (w, x, y, z): body axes to space."""
    w, x, y, z = np.asarray(q, float) / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def rotation_between(a, b):
    """The rotation that takes the direction a to the direction b (Eigen's FromTwoVectors)."""
    a = np.asarray(a, float) / np.linalg.norm(a)
    b = np.asarray(b, float) / np.linalg.norm(b)
    v, c = np.cross(a, b), float(np.dot(a, b))
    k = np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])
    return np.eye(3) + k + k @ k / (1 + c)


def about_z(angle):
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1.0]])


# ---- 2D helpers -------------------------------------------------------------------

def ref_line(ax, y, text, color=GRAY, x=0.99):
    """A dashed horizontal reference line with its label on it, as the labs' add_ref_line."""
    ax.axhline(y, color=color, ls="--", lw=2)
    ax.annotate(text, (x, y), xycoords=("axes fraction", "data"), xytext=(0, 6),
                textcoords="offset points", ha="right" if x > 0.5 else "left", color=color)


# ---- 3D helpers ---------------------------------------------------------------

def surface(ax, x, y, z, color, alpha, label):
    ax.plot_surface(x, y, z, color=color, alpha=alpha, **SURFACE)
    if label:
        # matplotlib 3.6 cannot put a 3D surface in a legend: a square swatch stands in
        ax.plot([], [], "s", color=color, alpha=alpha, markersize=18, label=label)


def rings(ax, pts, color, alpha, label):
    """A surface through rings of points: pts[j], an (n, 3) array, is its j-th ring."""
    x, y, z = (np.stack([p[:, k] for p in pts], axis=1) for k in range(3))
    surface(ax, x, y, z, color, alpha, label)


def ellipsoid(ax, centre, semi, color, alpha=1.0, label=None, n=48):
    u = np.linspace(0, 2 * np.pi, n)
    v = np.linspace(0, np.pi, n // 2)
    x = centre[0] + semi[0] * np.outer(np.cos(u), np.sin(v))
    y = centre[1] + semi[1] * np.outer(np.sin(u), np.sin(v))
    z = centre[2] + semi[2] * np.outer(np.ones_like(u), np.cos(v))
    surface(ax, x, y, z, color, alpha, label)


def frame(axis):
    axis = np.asarray(axis, float) / np.linalg.norm(axis)
    a = np.array([1.0, 0, 0]) if abs(axis[0]) < 0.9 else np.array([0, 1.0, 0])
    e1 = np.cross(axis, a)
    e1 /= np.linalg.norm(e1)
    return e1, np.cross(axis, e1), axis


def ring(centre, normal, radius, n=48):
    """n points round the circle of a radius about centre, normal to normal (the last the first)."""
    e1, e2, _ = frame(normal)
    u = np.linspace(0, 2 * np.pi, n)
    return np.asarray(centre, float) + radius * (np.outer(np.cos(u), e1) + np.outer(np.sin(u), e2))


def cone(ax, apex, base, radius, color, alpha=1.0, label=None, n=48):
    rim = ring(base, np.subtract(apex, base), radius, n)
    rings(ax, [rim, np.tile(np.asarray(apex, float), (n, 1))], color, alpha, label)


def disk(ax, centre, normal, radius, color, alpha=1.0, label=None, n=48):
    rings(ax, [ring(centre, normal, 0.0, n), ring(centre, normal, radius, n)], color, alpha, label)


def cylinder(ax, start, end, radius, color, alpha=1.0, label=None, n=48):
    """A capped cylinder: its side and a disk at each end."""
    axis = np.subtract(end, start)
    rings(ax, [ring(start, axis, radius, n), ring(end, axis, radius, n)], color, alpha, label)
    for c in (start, end):
        disk(ax, c, axis, radius, color, alpha, n=n)


def torus(ax, centre, normal, radius, tube, color, alpha=1.0, label=None, n=48, m=12):
    """A ring of a radius about normal, its tube of radius tube: n segments round, m across."""
    _, _, e3 = frame(normal)
    pts = [ring(np.asarray(centre) + tube * math.sin(s) * e3, normal,
                radius + tube * math.cos(s), n) for s in np.linspace(0, 2 * np.pi, m)]
    rings(ax, pts, color, alpha, label)


def arrow(ax, start, end, color, label=None, lw=4):
    d = np.subtract(end, start)
    ax.quiver(*start, *d, color=color, linewidth=lw, arrow_length_ratio=0.12, label=label)
    # quiver scales the axes to the arrows' tails only: the tip too, as the labs' scenes fit
    ax.auto_scale_xyz(*np.stack([start, end], axis=1), had_data=True)


def axes_triad(ax, length, labels, origin=(0, 0, 0)):
    for k, name in enumerate(labels):
        e = np.zeros(3)
        e[k] = length
        arrow(ax, origin, np.add(origin, e), "#505050", lw=2.5)
        ax.text(*(np.add(origin, 1.08 * e)), name, fontsize=22)


def view_from(eye, target):
    """matplotlib's (elev, azim) for a lab's camera at eye looking at target."""
    d = np.subtract(eye, target)
    return (math.degrees(math.atan2(d[2], math.hypot(d[0], d[1]))),
            math.degrees(math.atan2(d[1], d[0])))


def scene_axes(fig, title, elev=25, azim=-60):
    ax = fig.add_subplot(projection="3d")
    ax.set_title(title, fontsize=22)
    ax.view_init(elev=elev, azim=azim)
    return ax


def save(fig, path):
    fig.savefig(path)
    plt.close(fig)


# ---- the figures ----------------------------------------------------------------

def lamina_scene(d, path):
    fig = plt.figure(**SIZE)
    ax = scene_axes(fig, "lamina_tensor: m = 1 kg, a = 1 m, b = 2 m, origin at the corner, "
                         "angle(L, ω) = 51.5°", 35, -60)
    a, b = 1.0, 2.0
    # the lamina: a thin box as two faces
    xs, ys = np.meshgrid([0, a], [0, b])
    for z in (-0.01, 0.01):
        surface(ax, xs, ys, np.full_like(xs, z, dtype=float), SKY, 0.55,
                "lamina" if z < 0 else None)
    n = np.array([0.8, 0.6, 0.0])
    ax.plot(*np.outer([-0.8, 2.3], n).T, color=GRAY, lw=3, label="rotation axis n")
    arrow(ax, (0, 0, 0), 1.8 * n, BLUE, "ω")
    L = np.array(d["angular_momentum"])
    arrow(ax, (0, 0, 0), 1.8 * L / np.linalg.norm(L), VERMILLION, "L = Iω (direction)")
    ax.text(*(1.95 * n), "ω", color=BLUE)
    ax.text(*(1.95 * L / np.linalg.norm(L)), "L", color=VERMILLION)
    axes = np.linalg.eigh(np.array(d["inertia_tensor"]))[1].T
    for i, (e, c) in enumerate(zip(axes, (GREEN, ORANGE, PURPLE))):
        reach = 1.2 if i == 2 else 1.5
        ax.plot(*np.outer([-reach, reach], e).T, color=c, lw=5,
                label=f"principal axis {i + 1}: I_{i + 1}")
        ax.text(*(1.1 * reach * e), str(i + 1), color=c)
    axes_triad(ax, 0.7, "xyz")
    ax.legend(loc="upper right")
    save(fig, path)


def lamina_moment(d, path):
    I = np.array(d["inertia_tensor"])
    alpha = np.radians(np.linspace(-90, 90, 361))
    n = np.stack([np.cos(alpha), np.sin(alpha), np.zeros_like(alpha)], axis=1)
    moment = np.einsum("ij,jk,ik->i", n, I, n)
    fig, ax = plt.subplots(**SIZE)
    ax.set_title("lamina_tensor: m = 1 kg, a = 1 m, b = 2 m, origin at the corner: "
                 "moment about an axis in the x-y plane")
    ax.plot(np.degrees(alpha), moment, color=BLUE, label="I(α) = n·I·n")
    for k in (np.argmin(moment), np.argmax(moment)):
        deg = np.degrees(alpha[k])
        ax.axvline(deg, color=GRAY, lw=2, label=f"principal axis {deg:.1f}°")
        ax.annotate(f"{moment[k]:.4g} kg m²", (deg, moment[k]), xytext=(10, 20),
                    textcoords="offset points")
    ax.plot([36.87], [0.4933], "o", color=VERMILLION, markersize=12, label="chosen axis n")
    ax.set_xlim(-90, 90)
    ax.set_ylim(0, 1.15 * moment.max())
    ax.set_xlabel("axis angle α from x (°)")
    ax.set_ylabel("moment n·I·n (kg m²)")
    ax.legend(loc="lower left")
    save(fig, path)


def tire_scene(d, path):
    a, b, tilt = 0.18, 0.05, math.radians(12.0)
    fig = plt.figure(**SIZE)
    ax = scene_axes(fig, "tire_balancing: m = 10 kg, a = 0.18 m, b = 0.05 m, θ = 1° "
                         "(angles drawn ×12)", 25, -70)
    disk(ax, (0, 0, 0), (1, 0, 0), a, LIGHT, 0.6, "disk (symmetry axis x)")
    axle = np.array([math.cos(tilt), math.sin(tilt), 0])
    ax.plot(*np.outer([-1.9 * a, 1.9 * a], axle).T, color=GRAY, lw=8, label="crooked axle")
    m0 = d["results"]["balance_mass_kg"]
    for i, c in enumerate(((-b, a, 0), (b, -a, 0))):
        ellipsoid(ax, c, [0.02] * 3, VERMILLION, 1.0,
                  f"balancing masses m_0 = {1e3 * m0:.1f} g" if i == 0 else None, n=24)
    length = 1.6 * a
    cone_angle = math.radians(6.0)
    cone(ax, (0, 0, 0), length * math.cos(cone_angle) * axle, length * math.sin(cone_angle),
         SKY, 0.35, "cone swept by L (unbalanced)")
    L = np.array([math.cos(tilt + cone_angle), math.sin(tilt + cone_angle), 0])
    arrow(ax, (0, 0, 0), length * L, BLUE, "L before balancing")
    arrow(ax, (0, 0, 0), 1.12 * length * axle, GREEN, "ω along the axle")
    ax.text(*(1.05 * length * L), "L", color=BLUE)
    ax.text(*(1.15 * length * axle), "ω", color=GREEN)
    axes_triad(ax, 0.6 * a, "xyz")
    ax.legend(loc="upper right")
    save(fig, path)


def tire_mass(d, path):
    m, a, b = 10.0, 0.18, 0.05
    tilt = np.radians(np.linspace(5.0 / 200, 5.0, 200))
    # eq. 60: tan 2θ = 2 P / (I1 - I2) with P from the masses; eq. 61: θ ≈ 8 b m0 / (a m)
    small = 1e3 * tilt * a * m / (8 * b)
    exact = small * np.tan(2 * tilt) / (2 * tilt)
    fig, ax = plt.subplots(**SIZE)
    ax.set_title("tire_balancing: m = 10 kg, a = 0.18 m, b = 0.05 m, θ = 1°: "
                 "balancing mass against axle tilt")
    ax.plot(np.degrees(tilt), exact, color=BLUE, label="exact, tan 2θ (eq. 60)")
    ax.plot(np.degrees(tilt), small, "--", color=ORANGE, label="small angle, θ ≈ 8bm₀/(am) (eq. 61)")
    m0 = 1e3 * d["results"]["balance_mass_kg"]
    ax.plot([1.0], [m0], "o", color=BLUE, markersize=12, label=f"this wheel: {m0:.1f} g")
    ax.set_xlim(0, 5)
    ax.set_ylim(0)
    ax.set_xlabel("axle tilt θ (°)")
    ax.set_ylabel("balancing mass m₀ (g)")
    ax.legend()
    save(fig, path)


def surface_curve(semi, k, family, about_largest, n):
    """A closed curve of n points on the ellipsoid, about axis 1 or 3 (same size as a polhode)."""
    s = np.linspace(0, 2 * np.pi, n)
    r = 0.95 * k / (family + 1)
    if about_largest:
        d = np.stack([r * np.cos(s), r * np.sin(s), np.ones_like(s)], axis=1)
    else:
        d = np.stack([np.ones_like(s), r * np.cos(s), r * np.sin(s)], axis=1)
    d /= np.linalg.norm(d / semi, axis=1)[:, None]
    return d * 1.004


def polhodes_figure(path, title, semi, polhode, omega0):
    """The labs' polhodes_scene (poinsot, tennis_racquet): 7 polhodes each way about the largest
    and the smallest axis (moments in ascending order), the two separatrix ellipses through the
    intermediate axis, this body's polhode and omega0 on the energy ellipsoid."""
    semi = np.asarray(semi, float)
    size = semi.max()
    fig = plt.figure(**SIZE)
    ax = scene_axes(fig, title, *view_from((3.2, 2.3, 2.0), (0, 0, 0.2)))
    ellipsoid(ax, (0, 0, 0), semi, LIGHT, 1.0, "energy ellipsoid")
    family = 7
    for k in range(1, family + 1):
        for about_largest in (True, False):
            for sign in (1, -1):
                c = surface_curve(semi, k, family, about_largest, 240) * sign
                label = None
                if k == 1 and sign > 0:
                    label = ("polhodes about the largest axis" if about_largest
                             else "polhodes about the smallest axis")
                ax.plot(*c.T, color=PURPLE if about_largest else GREEN, lw=3, label=label)
    # each separatrix lies in a plane through axis 2 where I1 (I2 - I1) ω1² = I3 (I3 - I2) ω3²
    I1, I2, I3 = 1 / semi ** 2  # the moments up to a factor 2T
    s = np.linspace(0, 2 * np.pi, 400)
    for i, sign in enumerate((1, -1)):
        u = np.array([1.0, 0.0, sign * math.sqrt(I1 * (I2 - I1) / (I3 * (I3 - I2)))])
        u /= np.linalg.norm(u / semi)
        c = 1.004 * (np.outer(np.cos(s), [0, semi[1], 0]) + np.outer(np.sin(s), u))
        ax.plot(*c.T, color=BLACK, lw=4, label="separatrix" if i == 0 else None)
    ax.plot(*(1.004 * np.asarray(polhode)).T, color=BLUE, lw=5, label="this body's polhode")
    ellipsoid(ax, 1.004 * np.asarray(omega0), [0.03 * size] * 3, BLACK, 1.0, "ω₀", n=24)
    axes_triad(ax, 1.3 * size, ["ω₁", "ω₂", "ω₃"])
    ax.legend(loc="upper right")
    ax.set_aspect("equal")
    save(fig, path)


def poinsot_ellipsoids(d, series, path):
    res = d["results"]
    fig = plt.figure(**SIZE)
    ax = scene_axes(fig, lab_title(POINSOT, "energy and momentum ellipsoids"))
    ellipsoid(ax, (0, 0, 0), res["energy_ellipsoid_semi_axes"], SKY, 0.45,
              "energy ellipsoid ΣIᵢωᵢ² = 2T")
    ellipsoid(ax, (0, 0, 0), res["momentum_ellipsoid_semi_axes"], ORANGE, 0.35,
              "momentum ellipsoid ΣIᵢ²ωᵢ² = L²")
    w = np.stack([series["omega1"], series["omega2"], series["omega3"]], axis=1)[:400]
    ax.plot(*w.T, color=VERMILLION, lw=5, label="polhode")
    ellipsoid(ax, w[0], [0.1] * 3, BLACK, 1.0, "ω₀", n=24)
    size = max(max(res["energy_ellipsoid_semi_axes"]), max(res["momentum_ellipsoid_semi_axes"]))
    axes_triad(ax, 1.25 * size, ["ω₁", "ω₂", "ω₃"])
    ax.legend(loc="upper right")
    save(fig, path)


def poinsot_polhodes(d, series, path):
    res = d["results"]
    # this body's polhode: one period of omega, 400 points, as the lab's
    _, w = resample(series["t_s"], [series["omega1"], series["omega2"], series["omega3"]],
                    res["polhode_period_s"], 400)
    polhodes_figure(path, lab_title(POINSOT, "polhodes on the energy ellipsoid"),
                    res["energy_ellipsoid_semi_axes"], w, w[0])


def poinsot_omega(d, series, path):
    t = series["t_s"]
    w = [series["omega1"], series["omega2"], series["omega3"]]
    fig, (left, right) = plt.subplots(1, 2, **SIZE)
    fig.suptitle(lab_title(POINSOT), fontsize=24)
    left.set_title("angular velocity in body axes")
    for i in range(3):
        left.plot(t, w[i], color=PALETTE[i], label=f"ω{'₁₂₃'[i]}")
    left.set_xlabel("t (s)")
    left.set_ylabel("ωᵢ (rad/s)")
    left.legend()
    right.set_title("phase plot")
    right.plot(w[0], w[1], color=PALETTE[1], label="ω₂ against ω₁")
    right.plot(w[0], w[2], color=PALETTE[2], label="ω₃ against ω₁")
    right.plot([w[0][0]] * 2, [w[1][0], w[2][0]], "o", color=BLACK, markersize=12, label="t = 0")
    right.set_aspect("equal", adjustable="datalim")
    right.set_xlabel("ω₁ (rad/s)")
    right.set_ylabel("ωⱼ (rad/s)")
    right.legend()
    save(fig, path)


def equal_cost_runs(res, period, tolerances, finals, seed):
    """The six methods of a lab's comparison at equal cost: their legend names (the fixed steps
    that cost the lab's evaluations a period: 1, 5 and 4 a step), the sample times in periods
    (EQUAL_COST_SAMPLES a period, from t = 0) and synthetic error traces, the error growing to
    finals[k], the energy error to the maximum the lab reports for that method."""
    h = period / res["equal_cost_evaluations_per_period"]
    names = [f"splitting, h = {h:.3g} s", f"splitting4, h = {5 * h:.3g} s",
             f"rk4, h = {4 * h:.3g} s"]
    names += [f"{m}, tol {tol:.2g}" for m, tol in zip(("dopri5", "rkf78", "bulirsch-stoer"),
                                                      tolerances)]
    keys = ["splitting", "splitting4", "rk4", "dopri5", "rkf78", "bulirsch_stoer"]
    periods = res["equal_cost_periods"]
    t = np.linspace(0, periods, int(round(periods * EQUAL_COST_SAMPLES)) + 1)
    x = t / periods
    rng = np.random.default_rng(seed)
    curves = []
    for k, key in enumerate(keys):
        symplectic = k < 2  # an energy error in a band, not a drift
        noise = np.exp(0.2 * rng.standard_normal((2, t.size)))
        error = finals[k] * x ** (1.0 if symplectic else 2.0) * (1 + 0.3 * np.sin(np.pi * t) ** 2)
        energy = (res[f"equal_cost_energy_error_max_rel_{key}"]
                  * (np.minimum(1.0, 20 * x) if symplectic else x))
        curves.append((error * noise[0], energy * noise[1]))
    return names, t, curves


def equal_cost_title(res):
    return f"at equal cost: {res['equal_cost_evaluations_per_period']:g} evaluations a period"


def integrators_figure(path, title, t, names, curves, error_title, error_label, energy_label,
                       t_label):
    """The labs' integrators_plot: each method's error and energy error, the largest so far
    from the second sample on (a floor of 1e-17), on log axes side by side."""
    fig, (err, energy) = plt.subplots(1, 2, **SIZE)
    fig.suptitle(title, fontsize=24)
    for k, (name, errors) in enumerate(zip(names, curves)):
        for ax, e in zip((err, energy), errors):
            ax.semilogy(t[1:], np.maximum.accumulate(np.maximum(e[1:], 1e-17)), DASHES[k % 6],
                        color=PALETTE[k], label=name)
    err.set_title(f"{error_title}, largest so far")
    err.set_xlabel(t_label)
    err.set_ylabel(error_label)
    err.legend(loc="lower right")
    energy.set_title("energy error, largest so far")
    energy.set_xlabel(t_label)
    energy.set_ylabel(energy_label)
    save(fig, path)


def poinsot_integrators(d, path):
    res = d["results"]
    names, t, curves = equal_cost_runs(res, res["polhode_period_s"], (4.3e-6, 4.5e-5, 8.7e-6),
                                       (3.3e-2, 2.6e-2, 2.5e-2, 3.0e-2, 9.0e-2, 1.7e-1), 1)
    integrators_figure(path, lab_title(POINSOT, equal_cost_title(res)), t,
                       names, curves, "error in ω", "|ω - ω_exact| / |ω₀|", "|T - T₀| / T₀",
                       "t (polhode periods)")


def football_cones(res, path, prefix=""):
    """The body cone (about 3) rolling on the space cone (about L) along omega; small angles
    magnified by one factor, as the lab's."""
    theta = math.radians(res["theta_deg"])
    alpha = math.radians(res["body_cone_half_angle_deg"])
    space = math.radians(res["space_cone_half_angle_deg"])
    magnify = max(1.0, min(math.radians(22.0) / alpha, math.radians(70.0) / max(theta, alpha)))
    theta, alpha, space = magnify * theta, magnify * alpha, magnify * space
    lead = theta - alpha  # omega's angle from L
    L = np.array([0.0, 0.0, 1.0])
    axis3 = np.array([math.sin(theta), 0.0, math.cos(theta)])
    omega = np.array([math.sin(lead), 0.0, math.cos(lead)])
    own = (f"{prefix}Is/I = {res['moment_ratio']:.6g}, α = {res['body_cone_half_angle_deg']:.3g}°, "
           f"body cone rolls {'round' if res['cones_touch'] == 'inside' else 'outside'} "
           f"the space cone")
    if magnify > 1:
        own += f"; angles ×{magnify:.3g}"
    fig = plt.figure(**SIZE)
    ax = scene_axes(fig, lab_title(FOOTBALL, own), *view_from((0.9, -3.6, 1.5), (0.15, 0, 0.55)))
    # the space cone as lines: its rim and 12 lines from the apex
    rim = ring((0, 0, math.cos(space)), L, math.sin(space), 121)
    ax.plot(*rim.T, color=VERMILLION, lw=3, label="space cone (fixed, about L)")
    ax.add_collection3d(Line3DCollection([[(0, 0, 0), p] for p in rim[:-1:10]],
                                         colors=VERMILLION, linewidths=2))
    cone(ax, (0, 0, 0), math.cos(alpha) * axis3, math.sin(alpha), PURPLE, 0.35,
         "body cone (about 3, rolls)")
    arrow(ax, (0, 0, 0), 1.45 * L, VERMILLION, "L (fixed in space)")
    arrow(ax, (0, 0, 0), 1.45 * axis3, PURPLE, "symmetry axis 3")
    arrow(ax, (0, 0, 0), 1.3 * omega, BLUE, "ω, the line of contact")
    for r, a, color, label in ((1.45, theta, PURPLE, "path of 3 about L"),
                               (1.3, lead, BLUE, "path of ω about L")):
        c = ring((0, 0, r * math.cos(a)), L, r * math.sin(abs(a)), 121)
        ax.plot(*c.T, color=color, lw=3, label=label)
    for at, text, color in ((1.5 * L, "L", VERMILLION), (1.5 * axis3, "3", PURPLE),
                            (1.35 * omega, "ω", BLUE)):
        ax.text(*at, text, color=color)
    ax.legend(loc="upper right")
    ax.set_aspect("equal")
    save(fig, path)


def football_rates(res, path):
    ratio = res["moment_ratio"]
    alpha = np.radians(0.5 * np.arange(1, 180))
    body = np.cos(alpha) * (ratio - 1)  # eq. 109, Omega / omega
    space = np.sqrt(1 + (ratio ** 2 - 1) * np.cos(alpha) ** 2)  # eq. 147, phi_dot / omega
    a0 = res["body_cone_half_angle_deg"]
    fig, ax = plt.subplots(**SIZE)
    ax.set_title(lab_title(FOOTBALL, f"rates against α, Is/I = {ratio:.4g}"))
    ax.plot(np.degrees(alpha), space, color=VERMILLION,
            label="φ-dot / ω, 3 about L in space (eq. 147)")
    ax.plot(np.degrees(alpha), body, color=PURPLE, label="Ω / ω, ω about 3 in the body (eq. 109)")
    ax.plot([a0, a0], [res["space_rate_over_omega"], res["body_rate_over_omega"]], "o",
            color=BLACK, markersize=10, label=f"this run, α = {a0:.3g}°")
    ax.set_xlim(0, 90)
    ax.set_xlabel("angle α between ω and 3 (°)")
    ax.set_ylabel("rate / ω")
    ax.legend(loc="upper left")
    save(fig, path)


def tennis_omega(res, motion, path):
    """omega_1, omega_2, omega_3 against t (1500 samples) for a spin about each axis."""
    words = ["the handle", "in the plane", "the face's normal"]
    rates = [res["wobble_frequencies_rad_s"][0], res["growth_rate_per_s"],
             res["wobble_frequencies_rad_s"][1]]
    t = motion["t"]
    fig, panels = plt.subplots(3, 1, gridspec_kw={"hspace": 0.5}, **SIZE)
    fig.suptitle(lab_title(TENNIS, "ω in body axes for a spin about each principal axis"),
                 fontsize=24)
    for axis, ax in enumerate(panels):
        if axis == 1:
            ax.set_title(f"about 2 ({words[1]}): unstable, grows at {rates[1]:.4g}/s, "
                         f"flips every {res['flip_interval_s']:.3g} s", fontsize=22)
        else:
            ax.set_title(f"about {axis + 1} ({words[axis]}): stable, wobbles at "
                         f"{rates[axis]:.4g} rad/s", fontsize=22)
        for i in range(3):
            ax.plot(t, motion["launches"][:, axis, i], color=(GREEN, ORANGE, PURPLE)[i],
                    label=f"ω{'₁₂₃'[i]}")
        ax.set_xlim(0, t[-1])
        ax.set_ylabel("ωᵢ (rad/s)")
    panels[2].set_xlabel("t (s)")
    panels[0].legend(loc="center right")
    save(fig, path)


def tennis_growth(res, motion, path):
    """The transverse share of omega about axis 2 (800 samples to the flip) on a log scale, with
    lines of the predicted, the measured and the text's slope through the end of the fit."""
    t, share = motion["share_t"], motion["share"]
    t_begin, t_fit = res["growth_fit_interval_s"]
    share_fit = res["growth_fit_shares"][1]
    top = 1.6

    def slope_line(rate):
        v = share_fit * np.exp(rate * (t - t_fit))
        n = np.argmax(v > top) if (v > top).any() else v.size
        return t[:n], v[:n]

    textbook = res["growth_rate_textbook_per_s"]
    fig, ax = plt.subplots(**SIZE)
    ax.set_title(lab_title(TENNIS, "the disturbance of a spin about 2 grows exponentially"))
    ax.axvspan(t_begin, t_fit, color=GRAY, alpha=0.2, lw=0, label="fitted interval")
    ax.plot(t, share, color=BLACK, label="exact motion")
    for rate, style, color, lw, label in (
            (res["growth_rate_per_s"], "--", BLUE, 3, "predicted, eqs. 86-88: {:.4g}/s"),
            (res["growth_rate_measured_per_s"], ":", VERMILLION, 5, "measured: {:.4g}/s"),
            (textbook, "-.", ORANGE, 3, "eq. 92 (ω₂): {:.4g}/s")):
        ax.plot(*slope_line(rate), style, color=color, lw=lw, label=label.format(rate))
    ref_line(ax, 1.0, "ω all transverse: the flip", x=0.01)
    ax.set_yscale("log")
    ax.set_xlim(0, t[-1])
    ax.set_ylim(0.3 * min(share[0], slope_line(textbook)[1][0]), top)
    ax.set_xlabel("t (s)")
    ax.set_ylabel("transverse share |ω⊥| / |ω| = √(ω₁² + ω₃²) / |ω|")
    ax.legend(loc="lower right")
    save(fig, path)


def tennis_flip(res, inputs, motion, path):
    """The racquet (ring, two faces, handle) with L and body axis 2 at six instants of one flip,
    in a frame that keeps L vertical and turns with the handle about L, as the lab's."""
    a, R = inputs["head_radius"], res["cm_offset_m"]
    head_centre, handle_start = np.array([-R, 0, 0]), np.array([a - R, 0, 0])
    handle_end = np.array([a + inputs["handle_length"] - R, 0, 0])
    length = np.linalg.norm(handle_end - head_centre) + a
    spacing_x, spacing_z = 1.15 * length, 1.35 * a * 2 + 0.6 * length
    z = np.array([0.0, 0.0, 1.0])
    fig = plt.figure(**SIZE)
    ax = scene_axes(fig, lab_title(TENNIS, "one flip: axis 2 turns from L to -L (seen turning "
                                           "with the handle about L)"),
                    *view_from((0.9 * spacing_x, -12 * length, 2.4 * length),
                               (spacing_x, 0, -0.5 * spacing_z)))
    for k, (t, rot, angle) in enumerate(motion["flip"]):
        first = k == 0
        c = np.array([(k % 3) * spacing_x, 0, -(k // 3) * spacing_z])
        head, n3 = c + rot @ head_centre, rot[:, 2]
        torus(ax, head, n3, a, 0.06 * a, GRAY, 1.0, "the head, a ring" if first else None)
        disk(ax, head + 0.004 * a * n3, n3, 0.96 * a, SKY, 1.0, "face toward +3" if first else None)
        disk(ax, head - 0.004 * a * n3, -n3, 0.96 * a, YELLOW, 1.0,
             "face toward -3" if first else None)
        ax.plot(*np.stack([c + rot @ handle_start, c + rot @ handle_end]).T, color=BLACK, lw=6,
                label="the handle, axis 1" if first else None)
        arrow(ax, c, c + 0.55 * length * z, VERMILLION, "L, fixed in space" if first else None,
              lw=3)
        arrow(ax, c, c + 0.4 * length * rot[:, 1], ORANGE, "body axis 2" if first else None, lw=3)
        ax.text(*(c - 0.45 * length * z), f"t = {t:.3f} s", ha="center")
        ax.text(*(c + 0.45 * length * rot[:, 1]), f"{angle:.0f}°", color=ORANGE)
    ax.legend(loc="upper right")
    ax.set_aspect("equal")
    save(fig, path)


def tennis_polhodes(res, motion, path):
    moments = np.array(res["principal_moments"])
    w0 = motion["polhode"][0]
    semi = np.sqrt(np.dot(moments, w0 ** 2) / moments)  # sqrt(2T / I)
    polhodes_figure(path, lab_title(TENNIS, "polhodes on the energy ellipsoid"), semi,
                    motion["polhode"], w0)


def top_potential(res, path):
    """V(theta) of eq. 195 (601 samples) with E', the turning points and the minimum."""
    I, Is, mgl = res["moment_transverse_kg_m2"], res["moment_symmetry_kg_m2"], res["mgl_n_m"]
    p_phi, p_psi, S = res["p_phi"], res["p_psi"], res["spin_rad_s"]

    def potential(th):
        return (p_phi - p_psi * np.cos(th)) ** 2 / (2 * I * np.sin(th) ** 2) + mgl * np.cos(th)

    E_prime = res["energy_j"] - 0.5 * Is * S * S
    lo, hi = math.radians(res["theta_min_deg"]), math.radians(res["theta_max_deg"])
    span = max(hi - lo, math.radians(6.0))
    a, b = max(lo - 0.8 * span, math.radians(0.2)), min(hi + 0.8 * span, math.radians(179.8))
    theta = np.linspace(a, b, 601)
    V = potential(theta)
    k = int(np.clip(np.argmin(V), 1, V.size - 2))  # the minimum: a parabola through 3 samples
    h = theta[1] - theta[0]
    steady = theta[k] + 0.5 * h * (V[k - 1] - V[k + 1]) / (V[k - 1] - 2 * V[k] + V[k + 1])
    V_min = float(potential(steady))
    depth = max(E_prime - V_min, 1e-12 * (abs(E_prime) + mgl))
    y_top, y_bottom = E_prime + 1.2 * depth, V_min - 0.25 * depth
    shown = V <= y_top  # V climbs steeply off the drawn range
    fig, ax = plt.subplots(**SIZE)
    ax.set_title(lab_title(TOP, "the effective potential V(θ) (eq. 195)"))
    ax.plot(np.degrees(theta[shown]), V[shown], color=BLUE, label="V(θ)")
    ref_line(ax, E_prime, f"E' = {E_prime:.5g} J", VERMILLION)
    ax.plot(np.degrees([lo, hi]), [E_prime, E_prime], "o", color=VERMILLION, markersize=13,
            label=f"turning points {math.degrees(lo):.4g}°, {math.degrees(hi):.4g}°")
    ax.plot([math.degrees(steady)], [V_min], "s", color=BLACK, markersize=13,
            label=f"minimum: steady precession at {math.degrees(steady):.4g}°")
    ax.set_xlim(math.degrees(a), math.degrees(b))
    ax.set_ylim(y_bottom, y_top)
    ax.set_xlabel("θ (°)")
    ax.set_ylabel("V(θ) and E' (J)")
    ax.legend(loc="upper center")
    save(fig, path)


def top_paths(res, paths, path):
    """The symmetry axis's path (901 points) on a translucent unit sphere with its turning
    circles, for three starts that differ only in phi_dot0, side by side."""
    reference = abs(res["steady_precession_rates_rad_s"][0])
    gap = 2.6
    z = np.array([0.0, 0.0, 1.0])
    fig = plt.figure(**SIZE)
    ax = scene_axes(fig, lab_title(TOP, f"the symmetry axis on the unit sphere for φ-dot₀ = "
                                        f"{0.5 * reference:.3g}, 0, {-0.5 * reference:.3g} rad/s"),
                    *view_from((gap, -3.5, 10.0), (gap, 0, 0.5)))
    for index, p in enumerate(paths):
        first = index == 0
        c = np.array([gap * index, 0.0, 0.0])
        ellipsoid(ax, c, [1.0] * 3, LIGHT, 0.35, "unit sphere" if first else None)
        ax.plot(*(c + 1.02 * p["axis"]).T, color=PURPLE, lw=5,
                label="path of the symmetry axis" if first else None)
        for k, theta in enumerate((p["theta_min"], p["theta_max"])):
            circle = ring(c + 1.02 * math.cos(theta) * z, z, 1.02 * math.sin(theta), 181)
            ax.plot(*circle.T, color=BLACK, lw=2.5,
                    label="turning circles θₘᵢₙ, θₘₐₓ" if first and k == 0 else None)
        arrow(ax, c, c + 1.25 * z, GRAY, "vertical z" if first else None)
        ax.text(*(c + (0, -1.3, 0)), p["regime"], ha="center")
    ax.legend(loc="upper right")
    ax.set_aspect("equal")
    save(fig, path)


def top_band(res, paths, path):
    """The same three paths as theta against phi (unwrapped), one panel each, with the
    turning angles as dashed lines."""
    fig, axes = plt.subplots(len(paths), 1, **SIZE)
    fig.suptitle(lab_title(TOP, "the band between the turning circles, 3 nutation periods"))
    for ax, p in zip(axes, paths):
        a = p["axis"]
        theta = np.degrees(np.arccos(np.clip(a[:, 2], -1, 1)))
        phi = np.degrees(np.unwrap(np.arctan2(a[:, 1], a[:, 0])))
        ax.plot(phi, theta, color=PURPLE, lw=2)
        for t in (p["theta_min"], p["theta_max"]):
            ax.axhline(math.degrees(t), color=BLACK, ls="--", lw=1.5)
        ax.set_title(p["regime"])
        ax.set_ylabel("θ (°)")
        ax.grid(True, color="#e8e8e8")
    axes[-1].set_xlabel("φ (°)")
    save(fig, path)


def top_theta(res, series, path):
    """theta(t) and phi_dot(t): the exact motion (1201 samples) beside 61 samples of an
    integrated run (splitting4), with theta_min, theta_max and the mean phi_dot."""
    I, p_phi, p_psi = res["moment_transverse_kg_m2"], res["p_phi"], res["p_psi"]

    def phi_dot(theta):  # p_phi = I phi_dot sin^2 theta + p_psi cos theta
        return (p_phi - p_psi * np.cos(theta)) / (I * np.sin(theta) ** 2)

    t, theta = resample(series["t_s"], [series["theta_exact_rad"]], res["t_end_s"], 1201)
    theta = theta[:, 0]
    stride = max(1, series["t_s"].size // 60)
    ti, thetai = series["t_s"][::stride], series["theta_rad"][::stride]
    fig, (upper, lower) = plt.subplots(2, 1, **SIZE)
    fig.suptitle(lab_title(TOP, "nutation and precession"), fontsize=24)
    for ax, exact, integrated in ((upper, np.degrees(theta), np.degrees(thetai)),
                                  (lower, phi_dot(theta), phi_dot(thetai))):
        ax.plot(t, exact, color=BLUE, label="exact")
        ax.plot(ti, integrated, "o", color=VERMILLION, markersize=8,
                label="splitting4, integrated")
    ref_line(upper, res["theta_min_deg"], "θₘᵢₙ", x=0.8)
    ref_line(upper, res["theta_max_deg"], "θₘₐₓ")
    mean = res["mean_precession_rate_rad_s"]
    ref_line(lower, mean, f"mean {mean:.4g} rad/s", x=0.5)
    upper.set_ylabel("θ (°)")
    upper.legend(loc="lower center")
    lower.set_xlabel("t (s)")
    lower.set_ylabel("φ-dot (rad/s)")
    save(fig, path)


def top_top(res, inputs, series, path):
    """The top at t = 0 (tip, spindle, disk) with L, the gravity torque, omega, the circle its
    centre of mass sweeps and the axes."""
    I, Is, mgl = res["moment_transverse_kg_m2"], res["moment_symmetry_kg_m2"], res["mgl_n_m"]
    l, r = inputs["arm"], inputs["disk_radius"]
    size = max(l + r, 2 * r)
    rot = rotation([series[k][0] for k in ("qw", "qx", "qy", "qz")])
    w = np.array([series[k][0] for k in ("omega1", "omega2", "omega3")])
    z = np.array([0.0, 0.0, 1.0])
    e3 = rot[:, 2]
    L = rot @ (np.array([I, I, Is]) * w)
    omega = rot @ w
    torque = -mgl * np.cross(e3, z)
    fig = plt.figure(**SIZE)
    ax = scene_axes(fig, lab_title(TOP, "the top at t = 0; arrows show directions"),
                    *view_from(size * np.array([4.0, -6.5, 1.2]), (0, 0, 0.4 * size)))
    ellipsoid(ax, (0, 0, 0), [0.04 * size] * 3, GRAY, 1.0, "tip (pivot)", n=24)
    ax.plot(*np.outer([0, l + 0.5 * r], e3).T, color=GRAY, lw=8)
    cylinder(ax, (l - 0.05 * r) * e3, (l + 0.05 * r) * e3, r, SKY, 0.5, "disk")
    length = 1.6 * size
    arrow(ax, (0, 0, 0), length * L / np.linalg.norm(L), VERMILLION, "L", lw=6)
    arrow(ax, l * e3, l * e3 + 0.8 * length * torque / np.linalg.norm(torque), YELLOW,
          "gravity torque", lw=6)
    arrow(ax, (0, 0, 0), 1.2 * length * omega / np.linalg.norm(omega), BLUE, "ω", lw=5)
    circle = ring(l * e3[2] * z, z, l * math.hypot(e3[0], e3[1]), 181)
    ax.plot(*circle.T, color=PURPLE, lw=3, label="centre of mass's precession circle")
    axes_triad(ax, 1.4 * size, "xyz")
    ax.legend(loc="upper right")
    ax.set_aspect("equal")
    save(fig, path)


def top_integrators(res, path):
    names, t, curves = equal_cost_runs(res, res["nutation_period_s"], (3.4e-6, 1.2e-5, 8.7e-6),
                                       (4.2e-2, 1.1e-3, 6.5, 4.2, 8.0, 2.9), 2)
    integrators_figure(path, lab_title(TOP, equal_cost_title(res)), t, names, curves,
                       "error in θ", "|θ - θ_exact| (°)", "|E - E₀| / (T₀ + mgl)",
                       "t (nutation periods)")


# ---- data the figures need beyond the labs' output (prepared before any timing) ----------

def flip_instants(res, series, instants=6):
    """tennis_racquet's flip figure from its --csv: the instants where body axis 2 makes the
    k-th of six angles with L through the first flip, each (t, attitude in a frame with L up,
    turned about L so the handle points the same way, the angle in degrees)."""
    t = series["t_s"]
    q = np.stack([series[k] for k in ("qw", "qx", "qy", "qz")], axis=1)
    w = np.stack([series[k] for k in ("omega1", "omega2", "omega3")], axis=1)
    moments = np.array(res["principal_moments"])
    L_body = moments * w[0]
    angle2 = np.arccos(np.clip(moments[1] * w[:, 1] / np.linalg.norm(L_body), -1, 1))
    to_display = rotation_between(rotation(q[0]) @ L_body, (0, 0, 1))
    flip, quarter = res["first_flip_s"], 0.25 * res["polhode_period_s"]
    inside = (t >= flip - quarter) & (t <= flip + quarter)
    ts, rising = t[inside], np.maximum.accumulate(angle2[inside])
    out = []
    for k in range(instants):
        target = rising[0] + (rising[-1] - rising[0]) * (0.03 + 0.94 * k / (instants - 1))
        tk = float(np.interp(target, rising, ts))
        rot = to_display @ rotation([np.interp(tk, t, q[:, i]) for i in range(4)])
        handle = rot[:, 0]
        rot = about_z(-math.atan2(handle[1], handle[0]) + math.radians(-25.0)) @ rot
        out.append((tk, rot, math.degrees(target)))
    return out


def tennis_motion(res, inputs, series):
    """omega(t) launched about each axis, the share of omega off axis 2 up to the first flip,
    this racquet's polhode (one period) and the flip's instants."""
    moments = res["principal_moments"]
    omega, eps = inputs["omega"], inputs["perturbation"]
    w0 = np.zeros((3, 3))  # the launches: along each axis, eps of omega along the next
    for axis in range(3):
        w0[axis, axis] = omega * math.sqrt(1 - eps * eps)
        w0[axis, (axis + 1) % 3] = omega * eps
    spin = int(inputs["spin_axis"]) - 1
    flip = res["first_flip_s"]
    w = euler_omega(moments, w0[1], flip, 800)
    return {"t": np.linspace(0, res["t_end_s"], 1500),
            "launches": euler_omega(moments, w0, res["t_end_s"], 1500),
            "share_t": np.linspace(0, flip, 800),
            "share": np.hypot(w[:, 0], w[:, 2]) / np.linalg.norm(w, axis=1),
            "polhode": euler_omega(moments, w0[spin], res["polhode_period_s"], 400),
            "flip": flip_instants(res, series)}


def top_path_runs(labs, work, res):
    """The symmetry axis over three nutation periods (901 points) from top_nutation runs with
    phi_dot0 = +1/2, 0, -1/2 of the slow steady rate, with their turning angles and regimes."""
    reference = abs(res["steady_precession_rates_rad_s"][0])
    out = []
    for k, phi_dot0 in enumerate((0.5 * reference, 0.0, -0.5 * reference)):
        path = os.path.join(work, f"top_path{k}.csv")
        r = run_lab(labs, "top_nutation", "--phidot0", f"{phi_dot0:.17g}", "--csv", path)["results"]
        s = read_csv(path)
        w, x, y, z = (s[key] for key in ("qw", "qx", "qy", "qz"))
        axis = [2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)]  # R e3
        _, axis = resample(s["t_s"], axis, r["t_end_s"], 901)
        out.append({"axis": axis / np.linalg.norm(axis, axis=1)[:, None], "regime": r["regime"],
                    "theta_min": math.radians(r["theta_min_deg"]),
                    "theta_max": math.radians(r["theta_max_deg"])})
    return out


ANIMATION = dict(frames=300, fps=30, figsize=(12.8, 7.2), dpi=100)  # 10 s at 1280x720


def rotated_ellipsoid(ax, centre, semi, R, color, alpha, n=40):
    """An ellipsoid of these semi-axes turned by R about its centre, as plot_surface draws it."""
    u = np.linspace(0, 2 * np.pi, n)
    v = np.linspace(0, np.pi, n // 2)
    pts = np.stack([semi[0] * np.outer(np.cos(u), np.sin(v)),
                    semi[1] * np.outer(np.sin(u), np.sin(v)),
                    semi[2] * np.outer(np.ones_like(u), np.cos(v))], axis=-1) @ R.T
    ax.plot_surface(*(pts[..., k] + centre[k] for k in range(3)), color=color, alpha=alpha,
                    linewidth=0, antialiased=True, shade=True)


def poinsot_animation(d, series, path, on_frame=None):
    """poinsot --animate drawn by matplotlib's FuncAnimation through its ffmpeg writer (H.264,
    veryfast, CRF 20, as rigidlab's): the body turning with L fixed (down), its energy ellipsoid
    rolling on the invariable plane with the polhode, the herpolhode growing. Every frame clears
    the axes and draws the scene anew, as a user of mplot3d does; the frames are the lab's run
    (its --csv) resampled at the frame times."""
    from matplotlib.animation import FFMpegWriter, FuncAnimation
    res = d["results"]
    semi = np.array([3.0, 2.0, 1.0])
    moments = np.array(res["principal_moments"])
    energy_semi = np.array(res["energy_ellipsoid_semi_axes"])
    t_end = series["t_s"][-1]
    times = np.linspace(0, t_end, ANIMATION["frames"], endpoint=False)
    _, w = resample(series["t_s"], [series["omega1"], series["omega2"], series["omega3"]],
                    t_end, ANIMATION["frames"] + 1)
    _, q = resample(series["t_s"], [series["qw"], series["qx"], series["qy"], series["qz"]],
                    t_end, ANIMATION["frames"] + 1)
    S = rotation_between(moments * w[0], [0, 0, -1])  # L down
    scale = semi.max() / energy_semi.max()
    offset = np.array([3 * semi.max(), 0, 0])
    depth = scale * 2 * res["energy"] / res["angular_momentum_magnitude"]
    polhode = w[:, :].copy()
    contacts = np.array([offset + scale * (S @ rotation(q[k]) @ w[k])
                         for k in range(ANIMATION["frames"])])
    fig = plt.figure(figsize=ANIMATION["figsize"], dpi=ANIMATION["dpi"])
    fig.subplots_adjust(0, 0, 1, 0.86)
    ax = fig.add_subplot(projection="3d")

    def draw(k):
        ax.cla()
        R = S @ rotation(q[k])
        ax.set_title(lab_title(POINSOT, "the body turning, L fixed; its energy ellipsoid rolls "
                               f"on the invariable plane: t = {times[k]:.2f} s"), fontsize=16)
        rotated_ellipsoid(ax, np.zeros(3), semi, R, SKY, 1.0)
        arrow(ax, [0, 0, 0], [0, 0, -1.9 * semi.max()], VERMILLION, "L, fixed in space")
        arrow(ax, [0, 0, 0], 1.7 * scale * (R @ w[k]), BLUE, "ω")
        rotated_ellipsoid(ax, offset, scale * energy_semi, R, LIGHT, 0.55)
        ax.plot(*(offset[:, None] + scale * (R @ (1.004 * polhode.T))), color=BLUE, lw=3,
                label="polhode")
        r = np.linspace(0, 1.2 * np.abs(contacts[:, :2] - offset[:2]).max(), 2)
        a = np.linspace(0, 2 * np.pi, 48)
        ax.plot_surface(offset[0] + np.outer(r, np.cos(a)), offset[1] + np.outer(r, np.sin(a)),
                        np.full((2, 48), offset[2] - depth), color=LIGHT, alpha=0.55, linewidth=0)
        ax.plot(*contacts[:k + 1].T, color=BLACK, lw=3, label="herpolhode")
        ax.legend(loc="upper right")
        ax.view_init(*view_from((1.5, -8.0, 6.0), (1.5, 0, -0.5)))
        ax.set_xlim(-semi.max(), offset[0] + semi.max())
        ax.set_ylim(-semi.max(), semi.max())
        ax.set_zlim(-1.9 * semi.max(), semi.max())
        ax.set_box_aspect((offset[0] + 2 * semi.max(), 2 * semi.max(), 2.9 * semi.max()),
                          zoom=1.3)
        ax.set_axis_off()

    anim = FuncAnimation(fig, draw, frames=ANIMATION["frames"])
    anim.save(path, writer=FFMpegWriter(fps=ANIMATION["fps"], codec="libx264",
                                        extra_args=["-preset", "veryfast", "-crf", "20",
                                                    "-pix_fmt", "yuv420p"]),
              progress_callback=on_frame)
    plt.close(fig)


def lab_runs(labs, work):
    """What the figures draw: each lab's results and series, run as a user runs it."""
    r = types.SimpleNamespace()
    r.lamina = run_lab(labs, "lamina_tensor")["results"]
    r.tire = run_lab(labs, "tire_balancing", "--csv", os.path.join(work, "tire.csv"))
    r.poinsot = run_lab(labs, "poinsot", "--csv", os.path.join(work, "poinsot.csv"))
    r.series = read_csv(os.path.join(work, "poinsot.csv"))
    r.football = run_lab(labs, "football")["results"]
    # the contrast beside this prolate football: an oblate thin disk (Is = 2I) at its alpha
    r.disk_body = run_lab(labs, "football", "--inertia", "1,2", "--alpha-deg",
                          f"{r.football['body_cone_half_angle_deg']:.17g}")["results"]
    tennis = run_lab(labs, "tennis_racquet", "--csv", os.path.join(work, "tennis.csv"))
    r.tennis_inputs, r.tennis = tennis["inputs"], tennis["results"]
    r.racquet = tennis_motion(r.tennis, r.tennis_inputs, read_csv(os.path.join(work, "tennis.csv")))
    # theta(t) beside an integrated run: splitting4, as the lab draws it beside the exact one
    top = run_lab(labs, "top_nutation", "--method", "splitting4",
                  "--csv", os.path.join(work, "top.csv"))
    r.top_inputs, r.top = top["inputs"], top["results"]
    r.top_series = read_csv(os.path.join(work, "top.csv"))
    r.top_paths_data = top_path_runs(labs, work, r.top)
    return r


def figure_list(r):
    """Every figure rigidlab draws, by its PNG's name, as a function of the path."""
    return [
        ("lamina_tensor_scene.png", lambda p: lamina_scene(r.lamina, p)),
        ("lamina_tensor_moment.png", lambda p: lamina_moment(r.lamina, p)),
        ("tire_balancing_scene.png", lambda p: tire_scene(r.tire, p)),
        ("tire_balancing_mass.png", lambda p: tire_mass(r.tire, p)),
        ("poinsot_ellipsoids.png", lambda p: poinsot_ellipsoids(r.poinsot, r.series, p)),
        ("poinsot_polhodes.png", lambda p: poinsot_polhodes(r.poinsot, r.series, p)),
        ("poinsot_omega.png", lambda p: poinsot_omega(r.poinsot, r.series, p)),
        ("poinsot_integrators.png", lambda p: poinsot_integrators(r.poinsot, p)),
        ("football_cones.png", lambda p: football_cones(r.football, p)),
        ("football_cones_contrast.png",
         lambda p: football_cones(r.disk_body, p, "for contrast, an oblate thin disk: ")),
        ("football_rates.png", lambda p: football_rates(r.football, p)),
        ("tennis_racquet_omega.png", lambda p: tennis_omega(r.tennis, r.racquet, p)),
        ("tennis_racquet_growth.png", lambda p: tennis_growth(r.tennis, r.racquet, p)),
        ("tennis_racquet_flip.png",
         lambda p: tennis_flip(r.tennis, r.tennis_inputs, r.racquet, p)),
        ("tennis_racquet_polhodes.png", lambda p: tennis_polhodes(r.tennis, r.racquet, p)),
        ("top_nutation_potential.png", lambda p: top_potential(r.top, p)),
        ("top_nutation_paths.png", lambda p: top_paths(r.top, r.top_paths_data, p)),
        ("top_nutation_band.png", lambda p: top_band(r.top, r.top_paths_data, p)),
        ("top_nutation_theta.png", lambda p: top_theta(r.top, r.top_series, p)),
        ("top_nutation_top.png", lambda p: top_top(r.top, r.top_inputs, r.top_series, p)),
        ("top_nutation_integrators.png", lambda p: top_integrators(r.top, p)),
    ]


def time_figures(figures, out_dir, repeats, progress):
    """The best time of each figure, in rounds over the whole set, so a burst of load on
    the machine hits one round, not one figure."""
    best = {name: math.inf for name, _ in figures}
    for _ in range(repeats):
        for name, draw in figures:
            t0 = time.perf_counter()
            draw(os.path.join(out_dir, name))
            best[name] = min(best[name], time.perf_counter() - t0)
            progress.update(progress.done + WEIGHT["figure"], name)
    entries = []
    for name, _ in figures:
        entries.append({"group": "figures", "case": name, "tool": "matplotlib",
                        "seconds": best[name], "kind": "figure"})
        detail(f"figures_matplotlib: {name}: {best[name] * 1e3:.1f} ms")
    return entries


def time_animation(r, out_dir, progress):
    """The poinsot animation, once (it takes tens of seconds): its entry."""
    figures_done = progress.done
    t0 = time.perf_counter()
    poinsot_animation(r.poinsot, r.series, os.path.join(out_dir, "poinsot_motion.mp4"),
                      lambda i, n: progress.update(figures_done + (i + 1) * WEIGHT["frame"],
                                                   f"animation frame {i + 1}/{n}"))
    seconds = time.perf_counter() - t0
    detail(f"figures_matplotlib: poinsot animation (300 frames, 1280x720): {seconds:.1f} s")
    return {"group": "figures", "case": "poinsot animation", "tool": "matplotlib",
            "seconds": seconds, "kind": "animation", "frames": ANIMATION["frames"],
            "fps": ANIMATION["fps"], "size": "1280x720"}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--labs", required=True, help="directory with the lab executables")
    ap.add_argument("--out", required=True)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--keep", help="directory to leave the PNGs in (default: a temporary one)")
    add_arguments(ap)
    args = ap.parse_args()
    configure(args)

    work = tempfile.mkdtemp(prefix="rigid_mpl_")
    out_dir = args.keep or work
    os.makedirs(out_dir, exist_ok=True)
    runs = lab_runs(args.labs, work)
    figures = figure_list(runs)
    animating = shutil.which("ffmpeg") is not None
    progress = Progress("bench figures_matplotlib", None,
                        args.repeats * len(figures) * WEIGHT["figure"]
                        + (ANIMATION["frames"] * WEIGHT["frame"] if animating else 0.0),
                        args.quiet)
    entries = [{"group": "figures", "case": "import", "tool": "matplotlib",
                "seconds": IMPORT_SECONDS, "kind": "import"}]
    entries += time_figures(figures, out_dir, args.repeats, progress)
    detail(f"figures_matplotlib: import {IMPORT_SECONDS * 1e3:.1f} ms")
    summary = f"{len(figures)} figures"
    # the animation where ffmpeg is installed
    if animating:
        entries.append(time_animation(runs, out_dir, progress))
        summary += f" and the poinsot animation ({entries[-1]['seconds']:.1f} s)"
    with open(args.out + ".tmp", "w") as f:
        json.dump(entries, f, indent=1)
    os.replace(args.out + ".tmp", args.out)
    progress.finish(f"{summary} in {duration(progress.seconds())}; wrote {args.out}")


if __name__ == "__main__":
    main()
