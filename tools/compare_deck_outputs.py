#!/usr/bin/env python3
"""Runs decks with two cgcm binaries and compares their load curves.

A change that must keep behaviour (a refactoring) is checked by running every
deck of inputs/ with the binary before the change (--reference) and after it
(--candidate), and comparing load_curve.csv column by column. With a direct
linear solver the two must agree bit for bit (--rtol 0, the default); the
table lists, per deck, the rows of each and the largest relative difference.

  tools/compare_deck_outputs.py --reference old/cgcm --candidate build/bin/cgcm \
      [--decks inputs/a.xml ...] [--workdir output/compare] [--jobs 2] [--rtol 0] [-- override ...]

Exit code 0 when every deck agrees, 1 otherwise, 2 for bad arguments.
"""
import argparse
import concurrent.futures
import csv
import glob
import math
import os
import subprocess
import sys
import time


def read_curve(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], rows[1:]


def run(binary, deck, outdir, overrides):
    os.makedirs(outdir, exist_ok=True)
    start = time.time()
    proc = subprocess.run([binary, deck, f"Output/Directory={outdir}", "Output/Print Steps=false"] + overrides,
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    return proc.returncode, time.time() - start, proc.stderr.strip().splitlines()[-1:] if proc.stderr else []


def compare(ref_csv, new_csv, rtol):
    """(agree, rows_ref, rows_new, largest relative difference, where)."""
    head_a, rows_a = read_curve(ref_csv)
    head_b, rows_b = read_curve(new_csv)
    if head_a != head_b:
        return False, len(rows_a), len(rows_b), math.inf, "columns differ"
    worst, where = 0.0, ""
    for i, (ra, rb) in enumerate(zip(rows_a, rows_b)):
        for name, a, b in zip(head_a, ra, rb):
            if a == b:
                continue
            try:
                x, y = float(a), float(b)
                d = abs(x - y) / max(abs(x), abs(y), 1e-300)
            except ValueError:
                d = math.inf
            if d > worst:
                worst, where = d, f"row {i + 1}, {name}: {a} vs {b}"
    agree = len(rows_a) == len(rows_b) and worst <= rtol
    return agree, len(rows_a), len(rows_b), worst, where


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--reference", required=True, help="cgcm before the change")
    ap.add_argument("--candidate", required=True, help="cgcm after the change")
    ap.add_argument("--decks", nargs="*", help="decks (default: every inputs/**/*.xml)")
    ap.add_argument("--workdir", default="output/compare-decks")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--rtol", type=float, default=0.0, help="largest relative difference allowed (default 0)")
    ap.add_argument("overrides", nargs="*", help="Path/To/Parameter=value for every run (after --)")
    args = ap.parse_args()
    for b in (args.reference, args.candidate):
        if not os.access(b, os.X_OK):
            ap.error(f"{b}: not an executable")
    if args.jobs < 1:
        ap.error("--jobs: at least 1")
    decks = args.decks or sorted(glob.glob("inputs/**/*.xml", recursive=True))
    if not decks:
        ap.error("no decks")
    jobs = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        for deck in decks:
            name = os.path.splitext(os.path.relpath(deck, "inputs") if deck.startswith("inputs") else
                                    os.path.basename(deck))[0].replace(os.sep, "-")
            for side, binary in (("reference", args.reference), ("candidate", args.candidate)):
                out = os.path.join(args.workdir, name, side)
                jobs.append((deck, name, side, out, pool.submit(run, binary, deck, out, args.overrides)))
        results = {}
        for deck, name, side, out, fut in jobs:
            results[(name, side)] = (deck, out) + fut.result()
    failed = 0
    print(f"{'deck':38s} {'exit':>9s} {'rows':>9s} {'max rel diff':>13s}  seconds (ref, new)")
    for name in dict.fromkeys(n for n, _ in results):
        deck, out_a, rc_a, t_a, err_a = results[(name, "reference")]
        _, out_b, rc_b, t_b, err_b = results[(name, "candidate")]
        csv_a, csv_b = os.path.join(out_a, "load_curve.csv"), os.path.join(out_b, "load_curve.csv")
        if rc_a != rc_b or not (os.path.exists(csv_a) and os.path.exists(csv_b)):
            ok, na, nb, worst, where = False, 0, 0, math.inf, f"exit {rc_a} vs {rc_b} {err_a} {err_b}"
            if os.path.exists(csv_a) and os.path.exists(csv_b):
                ok, na, nb, worst, where = compare(csv_a, csv_b, args.rtol)
                ok = ok and rc_a == rc_b
        else:
            ok, na, nb, worst, where = compare(csv_a, csv_b, args.rtol)
        failed += not ok
        print(f"{name:38s} {rc_a:>4d},{rc_b:>4d} {na:>4d},{nb:>4d} {worst:13.3g}  {t_a:7.1f}, {t_b:7.1f}"
              + ("" if ok else f"  DIFFERS: {where}"))
    print(f"{len(results) // 2 - failed} agree, {failed} differ")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
