#!/usr/bin/env python3
"""Compares columns of two CSV files with headers, row by row:
|a - b| <= abs + rel * max(|a|, |b|). Exit 0 if all agree, 1 otherwise.

usage: compare_csv.py A.csv B.csv --columns u,P [--rel 1e-8] [--abs 1e-12]
"""
import argparse
import csv
import sys


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"compare_csv: {path} has no data rows")
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("a")
    ap.add_argument("b")
    ap.add_argument("--columns", required=True, help="comma-separated column names")
    ap.add_argument("--rel", type=float, default=1e-8)
    ap.add_argument("--abs", type=float, default=1e-12)
    args = ap.parse_args()
    a, b = read(args.a), read(args.b)
    if len(a) != len(b):
        print(f"row counts differ: {len(a)} vs {len(b)}")
        return 1
    worst = 0.0
    bad = 0
    for i, (ra, rb) in enumerate(zip(a, b)):
        for c in args.columns.split(","):
            if c not in ra or c not in rb:
                print(f"column {c!r} missing")
                return 1
            x, y = float(ra[c]), float(rb[c])
            diff = abs(x - y)
            tol = args.abs + args.rel * max(abs(x), abs(y))
            worst = max(worst, diff / tol if tol > 0 else 0.0)
            if diff > tol:
                bad += 1
                print(f"row {i} column {c}: {x!r} vs {y!r} (|diff| = {diff:.3e} > {tol:.3e})")
    print(f"{len(a)} rows compared, worst |diff|/tolerance = {worst:.3f}")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
