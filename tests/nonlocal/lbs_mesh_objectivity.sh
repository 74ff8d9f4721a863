#!/usr/bin/env bash
# The [LBS] biaxial test of benchmarks/lbs2018 on the 2x4 and 4x8 meshes,
# local and with the nonlocal operator (R = 2.5 mm, as run.sh's nonlocal_*
# cases), to 10 % axial strain on 2 ranks; then check_mesh_objectivity.py:
# after the peak the two nonlocal meshes must agree at least twice as well
# as the two local ones (issue 37). About 10 minutes on 2 cores.
# Usage: lbs_mesh_objectivity.sh BUILD_DIR WORK_DIR
set -euo pipefail
build=$1 work=$2
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
rm -rf "$work"; mkdir -p "$work"
for c in local_2x4 local_4x8 nonlocal_2x4 nonlocal_4x8; do
  cells=${c#*_}
  mkdir -p "$work/$c"
  {
    sed "s#\.\./\.\./rve_templates#$root/rve_templates#; s#^set Output directory.*#set Output directory = out#" \
      "$root/benchmarks/lbs2018/lbs2018.prm"
    printf 'subsection Geometry\n  set Cells x = %s\n  set Cells y = %s\nend\n' "${cells%x*}" "${cells#*x}"
    [[ $c != nonlocal_* ]] || printf 'subsection Nonlocal\n  set Interaction radius = 0.0025\nend\n'
  } > "$work/$c/case.prm"
  mpirun --allow-run-as-root --oversubscribe -np 2 "$build/dealii_app/solver/fe2dem" "$work/$c/case.prm" \
    > "$work/$c/run.log" 2>&1 || { tail -n 20 "$work/$c/run.log"; exit 1; }
done
/usr/bin/python3 "$here/../check_mesh_objectivity.py" "$work"/local_2x4/out "$work"/local_4x8/out -- \
  "$work"/nonlocal_2x4/out "$work"/nonlocal_4x8/out
