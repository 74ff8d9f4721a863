#!/usr/bin/env bash
# Dynamic RVEs against the continuous reference (issue 35, item 5): the
# one-element simple shear of tests/dynamics_rve/shear_3d.prm (small_3d,
# every node prescribed, F12 to 2 %) in explicit dynamics over 0.0192,
# 0.0768 and 0.3072 s (shear rates 1.04, 0.26, 0.065 /s), against fe2dem-rve
# driven continuously at 0.0163 /s (a quarter of the slowest) on the same
# RVE (tests/dynamics_rve/shear_continuous_rve.prm with that rate).
# Writes results/dynamic_bias/{dyn_*,reference}/ and results/dynamic_bias.txt.
#
#   dynamic_bias.sh BUILD
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
[[ $# -eq 1 ]] || { sed -n '2,10p' "$0"; exit 2; }
build="$(cd "$1" && pwd)"
out="$here/results/dynamic_bias"
mkdir -p "$out"
rebase() { sed "s#\.\./\.\./rve_templates#$root/rve_templates#" "$@"; }

ref="$out/reference"
if [[ ! -f "$ref/rve.csv" ]]; then
  mkdir -p "$ref"
  rebase "$root/tests/dynamics_rve/shear_continuous_rve.prm" |
    sed 's/^\( *set Strain rate *=\).*/\1 0.016276/' > "$ref/case.prm"
  t0=$SECONDS
  "$build/dealii_app/rve_driver/fe2dem-rve" "$ref/case.prm" --output-directory "$ref" > "$ref/run.log"
  echo "reference: $((SECONDS - t0)) s"
fi
for end_time in 0.0192 0.0768 0.3072; do
  d="$out/dyn_$end_time"
  if [[ ! -f "$d/out/history.h5" ]]; then
    mkdir -p "$d"
    rebase "$root/tests/dynamics_rve/shear_3d.prm" | sed "s#END_TIME#$end_time#g" > "$d/macro.prm"
    t0=$SECONDS
    (cd "$d" && "$build/dealii_app/solver/fe2dem" macro.prm > log)
    echo "dynamic over $end_time s: $((SECONDS - t0)) s"
  fi
done
{
  echo "# dynamic one-element simple shear (small_3d) against fe2dem-rve continuous at 0.0163 /s"
  for end_time in 0.0192 0.0768 0.3072; do
    echo "## dynamic over $end_time s (shear rate $(awk -v t=$end_time 'BEGIN {printf "%.3g", 0.02 / t}') /s)"
    /usr/bin/python3 "$root/tests/compare_rve_stress.py" "$out/dyn_$end_time/out/history.h5" "$ref/rve.csv" 1 1 1
  done
} | tee "$here/results/dynamic_bias.txt"
