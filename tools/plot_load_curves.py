#!/usr/bin/env python3
"""Plots load curves written by cgcm (load_curve.csv) and prints a table of
P_min. With --figures DIR and a folder of paper runs (output/paper), writes
the Fig. 5 / Fig. 6 style plots: P(u) and gap(u) for the gammaL and gammaW
sweeps. With plain CSV files, plots P(u) of each into --output.

    plot_load_curves.py --figures doc/figures output/paper
    plot_load_curves.py --output curve.png output/demo/load_curve.csv
"""
import argparse
import csv
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]} if rows else {}


def draw(ax, c, y, **kw):
    """Plots y(u) with the stable parts solid and the unstable ones dashed
    (a segment is unstable when either end is); folds are marked, and each
    jump (displacement control) is an arrow from its fold row to the landing
    row instead of a line."""
    u, stable = c["u"], c.get("stable", [1.0] * len(c["u"]))
    jump = c.get("jump", [0.0] * len(u))
    color = kw.pop("color", None)
    label = kw.pop("label", None)
    starts = [0] + [k for k in range(1, len(u)) if jump[k] > 0] + [len(u)]
    for first, stop in zip(starts, starts[1:]):
        start = first
        for k in range(first + 1, stop + 1):
            seg_unstable = k < stop and (stable[k] == 0 or stable[k - 1] == 0)
            run_unstable = stable[start] == 0 or (start + 1 < stop and stable[start + 1] == 0)
            if k == stop or seg_unstable != run_unstable:
                end = k if k < stop else k - 1
                line, = ax.plot(u[start:end + 1], y[start:end + 1], ls="--" if run_unstable else "-", color=color,
                                label=label, **kw)
                color, label = line.get_color(), None
                start = end
    for k, f in enumerate(c.get("fold", [])):
        if f > 0:
            ax.plot(u[k], y[k], "o", ms=3.5, mfc="none", color=color)
    fold = None
    for k in range(len(u)):
        if c.get("fold", [0.0] * len(u))[k] > 0:
            fold = k
        if jump[k] > 0 and fold is not None:
            ax.annotate("", xy=(u[k], y[k]), xytext=(u[fold], y[fold]),
                        arrowprops=dict(arrowstyle="->", color=color, lw=1.0, shrinkA=2, shrinkB=2))
            fold = None
    return color


def minimum(c):
    i = min(range(len(c["P"])), key=lambda k: c["P"][k])
    return c["P"][i], c["u"][i]


def sweep(folder, prefix):
    runs = []
    if not os.path.isdir(folder):
        return runs
    for name in os.listdir(folder):
        m = re.fullmatch(prefix + r"-(\d+)", name)
        path = os.path.join(folder, name, "load_curve.csv")
        if m and os.path.exists(path):
            runs.append((int(m.group(1)), read(path)))
    return sorted(runs, key=lambda r: r[0])


def plot_sweep(runs, label, title, out):
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.2))
    for value, c in runs:
        color = draw(a, c, c["P"], lw=1.2, label=f"{label} = {value}")
        draw(b, c, c["gap"], lw=1.2, color=color)
    for ax in (a, b):
        ax.set_xlim(-0.1, 0.065)  # the window of the paper's figures: adhesion and contact phases
    a.set_xlabel("u / R0")
    a.set_ylabel("P R0 / E0")
    a.axhline(0.0, color="k", lw=0.5)
    a.set_title("load (dashed: unstable under displacement control; o: folds)")
    a.legend(fontsize=8)
    b.set_xlabel("u / R0")
    b.set_ylabel("gap / R0")
    b.set_yscale("log")
    b.set_title("gap on the axis")
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("inputs", nargs="+", help="a folder of paper runs, or load_curve.csv files")
    ap.add_argument("--figures", help="folder for the Fig. 5/6 plots")
    ap.add_argument("--output", default="load_curves.png", help="plot of the CSV files given")
    args = ap.parse_args()
    csvs = [p for p in args.inputs if p.endswith(".csv")]
    folders = [p for p in args.inputs if os.path.isdir(p)]
    for folder in folders:
        for prefix, label, title in (("fig5-gammaL", "gammaL", "gammaW = 200 (Fig. 5)"),
                                     ("fig6-gammaW", "gammaW", "gammaL = 50 (Fig. 6)")):
            runs = sweep(folder, prefix)
            if not runs:
                continue
            print(f"{prefix}: {label:>7} {'P_min':>13} {'u(P_min)':>11} {'P(u=0.06)':>11} {'folds':>5}")
            for value, c in runs:
                p, u = minimum(c)
                end = [c["P"][k] for k in range(len(c["u"])) if abs(c["u"][k] - 0.06) < 1e-9]
                print(f"{'':12}{value:>8} {p:13.5e} {u:11.5f} {end[0] if end else float('nan'):11.5e} "
                      f"{int(sum(c.get('fold', [])))}")
            if args.figures:
                os.makedirs(args.figures, exist_ok=True)
                plot_sweep(runs, label, title, os.path.join(args.figures, prefix + ".png"))
    if csvs:
        fig, a = plt.subplots(figsize=(6, 4))
        for path in csvs:
            c = read(path)
            draw(a, c, c["P"], lw=1.2, label=os.path.basename(os.path.dirname(os.path.abspath(path))))
            p, u = minimum(c)
            print(f"{path}: P_min = {p:.6e} at u = {u:.6f}")
        a.set_xlabel("u / R0")
        a.set_ylabel("P R0 / E0")
        a.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(args.output, dpi=120)
    return 0


if __name__ == "__main__":
    sys.exit(main())
