#!/usr/bin/env bash
# Usage: cycle.sh BUILD_DIR OUT — one lsyf_300 RVE round the isotropic strain
# cycle of tests/dynamics_rve/volumetric_cycle.prm (25 kHz, amplitude 1e-5,
# five periods) in explicit dynamics at each macro step and check interval
# below, and the internal work of each period (README, "What the filter's
# delay does"; > 0: the packing dissipates, < 0: it gives energy back).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"; root="$here/../.."
build=$(realpath "$1") out=$2; mkdir -p "$out"
prm="$root/tests/dynamics_rve/volumetric_cycle.prm"
for run in "2e-6 10" "2e-6 5" "2e-6 20" "1e-6 10"; do
  set -- $run
  dir="$out/dt$1_checks$2"; mkdir -p "$dir"
  sed "s#\.\./\.\./rve_templates#$root/rve_templates#; s#CHECKS#$2#; s#set Time step = 2e-6#set Time step = $1#" "$prm" > "$dir/macro.prm"
  (cd "$dir" && "$build/dealii_app/solver/fe2dem" macro.prm > log 2>&1)
  echo "macro step $1 s, checks of $2 DEM steps ($(awk -v dt="$1" -v c="$2" 'BEGIN { print dt / 1e-7 / c }') per step):"
  /usr/bin/python3 "$root/tests/check_cycle_work.py" "$dir/out/energy.csv" 0 | head -1
done
