#!/usr/bin/env bash
# The JKR end of the pull-off force (issue: soft bodies, large lambda): the
# CGCM minimum force at Maugis-Dugdale lambda = 3 (Tabor mu = 2.6) on
# successively finer meshes and at two gammaL, against the Lennard-Jones
# sphere reference (cgcm-analytic ljsphere) and JKR's -1.5 pi w R. Usage:
#   tools/run_jkr_study.sh [build-dir]        (make jkr-study; about 12 min)
set -uo pipefail
build=${1:-build}
cd "$(dirname "$0")/.."
out=output/validation/jkr-study
mkdir -p "$out"
deck=inputs/validation/jkr-limit.xml
# name | overrides of the deck (gammaL = 800, gammaW = 24.8, level 1, zone 0.1)
g200="Interaction/gammaL=200;Interaction/gammaW=12.4;Loading/Approach Path={-0.015,0.01,-0.009};Loading/Initial Increment=0.0005;Loading/Max Increment=0.0005"
base="Geometry/Mesh Refinement=0;Geometry/Contact Zone Size=0.5;Loading/Initial Increment=0.001;Loading/Max Increment=0.002"
cases=(
  "gammaL50-gammaW200-L0|$base;Interaction/gammaL=50;Interaction/gammaW=200;Loading/Approach Path={-0.02,0.06,-0.03}"
  "gammaL50-gammaW20-L0|$base;Interaction/gammaL=50;Interaction/gammaW=20;Loading/Approach Path={-0.03,0.0,-0.04}"
  "gammaL200-L1-zone0.3|$g200;Geometry/Contact Zone Size=0.3"
  "gammaL200-L1-zone0.2|$g200;Geometry/Contact Zone Size=0.2"
  "gammaL200-L2-zone0.3|$g200;Geometry/Contact Zone Size=0.3;Geometry/Mesh Refinement=2"
  "gammaL200-L2-zone0.2|$g200;Geometry/Contact Zone Size=0.2;Geometry/Mesh Refinement=2"
  "gammaL800-L1-zone0.1|"
  "gammaL800-L2-zone0.1|Geometry/Mesh Refinement=2"
)
printf '%-22s %7s %7s %7s %11s %10s %10s\n' case mu lambda nodes 'P_min/piwR' 'LJ sphere' 'M-D'
echo "case,mu,lambda,nodes,P_min_over_piwR,lj_sphere,maugis_dugdale" > "$out/table.csv"
for c in "${cases[@]}"; do
  name=${c%%|*}
  IFS=';' read -ra args <<< "${c#*|}"
  "$build/bin/cgcm" "$deck" "Output/Directory=$out/$name" "${args[@]}" > "$out/$name.log" 2>&1
  mu=$(sed -n 's/.*Tabor mu = \([0-9.e+-]*\),.*/\1/p' "$out/$name.log")
  twopiwR=$(sed -n 's/.*2 pi w R = \([0-9.e+-]*\),.*/\1/p' "$out/$name.log")
  nodes=$(sed -n 's/^cgcm: [a-z ]*, \([0-9]*\) nodes.*/\1/p' "$out/$name.log")
  pmin=$(sed -n 's/^P_min = \([0-9.e+-]*\) .*/\1/p' "$out/$name/summary.txt" 2>/dev/null)
  ref=$("$build/bin/cgcm-analytic" ljsphere --mu "$mu" --pulloff 2>/dev/null | tail -1 | cut -d, -f2)
  lambda=$(sed -n 's/.*lambda (theory) = \([0-9.e+-]*\),.*/\1/p' "$out/$name.log")
  md=$("$build/bin/cgcm-analytic" pulloff --model md --lambda "$lambda" 2>/dev/null | sed -n 's/^load,\([^,]*\),.*/\1/p')
  ratio=stopped
  [ -n "$pmin" ] && ratio=$(awk -v p="$pmin" -v s="$twopiwR" 'BEGIN { printf "%.4f", 2 * p / s }')
  printf '%-22s %7.4f %7.4f %7s %11s %10.4f %10.4f\n' "$name" "$mu" "$lambda" "$nodes" "$ratio" "$ref" "$md"
  echo "$name,$mu,$lambda,$nodes,$ratio,$ref,$md" >> "$out/table.csv"
done
/usr/bin/python3 tools/plot_jkr_limit.py --analytic "$build/bin/cgcm-analytic" --table "$out/table.csv" \
  --output doc/figures/jkr-limit.png
