#!/usr/bin/env bash
# Two ranks against one, and what this machine allows:
#  - the ceiling: one Newton iteration of the 312k-unknown hex8 box on one
#    rank alone, then two such one-rank runs at once (no communication at
#    all: what is lost is the cores sharing memory bandwidth and caches);
#  - the same box on two ranks;
#  - the 3D sphere deck at lcContact = 0.02 (27k unknowns, 14 states) on one
#    rank and on two with the geometric and the contiguous cell partition
#    (summary.txt: the split of the path).
# Not a test: the numbers go into doc/performance.md.
set -euo pipefail
build=${1:-build}
mpi="mpirun --allow-run-as-root --oversubscribe --mca mpi_yield_when_idle 1"
box=("$build/bin/bench_newton_iteration" 3D 46 46 46 "Belos GMRES + MueLu" 2)
echo "-- box, one rank alone"
"${box[@]}"
echo "-- box, two independent one-rank runs at once"
"${box[@]}" > /tmp/cgcm-ceiling-a.txt & "${box[@]}" > /tmp/cgcm-ceiling-b.txt; wait
cat /tmp/cgcm-ceiling-a.txt /tmp/cgcm-ceiling-b.txt
echo "-- box, two ranks"
$mpi -np 2 "${box[@]}"
out=output/bench-parallel
sphere=(inputs/3d/sphere-on-half-space.xml "Output/Print Steps=false" "Output/Exodus=false"
        "Loading/Approach Path={-0.02,0.004}" "Geometry/Mesh Numbers/lcContact=0.02")
"$build/bin/cgcm" "${sphere[@]}" "Output/Directory=$out/np1" > /dev/null
for partition in geometric contiguous; do
  $mpi -np 2 "$build/bin/cgcm" "${sphere[@]}" "Output/Directory=$out/np2-$partition" "Solver/Partition=$partition" > /dev/null
done
for run in np1 np2-geometric np2-contiguous; do
  echo "-- 3D sphere, 27k unknowns: $run"
  grep -E "^states|^linear solves|^wall time" "$out/$run/summary.txt"
done
