#!/usr/bin/env python3
r"""Self-consistent Lennard-Jones sphere: displacement-controlled pull-off force.

Problem
-------
A rigid paraboloid (radius R) approaches a linear elastic half-space (combined
modulus E*).  The surfaces interact through the Lennard-Jones 9-3 half-space
law in the Derjaguin approximation, i.e. the local normal traction depends only
on the local gap h(r):

    p(h) = (8 w / (3 z0)) [ (z0/h)^9 - (z0/h)^3 ]

Sign convention: p > 0 is a compressive (repulsive) pressure, p < 0 is an
adhesive tension.  p(z0) = 0, the maximum tension is 16 w / (9 sqrt(3) z0) at
h = 3^(1/6) z0, and -int_{z0}^inf p dh = w (work of adhesion).  The gap is

    h(r) = delta + r^2/(2R) + u(r),
    u(r) = (4/(pi E*)) int_0^inf p(s) s/(r+s) K(2 sqrt(r s)/(r+s)) ds,

with u the axisymmetric Boussinesq normal surface displacement (positive away
from the sphere under compression) and K the complete elliptic integral of
the first kind of modulus k.  The total load is
P = 2 pi int_0^inf p r dr (P > 0 compressive).  The only parameter is the
Tabor parameter mu = (R w^2 / (E*^2 z0^3))^(1/3).

Non-dimensional form
--------------------
H = h/z0, rho = r / sqrt(2 R z0), pt = p z0 / w, Delta = delta/z0:

    H(rho) = Delta + rho^2 + c (4/pi) int_0^inf pt(H(s)) s/(rho+s) K(...) ds,
    c = sqrt(2) mu^(3/2),
    pt(H) = (8/3) (H^-9 - H^-3),
    P / (pi w R) = 4 int_0^inf pt rho drho.

Rigid limit (mu -> 0): P/(pi w R) = 2 int_Delta^inf pt dH, minimum -2 at
Delta = 1 (Bradley).  JKR limit (mu -> inf): -1.5.

Discretisation
--------------
* pt(rho) is continuous piecewise linear on a non-uniform node set
  0 = rho_0 < ... < rho_{N-1} = rho_out; nodal values pt(H_i) (collocation
  of the gap equation at the nodes).  Beyond rho_out the pressure is zero in
  the elastic problem; its load (rigid-gap tail) is added analytically.
* Influence matrix C_ij = (4/pi) int phi_j(s) s/(rho_i+s) K ds, phi_j the
  hat functions, integrated element by element: Gauss-Legendre (12 points)
  on regular elements, and on the two elements touching rho_i (where K has
  its logarithmic singularity) the substitution s = rho_i +- L t^4 followed
  by 30-point Gauss-Legendre.  K is evaluated as ellipkm1(k'^2),
  k' = |rho-s|/(rho+s), which is accurate next to the singularity.  Quadrature
  error of C is ~1e-10 relative; the discretisation error is O(h^2)
  (verified on p = exp(-r^2), whose displacement is sqrt(pi) e^{-r^2/2}
  I0(r^2/2)).
* The grid is adapted to the state: a uniform fine band of spacing h_f
  around the edge, [a - 3 wz, a + 3 wz] with h_f = wz / n_band (a = radius
  of maximum tension, H = 3^(1/6); wz = radial width of the region where the
  tension exceeds half its maximum, both taken from a preliminary solution),
  a geometrically graded transition (rate 0.05) to spacing h_c = 0.02 inside
  the contact, and geometric growth outside up to rho_out = 40.
  Refinement level f divides h_f, h_c and the grading rate by f.
* Nonlinear equations: damped Newton with the exact Jacobian on the nodal
  gaps, F_i = H_i - Delta - rho_i^2 - c (C pt(H))_i = 0, closed by one
  parametrising condition: either a prescribed central gap H_0 (Delta
  eliminated), or a prescribed edge radius a, i.e. the linearly interpolated
  gap at rho = a equals 3^(1/6) (Delta unknown).  Near pull-off at large mu
  the edge moves a lot for tiny changes of H_0, so the edge radius is the
  well-conditioned parameter there.

Procedure
---------
1. Branch scan (mu <= 5): pseudo-arclength continuation in (H_0, H_i) on a
   preliminary grid (refined around the JKR pull-off radius estimate), from
   a separated state (H_0 = 2) through snap-in (folds in Delta) into
   contact, until P has risen 0.1 above the smallest load seen; the
   smallest load on the branch is located by Brent minimisation in H_0.
   For mu > 5 the scan is done at mu = 5 (the snap-in part of the branch,
   far above P_min, becomes expensive to resolve) and the pull-off state is
   carried to mu in steps of <= 25 % (profile stretched by mu^(1/2),
   converged with the edge pinned, P minimised over the edge radius).
2. One adapted grid (f = 1) around that state; P minimised over a (Brent).
3. Grid family around the resulting edge: P_min for each refinement level
   (default f = 1, 2, 4) and for a doubled outer radius; Richardson
   extrapolation of the last two levels (the convergence is O(h^2)).
4. Displacement-control check: from the minimum the edge is moved outwards
   (deeper contact, on a grid refined along the whole walk) and Delta must
   decrease monotonically, i.e. the unloading path from contact reaches
   P_min before any fold (jump) in Delta.

Usage
-----
    /usr/bin/python3 tools/lj_sphere_crosscheck.py --mu 1 2 3 5
    /usr/bin/python3 tools/lj_sphere_crosscheck.py --mu 0.3 10 --levels 2 4 8
    /usr/bin/python3 tools/lj_sphere_crosscheck.py --selftest

Prints, per mu, P_min/(pi w R) on each grid (node count N, central gap H0,
Delta and edge radius a at the minimum), the Richardson estimate and the
displacement-control check, then a summary table: one column per
refinement level, the change caused by doubling rho_out (at the first
level), the Richardson value and the run time.  --selftest checks the
traction-law normalisation, the elastic operator against a closed form and
the rigid (Bradley) limit.  Setting OPENBLAS_NUM_THREADS=1 keeps a run on
one core; the default set (mu = 1, 2, 3, 5) takes about a minute there.
"""

