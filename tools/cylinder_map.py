#!/usr/bin/env python3
"""Pull-off force of the cylinder on the half-space (plane strain, per unit
length) over the Maugis-Dugdale parameter of the cylinder,
lambda = 2 sigma_max (R/(pi w E*^2))^(1/3): for each lambda the CGCM approaches
into contact and retracts past the minimum force, once at finite strain and
once with Material/Kinematics = small strain on the same mesh and path. The
minimum force over the retraction is compared with the Maugis-Dugdale cylinder
(Baney & Hui 1997; cgcm-analytic cylinder) in its units F = (pi^2 w^2 E* R)^(1/3),
and at the JKR end with Barquins' -3 (pi E* w^2 R/16)^(1/3) = -3/(16 pi)^(1/3) F.

The built-in sphere-on-half-space geometry in plane strain is the cylinder
(radius R = 1) on a half-space, both elastic with Y = 1, nu = 0.2, and on a
rigid half-space (Bodies/half-space/Rigid; E* = Y/(1 - nu^2)).
gammaW is set for lambda at the given gammaL (lambda ~ gammaW^(-2/3)). The mesh
follows tools/pulloff_map.py: the finest cells at most --cell-size cohesive
lengths E* r_S0^2 / w and r0, over 1.3 zero-load half-widths (of the M-D
cylinder) and at least to where the gap is 4 r0; the graded built-in mesh up
to --max-level, beyond it meshes/sphere-on-half-space-band.geo. The approach
ends where the contact half-width is about 1.15 zero-load half-widths (u =
1.46 a^2/R + 2 r_S0, calibrated on the default deck in plane strain, where
u = 1.46 a^2 at a = 0.2; the pull-off half-width is below the zero-load one);
the path starts and ends at -max(3 r_S0, 0.3 u_in), twice and four times that
if the bodies snap together at the start or the minimum force lies at the end
of the path. P_min is the
vertex of the parabola through the lowest stable retraction state and its
neighbours.

Writes table.csv and cylinder_map.png into --output.

    cylinder_map.py --build build --output output/cylinder-map [--lambda 0.1 0.2 0.5 1 2 5]
                    [--gammaL 200] [--half-space elastic rigid] [--jobs 2] [--max-level 2] [--cell-size 0.4]
                    [--rerun] [--plan] [--plot-only]
"""
import concurrent.futures
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pulloff_map  # noqa: E402
from analytic_csv import rows  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
NU = 0.2
BUILD = "build"
LAMBDAS = [0.1, 0.2, 0.5, 1.0, 2.0, 5.0]
JKR = -3.0 / (16.0 * math.pi) ** (1.0 / 3.0)  # Barquins' pull-off in units of F


def exe():
    return os.path.join(BUILD, "bin", "cgcm-analytic")


def scales(gl, gw, rigid_flat):
    """w, sigma_max, E*, lambda of the cylinder and F at (gammaL, gammaW), R = Y = 1."""
    m = {k: float(v) for k, v in rows(exe(), "map", "--gammaL", f"{gl:.12g}", "--gammaW", f"{gw:.12g}",
                                      "--nu", f"{NU}")[0].items()}
    estar = 1.0 / (1.0 - NU * NU) if rigid_flat else m["f_E"]
    w, smax = m["w"], m["sigma_max"]
    lam = 2.0 * smax * (1.0 / (math.pi * w * estar ** 2)) ** (1.0 / 3.0)
    force = (math.pi ** 2 * w * w * estar) ** (1.0 / 3.0)
    return {"w": w, "sigma_max": smax, "Estar": estar, "lambda": lam, "F": force,
            "length": (math.pi * w / estar) ** (1.0 / 3.0)}


