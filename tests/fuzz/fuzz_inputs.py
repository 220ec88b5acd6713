#!/usr/bin/env python3
"""Mutation fuzzing of cgcm's inputs: decks (values, types, names, nesting,
bytes) and the .geo files they name. Every mutated deck goes through
`cgcm --check-list` (validation and the problem's set-up, in batches); a
sample of those found valid is run in full. Each input must end with exit
code 0, 1 or 2 and a message, never a signal and never past the time limit.

usage: fuzz_inputs.py --cgcm CGCM --source-dir SRC --workdir DIR [--count N] [--seed S]
                      [--full-runs K] [--run-limit SECONDS] [--jobs J]
Exit 0 when no input failed; the failing inputs are kept in DIR/failures.
"""
import argparse
import concurrent.futures as futures
import glob
import os
import random
import shutil
import signal
import subprocess
import sys
import time
import xml.etree.ElementTree as ET

NASTY = ["0", "-0", "-1", "1", "2", "7", "1e308", "-1e308", "1e-320", "nan", "NaN", "inf", "-inf", "", " ", "abc",
         "2147483647", "-2147483648", "99999999999999999999", "0x10", "1,5", " 3 ", "true", "false", "{", "{}", "{1,2",
         "{nan}", "{1e308,-1e308}", "{0,0}", "{-0.02, 0.06, -0.03, 1e9}", "x" * 5000, "\u00e9\u00e8", "1e", "--1",
         "1.5.2", "%s%n", "../../../etc/passwd", "/dev/null", "output/../../x", "{ , }", "[1,2]"]
TYPES = ["int", "double", "string", "bool", "Array(double)", "Array(int)", "Array(string)", "float", "long", "x"]


def mutate_tree(root, rng):
    params = root.findall(".//Parameter")
    lists = root.findall(".//ParameterList")
    kind = rng.choice(["value", "value", "value", "type", "name", "delete", "duplicate", "move", "sublist",
                       "number", "number"])
    if kind in ("value", "type", "name", "delete", "duplicate", "move", "number") and not params:
        kind = "sublist"
    if kind == "value":
        rng.choice(params).set("value", rng.choice(NASTY))
    elif kind == "number":  # a plausible number, scaled: absurd sizes, zeros, signs
        p = rng.choice(params)
        try:
            v = float(p.get("value", "0"))
        except ValueError:
            v = 1.0
        p.set("value", repr(rng.choice([0.0, -v, v * 10 ** rng.randint(-12, 12), v + 1, 1e6, 3.0, 6.0])))
    elif kind == "type":
        rng.choice(params).set("type", rng.choice(TYPES))
    elif kind == "name":
        p = rng.choice(params)
        name = p.get("name", "")
        if name and rng.random() < 0.5:
            i = rng.randrange(len(name))
            name = name[:i] + rng.choice("aeXz_ ") + name[i + 1:]
        else:
            name = rng.choice(params).get("name", "") + rng.choice(["", "s", " "])
        p.set("name", name)
    elif kind == "delete":
        p = rng.choice(params)
        for parent in root.iter():
            if p in list(parent):
                parent.remove(p)
                break
    elif kind == "duplicate":
        p = rng.choice(params)
        for parent in root.iter():
            if p in list(parent):
                parent.append(ET.fromstring(ET.tostring(p)))
                break
    elif kind == "move":
        p = rng.choice(params)
        for parent in root.iter():
            if p in list(parent):
                parent.remove(p)
                break
        rng.choice(lists + [root]).append(p)
    else:  # sublists: remove one, add an unknown one, nest one in another
        r = rng.random()
        if lists and r < 0.4:
            victim = rng.choice(lists)
            for parent in root.iter():
                if victim in list(parent):
                    parent.remove(victim)
                    break
        elif r < 0.7:
            extra = ET.SubElement(rng.choice(lists + [root]), "ParameterList", {"name": rng.choice(
                ["Solver", "Bogus", "LOCA", "Geometry", "Block", ""])})
            ET.SubElement(extra, "Parameter", {"name": "x", "type": "double", "value": "1"})
        elif lists:
            a = rng.choice(lists)
            for parent in root.iter():
                if a in list(parent):
                    parent.remove(a)
                    break
            rng.choice(root.findall(".//ParameterList") + [root]).append(a)


