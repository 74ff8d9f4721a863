#!/usr/bin/env bash
# --resume refuses what it cannot continue: no checkpoint yet, a
# checkpoint written with other parameters (named in the message), or one
# of an older checkpoint format (its summary rows have fewer columns).
# Usage: bad_resume.sh FE2DEM PRM WORKDIR
set -uo pipefail
exe=$1 prm=$2 work=$3
tests=$(cd "$(dirname "$0")" && pwd)
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
# Every kept checkpoint made one format older, with its fingerprint (FNV-1a
# and size, file_hash.cpp) written again, as an earlier fe2dem would have;
# otherwise it counts as damaged and the one before is tried.
newest=$(ls out/checkpoints/checkpoint-*.h5 | sort | tail -n 1)
for f in out/checkpoints/checkpoint-*.h5; do
  /usr/bin/python3 - "$f" <<'PY' || fail "could not age $f"
import sys, h5py
path = sys.argv[1]
with h5py.File(path, "r+") as f:
    f.attrs["format"] = f.attrs["format"] - 1
PY
  /usr/bin/python3 "$tests/refingerprint.py" "$f" || fail "could not fingerprint $f"
done
out=$("$exe" case.prm --resume 2>&1) && fail "--resume of an older checkpoint format exited 0"
echo "$out" | tail -n 2
for n in "$newest" "has format" "earlier fe2dem" "without --resume"; do
  grep -qF -- "$n" <<<"$out" || fail "message lacks '$n'"
done
cmp -s out/summary.csv finished.csv || fail "the refused resume changed summary.csv"
echo "ok: all three refused with exit code != 0, the finished run's files untouched"
