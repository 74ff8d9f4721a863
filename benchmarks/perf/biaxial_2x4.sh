#!/usr/bin/env bash
# The full [LBS] 2x4 biaxial run to 10 % axial strain on 2 ranks with one
# setting of accelerations.sh (default: the fastest documented one on 2x4 at
# equal accuracy, mts50+incremental+extrap+affine+ext; mts50+incremental+extrap+affine
# and mts50+incremental before):
# wall time, DEM steps, RVE solves, macro iterations, peak stress ratio.
# Usage: benchmarks/perf/biaxial_2x4.sh [BUILD_DIR] [SETTING]
exec "$(dirname "${BASH_SOURCE[0]}")/accelerations.sh" "${1:-}" 2x4 "${2:-mts50+incremental+extrap+affine+ext}"
