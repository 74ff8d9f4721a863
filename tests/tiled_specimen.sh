#!/usr/bin/env bash
# The DNS specimens of benchmarks/lbs2018 are periodic packings tiled by
# rve_templates/tile_packing.py and framed by build_frame.py. Checks on the
# small test packing tiled 2 x 1: the tiled packing has the same contact
# statistics (every particle keeps its periodic neighbours), a cell twice as
# wide, and fe2dem-rve compresses the rectangular specimen isotropically to
# 150 kN/m with the contract checks of check_rve_csv.py.
# Usage: tiled_specimen.sh FE2DEM_RVE OUTDIR
set -euo pipefail
exe=$1 out=$2
src="$(cd "$(dirname "$0")/.." && pwd)"
rm -rf "$out"; mkdir -p "$out"
python3 "$src/rve_templates/tile_packing.py" "$src/rve_templates/packings/small_2d.periodic.data" 2 1 "$out/tiled.periodic.data"
python3 "$src/rve_templates/build_frame.py" "$out/tiled.periodic.data" tiled --outdir "$out" --allow-rectangular --quiet
python3 - "$src/rve_templates/packings/small_2d" "$out/tiled" <<'PY'
import sys
def stats(base):
    return dict(l.split()[:2] for l in open(base + ".stats.txt") if len(l.split()) >= 2)
def lx(base):
    return next(float(l.split()[3]) for l in open(base + ".vars") if "rve_Lx" in l)
one, two = stats(sys.argv[1]), stats(sys.argv[2])
bad = [k for k in ("coordination", "coordination_mechanical", "packing_fraction", "anisotropy")
       if one[k] != two[k]]
bad += [f"n_contacts {two['n_contacts']} != 2 x {one['n_contacts']}"] \
    if int(two["n_contacts"]) != 2 * int(one["n_contacts"]) else []
bad += [f"Lx {lx(sys.argv[2])} != 2 x {lx(sys.argv[1])}"] \
    if abs(lx(sys.argv[2]) - 2 * lx(sys.argv[1])) > 1e-15 else []
for k in bad:
    print(f"FAIL: tiled packing: {k} (small_2d {one.get(k, '')}, tiled {two.get(k, '')})")
print("tiled packing:", {k: two[k] for k in ("n_inner", "n_frame", "coordination", "anisotropy")})
sys.exit(1 if bad else 0)
PY
cat > "$out/isotropic.prm" <<PRM
subsection RVE
  set Template = $src/rve_templates/rve_setup_2d.liggghts
  set Packing  = $out/tiled
end
subsection Path
  set Type            = isotropic
  set Pressure        = 1.5e5
  set Isotropic steps = 5
end
PRM
"$exe" "$out/isotropic.prm" --output-directory "$out/run"
python3 "$src/tests/check_rve_csv.py" "$out/run/rve.csv" isotropic 1.5e5 5 6
