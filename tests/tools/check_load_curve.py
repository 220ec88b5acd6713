#!/usr/bin/env python3
"""Checks a cgcm load curve (load_curve.csv) against an analytic limit.
Exit 0 when within tolerance, 1 otherwise; prints the measured numbers.

  check_load_curve.py hertz   CSV --modulus E* --radius R [--tolerance 0.05] [--u-min U]
      repulsive contact: fits P^(2/3) = k (u - u0) over u >= u-min and
      compares P = k^(3/2) (u - u0)^(3/2) with Hertz, k_H^(3/2) = (4/3) E* sqrt(R)
  pulloff CSV --expected P [--tolerance 0.03] [--retraction]
      minimum of P (over the retraction part: after the largest u) vs the expected value
  value   CSV --u U --expected P [--tolerance 0.01] [--column P]
      the column at the state u (first occurrence) vs the expected value
  balance CSV [--tolerance 0.03]
      |P - P_lower| <= tolerance * max |P| over all states (the interaction's force imbalance)
  jumps   CSV --expected N [--contact-gap G]
      exactly N states marked as jumps; with --contact-gap, the first jump lands
      in contact (gap < G) and the last one out of it (gap > G)
  folds   CSV --expected N [--unstable] [--contact-gap G]
      exactly N fold rows; with --unstable, unstable rows (stable = 0) lie
      between consecutive folds and nowhere else; with --contact-gap, the
      state after the first fold is in contact (gap < G) and the one after
      the last fold out of it (gap > G)
  firstfold CSV --expected U --abs A
      the u of the first fold row (the jump-to-contact of an approach) within A of U
  converged CSV --tolerance T [--summary SUMMARY --stopped]
      every row's residual is <= T (the absolute force tolerance the run
      printed); with --summary, its first line says "completed" (or, with
      --stopped, "stopped: ...")
  stiffness CSV --from U1 --to U2 --expected K [--tolerance 0.02]
      the secant dP/du between U1 and U2 on the approach (up to the largest u,
      P interpolated linearly between states) vs the expected value
  fit     CSV --analytic EXE --gammaL G --gammaW G [--nu V] --expected L [--tolerance 0.02]
      the Maugis-Dugdale lambda of `cgcm-analytic fit` for the curve vs the expected value
  agree   A.csv B.csv --at U [U ...] [--tolerance REL] [--abs ABS]
      P of the last row at each u = U agrees between the two curves
  bodies  BODY_FORCES.csv [--mirror A B --axis x] [--mirror-tolerance REL] [--zero x y]
          [--zero-tolerance REL] [--balance-tolerance REL]
      body_forces.csv: with --mirror, bodies A and B are mirror images in
      the plane normal to --axis (that component opposite, the others equal)
      within REL; --zero components sum to zero over the bodies within
      --zero-tolerance; the other components' sum (the interaction's force
      imbalance) within --balance-tolerance; all relative to the largest
      force of any body in any state
  returns CSV --u U [--abs ABS]
      a there-and-back continuation at u = U: the last row comes back to the
      first row at u = U, |P_last - P_first| <= ABS, and P moved on the way
  branches CSV --at U [U ...] --abs A [--stable-branch]
      Output/Eigenvalues with Loading/Branch Switching: the path (branch = 0)
      has branch points at exactly these u (within A), across each the count
      of negative eigenvalues changes by one; its rows where stable and
      stable_by_folds differ lie between the first and the last branch point
      and there is one at least (the parity of folds misses the branch
      point); each branch k = 1 .. N has rows, ends at a fold within A in u
      of a branch point of the path, and (--stable-branch) one of them has a
      stable row
  criteria CSV [--min-unstable N]
      Output/Eigenvalues: stable (from the eigenvalues) and stable_by_folds
      (the parity of folds) agree on every row that is not a located fold or
      branch point, there is no branch point, and at least N rows are unstable
  cusp    CSV --column C --expected V [--tolerance REL]
      LOCA/Bifurcation/Type = Turning Point: the last row is on the fold
      curve (fold_curve = 1) and is its located extreme (fold = 1), where
      column C (the continuation parameter) is the expected value
  foldsmatch ARC.csv DISP.csv [--tolerance T]
      the folds of an arc-length curve that end stable branches are where the
      displacement-controlled curve jumps (fold rows of both at the same u within T)
"""
import argparse
import csv
import io
import math
import subprocess
import sys


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"{path}: no data")
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def hertz(c, a):
    pts = [(u, p) for u, p in zip(c["u"], c["P"]) if a.u_min <= u <= a.u_max and p > 0]
    if len(pts) < 4:
        print("too few contact points")
        return 1
    xs = [u for u, _ in pts]
    ys = [p ** (2.0 / 3.0) for _, p in pts]
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    k = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
    u0 = mx - my / k
    ratio = k ** 1.5 / ((4.0 / 3.0) * a.modulus * math.sqrt(a.radius))
    print(f"Hertz fit over {n} points: P = {k ** 1.5:.6g} (u - {u0:.3g})^1.5, ratio to Hertz = {ratio:.5f} "
          f"(tolerance {a.tolerance})")
    return 0 if abs(ratio - 1.0) <= a.tolerance else 1


