#!/usr/bin/env bash
# Kill test: runs fe2dem with a checkpoint after every load step, kills the
# whole job with SIGKILL at a random moment after the first checkpoint,
# resumes (possibly on another number of ranks) and compares summary.csv and
# history.h5 with an uninterrupted run, bitwise (wall_s aside).
# Usage: kill_and_resume.sh FE2DEM PRM WORKDIR REFERENCE_OUT NP_KILLED NP_RESUMED
#   PRM: the reference run's parameter file (its Output directory is replaced).
#   The moment (seeded from the clock, printed): a random delay in [0, 400) ms
#   after the checkpoint of a random load step in 1..4 (the run has >= 7).
set -uo pipefail
exe=$1 prm=$2 work=$3 reference=$4 np_killed=$5 np_resumed=$6
tests=$(cd "$(dirname "$0")" && pwd)
mpirun_np() { if [[ $1 -eq 1 ]]; then shift; "$@"; else n=$1; shift; mpiexec --allow-run-as-root --oversubscribe -np "$n" "$@"; fi; }
rm -rf "$work"; mkdir -p "$work"
{ sed 's#^set Output directory.*#set Output directory = out#' "$prm"
  printf '\nsubsection Checkpoint\n  set Every = 1\n  set Keep  = 2\nend\n'; } > "$work/case.prm"
cd "$work"
seed=$(( $(date +%s%N) % 32768 )); RANDOM=$seed
after_step=$(( 1 + RANDOM % 4 )) delay_ms=$(( RANDOM % 400 ))
echo "seed $seed: SIGKILL ${delay_ms} ms after the checkpoint of load step $after_step, $np_killed rank(s) killed, $np_resumed resumed"
if [[ $np_killed -eq 1 ]]; then setsid "$exe" case.prm > killed.log 2>&1 &
else setsid mpiexec --allow-run-as-root --oversubscribe -np "$np_killed" "$exe" case.prm > killed.log 2>&1 &
fi
pid=$!
# (The load step of the newest checkpoint; the digit of '.h5' is not part of it.)
newest() { ls out/checkpoints 2> /dev/null | sed -n 's/^checkpoint-0*\([0-9][0-9]*\)\.h5$/\1/p' | sort -n | tail -n 1; }
for _ in $(seq 1200); do
  [[ $(newest) -ge $after_step ]] 2> /dev/null && break
  kill -0 $pid 2> /dev/null || break
  sleep 0.1
done
sleep "$(awk -v m=$delay_ms 'BEGIN {print m / 1000}')"
if ! kill -0 $pid 2> /dev/null; then
  echo "FAIL: the run ended before the kill (lengthen the run or shorten the delay)"; cat killed.log; exit 1
fi
# mpiexec starts each rank in its own process group: kill the ranks, then mpiexec.
pkill -KILL -P $pid; kill -KILL $pid; wait $pid 2> /dev/null
sleep 0.2
echo "killed after $(($(wc -l < out/summary.csv) - 1)) summary rows; checkpoints: $(ls out/checkpoints | tr '\n' ' ')"
mpirun_np "$np_resumed" "$exe" case.prm --resume > resumed.log 2>&1 || { echo "FAIL: resume"; tail resumed.log; exit 1; }
grep -m1 "resuming from" resumed.log
python3 "$tests/compare_summaries.py" "$reference/summary.csv" out/summary.csv || exit 1
/usr/bin/python3 "$tests/compare_histories.py" "$reference/history.h5" out/history.h5 || exit 1
if [[ -f "$reference/energy.csv" ]]; then
  cmp "$reference/energy.csv" out/energy.csv || { echo "FAIL: energy.csv differs from the uninterrupted run"; exit 1; }
  echo "energy.csv: bitwise equal"
fi
