#!/usr/bin/env bash
# Damaged checkpoints and changed RVE files on --resume (issue 16). A run on
# a copy of its RVE template, stopped by SIGTERM with two checkpoints kept:
#   truncated: the newest checkpoint cut to half -> --resume says so, falls
#              back to the one before, and completes equal to REFERENCE;
#   corrupted: 64 bytes in the middle of the newest overwritten -> the same;
#   both:      every checkpoint damaged -> a clear error, exit 1;
#   template:  the template copy changed -> --resume refused, naming it;
#   image:     64 bytes of RVE 0's image in the newest checkpoint overwritten
#              and the fingerprint made again (a damage written before it was
#              taken), at several offsets -> every --resume ends within 120 s,
#              never by a signal, and a failure names the RVE; at least one
#              offset is refused before any RVE is restored (the image test-
#              restored in a child process; in-process it crashed LIGGGHTS).
# Usage: damaged_checkpoint.sh FE2DEM PRM WORKDIR REFERENCE_OUT MODE
set -uo pipefail
exe=$1 prm=$2 work=$3 reference=$4 mode=$5
tests=$(cd "$(dirname "$0")" && pwd)
. "$tests/lib.sh"
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$work"; mkdir -p "$work"; cd "$work"
template=$(sed -n 's/^ *set Template *= *//p' "$prm" | head -n 1)
[[ $template = /* ]] || template="$(dirname "$prm")/$template"
cp "$template" template.liggghts
{ sed 's#^set Output directory.*#set Output directory = out#' "$prm"
  printf '\nsubsection RVE\n  set Template = %s\nend\nsubsection Checkpoint\n  set Every = 1\n  set Keep = 2\nend\n' "$work/template.liggghts"
} > case.prm
"$exe" case.prm > stopped.log 2>&1 & pid=$!
wait_for_rows out/summary.csv 4
kill -TERM $pid; wait $pid || fail "the run did not stop cleanly: $(tail -n 3 stopped.log)"
mapfile -t kept < <(ls out/checkpoints/checkpoint-*.h5 | sort)
[[ ${#kept[@]} -eq 2 ]] || fail "expected 2 checkpoints, found ${kept[*]}"
newest=${kept[1]} older=${kept[0]}
damage() { # FILE KIND
  local size; size=$(stat -c %s "$1")
  if [[ $2 == truncated ]]; then truncate -s $((size / 2)) "$1"
  else dd if=/dev/urandom of="$1" bs=1 count=64 seek=$((size / 2)) conv=notrunc status=none; fi
}
case $mode in
  truncated|corrupted)
    damage "$newest" "$mode"
    "$exe" case.prm --resume > resumed.log 2>&1 || fail "resume: $(tail -n 3 resumed.log)"
    grep -qF "checkpoint '$newest' is damaged" resumed.log || fail "no message about the damaged $newest"
    grep -qF "resuming from $older" resumed.log || fail "did not fall back to $older"
    python3 "$tests/compare_summaries.py" "$reference/summary.csv" out/summary.csv || exit 1
    /usr/bin/python3 "$tests/compare_histories.py" "$reference/history.h5" out/history.h5 || exit 1
    echo "ok: $mode newest checkpoint detected: $(grep -F 'is damaged' resumed.log | head -n 1)"
    echo "    fell back to $older and completed equal to the undisturbed run" ;;
  both)
    damage "$newest" truncated; damage "$older" corrupted
    out=$("$exe" case.prm --resume 2>&1) && fail "--resume exited 0 with every checkpoint damaged"
    grep -qF "no intact checkpoint" <<<"$out" || fail "unclear message: $(tail -n 3 <<<"$out")"
    echo "ok: $(grep -F 'no intact checkpoint' <<<"$out")" ;;
  template)
    echo "# changed" >> template.liggghts
    out=$("$exe" case.prm --resume 2>&1) && fail "--resume exited 0 with a changed template"
    grep -qF "RVE/Template file content" <<<"$out" || fail "the message does not name the template: $(tail -n 4 <<<"$out")"
    echo "ok: refused: $(grep -F 'RVE/Template file content' <<<"$out" | head -n 1)" ;;
  image)
    cp -r out out_stopped
    refused=0
    for offset in 1000 30000 37800 60000 70000; do
      rm -rf out && cp -r out_stopped out
      /usr/bin/python3 - "$newest" "$offset" <<'PY' || fail "could not damage the image"
import sys, h5py
path, offset = sys.argv[1], int(sys.argv[2])
with h5py.File(path, "r+") as f:
    d = f["rve"][sorted(f["rve"].keys())[0]]
    a = d[()].copy(); a[offset:offset + 64] = 255; d[...] = a
PY
      /usr/bin/python3 "$tests/refingerprint.py" "$newest" || fail "could not fingerprint $newest"
      timeout 120 "$exe" case.prm --resume > resumed.log 2>&1; rc=$?
      [[ $rc -ne 124 ]] || fail "offset $offset: --resume hung (killed after 120 s)"
      [[ $rc -lt 128 ]] || fail "offset $offset: --resume ended by signal $((rc - 128)): $(tail -n 2 resumed.log)"
      if [[ $rc -ne 0 ]]; then
        grep -q "RVE of IP" resumed.log || fail "offset $offset: the failure does not name the RVE: $(tail -n 2 resumed.log)"
        grep -q "cannot be restored" resumed.log && refused=$((refused + 1))
      fi
      echo "offset $offset: exit $rc $(grep -m1 'error' resumed.log | cut -c1-160)"
    done
    [[ $refused -ge 1 ]] || fail "no damaged image was refused before restoring"
    echo "ok: every damaged image ended the resume cleanly; $refused refused before any RVE was restored" ;;
  *) fail "MODE = $mode: use truncated, corrupted, both, template or image" ;;
esac
