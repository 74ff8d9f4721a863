#!/usr/bin/env bash
# Installs what is missing, configures and builds in build/, runs the whole ctest suite.
# Usage: scripts/run-tests.sh [extra ctest arguments, e.g. -R servo]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
jobs="$(nproc)"
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$root/build" -j "$jobs"
cd "$root/build"
ctest --output-on-failure -j "$jobs" "$@"
