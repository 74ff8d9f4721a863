#!/bin/bash
# YADE periodic 3D reference, issue 35 (see README.md, section "3D").
#
#   benchmarks/yade_periodic/run_3d.sh [--force] [CASE ...]
#
# CASE = PACKING:PATH:RATE_FACTOR[:NAME=VALUE+NAME=VALUE...] (PATH
# triaxial|shear|shear_cv, factor 1 = 0.25 /s, 0.5 = 0.125 /s; the optional fourth
# field overrides parameters of periodic_3d.py and names the CSV, e.g.
# small_3d:triaxial:1:RELAX_EVERY=2+EPS_END=0.03 -> ..._rate1_RELAX_EVERY2_EPS_END0.03.csv,
# the path held at rest every 0.5 %, issue 35); default: small_3d and
# lsyf_1000, both paths, both rates.
# Runs periodic_3d.py on rve_templates/packings/PACKING.periodic.data (or, if
# there is none, PACKING.rve.data: a weakened RVE), one
# YADE thread, one run after the other, into results_3d/PACKING_PATH_rateF.csv
# (+ _trace.csv, .log).  A case whose CSV exists is skipped (a CSV is only
# written by a finished run) unless --force.  Then compare_3d.py prints the
# `name value unit` summary and writes results_3d/tables_3d.md and
# results_3d/yade_3d.png.  Installs Debian's yade if missing (needs root).
set -euo pipefail

HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
PACK="$ROOT/rve_templates/packings"
OUT="$HERE/results_3d"
FORCE=0
CASES=()
for a in "$@"; do
    if [ "$a" = "--force" ]; then FORCE=1; else CASES+=("$a"); fi
done
if [ ${#CASES[@]} -eq 0 ]; then
    for p in small_3d lsyf_1000; do
        for path in triaxial shear; do
            for f in 1 0.5; do CASES+=("$p:$path:$f"); done
        done
    done
fi

if ! command -v yade >/dev/null 2>&1; then
    echo "run_3d.sh: yade not found, installing Debian's package" >&2
    apt-get update
    DEBIAN_FRONTEND=noninteractive apt-get install -y yade
fi
if ! /usr/bin/python3 -c "import numpy, matplotlib" >/dev/null 2>&1; then
    # only needed for the plot; compare_3d.py works without them
    DEBIAN_FRONTEND=noninteractive apt-get install -y python3-numpy python3-matplotlib || true
fi

mkdir -p "$OUT"
echo "yade_version $(dpkg-query -W -f='${Version}' yade 2>/dev/null || echo unknown) -"
T0=$(date +%s.%N)
for c in "${CASES[@]}"; do
    IFS=: read -r name path f extra <<<"$c"
    overrides=(); tag=""
    if [ -n "${extra:-}" ]; then
        IFS=+ read -r -a overrides <<<"$extra"
        tag="_$(echo "$extra" | tr -d '=' | tr '+' '_')"
    fi
    data="$PACK/$name.periodic.data"
    # an RVE without a periodic file (a weakened one): its .rve.data, read as the periodic packing
    [ -f "$data" ] || data="$PACK/$name.rve.data"
    [ -f "$data" ] || { echo "run_3d.sh: no packing $PACK/$name.periodic.data or .rve.data" >&2; exit 1; }
    csv="$OUT/${name}_${path}_rate$f$tag.csv"
    log="$OUT/${name}_${path}_rate$f$tag.log"
    if [ -f "$csv" ] && [ $FORCE -eq 0 ]; then
        echo "run_3d.sh: $csv exists, skipped (--force to redo)" >&2
        continue
    fi
    rm -f "$csv" "${csv%.csv}_trace.csv"
    t1=$(date +%s.%N)
    if ! yade -n -x -j1 "$HERE/periodic_3d.py" "$data" "$csv" "$path" "$f" ${overrides[@]+"${overrides[@]}"} >"$log" 2>&1 \
        || [ ! -f "$csv" ]; then
        echo "run_3d.sh: YADE run $c failed, see $log" >&2
        tail -n 20 "$log" >&2
        exit 1
    fi
    t2=$(date +%s.%N)
    echo "${name}_${path}_rate${f}${tag}_wall_shell $(awk -v a="$t1" -v b="$t2" 'BEGIN{printf "%.1f", b-a}') s"
done
T3=$(date +%s.%N)

/usr/bin/python3 "$HERE/compare_3d.py" --results "$OUT"
echo "wall_total_shell $(awk -v a="$T0" -v b="$T3" 'BEGIN{printf "%.1f", b-a}') s"
