#!/usr/bin/env bash
# What each rank holds and what memory it takes, 1 to 4 ranks, and two ways
# of trading memory (doc/performance.md, "What each rank holds" and "Keeping
# the preconditioner"):
#  - the 3D sphere deck at lcContact = 0.0075 (about 326k unknowns; HXT mesh,
#    kept in a mesh cache so that every run has the same mesh), its first two
#    states, on 1, 2, 3 and 4 ranks (3 and 4 oversubscribe a 2-core machine:
#    only the sizes count), and the same deck at lcContact = 0.2 as the empty
#    run (libraries, MPI, gmsh); results.e written, as by default (rank 0
#    writes what the ranks stream to it);
#  - on 2 ranks, glibc's moving mmap threshold (CGCM_MMAP_THRESHOLD=0)
#    against cgcm's fixed 4 MiB;
#  - on 2 ranks, five states, Preconditioner Reuse 0 against 3.
# Not a test: the numbers go into doc/performance.md. About 10 minutes.
set -euo pipefail
build=${1:-build}
mpi="mpirun --allow-run-as-root --oversubscribe --mca mpi_yield_when_idle 1"
out=output/bench-rank-memory
deck=(inputs/3d/sphere-on-half-space.xml "Output/Print Steps=false"
      "Geometry/Gmsh Options/Mesh.Algorithm3D=10" "Geometry/Gmsh Options/General.NumThreads=2"
      "Geometry/Mesh Cache=$PWD/$out/mesh-cache")
mkdir -p "$out/mesh-cache"
show() {  # the lines of a run's summary.txt that this benchmark is about
  echo "-- $1"
  grep -E "^P_min|^states|^linear solves|^wall time of the path|^peak memory|^mesh held" "$out/$1/summary.txt"
}
for p in 1 2 4; do
  $mpi -np $p "$build/bin/cgcm" "${deck[@]}" "Geometry/Mesh Numbers/lcContact=0.2" \
    "Geometry/Mesh Numbers/lcSphere=0.4" "Geometry/Mesh Numbers/lcFar=2.0" \
    "Loading/Approach Path={-0.02,-0.019}" "Output/Directory=$out/empty-np$p" > /dev/null
  show "empty-np$p"
done
sized=("${deck[@]}" "Geometry/Mesh Numbers/lcContact=0.0075")
for p in 1 2 3 4; do
  $mpi -np $p "$build/bin/cgcm" "${sized[@]}" "Loading/Approach Path={-0.02,-0.019}" "Output/Directory=$out/np$p" > /dev/null
  show "np$p"
done
CGCM_MMAP_THRESHOLD=0 $mpi -x CGCM_MMAP_THRESHOLD -np 2 "$build/bin/cgcm" "${sized[@]}" \
  "Loading/Approach Path={-0.02,-0.019}" "Output/Directory=$out/np2-moving-threshold" > /dev/null
show np2-moving-threshold
for reuse in 0 3; do
  $mpi -np 2 "$build/bin/cgcm" "${sized[@]}" "Loading/Approach Path={-0.02,-0.015}" \
    "Solver/Linear Solver/Preconditioner Reuse=$reuse" "Output/Directory=$out/np2-reuse$reuse" > /dev/null
  show "np2-reuse$reuse"
done
