#!/usr/bin/env bash
# Runs a command that must fail: asserts a non-zero exit code and that the
# combined output contains every given needle.
# Usage: expect_failure.sh NEEDLE [NEEDLE...] -- COMMAND [ARGS...]
needles=()
while [[ $# -gt 0 && "$1" != "--" ]]; do needles+=("$1"); shift; done
shift
out="$("$@" 2>&1)"
rc=$?
echo "$out" | tail -n 5
if [[ $rc -eq 0 ]]; then echo "FAIL: exit code 0, expected non-zero"; exit 1; fi
for n in "${needles[@]}"; do
  if ! grep -qF -- "$n" <<<"$out"; then echo "FAIL: output lacks '$n'"; exit 1; fi
done
echo "ok: exit code $rc, message names: ${needles[*]}"
