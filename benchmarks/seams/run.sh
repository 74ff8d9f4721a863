#!/usr/bin/env bash
# Runs the cases that must not change bit for bit across a redesign, with
# the programs of BUILD_DIR, into OUT_DIR (one folder per case):
#   one_element   tests/one_element/macro.prm, 1 rank, particle dumps, checkpoints
#   one_element_rve  tests/one_element/rve.prm through fe2dem-rve
#   demo_1x1      dealii_app/examples/biaxial_1x1.prm, 2 ranks (scripts/run-demo.sh)
#   mts20_2x4     benchmarks/perf/biaxial_2x4_strict.prm, 2 ranks, check10 + mts20
#   elastic_block dealii_app/examples/elastic_block.prm (neo-Hookean)
#   recommended_2x4  benchmarks/lbs2018/lbs2018.prm: 2x4, the recommended accelerations, 2 ranks
#   one_element_3d   tests/one_element_3d/shear_macro.prm, 3D with RVEs (dynamic relaxation)
#   dynamic_rve   tests/dynamics_rve/column_3d.prm, 3D RVEs in explicit dynamics, 2 ranks
#   rve_shear_3d_continuous  tests/slow_loading/shear_continuous_rve.prm through fe2dem-rve
#                 (3D timed solves along a turning path, inner_start affine)
#   rve_shear_3d_stepped     the same path in 4 quasi-static steps to 1 % (3D frame moves
#                 on the polar path with the affine velocity of inner_start affine)
# Compare two OUT_DIRs with compare.py.
# Usage: benchmarks/seams/run.sh BUILD_DIR OUT_DIR [CASE...]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="$(realpath -m "$1")" out="$(realpath -m "$2")"
shift 2
cases=("${@:-one_element one_element_rve demo_1x1 mts20_2x4 elastic_block recommended_2x4 one_element_3d dynamic_rve rve_shear_3d_continuous rve_shear_3d_stepped}")
read -r -a cases <<<"${cases[*]}"
mpirun=(mpirun --allow-run-as-root --oversubscribe)
fe2dem="$build/dealii_app/solver/fe2dem"
prm_of() { # PRM DIR [extra lines]: copy with absolute paths and the output in DIR/out
  sed "s#^set Output directory.*#set Output directory = $2/out#; s#\.\./\.\./rve_templates#$root/rve_templates#" "$1"
}
for c in "${cases[@]}"; do
  d="$out/$c"
  rm -rf "$d" && mkdir -p "$d"
  start=$(date +%s.%N)
  case $c in
    one_element)
      { prm_of "$root/tests/one_element/macro.prm" "$d"
        printf 'subsection Checkpoint\n  set Every = 2\n  set Keep = 10\nend\n'; } > "$d/case.prm"
      "${mpirun[@]}" -np 1 "$fe2dem" "$d/case.prm" > "$d/log" 2>&1 ;;
    one_element_rve)
      sed "s#\.\./\.\./rve_templates#$root/rve_templates#" "$root/tests/one_element/rve.prm" > "$d/case.prm"
      "$build/dealii_app/rve_driver/fe2dem-rve" "$d/case.prm" --output-directory "$d/out" > "$d/log" 2>&1 ;;
    demo_1x1)
      prm_of "$root/dealii_app/examples/biaxial_1x1.prm" "$d" > "$d/case.prm"
      "${mpirun[@]}" -np 2 "$fe2dem" "$d/case.prm" > "$d/log" 2>&1 ;;
    mts20_2x4)
      { prm_of "$root/benchmarks/perf/biaxial_2x4_strict.prm" "$d"
        printf 'subsection Material\n  set History = continuous\n  set DEM steps per iteration = 20\nend\n'
        printf 'subsection RVE\n  set Check interval = 10\nend\n'; } > "$d/case.prm"
      "${mpirun[@]}" -np 2 "$fe2dem" "$d/case.prm" > "$d/log" 2>&1 ;;
    elastic_block)
      prm_of "$root/dealii_app/examples/elastic_block.prm" "$d" > "$d/case.prm"
      "${mpirun[@]}" -np 1 "$fe2dem" "$d/case.prm" > "$d/log" 2>&1 ;;
    recommended_2x4)
      prm_of "$root/benchmarks/lbs2018/lbs2018.prm" "$d" > "$d/case.prm"
      "${mpirun[@]}" -np 2 "$fe2dem" "$d/case.prm" > "$d/log" 2>&1 ;;
    one_element_3d)
      prm_of "$root/tests/one_element_3d/shear_macro.prm" "$d" > "$d/case.prm"
      "${mpirun[@]}" -np 1 "$fe2dem" "$d/case.prm" > "$d/log" 2>&1 ;;
    dynamic_rve)
      prm_of "$root/tests/dynamics_rve/column_3d.prm" "$d" > "$d/case.prm"
      "${mpirun[@]}" -np 2 "$fe2dem" "$d/case.prm" > "$d/log" 2>&1 ;;
    rve_shear_3d_continuous)
      sed "s#\.\./\.\./rve_templates#$root/rve_templates#" "$root/tests/slow_loading/shear_continuous_rve.prm" > "$d/case.prm"
      "$build/dealii_app/rve_driver/fe2dem-rve" "$d/case.prm" --output-directory "$d/out" > "$d/log" 2>&1 ;;
    rve_shear_3d_stepped)
      sed -e "s#\.\./\.\./rve_templates#$root/rve_templates#" -e "s/^\( *set Drive *=\).*/\1 stepped/" \
        -e "s/^\( *set Loading steps *=\).*/\1 4/" -e "s/^\( *set Shear strain *=\).*/\1 0.01/" \
        "$root/tests/slow_loading/shear_continuous_rve.prm" > "$d/case.prm"
      "$build/dealii_app/rve_driver/fe2dem-rve" "$d/case.prm" --output-directory "$d/out" > "$d/log" 2>&1 ;;
    *) echo "unknown case '$c'" >&2; exit 2 ;;
  esac
  awk -v s="$start" -v e="$(date +%s.%N)" -v c="$c" 'BEGIN {printf "%s %.1f s\n", c, e - s}'
done