def plan(lam, gl, rigid_flat, max_level, cell_size, extension=0):
    """Deck overrides and scales of one case (see the module's text)."""
    s1 = scales(gl, 100.0, rigid_flat)
    gw = 100.0 * (s1["lambda"] / lam) ** 1.5
    s = scales(gl, gw, rigid_flat)
    curve = rows(exe(), "cylinder", "--model", "md", "--lambda", f"{lam:.10g}", "--a-max", "6", "--points", "1200")
    zero = next(r for r in curve if float(r["P"]) >= 0.0)  # the zero-load half-width
    a0 = float(zero["a"]) * s["length"]
    r0 = 1.0 / gl
    rs0 = r0 / 15 ** (1 / 6)
    ell = s["Estar"] * rs0 ** 2 / s["w"]
    cell_max = min(cell_size * ell, r0)
    wanted = max(1.3 * a0, math.sqrt(8.0 * r0))
    zone = min(0.85, wanted)
    warnings = [] if wanted <= zone else [f"the fine zone is cut to 0.85 R from the {wanted:.3g} R the contact needs"]
    level = max(0, math.ceil(math.log2(zone / 20 / cell_max)))
    if level > max_level:
        geometry = ["Geometry/Type=gmsh", f"Geometry/File={os.path.join(ROOT, 'meshes', 'sphere-on-half-space-band.geo')}",
                    f"Geometry/Mesh Numbers/zone={zone:.4g}", f"Geometry/Mesh Numbers/lc={cell_max:.4g}",
                    f"Geometry/Mesh Numbers/gap={rs0:.6g}"]
        label, cell = f"band {cell_max:.3g}", cell_max
    else:
        geometry = [f"Geometry/Mesh Refinement={level}", f"Geometry/Contact Zone Size={zone:.4g}"]
        label, cell = f"level {level}", zone / 20 / 2 ** level
    u_in = 1.46 * (1.15 * a0) ** 2 + 2.0 * rs0
    u_end = -max(3.0 * rs0, 0.3 * u_in) * 2 ** extension
    u_start = u_end  # where the bodies are still apart: strong adhesion snaps them together from further away
    step = (u_in - u_end) / 80
    path = f"{{{u_start:.6g},{u_in:.6g},{u_end:.6g}}}"
    overrides = ["Problem/Formulation=plane strain", f"Interaction/gammaL={gl:.12g}", f"Interaction/gammaW={gw:.12g}",
                 *geometry, f"Loading/Approach Path={path}", f"Loading/Initial Increment={step:.6g}",
                 f"Loading/Max Increment={step:.6g}", f"Loading/Min Increment={step * 1e-5:.6g}",
                 "Output/Print Steps=false", "Output/Exodus=false", "Output/Checkpoint=false"]
    if rigid_flat:
        overrides.append("Bodies/half-space/Rigid=true")
    return {"lambda": lam, "gammaL": gl, "gammaW": gw, "rigid_flat": rigid_flat, "mesh": label, "zone": zone,
            "cell_over_ell": cell / ell, "cells_across": zone / cell, "a0": a0, "path": path, "overrides": overrides,
            "warnings": warnings, "extension": extension, **s}


def lj_over_dugdale_rigid_cylinder():
    """The pull-off of a rigid cylinder under the 9-3 law of the Lennard-Jones half-spaces,
    sigma(h) ~ (z0/h)^9 - (z0/h)^3, over Dugdale's 2 sigma_max sqrt(2 R h0) at the same w and
    sigma_max (Derjaguin over the profile: sqrt(2R) min_g0 of the integral of sigma(g)/sqrt(g - g0)
    over g > g0, with g = g0 + t^2 and t = u/(1 - u) on a midpoint rule). The small-lambda end of
    the CGCM cylinder is this times -2 sqrt(lambda/pi)."""
    import numpy as np
    u = (np.arange(400000) + 0.5) / 400000
    t, dt = u / (1 - u), 1.0 / (1 - u) ** 2 / len(u)

    def integral(s0):  # of (s^-9 - s^-3)/sqrt(s - s0), s = g/z0
        s = s0 + t * t
        return float(np.sum(2.0 * (s ** -9 - s ** -3) * dt))

    lo, hi = 1.0, 1.3  # golden section on the minimum over s0 (at 1.10)
    for _ in range(60):
        m1, m2 = hi - 0.618 * (hi - lo), lo + 0.618 * (hi - lo)
        if integral(m1) < integral(m2):
            hi = m2
        else:
            lo = m1
    s = np.linspace(1.0, 3.0, 200001)
    tension = float(np.max(s ** -3 - s ** -9))  # sigma_max in the same units
    return abs(integral(0.5 * (lo + hi))) * math.sqrt(8.0 / 3.0) / (2.0 * math.sqrt(tension))


def retraction_minimum(csv_path):
    """P_min over the stable states from the turning point of the path on, its u, and whether it
    lies inside them."""
    with open(csv_path, newline="") as f:
        states = list(csv.DictReader(f))
    if not states:
        return float("nan"), float("nan"), False
    turn = max(range(len(states)), key=lambda i: float(states[i]["u"]))
    ret = [r for r in states[turn:] if r["stable"] == "1"]
    return pulloff_map.parabola_minimum([float(r["u"]) for r in ret], [float(r["P"]) for r in ret])


