#!/usr/bin/env bash
# The 3D frame membrane (fix_rve_servo_membrane_3d.tpp) against its two claims:
# 1. it holds an inner sphere that passes through a gap of the frame: the
#    probe of membrane_probe_3d.py, shot at a square hole of the face x = 0,
#    leaves the frame without it (status escaped, x < 0) and stays inside
#    with it (still running, membrane contacts > 0, x > 0);
# 2. it never acts on a packing as built: a solve of PACKING at F = I gives
#    the same status, stress and membrane count 0 with and without it.
# Usage: check_membrane_3d.sh FE2DEM_LIGGGHTS TEMPLATE LATTICE_PREFIX PACKING WORKDIR
set -euo pipefail
exe=$1 template=$2 lattice=$3 packing=$4 work=$5
here="$(cd "$(dirname "$0")" && pwd)"
rm -rf "$work"; mkdir -p "$work"
probe=$(python3 "$here/membrane_probe_3d.py" "$lattice" "$work/probe")
run() { # data-prefix probe-id membrane [extra -var pairs]
  local prefix=$1 id=$2 membrane=$3; shift 3
  (cd "$work" && "$exe" -in "$here/membrane_probe_3d.liggghts" -log none -var template "$template" \
     -var rve_data "$prefix.rve.data" -var rve_vars "$prefix.vars" -var probe "$id" \
     -var membrane "$membrane" "$@") | grep '^MEMBRANE_PROBE' | tail -1
}
field() { awk -v k="$2" '{for (i = 1; i < NF; ++i) if ($i == k) print $(i + 1)}' <<<"$1"; }
fail=0
check() { if eval "$2"; then echo "ok    $1"; else echo "FAIL  $1"; fail=1; fi; }
shot="-var dt 2e-8 -var relax_tol 1e-30 -var on_failure flag"
without=$(run "$work/probe" "$probe" no $shot); echo "membrane no:  $without"
with=$(run "$work/probe" "$probe" yes $shot); echo "membrane yes: $with"
check "without membrane the probe escapes (status 3)" '[[ $(field "$without" status) == 3 ]]'
check "without membrane the probe is beyond x = 0" "awk 'BEGIN{exit !($(field "$without" x) < 0)}'"
check "with membrane the solve goes on (status 0)" '[[ $(field "$with" status) == 0 ]]'
check "with membrane it acted (membrane steps > 0)" "awk 'BEGIN{exit !($(field "$with" membrane_steps) > 0)}'"
check "with membrane the probe is inside (x > 0)" "awk 'BEGIN{exit !($(field "$with" x) > 0)}'"
plain_no=$(run "$packing" 0 no); echo "packing, membrane no:  $plain_no"
plain_yes=$(run "$packing" 0 yes); echo "packing, membrane yes: $plain_yes"
check "on the packing as built it never acts (membrane steps 0)" '[[ $(field "$plain_yes" membrane_steps) == 0 ]]'
check "on the packing as built results are the same with and without it" '[[ "$plain_no" == "$plain_yes" ]]'
exit $fail
