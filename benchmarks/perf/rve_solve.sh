#!/usr/bin/env bash
# DEM steps and seconds of one RVE solve of the reference packing at the
# first axial load step of the [LBS] biaxial test, and of the next
# dynamic-relaxation iteration (F changed by 1e-5), for each history mode
# (committed / continuous) and start option (keep / reset frame
# fluctuations). Prints `name value unit` lines; appends them to results_rve_solve.csv.
# Usage: benchmarks/perf/rve_solve.sh [BUILD_DIR]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="$(realpath -m "${1:-$root/build}")"
source "$root/benchmarks/common.sh"
out=$("$build/benchmarks/perf/bench_rve_solve" "$root/rve_templates/rve_setup_2d.liggghts" "$root/rve_templates/packings/lbs_ref")
echo "$out"
append_result "$here/results_rve_solve.csv" "benchmark,$(awk '{print $1}' <<<"$out" | paste -sd,)" \
  "rve_solve,$(awk '{print $2}' <<<"$out" | paste -sd,)"
