#!/usr/bin/env bash
# Method 1 (volume pairs) against Method 3 (half-space points) on the paper's
# benchmark (axisymmetric sphere on half-space, gammaW = 200) for gammaL = 2,
# 5, 20, 50, 200: the same path in units of r0 (approach from -r0 to 3 r0,
# retract to -1.5 r0), the contact zone scaled so that the cells at the
# surface stay about 1.25 r0 (or finer) long. Writes the table of P_min and
# its u per method to output/validation/method-study/table.csv. Usage:
#   tools/run_method_study.sh [build-dir] [gammaL ...]   (make method-study)
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
[ -f "$table" ] || echo "gammaL,method,P_min,u_at_P_min,states,newton,path_seconds,interaction_seconds" > "$table"
for g in "${gammas[@]}"; do
  r0=$(awk -v g="$g" 'BEGIN { printf "%.10g", 1 / g }')
  zone=$(awk -v g="$g" 'BEGIN { z = 25 / g; if (z > 0.85) z = 0.85; printf "%.6g", z }')
  path="{$(awk -v r="$r0" 'BEGIN { printf "%.10g,%.10g,%.10g", -r, 3 * r, -1.5 * r }')}"
  inc=$(awk -v r="$r0" 'BEGIN { printf "%.10g", 0.05 * r }')
  maxinc=$(awk -v r="$r0" 'BEGIN { printf "%.10g", 0.1 * r }')
  for method in "half-space point" "volume pair"; do
    name="gammaL$g-${method// /-}"
    "$build/bin/cgcm" "$deck" "Output/Directory=$out/$name" "Output/Print Steps=false" "Interaction/gammaL=$g" \
      "Interaction/Method=$method" "Geometry/Contact Zone Size=$zone" "Loading/Approach Path=$path" \
      "Loading/Initial Increment=$inc" "Loading/Max Increment=$maxinc" > "$out/$name.log" 2>&1
    s=$out/$name/summary.txt
    pmin=$(sed -n 's/^P_min = \([0-9.e+-]*\) at u = \([0-9.e+-]*\) .*/\1,\2/p' "$s" 2>/dev/null)
    [ -z "$pmin" ] && pmin="stopped,"
    states=$(sed -n 's/^states = \([0-9]*\) .*Newton iterations = \([0-9]*\) .*/\1,\2/p' "$s" 2>/dev/null)
    times=$(sed -n 's/^wall time of the path \([0-9.]*\) s = .* interaction \([0-9.]*\) s .*/\1,\2/p' "$s" 2>/dev/null)
    echo "$g,$method,$pmin,$states,$times" | tee -a "$table"
  done
done
