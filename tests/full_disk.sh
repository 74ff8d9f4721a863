#!/usr/bin/env bash
# A full disk at an output file (issue 16): solution-0002.vtu is made a link
# to /dev/full (every write fails with ENOSPC). fe2dem must stop on every rank
# (no hang: run under 'timeout') with an I/O message naming the file, not
# "error in the parameter file".
# Usage: full_disk.sh FE2DEM PRM WORKDIR NP
set -uo pipefail
exe=$1 prm=$2 work=$3 np=$4
[[ -w /dev/full ]] || { echo "SKIP: no /dev/full"; exit 77; }
rm -rf "$work"; mkdir -p "$work/out"; cd "$work"
sed 's#^set Output directory.*#set Output directory = out#' "$prm" > case.prm
ln -s /dev/full out/solution-0002.vtu
out=$(timeout 120 mpiexec --allow-run-as-root --oversubscribe -np "$np" "$exe" case.prm 2>&1); rc=$?
echo "$out" | tail -n 4
[[ $rc -ne 0 && $rc -ne 124 ]] || { echo "FAIL: exit code $rc (124: it hung)"; exit 1; }
grep -qF "cannot write 'out/solution-0002.vtu' (No space left on device)" <<<"$out" || { echo "FAIL: no I/O message naming the file"; exit 1; }
! grep -qF "error in the parameter file" <<<"$out" || { echo "FAIL: reported as a parameter-file error"; exit 1; }
echo "ok: exit code $rc, I/O error named, on $np ranks"