import argparse
import sys
import time

import numpy as np
from scipy.linalg import lu_factor, lu_solve
from scipy.optimize import minimize_scalar
from scipy.special import ellipkm1, roots_legendre

# ----------------------------------------------------------------------------
# traction law (pressure in units of w/z0, gap in units of z0)


def ptrac(H):
    """Dimensionless pressure pt(H) = (8/3)(H^-9 - H^-3), compression > 0."""
    i3 = H ** -3
    return (8.0 / 3.0) * (i3 ** 3 - i3)


def dptrac(H):
    """d pt / dH."""
    return (8.0 / 3.0) * (-9.0 * H ** -10 + 3.0 * H ** -4)


# ----------------------------------------------------------------------------
# elastic influence matrix


def _kernel(r, s):
    """s/(r+s) K(k), k = 2 sqrt(r s)/(r+s), via K = ellipkm1(k'^2)."""
    m1 = ((r - s) / (r + s)) ** 2
    return s / (r + s) * ellipkm1(m1)


def influence_matrix(x, ng=12, ns=30, q=4):
    """C with u_i = sum_j C_ij p_j for continuous piecewise-linear p on nodes x.

    u in units of (p-unit * length-unit / E*); includes the 4/pi factor.
    """
    N = len(x)
    L = np.diff(x)
    tg, wg = roots_legendre(ng)
    tg = 0.5 * (tg + 1.0)
    wg = 0.5 * wg
    sig = x[:-1, None] + L[:, None] * tg[None, :]
    wL = L[:, None] * wg[None, :]
    wR_ = wL * tg[None, :]          # weight times right hat function
    wL_ = wL * (1.0 - tg[None, :])  # weight times left hat function
    C = np.zeros((N, N))
    for i in range(N):
        g = _kernel(x[i], sig)
        C[i, :-1] += (g * wL_).sum(1)
        C[i, 1:] += (g * wR_).sum(1)
    # elements with the collocation point at an end: replace by singular rule
    ts, ws = roots_legendre(ns)
    ts = 0.5 * (ts + 1.0)
    ws = 0.5 * ws
    tq = ts ** q
    jac = q * ts ** (q - 1) * ws
    for i in range(N):
        for e in (i - 1, i):
            if e < 0 or e > N - 2:
                continue
            g = _kernel(x[i], sig[e])
            C[i, e] -= (g * wL_[e]).sum()
            C[i, e + 1] -= (g * wR_[e]).sum()
            if e == i:
                s = x[e] + L[e] * tq
                fR = tq
            else:
                s = x[e + 1] - L[e] * tq
                fR = 1.0 - tq
            g = _kernel(x[i], s) * L[e] * jac
            C[i, e] += (g * (1.0 - fR)).sum()
            C[i, e + 1] += (g * fR).sum()
    return C * (4.0 / np.pi)


