#!/usr/bin/env python3
"""The measured error table of Method 1's Gauss rule (VolumeInteraction.cpp, kError2D12 .. kError3D6).

Relative quadrature error of the repulsive (r^-12) and attractive (r^-6) parts of a cell pair's
force: two aligned boxes of edge h (squares in 2D with the plane-strain line law, cubes in 3D)
facing each other at gap g, n-point tensor Gauss-Legendre per direction in both (n = 1 .. 12 in
2D, 1 .. 6 in 3D), h/g = 0.25 * sqrt(2)^k, k = 0 .. 12. The parts are power laws, so the
relative error depends on h/g and n only. The reference reduces the double integral of f(x - y)
over the two boxes exactly to one integral of f(d) times their overlap function (a product of
tents), integrated by composite Gauss on panels graded towards the near singularity. Prints the
table as C++ after its envelope: the largest error at the same or a higher order and the same or
a smaller h/g (so that the estimate grows with h/g and falls with n).

    /usr/bin/python3 tools/volume_quadrature_error.py
"""
import math
import numpy as np, sys

def up3(v):
    """v rounded up to three significant digits (the table is an upper bound)."""
    if v <= 0.0:
        return v
    e = math.floor(math.log10(v)) - 2
    return math.ceil(v / 10.0**e - 1e-9) * 10.0**e

def gl(n):
    x, w = np.polynomial.legendre.leggauss(n); return 0.5*(x+1), 0.5*w
def law(dim, d, p):
    # d: (..., dim) differences; returns d/d(d_y) of the pair law (per unit thickness in 2D)
    s = (d**2).sum(-1)
    if dim == 2:  # line integral of r^-p: s^(1/2 - p/2) * const (const dropped: relative errors)
        m = p/2.0; e = 0.5 - m
    else:
        e = -p/2.0
    return e * s**(e-1) * 2*d[..., 1]
def panels(a, b, g, grow=2.0):
    # breakpoints from a (near the singularity, at distance g) geometrically to b
    pts = [a]; step = g/8
    while pts[-1] + step < b: pts.append(pts[-1] + step); step *= grow
    pts.append(b); return pts
def composite(breaks, n=30):
    t, w = gl(n); X=[]; W=[]
    for a, b in zip(breaks[:-1], breaks[1:]): X.append(a + (b-a)*t); W.append((b-a)*w)
    return np.concatenate(X), np.concatenate(W)
def reference(dim, h, g, p):
    bx = panels(0.0, h, g); xs, wx = composite(bx); xs = np.concatenate([-xs[::-1], xs]); wx = np.concatenate([wx[::-1], wx])
    kx = h - np.abs(xs)
    ys, wy = composite(panels(g, g+h, g) + list(panels(g+h, g+2*h, h)[1:])); ky = h - np.abs(ys - (g+h))
    if dim == 2:
        D = np.stack(np.meshgrid(xs, ys, indexing='ij'), -1)
        return (law(2, D, p) * np.outer(wx*kx, wy*ky)).sum()
    tot = 0.0
    for i in range(len(xs)):
        D = np.stack(np.meshgrid(np.array([xs[i]]), ys, xs, indexing='ij'), -1)[0]
        tot += wx[i]*kx[i] * (law(3, D, p) * np.outer(wy*ky, wx*kx)).sum()
    return tot
def gauss(dim, h, g, p, n):
    t, w = gl(n)
    grids = np.meshgrid(*([t]*dim), indexing='ij'); W = np.ones_like(grids[0])
    for ws in np.meshgrid(*([w]*dim), indexing='ij'): W = W*ws
    P = np.stack([gg.ravel() for gg in grids], 1)*h; W = W.ravel()*h**dim
    Q = P.copy(); Q[:, 1] -= g + h
    D = P[:, None, :] - Q[None, :, :]
    return (law(dim, D, p) * W[:, None] * W[None, :]).sum()

def table():
    taus = [0.25 * 2 ** (k / 2) for k in range(13)]
    out = {}
    for dim, nmax in ((2, 12), (3, 6)):
        for p in (12, 6):
            M = np.ones((nmax, len(taus)))
            for j, tau in enumerate(taus):
                ref = reference(dim, tau, 1.0, p)
                for n in range(1, nmax + 1):
                    M[n - 1, j] = min(1.0, abs(gauss(dim, tau, 1.0, p, n) / ref - 1))
            out[(dim, p)] = M
    return out

if __name__ == "__main__":
    for (dim, p), M in sorted(table().items()):
        n, m = M.shape
        env = np.array([[max(M[i:, :j + 1].max(), 1e-15) for j in range(m)] for i in range(n)])
        print(f"// dim {dim}, r^-{p}: measured")
        for row in M: print("//   " + " ".join(f"{v:.2e}" for v in row))
        print("{{" + ",\n ".join("{" + ", ".join(f"{up3(v):.2e}" for v in row) + "}" for row in env) + "}},")
