#!/usr/bin/env bash
# Usage: run.sh BUILD_DIR OUT — the slow (4800 solves, 0.26/s) and the fast
# (960 solves, 1.3/s) shear of noise.liggghts, then analyse.py on both.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"; root="$here/../.."
build=$(realpath "$1") out=$2; mkdir -p "$out"
p="$root/rve_templates/packings/small_3d"
for run in "slow 4800 301" "fast 960 61"; do
  set -- $run
  "$build/liggghts_fix/fe2dem-liggghts" -in "$here/noise.liggghts" -var template "$root/rve_templates/rve_setup_3d.liggghts" \
    -var rve_data "$p.rve.data" -var rve_vars "$p.vars" -var nsolve "$2" -var check_every 10 -var on_failure flag \
    -log "$out/$1.log" -screen none > /dev/null
  echo "$1:"; /usr/bin/python3 "$here/analyse.py" "$out/$1.log" "$3"
done