def load_weights(x):
    """w with int_0^x[-1] p rho drho = w . p for piecewise-linear p."""
    a, b = x[:-1], x[1:]
    L = b - a
    w = np.zeros(len(x))
    w[:-1] += L / 6.0 * (2 * a + b)
    w[1:] += L / 6.0 * (a + 2 * b)
    return w


# ----------------------------------------------------------------------------
# grids


def uniform_grid(h, rho_u, rho_out, growth=0.05):
    """Uniform spacing h on [0, rho_u], then geometric growth to rho_out."""
    x = [0.0]
    while x[-1] < rho_out:
        r = x[-1]
        step = h if r < rho_u else max(h, growth * (r - rho_u) + h)
        x.append(r + step)
    x = np.array(x)
    x[-1] = rho_out if x[-1] > rho_out else x[-1]
    return x


def adapted_grid(band_lo, band_hi, h_f, h_c, rho_out, growth=0.05, f=1):
    """Fine band [band_lo, band_hi] (spacing h_f/f), graded (rate growth/f) to
    spacing h_c/f inside, and graded geometric growth outside up to rho_out."""
    h_f, h_c, g = h_f / f, h_c / f, growth / f
    band_lo = max(band_lo, 0.0)

    def spacing(r):
        d = max(band_lo - r, r - band_hi, 0.0)
        h = h_f + g * d
        if r < band_lo:
            return min(h, h_c)
        return min(h, max(h_c, g * r))

    x = [0.0]
    while x[-1] < rho_out:
        x.append(x[-1] + spacing(x[-1]))
    x = np.array(x)
    x[-1] = min(x[-1], rho_out)
    if x[-1] - x[-2] < 0.3 * (x[-2] - x[-3]):
        x = np.delete(x, -2)
    return x


# ----------------------------------------------------------------------------
# solver on a fixed grid


