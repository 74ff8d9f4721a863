#!/bin/bash
# YADE periodic biaxial reference (see README.md).
#
#   benchmarks/yade_periodic/run.sh [PACKING_NAME ...]     (default: lbs_ref lbs_a005)
#
# Installs Debian's yade if missing (apt-get; needs root), runs
# biaxial_periodic.py on rve_templates/packings/NAME.periodic.data at the base
# rate (factor 1) and at half the rate (factor 0.5), one YADE thread each, one
# run after the other, and writes results/NAME_rate{1,0.5}.csv (+ _trace.csv,
# .log), results/tables.md and results/biaxial_yade.png.  Prints `name value
# unit` lines (compare.py) and the wall times.
set -euo pipefail

HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
PACK="$ROOT/rve_templates/packings"
OUT="$HERE/results"
NAMES=("$@")
[ ${#NAMES[@]} -gt 0 ] || NAMES=(lbs_ref lbs_a005)

if ! command -v yade >/dev/null 2>&1; then
    echo "run.sh: yade not found, installing Debian's package" >&2
    apt-get update
    DEBIAN_FRONTEND=noninteractive apt-get install -y yade
fi
if ! /usr/bin/python3 -c "import numpy, matplotlib" >/dev/null 2>&1; then
    # only needed for the plot; compare.py works without them
    DEBIAN_FRONTEND=noninteractive apt-get install -y python3-numpy python3-matplotlib || true
fi

mkdir -p "$OUT"
YADE_VERSION="$(dpkg-query -W -f='${Version}' yade 2>/dev/null || echo unknown)"
echo "yade_version $YADE_VERSION -"

T0=$(date +%s.%N)
for name in "${NAMES[@]}"; do
    data="$PACK/$name.periodic.data"
    [ -f "$data" ] || { echo "run.sh: no packing $data" >&2; exit 1; }
    for f in 1 0.5; do
        csv="$OUT/${name}_rate$f.csv"
        log="$OUT/${name}_rate$f.log"
        t1=$(date +%s.%N)
        if ! yade -n -x -j1 "$HERE/biaxial_periodic.py" "$data" "$csv" "$f" >"$log" 2>&1 \
            || ! grep -q "^\[.*\] wrote " "$log"; then
            echo "run.sh: YADE run $name rate x$f failed, see $log" >&2
            tail -n 20 "$log" >&2
            exit 1
        fi
        t2=$(date +%s.%N)
        echo "${name}_rate${f}_wall_shell $(awk -v a="$t1" -v b="$t2" 'BEGIN{printf "%.1f", b-a}') s"
    done
done
T3=$(date +%s.%N)

/usr/bin/python3 "$HERE/compare.py" "$OUT" "${NAMES[@]}"
echo "wall_total_shell $(awk -v a="$T0" -v b="$T3" 'BEGIN{printf "%.1f", b-a}') s"
