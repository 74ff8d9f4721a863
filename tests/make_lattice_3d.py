#!/usr/bin/env python3
"""make_lattice_3d.py -- a pre-compressed simple cubic lattice of equal spheres
as a periodic LIGGGHTS packing, for the closed-form check of the 3D RVE.

Usage: make_lattice_3d.py N OUT.periodic.data [--radius R] [--overlap DELTA]

N^3 spheres at spacing d = 2R (1 - DELTA) in a cubic cell of side N d, one
sphere at the cell origin; density 2500 kg/m^3. Each sphere touches its six
neighbours along the axes. Writes OUT.periodic.data (LIGGGHTS write_data
layout, atom_style sphere) and OUT.lattice.txt (`key value`: spacing,
radius, n) for the test.
"""
import argparse
import sys


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("n", type=int)
    ap.add_argument("out")
    ap.add_argument("--radius", type=float, default=1.5e-4, help="sphere radius [m]")
    ap.add_argument("--overlap", type=float, default=0.001,
                    help="overlap / diameter of neighbouring spheres (pre-compression)")
    a = ap.parse_args(argv)
    if a.n < 3:
        print(f"make_lattice_3d: N = {a.n}: need N >= 3 (inner spheres besides the frame)",
              file=sys.stderr)
        return 1
    if not 0.0 < a.overlap < 0.1:
        print(f"make_lattice_3d: --overlap {a.overlap} must be in (0, 0.1)", file=sys.stderr)
        return 1
    if not a.out.endswith(".periodic.data"):
        print(f"make_lattice_3d: output '{a.out}' must end in .periodic.data", file=sys.stderr)
        return 1
    d = 2.0 * a.radius * (1.0 - a.overlap)
    L = a.n * d
    with open(a.out, "w") as fh:
        fh.write(f"FE2DEM simple cubic lattice {a.n}^3, spacing {d!r}, radius {a.radius!r}\n\n")
        fh.write(f"{a.n ** 3} atoms\n1 atom types\n\n")
        for axis in "xyz":
            fh.write(f"0 {L!r} {axis}lo {axis}hi\n")
        fh.write("\nAtoms\n\n")
        k = 0
        for i in range(a.n):
            for j in range(a.n):
                for m in range(a.n):
                    k += 1
                    fh.write(f"{k} 1 {2.0 * a.radius!r} 2500 {i * d!r} {j * d!r} {m * d!r}\n")
    with open(a.out[: -len(".periodic.data")] + ".lattice.txt", "w") as fh:
        fh.write(f"spacing {d!r}\nradius {a.radius!r}\nn {a.n}\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
