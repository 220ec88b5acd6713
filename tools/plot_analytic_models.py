#!/usr/bin/env python3
"""The analytic adhesion models (Hertz, JKR, DMT, Maugis-Dugdale) in the
Johnson-Greenwood normalisation (36), the paper's Figs. 7 and 8, all from
cgcm-analytic: contact pressure at a common contact radius (Fig. 7), load
curves with their pull-off points (Fig. 8) and a table of the pull-off points.

    plot_analytic_models.py [--fig7 doc/figures/fig7-analytic-pressure.png]
                            [--fig8 doc/figures/fig8-analytic-load-curves.png]
                            [--table output/figures/analytic-pulloff.csv]
                            [--lambdas 0.1,0.5,1,2,5] [--a 1]
                            [--analytic build/bin/cgcm-analytic]

Fig. 7: p̄(r̄/ā) at the same ā for every model. JKR is -inf at r = a (drawn
off the axis); M-D carries -lambda over a <= r <= m a; DMT is the Hertz
pressure in r < a, its adhesive force (P̄ = -2) acting outside the contact
with vanishing stress (as cgcm-analytic gives it), marked along p̄ = 0.
Fig. 8: P̄(δ̄), pull-off under load control (min P̄) filled, under displacement
control (d δ̄/d ā = 0, or the end of the branch) open. Hertz has no pull-off.
The table holds, per model and lambda, both pull-off rows of `pulloff`.
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from analytic_csv import columns as analytic_columns  # noqa: E402

BASE = [("hertz", "Hertz", "k", "-"), ("jkr", "JKR", "C3", "-"), ("dmt", "DMT", "C0", "--")]


def columns(exe, *args):
    """cgcm-analytic's CSV by column, its notes passed on."""
    return analytic_columns(exe, *args, notes=True)


def models(lambdas):
    """(model args, legend label, colour, line style) for the base models and M-D at each lambda."""
    out = [(["--model", m], lab, c, ls) for m, lab, c, ls in BASE]
    cmap = plt.get_cmap("viridis")
    for i, lam in enumerate(lambdas):
        col = cmap(0.9 * i / max(1, len(lambdas) - 1))
        out.append((["--model", "md", "--lambda", f"{lam:g}"], f"M-D, λ = {lam:g}", col, "-"))
    return out


def save(fig, path):
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    fig.tight_layout()
    fig.savefig(path, dpi=150)
    plt.close(fig)
    print(f"wrote {path}")


def fig7(exe, lambdas, a, points, path):
    a_arg = ["--a", f"{a:g}"]
    # first pass: the tool's default extent for M-D is 1.25 m, so its adhesive zone shows
    rmax = max(columns(exe, "pressure", "--model", "md", "--lambda", f"{lam:g}", *a_arg, "--points", "3")["r_over_a"][-1]
               for lam in lambdas)
    curves = [(lab, col, ls, columns(exe, "pressure", *m, *a_arg, "--rmax", f"{rmax:g}", "--points", str(points)))
              for m, lab, col, ls in models(lambdas)]
    finite = np.concatenate([c["p"][np.isfinite(c["p"])] for lab, _, _, c in curves if lab != "JKR"])
    lo, hi = 1.12 * finite.min(), 1.25 * finite.max()

    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    ax.axhline(0.0, color="k", lw=0.5)
    ax.axvline(1.0, color="0.5", lw=0.6, ls=":")
    for lab, col, ls, c in curves:
        r, p = c["r_over_a"], c["p"].copy()
        p[np.isneginf(p)] = lo - 10 * (hi - lo)  # JKR: -inf at r = a, drawn off the axis
        ax.plot(r, p, ls, color=col, lw=1.8 if lab == "Hertz" else 1.2, label=lab, zorder=3 if lab == "JKR" else 2)
    # DMT: adhesion outside the contact with vanishing stress over an unbounded annulus
    ax.plot([1.0, rmax], [0.0, 0.0], color="C0", lw=3, alpha=0.35, solid_capstyle="butt",
            label=r"DMT adhesive zone ($\bar{p} \to 0^-$, r > a)")
    ax.set_xlim(0.0, rmax)
    ax.set_ylim(lo, hi)
    ax.set_xlabel(r"$\bar{r}\,/\,\bar{a} = r/a$")
    ax.set_ylabel(r"$\bar{p} = p\,(9R\,/\,2\pi w E^{*2})^{1/3}$")
    ax.set_title(rf"Contact pressure at $\bar{{a}}$ = {a:g}  (JKR: $\bar{{p}} \to -\infty$ at r = a)", fontsize=10)
    ax.legend(fontsize=7.5, loc="lower right", ncol=2)
    ax.grid(True, lw=0.3, alpha=0.5)
    save(fig, path)


