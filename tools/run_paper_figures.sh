#!/usr/bin/env bash
# Runs the decks of inputs/paper/ (the paper's Fig. 5 and 6 studies) into
# output/paper/<deck>/ and plots Figs. 5 and 6 into doc/figures/ (the M-D
# comparisons of these runs: tools/make_figures.sh). Usage:
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
exit $status
