#!/usr/bin/env bash
# Runs the decks of inputs/paper/ (the paper's Fig. 5 and 6 studies) into
# output/paper/<deck>/ and plots them into doc/figures/. Usage:
#   tools/run_paper_figures.sh [build-dir]        (make paper)
set -uo pipefail
build=${1:-build}
cd "$(dirname "$0")/.."
status=0
mkdir -p output/paper
for deck in inputs/paper/*.xml; do
  name=$(basename "$deck" .xml)
  printf '%-24s ' "$name"
  if "$build/bin/cgcm" "$deck" > "output/paper/$name.log" 2>&1 || true; then
    { head -1 "output/paper/$name/summary.txt" | tr '\n' ' '; grep -m1 '^P_min' "output/paper/$name/summary.txt"; } \
      2>/dev/null || { echo "failed (see output/paper/$name.log)"; status=1; }
  fi
done
/usr/bin/python3 tools/plot_load_curves.py --figures doc/figures output/paper
# the decks state gammaL bar = 50 and gammaW bar = 200, 20: literal reading
gL=52.4558; gW200=115.470; gW20=11.5470
/usr/bin/python3 tools/plot_md_comparison.py --analytic "$build/bin/cgcm-analytic" --gammaL $gL --gammaW $gW200 \
  --curve output/paper/fig6-gammaW-200/load_curve.csv --output doc/figures/md-comparison-gw200.png
/usr/bin/python3 tools/plot_md_comparison.py --analytic "$build/bin/cgcm-analytic" --gammaL $gL --gammaW $gW20 \
  --curve output/paper/fig6-gammaW-20/load_curve.csv --output doc/figures/md-comparison-gw20.png
exit $status
