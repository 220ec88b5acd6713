#!/usr/bin/env bash
# Regenerates every figure of doc/validation.md (make figures) and the tables
# behind them (output/figures/*.csv). Usage: tools/make_figures.sh [build-dir]
#
#   Figs. 5, 6            the decks of inputs/paper/ (tools/run_paper_figures.sh)
#   Figs. 9a, 11a         their M-D comparisons (tools/plot_md_comparison.py)
#   Figs. 7, 8            the analytic models (tools/plot_analytic_models.py)
#   Figs. 9b, 10, 11b,    pressure, sigma_z and the five states of the paper's two
#   12, 13                M-D comparisons (tools/plot_paper_states.py)
#   demo, soft JKR        the default deck; the soft sphere on mesh levels 0 and 1
#   JKR limit, stability  the long studies (make jkr-study, stability-map,
#   map, pull-off map,    pulloff-map, jkr-end, method-study,
#   JKR end, Method 1     mesh-convergence): run if their tables are missing
#   vs 3, mesh conv.      under output/, otherwise plotted from them
#
# The plain (unbarred) gammaL, gammaW of the paper decks: literal reading of
# gammaL bar = 50 and gammaW bar = 200, 20 (doc/theory.md).
set -uo pipefail
build=${1:-build}
cd "$(dirname "$0")/.."
start=$(date +%s)
status=0
step() { printf '\n== %s (%d s)\n' "$1" $(( $(date +%s) - start )); }
py=/usr/bin/python3
analytic="$build/bin/cgcm-analytic"
mkdir -p output/figures doc/figures

step "paper decks: Figs. 5, 6"
bash tools/run_paper_figures.sh "$build" || status=1

step "analytic models: Figs. 7, 8"
$py tools/plot_analytic_models.py --analytic "$analytic" --fig7 doc/figures/fig7-analytic-pressure.png \
  --fig8 doc/figures/fig8-analytic-load-curves.png --table output/figures/analytic-pulloff.csv || status=1

gL=52.4558
step "gammaW bar = 200 at u = 0.043: Figs. 9b, 10"
$py tools/plot_paper_states.py --analytic "$analytic" --run output/paper/fig6-gammaW-200 --gammaL $gL \
  --gammaW 115.470 --at-u 0.043 --label "gammaL bar = 50, gammaW bar = 200" \
  --pressure doc/figures/fig9b-pressure.png --stress doc/figures/fig10-sigma-z.png \
  --table output/figures/fig9-state.csv || status=1
step "gammaW bar = 20 at P = 0: Figs. 11b, 12, 13"
$py tools/plot_paper_states.py --analytic "$analytic" --run output/paper/fig6-gammaW-20 --gammaL $gL \
  --gammaW 11.5470 --at-zero-load --stress-lambda theoretical --label "gammaL bar = 50, gammaW bar = 20" \
  --pressure doc/figures/fig11b-pressure.png --stress doc/figures/fig12-sigma-z.png \
  --states doc/figures/fig13-states.png --table output/figures/fig11-state.csv || status=1

step "the M-D comparisons of the load curves, states marked: Figs. 9a, 11a"
marks() { awk -F, -v pat="$2" '$1 ~ pat {print $2}' "$1" | paste -sd, -; }
$py tools/plot_md_comparison.py --analytic "$analytic" --gammaL $gL --gammaW 115.470 \
  --curve output/paper/fig6-gammaW-200/load_curve.csv --mark=$(marks output/figures/fig9-state.csv '^u$') \
  --output doc/figures/md-comparison-gw200.png || status=1
$py tools/plot_md_comparison.py --analytic "$analytic" --gammaL $gL --gammaW 11.5470 \
  --curve output/paper/fig6-gammaW-20/load_curve.csv --mark=$(marks output/figures/fig11-state.csv '^state_._u$') \
  --output doc/figures/md-comparison-gw20.png || status=1

step "default deck"
"$build/bin/cgcm" inputs/sphere-on-half-space.xml Output/Directory=output/figures/demo \
  > output/figures/demo.log 2>&1 || status=1
$py tools/plot_load_curves.py --output doc/figures/demo-load-curve.png output/figures/demo/load_curve.csv || status=1

step "soft sphere in the JKR regime, levels 0 and 1"
for level in 0 1; do
  "$build/bin/cgcm" inputs/sphere-on-half-space.xml Output/Directory=output/figures/soft-jkr-level$level \
    Interaction/gammaL=100 Interaction/gammaW=4.07 "Loading/Approach Path={-0.05,0.05,-0.12}" \
    "Geometry/Mesh Refinement=$level" Output/Exodus=false > output/figures/soft-jkr-level$level.log 2>&1 || status=1
done
$py tools/plot_load_curves.py --output doc/figures/soft-jkr.png \
  output/figures/soft-jkr-level0/load_curve.csv output/figures/soft-jkr-level1/load_curve.csv || status=1

step "long studies (cached under output/ when present)"
if [ -s output/validation/jkr-study/table.csv ]; then
  $py tools/plot_jkr_limit.py --analytic "$analytic" --table output/validation/jkr-study/table.csv \
    --output doc/figures/jkr-limit.png || status=1
else
  make --no-print-directory jkr-study BUILD_DIR="$build" || status=1
fi
if [ -s output/stability-map/stability_boundary.csv ] && [ -s output/stability-map/stability_map.png ]; then
  cp output/stability-map/stability_map.png doc/figures/stability-map.png
else
  make --no-print-directory stability-map BUILD_DIR="$build" || status=1
fi
if [ -s output/pulloff-map/table.csv ]; then
  $py tools/pulloff_map.py --build "$build" --output output/pulloff-map --plot-only || status=1
  cp output/pulloff-map/pulloff_map.png doc/figures/pulloff-map.png
else
  make --no-print-directory pulloff-map BUILD_DIR="$build" || status=1
fi
if [ -s output/validation/jkr-end/table.csv ]; then
  $py tools/jkr_end_study.py --build "$build" --output output/validation/jkr-end --plot-only || status=1
  cp output/validation/jkr-end/jkr_end.png doc/figures/jkr-end.png
else
  make --no-print-directory jkr-end BUILD_DIR="$build" || status=1
fi
if [ ! -s output/validation/mesh-convergence/orders.csv ]; then
  make --no-print-directory mesh-convergence BUILD_DIR="$build" || status=1
fi
if [ -s output/validation/method-study/table.csv ]; then
  $py tools/plot_method_study.py output/validation/method-study --output doc/figures/method1-vs-method3.png || status=1
else
  make --no-print-directory method-study BUILD_DIR="$build" || status=1
fi

step "done (status $status)"
exit $status
