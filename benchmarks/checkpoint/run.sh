#!/usr/bin/env bash
# Cost and size of fe2dem checkpoints for the [LBS] 2x4 mesh (32 RVEs of the
# reference packing) on 2 ranks: three load steps with a checkpoint after
# each. Prints `name value unit` lines and appends them with
# machine, date and commit to results.csv.
# Usage: benchmarks/checkpoint/run.sh [BUILD_DIR]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="$(realpath -m "${1:-$root/build}")"
source "$root/benchmarks/common.sh"
work="$(mktemp -d)"
{ sed "s#^set Output directory.*#set Output directory = $work/out#; s#\.\./\.\./rve_templates#$root/rve_templates#" \
    "$root/benchmarks/perf/biaxial_2x4_strict.prm"
  printf 'subsection Loading\n  set Isotropic steps = 2\n  set Load steps = 20\nend\n'
  printf 'subsection Checkpoint\n  set Every = 1\n  set Keep = 5\nend\n'; } > "$work/case.prm"
# Three load steps, then SIGTERM (a fourth checkpoint, of step 3).
mpirun --allow-run-as-root --oversubscribe -np 2 "$build/dealii_app/solver/fe2dem" "$work/case.prm" > "$work/run.log" 2>&1 &
pid=$!
until [[ -f "$work/out/summary.csv" && $(wc -l < "$work/out/summary.csv") -ge 4 ]]; do sleep 0.5; done
kill -TERM $pid; wait $pid || true  # mpirun itself may report the signal
times=$(grep -o 'checkpoint .*h5 (load step [0-9]*, [0-9.e-]* s)' "$work/run.log" | sed 's/.*, \([0-9.e-]*\) s)/\1/')
bytes=$(stat -c %s "$work"/out/checkpoints/checkpoint-000003.h5)
median_s=$(median $times) max_s=$(printf '%s\n' $times | sort -g | tail -n 1) n=$(echo $times | wc -w)
echo "checkpoint_seconds_median $median_s s"
echo "checkpoint_seconds_max $max_s s"
echo "checkpoints_timed $n count"
echo "checkpoint_bytes $bytes B"
echo "checkpoint_bytes_per_rve $((bytes / 32)) B"
append_result "$here/results.csv" "rves,checkpoints,seconds_median,seconds_max,bytes" "32,$n,$median_s,$max_s,$bytes"
rm -rf "$work"
