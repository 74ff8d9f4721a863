#!/usr/bin/env bash
# Runs fe2dem on PRM in a scratch copy (output relative to it, a relative mesh
# file made absolute) and checks it.
# Usage: run_macro.sh FE2DEM PRM WORKDIR CHECK_ARGS...   (CHECK_ARGS: see check_macro.py,
#        the summary path is inserted after the mode)
set -euo pipefail
exe=$1 prm=$2 work=$3 mode=$4; shift 4
rm -rf "$work"; mkdir -p "$work"
src=$(cd "$(dirname "$prm")" && pwd)
sed -e 's#^set Output directory.*#set Output directory = out#' \
    -e "s#^\( *set Mesh file *= *\)\([^/ ].*\)#\1$src/\2#" "$prm" > "$work/case.prm"
"$exe" "$work/case.prm"
python3 "$(dirname "$0")/check_macro.py" "$mode" "$work/out/summary.csv" "$@"
