#!/usr/bin/env python3
"""The paper's state figures from a cgcm run of the sphere on the half-space
(axisymmetric, results.e) against the Maugis-Dugdale model of the same
interaction (cgcm-analytic, mapped to the CGCM normalisation R0 = Y = 1):

  --pressure PNG   contact pressure p(r) on the half-space at the state
                   (the paper's Figs. 9b, 11b), M-D at the best-fit and at
                   the theoretical lambda;
  --stress PNG     sigma_z below the contact, CGCM (element means on the
                   deformed mesh) beside M-D (closed form (46)), one colour
                   scale (Figs. 10, 12);
  --states PNG     deformed shapes and sigma_z at five states of the load
                   curve (Fig. 13): just after the jump to contact, half way
                   to the largest tension, the largest tension, P = 0 and the
                   end of the approach;
  --table CSV      the numbers: state u, P, CGCM contact radius, lambdas,
                   M-D contact radius at the state's u, peak pressures.

The state is the approach state nearest --at-u (default: the paper's 0.043),
or with --at-zero-load the one where P crosses zero in contact.
The M-D contact radius is the one whose approach f_delta delta_MD(a) equals
the state's u on the displacement-control branch.

    plot_paper_states.py --run output/paper/fig6-gammaW-200 --gammaL 52.4558 --gammaW 115.470 \\
        --at-u 0.043 --pressure fig9b.png --stress fig10.png --table fig9.csv
"""
import argparse
import csv
import os
import sys

import matplotlib
import netCDF4
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402
from analytic_csv import columns  # noqa: E402
from plot_field import deformed_cells, deformed_xy, names  # noqa: E402


class Results:
    """The Exodus file of one run: globals per step (0-based steps here),
    deformed coordinates, element and nodal fields (tools/plot_field.py)."""

    def __init__(self, path):
        self.ds = netCDF4.Dataset(path)
        g = names(self.ds, "name_glo_var")
        vals = np.array(self.ds.variables["vals_glo_var"][:])
        self.glob = {n: vals[:, i] for i, n in enumerate(g)}
        self.nodal = names(self.ds, "name_nod_var")
        self.sets = names(self.ds, "ns_names")

    def xy(self, step):
        return deformed_xy(self.ds, step + 1)

    def nodal_field(self, name, step):
        return np.array(self.ds.variables[f"vals_nod_var{self.nodal.index(name) + 1}"][step])

    def node_set(self, name):
        return np.array(self.ds.variables[f"node_ns{self.sets.index(name) + 1}"][:]) - 1

    def cells(self, field, step):
        """(polygons, values) of every block on the deformed mesh."""
        return deformed_cells(self.ds, step + 1, field)


def approach_steps(res):
    """Steps up to the end of the first pass of u (the approach)."""
    u = res.glob["u"]
    end = int(np.argmax(u))
    return np.arange(end + 1)


def md_radius_at(exe, lam, u, common):
    """M-D contact radius (CGCM units) whose approach is u on the
    displacement-control branch (a beyond the minimum of u(a))."""
    c = columns(exe, "curve", "--model", "md", "--lambda", lam, "--a-max", 4, "--points", 2000, *common)
    i0 = int(np.argmin(c["u_cgcm"]))  # u rises with a beyond here
    uc = c["u_cgcm"][i0:]
    if not (uc[0] <= u <= uc[-1]):
        return float("nan"), float("nan"), float("nan")
    # (a, P) in CGCM units, and a in the tool's own normalisation for `pressure` and `stress`
    return tuple(float(np.interp(u, uc, c[k][i0:])) for k in ("a_cgcm", "P_cgcm", "a"))


def surface_pressure(res, step):
    """(r, p) on the half-space's top surface, sorted by deformed r."""
    nodes = res.node_set("lower top")
    x, _ = res.xy(step)
    p = res.nodal_field("pressure", step)
    order = np.argsort(x[nodes])
    return x[nodes][order], p[nodes][order]


