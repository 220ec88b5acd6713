#!/usr/bin/env python3
"""cgcm against dolfinx on the same compressible Neo-Hookean block.

Runs bench_peer_block (cgcm, C++) and neo_hookean_block_dolfinx.py (dolfinx
0.5 + PETSc from Debian) side by side, interleaved, on the same n^3 hex8
unit cube with the same Newton iteration and the same linear tolerance, and
prints per size and rank count the wall times of residual assembly,
Jacobian assembly and linear solves with their ratios (dolfinx / cgcm: above
1 means cgcm is faster). Each figure is the best of the repeats. Solve
times are totals over the Newton solve, preconditioner set-up (MueLu, GAMG)
included and also shown on its own. The top
reaction forces of the two codes must agree (they solve the same discrete
problem); the script exits 1 if they do not, or if a run fails.

    /usr/bin/python3 bench/peers/compare_dolfinx.py --bench build/bin/bench_peer_block \
        [--sizes 32 46] [--ranks 1 2] [--repeats 2] [--rtol 1e-8] [--markdown]

n = 32 gives 108k unknowns, n = 46 311k. cgcm's Jacobian time includes its
residual (one fused pass over the cells); dolfinx assembles the matrix
alone. Both solve with CG: cgcm with Belos CG + MueLu, the Dirichlet rows
eliminated symmetrically (three translations as near-null space), dolfinx
with CG + GAMG and the six rigid-body modes (symmetric elimination too).

Both codes run with the same malloc: by default glibc's in transparent huge
pages (the tunable glibc.malloc.hugetlb=1), with --pages small in 4 KiB pages
(CGCM_HUGE_PAGES=0, no tunable); in both, blocks from 4 MiB mapped
(glibc.malloc.mmap_threshold, which cgcm sets for itself and the script sets
for dolfinx too).
"""
import argparse
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
MPIRUN = ["mpirun", "--allow-run-as-root", "--oversubscribe", "--mca", "mpi_yield_when_idle", "1"]
PHASES = [("residual_s", "residual_evaluations", "residual"), ("jacobian_s", "newton", "Jacobian"),
          ("solve_s", None, "solve")]  # solves: totals over the Newton solve


def run(command, ranks, env):
    full = MPIRUN + ["-np", str(ranks)] + [arg for name in sorted(env) for arg in ("-x", name)] + command
    done = subprocess.run(full, capture_output=True, text=True, env={**os.environ, **env})
    lines = [l for l in done.stdout.splitlines() if l.startswith("{")]
    if done.returncode != 0 or not lines:
        sys.stderr.write(f"failed ({done.returncode}): {' '.join(full)}\n{done.stdout[-2000:]}{done.stderr[-2000:]}")
        return None
    return json.loads(lines[-1])


def best(runs):
    """Per phase the fastest repeat (counts and forces are equal between repeats)."""
    out = dict(runs[0])
    for key in [key for key, _, _ in PHASES] + ["setup_s"]:
        out[key] = min(r[key] for r in runs)
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--bench", required=True, help="path of cgcm's bench_peer_block")
    parser.add_argument("--sizes", type=int, nargs="+", default=[32, 46], help="cells per edge (default: 32 46)")
    parser.add_argument("--ranks", type=int, nargs="+", default=[1, 2], help="MPI ranks (default: 1 2)")
    parser.add_argument("--repeats", type=int, default=2, help="interleaved runs of each code (default: 2)")
    parser.add_argument("--rtol", type=float, default=1e-8, help="relative tolerance of every linear solve")
    parser.add_argument("--pages", choices=["huge", "small"], default="huge",
                        help="glibc malloc's pages in both codes: huge (transparent huge pages, cgcm's default) or "
                        "small (4 KiB)")
    parser.add_argument("--markdown", action="store_true", help="print the table as Markdown")
    args = parser.parse_args()
    if not os.access(args.bench, os.X_OK):
        parser.error(f"--bench {args.bench}: not an executable (build the target bench_peer_block)")
    if args.repeats < 1 or args.rtol <= 0 or min(args.sizes) < 1 or min(args.ranks) < 1:
        parser.error("--repeats, --sizes and --ranks must be at least 1, --rtol positive")

    tunables = [t for t in os.environ.get("GLIBC_TUNABLES", "").split(":")
                if t and "malloc.hugetlb" not in t and "malloc.mmap_threshold" not in t]
    tunables.append(f"glibc.malloc.mmap_threshold={4 << 20}")  # cgcm's (core/MallocTunables.hpp)
    if args.pages == "huge":
        tunables.append("glibc.malloc.hugetlb=1")
    env = {"GLIBC_TUNABLES": ":".join(tunables), "CGCM_HUGE_PAGES": "1" if args.pages == "huge" else "0"}
    cgcm = [os.path.abspath(args.bench)]
    dolfinx = ["/usr/bin/python3", os.path.join(HERE, "neo_hookean_block_dolfinx.py")]
    rows, ok = [], True
    for n in args.sizes:
        for ranks in args.ranks:
            results = {"cgcm": [], "dolfinx": []}
            for repeat in range(args.repeats):
                order = [("cgcm", cgcm), ("dolfinx", dolfinx)]
                for code, command in order if repeat % 2 == 0 else reversed(order):
                    r = run(command + [str(n), *(["Belos CG + MueLu"] if code == "cgcm" else []), str(args.rtol)],
                            ranks, env)
                    if r is None or not r["converged"] or r["unconverged_solves"]:
                        ok = False
                    if r is not None:
                        results[code].append(r)
            if not results["cgcm"] or not results["dolfinx"]:
                ok = False
                continue
            c, d = best(results["cgcm"]), best(results["dolfinx"])
            agree = abs(c["reaction"] - d["reaction"]) <= 1e-7 * abs(d["reaction"])
            ok = ok and agree
            rows.append((c, d, agree))
            sys.stderr.write(f"n={n} ranks={ranks}: cgcm {json.dumps(c)}\n  dolfinx {json.dumps(d)}\n")

    header = ["n", "unknowns", "ranks", "code", "Newton", "Krylov", "residual [s/eval]", "Jacobian [s/eval]",
              "solves, total (set-up) [s]", "reaction", "dolfinx/cgcm: residual", "Jacobian", "solves"]
    table = []
    for c, d, agree in rows:
        for r in (c, d):
            line = [str(r["n"]), str(r["dofs"]), str(r["ranks"]), r["code"], str(r["newton"]), str(r["krylov"])]
            line += [f"{r[key] / r[count]:.3f}" if count else f"{r[key]:.2f} ({r['setup_s']:.2f})"
                     for key, count, _ in PHASES]
            line.append(f"{r['reaction']:.6f}")
            if r is c:
                line += [f"{(d[key] / (d[count] if count else 1)) / (c[key] / (c[count] if count else 1)):.2f}"
                         for key, count, _ in PHASES]
                if not agree:
                    line[-1] += " (reactions differ)"
            else:
                line += ["", "", ""]
            table.append(line)
    if args.markdown:
        print("| " + " | ".join(header) + " |")
        print("|" + "---|" * len(header))
        for line in table:
            print("| " + " | ".join(line) + " |")
    else:
        widths = [max(len(h), *(len(l[i]) for l in table)) if table else len(h) for i, h in enumerate(header)]
        print("  ".join(h.rjust(w) for h, w in zip(header, widths)))
        for line in table:
            print("  ".join(v.rjust(w) for v, w in zip(line, widths)))
    if not ok:
        sys.stderr.write("some run failed, did not converge, or the two codes' reaction forces differ\n")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
