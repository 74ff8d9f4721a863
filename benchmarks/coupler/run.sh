#!/usr/bin/env bash
# RVE pool over MPI: memory per RVE and the 2-rank speed-up of a pool of N
# RVEs (default 32 [LBS] reference RVEs, 8 load steps of solve + commit),
# 1 and 2 ranks interleaved REPEATS times; medians and their ratio as
# `name value unit` lines, appended to results.csv with machine/date/commit.
# Usage: benchmarks/coupler/run.sh [BUILD_DIR] [N] [ITERATIONS] [REPEATS] [MODE]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="$(realpath -m "${1:-$root/build}")"
n="${2:-32}"; iterations="${3:-8}"; repeats="${4:-5}"; mode="${5:-committed}"
exe="$build/benchmarks/coupler/bench_pool"
args=("$root/rve_templates/rve_setup_2d.liggghts" "$root/rve_templates/packings/lbs_ref" "$n" "$iterations" "$mode")
mpirun=(mpirun --allow-run-as-root --oversubscribe)
t1=(); t2=(); imb=(); mem=""
for ((k = 0; k < repeats; ++k)); do
  o1=$("${mpirun[@]}" -np 1 "$exe" "${args[@]}")
  o2=$("${mpirun[@]}" -np 2 "$exe" "${args[@]}")
  t1+=("$(awk '/load_steps_wall/ {print $2}' <<<"$o1")")
  t2+=("$(awk '/load_steps_wall/ {print $2}' <<<"$o2")")
  imb+=("$(awk '/load_imbalance/ {print $2}' <<<"$o2")")
  mem="$(awk '/resident_per_rve/ {print $2}' <<<"$o1")"
  reb="$(awk '/rebalance_moved/ {m=$2} /rebalance_wall/ {w=$2} END {print m " RVEs in " w " s"}' <<<"$o2")"
done
m1=$(median "${t1[@]}"); m2=$(median "${t2[@]}"); mi=$(median "${imb[@]}")
speedup=$(ratio "$m1" "$m2")
echo "rves $n count"
echo "load_steps $iterations steps"
echo "history_mode $mode"
echo "wall_1_rank $m1 s"
echo "wall_2_ranks $m2 s"
echo "speedup_2_ranks $speedup ratio"
echo "load_imbalance_2_ranks $mi ratio"
echo "resident_per_rve $mem bytes"
echo "rebalance_2_ranks_last $reb"
echo "samples_1_rank ${t1[*]}"
echo "samples_2_ranks ${t2[*]}"
append_result "$here/results.csv" "rves,load_steps,mode,wall_1,wall_2,speedup,imbalance,resident_per_rve" \
  "$n,$iterations,$mode,$m1,$m2,$speedup,$mi,$mem"
