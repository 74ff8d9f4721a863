#!/usr/bin/env bash
# Installs what is missing, configures and builds in build/, runs the ctest
# suite without the tests labelled 'long' (tests/tiers.cmake).
# Usage: scripts/run-tests.sh [--long | --all] [extra ctest arguments, e.g. -R servo]
#   --long   only the long verification runs (about 25 minutes on 2 cores)
#   --all    every test
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
tier=(-LE long)
case "${1:-}" in
  --long) tier=(-L long); shift ;;
  --all)  tier=(); shift ;;
esac
"$root/scripts/install-deps.sh"
jobs="$(nproc)"
# FE2DEM_WERROR: a warning in the project's own code fails the build (and CI).
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release -DFE2DEM_WERROR=ON
cmake --build "$root/build" -j "$jobs"
cd "$root/build"
ctest --output-on-failure -j "$jobs" ${tier[@]+"${tier[@]}"} "$@"
