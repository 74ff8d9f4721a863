#!/usr/bin/env bash
# One-contact check of the tangential law: Debian LIGGGHTS 3.8
# (hooke/stiffness, tangential history) against YADE 2023.02a
# (Law2_ScGeom_FrictPhys_CundallStrack on Ig2_Sphere_Sphere_ScGeom) under the
# same prescribed kinematics (README.md). About 15 s.
# Usage: benchmarks/contact_pair/run.sh        (LIGGGHTS=/path/to/binary to override)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
LIGGGHTS="${LIGGGHTS:-liggghts}"
PY=/usr/bin/python3
cd "$here"
mkdir -p results
"$LIGGGHTS" -in pair.liggghts -var out results/liggghts.csv -log none -echo none > results/liggghts.log 2>&1
# variant: phase 3.5 (slide back 1e-5 m in 2000 steps) so that phases 4-6 start elastic
"$LIGGGHTS" -in pair.liggghts -var out results/liggghts_elastic.csv -var N3b 2000 -log none -echo none > results/liggghts_elastic.log 2>&1
# YADE, default Ig2_Sphere_Sphere_ScGeom (avoidGranularRatcheting True) and with it False
yade -n -x -j1 pair_yade.py results/yade.csv 1 > results/yade.log 2>&1
yade -n -x -j1 pair_yade.py results/yade_agr0.csv 0 > results/yade_agr0.log 2>&1
yade -n -x -j1 pair_yade.py results/yade_elastic.csv 1 2000 > results/yade_elastic.log 2>&1
grep -a -E '^(YADE|largest)' results/yade.log results/yade_agr0.log results/yade_elastic.log
echo "== LIGGGHTS vs YADE (avoidGranularRatcheting True, YADE's default)"
"$PY" compare.py results/liggghts.csv results/yade.csv | tee results/compare.txt
echo "== LIGGGHTS vs YADE (avoidGranularRatcheting False)"
"$PY" compare.py results/liggghts.csv results/yade_agr0.csv | tee results/compare_agr0.txt
echo "== variant with phase 3.5 (phases 4-6 start elastic), YADE default"
"$PY" compare.py results/liggghts_elastic.csv results/yade_elastic.csv | tee results/compare_elastic.txt
