#!/usr/bin/env bash
# Method 1 (volume pairs) against Method 3 (half-space points) on the paper's
# benchmark (axisymmetric sphere on half-space, gammaW = 200) for gammaL = 2,
# 5, 20, 50, 200: the same path in units of r0 (approach from -r0 to 3 r0,
# retract to -1.5 r0), the contact zone scaled so that the cells at the
# surface stay about 1.25 r0 (or finer) long: zone = ZONE_FACTOR / gammaL
# (ZONE_FACTOR = 25; 12.5 halves the cells), at most 0.85. METHODS selects
# the methods (default both), LEVEL the Mesh Refinement (default 0: each
# level halves every cell), CUTOFF the cutoff in r0 (default 10), APPROACH
# the path's waypoints in r0 (default -1,3,-1.5). Appends P_min and its u per case to
# output/validation/method-study/table.csv. Usage:
#   [ZONE_FACTOR=..] [METHODS=..] [LEVEL=..] [CUTOFF=..] [APPROACH=..] tools/run_method_study.sh [build-dir] [gammaL ...]   (make method-study)
set -uo pipefail
build=${1:-build}
shift || true
gammas=("$@")
[ ${#gammas[@]} -eq 0 ] && gammas=(50 20 200 5 2)
cd "$(dirname "$0")/.."
out=output/validation/method-study
mkdir -p "$out"
deck=inputs/sphere-on-half-space.xml
table=$out/table.csv
[ -f "$table" ] || echo "gammaL,zone,level,cutoff,method,P_min,u_at_P_min,states,newton,path_seconds,interaction_seconds" > "$table"
factor=${ZONE_FACTOR:-25}
cutoff=${CUTOFF:-10}
level=${LEVEL:-0}
IFS=',' read -ra approach <<< "${APPROACH:--1,3,-1.5}"
IFS=',' read -ra methods <<< "${METHODS:-half-space point,volume pair}"
for g in "${gammas[@]}"; do
  r0=$(awk -v g="$g" 'BEGIN { printf "%.10g", 1 / g }')
  zone=$(awk -v g="$g" -v f="$factor" 'BEGIN { z = f / g; if (z > 0.85) z = 0.85; printf "%.6g", z }')
  path="{$(for a in "${approach[@]}"; do awk -v r="$r0" -v a="$a" 'BEGIN { printf "%.10g,", a * r }'; done)"
  path="${path%,}}"
  inc=$(awk -v r="$r0" 'BEGIN { printf "%.10g", 0.05 * r }')
  maxinc=$(awk -v r="$r0" 'BEGIN { printf "%.10g", 0.1 * r }')
  for method in "${methods[@]}"; do
    name="gammaL$g-zone$zone-level$level-cutoff$cutoff-${method// /-}"
    "$build/bin/cgcm" "$deck" "Output/Directory=$out/$name" "Output/Print Steps=false" "Interaction/gammaL=$g" \
      "Interaction/Method=$method" "Interaction/Cutoff=$cutoff" "Geometry/Contact Zone Size=$zone" \
      "Geometry/Mesh Refinement=$level" \
      "Loading/Approach Path=$path" \
      "Loading/Initial Increment=$inc" "Loading/Max Increment=$maxinc" > "$out/$name.log" 2>&1
    s=$out/$name/summary.txt
    pmin=$(sed -n 's/^P_min = \([0-9.e+-]*\) at u = \([0-9.e+-]*\) .*/\1,\2/p' "$s" 2>/dev/null)
    [ -z "$pmin" ] && pmin="stopped,"
    states=$(sed -n 's/^states = \([0-9]*\) .*Newton iterations = \([0-9]*\) .*/\1,\2/p' "$s" 2>/dev/null)
    times=$(sed -n 's/^wall time of the path \([0-9.]*\) s = .* interaction \([0-9.]*\) s .*/\1,\2/p' "$s" 2>/dev/null)
    echo "$g,$zone,$level,$cutoff,$method,$pmin,$states,$times" | tee -a "$table"
  done
done
