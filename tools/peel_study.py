#!/usr/bin/env python3
"""Steady peel force of a strip on a rigid substrate over the peel angle, plane
strain, finite strain, against the energy balance of a strip held at its far
end on a bond without shear and against Kendall's extensible law.

inputs/peel.xml (meshes/peel-strip.geo: h = 1, E' = Y/(1 - nu^2), nu = 0.3,
the mesh turned so that the pull is vertical and stays at theta to the
substrate) at --epsilon values of w/(E' h) (1e-3: gammaL 20, sigma_max/E'
0.032; 1e-2: gammaL 5, sigma_max/E' 0.081). Each run peels the front by
7 bending lengths l_t = sqrt(E'I/F) + 10 (the start's transient decays as
exp(-advance/l_t)), in steps that move the front by at most 2 cells (a run
that stops, as at the start's peak beyond 120 degrees, is run again with
steps half as large, twice at most: "-retry1", "-retry2"); the strip
reaches 15 beyond; the path adds the stretch of the strip to the steady force.
The steady force is the last state's P; the table gives its drift over the
last bending length or the last tenth of the path, whichever is longer (a row
is "ok" when it is at most 0.5 %, else "not steady", and is not plotted) and
the rotation loss: the share of w that Method 3's traction, which counts
the underside's area projected on the substrate (rbar . n), does not do on an
underside that turns by alpha while it opens (the traction-weighted mean of
1 - cos alpha over the last state's front; doc/validation.md, "Peeling").
w is the work of adhesion the potential keeps inside its cutoff (0.67 % below
the full w, as `cgcm --check` prints it), and eps = w/(E' h) with that w.

With --current-area ANGLES (default 30 90 150) the same runs at those angles and the smaller
epsilon use Interaction/Surface Density = current area (the default of Method
3) instead of the deck's reference area: the table then shows by how much the
current area's traction, applied over the bending-stretched underside at the
front, raises the steady force.

Writes table.csv and peel_study.png into --output.

    peel_study.py --build build --output output/peel-study [--angles 30 45 ...]
                  [--epsilon 1e-3 1e-2] [--current-area 30 90 150] [--jobs 2] [--rerun] [--plan]
                  [--plot-only]
"""
import concurrent.futures
import csv
import math
import os
import re
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_field  # noqa: E402
import pulloff_map  # noqa: E402
from analytic_csv import rows  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
NU = 0.3
E_PLANE = 1.0 / (1.0 - NU * NU)  # Y = 1, h = 1
BENDING = E_PLANE / 12.0  # E'I per unit width
ANGLES = [15.0, 30.0, 45.0, 60.0, 90.0, 120.0, 150.0, 170.0]
EPSILONS = [1e-3, 1e-2]
CELL = 0.2  # along the strip: 0.05, 0.1 and 0.2 give the same force to 7e-5 (theta 90, eps 1e-3)
XF, R_BEND, ARM = 6.0, 5.0, 5.0  # front, bend radius and arm length of meshes/peel-strip.geo
# Below 25 degrees the front starts from a gentler bend, radius 20: from the mesh's R = 5 it had not
# started at 15 degrees when the strip was stretched to 1.6 times the steady force; from R = 20 it
# starts at 1.2 times it, in one jump whose relaxation takes more than the default 400 iterations.
SMALL_ANGLE, R_SMALL = 25.0, 20.0
BUILD = "build"
STEADY = 5e-3  # the last bending length may change the force by at most this for the row to be "ok"


def analytic(*args):
    return rows(os.path.join(BUILD, "bin", "cgcm-analytic"), *args)


def gamma_l_for(eps):
    """gammaL keeping sigma_max/E' small while the cohesive zone spans several cells."""
    return 20.0 if eps <= 2e-3 else 5.0


def laws(theta, eps):
    """(held end, Kendall, inextensible) F/(b w) from cgcm-analytic peel."""
    r = analytic("peel", "--epsilon", f"{eps:.12g}", "--theta", f"{theta:.12g}")[0]
    return float(r["held_end_F_over_bw"]), float(r["F_over_bw"]), float(r["inextensible_F_over_bw"])


