#!/usr/bin/env bash
# Runs PRM with 'Formulation' = corotational and again with total Lagrangian
# and compares their stresses (check_corotational.py compare).
# Usage: check_corotational.sh FE2DEM PRM WORKDIR TOL
set -euo pipefail
exe=$1 prm=$2 work=$3 tol=$4
rm -rf "$work"; mkdir -p "$work/corotational" "$work/total_lagrangian"
sed 's#^set Output directory.*#set Output directory = out#' "$prm" > "$work/corotational/case.prm"
sed -e 's#^set Output directory.*#set Output directory = out#' -e 's#Formulation = corotational#Formulation = total Lagrangian#' \
  "$prm" > "$work/total_lagrangian/case.prm"
grep -q "Formulation = total Lagrangian" "$work/total_lagrangian/case.prm"
for f in corotational total_lagrangian; do
  (cd "$work/$f" && "$exe" case.prm > log)
done
/usr/bin/python3 "$(dirname "$0")/check_corotational.py" compare "$work/corotational/out" "$work/total_lagrangian/out" "$tol"