class Solver:
    def __init__(self, mu, x):
        self.mu = mu
        self.x = x
        self.c = np.sqrt(2.0) * mu ** 1.5   # C carries the 4/pi
        self.C = influence_matrix(x)
        self.Cr = self.C[1:] - self.C[0][None, :]    # relative to the centre
        self.absCr = np.abs(self.Cr)
        self.wP = load_weights(x)
        self.rho2 = x[1:] ** 2

    def residual(self, H0, Hr):
        H = np.concatenate(([H0], Hr))
        return Hr - H0 - self.rho2 - self.c * (self.Cr @ ptrac(H))

    def solve(self, H0, Hr_guess, tol=1e-13, maxit=40):
        """Newton for the gaps H_1..H_{N-1} at prescribed central gap H0.

        Converged when max|F| < tol * (1 + c max_i sum_j |Cr_ij p_j|), i.e.
        relative to the size of the elastic term (round-off floor)."""
        Hr = np.maximum(Hr_guess.copy(), 0.5)

        def res(Hr):
            H = np.concatenate(([H0], Hr))
            p = ptrac(H)
            F = Hr - H0 - self.rho2 - self.c * (self.Cr @ p)
            scale = 1.0 + self.c * (self.absCr @ np.abs(p)).max()
            return F, np.abs(F).max() / scale

        F, nF = res(Hr)
        for it in range(maxit):
            if nF < tol:
                return Hr, it
            H = np.concatenate(([H0], Hr))
            J = -self.c * self.Cr[:, 1:] * dptrac(H[1:])[None, :]
            J[np.diag_indices_from(J)] += 1.0
            dH = -lu_solve(lu_factor(J, check_finite=False), F,
                           check_finite=False)
            # keep gaps positive, then backtrack on the residual norm
            alpha = 1.0
            neg = dH < 0
            if np.any(neg):
                alpha = min(1.0, 0.5 * np.min(Hr[neg] / -dH[neg]))
            for _ in range(40):
                Hn = Hr + alpha * dH
                Fn, nFn = res(Hn)
                if nFn < nF or nFn < tol:
                    break
                alpha *= 0.5
            else:
                if nF < 1e3 * tol:      # stalled at the round-off level
                    return Hr, it
                raise RuntimeError("line search failed")
            Hr, F, nF = Hn, Fn, nFn
        if nF < 1e3 * tol:
            return Hr, maxit
        raise RuntimeError("Newton did not converge (|F| = %g)" % nF)

    def solve_edge(self, a, H_guess, tol=1e-13, maxit=40):
        """Newton with the edge pinned instead of the central gap: unknowns
        all nodal gaps H_0..H_{N-1} and Delta, with the extra condition that
        the (linearly interpolated) gap at radius a equals H_TMAX.
        Returns the full gap vector."""
        x = self.x
        k = np.searchsorted(x, a) - 1
        th = (a - x[k]) / (x[k + 1] - x[k])
        N = len(x)
        H = np.maximum(H_guess.copy(), 0.5)
        absC = np.abs(self.C)

        def res(H, D):
            p = ptrac(H)
            F = np.empty(N + 1)
            F[:N] = H - D - x ** 2 - self.c * (self.C @ p)
            F[N] = (1 - th) * H[k] + th * H[k + 1] - H_TMAX
            scale = 1.0 + self.c * (absC @ np.abs(p)).max()
            return F, np.abs(F).max() / scale

        D = H[0] - self.c * (self.C[0] @ ptrac(H))
        F, nF = res(H, D)
        for it in range(maxit):
            if nF < tol:
                return H, it
            J = np.zeros((N + 1, N + 1))
            J[:N, :N] = -self.c * self.C * dptrac(H)[None, :]
            J[np.arange(N), np.arange(N)] += 1.0
            J[:N, N] = -1.0
            J[N, k], J[N, k + 1] = 1 - th, th
            dz = -lu_solve(lu_factor(J, check_finite=False), F,
                           check_finite=False)
            dH, dD = dz[:N], dz[N]
            alpha = 1.0
            neg = dH < 0
            if np.any(neg):
                alpha = min(1.0, 0.5 * np.min(H[neg] / -dH[neg]))
            for _ in range(40):
                Hn, Dn = H + alpha * dH, D + alpha * dD
                Fn, nFn = res(Hn, Dn)
                if nFn < nF or nFn < tol:
                    break
                alpha *= 0.5
            else:
                if nF < 1e3 * tol:
                    return H, it
                raise RuntimeError("line search failed (edge control)")
            H, D, F, nF = Hn, Dn, Fn, nFn
        if nF < 1e3 * tol:
            return H, maxit
        raise RuntimeError("Newton (edge control) did not converge")

    def state(self, H0, Hr):
        """Load P/(pi w R) (with analytic tail), Delta, full gap vector."""
        H = np.concatenate(([H0], Hr))
        p = ptrac(H)
        Delta = H0 - self.c * (self.C[0] @ p)
        X = H[-1]   # beyond rho_out: H = X + rho^2 - rho_out^2 (rigid)
        tail = (16.0 / 3.0) * (X ** -8 / 8.0 - X ** -2 / 2.0)
        return 4.0 * (self.wP @ p) + tail, Delta, H


# ----------------------------------------------------------------------------
# branch scan and minimisation


