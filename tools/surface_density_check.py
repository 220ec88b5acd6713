#!/usr/bin/env python3
"""Surface-density check of Method 3 at one state of a cgcm results.e
(axisymmetric sphere on half-space, Lennard-Jones, doc/theory.md#method-3).

Method 3 integrates the traction with the reference density over the current
area, f = N T(r) rbar (rbar.n) da. Particle conservation in the surface layer
gives beta da = beta0 dA, i.e. the density beta0/J_s on the current surface
with J_s = da/dA the surface stretch (axisymmetric: J_s = (x/X)(|t|/|T|)), or
beta0/J with the volume ratio J of the cell under the surface (the
one-dimensional surface-layer picture), or the same on both bodies
(beta_k/J_k beta_l/J_l). It also evaluates the Derjaguin reading of the
same deformed state, the one of the Lennard-Jones sphere reference
(cgcm-analytic ljsphere): the law at the vertical gap on the projected ring
area, which shows what the closest-point direction changes. This tool re-evaluates Method 3's force on each
body from the deformed surfaces of results.e (the same closest-point
projection onto the other body's polyline, Gauss points on [0, 1], the
tapered 9-3 law), checks it against the code's own nodal
interaction_force_*, and prints the resultant with da and with each
density correction, the surface stretch J_s over the interaction zone
(where the traction is tensile and where it peaks) and the force change
each correction makes, in units of pi w R.

It evaluates one state without re-equilibrating it: the printed changes are
first-order estimates of how much the correction would move P_min.

    surface_density_check.py output/run/results.e --gammaL 2000 --gammaW 14.6378
                     [--step N (1-based; default: the stable step of smallest P)]
                     [--points 4] [--cutoff 10] [--taper 0.2] [--profile]

Measured (gammaL 2000, mu 5, band mesh of cells l/4 as tools/pulloff_map.py
plans it, finite strain, state of P_min = -1.602 pi w R): J_s = 1.03 .. 1.06
where the tension exceeds half its peak (tension-weighted mean 1.026), and
beta0/J_s moves the force by -2.8 %; Method 1 on the same mesh gives -2.3 %.
"""
import argparse
import math

import netCDF4
import numpy as np

F_W = math.pi / 8 * 15 ** (1 / 3)


def names(ds, var):
    return [netCDF4.chartostring(n).item() for n in ds.variables[var][:]] if var in ds.variables else []


def surfaces(ds):
    """Per side set ('contact:<body>'): segments as (node a, node b, element index, block) with the
    body on the left of a -> b (counter-clockwise quads), so n = (t_y, -t_x)/|t| points outward."""
    blocks = [np.array(ds.variables[f"connect{b + 1}"][:]) - 1 for b in range(len(names(ds, "eb_names")))]
    offsets = np.cumsum([0] + [len(c) for c in blocks])
    out = {}
    for i, name in enumerate(names(ds, "ss_names")):
        elems = np.array(ds.variables[f"elem_ss{i + 1}"][:]) - 1
        sides = np.array(ds.variables[f"side_ss{i + 1}"][:]) - 1
        segs = []
        for e, s in zip(elems, sides):
            b = int(np.searchsorted(offsets, e, side="right") - 1)
            conn = blocks[b][e - offsets[b]]
            k = len(conn) if len(conn) in (3, 4) else 4
            segs.append((conn[s], conn[(s + 1) % k], e - offsets[b], b))
        out[name.split(":", 1)[-1]] = segs
    return out


def traction_law(gl, gw, cutoff, taper):
    """T(r) = beta0^2 Phi/beta0 with R0 = Y = beta0 = 1 (beta0^2 eps r0^3 = 1/gammaW), tapered."""
    r0 = 1.0 / gl
    rc, rt = cutoff * r0, (1.0 - taper) * cutoff * r0

    def T(r):
        q = r0 / r
        t = (math.pi / gw) * (q ** 9 / 45.0 - q ** 3 / 3.0)
        s = np.clip((r - rt) / (rc - rt), 0.0, 1.0)
        return np.where(r >= rc, 0.0, t * (1.0 - s * s * (3.0 - 2.0 * s)))
    return T


