#!/usr/bin/env bash
# Peak resident memory of RVE pools of the reference packing on one rank:
# 4 and 128 RVEs, one load step. Prints the growth per RVE measured inside
# the pool (bench_pool) and the process peak (GNU time) for each.
# Usage: benchmarks/perf/memory.sh [BUILD_DIR]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="$(realpath -m "${1:-$root/build}")"
source "$root/benchmarks/common.sh"
row=""
for n in 4 128; do
  out=$( { /usr/bin/time -f "peak_kb %M" "$build/benchmarks/coupler/bench_pool" \
      "$root/rve_templates/rve_setup_2d.liggghts" "$root/rve_templates/packings/lbs_ref" "$n" 1 continuous; } 2>&1)
  per=$(awk '/resident_per_rve/ {print $2}' <<<"$out")
  peak=$(awk '/peak_kb/ {print $2 * 1024}' <<<"$out")
  echo "memory_${n}_rves_resident_per_rve $per bytes"
  echo "memory_${n}_rves_process_peak $peak bytes"
  row="$row,$per,$peak"
done
append_result "$here/results_memory.csv" "benchmark,per_rve_4,peak_4,per_rve_128,peak_128" "memory$row"