def run_extended(name, out, rerun, args_of):
    """Runs cgcm with args_of(extension) for extension = 0, 1, 2 until the minimum force over the
    retraction lies inside the path (a later extension starts and ends further out: the bodies
    snapped together at the start, or the minimum is the last state). Returns the result of the
    last run: status, seconds and, with a load curve, P_min, u_min and inside."""
    folder = os.path.join(out, name)
    log = os.path.join(out, name + ".log")
    for extension in range(3):
        code, seconds = pulloff_map.run_logged(args_of(extension, folder), folder, log, rerun)
        result = {"status": "completed" if code == 0 else f"exit {code}", "seconds": seconds}
        curve = os.path.join(folder, "load_curve.csv")
        if os.path.exists(curve):
            pmin, umin, inside = retraction_minimum(curve)
            result.update(P_min=pmin, u_min=umin, inside=inside)
        with open(log) as f:
            snapped = "at the start of the load path" in f.read()  # no equilibrium apart: start further out
        if (code != 0 and not snapped) or result.get("inside", False):
            break
    return result


def run_case(case, kinematics, out, rerun, max_level, cell_size):
    """One case at one kinematics (run_extended)."""
    tag = "rigid" if case["rigid_flat"] else "elastic"
    name = f"{tag}-gL{case['gammaL']:g}-lambda{case['lambda']:.3g}-{kinematics.split()[0]}"

    def args_of(extension, folder):
        c = case if extension == 0 else plan(case["lambda"], case["gammaL"], case["rigid_flat"], max_level,
                                             cell_size, extension)
        return [os.path.join(BUILD, "bin", "cgcm"), os.path.join(ROOT, "inputs", "sphere-on-half-space.xml"),
                f"Output/Directory={folder}", f"Material/Kinematics={kinematics}", *c["overrides"]]

    return name, run_extended(name, out, rerun, args_of)


def main():
    global BUILD
    ap = pulloff_map.study_parser(__doc__, "output/cylinder-map", "print the cases and their meshes, run nothing")
    ap.add_argument("--lambda", dest="lambdas", type=float, nargs="+", default=LAMBDAS)
    ap.add_argument("--gammaL", type=float, nargs="+", default=[200.0],
                    help="default 200: at a given lambda the contact is half as wide as at 50, at the same cost; "
                         "larger values make sigma_max/E* smaller at the JKR end")
    ap.add_argument("--half-space", nargs="+", choices=("elastic", "rigid"), default=["elastic", "rigid"],
                    help="elastic (Y = 1, as the cylinder) and/or rigid (Bodies/half-space/Rigid)")
    ap.add_argument("--kinematics", nargs="+", choices=("finite", "small"), default=["finite", "small"],
                    help="finite and/or small strain (the other's columns stay empty)")
    ap.add_argument("--max-level", type=int, default=2, help="the finest graded level (0 .. 6); finer: the band mesh")
    ap.add_argument("--cell-size", type=float, default=0.4, help="the finest cells in cohesive lengths (and <= r0)")
    args = pulloff_map.parse_study_args(ap)
    BUILD = args.build
    if not args.cell_size > 0.0:
        ap.error(f"--cell-size must be > 0 (cohesive lengths), not {args.cell_size}")
    if not 0 <= args.max_level <= 6:
        ap.error(f"--max-level must be 0 .. 6 (Geometry/Mesh Refinement), not {args.max_level}")
    if any(not 1e-3 <= lam <= 1e3 for lam in args.lambdas):
        ap.error("--lambda values must lie in [1e-3, 1e3]")
    os.makedirs(args.output, exist_ok=True)
    table = os.path.join(args.output, "table.csv")
    if not args.plot_only:
        cases = [plan(lam, gl, hs == "rigid", args.max_level, args.cell_size)
                 for hs in args.half_space for gl in args.gammaL for lam in args.lambdas]
        for c in cases:
            print(f"{'rigid' if c['rigid_flat'] else 'elastic'} half-space, gammaL {c['gammaL']:g}, lambda {c['lambda']:g}: "
                  f"sigma_max/E* {c['sigma_max'] / c['Estar']:.3g}, gammaW {c['gammaW']:.4g}, {c['mesh']}, zone {c['zone']:.3g} (cells "
                  f"{c['cell_over_ell']:.2f} of the cohesive length), path {c['path']}", flush=True)
            for w in c["warnings"]:
                print(f"  warning: {w}", flush=True)
        if args.plan:
            return
        jobs = [(c, k + " strain") for c in sorted(cases, key=lambda c: c["cells_across"]) for k in args.kinematics]
        results = {}
        with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
            for name, r in pool.map(lambda j: run_case(j[0], j[1], args.output, args.rerun, args.max_level,
                                                       args.cell_size), jobs):
                results[name] = r
                print(f"{name}: {r['status']}, {r['seconds']:.0f} s, P_min {r.get('P_min', float('nan')):.6g}"
                      f"{'' if r.get('inside', False) else ' (at the end of the path)'}", flush=True)
        with open(table, "w", newline="") as f:
            out = csv.writer(f)
            out.writerow(["lambda", "gammaL", "gammaW", "half_space", "sigma_max_over_Estar", "mesh", "cell_over_ell",
                          "finite_P_over_F",
                          "small_P_over_F", "maugis_dugdale", "finite_vs_md_percent", "small_vs_md_percent",
                          "finite_vs_small_percent", "finite_seconds", "small_seconds", "status"])
            for c in cases:
                tag = "rigid" if c["rigid_flat"] else "elastic"
                key = f"{tag}-gL{c['gammaL']:g}-lambda{c['lambda']:.3g}"
                missing = {"status": "not run", "seconds": float("nan"), "inside": True}
                rf, rs = results.get(key + "-finite", missing), results.get(key + "-small", missing)
                pf = rf.get("P_min", float("nan")) / c["F"]
                ps = rs.get("P_min", float("nan")) / c["F"]
                md = float(rows(exe(), "cylinder", "--model", "md", "--lambda", f"{c['lambda']:.10g}",
                                "--pulloff")[0]["P"])
                status = ";".join(f"{k}: {r['status']}" + ("" if r.get("inside", False) else " (minimum not inside)")
                                  for k, r in (("finite", rf), ("small", rs))
                                  if r["status"] not in ("completed", "not run") or not r.get("inside", False)) or "ok"
                out.writerow([f"{c['lambda']:g}", f"{c['gammaL']:g}", f"{c['gammaW']:.6g}", tag,
                              f"{c['sigma_max'] / c['Estar']:.3g}", c["mesh"],
                              f"{c['cell_over_ell']:.3f}", f"{pf:.5f}", f"{ps:.5f}", f"{md:.5f}",
                              f"{100 * (pf / md - 1):.2f}", f"{100 * (ps / md - 1):.2f}", f"{100 * (pf / ps - 1):.2f}",
                              f"{rf['seconds']:.0f}", f"{rs['seconds']:.0f}", status])
        print(f"wrote {table}")
    plot(table, os.path.join(args.output, "cylinder_map.png"))


