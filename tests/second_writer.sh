#!/usr/bin/env bash
# One writer per output directory (issue 16): while a run writes, a second
# fe2dem on the same parameter file (fresh, and with --resume) is refused
# with a message naming the directory and the holder, and changes nothing:
# the first run's summary.csv and history.h5 equal an undisturbed run's.
# Usage: second_writer.sh FE2DEM PRM WORKDIR REFERENCE_OUT
set -uo pipefail
exe=$1 prm=$2 work=$3 reference=$4
tests=$(cd "$(dirname "$0")" && pwd)
. "$tests/lib.sh"
rm -rf "$work"; mkdir -p "$work"; cd "$work"
sed 's#^set Output directory.*#set Output directory = out#' "$prm" > case.prm
fail() { echo "FAIL: $*"; exit 1; }
"$exe" case.prm > first.log 2>&1 & first=$!
wait_for_rows out/summary.csv 2
kill -0 $first 2> /dev/null || fail "the first run ended before the second one started"
# Paused while the others try (however slow the machine), then resumed: it
# must still end as if undisturbed.
kill -STOP $first
trap 'kill -CONT $first 2> /dev/null' EXIT # never leave it paused
for args in "case.prm" "case.prm --resume"; do
  out=$("$exe" $args 2>&1); rc=$?
  [[ $rc -ne 0 ]] || fail "'fe2dem $args' beside a running fe2dem exited 0"
  grep -qF "is in use by another fe2dem or fe2dem-rve run (process $first" <<<"$out" || fail "'fe2dem $args': message lacks the holder: $(tail -n 2 <<<"$out")"
  echo "refused: fe2dem $args: $(grep -F 'in use' <<<"$out" | head -n 1 | cut -c1-160)"
done
kill -CONT $first
wait $first || fail "the first run failed: $(tail -n 3 first.log)"
python3 "$tests/compare_summaries.py" "$reference/summary.csv" out/summary.csv || fail "summary.csv differs from an undisturbed run"
/usr/bin/python3 "$tests/compare_histories.py" "$reference/history.h5" out/history.h5 || fail "history.h5 differs"
echo "ok"
