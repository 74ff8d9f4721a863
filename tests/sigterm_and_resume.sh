#!/usr/bin/env bash
# SIGTERM test: a batch system's warning signal (SIGTERM or SIGUSR1) in the
# middle of a load step makes fe2dem write a checkpoint of the last converged
# step and exit 0 with a message; --resume then completes the run with the
# same summary.csv and history.h5 as an uninterrupted one.
# Usage: sigterm_and_resume.sh FE2DEM PRM WORKDIR REFERENCE_OUT NP SIGNAL
set -uo pipefail
exe=$1 prm=$2 work=$3 reference=$4 np=$5 signal=$6
tests=$(cd "$(dirname "$0")" && pwd)
. "$tests/lib.sh"
run() { if [[ $np -eq 1 ]]; then "$exe" "$@"; else mpiexec --allow-run-as-root --oversubscribe -np "$np" "$exe" "$@"; fi; }
rm -rf "$work"; mkdir -p "$work"
{ sed 's#^set Output directory.*#set Output directory = out#' "$prm"
  printf '\nsubsection Checkpoint\n  set Every = 0\nend\n'; } > "$work/case.prm"
cd "$work"
# Started directly (not through a function) so that $! is the process to signal.
if [[ $np -eq 1 ]]; then "$exe" case.prm > stopped.log 2>&1 &
else mpiexec --allow-run-as-root --oversubscribe -np "$np" "$exe" case.prm > stopped.log 2>&1 &
fi
pid=$!
# Signal during load step 3 (after step 2's row).
wait_for_rows out/summary.csv 3
sleep 0.2
kill -"$signal" $pid
wait $pid; rc=$?
tail -n 3 stopped.log
[[ $rc -eq 0 ]] || { echo "FAIL: exit code $rc after SIG$signal, expected 0"; exit 1; }
grep -q "received SIG$signal" stopped.log || { echo "FAIL: no 'received SIG$signal' message"; exit 1; }
grep -q -- "--resume" stopped.log || { echo "FAIL: the message does not say how to continue"; exit 1; }
rows=$(($(wc -l < out/summary.csv) - 1))
ls out/checkpoints/checkpoint-$(printf %06d $rows).h5 > /dev/null || { echo "FAIL: no checkpoint of step $rows"; exit 1; }
[[ $rows -lt $(($(wc -l < "$reference/summary.csv") - 1)) ]] || { echo "FAIL: the run had finished"; exit 1; }
echo "stopped after $rows load steps with exit code 0 and checkpoint-$(printf %06d $rows).h5"
run case.prm --resume > resumed.log 2>&1 || { echo "FAIL: resume"; tail resumed.log; exit 1; }
python3 "$tests/compare_summaries.py" "$reference/summary.csv" out/summary.csv || exit 1
/usr/bin/python3 "$tests/compare_histories.py" "$reference/history.h5" out/history.h5 || exit 1
if [[ -f "$reference/energy.csv" ]]; then
  cmp "$reference/energy.csv" out/energy.csv || { echo "FAIL: energy.csv differs from the uninterrupted run"; exit 1; }
  echo "energy.csv: bitwise equal"
fi
