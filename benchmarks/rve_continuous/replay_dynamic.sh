#!/usr/bin/env bash
# The dynamic one-element triaxial test against the quasi-static RVE along
# its very kinematics (issue 35, item 5). The one-point element with
# rollers and pressure faces also shears through its bilinear modes (F12,
# F13, F31, F32 up to 5e-4), which fe2dem-rve's triaxial path with shear
# stretches 0 does not follow. Here fe2dem-rve replays the element's F
# history (tests/history_to_table.py, Type = table, 'Table row time',
# 'Table start' = isotropic stage) from the same prepared state
# (triaxial_continuous_rve.prm: 'Isotropic control' = prepared), so that
# only the driver differs:
#   dyn          tests/dynamics_rve/triaxial_3d.prm on small_3d at 0.065 /s
#                (0.3072 s, 40 rows), also with the RVE 'Check interval' =
#                100 and 25 (1 and 4 checks per 100-step macro step; 50: 2)
#   replay       its F path at a quarter of its rate (Control interval 150;
#                also 100 and 50: the solve structure of fe2dem-rve)
#   step / step_replay  the first 0.25 % with a row at every macro step
#                (480 rows) and its replay with one 100-step solve per row:
#                the same F at every macro step, the same solves
# Writes results/replay_dynamic/ and results/replay_dynamic.txt.
#   replay_dynamic.sh BUILD
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
[[ $# -eq 1 ]] || { sed -n '2,22p' "$0"; exit 2; }
build="$(cd "$1" && pwd)"
out="$here/results/replay_dynamic"
mkdir -p "$out"

# dynamic DIR END_TIME LOAD_STEPS [sed expression]: the rate stays 0.02 / 0.3072 s
dynamic() {
  local dir=$out/$1 t=$2 n=$3 edit=${4:-}
  [[ -f "$dir/out/history.h5" ]] && return
  mkdir -p "$dir"
  "$root/tests/rve_continuous/cases.sh" dynamic "$t" "$n" | sed "$edit" > "$dir/macro.prm"
  (cd "$dir" && "$build/dealii_app/solver/fe2dem" macro.prm > log)
  rm -rf "$dir/out/checkpoints" "$dir"/out/*.vtu "$dir"/out/*.pvd
}
# replay DIR FROM ROW_TIME CONTROL_INTERVAL [Check interval]
replay() {
  local dir=$out/$1 from=$out/$2 row_time=$3 ci=$4 check=${5:-50}
  [[ -f "$dir/rve.csv" ]] && return
  mkdir -p "$dir"
  /usr/bin/python3 "$root/tests/history_to_table.py" "$from/out/history.h5" 0 "$dir/table.txt" > /dev/null
  "$root/tests/rve_continuous/cases.sh" replay table.txt "$row_time" "$ci" "$check" > "$dir/case.prm"
  (cd "$dir" && "$build/dealii_app/rve_driver/fe2dem-rve" case.prm --output-directory . > log)
}

dynamic dyn 0.3072 40 &
dynamic dyn_check100 0.3072 40 "/subsection RVE/a\  set Check interval = 100" &
wait
dynamic dyn_check25 0.3072 40 "/subsection RVE/a\  set Check interval = 25" &
dynamic step 0.0384 480 &
wait
replay replay dyn 0.03072 150 &
replay replay_ci100 dyn 0.03072 100 &
wait
replay replay_ci50 dyn 0.03072 50 &
replay step_replay step 8e-5 100 &
wait

q_rows() { # q differences (%) of RUN against REF at the given rows
  /usr/bin/python3 - "$@" <<'PY'
import csv, sys
import h5py
def q_of(path):
    if path.endswith(".csv"):
        rows = list(csv.DictReader(open(path)))[3:]
        return [float(r["sigma22"]) - 0.5 * (float(r["sigma11"]) + float(r["sigma33"])) for r in rows]
    s = h5py.File(path, "r")["sigma"][:, 0, :]
    return [v[4] - 0.5 * (v[0] + v[8]) for v in s]
ref, runs, rows = q_of(sys.argv[1]), sys.argv[2].split(","), [int(k) for k in sys.argv[3].split(",")]
for run in runs:
    q = q_of(run)
    print(f"| {run.split('replay_dynamic/')[1]} | " + " | ".join(f"{100 * (q[k - 1] / ref[k - 1] - 1):+.2f}" for k in rows) + " |")
PY
}
{
  echo "# q against fe2dem-rve replaying the dynamic run's F path at a quarter of its rate (replay), rows at 0.05 % each"
  echo "| run | 0.05 % | 0.10 % | 0.15 % | 0.20 % | 0.25 % | 0.30 % | 0.40 % | 0.50 % | 0.75 % | 1.00 % |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|"
  q_rows "$out/replay/rve.csv" "$out/dyn/out/history.h5,$out/dyn_check100/out/history.h5,$out/dyn_check25/out/history.h5,$out/replay_ci100/rve.csv,$out/replay_ci50/rve.csv" 1,2,3,4,5,6,8,10,15,20
  echo
  echo "# the first 0.25 %, a row per macro step: the dynamic run against the replay of its F at every step (the same solves)"
  echo "| run | step 1 | 6 | 21 | 40 | 120 | 200 | 280 | 360 | 480 |"
  echo "|---|---|---|---|---|---|---|---|---|---|"
  q_rows "$out/step_replay/rve.csv" "$out/step/out/history.h5" 1,6,21,40,120,200,280,360,480
} | tee "$here/results/replay_dynamic.txt"
