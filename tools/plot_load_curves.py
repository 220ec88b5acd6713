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
        jumps = [k for k, j in enumerate(c.get("jump", [])) if j > 0]
        line, = a.plot(c["u"], c["P"], lw=1.2, label=f"{label} = {value}")
        b.plot(c["u"], c["gap"], lw=1.2, color=line.get_color())
        for k in jumps:
            a.plot(c["u"][k], c["P"][k], "o", mfc="none", color=line.get_color())
    for ax in (a, b):
        ax.set_xlim(-0.1, 0.065)  # the window of the paper's figures: adhesion and contact phases
    a.set_xlabel("u / R0")
    a.set_ylabel("P R0 / E0")
    a.axhline(0.0, color="k", lw=0.5)
    a.set_title("load")
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
            print(f"{prefix}: {label:>7} {'P_min':>13} {'u(P_min)':>11} {'P(u=0.06)':>11} {'jumps':>5}")
            for value, c in runs:
                p, u = minimum(c)
                end = [c["P"][k] for k in range(len(c["u"])) if abs(c["u"][k] - 0.06) < 1e-9]
                print(f"{'':12}{value:>8} {p:13.5e} {u:11.5f} {end[0] if end else float('nan'):11.5e} "
                      f"{int(sum(c.get('jump', [])))}")
            if args.figures:
                os.makedirs(args.figures, exist_ok=True)
                plot_sweep(runs, label, title, os.path.join(args.figures, prefix + ".png"))
    if csvs:
        fig, a = plt.subplots(figsize=(6, 4))
        for path in csvs:
            c = read(path)
            a.plot(c["u"], c["P"], lw=1.2, label=os.path.basename(os.path.dirname(os.path.abspath(path))))
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
