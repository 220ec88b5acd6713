#!/usr/bin/env bash
# Method 1 (volume pairs) on the default deck's approach into adhesive contact
# (u from -0.02 to 0.01), the same iterative solver on one and two MPI ranks:
# the kernel's throughput (quadrature-point pairs per second, the slowest
# rank's kernel time) and the interaction's share of the path, from
# summary.txt; the parallel efficiency of the kernel is t1 / (2 t2).
set -euo pipefail
build=${1:-build}
cd "$(dirname "$0")/.."
out=output/bench-method1
deck=inputs/sphere-on-half-space.xml
mpi="mpirun --allow-run-as-root --oversubscribe --mca mpi_yield_when_idle 1"
common=("Interaction/Method=volume pair" "Loading/Approach Path={-0.02,0.01}" "Output/Print Steps=false"
        "Solver/Linear Solver/Type=Belos GMRES + Ifpack2")
"$build/bin/cgcm" "$deck" "Output/Directory=$out/np1" "${common[@]}" > /dev/null
$mpi -np 2 "$build/bin/cgcm" "$deck" "Output/Directory=$out/np2" "${common[@]}" > /dev/null
for np in 1 2; do
  echo "== $np rank(s)"
  grep -E "^(states|wall time|volume pairs)" "$out/np$np/summary.txt"
done
t1=$(sed -n 's/.*kernel \([0-9.e+-]*\) s for.*/\1/p' "$out/np1/summary.txt")
t2=$(sed -n 's/.*kernel \([0-9.e+-]*\) s for.*/\1/p' "$out/np2/summary.txt")
awk -v a="$t1" -v b="$t2" 'BEGIN { printf "kernel: %.3f s on 1 rank, %.3f s on 2 (slowest rank): parallel efficiency %.0f %%\n", a, b, 100 * a / (2 * b) }'
