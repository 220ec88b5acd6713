#!/usr/bin/env python3
"""Plots a run with branch points (Output/Eigenvalues, Loading/Branch Switching).

Left: P against u, the path (branch 0) solid where stable, dashed where not (by the tangent's
eigenvalues), the branches switched to in colour, branch points as circles, folds as crosses.
Middle: the two eigenvalues nearest 0 along the path against u. Right: the sideways
displacement of one node (results.e; default the tip's apex of meshes/tip-over-groove.geo)
against u: 0 on the symmetric path, the pitchfork's asymmetric branches off it.

  tools/plot_branches.py OUTPUT_DIR [--node X Y] [--output branches.png]
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import netCDF4  # noqa: E402
import numpy as np  # noqa: E402


def segments(rows, key):
    """Runs of consecutive rows with the same value of key(row)."""
    out, run = [], []
    for r in rows:
        if run and key(r) != key(run[-1]):
            out.append(run + [r])  # joined to the next run
            run = []
        run.append(r)
    if run:
        out.append(run)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("output_dir")
    ap.add_argument("--node", type=float, nargs=2, metavar=("X", "Y"), default=(0.0, 0.2),
                    help="reference position of the node whose sideways displacement is drawn (default: the tip's apex)")
    ap.add_argument("--output", default="branches.png")
    a = ap.parse_args()
    with open(os.path.join(a.output_dir, "load_curve.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for k in r:
            r[k] = float(r[k])
    path = [r for r in rows if r["branch"] == 0]
    branches = sorted({int(r["branch"]) for r in rows if r["branch"] > 0})

    fig, (ax, ev, side) = plt.subplots(1, 3, figsize=(16, 5))
    for seg in segments(path, lambda r: r["stable"] > 0):
        stable = seg[0]["stable"] > 0
        ax.plot([r["u"] for r in seg], [1e3 * r["P"] for r in seg], "k-" if stable else "k--", lw=1.4)
    colours = ["tab:red", "tab:blue", "tab:green", "tab:purple"]
    for b in branches:
        rows_b = [r for r in rows if r["branch"] == b]
        for seg in segments(rows_b, lambda r: r["stable"] > 0):
            ax.plot([r["u"] for r in seg], [1e3 * r["P"] for r in seg], color=colours[(b - 1) % 4],
                    ls="-" if seg[0]["stable"] > 0 else "--", lw=1.0)
        ax.plot([], [], color=colours[(b - 1) % 4], label=f"branch {b} (switched to)")
    bp = [r for r in path if r["branch_point"] > 0]
    folds = [r for r in path if r["fold"] > 0]
    ax.plot([r["u"] for r in bp], [1e3 * r["P"] for r in bp], "o", mfc="none", mec="k", ms=8, label="branch point")
    ax.plot([r["u"] for r in folds], [1e3 * r["P"] for r in folds], "kx", ms=8, label="fold")
    ax.plot([], [], "k-", label="path, stable")
    ax.plot([], [], "k--", label="unstable (eigenvalues)")
    ax.set_xlabel("u")
    ax.set_ylabel("P  [1e-3]")
    ax.legend(fontsize=8)
    ax.set_title("load against approach")

    ev.plot([r["u"] for r in path], [r["eigenvalue_1"] for r in path], ".-", ms=3, lw=0.8, label="eigenvalue 1")
    ev.plot([r["u"] for r in path], [r["eigenvalue_2"] for r in path], ".-", ms=3, lw=0.8, label="eigenvalue 2")
    ev.axhline(0.0, color="k", lw=0.6)
    for r in bp:
        ev.axvline(r["u"], color="0.6", lw=0.6, ls=":")
    ev.set_xlabel("u")
    ev.set_ylabel("eigenvalues of the tangent nearest 0")
    ev.set_title("the path's spectrum (branch points dotted)")
    ev.legend(fontsize=8)

    # the order parameter: the sideways displacement of the node nearest --node (results.e)
    ds = netCDF4.Dataset(os.path.join(a.output_dir, "results.e"))
    x0, y0 = np.array(ds.variables["coordx"][:]), np.array(ds.variables["coordy"][:])
    node = int(np.argmin((x0 - a.node[0]) ** 2 + (y0 - a.node[1]) ** 2))
    ux = np.array(ds.variables["vals_nod_var1"][:, node])
    side.plot([r["u"] for r in path], [ux[rows.index(r)] for r in path], "k.", ms=3, label="path")
    for b in branches:
        idx = [k for k, r in enumerate(rows) if r["branch"] == b]
        side.plot([rows[k]["u"] for k in idx], [ux[k] for k in idx], ".", ms=3, color=colours[(b - 1) % 4],
                  label=f"branch {b}")
    side.plot([r["u"] for r in bp], [ux[rows.index(r)] for r in bp], "o", mfc="none", mec="k", ms=8)
    side.set_xlabel("u")
    side.set_ylabel(f"sideways displacement of the node at ({x0[node]:.3g}, {y0[node]:.3g})")
    side.set_title("the pitchfork: symmetric path and asymmetric branches")
    side.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(a.output, dpi=130)
    print(f"{a.output}: {len(path)} path rows, {len(bp)} branch points, {len(branches)} branches")


if __name__ == "__main__":
    sys.exit(main())
