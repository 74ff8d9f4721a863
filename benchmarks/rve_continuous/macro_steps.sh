#!/usr/bin/env bash
# fe2dem's quasi-static iterations against the continuous limit (issue 35):
# one_element_qs_small_3d.prm in 4, 8 and 16 load steps, and the continuous
# reference (fe2dem-rve, tests/dynamics_rve/triaxial_continuous_rve.prm at
# 0.065 /s); tables by curves.py --prepared into results/macro_steps.txt.
#   macro_steps.sh BUILD [--force]       about 25 min on two cores
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
[[ $# -ge 1 ]] || { sed -n '2,7p' "$0"; exit 2; }
build="$(cd "$1" && pwd)"; force="${2:-}"
out="$here/results/macro_steps"
mkdir -p "$out"
source "$here/../common.sh"
rebase() { sed -e "s|\.\./\.\./|$root/|g" "$@"; }
ref="$out/continuous_0.065"
[[ "$force" == "--force" ]] && rm -f "$ref/rve.csv"
if needs_run "$ref/case.prm" "$ref/rve.csv" < <(rebase "$root/tests/dynamics_rve/triaxial_continuous_rve.prm" | sed 's/RATE/0.065/'); then
  "$build/dealii_app/rve_driver/fe2dem-rve" "$ref/case.prm" --output-directory "$ref" > "$ref/run.log" 2>&1
fi
for n in 4 8 16; do
  d="$out/steps_$n"
  [[ "$force" == "--force" ]] && rm -f "$d/summary.csv"
  if needs_run "$d/case.prm" "$d/summary.csv" < <(rebase "$here/one_element_qs_small_3d.prm" | sed "s/LOAD_STEPS/$n/; s|^set Output directory.*|set Output directory = $d|"); then
    t0=$SECONDS
    "$build/dealii_app/solver/fe2dem" "$d/case.prm" > "$d/run.log" 2>&1
    echo "steps_$n: $((SECONDS - t0)) s"
  fi
done
# each run at the reference's rows (every 0.25 %), interpolated along its own steps
/usr/bin/python3 "$here/curves.py" --prepared 1e5 compare "$ref/rve.csv" \
  "$out/steps_4/summary.csv" "$out/steps_8/summary.csv" "$out/steps_16/summary.csv" > "$here/results/macro_steps.txt"
cat "$here/results/macro_steps.txt"
