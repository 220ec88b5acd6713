#!/usr/bin/env python3
"""Runs a deck to its end, changes a few bytes of its checkpoint.bin (at
--where: the middle of the file or its last byte) and checks that
`cgcm --restart DIR` refuses it before any work: exit code 2, a message
naming the file and its checksum, load_curve.csv and results.e untouched.

usage: restart_damaged_checkpoint.py --cgcm CGCM --output DIR [--where middle|end] -- DECK [overrides...]
"""
import argparse
import os
import re
import shutil
import subprocess
import sys


def read(path):
    with open(path, "rb") as f:
        return f.read()


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cgcm", required=True)
    ap.add_argument("--output", required=True)
    ap.add_argument("--where", choices=("middle", "end"), default="middle")
    ap.add_argument("args", nargs="+", help="deck and overrides")
    a = ap.parse_args()
    shutil.rmtree(a.output, ignore_errors=True)
    r = subprocess.run([a.cgcm] + a.args + ["Output/Directory=" + a.output], stdout=subprocess.DEVNULL,
                       stderr=subprocess.PIPE, text=True, timeout=300)
    if r.returncode != 0:
        sys.exit(f"restart_damaged_checkpoint: the run failed (exit {r.returncode}):\n{r.stderr}")
    checkpoint = os.path.join(a.output, "checkpoint.bin")
    data = bytearray(read(checkpoint))
    at = [len(data) // 2 + k for k in range(3)] if a.where == "middle" else [len(data) - 1]
    for k in at:
        data[k] ^= 0x5A
    with open(checkpoint, "wb") as f:
        f.write(data)
    kept = {name: read(os.path.join(a.output, name)) for name in ("load_curve.csv", "results.e")
            if os.path.exists(os.path.join(a.output, name))}

    r = subprocess.run([a.cgcm, "--restart", a.output], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                       timeout=300)
    print(f"bytes {at} of {len(data)} changed; exit code {r.returncode}\nstdout:\n{r.stdout}\nstderr:\n{r.stderr}")
    expected = (r"cgcm: error: --restart .*: " + re.escape(checkpoint) +
                r" is damaged: its checksum \(CRC-32\) does not match its contents")
    failures = []
    if r.returncode != 2:
        failures.append(f"expected exit code 2, got {r.returncode}")
    if not re.search(expected, r.stderr):
        failures.append(f"stderr does not match: {expected}")
    for name, before in kept.items():
        if read(os.path.join(a.output, name)) != before:
            failures.append(f"{name} changed: the restart did work before refusing the checkpoint")
    if failures:
        sys.exit("restart_damaged_checkpoint: " + "; ".join(failures))


if __name__ == "__main__":
    main()
