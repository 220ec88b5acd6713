#!/usr/bin/env python3
"""The JKR end of the pull-off force at small contacts: the sphere on the
half-space at one large gammaL (default 2000, contact radii of a few
hundredths of R at the minimum) over Tabor mu (default 2, 3, 5), against
the Lennard-Jones sphere (cgcm-analytic ljsphere: Derjaguin, small strain).
At mu = 8 (cells of 0.4 r0) the jump-in needs more than the default 400
relaxation iterations (|f| 7.6e-5 after them): the runs here allow
Loading/Relaxation Iterations = 5000 (mu = 8, Method 3: 42 min a run; pass
--mu 2 3 5 8).

Each mu runs Method 3 with both surface densities (Interaction/Surface
Density: "current area", the default, and "reference area"), each at finite
and at small strain, on the band mesh (meshes/sphere-on-half-space-band.geo)
with cells of at most a quarter cohesive length E* r_S0^2 / w and r0, along
the path tools/pulloff_map.py plans (approach through the jump-to-contact,
retraction past the minimum). Method 1 (Interaction/Method = volume pair,
finite strain, Interaction/Cutoff = 20 r0: at the deck's 10 r0 the point pairs
it leaves out carry 3.0 % of w, and a pull-off force at the JKR end scales
with w) is the arbiter: its jump-in on these meshes would take hours,
so a Method 3 run (reference area) with a checkpoint stops three states before its
minimum and Method 1 goes on from there (cgcm --restart) to three states
after it; its minimum is taken over its own states only.

Writes table.csv and jkr_end.png into --output; finished runs are reused.

    jkr_end_study.py --build build --output output/validation/jkr-end
                     [--gammaL 2000] [--mu 2 3 5] [--cell-size 0.25] [--jobs 2]
                     [--no-method1] [--method1-cutoff 20] [--rerun] [--plot-only]
"""
import argparse
import concurrent.futures
import csv
import math
import os
import shutil

import matplotlib
import matplotlib.ticker

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pulloff_map as pm  # noqa: E402
from analytic_csv import lj_sphere_pulloff  # noqa: E402

DENSITIES = {"current": "current area", "reference": "reference area"}
RELAXATION = 5000  # iterations a jump may take (the deck's 400 do not pass mu = 8's jump-in)
KINEMATICS = ("finite strain", "small strain")


def stable_rows(csv_path, after_step=None):
    with open(csv_path, newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["stable"] == "1"]
    return [r for r in rows if after_step is None or int(r["step"]) > after_step]


def retraction(rows):
    """The states from the deepest approach on: the pull-off is the minimum of the separation (at
    small strain the landing of the jump-in can lie lower)."""
    if not rows:
        return rows
    top = max(range(len(rows)), key=lambda i: float(rows[i]["u"]))
    return rows[top:]


def minimum(rows):
    """P_min (parabola vertex as tools/pulloff_map.py), its u, whether it is inside the rows, and the
    contact radius at the lowest state."""
    if not rows:
        return float("nan"), float("nan"), False, float("nan")
    u = [float(r["u"]) for r in rows]
    p = [float(r["P"]) for r in rows]
    k = min(range(len(p)), key=p.__getitem__)
    pmin, umin, inside = pm.parabola_minimum(u, p)
    return pmin, umin, inside, float(rows[k]["contact_radius"])


def case_name(case):
    return f"gL{case['gammaL']:g}-mu{case['mu']:.3g}"


def method3(case, density, kinematics, out, rerun):
    name = f"{case_name(case)}-{density}-{kinematics.split()[0]}"
    folder = os.path.join(out, name)
    args = [os.path.join(pm.BUILD, "bin", "cgcm"), os.path.join(pm.ROOT, "inputs", "sphere-on-half-space.xml"),
            f"Output/Directory={folder}", f"Material/Kinematics={kinematics}", *case["overrides"],
            f"Interaction/Surface Density={DENSITIES[density]}", f"Loading/Relaxation Iterations={RELAXATION}"]
    code, seconds = pm.run_logged(args, folder, os.path.join(out, name + ".log"), rerun)
    curve = os.path.join(folder, "load_curve.csv")
    pmin, umin, inside, a = minimum(retraction(stable_rows(curve))) if os.path.exists(curve) else (math.nan,) * 2 + (False, math.nan)
    return name, {"code": code, "seconds": seconds, "P_min": pmin, "u_min": umin, "inside": inside, "a": a,
                  "curve": curve}