def scan_branch(sol, H0_start=2.0, H0_stop=0.9, rise=0.1, dP_max=0.04,
                verbose=False):
    """Pseudo-arclength continuation of the branch from a separated state
    (central gap H0_start) into contact, unknowns y = (H0, H_1..H_{N-1}).

    Arclength metric: ds^2 = dH0^2 + mean(dH_i^2).  Stops when H0 < H0_stop
    or when P has risen by `rise` above the smallest load seen so far.
    Returns a list of (H0, P, Delta, Hr)."""
    x = sol.x
    n = len(x) - 1
    wt = np.full(n + 1, 1.0 / n)
    wt[0] = 1.0
    out = []
    for H0 in (H0_start, H0_start - 0.02):
        Hr, _ = sol.solve(H0, H0 + x[1:] ** 2)
        P, D, _ = sol.state(H0, Hr)
        out.append((H0, P, D, Hr))
    ds = 0.02
    Pmin = min(o[1] for o in out)
    while True:
        (a0, _, _, ha), (b0, Pb, _, hb) = out[-2], out[-1]
        ya = np.concatenate(([a0], ha))
        yb = np.concatenate(([b0], hb))
        t = yb - ya
        sab = np.sqrt(np.sum(wt * t * t))
        t /= sab
        y = yb + ds * t
        if len(out) > 2:
            # quadratic predictor through the last three states
            yc = np.concatenate(([out[-3][0]], out[-3][3]))
            d = ya - yc
            sca = np.sqrt(np.sum(wt * d * d))
            s0, s1, s2, s3 = -sab - sca, -sab, 0.0, ds
            y = (yc * (s3 - s1) * (s3 - s2) / ((s0 - s1) * (s0 - s2))
                 + ya * (s3 - s0) * (s3 - s2) / ((s1 - s0) * (s1 - s2))
                 + yb * (s3 - s0) * (s3 - s1) / ((s2 - s0) * (s2 - s1)))
        ok = False
        for it in range(12):
            H = y.copy()
            if np.any(H <= 0.3):
                break
            F = np.empty(n + 1)
            F[:n] = sol.residual(H[0], H[1:])
            F[n] = np.sum(wt * t * (y - yb)) - ds
            if np.abs(F).max() < 1e-9:
                ok = True
                break
            dp = dptrac(H)
            J = np.empty((n + 1, n + 1))
            J[:n, 1:] = -sol.c * sol.Cr[:, 1:] * dp[None, 1:]
            J[np.arange(n), np.arange(1, n + 1)] += 1.0
            J[:n, 0] = -1.0 - sol.c * sol.Cr[:, 0] * dp[0]
            J[n, :] = wt * t
            y = y - np.linalg.solve(J, F)
        if ok:
            P, D, _ = sol.state(y[0], y[1:])
            ok = abs(P - Pb) < dP_max
        if not ok:
            ds *= 0.5
            if ds < 1e-10:
                raise RuntimeError("arclength continuation stalled at "
                                   "H0 = %.10f" % b0)
            continue
        out.append((y[0], P, D, y[1:].copy()))
        if verbose:
            print("  scan H0=%.10f P=%.6f Delta=%.6f it=%d ds=%.2e"
                  % (y[0], P, D, it, ds))
        Pmin = min(Pmin, P)
        if y[0] < H0_stop or (P > Pmin + rise):
            return out
        # step control: aim at ~4 Newton iterations and |dP| ~ dP_max/2
        ds *= min(1.5, 0.5 * dP_max / max(abs(P - Pb), 1e-12),
                  max(0.5, 4.0 / max(it, 1)))


def solve_from(sol, H0, cache):
    """Solve at H0 starting from the nearest cached state (list of (H0, Hr));
    if Newton fails, approach H0 from there by bisected continuation steps.
    Every converged state is appended to the cache."""
    h, Hr = min(cache, key=lambda t: abs(t[0] - H0))
    step = H0 - h
    while True:
        tgt = H0 if abs(H0 - h) <= abs(step) else h + step
        try:
            Hn, _ = sol.solve(tgt, Hr, maxit=30)
        except RuntimeError:
            step *= 0.5
            if abs(step) < 1e-14:
                raise
            continue
        h, Hr = tgt, Hn
        cache.append((h, Hr))
        if h == H0:
            return Hr


def minimise(sol, lo, hi, seeds, xatol=1e-11):
    """Bounded Brent minimisation of P(H0) on [lo, hi].

    seeds: list of (H0, Hr) on sol's grid used as Newton starting points.
    """
    cache = list(seeds)

    def f(H0):
        Hr = solve_from(sol, H0, cache)
        return sol.state(H0, Hr)[0]

    res = minimize_scalar(f, bounds=(lo, hi), method="bounded",
                          options={"xatol": xatol, "maxiter": 200})
    H0 = res.x
    Hr = solve_from(sol, H0, cache)
    P, D, H = sol.state(H0, Hr)
    return P, H0, D, H


H_TMAX = 3.0 ** (1.0 / 6.0)   # gap of maximum tension


def edge_radius(x, H):
    """Edge radius a: first radius where the gap reaches H_TMAX, i.e. the
    position of the maximum adhesive tension (the crack tip for large mu)."""
    i = np.nonzero(H >= H_TMAX)[0][0]
    if i == 0:
        return 0.0
    return x[i - 1] + (H_TMAX - H[i - 1]) / (H[i] - H[i - 1]) * (x[i] - x[i - 1])


def edge_band(x, H):
    """Edge radius a and cohesive-zone width wz (radial extent of the region
    where the tension exceeds half its maximum)."""
    p = ptrac(H)
    strong = np.nonzero(p < 0.5 * p.min())[0]
    wz = x[strong[-1]] - x[strong[0]]
    return edge_radius(x, H), max(wz, 1e-3)