def project(p, a, b):
    """Closest points of points p (n, 2) on the polyline of segments a -> b (m, 2): distance,
    foot, index of the segment (brute force, clamped to the segment)."""
    d = b - a
    dd = np.einsum("ij,ij->i", d, d)
    rel = p[:, None, :] - a[None, :, :]
    lam = np.clip(np.einsum("nmj,mj->nm", rel, d) / dd[None, :], 0.0, 1.0)
    foot = a[None, :, :] + lam[..., None] * d[None, :, :]
    dist2 = np.einsum("nmj,nmj->nm", p[:, None, :] - foot, p[:, None, :] - foot)
    k = np.argmin(dist2, axis=1)
    idx = np.arange(len(p))
    return np.sqrt(dist2[idx, k]), foot[idx, k], k


def evaluate(ds, step, gl, gw, npts, cutoff, taper):
    X0, Y0 = np.array(ds.variables["coordx"][:]), np.array(ds.variables["coordy"][:])
    ux, uy = (np.array(ds.variables[f"vals_nod_var{i}"][step - 1]) for i in (1, 2))
    x, y = X0 + ux, Y0 + uy
    elem_names = names(ds, "name_elem_var")
    jvol = [np.array(ds.variables[f"vals_elem_var{elem_names.index('J') + 1}eb{b + 1}"][step - 1])
            for b in range(len(names(ds, "eb_names")))]
    surf = surfaces(ds)
    T = traction_law(gl, gw, cutoff, taper)
    g, w = np.polynomial.legendre.leggauss(npts)
    xi, wq = 0.5 * (g + 1.0), 0.5 * w
    res = {}
    for body, other in (("sphere", "half-space"), ("half-space", "sphere")):
        S, O = np.array(surf[body]), np.array(surf[other])
        a_n, b_n = S[:, 0], S[:, 1]
        oa = np.column_stack((x[O[:, 0]], y[O[:, 0]]))
        ob = np.column_stack((x[O[:, 1]], y[O[:, 1]]))
        rows = []
        for q in range(npts):
            N0, N1 = 1.0 - xi[q], xi[q]
            p = np.column_stack((N0 * x[a_n] + N1 * x[b_n], N0 * y[a_n] + N1 * y[b_n]))
            P0 = np.column_stack((N0 * X0[a_n] + N1 * X0[b_n], N0 * Y0[a_n] + N1 * Y0[b_n]))
            t = np.column_stack((x[b_n] - x[a_n], y[b_n] - y[a_n]))
            t0 = np.column_stack((X0[b_n] - X0[a_n], Y0[b_n] - Y0[a_n]))
            L, L0 = np.hypot(t[:, 0], t[:, 1]), np.hypot(t0[:, 0], t0[:, 1])
            n = np.column_stack((t[:, 1], -t[:, 0])) / L[:, None]
            da = 2 * math.pi * p[:, 0] * L * wq[q]
            dA = 2 * math.pi * P0[:, 0] * L0 * wq[q]
            r, foot, k = project(p, oa, ob)
            rb = (p - foot) / r[:, None]
            c = np.einsum("ij,ij->i", rb, n)
            Tr = T(r)
            Jk = jvol[S[0, 3]][S[:, 2]]
            Jl = jvol[O[0, 3]][O[k, 2]]
            # the Derjaguin reading of the same state (the Lennard-Jones sphere reference's): the law at
            # the vertical gap to the other surface, on the projected ring area 2 pi x |dx|
            ox, oy = np.concatenate((oa[:, 0], ob[:, 0])), np.concatenate((oa[:, 1], ob[:, 1]))
            order = np.argsort(ox)
            hv = np.abs(p[:, 1] - np.interp(p[:, 0], ox[order], oy[order]))
            dxp = 2 * math.pi * p[:, 0] * np.abs(t[:, 0]) * wq[q]
            rows.append(dict(X=P0[:, 0], x=p[:, 0], r=r, T=Tr, c=c, rb=rb, da=da, dA=dA, Jk=Jk, Jl=Jl,
                             Tv=T(hv), dxp=dxp,
                             fa0=N0 * Tr * c, fa1=N1 * Tr * c, a=a_n, b=b_n))
        res[body] = rows
    return res, (x, y)


