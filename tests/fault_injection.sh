#!/usr/bin/env bash
# An injected RVE fault (subsection Faults, 'Inject fault' = IP (2) at load
# step 3) must be reported with IP, position, load step and reason, and
# handled as chosen:
#   cut:  the load step is cut and retried; the run completes all rows;
#   stop: the run stops with exit code 1 after a checkpoint of step 2, and
#         --resume without the fault completes it identically to REFERENCE.
# KIND 'budget' (default): a step budget of 1; 'liggghts': an error raised
# inside LIGGGHTS (F11 x 1e10: the shrink-wrapped box outgrows LIGGGHTS'
# neighbour bins), which must take the same path instead of
# ending the job in MPI_Abort. RANKS (default 1) > 1 runs under mpirun, the
# faulty RVE then living on another rank than rank 0's.
# SAME_AS (cut only): the output of another run with a fault at the same IP
# and step, which this one must equal bitwise: the cut does not depend on
# the kind of fault or on the rank count.
# Usage: fault_injection.sh FE2DEM PRM WORKDIR REFERENCE_OUT cut|stop [IP] [KIND] [RANKS] [SAME_AS]
set -uo pipefail
exe=$1 prm=$2 work=$3 reference=$4 mode=$5 ip=${6:-2} kind=${7:-budget} ranks=${8:-1} same_as=${9:-}
tests=$(cd "$(dirname "$0")" && pwd)
reaction=$([[ $mode == cut ]] && echo "cut step" || echo stop)
launch=(); [[ $ranks -gt 1 ]] && launch=(mpirun --allow-run-as-root --oversubscribe -np "$ranks")
rm -rf "$work"; mkdir -p "$work"; cd "$work"
sed 's#^set Output directory.*#set Output directory = out#' "$prm" > clean.prm
{ cat clean.prm; printf '\nsubsection Faults\n  set On RVE failure = %s\n  set Inject fault = %s 3 %s\nend\n' "$reaction" "$ip" "$kind"; } > case.prm
"${launch[@]}" "$exe" case.prm > run.log 2>&1; rc=$?
grep -E "injected|RVE of IP|cut|stopped|MPI_ABORT" run.log
fail() { echo "FAIL: $*"; exit 1; }
reason=$([[ $kind == liggghts ]] && echo "LIGGGHTS error: " || echo "not converged within max_steps")
for needle in "injected a fault into the RVE of IP $ip" "RVE of IP $ip at (" "load step 3" "$reason"; do
  grep -qF "$needle" run.log || fail "log lacks '$needle'"
done
rows=$(($(wc -l < out/summary.csv) - 1))
if [[ $mode == cut ]]; then
  [[ $rc -eq 0 ]] || fail "exit code $rc, expected 0"
  grep -qF "cut 1: every RVE back to the start of the load step, retrying it in 2 sub-steps" run.log || fail "no cut reported"
  [[ $rows -eq $(($(wc -l < "$reference/summary.csv") - 1)) ]] || fail "$rows rows"
  if [[ -n $same_as ]]; then
    python3 "$tests/compare_summaries.py" "$same_as/summary.csv" out/summary.csv || exit 1
    /usr/bin/python3 "$tests/compare_histories.py" "$same_as/history.h5" out/history.h5 || exit 1
  fi
  echo "ok: fault reported, load step 3 cut once, all $rows rows written"
else
  [[ $rc -ne 0 ]] || fail "exit code 0 after a fault with 'On RVE failure' = stop"
  grep -qF "the run stopped after writing" run.log && grep -qF -- "--resume" run.log || fail "no stop message"
  [[ $rows -eq 2 && -f out/checkpoints/checkpoint-000002.h5 ]] || fail "$rows rows / no checkpoint of step 2"
  "$exe" clean.prm --resume > resumed.log 2>&1 || fail "resume: $(tail -n 3 resumed.log)"
  python3 "$tests/compare_summaries.py" "$reference/summary.csv" out/summary.csv || exit 1
  /usr/bin/python3 "$tests/compare_histories.py" "$reference/history.h5" out/history.h5 || exit 1
  echo "ok: stopped with exit code $rc after step 2, resumed to the reference"
fi
