#!/usr/bin/env bash
# Shared by the perf scripts: runs fe2dem on a copy of an example parameter
# file with extra entries and prints its wall time in seconds; the summary
# stays in OUT/summary.csv.
# Usage: run_case.sh BUILD_DIR EXAMPLE.prm OUT NP 'EXTRA PRM TEXT'
set -euo pipefail
build=$1 example=$2 out=$3 np=$4 extra=$5
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
rm -rf "$out"; mkdir -p "$out"
{ sed "s#^set Output directory.*#set Output directory = $out#; s#\.\./\.\./rve_templates#$root/rve_templates#" "$example"
  printf '%b\n' "$extra"; } > "$out/case.prm"
start=$(date +%s.%N)
mpirun --allow-run-as-root --oversubscribe -np "$np" "$build/dealii_app/solver/fe2dem" "$out/case.prm" > "$out/run.log" 2>&1
awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN {printf "%.2f\n", e - s}'
