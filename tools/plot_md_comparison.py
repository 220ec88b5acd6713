#!/usr/bin/env python3
"""Overlays a CGCM load curve with the Maugis-Dugdale curves of the same
interaction (the paper's Fig. 9a / 11a) at the theoretical lambda and at the
lambda fitted to the curve (cgcm-analytic fit), mapped to the CGCM
normalisation by cgcm-analytic (P_C = f_F P_MD, u = f_delta delta_MD); the
states of the other figures are marked (--mark U, approach).

    plot_md_comparison.py --curve output/demo/load_curve.csv --gammaL 50 --gammaW 200 --nu 0.2
                          [--lambda L (instead of the two)] [--mark=U1,U2,...]
                          [--analytic build/bin/cgcm-analytic] [--output md.png]
"""
import argparse
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from analytic_csv import columns  # noqa: E402
from plot_load_curves import draw  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--curve", required=True)
    ap.add_argument("--gammaL", required=True)
    ap.add_argument("--gammaW", required=True)
    ap.add_argument("--nu", default="0.2")
    ap.add_argument("--lambda", dest="lam", help="one lambda instead of the theoretical and the best fit")
    ap.add_argument("--mark", default="", help="u of approach states to mark (open circles), comma-separated")
    ap.add_argument("--analytic", default="build/bin/cgcm-analytic")
    ap.add_argument("--output", default="md-comparison.png")
    a = ap.parse_args()
    m = columns(a.analytic, "map", "--gammaL", a.gammaL, "--gammaW", a.gammaW, "--nu", a.nu)
    if a.lam:
        lams = [("", float(a.lam))]
    else:
        fit = columns(a.analytic, "fit", "--curve", a.curve, "--gammaL", a.gammaL, "--gammaW", a.gammaW, "--nu", a.nu)
        lams = [("theoretical ", m["lambda_theory"][0]), ("best fit ", fit["lambda"][0])]
    jkr = columns(a.analytic, "curve", "--model", "jkr")
    fF, fd = m["f_F"][0], m["f_delta"][0]
    with open(a.curve, newline="") as f:
        rows = list(csv.DictReader(f))
    c = {k: [float(r[k]) for r in rows] for k in rows[0]}
    u, P = c["u"], c["P"]
    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    draw(ax, c, P, lw=1.6, label="CGCM (Method 3, large deformation; dashed: unstable)")
    for (name, lam), style in zip(lams, ("--", "-.")):
        md = columns(a.analytic, "curve", "--model", "md", "--lambda", repr(lam))
        ax.plot([fd * d for d in md["delta"]], [fF * p for p in md["P"]], style, lw=1.2,
                label=f"Maugis-Dugdale, {name}lambda = {lam:.3g}")
    end = max(range(len(u)), key=lambda k: u[k])  # the approach ends at the largest u
    for target in [float(v) for v in a.mark.split(",") if v.strip()]:
        k = min(range(end + 1), key=lambda k: abs(u[k] - target))
        ax.plot(u[k], P[k], "o", mfc="none", mec="k", ms=8)
    ax.plot([fd * d for d in jkr["delta"]], [fF * p for p in jkr["P"]], ":", lw=1.0, label="JKR")
    ax.set_xlim(min(u), max(u))
    ax.set_ylim(1.3 * min(P), 1.05 * max(P))
    ax.axhline(0.0, color="k", lw=0.5)
    ax.set_xlabel("u / R0")
    ax.set_ylabel("P R0 / E0")
    ax.set_title(f"gammaL = {a.gammaL}, gammaW = {a.gammaW}")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(a.output, dpi=120)
    print(f"wrote {a.output} (lambda = {', '.join(f'{n}{v:.4g}' for n, v in lams)})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
