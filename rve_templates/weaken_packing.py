#!/usr/bin/env python3
"""A weakened copy of a 3D RVE packing: the N inner spheres nearest the
cell's centre removed, to seed a shear band ([LSYF] §3.2, problem 3: one RVE
with 25 particles removed; fe2dem's subsection Imperfection).

Usage: weaken_packing.py SRC_PREFIX OUT_PREFIX [N]   (N defaults to 25)

Reads SRC.rve.data and SRC.vars (build_frame_3d.py's layout: atom type 1
inner, 2 frame; ids in build order, inner first) and writes OUT.rve.data and
OUT.vars. The N inner spheres whose centres are nearest (Lx, Ly, Lz)/2 go
(ties: the lower id); the others keep their lines and order and are numbered
again 1, 2, ... in the order of their old ids, so inner spheres still come
first and the frame's relative order (which orders its groups in fix
rve/servo) is unchanged. The frame is not touched. The .vars get the new
counts, extreme radii and smallest mass, and the solid fraction less the
removed volume. Only the standard library.
"""
import math
import sys


def read_vars(path):
    """(lines, {name: value}) of a .vars file."""
    lines = open(path).read().splitlines()
    return lines, {l.split()[1]: l.split()[3] for l in lines if l.startswith("variable")}


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    src, out = sys.argv[1], sys.argv[2]
    n_remove = int(sys.argv[3]) if len(sys.argv) == 4 else 25
    lines = open(src + ".rve.data").read().splitlines()
    vars_lines, var = read_vars(src + ".vars")
    if "rve_Lz" not in var:
        sys.exit(f"weaken_packing.py: {src}.vars has no rve_Lz: a 3D packing is needed")
    L = [float(var["rve_L" + k]) for k in "xyz"]
    first = next(i for i, l in enumerate(lines) if l.strip() == "Atoms") + 2
    head, rows = lines[:first], [l.split() for l in lines[first:] if l.strip()]
    if any(len(r) != 7 for r in rows):
        sys.exit(f"weaken_packing.py: {src}.rve.data: expected rows 'id type diameter density x y z'")
    centre = [0.5 * l for l in L]

    def distance(r):
        return math.dist([float(v) for v in r[4:7]], centre)

    inner = [r for r in rows if r[1] == "1"]
    if n_remove < 1 or n_remove >= len(inner):
        sys.exit(f"weaken_packing.py: N = {n_remove}: give 1 to {len(inner) - 1} (the packing has {len(inner)} "
                 "inner spheres)")
    removed = sorted(inner, key=lambda r: (distance(r), int(r[0])))[:n_remove]
    gone = {int(r[0]) for r in removed}
    kept = [r for r in rows if int(r[0]) not in gone]
    new_id = {old: k + 1 for k, old in enumerate(sorted(int(r[0]) for r in kept))}
    kept = [[str(new_id[int(r[0])])] + r[1:] for r in kept]

    with open(out + ".rve.data", "w") as f:
        for l in head:
            if l.endswith(" atoms"):
                l = f"{len(kept)} atoms"
            elif l.startswith("FE2DEM"):
                l += f"; weakened: the {n_remove} inner spheres nearest the centre removed (weaken_packing.py)"
            f.write(l + "\n")
        f.writelines(" ".join(r) + "\n" for r in kept)

    def volume(r):
        return math.pi / 6.0 * float(r[2]) ** 3

    n_inner = sum(r[1] == "1" for r in kept)
    removed_fraction = sum(map(volume, removed)) / (L[0] * L[1] * L[2])
    update = {"rve_natoms": str(len(kept)), "rve_ninner": str(n_inner), "rve_nframe": str(len(kept) - n_inner),
              "rve_Rmin": f"{min(0.5 * float(r[2]) for r in kept):.16e}",
              "rve_Rmax": f"{max(0.5 * float(r[2]) for r in kept):.16e}",
              "rve_massmin": f"{min(volume(r) * float(r[3]) for r in kept):.16e}",
              "rve_phi": f"{float(var['rve_phi']) - removed_fraction:.9f}"}
    name = out.rsplit("/", 1)[-1]
    with open(out + ".vars", "w") as f:
        for l in vars_lines:
            w = l.split()
            if l.startswith("variable") and w[1] in update:
                l = f"variable {w[1]} equal {update[w[1]]}"
            elif l.startswith("#"):
                l = f"# FE2DEM RVE {name}: include after read_data {name}.rve.data ({src.rsplit('/', 1)[-1]} " \
                    f"with the {n_remove} inner spheres nearest the centre removed)"
            f.write(l + "\n")
    print(f"{out}: removed {n_remove} inner spheres (old ids {sorted(gone)}), all within "
          f"{max(map(distance, removed)):.4g} m of the centre (L/2 = {L[0] / 2:.4g} m); removed volume "
          f"{removed_fraction:.4f} of the cell; {len(kept)} atoms, {n_inner} inner; solid fraction {update['rve_phi']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
