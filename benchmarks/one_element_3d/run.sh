#!/usr/bin/env bash
# The 3D one-element check: fe2dem (one hexahedron, one point = one RVE)
# and fe2dem-rve on the same packing and triaxial path, then the comparison
# of the axial stress and stress ratio at every axial step of fe2dem
# (every fifth of fe2dem-rve; tests/compare_one_element.py, 2 % tolerance).
# Usage: benchmarks/one_element_3d/run.sh BUILD_DIR OUT_DIR [small_3d]
#   small_3d: the first set-up (macro_small_3d.prm, rve_small_3d.prm), kept
#   for the record in results/small_3d (README).
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build="$(realpath -m "$1")" out="$(realpath -m "$2")"
case "${3:-}" in
  "") suffix="" ;;
  small_3d) suffix="_small_3d" ;;
  *) echo "run.sh: unknown set-up '$3' (known: small_3d, or none for lsyf_1000)" >&2; exit 2 ;;
esac
mkdir -p "$out"
sed "s#^set Output directory.*#set Output directory = $out/macro#; s#\.\./\.\./rve_templates#$here/../../rve_templates#" \
  "$here/macro$suffix.prm" > "$out/macro.prm"
sed "s#\.\./\.\./rve_templates#$here/../../rve_templates#" "$here/rve$suffix.prm" > "$out/rve.prm"
/usr/bin/time -f "fe2dem %e s" "$build/dealii_app/solver/fe2dem" "$out/macro.prm" > "$out/macro.log" 2>&1 &
/usr/bin/time -f "fe2dem-rve %e s" "$build/dealii_app/rve_driver/fe2dem-rve" "$out/rve.prm" \
  --output-directory "$out/rve" > "$out/rve.log" 2>&1
wait
tail -n 1 "$out/macro.log" "$out/rve.log"
python3 "$here/../../tests/compare_one_element.py" "$out/macro/summary.csv" "$out/rve/rve.csv" 2 0.02 5
