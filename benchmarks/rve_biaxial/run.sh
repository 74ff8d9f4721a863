#!/usr/bin/env bash
# Single-RVE biaxial curves of the [LBS] reference packing: friction 0.2,
# 0.4, 0.6 with free rotation, and 0.4 with locked rotation. Writes
# results/CASE/rve.csv, results/biaxial.png and prints per case
# `name value unit` lines (peak stress ratio, strain at peak, wall time).
# A case that stops early (fe2dem-rve reports why) keeps its rows so far.
# Usage: benchmarks/rve_biaxial/run.sh [BUILD_DIR]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="$(realpath -m "${1:-$root/build}")"
cd "$here"
cases=("free_mu0.2 free 0.2" "free_mu0.4 free 0.4" "free_mu0.6 free 0.6" "locked_mu0.4 locked 0.4")
mkdir -p results
for c in "${cases[@]}"; do
  set -- $c
  prm="$(mktemp --suffix=.prm -p "$here")"
  { cat biaxial_10pct.prm
    printf 'subsection RVE\n  set Rotation = %s\n  set Friction = %s\nend\n' "$2" "$3"; } > "$prm"
  start=$(date +%s.%N)
  if "$build/dealii_app/rve_driver/fe2dem-rve" "$prm" --output-directory "results/$1" > "results/$1.log" 2>&1; then
    echo "$1_completed 1 bool"
  else
    # Keep the rows written so far; the log names the reason (e.g. an escaped particle).
    echo "$1_completed 0 bool"
    echo "$1_failure $(grep -m1 'error:' "results/$1.log" | sed 's/.*error: //')"
  fi
  rm -f "$prm"
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
print(f"{name}_last_axial_strain {1 - float(rows[-1]['F22']) / f22_iso:.4f} 1")
PY
done
/usr/bin/python3 "$here/plot.py" results