class EdgeBranch:
    """States of one grid/mu parametrised by the edge radius a, with a cache
    of converged states used as Newton starting points; a target edge is
    approached from the nearest cached one by bisected steps if needed."""

    def __init__(self, sol, a0, H0vec):
        self.sol = sol
        self.cache = [(a0, H0vec)]

    def solve(self, ae):
        h, Hs = min(self.cache, key=lambda t: abs(t[0] - ae))
        step = ae - h
        while True:
            tgt = ae if abs(ae - h) <= abs(step) else h + step
            try:
                Hn, _ = self.sol.solve_edge(tgt, Hs, maxit=30)
            except RuntimeError:
                step *= 0.5
                if abs(step) < 1e-10:
                    raise
                continue
            h, Hs = tgt, Hn
            self.cache.append((h, Hs))
            if h == ae:
                return Hs

    def load(self, ae):
        return 4.0 * (self.sol.wP @ ptrac(self.solve(ae)))

    def minimise(self, lo, hi, xatol=1e-8):
        res = minimize_scalar(self.load, bounds=(lo, hi), method="bounded",
                              options={"xatol": xatol, "maxiter": 200})
        if min(res.x - lo, hi - res.x) < 1e-3 * (hi - lo):
            raise RuntimeError("minimum at the end of the edge bracket")
        H = self.solve(res.x)
        P, D, _ = self.sol.state(H[0], H[1:])
        return res.x, H, P, D


def _scan_start(mu, rho_out, verbose):
    """Preliminary grid refined around the JKR pull-off radius estimate,
    arclength scan of the branch from separation into contact, and Brent
    minimisation of P(H0) around the smallest load seen."""
    a_jkr = (9 * np.pi / 8 / 2 ** 1.5) ** (1 / 3) * mu ** 0.5
    h_pre = min(0.01, 0.03 / mu)
    x = adapted_grid(0.5 * a_jkr, 1.25 * a_jkr, h_pre, 0.01, rho_out)
    sol = Solver(mu, x)
    br = scan_branch(sol, verbose=verbose)
    Ps = np.array([b[1] for b in br])
    k = int(np.argmin(Ps))
    if k == 0 or k == len(br) - 1:
        raise RuntimeError("minimum not bracketed by the scan")
    lo, hi = br[k + 1][0], br[k - 1][0]
    if not lo < br[k][0] < hi:
        raise RuntimeError("H0 not monotone around the minimum")
    P, H0, D, H = minimise(sol, lo, hi, [(b[0], b[3]) for b in br[k - 1:k + 2]])
    return x, H, P, D


def _mu_step(mu_a, mu_b, x_a, H_a, n_band, h_c, rho_out):
    """Carry the pull-off state from mu_a to mu_b on the contact side of the
    branch: stretch the profile radially by (mu_b/mu_a)^(1/2), re-grid,
    converge with the edge pinned (sub-stepping in mu if needed) and
    minimise P over the edge radius."""
    s = np.sqrt(mu_b / mu_a)
    a, wz = edge_band(x_a, H_a)
    a_b = s * a
    wz_b = wz * (mu_a / mu_b) ** 1.2
    lo, hi = 0.95 * a_b, 1.05 * a_b
    x = adapted_grid(lo - 3 * wz_b, hi + 3 * wz_b, wz_b / n_band, h_c,
                     rho_out)
    sol = Solver(mu_a, x)
    H = np.interp(x / s, x_a, H_a)
    m, dm = mu_a, mu_b - mu_a
    while m < mu_b:
        mt = min(m + dm, mu_b)
        sol.c = np.sqrt(2.0) * mt ** 1.5
        try:
            Hn, _ = sol.solve_edge(a_b, H, maxit=30)
        except RuntimeError:
            dm *= 0.5
            if dm < 1e-6:
                raise
            continue
        m, H = mt, Hn
    sol.mu = mu_b
    a_min, H, P, D = EdgeBranch(sol, a_b, H).minimise(lo, hi)
    return x, H, P, D


def _refine(mu, x_prev, H_prev, a_prev, da, band, h_f, h_c, ro, f):
    """Minimise P over the edge radius in [a_prev - da, a_prev + da] on the
    adapted grid (band, h_f, h_c, ro, f), starting from a state interpolated
    from a previous grid."""
    xg = adapted_grid(band[0], band[1], h_f, h_c, ro, f=f)
    sg = Solver(mu, xg)
    guess = np.interp(xg, x_prev, H_prev, right=np.nan)
    bad = np.isnan(guess)
    guess[bad] = H_prev[-1] + xg[bad] ** 2 - x_prev[-1] ** 2
    H, _ = sg.solve_edge(a_prev, guess)
    br = EdgeBranch(sg, a_prev, H)
    a, H, P, D = br.minimise(a_prev - da, a_prev + da)
    return xg, sg, br, a, H, P, D


