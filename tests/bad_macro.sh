#!/usr/bin/env bash
# A wrong fe2dem input must fail before the expensive part: non-zero exit
# code, a message with every NEEDLE, and no summary.csv row that could pass
# for a result.
# Usage: bad_macro.sh FE2DEM BASE.prm WORKDIR 'OVERRIDES' NEEDLE...
#   OVERRIDES: parameter-file lines separated by '~', appended to BASE.prm
#   (a later 'set' wins), e.g. 'subsection Geometry~set Mesh file = x.msh~end'.
#   '@TESTS@' in BASE.prm and OVERRIDES becomes this directory.
#   LAUNCH (environment): launcher prefix, e.g. "mpiexec -np 3".
#   ABSENT (environment): a text the output must not contain, e.g. "RVEs on"
#   for a refusal that must come before any RVE is built.
set -uo pipefail
exe=$1 base=$2 work=$3 overrides=$4; shift 4
tests=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"; mkdir -p "$work"
{ cat "$base"; echo; tr '~' '\n' <<<"$overrides"; echo; } | sed "s#@TESTS@#$tests#g" > "$work/case.prm"
out="$(cd "$work" && ${LAUNCH:-} "$exe" case.prm 2>&1)"
rc=$?
echo "$out" | tail -n 8
[[ $rc -ne 0 ]] || { echo "FAIL: exit code 0, expected non-zero"; exit 1; }
for n in "$@"; do
  grep -qF -- "$n" <<<"$out" || { echo "FAIL: output lacks '$n'"; exit 1; }
done
if [[ -n "${ABSENT:-}" ]] && grep -qF -- "$ABSENT" <<<"$out"; then
  echo "FAIL: the output has '$ABSENT'"; exit 1
fi
if [[ -f "$work/out/summary.csv" && $(wc -l < "$work/out/summary.csv") -gt 1 ]]; then
  echo "FAIL: $work/out/summary.csv has result rows"; exit 1
fi
echo "ok: exit code $rc, message names: $*"
