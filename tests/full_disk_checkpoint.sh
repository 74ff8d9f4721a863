#!/usr/bin/env bash
# A full disk while checkpoints are written every load step (issue 39): the
# output directory on a tmpfs of SIZE. fe2dem must stop on every rank (no
# hang, no crash: HDF5 writing to the full disk itself used to fail at its
# close and end in SIGSEGV at MPI_Finalize) with a message naming the file
# that did not fit (WHAT: checkpoint, or history for history.h5) and the
# cause, leave no partial checkpoint (*.tmp, or one without its
# fingerprint), and every complete checkpoint it left must be intact
# (--resume would take it); with MIN_KEPT, at least that many.
# Needs root to mount the tmpfs; skipped (77) with a message otherwise.
# Usage: full_disk_checkpoint.sh FE2DEM PRM WORKDIR NP SIZE WHAT MIN_KEPT
set -uo pipefail
exe=$1 prm=$2 work=$3 np=$4 size=$5 what=$6 min_kept=$7
[[ $(id -u) -eq 0 ]] || { echo "SKIP: mounting a tmpfs needs root"; exit 77; }
mountpoint -q "$work/disk" 2>/dev/null && umount "$work/disk"
rm -rf "$work"; mkdir -p "$work/disk"
mount -t tmpfs -o size="$size" tmpfs "$work/disk" || { echo "SKIP: cannot mount a tmpfs"; exit 77; }
trap 'cd /; umount "$work/disk"' EXIT
cd "$work/disk"
sed 's#^set Output directory.*#set Output directory = out#' "$prm" > case.prm
printf 'subsection Checkpoint\n  set Every = 1\nend\n' >> case.prm
out=$(timeout 120 mpiexec --allow-run-as-root --oversubscribe -np "$np" "$exe" case.prm 2>&1); rc=$?
echo "$out" | grep -v "^stage" | tail -n 4
[[ $rc -ne 0 && $rc -ne 124 ]] || { echo "FAIL: exit code $rc (0: the disk did not fill; 124: it hung)"; exit 1; }
! grep -qiE "segmentation fault|signal 11|HDF5-DIAG" <<<"$out" || { echo "FAIL: a crash or HDF5's own diagnostics"; exit 1; }
if [[ $what == checkpoint ]]; then
  grep -qE "cannot write checkpoint file 'out/checkpoints/checkpoint-[0-9]+\.h5(\.tmp|\.fnv)' \(No space left on device\)" <<<"$out" ||
    { echo "FAIL: no message naming the checkpoint file and the full disk"; exit 1; }
  grep -qF "the newest complete checkpoint is kept" <<<"$out" || { echo "FAIL: the message does not say what is kept"; exit 1; }
else
  grep -qF "cannot write 'out/history.h5' (No space left on device" <<<"$out" ||
    { echo "FAIL: no message naming history.h5 and the full disk"; exit 1; }
fi
leftover=$(find out/checkpoints -name '*.tmp')
[[ -z "$leftover" ]] || { echo "FAIL: partial checkpoint left: $leftover"; exit 1; }
n=0
for c in out/checkpoints/checkpoint-*.h5; do
  [[ -e "$c" ]] || continue
  n=$((n + 1))
  read -r hash bytes < "$c.fnv" || { echo "FAIL: $c without a fingerprint"; exit 1; }
  [[ $(stat -c %s "$c") -eq $bytes ]] || { echo "FAIL: $c has $(stat -c %s "$c") bytes, its fingerprint $bytes"; exit 1; }
done
[[ $n -ge $min_kept ]] || { echo "FAIL: $n complete checkpoint(s), expected at least $min_kept"; exit 1; }
echo "ok: exit code $rc, the full disk named, no partial checkpoint, $n complete checkpoint(s) intact, on $np ranks"