def pulloff(c, a):
    start = 0
    if a.retraction:
        start = max(range(len(c["u"])), key=lambda k: c["u"][k])
    k = min(range(start, len(c["P"])), key=lambda i: c["P"][i])
    ratio = c["P"][k] / a.expected
    print(f"P_min = {c['P'][k]:.6g} at u = {c['u'][k]:.5g}; expected {a.expected:.6g}, ratio {ratio:.5f} "
          f"(tolerance {a.tolerance})")
    return 0 if abs(ratio - 1.0) <= a.tolerance else 1


def value(c, a):
    for u, v in zip(c["u"], c[a.column]):
        if abs(u - a.u) <= 1e-9 * max(1.0, abs(u)):
            ratio = v / a.expected
            print(f"{a.column}(u = {u:g}) = {v:.6g}; expected {a.expected:.6g}, ratio {ratio:.5f} "
                  f"(tolerance {a.tolerance})")
            return 0 if abs(ratio - 1.0) <= a.tolerance else 1
    print(f"no state at u = {a.u}")
    return 1


def fit(a):
    """The Maugis-Dugdale lambda that cgcm-analytic fit finds for the curve."""
    out = subprocess.run([a.analytic, "fit", "--curve", a.csv, "--gammaL", str(a.gammaL), "--gammaW", str(a.gammaW),
                          "--nu", str(a.nu)], check=True, capture_output=True, text=True).stdout
    row = list(csv.DictReader(io.StringIO(out)))[0]
    lam = float(row["lambda"])
    ratio = lam / a.expected
    print(f"best-fit lambda = {lam:.6g} (rms {float(row['rms_relative']):.3g} of P); expected {a.expected:.6g}, "
          f"ratio {ratio:.5f} (tolerance {a.tolerance})")
    return 0 if abs(ratio - 1.0) <= a.tolerance else 1


def stiffness(c, a):
    last = max(range(len(c["u"])), key=lambda k: c["u"][k])
    u, P = c["u"][: last + 1], c["P"][: last + 1]

    def at(x):
        for i in range(len(u) - 1):
            if min(u[i], u[i + 1]) <= x <= max(u[i], u[i + 1]) and u[i] != u[i + 1]:
                return P[i] + (x - u[i]) / (u[i + 1] - u[i]) * (P[i + 1] - P[i])
        sys.exit(f"u = {x} is not on the approach (u from {min(u)} to {max(u)})")

    k = (at(a.to) - at(a.start)) / (a.to - a.start)
    ratio = k / a.expected
    print(f"dP/du on [{a.start:g}, {a.to:g}] = {k:.6g}; expected {a.expected:.6g}, ratio {ratio:.5f} "
          f"(tolerance {a.tolerance})")
    return 0 if abs(ratio - 1.0) <= a.tolerance else 1


