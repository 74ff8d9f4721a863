#!/bin/bash
# Extra checks of the 3D YADE reference (README.md, section 3D, "Checks"):
# lsyf_1000 triaxial at the base rate with dt halved, with the servo time
# TAU doubled, and at a quarter of the base rate.  One YADE thread, one run
# after the other, into results_3d/checks/; then compare_3d.py --pair.
#   benchmarks/yade_periodic/checks_3d.sh [--force]
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
DATA="$HERE/../../rve_templates/packings/lsyf_1000.periodic.data"
OUT="$HERE/results_3d/checks"
mkdir -p "$OUT"
run() {  # NAME FACTOR OVERRIDES...
    local name=$1 f=$2; shift 2
    if [ ! -f "$OUT/$name.csv" ] || [ "$FORCE" = 1 ]; then
        local t1 t2
        t1=$(date +%s.%N)
        yade -n -x -j1 "$HERE/periodic_3d.py" "$DATA" "$OUT/$name.csv" triaxial "$f" "$@" >"$OUT/$name.log" 2>&1
        t2=$(date +%s.%N)
        echo "${name}_wall_shell $(awk -v a="$t1" -v b="$t2" 'BEGIN{printf "%.1f", b-a}') s"
    fi
}
FORCE=0
[ "${1:-}" = "--force" ] && FORCE=1
# dt halved: the step-counted parameters doubled, so that the ramp, hold and
# servo period are the same in time
run lsyf_1000_triaxial_rate1_dt4e-7 1 DT=4e-7 N_RAMP=200000 ISO_HOLD=10000 NCTL=20
run lsyf_1000_triaxial_rate1_tau1e-4 1 TAU=1e-4
run lsyf_1000_triaxial_rate0.25 0.25
R="$HERE/results_3d"
/usr/bin/python3 "$HERE/compare_3d.py" --results "$R" --no-files \
    --pair "dtcheck=$R/lsyf_1000_triaxial_rate1.csv,$OUT/lsyf_1000_triaxial_rate1_dt4e-7.csv" \
    --pair "servocheck=$R/lsyf_1000_triaxial_rate1.csv,$OUT/lsyf_1000_triaxial_rate1_tau1e-4.csv" \
    --pair "quarterrate=$R/lsyf_1000_triaxial_rate1.csv,$OUT/lsyf_1000_triaxial_rate0.25.csv" \
    --pair "quarter_vs_half=$R/lsyf_1000_triaxial_rate0.5.csv,$OUT/lsyf_1000_triaxial_rate0.25.csv" \
    | grep -E "^(dtcheck|servocheck|quarterrate|quarter_vs_half)"
