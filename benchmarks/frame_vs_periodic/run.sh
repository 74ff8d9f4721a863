#!/usr/bin/env bash
# The frame RVE against the YADE periodic cell (issue 14): each packing along
# the biaxial path of biaxial.prm with the default settings and with each
# candidate that could separate the two, one at a time:
#   default     0.5 % load steps, servo tolerance 1e-4 (R14), E_kin/E_pot <= 1e-3
#   steps0.1    0.1 % load steps (100 instead of 20)
#   servo1e-6   servo tolerance r_a <= 1e-6 (R14)
#   relax1e-6   E_kin/E_pot <= 1e-6 (R12)
#   force       force-based tolerances: unbalanced-force index (R13) <= 1e-3 and
#               servo_scale contact, rms pair imbalance <= 1e-3 rms contact force
#   affine      Inner start = affine: the inner particles also follow the affine
#               velocity field of the frame's motion at a new F
#   tight       0.1 % steps, r_a <= 1e-6, E_kin/E_pot <= 1e-6 together
# CASES="..." picks cases.
# Usage: benchmarks/frame_vs_periodic/run.sh [--build DIR] [PACKING ...]
#   (default packings: lbs_ref lbs_a005). Writes runs/PACKING/CASE/rve.csv
#   (not committed) and results/runs.csv; compare.py makes the tables and PNG.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
source "$root/benchmarks/common.sh"
build="$root/build"
if [[ "${1:-}" == --build ]]; then build="$(realpath -m "$2")"; shift 2; fi
packings=("$@"); [[ ${#packings[@]} -gt 0 ]] || packings=(lbs_ref lbs_a005)
exe="$build/dealii_app/rve_driver/fe2dem-rve"
[[ -x "$exe" ]] || { echo "run.sh: $exe not found: build first (scripts/run-tests.sh) or pass --build DIR" >&2; exit 1; }
cd "$here"
mkdir -p runs results
overrides() {
  case "$1" in
    default) ;;
    steps0.1) printf 'subsection Path\n  set Loading steps = 100\nend\n' ;;
    servo1e-6) printf 'subsection RVE\n  set Servo tolerance = 1e-6\nend\n' ;;
    relax1e-6) printf 'subsection RVE\n  set Relaxation tolerance = 1e-6\nend\n' ;;
    force) printf 'subsection RVE\n  set Relaxation criterion = unbalanced\n  set Relaxation tolerance = 1e-3\n  set Servo residual scale = contact\n  set Servo tolerance = 1e-3\nend\n' ;;
    affine) printf 'subsection RVE\n  set Inner start = affine\nend\n' ;;
    tight) printf 'subsection Path\n  set Loading steps = 100\nend\nsubsection RVE\n  set Servo tolerance = 1e-6\n  set Relaxation tolerance = 1e-6\nend\n' ;;
    *) echo "run.sh: unknown case '$1' (default steps0.1 servo1e-6 relax1e-6 force affine tight)" >&2; exit 2 ;;
  esac
}
for p in "${packings[@]}"; do
  for c in ${CASES:-default steps0.1 servo1e-6 relax1e-6 force affine tight}; do
    out="runs/$p/$c"; mkdir -p "$out"
    # Paths in a parameter file are relative to it: make them absolute.
    { sed "s#\.\./\.\./rve_templates#$root/rve_templates#" biaxial.prm
      printf 'subsection RVE\n  set Packing = %s/rve_templates/packings/%s\nend\n' "$root" "$p"
      overrides "$c"; } > "$out/case.prm"
    start=$(date +%s.%N)
    status=completed
    "$exe" "$out/case.prm" --output-directory "$here/$out" > "$out/run.log" 2>&1 || status=failed
    wall=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN {printf "%.1f", e - s}')
    echo "${p}_${c}_wall $wall s ($status)"
    append_result results/runs.csv "packing,case,status,wall_s" "$p,$c,$status,$wall"
  done
done
