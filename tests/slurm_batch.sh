#!/usr/bin/env bash
# scripts/slurm/fe2dem.sbatch on a real one-node SLURM (tests/slurm_cluster.sh):
# submitted with sbatch, the ranks started by srun (a direct launch, so the
# template check's child process must start under it), interrupted by the
# time-limit signal of its own '#SBATCH --signal=B:USR1@600', requeued by
# itself and resumed by SLURM; the result must equal the uninterrupted run's
# bitwise. Exit 77 (skipped, with the reason) where the daemons cannot start.
#
# Making the time-limit signal arrive during a load step without depending on
# timing: once 3 load steps are written the test stops the ranks (SIGSTOP),
# lowers the job's time limit below the signal's 600 s margin, waits until
# SLURM's signal is pending at every rank, and lets them go on (SIGCONT).
# Usage: slurm_batch.sh FE2DEM PRM WORKDIR REFERENCE_OUT SBATCH_SCRIPT
set -uo pipefail
exe=$1 prm=$2 work=$3 reference=$4 script=$5
tests=$(cd "$(dirname "$0")" && pwd)
. "$tests/lib.sh"
fail() { echo "FAIL: $*"; [[ -n ${job:-} ]] && scancel "$job" 2>/dev/null; exit 1; }
rm -rf "$work"; mkdir -p "$work"; cd "$work"
cluster=$("$tests/slurm_cluster.sh" start "$work/cluster"); rc=$?
[[ $rc -eq 0 ]] || exit $rc
eval "$cluster"
trap '"$tests/slurm_cluster.sh" stop "$work/cluster"' EXIT
{ sed 's#^set Output directory.*#set Output directory = out#' "$prm"
  printf '\nsubsection Checkpoint\n  set Every = 0\nend\n'; } > case.prm

job=$(sbatch --parsable --ntasks=2 --time=30 --chdir="$work" --export=ALL,FE2DEM="$exe" "$script" case.prm) \
  || fail "sbatch refused the script"
echo "submitted job $job"
# Until three load steps are written or the job has ended (a busy machine
# only makes this slower; the bound is a guard against a hang).
for _ in $(seq 3000); do
  [[ -f out/summary.csv && $(wc -l < out/summary.csv) -ge 3 ]] && break
  squeue -h -j "$job" 2>/dev/null | grep -q . || break
  sleep 0.2
done
[[ -f out/summary.csv && $(wc -l < out/summary.csv) -ge 3 ]] ||
  fail "no 3 load steps while the job ran (job log: $(cat fe2dem-$job.log 2>/dev/null))"
# This job's ranks: other tests may run the same fe2dem on their own
# case.prm at the same time, so only the processes started in $work count.
here=$(pwd -P)
ranks=()
for pid in $(pgrep -f "^$exe case.prm"); do
  [[ $(readlink "/proc/$pid/cwd" 2>/dev/null) == "$here" ]] && ranks+=("$pid")
done
[[ ${#ranks[@]} -eq 2 ]] || fail "expected 2 fe2dem ranks in $here, found ${#ranks[@]}"
kill -STOP "${ranks[@]}"
# 9 minutes: below the 10 of --signal=B:USR1@600, so the signal is due at once,
# and as far from the hard limit as that allows for the rest of the run.
scontrol update JobId="$job" TimeLimit=9 || fail "scontrol update refused"
# SIGUSR1 is signal 10: bit 9 of the pending masks in /proc/PID/status.
pending() { awk '/^(SigPnd|ShdPnd):/ {m = m " " $2} END {print m}' "/proc/$1/status" 2>/dev/null |
  /usr/bin/python3 -c 'import sys; print(any(int(w, 16) >> 9 & 1 for w in sys.stdin.read().split()))'; }
for _ in $(seq 1500); do
  all=1
  for r in "${ranks[@]}"; do [[ $(pending "$r") == True ]] || all=0; done
  [[ $all -eq 1 ]] && break
  sleep 0.2
done
kill -CONT "${ranks[@]}"
[[ $all -eq 1 ]] || fail "SLURM's time-limit signal did not reach the ranks within 300 s"
state() { scontrol show job "$job" 2>/dev/null | grep -o 'JobState=[A-Z_]*\|Restarts=[0-9]*' | tr '\n' ' '; }
for _ in $(seq 3000); do
  [[ $(state) == *"JobState=COMPLETED Restarts=1"* || $(state) == *FAILED* || $(state) == *CANCELLED* ]] && break
  sleep 0.2
done
echo "job $job: $(state)"
cat "fe2dem-$job.log"
[[ $(state) == *"JobState=COMPLETED Restarts=1"* ]] || fail "the job did not end after one requeue"
grep -q "received SIGUSR1" "fe2dem-$job-0.log" || fail "the ranks did not get SIGUSR1 (fe2dem-$job-0.log)"
grep -q "restart 1, 2 ranks, --resume" "fe2dem-$job.log" || fail "the requeued start did not resume"
stopped=$(grep -o "during load step [0-9]*" "fe2dem-$job-0.log")
python3 "$tests/compare_summaries.py" "$reference/summary.csv" out/summary.csv || exit 1
/usr/bin/python3 "$tests/compare_histories.py" "$reference/history.h5" out/history.h5 || exit 1
echo "ok: job $job stopped by its time-limit signal $stopped, requeued, resumed to the reference"
