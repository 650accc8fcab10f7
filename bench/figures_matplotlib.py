#!/usr/bin/python3
"""matplotlib peer for the figure-speed benchmark (issue 3, "Speed").

Draws the same figures as the labs (same data or data of the same size and
shape, 1600x1200 pixels: figsize 16x12 inches at 100 dpi, similar elements:
lines, markers, legends, labels, titles, grids; 3D scenes with
mpl_toolkits.mplot3d, plot_surface for ellipsoids, spheres, disks and cones,
lines and quiver for arrows, tubes and axes) with the Agg backend and saves
each as PNG. Each figure is timed from creating it to the PNG on disk and the
figure closed, after import (the import time of matplotlib, pyplot, mplot3d
and numpy is measured on its own, once, at the start of this process), the
best of --repeats.

Data: tire_balancing and poinsot series come from the labs' --csv output
(the axle-tilt sweep of the balancing mass is recomputed from eqs. 60 and 61
as the lab does); the rest (polhodes on the energy ellipsoid, integrator error
traces) is regenerated in numpy with the same number of curves and points,
since what is measured is drawing, not physics.

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

IMPORT_SECONDS = time.perf_counter() - _t0

import argparse  # noqa: E402
import csv  # noqa: E402
import json  # noqa: E402
import math  # noqa: E402
import os  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import tempfile  # noqa: E402

# Okabe-Ito, as rigid::render's palette
BLACK, ORANGE, SKY, GREEN, YELLOW, BLUE, VERMILLION, PURPLE = (
    "#000000", "#E69F00", "#56B4E9", "#009E73", "#F0E442", "#0072B2", "#D55E00", "#CC79A7")
GRAY, LIGHT = "#808080", "#C8C8C8"
PALETTE = [BLUE, ORANGE, GREEN, VERMILLION, PURPLE, SKY, YELLOW, BLACK]

plt.rcParams.update({
    "font.size": 20, "axes.titlesize": 24, "axes.labelsize": 22, "legend.fontsize": 18,
    "lines.linewidth": 3, "axes.grid": True, "grid.color": "#E6E6E6",
})

SIZE = dict(figsize=(16, 12), dpi=100)
SURFACE = dict(rcount=48, ccount=48, linewidth=0, antialiased=True, shade=True)


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    head, data = rows[0], np.array(rows[1:], dtype=float)
    return {h: data[:, i] for i, h in enumerate(head)}


def run_lab(labs, name, *args):
    out = subprocess.run([os.path.join(labs, name), "--json", *args], check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out)


# ---- 3D helpers ---------------------------------------------------------------

def surface(ax, x, y, z, color, alpha, label):
    ax.plot_surface(x, y, z, color=color, alpha=alpha, **SURFACE)
    if label:
        # matplotlib 3.6 cannot put a 3D surface in a legend: a square swatch stands in
        ax.plot([], [], "s", color=color, alpha=alpha, markersize=18, label=label)


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


def cone(ax, apex, base, radius, color, alpha=1.0, label=None, n=48):
    e1, e2, _ = frame(np.subtract(apex, base))
    u = np.linspace(0, 2 * np.pi, n)
    s = np.array([0.0, 1.0])  # base ring to apex
    ring = (np.outer(np.cos(u), e1) + np.outer(np.sin(u), e2)) * radius
    pts = [np.asarray(base) + ring * (1 - t) + t * (np.subtract(apex, base)) for t in s]
    x, y, z = (np.stack([p[:, k] for p in pts], axis=1) for k in range(3))
    surface(ax, x, y, z, color, alpha, label)


def disk(ax, centre, normal, radius, color, alpha=1.0, label=None, n=48):
    e1, e2, _ = frame(normal)
    u = np.linspace(0, 2 * np.pi, n)
    r = np.array([0.0, 1.0])
    pts = [np.asarray(centre) + radius * rr * (np.outer(np.cos(u), e1) + np.outer(np.sin(u), e2))
           for rr in r]
    x, y, z = (np.stack([p[:, k] for p in pts], axis=1) for k in range(3))
    surface(ax, x, y, z, color, alpha, label)


def arrow(ax, start, end, color, label=None, lw=4):
    d = np.subtract(end, start)
    ax.quiver(*start, *d, color=color, linewidth=lw, arrow_length_ratio=0.12, label=label)


def axes_triad(ax, length, labels, origin=(0, 0, 0)):
    for k, name in enumerate(labels):
        e = np.zeros(3)
        e[k] = length
        arrow(ax, origin, np.add(origin, e), "#505050", lw=2.5)
        ax.text(*(np.add(origin, 1.08 * e)), name, fontsize=22)


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


def poinsot_ellipsoids(d, series, path):
    res = d["results"]
    fig = plt.figure(**SIZE)
    ax = scene_axes(fig, "poinsot: I = (3.142, 6.283, 8.168) kg m², ω₀ = (1, 1, 1) rad/s: "
                         "energy and momentum ellipsoids")
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
    semi = np.array(d["results"]["energy_ellipsoid_semi_axes"])
    fig = plt.figure(**SIZE)
    ax = scene_axes(fig, "poinsot: I = (3.142, 6.283, 8.168) kg m², ω₀ = (1, 1, 1) rad/s: "
                         "polhodes on the energy ellipsoid")
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
                ax.plot(*c.T, color=BLUE if about_largest else GREEN, lw=3, label=label)
    for i, sign in enumerate((1, -1)):
        s = np.linspace(0, 2 * np.pi, 400)
        c = np.stack([np.cos(s), np.zeros_like(s), np.sin(s)], axis=1) * semi * 1.004
        c[:, 1] = sign * 0.3 * semi[1] * np.sin(2 * s)
        ax.plot(*c.T, color=VERMILLION, lw=4, label="separatrix" if i == 0 else None)
    w = np.stack([series["omega1"], series["omega2"], series["omega3"]], axis=1)[:400]
    ax.plot(*w.T, color=BLACK, lw=5, label="this body's polhode")
    axes_triad(ax, 1.3 * semi.max(), ["ω₁", "ω₂", "ω₃"])
    ax.legend(loc="upper right")
    save(fig, path)


def poinsot_omega(d, series, path):
    t = series["t_s"]
    w = [series["omega1"], series["omega2"], series["omega3"]]
    fig, (left, right) = plt.subplots(1, 2, **SIZE)
    fig.suptitle("poinsot: I = (3.142, 6.283, 8.168) kg m², ω₀ = (1, 1, 1) rad/s", fontsize=24)
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


def poinsot_integrators(d, series, path):
    t = series["t_s"][1:]
    rng = np.random.default_rng(1)
    names = ["splitting, h = 0.00515 s", "splitting4, h = 0.00515 s", "rk4, h = 0.00515 s",
             "dopri5, tol 1e-10", "rkf78, tol 1e-10", "bulirsch-stoer, tol 1e-10"]
    levels = [1e-5, 1e-11, 1e-11, 1e-10, 1e-14, 1e-9]
    dashes = ["-", "--", "-", "-.", "-", ":"]
    fig, (err, energy) = plt.subplots(1, 2, **SIZE)
    fig.suptitle("poinsot: I = (3.142, 6.283, 8.168) kg m², ω₀ = (1, 1, 1) rad/s: "
                 "integrators against the exact solution", fontsize=24)
    for k, (name, level) in enumerate(zip(names, levels)):
        grow = level * (0.1 + t / t[-1]) * (1 + 0.5 * np.sin(0.6 * t))
        e1 = np.maximum(grow * np.exp(0.3 * rng.standard_normal(t.size)), 1e-17)
        e2 = np.maximum(0.1 * grow * np.abs(np.sin(1.2 * t)), 1e-17)
        err.semilogy(t, e1, dashes[k], color=PALETTE[k], label=name)
        energy.semilogy(t, e2, dashes[k], color=PALETTE[k])
    err.set_title("error in ω")
    err.set_xlabel("t (s)")
    err.set_ylabel("|ω - ω_exact| / |ω₀|")
    err.legend(loc="lower right")
    energy.set_title("energy error")
    energy.set_xlabel("t (s)")
    energy.set_ylabel("|T - T₀| / T₀")
    save(fig, path)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--labs", required=True, help="directory with the lab executables")
    ap.add_argument("--out", required=True)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--keep", help="directory to leave the PNGs in (default: a temporary one)")
    args = ap.parse_args()

    work = tempfile.mkdtemp(prefix="rigid_mpl_")
    out_dir = args.keep or work
    os.makedirs(out_dir, exist_ok=True)
    lamina = run_lab(args.labs, "lamina_tensor")["results"]
    tire = run_lab(args.labs, "tire_balancing", "--csv", os.path.join(work, "tire.csv"))
    poinsot = run_lab(args.labs, "poinsot", "--csv", os.path.join(work, "poinsot.csv"))
    series = read_csv(os.path.join(work, "poinsot.csv"))

    figures = [
        ("lamina_tensor_scene.png", lambda p: lamina_scene(lamina, p)),
        ("lamina_tensor_moment.png", lambda p: lamina_moment(lamina, p)),
        ("tire_balancing_scene.png", lambda p: tire_scene(tire, p)),
        ("tire_balancing_mass.png", lambda p: tire_mass(tire, p)),
        ("poinsot_ellipsoids.png", lambda p: poinsot_ellipsoids(poinsot, series, p)),
        ("poinsot_polhodes.png", lambda p: poinsot_polhodes(poinsot, series, p)),
        ("poinsot_omega.png", lambda p: poinsot_omega(poinsot, series, p)),
        ("poinsot_integrators.png", lambda p: poinsot_integrators(poinsot, series, p)),
    ]
    entries = [{"group": "figures", "case": "import", "tool": "matplotlib",
                "seconds": IMPORT_SECONDS, "kind": "import"}]
    best = {name: math.inf for name, _ in figures}
    # rounds over the whole set, so a burst of load on the machine hits one round, not one figure
    for _ in range(args.repeats):
        for name, draw in figures:
            t0 = time.perf_counter()
            draw(os.path.join(out_dir, name))
            best[name] = min(best[name], time.perf_counter() - t0)
    for name, _ in figures:
        entries.append({"group": "figures", "case": name, "tool": "matplotlib",
                        "seconds": best[name], "kind": "figure"})
        print(f"figures_matplotlib: {name}: {best[name] * 1e3:.1f} ms", file=sys.stderr)
    print(f"figures_matplotlib: import {IMPORT_SECONDS * 1e3:.1f} ms", file=sys.stderr)
    with open(args.out + ".tmp", "w") as f:
        json.dump(entries, f, indent=1)
    os.replace(args.out + ".tmp", args.out)


if __name__ == "__main__":
    main()
