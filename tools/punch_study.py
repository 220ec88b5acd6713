#!/usr/bin/env python3
"""Pull-off force of a rigid flat punch on an elastic half-space over its size
in critical sizes, a / a_cr with a_cr = 8 E* w / (pi sigma_max^2) (Gao & Yao
2004), against the strength limit pi a^2 sigma_max (a << a_cr) and Kendall's
sqrt(8 pi a^3 E* w) (a >> a_cr), finite strain.

inputs/flat-punch.xml (axisymmetric; meshes/flat-punch.geo, a = 1, the punch
rigid) at gammaL = --gammaL (default 2000: r_S0 = 3.2e-4 a, so that the
critical size can be small against a while sigma_max / E* stays small); a/a_cr
is set by gammaW (a_cr ~ gammaW at fixed gammaL), so sigma_max / E* grows with
a/a_cr (0.05 at a = 50 a_cr with the default gammaL; the table says it). The
corner cells are a tenth of the smallest critical size (at most 0.002 a), over
2.5 of it. The approach presses the punch in by 2 r_S0; the retraction goes to
-(1.5 delta_c + 5 r_S0), with delta_c = (pi/2)(sigma_max/E*) a min(1,
sqrt(a_cr/a)) the punch's elastic approach at its pull-off, and is extended
(twice) while the minimum force lies at its end; the start moves out likewise
when the punch snaps onto the half-space there. P_min is the vertex of the
parabola through the lowest stable retraction state and its neighbours.

Writes table.csv and punch_study.png into --output.

    punch_study.py --build build --output output/punch-study [--sizes 0.05 0.2 1 5 20 50 100]
                   [--gammaL 2000] [--jobs 2] [--rerun] [--plan] [--plot-only]
"""
import concurrent.futures
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pulloff_map  # noqa: E402
from analytic_csv import rows  # noqa: E402
from cylinder_map import run_extended  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
NU = 0.2
ESTAR = 1.0 / (1.0 - NU * NU)  # a rigid punch on the half-space of Y = 1
BUILD = "build"
SIZES = [0.05, 0.2, 1.0, 5.0, 20.0, 50.0, 100.0]


def exe():
    return os.path.join(BUILD, "bin", "cgcm-analytic")


def interaction(gl, gw):
    m = rows(exe(), "map", "--gammaL", f"{gl:.12g}", "--gammaW", f"{gw:.12g}", "--nu", f"{NU}")[0]
    w, s = float(m["w"]), float(m["sigma_max"])
    return w, s, 8.0 * ESTAR * w / (math.pi * s * s)


def plan(size, gl, smallest, extension=0):
    """Deck overrides of the punch at a = size critical sizes (a = 1); `smallest` is the smallest
    critical size of the study (the corner cells resolve it)."""
    w1, s1, acr1 = interaction(gl, 100.0)
    gw = 100.0 * (1.0 / size) / acr1  # a_cr ~ gammaW
    w, s, acr = interaction(gl, gw)
    r0 = 1.0 / gl
    rs0 = r0 / 15 ** (1 / 6)
    corner = min(0.002, smallest / 10.0)
    delta_c = 0.5 * math.pi * (s / ESTAR) * min(1.0, math.sqrt(acr))
    u_in = 2.0 * rs0
    u_end = -(1.5 * delta_c + 5.0 * rs0) * 2 ** extension
    u_start = -8.0 * rs0 * 2 ** extension  # strong adhesion snaps the punch in from further away
    step = min(rs0 / 2.0, (u_in - u_end) / 120.0)
    path = f"{{{u_start:.6g},{u_in:.6g},{u_end:.6g}}}"
    overrides = [f"Interaction/gammaL={gl:.12g}", f"Interaction/gammaW={gw:.12g}",
                 f"Geometry/Mesh Numbers/gap={rs0:.6g}", "Geometry/Mesh Numbers/lc=0.02",
                 f"Geometry/Mesh Numbers/lcCorner={corner:.4g}",
                 f"Geometry/Mesh Numbers/cornerZone={max(0.05, 2.5 * smallest):.4g}",
                 f"Loading/Approach Path={path}", f"Loading/Initial Increment={step:.6g}",
                 f"Loading/Max Increment={step:.6g}", f"Loading/Min Increment={step * 1e-5:.6g}",
                 # from about 20 a_cr the detachment is one jump across the face, longer than the
                 # default 400 relaxation iterations (measured at 20 a_cr: stopped at 400, done at 4000)
                 "Loading/Relaxation Iterations=4000",
                 "Output/Print Steps=false", "Output/Exodus=false", "Output/Checkpoint=false"]
    kendall = math.sqrt(8.0 * math.pi * ESTAR * w)  # a = 1
    return {"size": size, "gammaL": gl, "gammaW": gw, "w": w, "sigma_max": s, "a_cr": acr, "path": path,
            "overrides": overrides, "kendall": kendall, "strength": math.pi * s, "corner": corner,
            "smallest": smallest}


