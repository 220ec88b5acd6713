#!/usr/bin/env python3
"""Where the approach of the sphere on the half-space becomes stable: for each
gammaL, the critical gammaW below which the approach jumps into contact.

Method "fold" (the default): one cgcm run per gammaL. It follows the approach
(inputs/sphere-on-half-space.xml, Loading/Control = arc-length, from 6 r0
apart to 2 r0 past the equilibrium gap) at a gammaW where it jumps, locates
the jump-in fold, and follows that fold in (u, gammaW) with LOCA's
turning-point continuation (LOCA/Bifurcation/Type = Turning Point,
Loading/Continuation Parameter = gammaW) to the cusp where it ends: the
fold curve's largest gammaW, located to solver tolerance, is gammaW_crit;
u, P and the apex gap there are the critical point's.

Method "bisection": for a given (gammaL, gammaW) the approach is unstable
when its path has a fold with the apex gap above 1.1 r_S0 (the small loops a
coarse contact zone adds while the contact grows ring by ring sit at gaps of
1.0-1.05 r_S0); gammaW_crit is bracketed in log gammaW until the bracket is
3 % wide, one approach per trial. Near the cusp the jump-in loop is narrower
in u than the approach's steps (r0/10): at gammaL = 50 and gammaW = 41.5 it
is 5e-6 wide, and the steps pass it without a fold, so bisection puts
gammaW_crit too low (doc/validation.md).

Writes stability_boundary.csv (gammaL, gammaW_crit, u_crit, P_crit,
gap_crit, tabor_mu_crit, seconds; with --method both also the bisection's
gammaW_crit and seconds) and stability_map.png.

    stability_map.py --build build --output output/stability-map [--gammaL 10 20 50 100 200]
        [--method fold|bisection|both]
"""
import argparse
import csv
import math
import os
import subprocess
import sys
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
F_W = math.pi / 8 * 15 ** (1 / 3)        # w = f_w beta0^2 eps r0^4
TABOR = 2.3746                            # mu = TABOR (gammaL / gammaW^2)^(1/3) at nu = 0.2


def tabor(gl, gw):
    return TABOR * (gl / gw ** 2) ** (1 / 3)


def approach(build, name, gl, gw, extra=()):
    """The cgcm command of the approach of (gl, gw) into folder `name`."""
    r0 = 1.0 / gl
    zone = min(0.5, max(0.1, 30 * r0))  # fine cells of about r0 / 1.5 around the contact
    return [os.path.join(build, "bin", "cgcm"), os.path.join(ROOT, "inputs", "sphere-on-half-space.xml"),
            f"Output/Directory={name}", "Output/Print Steps=false", "Output/Exodus=false", "Loading/Control=arc-length",
            f"Interaction/gammaL={gl:.10g}", f"Interaction/gammaW={gw:.10g}",
            f"Geometry/Contact Zone Size={zone:.4g}",
            f"Loading/Approach Path={{{-6 * r0:.6g},{2 * r0:.6g}}}",
            f"Loading/Initial Increment={r0 / 20:.6g}", f"Loading/Max Increment={r0 / 10:.6g}",
            f"Loading/Min Increment={r0 * 1e-6:.6g}", *extra]


def fold_curve(build, out, gl):
    """The cusp of the jump-in fold followed in (u, gammaW): (gammaW_crit, u, P, gap, seconds, states)."""
    guess = math.sqrt(gl * (TABOR / 0.65) ** 3)  # Tabor mu = 0.65
    start, t0 = 0.5 * guess, time.time()
    while True:
        name = os.path.join(out, f"gL{gl:g}-fold-from-gW{start:.6g}")
        args = approach(build, name, gl, start, ["Loading/Continuation Parameter=gammaW",
                                                  f"Loading/Parameter Path={{{4 * guess:.6g}}}",
                                                  "LOCA/Bifurcation/Type=Turning Point"])
        proc = subprocess.run(args, capture_output=True, text=True)
        if proc.returncode == 1 and "has no fold to follow" in proc.stderr:
            start /= 2  # the approach at this gammaW has no jump-in
            continue
        if proc.returncode != 0:
            sys.exit(f"cgcm failed for gammaL = {gl}, following the fold from gammaW = {start:.6g}:\n{proc.stderr}")
        break
    with open(os.path.join(name, "load_curve.csv"), newline="") as f:
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    curve = [r for r in rows if r["fold_curve"] > 0]
    if not curve or curve[-1]["fold"] == 0:
        sys.exit(f"gammaL = {gl}: the fold reached gammaW = {4 * guess:.6g} without a cusp")
    cusp = curve[-1]
    return cusp["gammaW"], cusp["u"], cusp["P"], cusp["gap"], time.time() - t0, len(curve)


