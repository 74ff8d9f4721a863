#!/usr/bin/env bash
# Coupler cost per DEM step of two builds side by side: bench_rve_steps of
# OLD_BUILD and NEW_BUILD alternating (order swapped every pair), pinned to
# core 1, check interval 50; one line "old_us new_us" per pair, then the
# medians and the median of the pair ratios new/old.
# Usage: benchmarks/seams/cost_pairs.sh OLD_BUILD NEW_BUILD TEMPLATE PACKING_PREFIX STEPS PAIRS
set -euo pipefail
old=$1/benchmarks/rve_cost/bench_rve_steps new=$2/benchmarks/rve_cost/bench_rve_steps
template=$3 packing=$4 steps=$5 pairs=$6
pin=(); command -v taskset >/dev/null && [[ $(nproc) -ge 2 ]] && pin=(taskset -c 1)
run() { "${pin[@]}" "$1" "$template" "$packing" "$steps" 50 | awk '/coupler_us_per_step/ {print $2}'; }
out=$(for ((k = 0; k < pairs; ++k)); do
  if ((k % 2 == 0)); then o=$(run "$old"); n=$(run "$new"); else n=$(run "$new"); o=$(run "$old"); fi
  echo "$o $n"
done)
echo "$out"
/usr/bin/python3 - "$out" <<'PY'
import sys, statistics as st
rows = [tuple(map(float, l.split())) for l in sys.argv[1].splitlines()]
r = [n / o for o, n in rows]
print(f"old median {st.median(o for o, _ in rows):.3f} us, new median {st.median(n for _, n in rows):.3f} us, "
      f"new/old median of pairs {st.median(r):.4f} ({min(r):.4f}-{max(r):.4f})")
PY