def plan(theta, eps, density="reference area"):
    gl = gamma_l_for(eps)
    f_w = float(analytic("map", "--gammaL", f"{gl:g}", "--gammaW", "1", "--nu", f"{NU}")[0]["f_w"])
    gw = f_w / (gl * eps * E_PLANE)  # w = f_w/(gammaL gammaW) with R0 = 1
    held, _, _ = laws(theta, eps)
    force = held * eps * E_PLANE
    bending_length = math.sqrt(BENDING / force)
    advance = 7.0 * bending_length + 10.0
    length = XF + advance + 15.0
    t = math.radians(theta)
    bend = R_SMALL if theta < SMALL_ANGLE else R_BEND
    # the pull point moves along the pull by (1 + e_a) - (1 + e_b) cos t per unit advance (arm strain
    # e_a = F/(E'h), bonded part e_b = e_a cos t), after the strip has been stretched to F: the arm
    # (its length at the start, ARM + R t) by e_a and the bonded part, L - XF long, by e_b along x
    strain = force / E_PLANE
    travel = 1.0 - math.cos(t) + strain * math.sin(t) ** 2
    stretch = strain * (ARM + bend * t + (length - XF) * math.cos(t) ** 2)
    if strain > 0.05:
        stretch *= 1.0 + 3.0 * strain  # Neo-Hookean tension: about 1.45 times the linear strain at 0.2
    if bend != R_BEND:
        stretch *= 1.3  # the front starts at 1.2 times the steady force there
    u_end = advance * travel + stretch
    step = 2.0 * CELL * travel  # the front moves by at most 2 cells a step
    if not stretch < 0.5 * u_end:
        step = min(step, 0.05 * u_end)  # small angles: most of the path stretches the strip
    gap = (1.0 / gl) / 15 ** (1 / 6)
    overrides = [f"Interaction/gammaL={gl:g}", f"Interaction/gammaW={gw:.12g}",
                 f"Interaction/Surface Density={density}",
                 f"Geometry/Mesh Numbers/theta={theta:g}", f"Geometry/Mesh Numbers/L={length:.4g}",
                 f"Geometry/Mesh Numbers/lc={CELL:g}", f"Geometry/Mesh Numbers/gap={gap:.9g}",
                 f"Loading/Approach Path={{0,{u_end:.6g}}}", f"Loading/Initial Increment={step / 8:.6g}",
                 f"Loading/Max Increment={step:.6g}", f"Loading/Min Increment={step * 1e-6:.6g}",
                 "Output/Print Steps=false", "Output/Checkpoint=false"]
    if bend != R_BEND:
        overrides += [f"Geometry/Mesh Numbers/R={bend:g}", "Loading/Relaxation Iterations=4000"]
    tag = "ref" if density == "reference area" else "cur"
    return {"theta": theta, "eps": eps, "density": density, "gammaL": gl, "gammaW": gw,
            "bending_length": bending_length, "advance": advance, "travel": travel, "u_end": u_end,
            "overrides": overrides, "name": f"theta{theta:g}-eps{eps:g}-{tag}"}


def steady_force(curve, case):
    """Last P and its drift (relative) over the last bending length of advance or the last tenth
    of the path, whichever is longer."""
    with open(curve, newline="") as f:
        data = [(float(r["u"]), float(r["P"])) for r in csv.DictReader(f)]
    u_last, p_last = data[-1]
    du = max(case["bending_length"] * case["travel"], 0.1 * u_last)
    earlier = min(data, key=lambda r: abs(r[0] - (u_last - du)))
    return p_last, (earlier[1] - p_last) / p_last


def rotation_loss(results, case, gap, cutoff):
    """The share of the work of adhesion that Method 3's traction T rbar (rbar . n) dA does not do
    on a surface that turns as it opens: the traction-weighted mean of 1 - cos(alpha) over the
    opening gap <- r_S0 .. cutoff of the last state's front, alpha the underside's slope to the
    substrate (in steady state every point of the underside passes through these states).
    T ~ s^3 - s^9, s = r_S0/g (the 9-3 law's shape). NaN without results.e."""
    try:
        import netCDF4  # python3-netcdf4
        import numpy as np
    except ImportError:
        return float("nan")
    if not os.path.exists(results):
        return float("nan")
    with netCDF4.Dataset(results) as ds:
        x, y = np.array(ds["coordx"][:]), np.array(ds["coordy"][:])
        xd, yd = plot_field.deformed_xy(ds, ds.dimensions["time_step"].size)  # the last state
    phi = -math.radians(case["theta"] - 90.0)  # back to the drawing's frame: substrate top on y = 0
    c, s = math.cos(phi), math.sin(phi)
    def turn(a, b):
        return c * a - s * b, s * a + c * b
    X0, Y0 = turn(x, y)
    bonded = np.where((np.abs(Y0 - gap) < 1e-6) & (X0 > XF - 1e-9))[0]
    bonded = bonded[np.argsort(X0[bonded])]
    xc, yc = turn(xd[bonded], yd[bonded])
    alpha = np.arctan2(np.gradient(yc), np.gradient(xc))
    zone = (yc > gap * 1.0001) & (yc < cutoff)
    if zone.sum() < 4:
        return float("nan")
    g, a = yc[zone], alpha[zone]
    order = np.argsort(g)
    g, a = g[order], a[order]
    t = (gap / g) ** 3 - (gap / g) ** 9
    return float(np.trapz(t * (1.0 - np.cos(a)), g) / np.trapz(t, g))