def run(build, out, gl, gw):
    """Approach of (gl, gw); returns the jump-in fold (u, P) or None."""
    rs0 = 1.0 / gl / 15 ** (1 / 6)
    name = os.path.join(out, f"gL{gl:g}-gW{gw:.6g}")
    args = approach(build, name, gl, gw)
    proc = subprocess.run(args, capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit(f"cgcm failed for gammaL = {gl}, gammaW = {gw}:\n{proc.stderr}")
    with open(os.path.join(name, "load_curve.csv"), newline="") as f:
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    for r in rows:
        if r["fold"] > 0 and r["gap"] > 1.1 * rs0:
            return r["u"], r["P"]
    return None


def critical(build, out, gl, width=0.03):
    guess = math.sqrt(gl * (TABOR / 0.65) ** 3)  # Tabor mu = 0.65
    lo, hi = 0.5 * guess, 2.0 * guess           # lo: unstable, hi: stable
    fold_lo = run(build, out, gl, lo)
    while fold_lo is None:
        hi, lo = lo, lo / 2
        fold_lo = run(build, out, gl, lo)
    fold_hi = run(build, out, gl, hi)
    while fold_hi is not None:
        lo, fold_lo, hi = hi, fold_hi, hi * 2
        fold_hi = run(build, out, gl, hi)
    while hi / lo > 1 + width:
        mid = math.sqrt(lo * hi)
        fold = run(build, out, gl, mid)
        if fold is None:
            hi = mid
        else:
            lo, fold_lo = mid, fold
        print(f"  gammaL {gl:g}: gammaW in [{lo:.4g}, {hi:.4g}]", flush=True)
    return lo, hi, fold_lo


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", default="build")
    ap.add_argument("--output", default="output/stability-map")
    ap.add_argument("--gammaL", type=float, nargs="+", default=[10, 20, 50, 100, 200])
    ap.add_argument("--method", choices=("fold", "bisection", "both"), default="fold")
    ap.add_argument("--plot-only", action="store_true", help="plot an existing stability_boundary.csv")
    a = ap.parse_args()
    os.makedirs(a.output, exist_ok=True)
    path = os.path.join(a.output, "stability_boundary.csv")
    if a.plot_only:
        with open(path, newline="") as f:
            plot([{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)], a.output)
        return 0
    rows = []
    for gl in a.gammaL:
        row = {"gammaL": gl}
        if a.method in ("fold", "both"):
            gw, u, p, gap, seconds, states = fold_curve(a.build, a.output, gl)
            row.update({"gammaW_crit": gw, "u_crit": u, "P_crit": p, "gap_crit": gap, "tabor_mu_crit": tabor(gl, gw),
                        "seconds": seconds})
            print(f"gammaL = {gl:g}: cusp of the jump-in fold at gammaW = {gw:.6g} (Tabor mu {tabor(gl, gw):.3f}), "
                  f"u = {u:.6g}, P = {p:.5g}, gap = {gap:.5g}; {states} fold-curve states, {seconds:.0f} s", flush=True)
        if a.method in ("bisection", "both"):
            t0 = time.time()
            lo, hi, (u, p) = critical(a.build, a.output, gl)
            gw = math.sqrt(lo * hi)
            bisection = {"gammaW_crit_bisection": gw, "seconds_bisection": time.time() - t0}
            if a.method == "bisection":
                bisection = {"gammaW_crit": gw, "u_crit": u, "P_crit": p, "gap_crit": float("nan"),
                             "tabor_mu_crit": tabor(gl, gw), "seconds": bisection["seconds_bisection"]}
            row.update(bisection)
            print(f"gammaL = {gl:g}: bisection gammaW_crit = {gw:.4g} in [{lo:.4g}, {hi:.4g}], "
                  f"{time.time() - t0:.0f} s", flush=True)
        rows.append(row)
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    print(f"wrote {path}")
    plot(rows, a.output)
    return 0


def plot(rows, out):
    fig, ax = plt.subplots(figsize=(6, 4.5))
    gls = [r["gammaL"] for r in rows]
    ax.plot(gls, [r["gammaW_crit"] for r in rows], "o-", label="cgcm: critical gammaW (cusp of the jump-in fold)")
    if all("gammaW_crit_bisection" in r for r in rows):
        ax.plot(gls, [r["gammaW_crit_bisection"] for r in rows], "s--", mfc="none", lw=0.8,
                label="bisection with approaches in steps of r0/10")
    span = [min(gls) / 1.5, max(gls) * 1.5]
    for mu in (0.7, 0.8):
        ax.plot(span, [math.sqrt(g * (TABOR / mu) ** 3) for g in span], ":", lw=1, label=f"Tabor mu = {mu}")
    # the paper's statement at gammaL bar = 50 (literal reading): gammaW bar = 50 jumps, 100 does not
    glp = 50 / 0.75 ** (1 / 6)
    ax.plot([glp], [50 / math.sqrt(3)], "rx", label="paper: unstable (gammaW bar 50)")
    ax.plot([glp], [100 / math.sqrt(3)], "g+", ms=9, label="paper: stable (gammaW bar 100)")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("gammaL = R0 / r0")
    ax.set_ylabel("gammaW")
    ax.set_title("jump-to-contact on approach below the curve")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "stability_map.png"), dpi=120)


if __name__ == "__main__":
    sys.exit(main())
