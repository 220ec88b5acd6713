#!/usr/bin/env bash
# The 3D iterative solver, GMRES + MueLu (Chebyshev smoothing), side by side:
#  - one Newton iteration of the hex8 Neo-Hookean box (bench_newton_iteration)
#    at 108k and 312k unknowns with MueLu's translations or the rigid-body
#    modes as near-null space, on one rank, and at 312k on two;
#  - the 3D sphere deck at lcContact = 0.02 (27k unknowns) over its first
#    states with the constant and the Eisenstat-Walker forcing term, and with
#    both near-null spaces (summary.txt: Newton iterations, linear solves and
#    Krylov iterations, the time split).
# Not a test: the numbers go into doc/performance.md.
set -euo pipefail
build=${1:-build}
mpi="mpirun --allow-run-as-root --oversubscribe --mca mpi_yield_when_idle 1"
for n in 32 46; do
  for space in translations rigid; do
    "$build/bin/bench_newton_iteration" 3D $n $n $n "Belos GMRES + MueLu" 1 $space
  done
done
$mpi -np 2 "$build/bin/bench_newton_iteration" 3D 46 46 46 "Belos GMRES + MueLu" 1 translations
out=output/bench-3d-solvers
for forcing in Eisenstat-Walker constant; do
  for space in translations "rigid body modes"; do
    dir="$out/$forcing-${space// /-}"
    "$build/bin/cgcm" inputs/3d/sphere-on-half-space.xml "Output/Directory=$dir" "Output/Print Steps=false" \
      "Output/Exodus=false" "Loading/Approach Path={-0.02,-0.012}" "Geometry/Mesh Numbers/lcContact=0.02" \
      "Solver/Linear Solver/Forcing Term=$forcing" "Solver/Linear Solver/MueLu Near Null Space=$space"
    echo "-- forcing term $forcing, near-null space $space"
    grep -E "^states|^linear solves|^wall time" "$dir/summary.txt"
  done
done
