"""cgcm-analytic from the plotting tools: run one command, read its CSV.

    rows(exe, "pulloff", "--model", "md", "--lambda", 1)   -> [{"control": "load", "P": "-1.58", ...}, ...]
    columns(exe, "curve", "--model", "jkr")                -> {"a": array, "P": array, "delta": array}
"""
import csv
import io
import subprocess
import sys

import numpy as np


def rows(exe, *args, notes=False):
    """The CSV rows of `exe args` as dicts of strings. A failure stops the caller with
    cgcm-analytic's message; with notes, its remarks on stderr are passed on."""
    cmd = [str(exe), *map(str, args)]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"{' '.join(cmd)} failed ({p.returncode}):\n{p.stderr.strip()}")
    for line in p.stderr.strip().splitlines() if notes else []:
        print(f"  note: {line}", file=sys.stderr)
    return list(csv.DictReader(io.StringIO(p.stdout)))


def columns(exe, *args, notes=False):
    """The CSV of `exe args` by column: numbers as numpy arrays, text columns as lists."""
    table = rows(exe, *args, notes=notes)
    out = {}
    for key in table[0]:
        values = [r[key] for r in table]
        try:
            out[key] = np.array([float(v) for v in values])
        except ValueError:
            out[key] = values
    return out


LAMBDA_OVER_MU = 1.15701  # Maugis-Dugdale lambda of the 9-3 half-space law at Tabor mu (analytic-models.md)


def lj_sphere_pulloff(exe, mu):
    """Minimum force / (pi w R) of the Lennard-Jones sphere at Tabor mu (negative)."""
    return float(rows(exe, "ljsphere", "--mu", f"{mu:.8g}", "--pulloff")[-1]["P_min"])


def md_pulloff(exe, lam):
    """Load-control pull-off / (pi w R) of Maugis-Dugdale at lambda (negative)."""
    return float(next(r for r in rows(exe, "pulloff", "--model", "md", "--lambda", f"{lam:.8g}")
                      if r["control"] == "load")["P"])
