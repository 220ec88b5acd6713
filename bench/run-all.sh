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
"$build/bin/bench_newton_iteration" 3D 32 32 32 "Belos GMRES + Ifpack2" 1
$mpi -np 2 "$build/bin/bench_newton_iteration" 3D 32 32 32 "Belos GMRES + Ifpack2" 1
"$build/bin/bench_newton_iteration" 3D 46 46 46 "Belos GMRES + Ifpack2" 1
