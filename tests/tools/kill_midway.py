#!/usr/bin/env python3
"""Kills a cgcm run with SIGKILL once its results.e holds at least two steps,
then checks that the file still reads (exo_compare --dump) with those steps
and that each step's u is the u of the same row of load_curve.csv.

usage: kill_midway.py --cgcm CGCM --exo-compare EXO --output DIR -- DECK [overrides...]
"""
import argparse
import csv
import os
import re
import signal
import subprocess
import sys
import time


def dump(exo, path):
    r = subprocess.run([exo, "--dump", path], capture_output=True, text=True)
    return r.returncode, r.stdout + r.stderr


def steps(text):
    m = re.search(r"^steps: (\d+)$", text, re.M)
    return int(m.group(1)) if m else 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cgcm", required=True)
    ap.add_argument("--exo-compare", required=True)
    ap.add_argument("--output", required=True)
    ap.add_argument("--timeout", type=float, default=120.0)
    ap.add_argument("args", nargs="+", help="deck and overrides")
    a = ap.parse_args()
    results = os.path.join(a.output, "results.e")
    if os.path.exists(results):
        os.remove(results)
    run = subprocess.Popen([a.cgcm] + a.args + ["Output/Directory=" + a.output],
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    start = time.time()
    while time.time() - start < a.timeout:
        if run.poll() is not None:
            sys.exit(f"kill_midway: cgcm ended (exit {run.returncode}) before results.e had two steps")
        if os.path.exists(results) and steps(dump(a.exo_compare, results)[1]) >= 2:
            break
        time.sleep(0.05)
    else:
        run.kill()
        sys.exit("kill_midway: results.e did not reach two steps in time")
    run.send_signal(signal.SIGKILL)
    run.wait()
    code, text = dump(a.exo_compare, results)
    print(text)
    if code != 0:
        sys.exit(f"kill_midway: results.e does not read after SIGKILL (exo_compare exit {code})")
    n = steps(text)
    with open(os.path.join(a.output, "load_curve.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    names = re.search(r"^step time (.*)$", text, re.M).group(1).split()
    table = re.findall(r"^(\d+) (\S+) (.*)$", text.split("step time", 1)[1], re.M)
    for step, _, values in table:
        k = int(step) - 1
        if k < len(rows):
            u = float(values.split()[names.index("u")])
            if abs(u - float(rows[k]["u"])) > 1e-12:
                sys.exit(f"kill_midway: step {step} has u = {u}, load_curve.csv row {k + 1} u = {rows[k]['u']}")
    print(f"killed after {n} steps; results.e reads, {len(rows)} load-curve rows")
    return 0 if n >= 2 else 1


if __name__ == "__main__":
    sys.exit(main())
