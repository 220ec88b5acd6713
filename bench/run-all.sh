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
"$build/bin/bench_newton_iteration" axisymmetric 38 38 "MUMPS"
"$build/bin/bench_newton_iteration" 3D 32 32 32 "Belos GMRES + MueLu" 1
$mpi -np 2 "$build/bin/bench_newton_iteration" 3D 32 32 32 "Belos GMRES + MueLu" 1
"$build/bin/bench_newton_iteration" 3D 46 46 46 "Belos GMRES + MueLu" 1
echo "== one approach-retraction curve of the default deck (split in summary.txt)"
"$build/bin/cgcm" inputs/sphere-on-half-space.xml Output/Directory=output/bench-demo "Output/Print Steps=false"
cat output/bench-demo/summary.txt
echo "== the linear solvers on the default deck, mesh levels 0 and 1"
bash bench/linear_solvers.sh "$build" 0 1
echo "== the 3D iterative solver: near-null space, forcing term (GMRES + MueLu)"
bash bench/iterative_solvers_3d.sh "$build"
echo "== two ranks against one: the machine's ceiling, the box, the 3D sphere per partition"
bash bench/parallel_efficiency.sh "$build"
echo "== what each rank holds, 1 to 4 ranks; glibc's mmap threshold; keeping the preconditioner"
bash bench/rank_memory.sh "$build"
echo "== Method 3 kernel and search, per pair"
"$build/bin/bench_interaction_kernel"
echo "== closest-point search: AABB build and queries per Newton iteration"
"$build/bin/bench_closest_point"
echo "== the search's share of 3D runs (summary.txt: interaction, closest-point search, solves)"
"$build/bin/cgcm" inputs/3d/sphere-on-half-space.xml Output/Directory=output/bench-3d-sphere "Output/Print Steps=false" \
  "Loading/Approach Path={-0.02,0.004}"
tail -2 output/bench-3d-sphere/summary.txt
"$build/bin/cgcm" inputs/3d/three-spheres.xml Output/Directory=output/bench-3d-three-spheres "Output/Print Steps=false" \
  "Loading/Approach Path={0.03,0.041,0.034}"
tail -2 output/bench-3d-three-spheres/summary.txt
echo "== Method 1 (volume pairs): kernel throughput on one and two ranks"
bash bench/method1.sh "$build"
echo "== a path through folds: displacement against arc-length control"
bash bench/continuation.sh "$build"
