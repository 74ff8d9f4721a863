#!/usr/bin/env bash
# Why the local 8x16 one-point run by slow loading stopped at 8.5 % (issue 37,
# session 55; README, "Session 55: the local 8x16 stop and the band's rate"): the RVE of
# its band IP 0 alone, along its own deformation path, at the macro run's pace
# and at half of it, and the same RVE in isochoric pure shear and simple shear.
#
# Usage: benchmarks/lbs2018/band_rve_replay.sh [--build DIR] [--refresh-path]
#
# The path is results/band_rve_path_ip0.txt: F of IP 0 in each of the 78 load
# steps of session 55's runs/mesh_8x16_op_quarter_sl0.25/history.h5
# (tests/history_to_table.py; rewritten from that run's history.h5 only with
# --refresh-path: a later run of that case is another path),
# plus four rows that continue its last increment. Each row is reached in the
# macro run's 5 ms (0.125 % at 0.25 /s) or in 10 ms; F moves linearly between
# rows ('Table row time'). ip0_path_5ms_rounded: the same rows rounded to 10
# significant digits (how sensitive the failure is to the path: README).
# One rank each; output in runs/band_rve_replay/CASE/; the three IP 0 cases
# write a particle dump after every row (CASE/particles/stepNNNN.*, for
# frame_pinch.py).
# Prints, per case, the last step rve.csv holds and the error, if any.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="$root/build"
refresh=no
while [[ $# -gt 0 ]]; do
  case $1 in
    --build) [[ $# -ge 2 ]] || { echo "band_rve_replay.sh: --build needs a directory" >&2; exit 2; }
             build="$(realpath -m "$2")"; shift 2 ;;
    --refresh-path) refresh=yes; shift ;;
    *) sed -n '2,/^set -euo/{/^#/p}' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 2 ;;
  esac
done
rve="$build/dealii_app/rve_driver/fe2dem-rve"
[[ -x $rve ]] || { echo "band_rve_replay.sh: no $rve (build first: cmake --build build)" >&2; exit 1; }
python=/usr/bin/python3
path="$here/results/band_rve_path_ip0.txt"
history="$here/runs/mesh_8x16_op_quarter_sl0.25/history.h5"
out="$here/runs/band_rve_replay"
mkdir -p "$out"
if [[ $refresh == yes ]]; then
  [[ -f $history ]] || { echo "band_rve_replay.sh: --refresh-path: no $history" >&2; exit 1; }
  "$python" "$root/tests/history_to_table.py" "$history" 0 "$out/ip0.txt" >/dev/null
  "$python" - "$out/ip0.txt" "$path" <<'EOF'
import sys
import numpy as np
a = np.loadtxt(sys.argv[1])
rows = np.vstack([a] + [a[-1] + k * (a[-1] - a[-2]) for k in range(1, 5)])
np.savetxt(sys.argv[2], rows, fmt="%.17g",
           header="F11 F12 F21 F22 of IP 0, runs/mesh_8x16_op_quarter_sl0.25/history.h5 steps 1-78, "
                  "then 4 rows continuing the last increment (band_rve_replay.sh)")
EOF
fi
[[ -f $path ]] || { echo "band_rve_replay.sh: no $path (--refresh-path makes it from $history)" >&2; exit 1; }
"$python" - "$out" "$path" <<'EOF'
import sys
import numpy as np
np.savetxt(f"{sys.argv[1]}/ip0_rounded.txt", np.loadtxt(sys.argv[2]), fmt="%.10g")
a = 1 + 0.005 * np.arange(1, 101)
np.savetxt(f"{sys.argv[1]}/pure_shear.txt", np.c_[a, 0 * a, 0 * a, 1 / a], fmt="%.10g")
g = -0.005 * np.arange(1, 101)
np.savetxt(f"{sys.argv[1]}/simple_shear.txt", np.c_[1 + 0 * g, g, 0 * g, 1 + 0 * g], fmt="%.10g")
EOF

# case, table, start, row time [s], particle dumps every N rows (0: none)
run_case() {
  local name=$1 table=$2 start=$3 row_time=$4 dumps=$5 dir="$out/$1"
  rm -rf "$dir/particles"  # a shorter rerun must not leave an older run's later dumps
  mkdir -p "$dir"
  local iso=""
  [[ $start == "isotropic stage" ]] && iso=$'  set Pressure        = 1.5e5\n  set Isotropic steps = 2'
  cat > "$dir/case.prm" <<EOF
# band_rve_replay.sh: $name
set Output directory = $dir
set Particle dumps every = $dumps
subsection RVE
  set Template       = $root/rve_templates/rve_setup_2d.liggghts
  set Packing        = $root/rve_templates/packings/lbs_ref
  set Friction       = 0.4
  set Rotation       = free
  set Check interval = 10
  set Inner start    = affine
end
subsection Path
  set Type             = table
  set Table file       = $table
  set Table start      = $start
$iso
  set Table row time   = $row_time
  set Control interval = 10
end
EOF
  local rc=0
  "$rve" "$dir/case.prm" > "$dir/run.log" 2>&1 || rc=$?
  local last_step=none
  [[ -f $dir/rve.csv ]] && last_step=$(tail -n 1 "$dir/rve.csv" | cut -d, -f1)
  local last; last=$(grep -m1 'error' "$dir/run.log" | cut -c1-160 || true)
  printf '| %s | %s s | %s | %s |\n' "$name" "$row_time" "$last_step" "${last:-no failure (exit $rc)}"
}
echo "| case | row time | last step in rve.csv | end |"
echo "|---|---|---|---|"
run_case ip0_path_5ms "$path" packing 0.005 1
run_case ip0_path_5ms_rounded "$out/ip0_rounded.txt" packing 0.005 1
run_case ip0_path_10ms "$path" packing 0.01 1
run_case pure_shear_1_per_s "$out/pure_shear.txt" "isotropic stage" 0.005 0
run_case simple_shear_1_per_s "$out/simple_shear.txt" "isotropic stage" 0.005 0
