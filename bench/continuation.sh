#!/usr/bin/env bash
# Cost of following a path with folds: the gammaL = 50, gammaW = 20 sphere on
# the level-0 mesh (jump-to-contact and jump-off), approach to u = 0.01 and
# retraction to -0.04, under displacement control (jumps found by
# continuation) and under arc-length control (the whole loop). Prints states,
# Newton iterations per state and the wall-time split of summary.txt.
set -euo pipefail
build=${1:-build}
cd "$(dirname "$0")/.."
out=output/bench-continuation
deck=inputs/sphere-on-half-space.xml
common=(Interaction/gammaL=50 Interaction/gammaW=20 "Loading/Approach Path={-0.04,0.01,-0.04}" "Output/Print Steps=false")
for control in displacement arc-length; do
  echo "== Loading/Control = $control"
  start=$(date +%s.%N)
  "$build/bin/cgcm" "$deck" "Loading/Control=$control" "Output/Directory=$out/$control" "${common[@]}" > /dev/null
  end=$(date +%s.%N)
  grep -E "^(states|wall time|P_min|fold|jump)" "$out/$control/summary.txt"
  awk -v s="$start" -v e="$end" 'BEGIN { printf "whole run (set-up included): %.2f s\n", e - s }'
done