def draw_field(ax, res, step, field, norm, window, edges=True):
    polys, values = res.cells(field, step)
    cells = PolyCollection(polys, array=values, cmap="RdBu_r", norm=norm,
                           edgecolors="k" if edges else "face", linewidths=0.05)
    ax.add_collection(cells)
    ax.set_xlim(window[0], window[1])
    ax.set_ylim(window[2], window[3])
    ax.set_aspect("equal")
    return cells


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--run", required=True, help="output folder of the run (results.e, load_curve.csv)")
    ap.add_argument("--gammaL", required=True, help="plain gammaL of the run (not barred)")
    ap.add_argument("--gammaW", required=True, help="plain gammaW of the run")
    ap.add_argument("--nu", default="0.2")
    ap.add_argument("--at-u", type=float, default=0.043, help="u of the state (approach)")
    ap.add_argument("--at-zero-load", action="store_true",
                    help="the state is where P crosses 0 in contact on the approach (Fig. 13's (d)) instead")
    ap.add_argument("--label", default="", help="title prefix, e.g. 'gammaL bar = 50, gammaW bar = 200'")
    ap.add_argument("--analytic", default="build/bin/cgcm-analytic")
    ap.add_argument("--stress-lambda", choices=("best fit", "theoretical", "fit", "theory"), default="best fit",
                    help="the M-D lambda of --stress (default: the load curve's best fit)")
    ap.add_argument("--pressure")
    ap.add_argument("--stress")
    ap.add_argument("--states")
    ap.add_argument("--table")
    a = ap.parse_args()
    exe = a.analytic
    common = ["--gammaL", a.gammaL, "--gammaW", a.gammaW, "--nu", a.nu]
    res = Results(os.path.join(a.run, "results.e"))
    m = columns(exe, "map", *common)
    lam_theory = float(m["lambda_theory"][0])
    fit = columns(exe, "fit", "--curve", os.path.join(a.run, "load_curve.csv"), *common)
    lam_fit = float(fit["lambda"][0])

    steps = approach_steps(res)
    u, P = res.glob["u"], res.glob["P"]
    step = five_states(res, steps)[3][1] if a.at_zero_load else int(steps[np.argmin(np.abs(u[steps] - a.at_u))])
    us, Ps = float(u[step]), float(P[step])
    a_cgcm = float(res.glob["contact_radius"][step])
    lams = [("best fit", lam_fit), ("theoretical", lam_theory)]
    md = {name: md_radius_at(exe, lam, us, common) for name, lam in lams}
    title = (a.label + ": " if a.label else "") + f"u = {us:.4f}, P = {Ps:.3g}"

    r, p = surface_pressure(res, step)
    rows = [("step", step), ("u", us), ("P", Ps), ("contact_radius_cgcm", a_cgcm),
            ("p_max_cgcm", float(p.max())), ("p_min_cgcm", float(p.min())),
            ("lambda_fit", lam_fit), ("lambda_theory", lam_theory)]

    if a.pressure:
        fig, ax = plt.subplots(figsize=(6.4, 4.2))
        ax.plot(r, p, "k-", lw=1.6, label=f"CGCM (half-space surface), contact radius {a_cgcm:.3f}")
        for (name, lam), style in zip(lams, ("--", ":")):
            a_md, P_md, a_tool = md[name]
            if not np.isfinite(a_md):
                continue
            q = columns(exe, "pressure", "--model", "md", "--lambda", lam, "--a", a_tool, "--rmax", 2.0, "--points", 801,
                         *common)
            ax.plot(q["r_cgcm"], q["p_cgcm"], style, lw=1.3,
                    label=f"M-D, {name} lambda = {lam:.3g}: a = {a_md:.3f}, P = {P_md:.3g}")
            rows += [(f"a_md_{name.replace(' ', '_')}", a_md), (f"P_md_{name.replace(' ', '_')}", P_md),
                     (f"p_max_md_{name.replace(' ', '_')}", float(np.nanmax(q["p_cgcm"])))]
        ax.axhline(0.0, color="k", lw=0.5)
        ax.set_xlim(0, max(2.0 * max(a_cgcm, 0.05), 0.5))
        ax.set_xlabel("r / R0")
        ax.set_ylabel("p R0^3 / E0  (compression > 0)")
        ax.set_title(title, fontsize=10)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(a.pressure, dpi=150)
        print(f"wrote {a.pressure}")

    if a.stress:
        which = "theoretical" if a.stress_lambda in ("theoretical", "theory") else "best fit"
        lam_s = dict(lams)[which]
        a_md, _, a_tool = md[which]
        extent = 2.0 * max(a_cgcm, a_md if np.isfinite(a_md) else 0.0, 0.05)
        nr = nz = 121
        s = columns(exe, "stress", "--model", "md", "--lambda", lam_s, "--a", a_tool, "--grid", f"{nr},{nz}",
                     "--rmax", extent / a_md, "--zmax", extent / a_md, *common)
        # one scale for both: the M-D extremes and the CGCM cells' 0.5/99.5 percentiles
        fe = res.cells("stress_zz", step)[1]
        lo = min(float(np.nanmin(s["sigma_z_cgcm"])), float(np.percentile(fe, 0.5)))
        hi = max(float(np.nanmax(s["sigma_z_cgcm"])), float(np.percentile(fe, 99.5)), -0.25 * lo)
        norm = matplotlib.colors.TwoSlopeNorm(vmin=lo, vcenter=0.0, vmax=hi)
        fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4.6), sharey=True)
        window = (0.0, extent, -extent, 0.5 * extent)
        draw_field(left, res, step, "stress_zz", norm, window)
        left.set_title(f"CGCM (finite strain), contact radius {a_cgcm:.3f}", fontsize=9)
        sc = right.tripcolor(s["r_cgcm"], -s["z_cgcm"], s["sigma_z_cgcm"], cmap="RdBu_r", norm=norm, shading="gouraud")
        right.set_xlim(window[0], window[1])
        right.set_ylim(window[2], window[3])
        right.set_aspect("equal")
        right.set_title(f"Maugis-Dugdale, {which} lambda = {lam_s:.3g}, a = {a_md:.3f}", fontsize=9)
        for ax in (left, right):
            ax.set_xlabel("r / R0")
        left.set_ylabel("z / R0")
        fig.colorbar(sc, ax=[left, right], label="sigma_z R0^3 / E0", shrink=0.85)
        fig.suptitle(title + " (one colour scale; the M-D field is below z = 0 only)", fontsize=10)
        fig.savefig(a.stress, dpi=150)
        print(f"wrote {a.stress}")
        rows += [("sigma_z_min_cgcm", float(fe.min())), ("sigma_z_max_cgcm", float(fe.max())),
                 ("sigma_z_min_md", float(np.nanmin(s["sigma_z_cgcm"]))),
                 ("sigma_z_max_md", float(np.nanmax(s["sigma_z_cgcm"])))]

    if a.states:
        picks = five_states(res, steps)
        polys_all = [res.cells("stress_zz", k)[1] for _, k in picks]
        lo = min(float(np.percentile(v, 0.5)) for v in polys_all)
        hi = max(float(np.percentile(v, 99.5)) for v in polys_all)
        norm = matplotlib.colors.TwoSlopeNorm(vmin=min(lo, -1e-12), vcenter=0.0, vmax=max(hi, 1e-12))
        fig = plt.figure(figsize=(13, 7.5))
        grid = fig.add_gridspec(2, 5, height_ratios=[1, 1.1])
        curve = fig.add_subplot(grid[0, 1:4])
        axes = [fig.add_subplot(grid[1, k]) for k in range(5)]
        stable = res.glob["stable"][steps] > 0.5
        curve.plot(u[steps], P[steps], "k-", lw=0.8)
        curve.plot(u[steps][~stable], P[steps][~stable], "r.", ms=2, label="unstable (arc-length)")
        window = (0.0, 0.45, -0.2, 0.2)
        for (tag, k), ax in zip(picks, axes):
            curve.plot(u[k], P[k], "o", mfc="none", mec="C0", ms=8)
            curve.annotate(f"({tag})", (u[k], P[k]), textcoords="offset points", xytext=(6, -12), fontsize=9)
            cells = draw_field(ax, res, k, "stress_zz", norm, window, edges=True)
            ax.set_title(f"({tag}) u = {u[k]:.4f}, P = {P[k]:.3g}", fontsize=8)
            ax.set_xticks([0, 0.2, 0.4])
            ax.set_xlabel("r / R0", fontsize=8)
            ax.tick_params(labelsize=7)
            rows += [(f"state_{tag}_u", float(u[k])), (f"state_{tag}_P", float(P[k]))]
        axes[0].set_ylabel("z / R0", fontsize=8)
        curve.set_xlabel("u / R0")
        curve.set_ylabel("P R0 / E0")
        curve.axhline(0.0, color="k", lw=0.4)
        curve.grid(alpha=0.3)
        curve.legend(fontsize=8)
        fig.colorbar(cells, ax=axes, orientation="horizontal", label="sigma_z R0^3 / E0", shrink=0.5, pad=0.18)
        fig.suptitle((a.label + ": " if a.label else "") + "deformation and sigma_z along the approach", fontsize=10)
        fig.savefig(a.states, dpi=150)
        print(f"wrote {a.states}")

    if a.table:
        with open(a.table, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["quantity", "value"])
            for k, v in rows:
                w.writerow([k, f"{v:.6g}" if isinstance(v, float) else v])
        print(f"wrote {a.table}")
    for k, v in rows:
        print(f"  {k} = {v:.6g}" if isinstance(v, float) else f"  {k} = {v}")
    return 0


