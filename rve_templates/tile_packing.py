#!/usr/bin/env python3
"""tile_packing.py -- tile a periodic 2D packing NX x NY times.

Usage: tile_packing.py PERIODIC.data NX NY OUT.periodic.data

Reads a periodic packing written by LIGGGHTS ``write_data`` (atom_style
sphere, as read by build_frame.py) with cell Lx x Ly and writes a periodic
packing of NX*NY copies in a cell NX*Lx x NY*Ly, copy (i, j) shifted by
(i*Lx, j*Ly). The result is periodic again, so ``build_frame.py
--allow-rectangular`` turns it into a specimen with a servo-controlled frame:
this is how the [LBS] direct numerical simulations (the reference RVE tiled
1x2 and 2x4, physics.md §3.1) are built (benchmarks/lbs2018/).

Ids: copy k = i + NX*j gets ids k*N + original id (N = largest original id).
stdlib only. Exit code 0 = success, 1 = error (message names file and value).
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from build_frame import FrameError, read_data  # noqa: E402


def tile(src, nx, ny, out):
    data = read_data(src)
    (xlo, xhi), (ylo, yhi), (zlo, zhi) = data["box"]["x"], data["box"]["y"], data["box"]["z"]
    lx, ly = xhi - xlo, yhi - ylo
    atoms = data["atoms"]
    nmax = max(a["id"] for a in atoms)
    lines = []
    for j in range(ny):
        for i in range(nx):
            k = i + nx * j
            for a in atoms:
                # wrap into the cell first so that the copies do not overlap each other's images
                x = xlo + (a["x"] - xlo) % lx + i * lx
                y = ylo + (a["y"] - ylo) % ly + j * ly
                lines.append(f"{k * nmax + a['id']} {a['type']} {a['d']:.17g} {a['rho']:.17g} "
                             f"{x:.17g} {y:.17g} {a['z']:.17g} 0 0 0")
    types = max(a["type"] for a in atoms)
    with open(out + ".tmp", "w") as fh:
        fh.write(f"FE2DEM tile_packing.py: {os.path.basename(src)} tiled {nx} x {ny}\n\n")
        fh.write(f"{len(lines)} atoms\n{types} atom types\n\n")
        fh.write(f"{xlo:.17g} {xlo + nx * lx:.17g} xlo xhi\n")
        fh.write(f"{ylo:.17g} {ylo + ny * ly:.17g} ylo yhi\n")
        fh.write(f"{zlo:.17g} {zhi:.17g} zlo zhi\n\nAtoms\n\n")
        fh.write("\n".join(lines) + "\n")
    os.replace(out + ".tmp", out)  # never leave a half-written packing behind
    print(f"tile_packing.py: {src}: {len(atoms)} particles x {nx * ny} copies = {len(lines)} "
          f"in {nx * lx:.6g} x {ny * ly:.6g} -> {out}")


def main(argv):
    if len(argv) != 5:
        print(__doc__.split("\n\n")[1], file=sys.stderr)
        return 2
    try:
        nx, ny = int(argv[2]), int(argv[3])
    except ValueError:
        print(f"tile_packing.py: NX and NY must be integers, got '{argv[2]}' '{argv[3]}'",
              file=sys.stderr)
        return 1
    if nx < 1 or ny < 1:
        print(f"tile_packing.py: NX = {nx}, NY = {ny}: both must be >= 1", file=sys.stderr)
        return 1
    try:
        tile(argv[1], nx, ny, argv[4])
    except FrameError as exc:
        print(f"tile_packing.py: {exc}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
