#!/usr/bin/env bash
# ctest rve_table_replays_continuous_triaxial (issue 35): a continuous
# triaxial path of fe2dem-rve (small_3d prepared at 100 kPa, 2 % at
# 0.25 /s, 16 rows), its F rows after the isotropic stage turned into a
# table (history_to_table.py), replayed by Type = table with 'Table row
# time' = the path's time per row and 'Table start' = isotropic stage. The
# replay prescribes every component, the original held the lateral
# stresses by rate control: the same kinematics must give the same axial
# stress and deviator within 1.5 % at every row to the peak (1 %).
# Measured 0.91 % with 16 rows, 1.04 % with 8 (F is linear within a row,
# the rate-controlled lateral stretches are not); the replay's lateral
# stresses within 1.2 % of the held 100 kPa. After the peak small_3d's
# stress drops are not reproducible (up to 6.7 %): printed, not checked.
#   table_replay.sh FE2DEM_RVE SOURCE_DIR OUT_DIR
set -euo pipefail
rve=$1 src=$2 out=$3
rm -rf "$out"; mkdir -p "$out/path" "$out/replay"
rebase() { sed "s#\.\./\.\./rve_templates#$src/../rve_templates#" "$@"; }
# 16 rows of 0.125 % at 0.25 /s: 0.005 s a row
rebase "$src/dynamics_rve/triaxial_continuous_rve.prm" | sed 's#RATE#0.25#; s#^\( *set Loading steps *=\).*#\1 16#' \
  | sed "0,/^subsection RVE/s//subsection RVE\n  set Inner start = affine/" > "$out/path/case.prm"
"$rve" "$out/path/case.prm" --output-directory "$out/path" > "$out/path/log"
/usr/bin/python3 "$src/history_to_table.py" "$out/path/rve.csv" 2 "$out/replay/table.txt"
"$src/rve_continuous/cases.sh" replay "$out/replay/table.txt" 0.005 150 > "$out/replay/case.prm"
"$rve" "$out/replay/case.prm" --output-directory "$out/replay" > "$out/replay/log"
grep -q "continuous table: 42 timed solves of 150 DEM steps per row" "$out/replay/log" \
  || { echo "FAIL: the replay did not run as a continuous table"; grep "continuous" "$out/replay/log"; exit 1; }
/usr/bin/python3 "$src/compare_triaxial.py" "$out/replay/rve.csv" "$out/path/rve.csv" 3 0.015 8