def resultant(rows, weight):
    """y-resultant of the force on the body (the applied force is -f): sum of T c rbar_y * weight."""
    return sum(float(np.sum(-(q["T"] * q["c"] * q["rb"][:, 1]) * weight(q))) for q in rows)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("results")
    ap.add_argument("--gammaL", type=float, required=True)
    ap.add_argument("--gammaW", type=float, required=True)
    ap.add_argument("--step", type=int, help="1-based (default: the stable step of the smallest P)")
    ap.add_argument("--points", type=int, default=4, help="Gauss points per segment (Interaction/Quadrature Points)")
    ap.add_argument("--cutoff", type=float, default=10.0, help="in r0")
    ap.add_argument("--taper", type=float, default=0.2)
    ap.add_argument("--profile", action="store_true", help="print J_s, J and T against the radius in the zone")
    a = ap.parse_args()
    ds = netCDF4.Dataset(a.results)
    glo = names(ds, "name_glo_var")
    gv = np.array(ds.variables["vals_glo_var"][:])
    P, stable = gv[:, glo.index("P")], gv[:, glo.index("stable")]
    step = a.step or int(np.argmin(np.where(stable > 0.5, P, np.inf))) + 1
    w = F_W / (a.gammaL * a.gammaW)
    unit = math.pi * w
    res, (x, y) = evaluate(ds, step, a.gammaL, a.gammaW, a.points, a.cutoff, a.taper)
    nod = names(ds, "name_nod_var")
    fy = np.array(ds.variables[f"vals_nod_var{nod.index('interaction_force_y') + 1}"][step - 1])
    print(f"step {step}: u = {gv[step - 1, glo.index('u')]:.6g}, P = {P[step - 1]:.6g} = "
          f"{P[step - 1] / unit:.5f} pi w R, contact radius {gv[step - 1, glo.index('contact_radius')]:.4g}")
    for body, rows in res.items():
        nodes = np.unique(np.concatenate([rows[0]["a"], rows[0]["b"]]))
        code = float(np.sum(fy[nodes]))
        base = resultant(rows, lambda q: q["da"])
        v = {"beta0/J_s (dA)": resultant(rows, lambda q: q["dA"]),
             "beta0/J (cell)": resultant(rows, lambda q: q["da"] / q["Jk"]),
             "both bodies /J": resultant(rows, lambda q: q["da"] / (q["Jk"] * q["Jl"]))}
        sgn = 1.0 if base < 0 else -1.0  # the sphere's force is along -y for attraction
        v["Derjaguin (vert.)"] = sgn * sum(float(np.sum(q["Tv"] * q["dxp"])) for q in rows)
        wedge = resultant([dict(q, T=np.where(np.abs(q["c"]) < 0.999, q["T"], 0.0)) for q in rows],
                          lambda q: q["da"])
        print(f"{body}: force from results.e {code / unit:+.5f}, re-evaluated (da) {base / unit:+.5f} pi w R")
        for k, val in v.items():
            print(f"  {k:16s} {val / unit:+.5f}  change {(val - base) / unit:+.5f} pi w R "
                  f"({100 * (val / base - 1):+.2f} %)")
        # where the force is gathered: compressive and tensile parts, J_s there
        allq = {k: np.concatenate([q[k] for q in rows]) for k in ("X", "x", "T", "c", "da", "dA", "Jk", "r")}
        fyq = -np.concatenate([q["T"] * q["c"] * q["rb"][:, 1] * q["da"] for q in rows])
        Js = allq["da"] / allq["dA"]
        comp, tens = fyq[allq["T"] > 0].sum(), fyq[allq["T"] < 0].sum()
        print(f"  compressive part {comp / unit:+.4f}, tensile part {tens / unit:+.4f} pi w R; from points whose "
              f"rbar is more than 2.6 deg off the normal (the opening wedge) {wedge / unit:+.4f} pi w R")
        peak = np.argmin(allq["T"])
        inzone = allq["T"] < 0.5 * allq["T"].min()
        wt = np.abs(fyq[allq["T"] < 0])
        print(f"  peak tension at X = {allq['X'][peak]:.5g}: J_s = {Js[peak]:.5f}, J = {allq['Jk'][peak]:.5f}; "
              f"where T < T_min/2: J_s {Js[inzone].min():.5f} .. {Js[inzone].max():.5f}; "
              f"tension-weighted mean J_s {np.sum(wt * Js[allq['T'] < 0]) / wt.sum():.5f}, "
              f"pressure-weighted {np.sum(np.abs(fyq[allq['T'] > 0]) * Js[allq['T'] > 0]) / max(abs(comp), 1e-300):.5f}")
        if a.profile:
            order = np.argsort(allq["X"])
            sel = order[np.abs(allq["T"][order]) > 1e-3 * np.abs(allq["T"]).max()]
            for i in sel[:: max(1, len(sel) // 40)]:
                print(f"    X {allq['X'][i]:.5f} r/r0 {allq['r'][i] * a.gammaL:7.3f} T {allq['T'][i]:+.4e} "
                      f"c {allq['c'][i]:+.4f} J_s {Js[i]:.5f} J {allq['Jk'][i]:.5f}")


if __name__ == "__main__":
    main()
