#!/usr/bin/env bash
# SIGTERM while an RVE solve never converges (issue 39): the RVEs' own
# relaxation tolerances are unreachable, so the first solve (the relaxation
# of the packing as built) would run for hours; fe2dem used to set a flag
# that nothing read until then. The RVE solves now end at their next chunk
# of DEM steps (coupler/stop_request.h): the run must stop on every rank
# within a minute of the signal, say why, and write no checkpoint (nothing
# converged: one would resume from unrelaxed RVEs).
# Usage: sigterm_stuck_solve.sh FE2DEM PRM WORKDIR NP
set -uo pipefail
exe=$1 prm=$2 work=$3 np=$4
source "$(dirname "$0")/stuck_solve_run.sh"
start_stuck_run "$exe" "$prm" "$work" "$np"
kill -TERM $pid
for ((i = 0; i < 600; ++i)); do kill -0 $pid 2>/dev/null || break; sleep 0.1; done
if kill -0 $pid 2>/dev/null; then
  kill -KILL $pid; pkill -KILL -f "$exe case.prm"
  echo "FAIL: still running 60 s after SIGTERM"; tail -n 3 stopped.log; exit 1
fi
wait $pid; rc=$?
tail -n 2 stopped.log
[[ $rc -eq 1 ]] || { echo "FAIL: exit code $rc, expected 1 (stopped before the first load step)"; exit 1; }
grep -q "stopped by signal 15 while the RVEs were built" stopped.log || { echo "FAIL: no message naming the signal and the phase"; exit 1; }
grep -q "no checkpoint is written" stopped.log || { echo "FAIL: the message does not say that nothing was saved"; exit 1; }
[[ -z $(find out -name 'checkpoint-*' 2>/dev/null) ]] || { echo "FAIL: a checkpoint of unrelaxed RVEs was written"; exit 1; }
echo "ok: stopped within $((i / 10)) s of SIGTERM on $np rank(s), exit code 1, no checkpoint"
