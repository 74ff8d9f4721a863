#!/usr/bin/env bash
# Cost of the 3D multiscale solver per macro step and per RVE solve, with one
# point per element (one RVE per hexahedron, hourglass control) and with full
# 2x2x2 Gauss integration (eight), side by side in one sitting: the case of
# tests/multiscale_3d (2 x 1 x 1 hexahedra, small_3d RVEs, triaxial at
# 130 kPa, 1 isotropic + 6 axial steps), 1 rank each, one after the other.
# ANALYSIS = dynamic: explicit dynamics instead, the case of
# tests/dynamics_rve/column_3d.prm (2 hexahedra in a column, 320 macro steps
# of 150 DEM steps each, 0.0384 s), into results_cost_3d_dynamic.csv; the
# "macro_iterations" column then counts macro time steps.
# Usage: cost_3d.sh [BUILD_DIR] [NP] [quasi-static|dynamic]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build="$(realpath "${1:-$here/../../build}")" np=${2:-1} analysis=${3:-quasi-static}
case $analysis in
  quasi-static) case_prm="$here/../../tests/multiscale_3d/macro.prm" csv="$here/results_cost_3d.csv" ;;
  dynamic) case_prm="$here/../../tests/dynamics_rve/column_3d.prm" csv="$here/results_cost_3d_dynamic.csv" ;;
  *) echo "cost_3d.sh: ANALYSIS = '$analysis': use quasi-static or dynamic" >&2; exit 2 ;;
esac
work=${COST3D_WORKDIR:-/tmp/fe2dem-cost-3d}/$analysis
commit=$(git -C "$here" rev-parse --short HEAD)
[[ -f $csv ]] || echo "date,commit,host,np,quadrature,rves,steps,wall_s,wall_per_step_s,rve_solves,s_per_rve_solve,dem_steps,us_per_dem_step,macro_iterations" > "$csv"
for q in "one point" "full"; do
  tag=${q// /_}
  wall=$("$here/run_case.sh" "$build" "$case_prm" "$work/$tag" "$np" \
    "subsection Finite elements\n  set Quadrature = $q\nend")
  /usr/bin/python3 - "$work/$tag/summary.csv" "$wall" "$np" "$tag" "$commit" "$(hostname)" "$csv" <<'PY'
import csv, sys, datetime
path, wall, np_, tag, commit, host, out = sys.argv[1:]
rows = list(csv.DictReader(open(path)))
wall = float(wall)
solves = sum(int(r["rve_solves"]) for r in rows)
dem = sum(int(r["dem_steps"]) for r in rows)
its = sum(int(r["macro_iterations"]) for r in rows)
rves = 2 if tag == "one_point" else 16
rve_s = sum(float(r["rve_rank_mean_s"]) for r in rows) * int(np_)
vals = [datetime.datetime.now().isoformat(timespec="seconds"), commit, host, np_, tag, rves, len(rows),
        f"{wall:.1f}", f"{wall / len(rows):.2f}", solves, f"{rve_s / solves:.4f}", dem,
        f"{1e6 * rve_s / dem:.2f}", its]
print(f"{tag}: {rves} RVEs, {len(rows)} steps, wall {wall:.1f} s = {wall / len(rows):.2f} s per load step; "
      f"{solves} RVE solves, {rve_s / solves * 1e3:.2f} ms each; {dem} DEM steps, "
      f"{1e6 * rve_s / dem:.2f} us each; {its} DR iterations or time steps, {wall / its * 1e3:.1f} ms each")
open(out, "a").write(",".join(map(str, vals)) + "\n")
PY
done
