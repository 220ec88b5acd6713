#!/usr/bin/env python3
"""Stability from the tangent's eigenvalues against the parity of folds, on every deck of inputs/.

Each deck runs with Output/Eigenvalues = 3 (stable = no eigenvalue of the tangent on the free dofs
with a negative real part; stable_by_folds = the parity of the folds passed) and, for the time it
costs, without. The plane-strain and axisymmetric decks also run under arc-length control
(Loading/Control = arc-length), where the path holds its unstable branches and parity says something.
Per run, the table (table.csv in --output) gives the states, the states the eigenvalues call unstable,
the states where the two criteria disagree (located folds and branch points left out: they are
marginal), the folds and branch points, and the run times.

  tools/stability_check.py [--decks inputs/a.xml ...] [--output output/stability-check] [--jobs 2]
      [--np 2] [--rerun] [--plan]

Exit code 0 when the two criteria agree on every state of every run that has no branch point, 1 otherwise.
"""
import concurrent.futures
import csv
import glob
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pulloff_map  # noqa: E402  (the study tools' shared options and cached runs)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EIGENVALUES = 3


def formulation(deck):
    with open(deck) as f:
        text = f.read()
    for name in ("plane strain", "3D"):
        if f'value="{name}"' in text:
            return name
    return "axisymmetric"


def cases(decks):
    out = []
    for deck in decks:
        name = os.path.relpath(deck, os.path.join(ROOT, "inputs")).replace("/", "-")[:-4]
        out.append({"name": name, "deck": deck, "control": "deck", "overrides": []})
        with open(deck) as f:
            already = 'value="arc-length"' in f.read()
        if formulation(deck) != "3D" and not already:
            out.append({"name": name + "-arc-length", "deck": deck, "control": "arc-length",
                        "overrides": ["Loading/Control=arc-length"]})
    return out


def run(case, args, eigen):
    folder = os.path.join(args.output, case["name"] + ("" if eigen else "-plain"))
    command = [os.path.join(args.build, "bin", "cgcm"), case["deck"], f"Output/Directory={folder}",
               "Output/Print Steps=false", "Output/Exodus=false", *case["overrides"]]
    if eigen:
        command.append(f"Output/Eigenvalues={EIGENVALUES}")
    else:  # a deck may ask for eigenvalues itself (and for branch switching, which needs them)
        command += ["Output/Eigenvalues=0", "Loading/Branch Switching=false"]
    if args.np > 1 and formulation(case["deck"]) == "3D":
        command = ["mpirun", "--allow-run-as-root", "--oversubscribe", "--mca", "mpi_yield_when_idle", "1",
                   "-np", str(args.np)] + command
    code, seconds = pulloff_map.run_logged(command, folder, folder + ".log", args.rerun)
    return folder, code, seconds


def judge(folder):
    path = os.path.join(folder, "load_curve.csv")
    if not os.path.exists(path):
        return None
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    marginal = [r for r in rows if r["fold"] == "1" or r["branch_point"] == "1"]
    plain = [r for r in rows if r not in marginal]
    disagree = [r for r in plain if r["stable"] != r["stable_by_folds"]]
    return {"states": len(rows), "unstable": sum(r["stable"] == "0" for r in plain),
            "disagree": len(disagree), "first_disagreement": disagree[0]["step"] if disagree else "",
            "folds": sum(r["fold"] == "1" for r in rows), "branch_points": sum(r["branch_point"] == "1" for r in rows)}


def main():
    ap = pulloff_map.study_parser(__doc__, "output/stability-check", "print the runs, run nothing")
    ap.add_argument("--decks", nargs="*", help="decks (default: every inputs/**/*.xml)")
    ap.add_argument("--np", type=int, default=2, help="ranks for the 3D decks")
    args = pulloff_map.parse_study_args(ap)
    decks = [os.path.abspath(d) for d in (args.decks or sorted(glob.glob(os.path.join(ROOT, "inputs", "**", "*.xml"),
                                                                          recursive=True)))]
    todo = cases(decks)
    if args.plan:
        for c in todo:
            print(c["name"], c["control"], " ".join(c["overrides"]))
        return 0
    os.makedirs(args.output, exist_ok=True)
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        futures = {(c["name"], eigen): pool.submit(run, c, args, eigen) for c in todo for eigen in (True, False)}
    table, ok = [], True
    for c in todo:
        folder, code, seconds = futures[(c["name"], True)].result()
        _, plain_code, plain_seconds = futures[(c["name"], False)].result()
        row = {"run": c["name"], "control": c["control"], "exit": code, "seconds_eigenvalues": f"{seconds:.1f}",
               "seconds_plain": f"{plain_seconds:.1f}" if plain_code == 0 else f"exit {plain_code}"}
        verdict = judge(folder)
        if verdict:
            row.update(verdict)
            ok = ok and (verdict["disagree"] == 0 or verdict["branch_points"] > 0)
        table.append(row)
    columns = ["run", "control", "exit", "states", "unstable", "disagree", "first_disagreement", "folds",
               "branch_points", "seconds_eigenvalues", "seconds_plain"]
    with open(os.path.join(args.output, "table.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, columns, extrasaction="ignore")
        w.writeheader()
        w.writerows(table)
    for r in table:
        print("  ".join(f"{k}={r.get(k, '')}" for k in columns))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
