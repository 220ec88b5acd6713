#!/usr/bin/env python3
"""Runs a deck to the end (the reference), runs it again and kills it with
SIGKILL once load_curve.csv holds a given share of the reference's rows,
checks that the killed run's summary says "running", continues it with
`cgcm --restart DIR`, and compares the continued run's load_curve.csv,
body_forces.csv (compare_csv.py) and results.e (exo_compare) with the
reference's. Exit 0 if all agree. With --launcher (e.g. "mpirun -np 2") every
run goes through it, and the kill takes the launcher's whole process group;
--restart-launcher continues the run through another one ("" for none: one
process), as a restart on another number of ranks.

usage: kill_and_restart.py --cgcm CGCM --exo-compare EXO --output DIR [--at 0.5] [--rel 1e-8] [--abs 1e-12]
                           [--launcher "MPIRUN ARGS"] [--restart-launcher "MPIRUN ARGS"] -- DECK [overrides...]
"""
import argparse
import os
import shlex
import shutil
import signal
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def rows(path):
    try:
        with open(path) as f:
            return sum(1 for _ in f) - 1
    except FileNotFoundError:
        return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cgcm", required=True)
    ap.add_argument("--exo-compare", required=True)
    ap.add_argument("--output", required=True)
    ap.add_argument("--at", type=float, default=0.5, help="share of the reference's rows at the kill")
    ap.add_argument("--rel", type=float, default=1e-8)
    ap.add_argument("--abs", type=float, default=1e-12, help="absolute tolerance of the results.e comparison")
    ap.add_argument("--timeout", type=float, default=300.0)
    ap.add_argument("--launcher", default="", help="command line that starts cgcm (MPI), split as a shell would")
    ap.add_argument("--restart-launcher", default=None, help="the same for the restart (default: --launcher)")
    ap.add_argument("args", nargs="+", help="deck and overrides")
    a = ap.parse_args()
    reference, killed = os.path.join(a.output, "reference"), os.path.join(a.output, "killed")
    for d in (reference, killed):
        shutil.rmtree(d, ignore_errors=True)
    quiet = dict(stdout=subprocess.DEVNULL)
    cgcm = shlex.split(a.launcher) + [a.cgcm]
    r = subprocess.run(cgcm + a.args + ["Output/Directory=" + reference], timeout=a.timeout, **quiet)
    if r.returncode != 0:
        sys.exit(f"kill_and_restart: the reference run failed (exit {r.returncode})")
    total = rows(os.path.join(reference, "load_curve.csv"))
    at = max(1, int(a.at * total))

    # a session of its own: SIGKILL to its process group takes the MPI launcher and its ranks together
    run = subprocess.Popen(cgcm + a.args + ["Output/Directory=" + killed], start_new_session=True, **quiet)
    start = time.time()
    while rows(os.path.join(killed, "load_curve.csv")) < at:
        if run.poll() is not None:
            sys.exit(f"kill_and_restart: the run ended (exit {run.returncode}) before {at} rows")
        if time.time() - start > a.timeout:
            os.killpg(run.pid, signal.SIGKILL)
            sys.exit("kill_and_restart: the run did not reach the kill point in time")
        time.sleep(0.005)
    os.killpg(run.pid, signal.SIGKILL)
    run.wait()
    with open(os.path.join(killed, "summary.txt")) as f:
        status = f.readline().strip()
    print(f"killed at {rows(os.path.join(killed, 'load_curve.csv'))} of {total} rows; summary: {status}")
    if not status.startswith("running"):
        sys.exit(f"kill_and_restart: the killed run's summary says \"{status}\", not \"running\"")

    restart = shlex.split(a.launcher if a.restart_launcher is None else a.restart_launcher) + [a.cgcm]
    r = subprocess.run(restart + ["--restart", killed, "Output/Print Steps=false"], timeout=a.timeout, **quiet)
    if r.returncode != 0:
        sys.exit(f"kill_and_restart: cgcm --restart failed (exit {r.returncode})")
    with open(os.path.join(killed, "summary.txt")) as f:
        status = f.readline().strip()
    if status != "completed":
        sys.exit(f"kill_and_restart: the continued run's summary says \"{status}\"")
    compare = [sys.executable, os.path.join(HERE, "compare_csv.py")]
    failed = False
    for name, columns in (("load_curve.csv", "step,u,P,gap,contact_radius,P_lower,stable,fold,jump"),
                          ("body_forces.csv", "step,u,body,Fx,Fy,Fz")):
        r = subprocess.run(compare + [os.path.join(reference, name), os.path.join(killed, name), "--columns", columns,
                                      "--rel", str(a.rel)])
        failed |= r.returncode != 0
    # the state's Newton residual norm is round-off below the acceptance tolerance (1e-10 here); like
    # the CSV's residual column it need not repeat digit for digit (MUMPS: up to 2.6e-12 apart)
    r = subprocess.run([a.exo_compare, "--rel", str(a.rel), "--abs", str(a.abs), "--abs-for", "residual=1e-10",
                        os.path.join(reference, "results.e"), os.path.join(killed, "results.e")])
    failed |= r.returncode != 0
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