def balance(c, a):
    scale = max(abs(p) for p in c["P"])
    worst = max(abs(p - q) for p, q in zip(c["P"], c["P_lower"])) / scale
    print(f"largest |P - P_lower| / max|P| = {worst:.5f} over {len(c['P'])} states (tolerance {a.tolerance})")
    return 0 if worst <= a.tolerance else 1


def jumps(c, a):
    idx = [k for k, j in enumerate(c["jump"]) if j > 0]
    print("jumps at u = " + ", ".join(f"{c['u'][k]:.6g} (P {c['P'][k]:.4g}, gap {c['gap'][k]:.4g})" for k in idx))
    ok = len(idx) == a.expected
    if ok and a.contact_gap is not None and idx:
        ok = c["gap"][idx[0]] < a.contact_gap < c["gap"][idx[-1]]
    return 0 if ok else 1


def firstfold(c, a):
    """u of the first fold (an approach's jump-to-contact) vs the expected value."""
    idx = [k for k, f in enumerate(c["fold"]) if f > 0]
    if not idx:
        print("no fold")
        return 1
    u = c["u"][idx[0]]
    print(f"first fold at u = {u:.9g} (P {c['P'][idx[0]]:.6g}); expected {a.expected:.9g} +- {a.abs:g}")
    return 0 if abs(u - a.expected) <= a.abs else 1


def folds(c, a):
    idx = [k for k, f in enumerate(c["fold"]) if f > 0]
    print("folds at u = " + ", ".join(f"{c['u'][k]:.9g} (P {c['P'][k]:.6g})" for k in idx))
    ok = len(idx) == a.expected
    if ok and a.contact_gap is not None and idx:
        # displacement control: the state after the first fold is in contact, the one after the last is not
        after = [c["gap"][k + 1] for k in (idx[0], idx[-1]) if k + 1 < len(c["gap"])]
        print("gap after the first and the last fold: " + ", ".join(f"{g:.4g}" for g in after))
        ok = len(after) == 2 and after[0] < a.contact_gap < after[1]
    if ok and a.unstable:
        for k, s in enumerate(c["stable"]):
            inside = sum(1 for f in idx if f < k) % 2 == 1
            if (s == 0) != inside and k not in idx:
                print(f"row {k} (u = {c['u'][k]:.9g}) has stable = {s:g} but lies {'between' if inside else 'outside'} folds")
                ok = False
    return 0 if ok else 1


def converged(c, a):
    worst = max(c["residual"])
    print(f"largest residual {worst:.3g} over {len(c['residual'])} rows (tolerance {a.tolerance:.3g})")
    ok = worst <= a.tolerance
    if a.summary:
        with open(a.summary) as f:
            first = f.readline().strip()
        print(f"summary: {first}")
        ok = ok and (first.startswith("stopped:") if a.stopped else first == "completed")
    return 0 if ok else 1


def last_at(c, u):
    k = max((i for i, v in enumerate(c["u"]) if abs(v - u) <= 1e-12 * max(1.0, abs(u))), default=None)
    return None if k is None else c["P"][k]


def agree(a):
    ca, cb = read(a.csv), read(a.other)
    ok = True
    for u in a.at:
        pa, pb = last_at(ca, u), last_at(cb, u)
        if pa is None or pb is None:
            print(f"no state at u = {u} in {'the first' if pa is None else 'the second'} curve")
            ok = False
            continue
        diff = abs(pa - pb)
        good = diff <= a.abs + a.tolerance * max(abs(pa), abs(pb))
        print(f"u = {u}: P = {pa:.12g} and {pb:.12g}, difference {diff:.3g} ({'ok' if good else 'too large'})")
        ok = ok and good
    return 0 if ok else 1


