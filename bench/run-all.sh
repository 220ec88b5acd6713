#!/usr/bin/env bash
# Runs every benchmark and prints its figures. Not a test: the numbers go into
# the issue notes and doc/, never into a pass/fail check.
set -euo pipefail
build=${1:-build}
mpi="mpirun --allow-run-as-root --oversubscribe --mca mpi_yield_when_idle 1"
echo "== element kernels (one core)"
"$build/bin/bench_fem_kernel"
echo "== one Newton iteration of the bulk problem"
"$build/bin/bench_newton_iteration" axisymmetric 38 38 "Amesos2 KLU2"
"$build/bin/bench_newton_iteration" 3D 32 32 32 "Belos GMRES + MueLu" 1
$mpi -np 2 "$build/bin/bench_newton_iteration" 3D 32 32 32 "Belos GMRES + MueLu" 1
"$build/bin/bench_newton_iteration" 3D 46 46 46 "Belos GMRES + MueLu" 1
echo "== one approach-retraction curve of the default deck (split in summary.txt)"
"$build/bin/cgcm" inputs/sphere-on-half-space.xml Output/Directory=output/bench-demo "Output/Print Steps=false"
cat output/bench-demo/summary.txt
echo "== Method 3 kernel and search, per pair"
"$build/bin/bench_interaction_kernel"
echo "== closest-point search: AABB build and queries per Newton iteration"
"$build/bin/bench_closest_point"
echo "== a path through folds: displacement against arc-length control"
bash bench/continuation.sh "$build"
