#!/usr/bin/env bash
# Fails when docs/parameters.md is not what scripts/print-parameters.sh
# writes for this build (an entry, default or documentation string of fe2dem
# or fe2dem-rve, or the keyword block of liggghts_fix/fix_rve_servo.h,
# changed without regenerating the reference).
#
# Usage: tests/check_parameters_doc.sh BUILD [DOC]
#   BUILD  the build tree holding fe2dem and fe2dem-rve
#   DOC    the file to compare (default: docs/parameters.md)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build=${1:?usage: tests/check_parameters_doc.sh BUILD [DOC]}
doc=${2:-$root/docs/parameters.md}
tmp=$(mktemp)
trap 'rm -f "$tmp"' EXIT
"$root/scripts/print-parameters.sh" "$build" "$tmp" > /dev/null
if ! diff -u "$doc" "$tmp"; then
  echo "docs/parameters.md is out of date: run scripts/print-parameters.sh $build" >&2
  exit 1
fi
echo "docs/parameters.md is up to date with $build"