def foldsmatch(a):
    arc, disp = read(a.csv), read(a.other)
    n = len(arc["u"])
    starts = [arc["u"][k] for k in range(1, n) if arc["fold"][k] > 0 and arc["stable"][k - 1] > 0
              and arc["fold"][k - 1] == 0]
    jumps = [disp["u"][k] for k in range(len(disp["u"])) if disp["fold"][k] > 0]
    print("arc-length folds ending stable branches at u = " + ", ".join(f"{u:.9g}" for u in starts))
    print("displacement-control folds (jumps) at u = " + ", ".join(f"{u:.9g}" for u in jumps))
    if len(starts) != len(jumps):
        return 1
    worst = max((abs(x - y) for x, y in zip(starts, jumps)), default=0.0)
    print(f"largest difference {worst:.3g} (tolerance {a.tolerance:.3g})")
    return 0 if worst <= a.tolerance else 1


def returns(c, a):
    first = next(k for k, v in enumerate(c["u"]) if abs(v - a.u) <= 1e-12 * max(1.0, abs(v)))
    changed = max(abs(p - c["P"][first]) for p in c["P"][first:])
    diff = abs(c["P"][-1] - c["P"][first])
    print(f"P at the start (u = {a.u:g}, row {first}) {c['P'][first]:.12g}, at the end "
          f"{c['P'][-1]:.12g}: difference {diff:.3g} (tolerance {a.abs:.3g}); largest change on the way {changed:.3g}")
    return 0 if diff <= a.abs and changed > 100 * a.abs else 1


def bodies(a):
    rows = list(csv.DictReader(open(a.csv)))
    steps = {}
    for r in rows:
        steps.setdefault(int(r["step"]), {})[int(r["body"])] = [float(r[k]) for k in ("Fx", "Fy", "Fz")]
    if not steps:
        print("no rows")
        return 1
    axes = "xyz"
    zero = [axes.index(c) for c in a.zero]
    worstMirror = worstZero = worstBalance = 0.0
    # the largest force of any body in any state: per-state scales vanish where forces change sign
    scale = max(abs(v) for forces in steps.values() for f in forces.values() for v in f)
    if scale == 0.0:
        print("every force is zero")
        return 1
    for step, forces in steps.items():
        if a.mirror:
            fa, fb = forces[a.mirror[0]], forces[a.mirror[1]]
            k = axes.index(a.axis)
            dev = max(abs(fa[i] + fb[i]) if i == k else abs(fa[i] - fb[i]) for i in range(3))
            worstMirror = max(worstMirror, dev / scale)
        for i in range(3):
            total = abs(sum(f[i] for f in forces.values())) / scale
            if i in zero:
                worstZero = max(worstZero, total)
            else:
                worstBalance = max(worstBalance, total)
    ok = True
    if a.mirror:
        good = worstMirror <= a.mirror_tolerance
        print(f"bodies {a.mirror[0]} and {a.mirror[1]} mirrored in {a.axis}: largest deviation {worstMirror:.3g} of the "
              f"largest force (tolerance {a.mirror_tolerance:.3g})")
        ok = ok and good
    if zero:
        good = worstZero <= a.zero_tolerance
        print(f"sum over the bodies of F{','.join(a.zero)}: largest {worstZero:.3g} of the largest force (tolerance "
              f"{a.zero_tolerance:.3g})")
        ok = ok and good
    good = worstBalance <= a.balance_tolerance
    print(f"sum of the other components (the force imbalance): largest {worstBalance:.3g} of the largest force "
          f"(tolerance {a.balance_tolerance:.3g}) over {len(steps)} states")
    return 0 if ok and good else 1


def criteria(c, a):
    rows = range(len(c["u"]))
    plain = [k for k in rows if not c["fold"][k] and not c["branch_point"][k]]
    differ = [k for k in plain if c["stable"][k] != c["stable_by_folds"][k]]
    unstable = sum(1 for k in plain if c["stable"][k] == 0)
    bps = sum(1 for k in rows if c["branch_point"][k])
    print(f"{len(plain)} rows (folds and branch points aside): {unstable} unstable, {len(differ)} where the "
          f"eigenvalues and the parity of folds differ{' (first at row ' + str(differ[0]) + ')' if differ else ''}; "
          f"{bps} branch points")
    return 0 if not differ and bps == 0 and unstable >= a.min_unstable else 1