def mutate_bytes(data, rng):
    data = bytearray(data)
    for _ in range(rng.randint(1, 4)):
        op = rng.random()
        if not data:
            break
        i = rng.randrange(len(data))
        if op < 0.3:
            data[i] = rng.randrange(256)
        elif op < 0.55:
            del data[i:i + rng.randint(1, 20)]
        elif op < 0.8:
            data[i:i] = bytes(rng.choice([b"<", b">", b"\"", b"&", b"\x00", b"</ParameterList>", b"{", b"9" * 30]))
        else:
            data = data[:i]  # truncated
    return bytes(data)


# The hand-written bad decks of the regression cases, in the order of their
# former file names (tests/regression/bad-input/*.xml, sorted): a seed draws
# the same decks as before they moved into their case folders.
BAD_DECKS = ["bad_array_for_number/deck.xml", "bad_nan_in_path/deck.xml", "bad_double_text/deck.xml",
             "bad_refinement_text/deck.xml", "bad_number_as_text/deck.xml", "bad_truncated_xml/truncated.xml",
             "bad_unknown_type/deck.xml", "bad_value_for_group/deck.xml", "bad_young_text/deck.xml"]


def make_inputs(src, workdir, count, rng):
    decks = sorted(glob.glob(os.path.join(src, "inputs", "**", "*.xml"), recursive=True)) + \
        [os.path.join(src, "tests", "regression", deck) for deck in BAD_DECKS]
    geos = sorted(glob.glob(os.path.join(src, "meshes", "*.geo")))
    os.makedirs(os.path.join(workdir, "inputs"), exist_ok=True)
    made = []
    for k in range(count):
        deck = rng.choice(decks)
        path = os.path.join(workdir, "inputs", f"{k:06d}.xml")
        text = open(deck, "rb").read()
        try:  # mesh files named relative to the deck stay found from the work folder
            root = ET.fromstring(text)
            for p in root.findall(".//Parameter[@name='File']"):
                if not os.path.isabs(p.get("value", "")):
                    p.set("value", os.path.normpath(os.path.join(os.path.dirname(deck), p.get("value", ""))))
            text = ET.tostring(root)
        except ET.ParseError:
            pass
        choice = rng.random()
        if choice < 0.15:
            data = mutate_bytes(text, rng)
        else:
            try:
                root = ET.fromstring(text)
            except ET.ParseError:
                root = None
            if root is None:
                data = mutate_bytes(text, rng)
            else:
                for _ in range(rng.choice([1, 1, 1, 2, 3])):
                    mutate_tree(root, rng)
                if choice > 0.9 and geos:  # a mutated mesh file, named by the deck
                    geo = rng.choice(geos)
                    gpath = os.path.join(workdir, "inputs", f"{k:06d}.geo")
                    g = open(geo, "rb").read()
                    # the .geo may include files next to it: keep it in its folder's reach
                    g = g.replace(b'Include "', b'Include "' + os.path.dirname(geo).encode() + b"/")
                    open(gpath, "wb").write(mutate_bytes(g, rng))
                    geometry = root.find("./ParameterList[@name='Geometry']")
                    if geometry is None:
                        geometry = ET.SubElement(root, "ParameterList", {"name": "Geometry"})
                    for name, value in (("Type", "gmsh"), ("File", gpath)):
                        p = geometry.find(f"./Parameter[@name='{name}']")
                        if p is None:
                            p = ET.SubElement(geometry, "Parameter", {"name": name, "type": "string"})
                        p.set("value", value)
                data = ET.tostring(root)
        out = os.path.join(workdir, "out", f"{k:06d}")
        data = data.replace(b"output/", out.encode() + b"/")  # runs write into the work folder
        open(path, "wb").write(data)
        made.append(path)
    return made


