#!/usr/bin/env bash
# Coupler overhead per DEM step: the reference RVE through the coupler and
# fix rve/servo versus the same packing and steps under bare Debian
# liggghts, interleaved, as a ratio of medians. The measurement lives in
# benchmarks/rve_cost/ (results appended to its results.csv).
# Usage: benchmarks/perf/overhead.sh [BUILD_DIR] [PACKING_PREFIX] [STEPS] [REPEATS]
exec "$(dirname "${BASH_SOURCE[0]}")/../rve_cost/run.sh" "$@"