def cusp(c, a):
    last = len(c["u"]) - 1
    value = c[a.column][last]
    on = c["fold_curve"][last] > 0 and c["fold"][last] > 0
    rel = abs(value - a.expected) / abs(a.expected)
    print(f"last row: {a.column} = {value:.9g} (expected {a.expected:.9g}, relative difference {rel:.2g}), "
          f"u = {c['u'][last]:.9g}, {'the located cusp' if on else 'not a located fold of the fold curve'}; "
          f"{sum(1 for v in c['fold_curve'] if v > 0)} fold-curve rows")
    return 0 if on and rel <= a.tolerance else 1


def branches(c, a):
    path = [k for k, b in enumerate(c["branch"]) if b == 0]
    bps = [k for k in path if c["branch_point"][k] > 0]
    us = [c["u"][k] for k in bps]
    print("branch points of the path at u = " + ", ".join(f"{u:.9g}" for u in us))
    ok = len(us) == len(a.at) and all(abs(u - e) <= a.abs for u, e in zip(us, a.at))
    for k in bps:
        i = path.index(k)
        if 0 < i < len(path) - 1:
            before, after = c["negative_eigenvalues"][path[i - 1]], c["negative_eigenvalues"][path[i + 1]]
            if abs(after - before) != 1:
                print(f"branch point at u = {c['u'][k]:.9g}: negative eigenvalues {before:g} -> {after:g}")
                ok = False
    differ = [k for k in path if c["stable"][k] != c["stable_by_folds"][k] and not c["fold"][k] and not c["branch_point"][k]]
    print(f"rows of the path where stable and stable_by_folds differ: {len(differ)}")
    if not differ or (bps and any(k < bps[0] or k > bps[-1] for k in differ)):
        ok = False
    for b in range(1, len(bps) + 1):
        rows = [k for k, v in enumerate(c["branch"]) if v == b]
        if not rows:
            print(f"branch {b}: no rows")
            ok = False
            continue
        last = rows[-1]
        rejoins = c["fold"][last] > 0 and any(abs(c["u"][last] - u) <= a.abs for u in us)
        stable = sum(1 for k in rows if c["stable"][k] > 0 and not c["fold"][k])
        print(f"branch {b}: {len(rows)} rows, u {min(c['u'][k] for k in rows):.6g} .. {max(c['u'][k] for k in rows):.6g}, "
              f"{stable} stable, ends at u = {c['u'][last]:.9g}{' (a branch point of the path)' if rejoins else ''}")
        ok = ok and rejoins and (stable > 0 or not a.stable_branch)
    return 0 if ok else 1


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    h = sub.add_parser("hertz")
    h.add_argument("csv")
    h.add_argument("--modulus", type=float, required=True)
    h.add_argument("--radius", type=float, required=True)
    h.add_argument("--tolerance", type=float, default=0.05)
    h.add_argument("--u-min", type=float, default=0.0)
    h.add_argument("--u-max", type=float, default=float("inf"))
    p = sub.add_parser("pulloff")
    p.add_argument("csv")
    p.add_argument("--expected", type=float, required=True)
    p.add_argument("--tolerance", type=float, default=0.03)
    p.add_argument("--retraction", action="store_true")
    v = sub.add_parser("value")
    v.add_argument("csv")
    v.add_argument("--u", type=float, required=True)
    v.add_argument("--expected", type=float, required=True)
    v.add_argument("--tolerance", type=float, default=0.01)
    v.add_argument("--column", default="P")
    st = sub.add_parser("stiffness")
    st.add_argument("csv")
    st.add_argument("--from", dest="start", type=float, required=True)
    st.add_argument("--to", type=float, required=True)
    st.add_argument("--expected", type=float, required=True)
    st.add_argument("--tolerance", type=float, default=0.02)
    b = sub.add_parser("balance")
    b.add_argument("csv")
    b.add_argument("--tolerance", type=float, default=0.03)
    j = sub.add_parser("jumps")
    j.add_argument("csv")
    j.add_argument("--expected", type=int, required=True)
    j.add_argument("--contact-gap", type=float)
    f = sub.add_parser("folds")
    f.add_argument("csv")
    f.add_argument("--expected", type=int, required=True)
    f.add_argument("--unstable", action="store_true")
    f.add_argument("--contact-gap", type=float)
    ff = sub.add_parser("firstfold")
    ff.add_argument("csv")
    ff.add_argument("--expected", type=float, required=True)
    ff.add_argument("--abs", type=float, required=True)
    cv = sub.add_parser("converged")
    cv.add_argument("csv")
    cv.add_argument("--tolerance", type=float, required=True)
    cv.add_argument("--summary")
    cv.add_argument("--stopped", action="store_true")
    ag = sub.add_parser("agree")
    ag.add_argument("csv")
    ag.add_argument("other")
    ag.add_argument("--at", type=float, nargs="+", required=True)
    ag.add_argument("--tolerance", type=float, default=1e-6)
    ag.add_argument("--abs", type=float, default=0.0)
    rt = sub.add_parser("returns")
    rt.add_argument("csv")
    rt.add_argument("--u", type=float, required=True)
    rt.add_argument("--abs", type=float, default=2e-10)
    br = sub.add_parser("branches")
    br.add_argument("csv")
    br.add_argument("--at", type=float, nargs="+", required=True)
    br.add_argument("--abs", type=float, required=True)
    br.add_argument("--stable-branch", action="store_true")
    cr = sub.add_parser("criteria")
    cr.add_argument("csv")
    cr.add_argument("--min-unstable", type=int, default=1)
    cu = sub.add_parser("cusp")
    cu.add_argument("csv")
    cu.add_argument("--column", required=True)
    cu.add_argument("--expected", type=float, required=True)
    cu.add_argument("--tolerance", type=float, default=1e-5)
    fm = sub.add_parser("foldsmatch")
    fm.add_argument("csv")
    fm.add_argument("other")
    fm.add_argument("--tolerance", type=float, default=1e-9)
    ft = sub.add_parser("fit")
    ft.add_argument("csv")
    ft.add_argument("--analytic", required=True)
    ft.add_argument("--gammaL", type=float, required=True)
    ft.add_argument("--gammaW", type=float, required=True)
    ft.add_argument("--nu", type=float, default=0.2)
    ft.add_argument("--expected", type=float, required=True)
    ft.add_argument("--tolerance", type=float, default=0.02)
    bd = sub.add_parser("bodies")
    bd.add_argument("csv")
    bd.add_argument("--mirror", type=int, nargs=2)
    bd.add_argument("--axis", default="x", choices=["x", "y", "z"])
    bd.add_argument("--mirror-tolerance", type=float, default=1e-9)
    bd.add_argument("--zero", nargs="*", default=[], choices=["x", "y", "z"])
    bd.add_argument("--zero-tolerance", type=float, default=1e-9)
    bd.add_argument("--balance-tolerance", type=float, default=0.05)
    a = ap.parse_args()
    if a.cmd == "bodies":
        return bodies(a)
    if a.cmd == "agree":
        return agree(a)
    if a.cmd == "foldsmatch":
        return foldsmatch(a)
    if a.cmd == "fit":
        return fit(a)
    c = read(a.csv)
    return {"hertz": hertz, "pulloff": pulloff, "value": value, "stiffness": stiffness, "balance": balance,
            "jumps": jumps, "folds": folds, "firstfold": firstfold,
            "converged": converged, "returns": returns, "branches": branches, "cusp": cusp,
            "criteria": criteria}[a.cmd](c, a)


if __name__ == "__main__":
    sys.exit(main())
