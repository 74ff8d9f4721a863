#!/usr/bin/env bash
# Results do not depend on the number of ranks, also with more ranks than
# cores and than RVEs per rank (issue 19): fe2dem on PRM on each rank count
# of NPS (oversubscribed), summary.csv and history.h5 bitwise against the
# first. SED: an extra sed expression for the copies (e.g. a finer mesh).
# Usage: many_ranks.sh FE2DEM PRM WORKDIR "NP..." [SED]
set -uo pipefail
exe=$1 prm=$2 work=$3 nps=$4 extra=${5:-}
tests=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$tests/.." && pwd)
rm -rf "$work"; mkdir -p "$work"
first=
for np in $nps; do
  d="$work/np$np"; mkdir -p "$d"
  sed "s#^set Output directory.*#set Output directory = out#; s#\.\./\.\./rve_templates#$root/rve_templates#; $extra" \
    "$prm" > "$d/macro.prm"
  start=$(date +%s.%N)
  (cd "$d" && mpiexec --allow-run-as-root --oversubscribe -np "$np" "$exe" macro.prm > run.log 2>&1) ||
    { tail -n 20 "$d/run.log"; echo "FAIL: fe2dem on $np ranks"; exit 1; }
  echo "$np ranks: $(($(wc -l < "$d/out/summary.csv") - 1)) load steps in" \
    "$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN {printf "%.1f", e - s}') s"
  if [[ -z $first ]]; then first=$np; continue; fi
  python3 "$tests/compare_summaries.py" "$work/np$first/out/summary.csv" "$d/out/summary.csv" || exit 1
  /usr/bin/python3 "$tests/compare_histories.py" "$work/np$first/out/history.h5" "$d/out/history.h5" || exit 1
  echo "ok: $np ranks equal $first bitwise"
done
