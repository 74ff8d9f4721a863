#!/usr/bin/env bash
# build_frame_3d.py picks a corner particle no other particle shares the
# corner with: sphere 1 (r 0.5 mm, nearest the box origin) and the larger
# sphere 2 (r 1 mm, 0.9 mm further along each axis) both cut the three planes
# through sphere 1's centre, so the default must skip sphere 1 and take
# sphere 2, and --corner-id 1 must stop with a message naming atom 2.
# Usage: check_corner_choice.sh BUILD_FRAME_3D WORK_DIR
set -euo pipefail
builder="$1"; work="$2"
mkdir -p "$work"
data="$work/two_corners.periodic.data"
cat > "$data" <<DATA
two spheres sharing a corner

4 atoms
1 atom types

0 0.01 xlo xhi
0 0.01 ylo yhi
0 0.01 zlo zhi

Atoms

1 1 0.001 2500 0.0002 0.0002 0.0002
2 1 0.002 2500 0.0011 0.0011 0.0011
3 1 0.001 2500 0.005 0.005 0.005
4 1 0.001 2500 0.005 0.0025 0.0075
DATA
python3 "$builder" "$data" --outdir "$work" --quiet
corner=$(awk '$1 == "corner_periodic_id" {print $2}' "$work/two_corners.stats.txt")
[[ "$corner" == 2 ]] || { echo "FAIL: corner_periodic_id $corner, expected 2"; exit 1; }
if msg=$(python3 "$builder" "$data" two_corners_forced --outdir "$work" --corner-id 1 --quiet 2>&1); then
  echo "FAIL: --corner-id 1 was accepted"; exit 1
fi
grep -q "atom 2 cuts all three planes" <<<"$msg" || { echo "FAIL: message: $msg"; exit 1; }
[[ ! -e "$work/two_corners_forced.rve.data" ]] || { echo "FAIL: output written on error"; exit 1; }
echo "PASS: default corner 2; --corner-id 1 refused: $msg"
