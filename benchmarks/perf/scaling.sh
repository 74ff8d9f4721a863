#!/usr/bin/env bash
# Parallel efficiency and load balance of fe2dem on the [LBS] 2x4 mesh (32
# RVEs): the first 8 load steps of the biaxial run (4 isotropic, 4 axial to
# 2 %, the full run's increments) on 1 and 2 ranks, REPEATS times
# interleaved. Prints medians, efficiency T1 / (2 T2) and the load imbalance
# (sum over steps of the busiest rank's RVE seconds / the mean rank's) as
# `name value unit` lines; appends them to results_scaling.csv.
# Usage: benchmarks/perf/scaling.sh [BUILD_DIR] [REPEATS]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="$(realpath -m "${1:-$root/build}")"
repeats="${2:-2}"
source "$root/benchmarks/common.sh"
# The fastest documented settings (accelerations.sh: check10).
extra='subsection Loading\n  set Load steps = 4\n  set Axial strain = 0.02\nend\nsubsection Checkpoint\n  set Every = 0\nend\nsubsection RVE\n  set Check interval = 10\nend'
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
t1=(); t2=(); imb=()
for ((k = 0; k < repeats; ++k)); do
  t1+=("$("$here/run_case.sh" "$build" "$root/benchmarks/perf/biaxial_2x4_strict.prm" "$work/np1" 1 "$extra")")
  t2+=("$("$here/run_case.sh" "$build" "$root/benchmarks/perf/biaxial_2x4_strict.prm" "$work/np2" 2 "$extra")")
  imb+=("$(awk -F, 'NR == 1 {for (i = 1; i <= NF; ++i) c[$i] = i} NR > 1 {m += $c["rve_rank_max_s"]; a += $c["rve_rank_mean_s"]} END {printf "%.4f", m / a}' "$work/np2/summary.csv")")
  python3 "$root/tests/compare_summaries.py" "$work/np1/summary.csv" "$work/np2/summary.csv" > /dev/null ||
    { echo "FAIL: 1 and 2 ranks differ"; exit 1; }
done
m1=$(median "${t1[@]}") m2=$(median "${t2[@]}") mi=$(median "${imb[@]}")
eff=$(awk -v a="$m1" -v b="$m2" 'BEGIN {printf "%.3f", a / (2 * b)}')
echo "scaling_wall_1_rank $m1 s"
echo "scaling_wall_2_ranks $m2 s"
echo "scaling_efficiency_2_ranks $eff 1"
echo "scaling_load_imbalance_max_over_mean $mi 1"
echo "scaling_runs_identical_1_vs_2_ranks 1 bool"
append_result "$here/results_scaling.csv" "benchmark,wall_1_rank_s,wall_2_ranks_s,efficiency,imbalance" \
  "scaling,$m1,$m2,$eff,$mi"
