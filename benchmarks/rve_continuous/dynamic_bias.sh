#!/usr/bin/env bash
# Dynamic RVEs against the continuous reference (issue 35, item 5), one
# element, one point, in fe2dem's explicit dynamics over 0.0192, 0.0768 and
# 0.3072 s (rates 1.04, 0.26, 0.065 /s), against fe2dem-rve driven
# continuously at 0.0163 /s (a quarter of the slowest) on the same RVE:
#   shear              tests/dynamics_rve/shear_3d.prm (small_3d, every node
#                      prescribed, F12 to 2 %) against shear_continuous_rve.prm
#   triaxial_PACKING   tests/dynamics_rve/triaxial_3d.prm (RVE prepared at
#                      100 kPa, lateral pressure 100 kPa, 2 % along y) on
#                      PACKING (small_3d, lsyf_1000) against
#                      triaxial_continuous_rve.prm; also the reference at
#                      0.0651 /s, to show the reference's own rate spread
# Both sides run with 'Inner start' = affine (the default of explicit
# dynamics; the references get it here); the keep results are in
# results/inner_keep/.
#   ensemble_PACKING   the slowest triaxial run on PACKING as an ensemble:
#                      dynamic runs at 0.0651 /s x F, F = 1, 0.98, 1.02, 1.04
#                      (lsyf_1000) or 1, 0.96, 0.97, ..., 1.04 (small_3d, nine),
#                      against references at 0.0163 /s x the same factors,
#                      the means compared row by row (after the deviator's
#                      plateau single runs drop at different strains)
# Writes results/dynamic_bias/CASE/{dyn_*,reference*}/ and results/dynamic_bias*.txt.
#
#   dynamic_bias.sh BUILD [shear|triaxial_small_3d|triaxial_lsyf_1000|ensemble_lsyf_1000|ensemble_small_3d|all]
#   (default shear)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
[[ $# -ge 1 && $# -le 2 ]] || { sed -n '2,24p' "$0"; exit 2; }
build="$(cd "$1" && pwd)"
what="${2:-shear}"
end_times=(0.0192 0.0768 0.3072)
source "$here/../common.sh"
rebase() { sed "s#\.\./\.\./rve_templates#$root/rve_templates#" "$@"; }

# run_reference DIR PRM RATE [sed expression]: fe2dem-rve continuous at RATE
run_reference() {
  local dir=$1 prm=$2 rate=$3 edit=${4:-}
  # the reference runs the RVE the dynamic run has: 'Inner start' = auto is
  # affine in explicit dynamics, keep in fe2dem-rve
  needs_run "$dir/case.prm" "$dir/rve.csv" < <(rebase "$prm" | sed "s/^\( *set Strain rate *=\).*/\1 $rate/; /^ *set Inner start *=/d; $edit" \
    | sed "0,/^subsection RVE/s//subsection RVE\n  set Inner start = affine/") || return 0
  local t0=$SECONDS
  "$build/dealii_app/rve_driver/fe2dem-rve" "$dir/case.prm" --output-directory "$dir" > "$dir/run.log"
  echo "reference $dir: $((SECONDS - t0)) s"
}
# run_dynamic DIR PRM END_TIME [sed expression]
run_dynamic() {
  local dir=$1 prm=$2 end_time=$3 edit=${4:-}
  needs_run "$dir/macro.prm" "$dir/out/history.h5" < <(rebase "$prm" | sed "s#END_TIME#$end_time#g; $edit") || return 0
  local t0=$SECONDS
  (cd "$dir" && "$build/dealii_app/solver/fe2dem" macro.prm > log)
  rm -rf "$dir/out/checkpoints" "$dir"/out/*.vtu "$dir"/out/*.pvd
  echo "dynamic $dir: $((SECONDS - t0)) s"
}
rate_of() { awk -v t="$1" 'BEGIN {printf "%.3g", 0.02 / t}'; }

shear() {
  local out="$here/results/dynamic_bias"
  run_reference "$out/reference" "$root/tests/dynamics_rve/shear_continuous_rve.prm" 0.016276
  for t in "${end_times[@]}"; do
    run_dynamic "$out/dyn_$t" "$root/tests/dynamics_rve/shear_3d.prm" "$t"
  done
  {
    echo "# dynamic one-element simple shear (small_3d) against fe2dem-rve continuous at 0.0163 /s"
    for t in "${end_times[@]}"; do
      echo "## dynamic over $t s (shear rate $(rate_of $t) /s)"
      /usr/bin/python3 "$root/tests/compare_rve_stress.py" "$out/dyn_$t/out/history.h5" "$out/reference/rve.csv" 1 1 1
    done
  } | tee "$here/results/dynamic_bias.txt"
}

triaxial() {
  local packing=$1 out="$here/results/dynamic_bias/triaxial_$1"
  local edit="s#packings/small_3d#packings/$packing#"
  run_reference "$out/reference" "$root/tests/dynamics_rve/triaxial_continuous_rve.prm" 0.016276 "s/RATE/0.016276/; $edit"
  run_reference "$out/reference_0.0651" "$root/tests/dynamics_rve/triaxial_continuous_rve.prm" 0.0651 "s/RATE/0.0651/; $edit"
  for t in "${end_times[@]}"; do
    run_dynamic "$out/dyn_$t" "$root/tests/dynamics_rve/triaxial_3d.prm" "$t" "$edit"
  done
  {
    echo "# dynamic one-element triaxial ($packing, 100 kPa) against fe2dem-rve continuous at 0.0163 /s"
    for t in "${end_times[@]}"; do
      echo "## dynamic over $t s (axial rate $(rate_of $t) /s)"
      /usr/bin/python3 "$root/tests/compare_triaxial.py" "$out/dyn_$t/out/history.h5" "$out/reference/rve.csv" 3 0.02 || true
    done
    echo "## the reference's own rate spread: fe2dem-rve continuous at 0.0651 /s"
    /usr/bin/python3 "$root/tests/compare_triaxial.py" "$out/reference_0.0651/rve.csv" "$out/reference/rve.csv" 3 0.02 || true
  } | tee "$here/results/dynamic_bias_triaxial_$packing.txt"
}

# ensemble PACKING F...: the factors F besides 1
ensemble() {
  local packing=$1 out="$here/results/dynamic_bias/triaxial_$1"
  local edit="s#packings/small_3d#packings/$packing#" f t r
  local dyn=("$out/dyn_0.3072/out/history.h5") ref=("$out/reference/rve.csv") # made by 'triaxial PACKING'
  shift
  for f in "$@"; do
    t=$(awk -v f="$f" 'BEGIN {printf "%.6g", 0.3072 / f}')
    r=$(awk -v f="$f" 'BEGIN {printf "%.6g", 0.016276 * f}')
    run_dynamic "$out/dyn_$t" "$root/tests/dynamics_rve/triaxial_3d.prm" "$t" "$edit" &
    run_reference "$out/reference_$r" "$root/tests/dynamics_rve/triaxial_continuous_rve.prm" "$r" "s/RATE/$r/; $edit"
    wait
    dyn+=("$out/dyn_$t/out/history.h5")
    ref+=("$out/reference_$r/rve.csv")
  done
  local IFS=,
  {
    echo "# the slowest dynamic triaxial run ($packing, 0.0651 /s) as an ensemble of ${#dyn[@]} rates (x 1, $*),"
    echo "# its mean against the mean of ${#ref[@]} continuous references at 0.0163 /s x the same factors"
    /usr/bin/python3 "$root/tests/compare_triaxial.py" "${dyn[*]}" "${ref[*]}" 3 0.02 || true
    echo "## each reference against the references' mean (their own spread)"
    for r in "${ref[@]}"; do
      /usr/bin/python3 "$root/tests/compare_triaxial.py" "$r" "${ref[*]}" 3 0.02 | tail -1 || true
    done
    echo "## each dynamic run against the references' mean"
    for d in "${dyn[@]}"; do
      /usr/bin/python3 "$root/tests/compare_triaxial.py" "$d" "${ref[*]}" 3 0.02 | tail -1 || true
    done
  } | tee "$here/results/dynamic_bias_ensemble_$packing.txt"
}

case "$what" in
  shear) shear ;;
  triaxial_small_3d) triaxial small_3d ;;
  triaxial_lsyf_1000) triaxial lsyf_1000 ;;
  ensemble_lsyf_1000) ensemble lsyf_1000 0.98 1.02 1.04 ;;
  ensemble_small_3d) ensemble small_3d 0.96 0.97 0.98 0.99 1.01 1.02 1.03 1.04 ;;
  all) shear; triaxial small_3d; triaxial lsyf_1000 ;;
  *) sed -n '2,24p' "$0"; exit 2 ;;
esac