def contact_side_check(mu, x0, H0vec, a_min, wz, h_f, h_c, rho_out,
                       rise=0.1, amax=1.15, nstep=15):
    """From the minimum, walk the edge outwards (deeper contact) until P has
    risen by `rise` or the edge reached amax * a_min, on a grid whose fine
    band covers the whole walk.  True if Delta decreases monotonically on
    the way, i.e. under displacement control the unloading path reaches
    the minimum before any fold (jump) in Delta."""
    x = adapted_grid(a_min - 3 * wz, amax * a_min + 3 * wz, h_f, h_c, rho_out)
    sol = Solver(mu, x)
    H = sol.solve_edge(a_min, np.interp(x, x0, H0vec))[0]
    br = EdgeBranch(sol, a_min, H)
    P_min = sol.state(H[0], H[1:])[0]
    Ds, P = [], P_min
    for a in np.linspace(a_min, amax * a_min, nstep + 1):
        H = br.solve(a)
        P, D, _ = sol.state(H[0], H[1:])
        Ds.append(D)
        if P > P_min + rise:
            break
    return bool(np.all(np.diff(Ds) < 0))


def pulloff(mu, levels=(1, 2, 4), rho_out=40.0, n_band=40, h_c=0.02,
            mu_scan_max=5.0, verbose=False):
    t0 = time.time()
    rows = []
    if mu <= mu_scan_max:
        # 1. branch scan on a preliminary grid
        x, H, P, D = _scan_start(mu, rho_out, verbose)
    else:
        # 1'. branch scan at mu_scan_max, then continuation in mu of the
        #     pull-off state (the snap-in part of the branch, far above
        #     P_min, becomes expensive to resolve at large mu)
        x, H, P, D = _scan_start(mu_scan_max, rho_out, verbose)
        nstep = int(np.ceil(np.log(mu / mu_scan_max) / np.log(1.25)))
        mus = mu_scan_max * (mu / mu_scan_max) ** (np.arange(nstep + 1) / nstep)
        for ma, mb in zip(mus[:-1], mus[1:]):
            x, H, P, D = _mu_step(ma, mb, x, H, n_band, h_c, rho_out)
            if verbose:
                print("  mu %.4g -> %.4g: N=%d P=%.6f (%.0f s)"
                      % (ma, mb, len(x), P, time.time() - t0))
    rows.append(dict(level="pre", N=len(x), P=P, H0=H[0], D=D,
                     a=edge_radius(x, H)))
    if verbose:
        print("  preliminary: N=%d P=%.6f H0=%.8f (%.0f s)"
              % (len(x), P, H[0], time.time() - t0))

    def band_of(x, H):
        a, wz = edge_band(x, H)
        return a, wz, (a - 3 * wz, a + 3 * wz), wz / n_band

    # 2. one adapted pass to locate the edge accurately; fold check
    a, wz, band, h_f = band_of(x, H)
    da = min(wz, 0.3 * a)
    x, sol, br, a, H, P, D = _refine(mu, x, H, a, da, band, h_f, h_c,
                                     rho_out, 1)
    # 3. grid family around that edge: refinement levels and outer radius
    a, wz, band, h_f = band_of(x, H)
    fold_free = contact_side_check(mu, x, H, a, wz, h_f, h_c, rho_out)
    da = 0.5 * min(wz, 0.3 * a)
    x_ref, H_ref, a_ref = x, H, a
    results = {}
    for ro, f in [(rho_out, f) for f in levels] + [(2 * rho_out, levels[0])]:
        xg, _, _, ag, Hg, P, D = _refine(mu, x_ref, H_ref, a_ref, da, band,
                                         h_f, h_c, ro, f)
        results[(ro, f)] = P
        rows.append(dict(level="f=%d ro=%g" % (f, ro), N=len(xg), P=P,
                         H0=Hg[0], D=D, a=ag))
        if verbose:
            print("  f=%d rho_out=%g N=%d P=%.8f H0=%.10f a=%.6f (%.0f s)"
                  % (f, ro, len(xg), P, Hg[0], ag, time.time() - t0))
    fl = levels[-1]
    P_fine = results[(rho_out, fl)]
    rich = None
    if len(levels) >= 2:
        P_c = results[(rho_out, levels[-2])]
        ratio = fl / levels[-2]
        rich = P_fine + (P_fine - P_c) / (ratio ** 2 - 1)
    return dict(mu=mu, rows=rows, results=results, rich=rich,
                fold_free=fold_free, band=band, h_f=h_f,
                time=time.time() - t0)


