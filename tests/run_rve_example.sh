#!/usr/bin/env bash
# Runs one fe2dem-rve example into OUTDIR and checks its rve.csv.
# Usage: run_rve_example.sh FE2DEM_RVE PRM OUTDIR KIND PRESSURE ISOTROPIC_STEPS ROWS [free_shear]
set -euo pipefail
exe=$1 prm=$2 out=$3 kind=$4 pressure=$5 n_iso=$6 rows=$7
rm -rf "$out"
"$exe" "$prm" --output-directory "$out"
python3 "$(dirname "$0")/check_rve_csv.py" "$out/rve.csv" "$kind" "$pressure" "$n_iso" "$rows" "${@:8}"
