#!/usr/bin/env bash
# Triaxial test of one 3D RVE (small_3d, linear contacts) to 10 % axial
# strain at 100 kPa confinement with fe2dem-rve, then q/p and volumetric
# strain against axial strain in triaxial.png (plot.py).
# Usage: benchmarks/rve_triaxial_3d/run.sh [BUILD_DIR] [OUT_DIR]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="$(realpath -m "${1:-$root/build}")"
out="$(realpath -m "${2:-$here/results}")"
mkdir -p "$out"
sed -e "s#^set Output directory.*#set Output directory = $out#" \
    -e "s#\.\./rve_setup_3d#$root/rve_templates/rve_setup_3d#; s#\.\./packings/#$root/rve_templates/packings/#" \
    -e "s#set Loading steps   = 4#set Loading steps   = 20#; s#set Axial strain    = 0.02#set Axial strain    = 0.10#" \
    "$root/rve_templates/examples/triaxial_3d.prm" > "$out/triaxial_10.prm"
start=$(date +%s)
"$build/dealii_app/rve_driver/fe2dem-rve" "$out/triaxial_10.prm" | tee "$out/fe2dem-rve.log"
echo "wall_s $(( $(date +%s) - start ))" | tee -a "$out/fe2dem-rve.log"
/usr/bin/python3 "$here/plot.py" "$out/rve.csv" "$out/triaxial.png"