def selftest():
    """Checks of the ingredients: traction-law normalisation, the discrete
    Boussinesq operator against a closed form, and the rigid (Bradley)
    limit of the whole procedure."""
    from scipy.integrate import quad
    from scipy.special import ive
    W = quad(ptrac, 1.0, np.inf)[0]
    tmax = -ptrac(H_TMAX)
    print("traction law: int_z0^inf p dh = %.12f w (expect -1), max tension "
          "%.12f w/z0 (expect 16/(9 sqrt 3) = %.12f)"
          % (W, tmax, 16 / (9 * np.sqrt(3))))
    print("Boussinesq operator, p = exp(-r^2), u E* = sqrt(pi) exp(-r^2/2) "
          "I0(r^2/2):")
    for h in (0.1, 0.05, 0.025):
        x = uniform_grid(h, 6.0, 60.0)
        u = influence_matrix(x) @ np.exp(-x ** 2)
        ue = np.sqrt(np.pi) * ive(0, x ** 2 / 2)
        m = x < 10
        print("  h = %-6g N = %4d  max|u - u_exact| (r < 10) = %.2e"
              % (h, len(x), np.abs(u - ue)[m].max()))
    r = pulloff(1e-4, levels=(1, 2, 4))
    print("rigid limit mu = 1e-4: P_min/(pi w R) = %.7f (f=1,2,4: %s), "
          "Bradley -2" % (r["rich"], ", ".join(
              "%.7f" % r["results"][(40.0, f)] for f in (1, 2, 4))))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    ap.add_argument("--mu", type=float, nargs="+", default=[1, 2, 3, 5])
    ap.add_argument("--levels", type=int, nargs="+", default=[1, 2, 4],
                    help="grid refinement factors (spacings divided by f)")
    ap.add_argument("--rho-out", type=float, default=40.0,
                    help="outer radius in units of sqrt(2 R z0)")
    ap.add_argument("--n-band", type=int, default=40,
                    help="nodes across the cohesive zone at level 1")
    ap.add_argument("--verbose", action="store_true")
    ap.add_argument("--selftest", action="store_true",
                    help="check the traction law, the elastic operator and "
                         "the rigid limit, then exit")
    args = ap.parse_args(argv)
    if args.selftest:
        selftest()
        return 0

    summary = []
    for mu in args.mu:
        r = pulloff(mu, levels=tuple(args.levels), rho_out=args.rho_out,
                    n_band=args.n_band, verbose=args.verbose)
        summary.append(r)
        print("\nmu = %g   (fine band [%.4f, %.4f], h_f = %.2e at f=1; "
              "%.0f s)" % (mu, r["band"][0], r["band"][1], r["h_f"], r["time"]))
        print("  %-16s %6s %14s %14s %12s %9s" %
              ("grid", "N", "P_min/(piwR)", "H0", "Delta", "a"))
        for row in r["rows"]:
            print("  %-16s %6d %14.8f %14.10f %12.6f %9.5f" %
                  (row["level"], row["N"], row["P"], row["H0"], row["D"],
                   row["a"]))
        if r["rich"] is not None:
            print("  Richardson (last two levels, O(h^2)): %.8f" % r["rich"])
        print("  Delta monotone from contact side to the minimum: %s"
              % r["fold_free"])

    lv = args.levels
    print("\nSummary: P_min/(pi w R)")
    hdr = "  %6s" % "mu" + "".join(" %12s" % ("f=%d" % f) for f in lv)
    hdr += " %12s %12s %9s" % ("d(2x rho_o)", "Richardson", "time/s")
    print(hdr)
    for r in summary:
        line = "  %6g" % r["mu"]
        for f in lv:
            line += " %12.7f" % r["results"][(args.rho_out, f)]
        line += " %12.1e" % (r["results"][(2 * args.rho_out, lv[0])]
                             - r["results"][(args.rho_out, lv[0])])
        line += " %12s" % ("%.7f" % r["rich"] if r["rich"] is not None else "-")
        line += " %9.0f" % r["time"]
        print(line)
    return 0


if __name__ == "__main__":
    sys.exit(main())
