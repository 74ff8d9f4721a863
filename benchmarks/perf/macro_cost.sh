#!/usr/bin/env bash
# The replicated macro part of fe2dem (issue 19, scaling model): every rank
# assembles the whole mesh at every iteration, so its cost bounds the
# speed-up of a mesh with many RVEs. Measured with the neo-Hookean material
# (no RVEs): the elastic block on meshes of growing size, one rank, two
# iteration budgets of the first load step (K1 and K2 dynamic-relaxation
# iterations, K2 - K1 at least 100 and about 4e6 / cells; the step not converged: fe2dem stops with 'did not converge',
# which is expected here); per-iteration seconds = (T(K2) - T(K1)) / (K2 - K1),
# so mesh set-up and start-up cancel. Prints `name value unit` lines and
# appends to results_macro_cost.csv.
# Usage: benchmarks/perf/macro_cost.sh [BUILD_DIR] [2|3] ["CELLS..."] [full|one point]
#   CELLS: cells along x (y has twice as many; z as many as x in 3D)
#   last: 'Quadrature' (subsection Finite elements; default full)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="$(realpath -m "${1:-$root/build}")"
dim="${2:-2}"
if [[ $dim == 3 ]]; then default="4 8 16 37"; else default="10 32 100 224"; fi
read -r -a cells <<<"${3:-$default}"
quadrature="${4:-full}"
source "$root/benchmarks/common.sh"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
k1=20
base="$root/dealii_app/examples/elastic_block.prm"
[[ $dim == 3 ]] && base="$root/dealii_app/examples/elastic_block_3d.prm"
run() { # run NX ITERATIONS -> wall seconds
  local nx=$1 it=$2 ny=$(( 2 * $1 )) start
  # undistorted, and the first load step small enough for the finest mesh's top cells
  { sed "s#^set Output directory.*#set Output directory = $work/out#; s#Cells x *=.*#Cells x = $nx#; s#Cells y *=.*#Cells y = $ny#; s#Cells z *=.*#Cells z = $nx#; s#Distortion *=.*#Distortion = 0#; s#Load steps *=.*#Load steps = 1000#" "$base"
    printf 'subsection Dynamic relaxation\n  set Max iterations = %s\n  set Min iterations = 1\n  set Kinetic energy tolerance = 1e-300\nend\n' "$it"
    printf 'subsection Finite elements\n  set Quadrature = %s\nend\n' "$quadrature"; } > "$work/case.prm"
  start=$(date +%s.%N)
  "$build/dealii_app/solver/fe2dem" "$work/case.prm" > "$work/log" 2>&1 || true
  grep -q "did not converge" "$work/log" || { echo "macro_cost.sh: unexpected end:" >&2; tail -5 "$work/log" >&2; exit 1; }
  awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN {printf "%.3f", e - s}'
}
for nx in "${cells[@]}"; do
  n=$(( nx * 2 * nx )); [[ $dim == 3 ]] && n=$(( n * nx ))
  k2=$(( k1 + (4000000 / n > 100 ? 4000000 / n : 100) )) # a few seconds of iterations
  t1=$(run "$nx" $k1); t2=$(run "$nx" $k2)
  per=$(awk -v a="$t1" -v b="$t2" -v k=$((k2 - k1)) 'BEGIN {printf "%.3e", (b - a) / k}')
  echo "macro_cost_${dim}d_${n}_cells_${quadrature// /_}_per_iteration $per s"
  append_result "$here/results_macro_cost.csv" "benchmark,dim,cells,quadrature,k1,t_k1_s,k2,t_k2_s,s_per_iteration" \
    "macro_cost,$dim,$n,$quadrature,$k1,$t1,$k2,$t2,$per"
done
