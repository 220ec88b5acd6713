#!/usr/bin/env python3
"""Plots the load curves of `make method-study` (tools/run_method_study.sh):
per gammaL, P / |P_min of Method 3| against u / r0, Method 3 and Method 1 on
each mesh. Usage: plot_method_study.py STUDY_DIR --output PNG"""
import argparse
import csv
import glob
import os
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def curve(folder):
    rows = list(csv.DictReader(open(os.path.join(folder, "load_curve.csv"))))
    return [float(r["u"]) for r in rows], [float(r["P"]) for r in rows]


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("study", help="output/validation/method-study")
    ap.add_argument("--output", required=True)
    a = ap.parse_args()
    runs = {}
    pattern = re.compile(r"gammaL([0-9.]+)-zone([0-9.]+)(?:-level([0-9]+))?-cutoff([0-9.]+)-(.*)")
    for folder in sorted(glob.glob(os.path.join(a.study, "gammaL*"))):
        m = pattern.fullmatch(os.path.basename(folder))
        if not m or not os.path.isfile(os.path.join(folder, "load_curve.csv")):
            continue
        g, zone, level, cutoff, method = m.groups()
        runs.setdefault((float(g), cutoff), []).append((method, zone, level or "0", folder))
    keys = sorted(runs, key=lambda k: (-k[0], k[1]))
    cols = min(3, len(keys))
    rows = (len(keys) + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 3.6 * rows), squeeze=False)
    for ax in axes.flat[len(keys):]:
        ax.set_visible(False)
    for ax, key in zip(axes.flat, keys):
        g, cutoff = key
        ref = [f for m, _, _, f in runs[key] if m == "half-space-point"]
        scale = abs(min(curve(ref[0])[1])) if ref else 1.0
        for method, zone, level, folder in sorted(runs[key], key=lambda r: (r[0] != "half-space-point", r[1], r[2])):
            u, p = curve(folder)
            label = "Method 3" if method == "half-space-point" else f"Method 1, zone {zone}, level {level}"
            ax.plot([x * g for x in u], [y / scale for y in p], "-" if method == "half-space-point" else "--",
                    label=label, linewidth=1.2)
        ax.set_title(f"gammaL = {g:g}, cutoff {cutoff} r0")
        ax.set_xlabel("u / r0")
        ax.set_xlim(-1.0, 1.0)
        ax.set_ylim(-1.15, 0.6)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    for row in axes:
        row[0].set_ylabel("P / |P_min (Method 3)|")
    fig.tight_layout()
    fig.savefig(a.output, dpi=120)
    print(f"wrote {a.output}")


if __name__ == "__main__":
    main()
