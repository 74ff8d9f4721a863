#!/usr/bin/env bash
# Installs what is missing, builds in build/, runs the demo and plots it:
# the [LBS] biaxial test on one element (4 RVEs of the reference packing),
# 2 MPI ranks, to 10 % axial strain (about a minute on 2 cores).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$root/build" -j "$(nproc)"
prm="$root/dealii_app/examples/biaxial_1x1.prm"
out="$root/output/biaxial_1x1"
mpirun --allow-run-as-root --oversubscribe -np 2 "$root/build/dealii_app/solver/fe2dem" "$prm"
/usr/bin/python3 "$root/scripts/plot_summary.py" "$out/biaxial.png" "1x1=$out/summary.csv"
echo "results: $out (summary.csv, history.h5, solution.pvd for ParaView)   plot: $out/biaxial.png"