def pulloffs(exe, lambdas):
    rows = []
    for m, lab, col, ls in models(lambdas):
        print(f"pulloff {' '.join(m)}", file=sys.stderr)
        t = columns(exe, "pulloff", *m)
        rows.append((m, lab, col, {ctl: [t[k][i] for k in ("P", "a", "delta")]
                                   for i, ctl in enumerate(t["control"])}))
    return rows


def fig8(exe, lambdas, points, po, path):
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    ax.axhline(0.0, color="k", lw=0.5)
    ax.axvline(0.0, color="k", lw=0.5)
    for (m, lab, col, ls), (_, _, _, pts) in zip(models(lambdas), po):
        c = columns(exe, "curve", *m, "--a-min", "1e-4", "--points", str(points))
        ax.plot(c["delta"], c["P"], ls, color=col, lw=1.8 if lab == "Hertz" else 1.2, label=lab,
                zorder=2.5 if lab == "JKR" else 2)
        if m[1] == "hertz":  # no adhesion, no pull-off (both rows P = 0 at a = 0)
            continue
        P, _, d = pts["displacement"]
        ax.plot(d, P, "o", ms=8, mfc="white", mec=col, mew=1.3, zorder=3)
        P, _, d = pts["load"]
        ax.plot(d, P, "o", ms=5, color=col, zorder=4)
    ax.plot([], [], "o", ms=5, color="0.3", label="pull-off, load control")
    ax.plot([], [], "o", ms=8, mfc="white", mec="0.3", label="pull-off, displacement control")
    ax.set_xlim(-2.0, 3.0)
    ax.set_ylim(-2.5, 5.0)
    ax.set_xlabel(r"$\bar{\delta} = \delta\,(16E^{*2}\,/\,9\pi^2 w^2 R)^{1/3}$")
    ax.set_ylabel(r"$\bar{P} = P\,/\,\pi w R$")
    ax.set_title("Load–approach curves, Johnson–Greenwood normalisation", fontsize=10)
    ax.legend(fontsize=7.5, loc="upper left")
    ax.grid(True, lw=0.3, alpha=0.5)
    save(fig, path)


def table(po, path):
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["model", "lambda", "P_load", "a_load", "delta_load", "P_disp", "a_disp", "delta_disp"])
        for m, _, _, pts in po:
            w.writerow([m[1], m[3] if len(m) > 2 else ""] + [f"{v:.10g}" for v in pts["load"] + pts["displacement"]])
    print(f"wrote {path}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--fig7", help="contact pressure figure (PNG)")
    ap.add_argument("--fig8", help="load curve figure (PNG)")
    ap.add_argument("--table", help="pull-off table (CSV)")
    ap.add_argument("--lambdas", default="0.1,0.5,1,2,5", help="M-D lambdas, comma-separated")
    ap.add_argument("--a", type=float, default=1.0, help="common contact radius ā of Fig. 7")
    ap.add_argument("--points", type=int, default=1201, help="points per curve")
    ap.add_argument("--analytic", default="build/bin/cgcm-analytic")
    args = ap.parse_args()
    if not (args.fig7 or args.fig8 or args.table):
        ap.error("nothing to do: give --fig7, --fig8 and/or --table")
    lambdas = [float(x) for x in args.lambdas.split(",")]
    if args.fig7:
        fig7(args.analytic, lambdas, args.a, args.points, args.fig7)
    if args.fig8 or args.table:
        po = pulloffs(args.analytic, lambdas)
        if args.fig8:
            fig8(args.analytic, lambdas, args.points, po, args.fig8)
        if args.table:
            table(po, args.table)


if __name__ == "__main__":
    main()
