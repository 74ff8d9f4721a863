#!/usr/bin/env bash
# The multiscale [LBS] biaxial test to 10 % axial strain with fe2dem on
# 2 ranks: the 1x1 mesh (4 RVEs) and the paper's 2x4 mesh (32 RVEs). Copies
# summary.csv and history.h5 into results/MESH/, plots results/biaxial.png
# and prints the wall time of each run. A run that stops early (fe2dem
# says why) keeps its converged steps.
# Usage: benchmarks/macro_biaxial/run.sh [BUILD_DIR] [MESHES...]   (default: 1x1 2x4)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="$(realpath -m "${1:-$root/build}")"
shift || true
meshes=("${@:-1x1 2x4}")
read -r -a meshes <<<"${meshes[*]}"
mkdir -p "$here/results"
plots=()
for m in "${meshes[@]}"; do
  work="$(mktemp -d)"
  # every entry at its default: the 2x4 example ships with the accelerations,
  # its strict copy is benchmarks/perf/biaxial_2x4_strict.prm
  prm="$root/dealii_app/examples/biaxial_$m.prm"
  [[ $m == 2x4 ]] && prm="$root/benchmarks/perf/biaxial_2x4_strict.prm"
  sed "s#^set Output directory.*#set Output directory = $work/out#; s#\.\./\.\./rve_templates#$root/rve_templates#" \
    "$prm" > "$work/case.prm"
  start=$(date +%s.%N)
  if mpirun --allow-run-as-root --oversubscribe -np 2 "$build/dealii_app/solver/fe2dem" "$work/case.prm" > "$here/results/$m.log" 2>&1; then
    echo "biaxial_${m}_completed 1 bool"
  else # keep the converged steps; the log says why it stopped
    echo "biaxial_${m}_completed 0 bool"
    echo "biaxial_${m}_stopped $(grep -m1 'error:' "$here/results/$m.log" | sed 's/.*error: //')"
  fi
  wall=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN {printf "%.0f", e - s}')
  mkdir -p "$here/results/$m"
  cp "$work/out/summary.csv" "$work/out/history.h5" "$here/results/$m/"
  rm -rf "$work"
  echo "biaxial_${m}_wall $wall s"
  peak=$(awk -F, 'NR > 1 && $2 == 2 && $5 > p {p = $5; e = $4} END {printf "%.4f %.4f", p, e}' "$here/results/$m/summary.csv")
  echo "biaxial_${m}_peak_stress_ratio ${peak% *} 1"
  echo "biaxial_${m}_axial_strain_at_peak ${peak#* } 1"
  echo "biaxial_${m}_dem_steps $(awk -F, 'NR > 1 {s += $14} END {print s}' "$here/results/$m/summary.csv") steps"
  plots+=("$m=$here/results/$m/summary.csv")
done
/usr/bin/python3 "$root/scripts/plot_summary.py" "$here/results/biaxial.png" "${plots[@]}"