def plot(table, png):
    with open(table, newline="") as f:
        rows_ = list(csv.DictReader(f))
    lams = [10 ** (math.log10(0.05) + i * (math.log10(10.0) - math.log10(0.05)) / 40) for i in range(41)]
    md = [-float(rows(exe(), "cylinder", "--model", "md", "--lambda", f"{lam:.8g}", "--pulloff")[0]["P"]) for lam in lams]
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    ax.axhline(-JKR, color="0.6", lw=0.8, ls=":")
    ax.text(0.055, -JKR + 0.01, "JKR cylinder (Barquins)  0.8129", va="bottom", fontsize=8, color="0.4")
    ax.plot(lams, md, "k--", lw=1.0, label="Maugis–Dugdale cylinder (Baney & Hui)")
    ax.plot(lams, [2 * math.sqrt(lam / math.pi) for lam in lams], ":", color="0.5", lw=0.8,
            label="Dugdale rigid-cylinder limit 2√(λ/π)")
    ratio = lj_over_dugdale_rigid_cylinder()
    small = [lam for lam in lams if lam <= 0.5]
    ax.plot(small, [ratio * 2 * math.sqrt(lam / math.pi) for lam in small], "-.", color="0.35", lw=0.8,
            label=f"Lennard-Jones (9-3) rigid-cylinder limit {ratio:.3f} × 2√(λ/π)")
    groups = sorted({(r["half_space"], r["gammaL"]) for r in rows_}, key=lambda g: (g[0], float(g[1])))
    for i, (tag, gl) in enumerate(groups):
        sel = [r for r in rows_ if (r["half_space"], r["gammaL"]) == (tag, gl)]
        x = [float(r["lambda"]) for r in sel]
        ax.plot(x, [-float(r["finite_P_over_F"]) for r in sel], "o-", color=f"C{i}", ms=6, lw=0.8,
                label=f"CGCM, {tag} half-space, γL = {gl}, finite strain")
        if any(r["small_P_over_F"] != "nan" for r in sel):
            ax.plot(x, [-float(r["small_P_over_F"]) for r in sel], "s:", color=f"C{i}", mfc="none", ms=6, lw=0.8,
                    label=f"CGCM, {tag} half-space, γL = {gl}, small strain")
    ax.set_xscale("log")
    ax.set_ylim(0.0, 1.0)
    ax.set_xlabel("Maugis–Dugdale parameter of the cylinder  λ = 2σ₀ (R/(π w E*²))^(1/3)")
    ax.set_ylabel("pull-off force  |P_min| / (π² w² E* R)^(1/3)")
    ax.legend(fontsize=7.5, loc="lower right")
    ax.grid(True, which="both", lw=0.3, alpha=0.5)
    fig.tight_layout()
    fig.savefig(png, dpi=130)
    print(f"wrote {png}")


if __name__ == "__main__":
    main()
