#!/usr/bin/env python3
"""Draws one field of a cgcm results.e (Exodus II, read with python3-netcdf4)
on the deformed 2D mesh: an element field (stress_*, J, von_mises) as
coloured cells, a nodal field (displacement_*, traction_*, pressure,
interaction_force_*) as coloured nodes, at one step (1-based; default: the
step of the smallest P).

    plot_field.py output/demo/results.e --field von_mises --output field.png
    plot_field.py results.e --field stress_zz --step 40 --window 0 0.4 -0.2 0.2
"""
import argparse
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import netCDF4  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402


def names(ds, var):
    return [netCDF4.chartostring(n).item() for n in ds.variables[var][:]] if var in ds.variables else []


def deformed_xy(ds, step):
    """Node coordinates at `step` (1-based): reference plus displacement."""
    return (np.array(ds.variables["coordx"][:]) + np.array(ds.variables["vals_nod_var1"][step - 1]),
            np.array(ds.variables["coordy"][:]) + np.array(ds.variables["vals_nod_var2"][step - 1]))


def deformed_cells(ds, step, field=None):
    """The cells of every block as polygons on the deformed mesh at `step`
    (1-based), and the element field's values on them (empty without one)."""
    x, y = deformed_xy(ds, step)
    element = names(ds, "name_elem_var")
    polys, values = [], []
    for b in range(1, len(names(ds, "eb_names")) + 1):
        conn = np.array(ds.variables[f"connect{b}"][:]) - 1
        if conn.shape[1] in (8, 9):  # QUAD8, QUAD9: the outline runs corner, edge node, corner, ...
            conn = conn[:, [0, 4, 1, 5, 2, 6, 3, 7]]
        polys += [np.column_stack((x[c], y[c])) for c in conn]
        if field in element:
            values += list(ds.variables[f"vals_elem_var{element.index(field) + 1}eb{b}"][step - 1])
    return polys, np.array(values)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("results")
    ap.add_argument("--field", default="von_mises")
    ap.add_argument("--step", type=int, help="1-based step (default: the step of the smallest P)")
    ap.add_argument("--window", type=float, nargs=4, metavar=("X0", "X1", "Y0", "Y1"), default=(0, 0.5, -0.25, 0.25),
                    help="region drawn, in the mesh's units (default: the contact zone of the benchmark)")
    ap.add_argument("--output", default="field.png")
    a = ap.parse_args()
    ds = netCDF4.Dataset(a.results)
    if "coordz" in ds.variables:
        sys.exit("plot_field: 2D meshes only")
    globals_ = names(ds, "name_glo_var")
    gvals = ds.variables["vals_glo_var"][:] if globals_ else None
    nsteps = len(ds.variables["time_whole"])
    step = a.step or (int(np.argmin(gvals[:, globals_.index("P")])) + 1 if "P" in globals_ else nsteps)
    if not 1 <= step <= nsteps:
        sys.exit(f"plot_field: step {step} not in 1 .. {nsteps}")
    x, y = deformed_xy(ds, step)
    nodal, element = names(ds, "name_nod_var"), names(ds, "name_elem_var")
    fig, ax = plt.subplots(figsize=(7, 6))
    polys, values = deformed_cells(ds, step, a.field)
    if a.field in element:
        cells = PolyCollection(polys, array=values, cmap="viridis", edgecolors="k", linewidths=0.1)
        ax.add_collection(cells)
        fig.colorbar(cells, ax=ax, label=a.field)
    elif a.field in nodal:
        ax.add_collection(PolyCollection(polys, facecolors="none", edgecolors="0.6", linewidths=0.2))
        v = np.array(ds.variables[f"vals_nod_var{nodal.index(a.field) + 1}"][step - 1])
        shown = v != 0.0
        dots = ax.scatter(x[shown], y[shown], c=v[shown], s=12, cmap="coolwarm", zorder=3)
        fig.colorbar(dots, ax=ax, label=a.field + " (nonzero nodes)")
    else:
        sys.exit(f"plot_field: no field {a.field!r}; element: {', '.join(element)}; nodal: {', '.join(nodal)}")
    ax.set_xlim(a.window[0], a.window[1])
    ax.set_ylim(a.window[2], a.window[3])
    ax.set_aspect("equal")
    title = f"{a.field} at step {step}"
    if globals_:
        title += ", " + ", ".join(f"{g} = {gvals[step - 1, globals_.index(g)]:.4g}" for g in ("u", "P") if g in globals_)
    ax.set_title(title + " (deformed mesh)", fontsize=10)
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    fig.tight_layout()
    fig.savefig(a.output, dpi=120)
    print(f"{a.output}: {title}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