def cutoff_fraction(case):
    """The share of w the potential's cutoff removes, as cgcm --check prints it for the case."""
    p = subprocess.run([os.path.join(BUILD, "bin", "cgcm"), "--check", os.path.join(ROOT, "inputs", "peel.xml"),
                        *(o for o in case["overrides"] if not o.startswith("Output/"))],  # printing on
                       capture_output=True, text=True)
    m = re.search(r"work removed by the cutoff = ([0-9.eE+-]+) % of w", p.stdout + p.stderr)
    if m is None:
        sys.exit(f"cgcm --check on {case['name']} did not print the cutoff's share of w:\n{p.stdout}{p.stderr}")
    return float(m.group(1)) / 100.0


def run_case(case, out, rerun):
    """Runs the case; one that stops is run again with half the largest step, twice at most."""
    for attempt in range(3):
        name = case["name"] + (f"-retry{attempt}" if attempt else "")
        folder = os.path.join(out, name)
        log = os.path.join(out, name + ".log")
        scale = 0.5 ** attempt
        overrides = [o if not o.startswith(("Loading/Max Increment=", "Loading/Initial Increment="))
                     else f"{o.split('=')[0]}={float(o.split('=')[1]) * scale:.6g}" for o in case["overrides"]]
        args = [os.path.join(BUILD, "bin", "cgcm"), os.path.join(ROOT, "inputs", "peel.xml"),
                f"Output/Directory={folder}", *overrides]
        code, seconds = pulloff_map.run_logged(args, folder, log, rerun)
        if code == 0:
            break
    result = {"status": "completed" if code == 0 else f"exit {code}", "seconds": seconds, "attempts": attempt + 1,
              "cutoff": cutoff_fraction(case)}
    curve = os.path.join(folder, "load_curve.csv")
    if code == 0 and os.path.exists(curve):
        result["P"], result["drift"] = steady_force(curve, case)
        r0 = 1.0 / case["gammaL"]
        result["rotation_loss"] = rotation_loss(os.path.join(folder, "results.e"), case, r0 / 15 ** (1 / 6),
                                                10.0 * r0)
    return case, result


def main():
    global BUILD
    ap = pulloff_map.study_parser(__doc__, "output/peel-study")
    ap.add_argument("--angles", type=float, nargs="+", default=ANGLES, help="peel angles, degrees (1 .. 170)")
    ap.add_argument("--epsilon", type=float, nargs="+", default=EPSILONS, help="w/(E' h) of the cases")
    ap.add_argument("--current-area", type=float, nargs="*", default=[30.0, 90.0, 150.0],
                    help="angles also run with Surface Density = current area at the smallest epsilon")
    args = pulloff_map.parse_study_args(ap)
    BUILD = args.build
    for t in args.angles + args.current_area:
        if not 1.0 <= t <= 170.0:
            ap.error(f"angle {t:g}: the mesh is drawn for 1 .. 170 degrees (at 180 the arm would lie on the strip, "
                     "and a body does not interact with itself)")
    if any(not 0.0 < e <= 0.1 for e in args.epsilon):
        ap.error("--epsilon: w/(E' h) in (0, 0.1]")
    os.makedirs(args.output, exist_ok=True)
    table = os.path.join(args.output, "table.csv")
    if not args.plot_only:
        cases = [plan(t, e) for e in args.epsilon for t in args.angles]
        cases += [plan(t, min(args.epsilon), "current area") for t in args.current_area]
        cases.sort(key=lambda c: -c["u_end"] / c["travel"])  # longest first: the pool finishes together
        for c in cases:
            print(f"{c['name']}: gammaL {c['gammaL']:g}, gammaW {c['gammaW']:.6g}, bending length "
                  f"{c['bending_length']:.3g}, advance {c['advance']:.3g}, u to {c['u_end']:.4g}", flush=True)
        if args.plan:
            return
        rows_out = []
        with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
            for c, r in pool.map(lambda c: run_case(c, args.output, args.rerun), cases):
                print(f"{c['name']}: {r['status']}, {r['seconds']:.0f} s", flush=True)
                rows_out.append((c, r))
        rows_out.sort(key=lambda cr: (cr[0]["density"], cr[0]["eps"], cr[0]["theta"]))
        with open(table, "w", newline="") as f:
            out = csv.writer(f)
            out.writerow(["theta_deg", "epsilon", "surface_density", "F_over_bw", "drift_last_bending_length",
                          "held_end_law", "kendall", "inextensible", "F_over_held_end",
                          "F_over_kendall", "rotation_loss", "F_over_held_end_less_rotation_loss", "gammaL",
                          "bending_length", "advance", "seconds", "status"])
            for c, r in rows_out:
                nan = float("nan")
                w = c["eps"] * E_PLANE * (1.0 - r["cutoff"])  # the work the potential keeps
                eps = w / E_PLANE
                held, kendall, inext = laws(c["theta"], eps)
                f_w = r.get("P", nan) / w
                out.writerow([f"{c['theta']:g}", f"{c['eps']:g}", c["density"], f"{f_w:.5f}",
                              f"{r.get('drift', nan):.2e}", f"{held:.5f}",
                              f"{kendall:.5f}", f"{inext:.5f}", f"{f_w / held:.4f}", f"{f_w / kendall:.4f}",
                              f"{r.get('rotation_loss', nan):.4f}",
                              f"{f_w / (held * (1.0 - r.get('rotation_loss', nan))):.4f}",
                              f"{c['gammaL']:g}", f"{c['bending_length']:.3g}", f"{c['advance']:.3g}",
                              f"{r['seconds']:.0f}",
                              ("ok" if r["status"] == "completed" and abs(r.get("drift", 1.0)) <= STEADY
                               else r["status"] if r["status"] != "completed"
                               else f"not steady (drift {r.get('drift', nan):.1e})") +
                              (f" (steps / {2 ** (r['attempts'] - 1)})" if r["attempts"] > 1 else "")])
        print(f"wrote {table}")
    plot(table, os.path.join(args.output, "peel_study.png"))


