#!/usr/bin/env python3
"""Checks the "mesh held per rank" line of a summary.txt of a run on several
ranks: the ranks' cells add up to the mesh's, their own surface facets add up
to the whole surfaces' (each facet on exactly one rank), no rank holds more
facets (own + ghost) than there are, and the ghosts were gathered at least
once. Exit 0 if so, 1 otherwise (with the reason).

usage: check_held_surfaces.py summary.txt [--ranks N]
"""
import argparse
import re
import sys

LINE = re.compile(r"^mesh held per rank \(cells, nodes, surface facets own \+ ghost\): (.*) of (\d+), (\d+), (\d+)"
                  r"(?:; ghosts gathered (\d+) times)?$")
RANK = re.compile(r"^\s*(\d+), (\d+), (\d+) \+ (\d+)\s*$")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("summary")
    ap.add_argument("--ranks", type=int, default=None, help="the number of ranks the run had")
    args = ap.parse_args()
    with open(args.summary) as f:
        matches = [LINE.match(line.rstrip("\n")) for line in f]
    matches = [m for m in matches if m]
    if len(matches) != 1:
        sys.exit(f"{args.summary}: {len(matches)} 'mesh held per rank' lines, one expected")
    m = matches[0]
    ranks = []
    for part in m.group(1).split(";"):
        r = RANK.match(part)
        if not r:
            sys.exit(f"{args.summary}: cannot read the rank entry '{part}'")
        ranks.append([int(v) for v in r.groups()])
    cells, nodes, facets = int(m.group(2)), int(m.group(3)), int(m.group(4))
    gathers = int(m.group(5)) if m.group(5) else 0
    failures = []
    if args.ranks is not None and len(ranks) != args.ranks:
        failures.append(f"{len(ranks)} ranks listed, {args.ranks} expected")
    if sum(r[0] for r in ranks) != cells:
        failures.append(f"the ranks' cells add up to {sum(r[0] for r in ranks)}, not {cells}")
    if sum(r[2] for r in ranks) != facets:
        failures.append(f"the ranks' own facets add up to {sum(r[2] for r in ranks)}, not {facets}")
    for k, r in enumerate(ranks):
        if r[2] + r[3] > facets:
            failures.append(f"rank {k} holds {r[2]} + {r[3]} facets of {facets}")
        if r[1] > nodes:
            failures.append(f"rank {k} holds {r[1]} nodes of {nodes}")
    if gathers < 1:
        failures.append("the ghosts were never gathered")
    for f in failures:
        print(f"{args.summary}: {f}")
    print(f"{len(ranks)} ranks: own + ghost facets " + ", ".join(f"{r[2]} + {r[3]}" for r in ranks) +
          f" of {facets}; gathered {gathers} times")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
