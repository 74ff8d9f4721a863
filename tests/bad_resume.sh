#!/usr/bin/env bash
# --resume refuses what it cannot continue: no checkpoint yet, or a
# checkpoint written with other parameters (named in the message).
# Usage: bad_resume.sh FE2DEM PRM WORKDIR
set -uo pipefail
exe=$1 prm=$2 work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
fail() { echo "FAIL: $*"; exit 1; }
{ sed 's#^set Output directory.*#set Output directory = out#' "$prm"
  printf '\nsubsection Checkpoint\n  set Every = 1\nend\n'; } > case.prm
out=$("$exe" case.prm --resume 2>&1) && fail "--resume without a checkpoint exited 0"
echo "$out" | tail -n 2
for n in "--resume" "no complete checkpoint" "out/checkpoints" "without --resume"; do
  grep -qF -- "$n" <<<"$out" || fail "message lacks '$n'"
done
[[ ! -s out/summary.csv || $(wc -l < out/summary.csv) -le 1 ]] || fail "summary.csv has rows"
"$exe" case.prm > first.log 2>&1 || fail "the first run failed: $(tail -n 3 first.log)"
cp out/summary.csv finished.csv
{ cat case.prm; printf '\nsubsection Loading\n  set Axial strain = 0.03\nend\n'; } > other.prm
out=$("$exe" other.prm --resume 2>&1) && fail "--resume with other parameters exited 0"
echo "$out" | tail -n 4
for n in "other parameters" "Loading/Axial strain" "0.02" "0.03" "other.prm"; do
  grep -qF -- "$n" <<<"$out" || fail "message lacks '$n'"
done
cmp -s out/summary.csv finished.csv || fail "the refused resume changed summary.csv"
echo "ok: both refused with exit code != 0, the finished run's files untouched"