def check_batch(cgcm, batch, workdir, index, limit):
    """--check-list over a batch; returns {deck: (code, message)}; a deck the
    batch did not report (crash, hang) is checked alone."""
    listing = os.path.join(workdir, f"batch-{index}.txt")
    open(listing, "w").write("\n".join(batch) + "\n")
    results = {}
    try:
        r = subprocess.run([cgcm, "--check-list", listing], capture_output=True, text=True, errors="replace",
                           timeout=limit * len(batch))
        out = r.stdout
    except subprocess.TimeoutExpired as e:
        out = (e.stdout or b"").decode(errors="replace") if isinstance(e.stdout, bytes) else (e.stdout or "")
    for line in out.splitlines():
        parts = line.split("\t", 2)
        if len(parts) == 3 and parts[0] in batch:
            results[parts[0]] = (int(parts[1]), parts[2].strip())
    for deck in batch:
        if deck in results:
            continue
        try:
            r = subprocess.run([cgcm, "--check", deck], capture_output=True, text=True, errors="replace",
                               timeout=limit)
            results[deck] = (r.returncode, (r.stderr or r.stdout).strip())
        except subprocess.TimeoutExpired:
            results[deck] = ("timeout", f"--check took more than {limit} s")
    return results


def full_run(cgcm, deck, workdir, limit):
    out = os.path.join(workdir, "runs", os.path.basename(deck)[:-4])
    shutil.rmtree(out, ignore_errors=True)
    p = subprocess.Popen([cgcm, deck, "Output/Directory=" + out, "Output/Print Steps=false"],
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, errors="replace",
                         start_new_session=True)
    try:
        _, err = p.communicate(timeout=limit)
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        p.communicate()
        rows = 0
        try:
            rows = sum(1 for _ in open(os.path.join(out, "load_curve.csv"))) - 1
        except OSError:
            pass
        return ("slow", f"{rows} states in {limit} s") if rows > 0 else ("timeout", f"no state in {limit} s")
    shutil.rmtree(out, ignore_errors=True)
    return p.returncode, err.strip()


def verdict(code, message):
    if code in (0,) or (code in (1, 2) and message):
        return None
    if code == "slow":
        return None
    if isinstance(code, int) and code < 0:
        return f"signal {-code}"
    return f"exit {code} with {'message' if message else 'no message'}"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cgcm", required=True)
    ap.add_argument("--source-dir", required=True)
    ap.add_argument("--workdir", required=True)
    ap.add_argument("--count", type=int, default=200)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--full-runs", type=int, default=5, help="valid inputs run in full (a random sample)")
    ap.add_argument("--run-limit", type=float, default=60.0, help="seconds per input")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--batch", type=int, default=100)
    a = ap.parse_args()
    rng = random.Random(a.seed)
    shutil.rmtree(a.workdir, ignore_errors=True)
    start = time.time()
    decks = make_inputs(os.path.abspath(a.source_dir), a.workdir, a.count, rng)
    batches = [decks[i:i + a.batch] for i in range(0, len(decks), a.batch)]
    results = {}
    with futures.ThreadPoolExecutor(a.jobs) as pool:
        for r in pool.map(lambda ib: check_batch(a.cgcm, ib[1], a.workdir, ib[0], a.run_limit), enumerate(batches)):
            results.update(r)
    valid = [d for d in decks if results[d][0] == 0]
    sample = rng.sample(valid, min(a.full_runs, len(valid)))
    runs = {}
    with futures.ThreadPoolExecutor(a.jobs) as pool:
        for deck, r in zip(sample, pool.map(lambda d: full_run(a.cgcm, d, a.workdir, a.run_limit), sample)):
            runs[deck] = r
    with open(os.path.join(a.workdir, "results.tsv"), "w") as f:  # every input's outcome, for reading
        for label, table in (("check", results), ("run", runs)):
            for deck, (code, message) in sorted(table.items()):
                f.write(f"{label}\t{deck}\t{code}\t{message}\n")
    failures = []
    for label, table in (("check", results), ("run", runs)):
        for deck, (code, message) in table.items():
            why = verdict(code, message)
            if why:
                failures.append((label, deck, why, message))
    counts = {}
    for code, _ in results.values():
        counts[code] = counts.get(code, 0) + 1
    run_counts = {}
    for code, _ in runs.values():
        run_counts[code] = run_counts.get(code, 0) + 1
    print(f"fuzz: {len(decks)} inputs (seed {a.seed}) in {time.time() - start:.0f} s; checks by exit code: "
          f"{dict(sorted(counts.items(), key=str))}; full runs of valid inputs: {dict(sorted(run_counts.items(), key=str))}")
    if failures:
        keep = os.path.join(a.workdir, "failures")
        os.makedirs(keep, exist_ok=True)
        for label, deck, why, message in failures:
            shutil.copy(deck, keep)
            print(f"FAIL ({label}) {deck}: {why}: {message[:300]}")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
