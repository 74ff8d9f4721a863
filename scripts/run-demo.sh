#!/usr/bin/env bash
# Installs what is missing, builds in build/, runs the demo and plots it.
# Until the macro solver lands (issue 4) the demo is one RVE of the [LBS]
# reference packing in biaxial compression through fe2dem-rve.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$root/build" -j "$(nproc)"
out="$root/output/demo_biaxial_rve"
"$root/build/dealii_app/rve_driver/fe2dem-rve" "$root/rve_templates/examples/biaxial_2d.prm" \
  --output-directory "$out"
/usr/bin/python3 "$root/scripts/plot_rve.py" "$out/rve.csv" "$out/rve.png"
echo "results: $out/rve.csv   plot: $out/rve.png"
