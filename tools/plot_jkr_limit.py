#!/usr/bin/env python3
"""Minimum force on retraction against the Tabor parameter: the CGCM runs of
tools/run_jkr_study.sh (table.csv) over the Lennard-Jones sphere reference and
the Maugis-Dugdale model (lambda = 1.16 mu), between Bradley's -2 and JKR's
-1.5 pi w R.

    plot_jkr_limit.py --table output/validation/jkr-study/table.csv
                      [--analytic build/bin/cgcm-analytic] [--output jkr-limit.png]
"""
import argparse
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from analytic_csv import LAMBDA_OVER_MU, lj_sphere_pulloff, md_pulloff  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--table", required=True)
    ap.add_argument("--analytic", default="build/bin/cgcm-analytic")
    ap.add_argument("--output", default="jkr-limit.png")
    args = ap.parse_args()

    mus = np.geomspace(0.05, 10.0, 14)
    lj = [lj_sphere_pulloff(args.analytic, m) for m in mus]
    md_mu = np.geomspace(0.05, 10.0, 60)
    md = [md_pulloff(args.analytic, LAMBDA_OVER_MU * m) for m in md_mu]

    with open(args.table, newline="") as f:
        runs = [r for r in csv.DictReader(f) if r["P_min_over_piwR"] not in ("", "nan")]

    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    ax.axhline(-2.0, color="0.6", lw=0.8, ls=":")
    ax.axhline(-1.5, color="0.6", lw=0.8, ls=":")
    ax.text(0.052, -2.005, "Bradley / DMT  −2", va="top", fontsize=8, color="0.4")
    ax.text(0.052, -1.51, "JKR  −1.5", va="top", fontsize=8, color="0.4")
    ax.plot(mus, lj, "k-", lw=1.4, label="Lennard-Jones sphere (Derjaguin, linear elastic)")
    ax.plot(md_mu, md, "k--", lw=1.0, label="Maugis–Dugdale, λ = 1.157 μ")
    markers = {"gammaL50": ("o", "C0", "CGCM, γL = 50"), "gammaL200": ("s", "C1", "CGCM, γL = 200"),
               "gammaL800": ("^", "C2", "CGCM, γL = 800")}
    seen = set()
    for r in runs:
        key = r["case"].split("-")[0]
        marker, color, label = markers.get(key, ("x", "C3", "CGCM"))
        ax.plot(float(r["mu"]), float(r["P_min_over_piwR"]), marker, color=color, mfc="none", ms=7,
                label=None if label in seen else label)
        seen.add(label)
    ax.set_xscale("log")
    ax.set_xlabel("Tabor parameter μ")
    ax.set_ylabel("minimum force on retraction  P_min / (π w R)")
    ax.set_ylim(-2.05, -1.45)
    ax.legend(fontsize=8, loc="lower right")
    ax.grid(True, which="both", lw=0.3, alpha=0.5)
    fig.tight_layout()
    fig.savefig(args.output, dpi=130)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