def five_states(res, steps):
    """(tag, step) of the Fig. 13 states on the approach: (a) the first
    stable state in contact after the jump (or, without a jump, where P
    starts to fall), (b) half way in u from (a) to (c), (c) the largest
    tension, (d) P = 0 in contact, (e) the last state."""
    u, P = res.glob["u"][steps], res.glob["P"][steps]
    stable = res.glob["stable"][steps] > 0.5
    c = int(np.argmin(np.where(stable, P, np.inf)))
    unstable = [k for k in range(c + 1) if not stable[k]]
    jumps = [k for k in range(1, c + 1) if res.glob["jump"][steps[k]] > 0.5]
    if unstable:  # arc-length: the stable contact branch where u is back at the jump-in fold
        u_in = u[unstable[0] - 1]
        first = next(k for k in range(unstable[-1] + 1, c + 1) if stable[k] and u[k] >= u_in)
    elif jumps:  # displacement control: the state the jump landed on
        first = jumps[0]
    else:
        first = int(np.argmax(P[: c + 1] < 0.5 * P[c])) if c > 0 else 0
    b = first + int(np.argmin(np.abs(u[first: c + 1] - 0.5 * (u[first] + u[c]))))
    after = np.arange(c, len(P))
    zero = [k for k in after[:-1] if stable[k] and P[k] <= 0.0 < P[k + 1]]
    d = (min(zero[0], zero[0] + 1, key=lambda k: abs(P[k])) if zero
         else int(after[np.argmin(np.abs(P[after]))]))
    return [("a", int(steps[first])), ("b", int(steps[b])), ("c", int(steps[c])), ("d", int(steps[d])),
            ("e", int(steps[-1]))]


if __name__ == "__main__":
    sys.exit(main())