def method1(case, reference_run, out, rerun, cutoff):
    """Method 3 (reference area, finite strain) with a checkpoint to three states before its minimum,
    then Method 1 (Interaction/Cutoff = cutoff r0) from there to three states after it."""
    name = f"{case_name(case)}-volume-pair-rc{cutoff:g}"
    rows = retraction(stable_rows(reference_run["curve"])) if os.path.exists(reference_run["curve"]) else []
    if not rows or not reference_run["inside"]:
        return name, {"code": -1, "seconds": 0.0, "P_min": math.nan, "u_min": math.nan, "inside": False,
                      "a": math.nan, "restart_step": -1}
    k = min(range(len(rows)), key=lambda i: float(rows[i]["P"]))
    stop, end = rows[max(k - 3, 1)], rows[min(k + 3, len(rows) - 1)]
    start, u_in = case["path"].strip("{}").split(",")[:2]
    folder = os.path.join(out, name)
    base = [os.path.join(pm.BUILD, "bin", "cgcm"), os.path.join(pm.ROOT, "inputs", "sphere-on-half-space.xml"),
            f"Output/Directory={folder}", "Material/Kinematics=finite strain",
            *[o for o in case["overrides"] if not o.startswith(("Loading/Approach Path", "Output/Checkpoint"))],
            "Interaction/Surface Density=reference area", "Output/Checkpoint=true",
            f"Loading/Approach Path={{{start},{u_in},{stop['u']}}}"]
    code, s1 = pm.run_logged(base, folder, os.path.join(out, name + "-checkpoint.log"), rerun)
    restart_step = int(stop["step"])
    if code != 0:
        return name, {"code": code, "seconds": s1, "P_min": math.nan, "u_min": math.nan, "inside": False,
                      "a": math.nan, "restart_step": restart_step}
    stopped = os.path.join(out, name + "-method3.csv")  # the curve up to the restart, kept apart from Method 1's rows
    if not os.path.exists(stopped) or os.path.getmtime(stopped) < os.path.getmtime(os.path.join(out, name + "-checkpoint.log")):
        shutil.copyfile(os.path.join(folder, "load_curve.csv"), stopped)
    restart_step = int(stable_rows(stopped)[-1]["step"])
    args = [os.path.join(pm.BUILD, "bin", "cgcm"), "--restart", folder, "Interaction/Method=volume pair",
            f"Interaction/Cutoff={cutoff:g}", f"Loading/Approach Path={{{start},{u_in},{end['u']}}}"]
    code, s2 = pm.run_logged(args, folder, os.path.join(out, name + ".log"), rerun, restart=True)
    pmin, umin, inside, a = minimum(stable_rows(os.path.join(folder, "load_curve.csv"), after_step=restart_step))
    return name, {"code": code, "seconds": s2, "P_min": pmin, "u_min": umin, "inside": inside, "a": a,
                  "restart_step": restart_step}


