#!/usr/bin/env python3
"""make_lattice.py -- a pre-compressed triangular lattice of equal discs as a
periodic LIGGGHTS packing, for the closed-form check of the RVE (issue 14).

Usage: make_lattice.py NX NY OUT.periodic.data [--radius R] [--overlap DELTA]

NX discs per row, NY rows (NY even, so that the cell is periodic), centre
spacing d = 2R (1 - DELTA), rows offset by d/2 and sqrt(3)/2 d apart; one disc
sits at the cell origin. Cell NX d x NY sqrt(3)/2 d. Areal density 2000 kg/m^2.
Writes OUT.periodic.data (LIGGGHTS write_data layout, atom_style sphere) and
OUT.lattice.txt (`key value`: spacing, radius, nx, ny) for the test.
"""
import argparse
import math
import sys


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("nx", type=int)
    ap.add_argument("ny", type=int)
    ap.add_argument("out")
    ap.add_argument("--radius", type=float, default=1.5e-4, help="disc radius [m]")
    ap.add_argument("--overlap", type=float, default=0.01,
                    help="overlap / diameter of neighbouring discs (pre-compression)")
    a = ap.parse_args(argv)
    if a.nx < 3 or a.ny < 4 or a.ny % 2:
        print(f"make_lattice: NX = {a.nx}, NY = {a.ny}: need NX >= 3 and an even NY >= 4 "
              "(the rows alternate, so an odd NY is not periodic)", file=sys.stderr)
        return 1
    if not 0.0 < a.overlap < 0.1:
        print(f"make_lattice: --overlap {a.overlap} must be in (0, 0.1)", file=sys.stderr)
        return 1
    d = 2.0 * a.radius * (1.0 - a.overlap)
    h = math.sqrt(3.0) / 2.0 * d
    lx, ly = a.nx * d, a.ny * h
    atoms = []
    for j in range(a.ny):
        for i in range(a.nx):
            atoms.append(((i + 0.5 * (j % 2)) * d, j * h))
    if not a.out.endswith(".periodic.data"):
        print(f"make_lattice: output '{a.out}' must end in .periodic.data", file=sys.stderr)
        return 1
    with open(a.out, "w") as fh:
        fh.write(f"FE2DEM triangular lattice {a.nx} x {a.ny}, spacing {d!r}, radius {a.radius!r}\n\n")
        fh.write(f"{len(atoms)} atoms\n1 atom types\n\n")
        fh.write(f"0 {lx!r} xlo xhi\n0 {ly!r} ylo yhi\n{-0.05 * lx!r} {0.05 * lx!r} zlo zhi\n\n")
        fh.write("Atoms\n\n")
        for k, (x, y) in enumerate(atoms):
            fh.write(f"{k + 1} 1 {2.0 * a.radius!r} 2000 {x!r} {y!r} 0\n")
    with open(a.out[: -len(".periodic.data")] + ".lattice.txt", "w") as fh:
        fh.write(f"spacing {d!r}\nradius {a.radius!r}\nnx {a.nx}\nny {a.ny}\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
