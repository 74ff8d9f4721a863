#!/usr/bin/env bash
# Single-RVE biaxial curves of the [LBS] reference packing: friction 0.2,
# 0.4, 0.6 with free rotation, and 0.4 with locked rotation. Writes
# results/CASE/rve.csv, results/biaxial.png and prints per case
# `name value unit` lines (peak stress ratio, strain at peak, wall time).
# Usage: benchmarks/rve_biaxial/run.sh [BUILD_DIR]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="$(realpath -m "${1:-$root/build}")"
cd "$here"
cases=("free_mu0.2 free 0.2" "free_mu0.4 free 0.4" "free_mu0.6 free 0.6" "locked_mu0.4 locked 0.4")
for c in "${cases[@]}"; do
  set -- $c
  prm="$(mktemp --suffix=.prm -p "$here")"
  { cat biaxial_10pct.prm
    printf 'subsection RVE\n  set Rotation = %s\n  set Friction = %s\nend\n' "$2" "$3"; } > "$prm"
  start=$(date +%s.%N)
  "$build/dealii_app/rve_driver/fe2dem-rve" "$prm" --output-directory "results/$1" > "results_$1.log" 2>&1 ||
    { rm -f "$prm"; echo "case $1 failed: see $here/results_$1.log" >&2; exit 1; }
  rm -f "$prm" "results_$1.log"
  wall=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN {printf "%.1f", e - s}')
  /usr/bin/python3 - "$1" "results/$1/rve.csv" "$wall" <<'PY'
import csv, sys
name, path, wall = sys.argv[1], sys.argv[2], sys.argv[3]
rows = list(csv.DictReader(open(path)))
f22_iso = float(rows[4]["F22"])
best = max(rows[5:], key=lambda r: abs((float(r["sigma11"]) - float(r["sigma22"])) / (float(r["sigma11"]) + float(r["sigma22"]))))
s11, s22 = float(best["sigma11"]), float(best["sigma22"])
print(f"{name}_peak_stress_ratio {abs((s11 - s22) / (s11 + s22)):.4f} 1")
print(f"{name}_axial_strain_at_peak {1 - float(best['F22']) / f22_iso:.4f} 1")
print(f"{name}_dem_steps {sum(int(float(r['dem_steps'])) for r in rows)} steps")
print(f"{name}_wall {wall} s")
PY
done
/usr/bin/python3 "$here/plot.py" results