COLUMNS = ["gammaL", "gammaW", "mu", "cell_over_ell", "lj_sphere"] + [
    f"{d}_{k.split()[0]}_{q}" for d in DENSITIES for k in KINEMATICS for q in ("P_over_piwR", "percent", "a_over_R")
] + ["volume_pair_P_over_piwR", "volume_pair_percent", "volume_pair_a_over_R", "volume_pair_seconds",
     "volume_pair_cutoff", "status"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", default="build")
    ap.add_argument("--output", default="output/validation/jkr-end")
    ap.add_argument("--gammaL", type=float, default=2000.0)
    ap.add_argument("--mu", type=float, nargs="+", default=[2.0, 3.0, 5.0])
    ap.add_argument("--cell-size", type=float, default=0.25,
                    help="the finest cells in cohesive lengths (and at most r0; default 0.25)")
    ap.add_argument("--jobs", type=int, default=1, help="cgcm runs at a time")
    ap.add_argument("--no-method1", action="store_true", help="Method 3 only")
    ap.add_argument("--method1-cutoff", type=float, default=20.0,
                    help="Method 1's Interaction/Cutoff in r0 (default 20: the pairs it leaves out carry 0.8 %% "
                         "of w, against 3.0 %% at the deck's 10)")
    ap.add_argument("--rerun", action="store_true", help="run again what the output folder already has")
    ap.add_argument("--plot-only", action="store_true", help="plot an existing table.csv")
    args = ap.parse_args()
    if not args.cell_size > 0.0:
        ap.error(f"--cell-size must be > 0 (cohesive lengths), not {args.cell_size}")
    if not args.method1_cutoff >= 1.0:
        ap.error(f"--method1-cutoff must be >= 1 (r0), not {args.method1_cutoff}")
    if args.jobs < 1:
        ap.error(f"--jobs must be at least 1, not {args.jobs}")
    if not args.gammaL >= 1.0 or any(not m > 0.0 for m in args.mu):
        ap.error("--gammaL must be >= 1 and every --mu > 0")
    pm.BUILD = args.build
    os.makedirs(args.output, exist_ok=True)
    table = os.path.join(args.output, "table.csv")
    if not args.plot_only:
        cases = [pm.plan(args.gammaL, mu, 0, "band", args.cell_size) for mu in args.mu]
        for c in cases:
            print(f"{case_name(c)}: gammaW {c['gammaW']:.4g}, {c['mesh']} (cells {c['cell_over_ell']:.2f} of the "
                  f"cohesive length), path {c['path']}", flush=True)
        jobs = [(c, d, k) for c in cases for d in DENSITIES for k in KINEMATICS]
        results = {}
        with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
            for name, r in pool.map(lambda j: method3(*j, args.output, args.rerun), jobs):
                results[name] = r
                print(f"{name}: exit {r['code']}, {r['seconds']:.0f} s, P_min {r['P_min']:.6g}", flush=True)
            if not args.no_method1:
                ref = {case_name(c): results[f"{case_name(c)}-reference-finite"] for c in cases}
                for name, r in pool.map(
                        lambda c: method1(c, ref[case_name(c)], args.output, args.rerun, args.method1_cutoff), cases):
                    results[name] = r
                    print(f"{name}: exit {r['code']}, {r['seconds']:.0f} s, P_min {r['P_min']:.6g} "
                          f"(from step {r['restart_step']})", flush=True)
        with open(table, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(COLUMNS)
            for c in cases:
                scale = math.pi * c["w"]
                lj = lj_sphere_pulloff(pm.exe(), c["mu"])
                row = [f"{c['gammaL']:g}", f"{c['gammaW']:.6g}", f"{c['mu']:.4g}", f"{c['cell_over_ell']:.3f}",
                       f"{lj:.5f}"]
                bad = []
                runs = [f"{case_name(c)}-{d}-{k.split()[0]}" for d in DENSITIES for k in KINEMATICS]
                if not args.no_method1:
                    runs.append(f"{case_name(c)}-volume-pair-rc{args.method1_cutoff:g}")
                for name in runs:
                    r = results[name]
                    p = r["P_min"] / scale
                    row += [f"{p:.5f}", f"{100 * (p / lj - 1):.2f}", f"{r['a']:.4g}"]
                    if r["code"] != 0 or not r["inside"]:
                        bad.append(f"{name}: exit {r['code']}" + ("" if r["inside"] else " (minimum not inside)"))
                if args.no_method1:
                    row += ["", "", ""]
                row += [f"{results.get(f'{case_name(c)}-volume-pair-rc{args.method1_cutoff:g}', {}).get('seconds', 0.0):.0f}",
                        "" if args.no_method1 else f"{args.method1_cutoff:g}",
                        ";".join(bad) or "ok"]
                w.writerow(row)
        print(f"wrote {table}")
    plot(table, os.path.join(args.output, "jkr_end.png"))


def plot(table, png):
    with open(table, newline="") as f:
        rows = list(csv.DictReader(f))
    mu = [float(r["mu"]) for r in rows]
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    ax.axhspan(-1.5, 1.5, color="0.9", lw=0)
    ax.axhline(0.0, color="k", lw=1.2, label="Lennard-Jones sphere (Derjaguin, small strain)")
    styles = [("reference_finite", "o-", "C0", "Method 3, β0 dA, finite strain"),
              ("reference_small", "o:", "C0", "Method 3, β0 dA, small strain"),
              ("current_finite", "s-", "C3", "Method 3, β0 da (default), finite strain"),
              ("current_small", "s:", "C3", "Method 3, β0 da, small strain"),
              ("volume_pair", "D-", "C2", "Method 1 (volume pairs), finite strain"
               + (f", cutoff {rows[0]['volume_pair_cutoff']} r0" if rows[0].get("volume_pair_cutoff") else ""))]
    for key, style, color, label in styles:
        y = [float(r[f"{key}_percent"]) if r[f"{key}_percent"] else math.nan for r in rows]
        mfc = "none" if ":" in style else color
        ax.plot(mu, y, style, color=color, mfc=mfc, ms=6, lw=0.9, label=label)
    ax.set_xscale("log")
    ax.set_xticks(mu)
    ax.set_xticklabels([f"{m:g}" for m in mu])
    ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    ax.set_xlabel(f"Tabor parameter μ (γL = {rows[0]['gammaL']})")
    ax.set_ylabel("|P_min| against the Lennard-Jones sphere (%)")
    ax.legend(fontsize=7.5, loc="upper left")
    ax.grid(True, which="both", lw=0.3, alpha=0.5)
    fig.tight_layout()
    fig.savefig(png, dpi=130)
    print(f"wrote {png}")


if __name__ == "__main__":
    main()
