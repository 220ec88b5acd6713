#!/usr/bin/env bash
# The linear solvers side by side on the default deck (one rank) at mesh
# levels 0-2: Newton iterations and the wall-time split of each path, from
# summary.txt; MUMPS with both of its orderings. Levels as arguments (default
# 0 1 2; level 2 takes minutes).
#   bench/linear_solvers.sh [build-dir] [levels...]
set -uo pipefail
build=${1:-build}
shift || true
levels=${*:-0 1 2}
solvers=(
  "MUMPS|MUMPS Ordering=AMD"
  "MUMPS|MUMPS Ordering=PORD"
  "Amesos2 KLU2|"
  "Belos GMRES + Ifpack2|"
)
for level in $levels; do
  for solver in "${solvers[@]}"; do
    type=${solver%%|*}
    option=${solver#*|}
    label="$type${option:+, $option}"
    args=("Solver/Linear Solver/Type=$type")
    [ -n "$option" ] && args+=("Solver/Linear Solver/$option")
    out=output/bench-linear-solvers/level$level-${label//[ ,=+]/_}
    "$build/bin/cgcm" inputs/sphere-on-half-space.xml "Output/Directory=$out" "Output/Print Steps=false" \
      "Geometry/Mesh Refinement=$level" "${args[@]}" > /dev/null 2>&1
    echo "level $level, $label:"
    grep -E "^(P_min|states|wall time)" "$out/summary.txt" | sed 's/^/  /'
  done
done
