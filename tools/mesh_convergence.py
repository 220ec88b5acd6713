#!/usr/bin/env python3
"""Mesh convergence of the paper's key numbers: the decks of Figs. 9 and 11
(inputs/paper/fig6-gammaW-200.xml, fig6-gammaW-20.xml) on mesh levels 0-3
(each level halves every cell). Per level: P_min and its u, the load and the
contact radius at the Fig. 9 state (u = 0.043), u and the contact radius
where P crosses zero in contact (the Fig. 11 state), the jump-in and jump-off
points, the run time. With three or more levels, the observed order of
convergence p = log2(|q_{l-1} - q_{l-2}| / |q_l - q_{l-1}|) of each number
on the three finest.

A level whose summary.txt says "completed" is not run again (delete its
folder to redo it); the tables (table.csv, orders.csv) hold every level of
every deck found in the output folder.

    mesh_convergence.py --build build --levels 0 1 2 3 --output output/validation/mesh-convergence
"""
import argparse
import csv
import math
import os
import re
import subprocess
import sys
import time

DECKS = {"gammaW-200": "inputs/paper/fig6-gammaW-200.xml", "gammaW-20": "inputs/paper/fig6-gammaW-20.xml"}


def read_curve(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def approach(c):
    """Rows up to the largest u (the approach)."""
    end = max(range(len(c["u"])), key=lambda k: c["u"][k])
    return range(end + 1)


def at_u(c, rows, target, key):
    rows = [k for k in rows if c["stable"][k] > 0.5]
    for k0, k1 in zip(rows, rows[1:]):
        if c["u"][k0] <= target <= c["u"][k1] and c["u"][k1] > c["u"][k0]:
            t = (target - c["u"][k0]) / (c["u"][k1] - c["u"][k0])
            return c[key][k0] + t * (c[key][k1] - c[key][k0])
    return float("nan")


def zero_load(c, rows):
    """(u, contact radius) where P crosses zero upwards in contact."""
    rows = [k for k in rows if c["stable"][k] > 0.5 and c["contact_radius"][k] > 0]
    for k0, k1 in zip(rows, rows[1:]):
        if c["P"][k0] <= 0.0 < c["P"][k1] and c["u"][k1] > c["u"][k0]:
            t = -c["P"][k0] / (c["P"][k1] - c["P"][k0])
            return (c["u"][k0] + t * (c["u"][k1] - c["u"][k0]),
                    c["contact_radius"][k0] + t * (c["contact_radius"][k1] - c["contact_radius"][k0]))
    return float("nan"), float("nan")


def summary_numbers(path):
    text = open(path).read()
    out = {"status": text.splitlines()[0].strip() if text else "missing"}
    m = re.search(r"^P_min = (\S+) at u = (\S+)", text, re.M)
    if m:
        out["P_min"], out["u_P_min"] = float(m.group(1)), float(m.group(2))
    jumps = [float(v) for v in re.findall(r"^jump under displacement control at u = (\S+):", text, re.M)]
    # the first jump of the approach is the jump-in; the last of the approach pass the jump-off
    out["jump_in_u"] = jumps[0] if jumps else float("nan")
    out["jump_off_u"] = min(jumps) if len(jumps) > 1 else float("nan")
    m = re.search(r"wall time of the path (\S+) s", text)
    out["seconds"] = float(m.group(1)) if m else float("nan")
    m = re.search(r"states = (\d+)", text)
    out["states"] = int(m.group(1)) if m else 0
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", default="build")
    ap.add_argument("--levels", type=int, nargs="+", default=[0, 1, 2, 3])
    ap.add_argument("--decks", nargs="+", default=list(DECKS), choices=list(DECKS))
    ap.add_argument("--output", default="output/validation/mesh-convergence")
    a = ap.parse_args()
    os.makedirs(a.output, exist_ok=True)
    for name in a.decks:
        for level in a.levels:
            folder = os.path.join(a.output, f"{name}-level{level}")
            summary = os.path.join(folder, "summary.txt")
            done = os.path.exists(summary) and open(summary).readline().strip() == "completed"
            if not done:
                t0 = time.time()
                with open(folder + ".log", "w") as log:
                    subprocess.run([os.path.join(a.build, "bin", "cgcm"), DECKS[name], f"Output/Directory={folder}",
                                    f"Geometry/Mesh Refinement={level}", "Output/Exodus=false",
                                    "Output/Print Steps=false"], stdout=log, stderr=subprocess.STDOUT)
                print(f"{name} level {level}: ran in {time.time() - t0:.0f} s", flush=True)
    # the table holds every level run so far, of every deck
    table = []
    for name in DECKS:
        for level in range(7):
            folder = os.path.join(a.output, f"{name}-level{level}")
            summary = os.path.join(folder, "summary.txt")
            if not os.path.exists(summary):
                continue
            row = {"deck": name, "level": level}
            row.update(summary_numbers(summary))
            if os.path.exists(os.path.join(folder, "load_curve.csv")):
                c = read_curve(os.path.join(folder, "load_curve.csv"))
                rows = approach(c)
                row["P_at_0.043"] = at_u(c, rows, 0.043, "P")
                row["a_at_0.043"] = at_u(c, rows, 0.043, "contact_radius")
                row["u_P0"], row["a_P0"] = zero_load(c, rows)
            table.append(row)
    keys = ["deck", "level", "status", "states", "seconds", "P_min", "u_P_min", "P_at_0.043", "a_at_0.043", "u_P0",
            "a_P0", "jump_in_u", "jump_off_u"]
    with open(os.path.join(a.output, "table.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys, extrasaction="ignore")
        w.writeheader()
        for r in table:
            w.writerow({k: (f"{r[k]:.6g}" if isinstance(r.get(k), float) else r.get(k, "")) for k in keys})
    # observed order on the three finest levels of each deck
    orders = []
    for name in DECKS:
        rows = sorted([r for r in table if r["deck"] == name and r.get("status") == "completed"],
                      key=lambda r: r["level"])
        if len(rows) < 3:
            continue
        q0, q1, q2 = rows[-3:]
        for key in keys[5:]:
            v = [q.get(key, float("nan")) for q in (q0, q1, q2)]
            if any(not isinstance(x, float) or math.isnan(x) for x in v):
                continue
            d1, d2 = abs(v[1] - v[0]), abs(v[2] - v[1])
            p = math.log2(d1 / d2) if d1 > 0 and d2 > 0 else float("nan")
            orders.append({"deck": name, "quantity": key, "levels": f"{q0['level']}-{q2['level']}",
                           "finest": v[2], "change_last": v[2] - v[1], "order": p})
    with open(os.path.join(a.output, "orders.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=["deck", "quantity", "levels", "finest", "change_last", "order"])
        w.writeheader()
        for o in orders:
            w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in o.items()})
    for r in table:
        print(", ".join(f"{k} = {r[k]:.6g}" if isinstance(r.get(k), float) else f"{k} = {r.get(k, '')}" for k in keys))
    for o in orders:
        print(f"{o['deck']} {o['quantity']}: finest {o['finest']:.6g}, last change {o['change_last']:.3g}, "
              f"observed order {o['order']:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
