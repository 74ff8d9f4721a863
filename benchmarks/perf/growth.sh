#!/usr/bin/env bash
# How the cost of fe2dem grows: wall time of the first 4 load steps of the
# [LBS] biaxial test (2 isotropic, 2 axial to 1 %) on 2 ranks
#   - against the number of IPs: meshes 1x1, 1x2, 2x4, 4x8 (4, 8, 32, 128
#     RVEs of lbs_ref, 228 particles each);
#   - against particles per RVE: 1x1 mesh with perf_n85 (104 particles),
#     lbs_ref (228) and perf_n800 (861; packings/ here, made by make_rve.sh).
# Writes results/growth.csv and results/growth.png; prints `name value unit`.
# Usage: benchmarks/perf/growth.sh [BUILD_DIR]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="$(realpath -m "${1:-$root/build}")"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
# With the fastest documented settings (accelerations.sh: check10).
short='subsection Loading\n  set Isotropic steps = 2\n  set Load steps = 2\n  set Axial strain = 0.01\nend\nsubsection Checkpoint\n  set Every = 0\nend\nsubsection RVE\n  set Check interval = 10\nend'
mkdir -p "$here/results"
csv="$here/results/growth.csv"
echo "series,ips,particles_per_rve,wall_s,dem_steps,rve_solves" > "$csv"
row() { # series ips particles wall summary
  echo "$1,$2,$3,$4,$(awk -F, 'NR > 1 {s += $14; r += $18} END {print s "," r}' "$5")" >> "$csv"
  echo "growth_${1}_${2}ips_${3}particles_wall $4 s"
}
for m in "1 1" "1 2" "2 4" "4 8"; do
  set -- $m
  w=$("$here/run_case.sh" "$build" "$root/benchmarks/perf/biaxial_2x4_strict.prm" "$work/m" 2 \
        "subsection Geometry\n  set Cells x = $1\n  set Cells y = $2\nend\n$short")
  row ips $((4 * $1 * $2)) 228 "$w" "$work/m/summary.csv"
done
for p in "$here/packings/perf_n85 104" "$root/rve_templates/packings/lbs_ref 228" "$here/packings/perf_n800 861"; do
  set -- $p
  w=$("$here/run_case.sh" "$build" "$root/dealii_app/examples/biaxial_1x1.prm" "$work/p" 2 \
        "subsection RVE\n  set Packing = $1\nend\n$short")
  row particles 4 "$2" "$w" "$work/p/summary.csv"
done
/usr/bin/python3 "$here/plot_growth.py" "$csv" "$here/results/growth.png"