def run_case(case, out, rerun):
    """One case (cylinder_map.run_extended)."""
    name = f"gL{case['gammaL']:g}-size{case['size']:.3g}"

    def args_of(extension, folder):
        c = case if extension == 0 else plan(case["size"], case["gammaL"], case["smallest"], extension)
        return [os.path.join(BUILD, "bin", "cgcm"), os.path.join(ROOT, "inputs", "flat-punch.xml"),
                f"Output/Directory={folder}", *c["overrides"]]

    return name, run_extended(name, out, rerun, args_of)


def main():
    global BUILD
    ap = pulloff_map.study_parser(__doc__, "output/punch-study")
    ap.add_argument("--sizes", type=float, nargs="+", default=SIZES, help="a / a_cr of the cases")
    ap.add_argument("--gammaL", type=float, default=2000.0)
    args = pulloff_map.parse_study_args(ap)
    BUILD = args.build
    if any(not x > 0.0 for x in args.sizes):
        ap.error("--sizes must be > 0 (multiples of the critical size)")
    os.makedirs(args.output, exist_ok=True)
    table = os.path.join(args.output, "table.csv")
    if not args.plot_only:
        smallest = 1.0 / max(args.sizes)
        cases = [plan(x, args.gammaL, smallest) for x in args.sizes]
        for c in cases:
            print(f"a = {c['size']:g} a_cr: gammaW {c['gammaW']:.4g}, sigma_max/E* {c['sigma_max'] / ESTAR:.3g}, "
                  f"corner cells {c['corner']:.3g}, path {c['path']}", flush=True)
        if args.plan:
            return
        results = {}
        with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
            for name, r in pool.map(lambda c: run_case(c, args.output, args.rerun), cases):
                results[name] = r
                print(f"{name}: {r['status']}, {r['seconds']:.0f} s, P_min {r.get('P_min', float('nan')):.6g}"
                      f"{'' if r.get('inside', False) else ' (at the end of the path)'}", flush=True)
        with open(table, "w", newline="") as f:
            out = csv.writer(f)
            out.writerow(["a_over_acr", "gammaL", "gammaW", "sigma_max_over_Estar", "P_over_strength",
                          "P_over_kendall", "kendall_over_strength", "seconds", "status"])
            for c in cases:
                r = results[f"gL{c['gammaL']:g}-size{c['size']:.3g}"]
                p = -r.get("P_min", float("nan"))
                status = r["status"] + ("" if r.get("inside", False) else " (minimum not inside)")
                out.writerow([f"{c['size']:g}", f"{c['gammaL']:g}", f"{c['gammaW']:.6g}",
                              f"{c['sigma_max'] / ESTAR:.4g}", f"{p / c['strength']:.4f}", f"{p / c['kendall']:.4f}",
                              f"{c['kendall'] / c['strength']:.4f}", f"{r['seconds']:.0f}",
                              "ok" if status == "completed" else status])
        print(f"wrote {table}")
    plot(table, os.path.join(args.output, "punch_study.png"))


def plot(table, png):
    with open(table, newline="") as f:
        data = list(csv.DictReader(f))
    xs = [10 ** (math.log10(0.02) + i * (math.log10(300.0) - math.log10(0.02)) / 60) for i in range(61)]
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    ax.plot(xs, [1.0 for _ in xs], ":", color="0.5", lw=1.0, label="strength limit  π a² σ_max")
    ax.plot(xs, [1.0 / math.sqrt(x) for x in xs], "k--", lw=1.0, label="Kendall  √(8π a³ E* w)")
    x = [float(r["a_over_acr"]) for r in data]
    ax.plot(x, [float(r["P_over_strength"]) for r in data], "o-", color="C0", ms=6, lw=0.8,
            label="CGCM, rigid punch, finite strain")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("punch radius in critical sizes  a / a_cr,  a_cr = 8 E* w / (π σ_max²)")
    ax.set_ylabel("pull-off force / (π a² σ_max)")
    ax.legend(fontsize=8, loc="lower left")
    ax.grid(True, which="both", lw=0.3, alpha=0.5)
    fig.tight_layout()
    fig.savefig(png, dpi=130)
    print(f"wrote {png}")


if __name__ == "__main__":
    main()