def plot(table, png):
    with open(table, newline="") as f:
        data = list(csv.DictReader(f))
    fig, (ax, bx) = plt.subplots(2, 1, figsize=(6.4, 7.0), sharex=True, gridspec_kw={"height_ratios": [3, 2]})
    thetas = [10.0 + i for i in range(171)]
    for k, eps in enumerate(sorted({float(r["epsilon"]) for r in data})):
        color = f"C{k}"
        curve = analytic_curve(thetas, eps)
        ax.plot(thetas, [float(r["held_end_F_over_bw"]) for r in curve], "-", color=color, lw=1.0,
                label=f"held far end, ε = {eps:g}")
        ax.plot(thetas, [float(r["F_over_bw"]) for r in curve], "--", color=color, lw=0.8,
                label=f"Kendall, ε = {eps:g}")
        for density, marker in (("reference area", "o"), ("current area", "s")):
            pts = [r for r in data if float(r["epsilon"]) == eps and r["surface_density"] == density
                   and r["status"].startswith("ok")]
            if not pts:
                continue
            x = [float(r["theta_deg"]) for r in pts]
            tag = f"CGCM, ε = {eps:g}" + (", current area" if density == "current area" else "")
            face = "none" if density == "current area" else color
            ax.plot(x, [float(r["F_over_bw"]) for r in pts], marker, color=color, ms=5, mfc=face, label=tag)
            bx.plot(x, [float(r["F_over_held_end"]) for r in pts], marker, color=color, ms=5, mfc=face, label=tag)
            bx.plot(x, [float(r["F_over_held_end_less_rotation_loss"]) for r in pts], "x", color=color, ms=6,
                    label=tag + ", rotation loss taken out" if density == "reference area" else None)
    ax.plot(thetas, [1.0 / (1.0 - math.cos(math.radians(t))) for t in thetas], ":", color="0.4", lw=0.8,
            label="inextensible 1/(1 − cos θ)")
    ax.set_yscale("log")
    ax.set_ylabel("steady peel force F / (b w)")
    ax.legend(fontsize=7, loc="upper right")
    ax.grid(True, which="both", lw=0.3, alpha=0.5)
    bx.axhspan(0.97, 1.03, color="0.9", zorder=0)
    bx.axhline(1.0, color="k", lw=0.8)
    bx.set_xlabel("peel angle θ (degrees)")
    bx.set_ylabel("F / held-end law")
    bx.set_ylim(0.85, 1.09)
    bx.legend(fontsize=6, loc="lower left", ncol=2)
    bx.grid(True, lw=0.3, alpha=0.5)
    fig.tight_layout()
    fig.savefig(png, dpi=130)
    print(f"wrote {png}")


def analytic_curve(thetas, eps):
    return analytic("peel", "--epsilon", f"{eps:.12g}", "--theta-min", f"{thetas[0]:g}", "--theta-max",
                    f"{thetas[-1]:g}", "--points", str(len(thetas)))


if __name__ == "__main__":
    main()
