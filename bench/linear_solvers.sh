#!/usr/bin/env bash
# The linear solvers side by side on the default deck (one rank) at mesh
# levels 0-2: Newton iterations and the wall-time split of each path, from
# summary.txt. Levels as arguments (default 0 1 2; level 2 takes minutes).
#   bench/linear_solvers.sh [build-dir] [levels...]
set -uo pipefail
build=${1:-build}
shift || true
levels=${*:-0 1 2}
for level in $levels; do
  for type in "MUMPS" "Amesos2 KLU2" "Belos GMRES + Ifpack2"; do
    out=output/bench-linear-solvers/level$level-${type// /_}
    "$build/bin/cgcm" inputs/sphere-on-half-space.xml "Output/Directory=$out" "Output/Print Steps=false" \
      "Geometry/Mesh Refinement=$level" "Solver/Linear Solver/Type=$type" > /dev/null 2>&1
    echo "level $level, $type:"
    grep -E "^(P_min|states|wall time)" "$out/summary.txt" | sed 's/^/  /'
  done
done
