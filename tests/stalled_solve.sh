#!/usr/bin/env bash
# The progress watchdog (RVE entry 'Stall steps', fix keyword stall_steps):
# with a servo tolerance no packing reaches (1e-30) and a step budget of
# 1e9, which would otherwise run for hours, the RVE solve must end as
# stalled after the watchdog's window ('Stall steps = 20000') with a message
# that names it, exit status 1, no result rows and no checkpoint, on NP ranks
# (fe2dem) or in fe2dem-rve (NP = rve). A time-out of 240 s catches a hang.
# Usage: stalled_solve.sh PROGRAM PRM WORKDIR NP|rve
set -uo pipefail
exe=$1 prm=$2 work=$3 np=$4
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$work"; mkdir -p "$work"; cd "$work"
{ sed 's#^set Output directory.*#set Output directory = out#' "$prm"
  printf '\nsubsection RVE\n  set Servo tolerance = 1e-30\n  set Step budget = 1000000000\n  set Stall steps = 20000\nend\n'; } > case.prm
if [[ $np == rve ]]; then timeout 240 "$exe" case.prm --output-directory out > run.log 2>&1
elif [[ $np -eq 1 ]]; then timeout 240 "$exe" case.prm > run.log 2>&1
else timeout 240 mpirun --allow-run-as-root --oversubscribe -np "$np" "$exe" case.prm > run.log 2>&1
fi
rc=$?
grep -m1 "error" run.log
[[ $rc -ne 124 ]] || fail "still running after 240 s: the watchdog did not end the solve"
[[ $rc -ne 0 ]] || fail "exit code 0"
for needle in "no progress towards convergence" "stall_steps = 20000" "servo_tol = 1e-30"; do
  grep -qF "$needle" run.log || fail "the message lacks '$needle'"
done
rows=0
for f in out/summary.csv out/rve.csv; do [[ -f $f ]] && rows=$(($(wc -l < "$f") - 1)); done
[[ $rows -le 0 ]] || fail "$rows result rows written"
[[ -z $(find out -name 'checkpoint-*' 2>/dev/null) ]] || fail "a checkpoint was written"
echo "ok: exit code $rc, the solve ended as stalled with a message, no rows, no checkpoint"
