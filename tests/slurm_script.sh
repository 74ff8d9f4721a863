#!/usr/bin/env bash
# scripts/slurm/fe2dem.sbatch without SLURM: `srun` and `scontrol` are
# stand-ins on PATH (srun runs mpirun with --ntasks ranks, scontrol records a
# requeue); fe2dem itself runs for real. The batch shell gets SIGUSR1 during
# load step 3 as `--signal=B:USR1@600` would send it: the script must pass it
# to the ranks, see the checkpoint stop and requeue; started again (as SLURM
# does after a requeue, with other ranks) it must resume and end without a
# requeue; the result must equal the uninterrupted run's bitwise.
# Usage: slurm_script.sh FE2DEM PRM WORKDIR REFERENCE_OUT SBATCH_SCRIPT
set -uo pipefail
exe=$1 prm=$2 work=$3 reference=$4 script=$5
tests=$(cd "$(dirname "$0")" && pwd)
. "$tests/lib.sh"
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$work"; mkdir -p "$work/bin"; cd "$work"
cat > bin/srun <<'STUB'
#!/bin/bash
n=1; [[ $1 == --ntasks=* ]] && { n=${1#--ntasks=}; shift; }
exec mpirun --allow-run-as-root --oversubscribe -np "$n" "$@"
STUB
printf '#!/bin/bash\necho "$@" >> %s/requeued\n' "$work" > bin/scontrol
chmod +x bin/srun bin/scontrol
{ sed 's#^set Output directory.*#set Output directory = out#' "$prm"
  printf '\nsubsection Checkpoint\n  set Every = 0\nend\n'; } > case.prm
export PATH="$work/bin:$PATH" FE2DEM="$exe" SLURM_JOB_ID=42
SLURM_NTASKS=2 SLURM_RESTART_COUNT=0 bash "$script" case.prm > job-0.log 2>&1 &
job=$!
wait_for_rows out/summary.csv 3
sleep 0.2
kill -USR1 $job
wait $job; rc=$?
cat job-0.log
[[ $rc -eq 0 ]] || fail "first start: exit code $rc"
grep -q "received SIGUSR1" fe2dem-42-0.log || fail "the ranks did not get SIGUSR1"
grep -q "^42$\|requeue 42" requeued 2>/dev/null || fail "no requeue after the checkpoint stop"
rows=$(($(wc -l < out/summary.csv) - 1))
[[ $rows -lt $(($(wc -l < "$reference/summary.csv") - 1)) ]] || fail "the run had finished before the signal"
rm -f requeued
SLURM_NTASKS=1 SLURM_RESTART_COUNT=1 bash "$script" case.prm > job-1.log 2>&1; rc=$?
cat job-1.log
[[ $rc -eq 0 ]] || fail "second start: exit code $rc"
grep -q "1 ranks, --resume" job-1.log || fail "second start did not resume"
[[ ! -f requeued ]] || fail "requeued a finished run"
python3 "$tests/compare_summaries.py" "$reference/summary.csv" out/summary.csv || exit 1
/usr/bin/python3 "$tests/compare_histories.py" "$reference/history.h5" out/history.h5 || exit 1
echo "ok: stopped after $rows load steps on 2 ranks, requeued, resumed on 1 rank to the reference"
