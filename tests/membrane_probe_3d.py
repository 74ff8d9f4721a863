#!/usr/bin/env python3
"""A probe for the 3D frame membrane: the simple cubic lattice RVE of
make_lattice_3d.py + build_frame_3d.py with one small sphere (radius 0.3 R)
added in the cubic void between the frame layer x = 0 and the first inner
layer, 0.03 d and 0.01 d off the centre of the square hole of four face
spheres. The hole's clearance is about 0.36 R, so the sphere, shot towards
-x, passes the frame unless the membrane holds it; its projection lies
inside one Delaunay triangle of the face (off both diagonals of the square).

Usage: membrane_probe_3d.py LATTICE_PREFIX OUT_PREFIX
Writes OUT_PREFIX.rve.data and .vars; prints the probe's atom id.
"""
import sys

from rve_data_copy import RveData

src, out = sys.argv[1], sys.argv[2]
data = RveData(src)
atoms = data.atoms
spacing = float(next(l.split()[1] for l in open(src + ".lattice.txt") if l.startswith("spacing")))
radius = float(atoms[0][2]) / 2  # equal spheres
probe_id = max(int(a[0]) for a in atoms) + 1
x = 0.5 * spacing
y = 1.5 * spacing + 0.03 * spacing
z = 1.5 * spacing + 0.01 * spacing
rows = atoms + [[str(probe_id), "1", repr(0.6 * radius), atoms[0][3], repr(x), repr(y), repr(z)]]
data.vars_text = data.vars_text.replace(f"rve_natoms equal {len(atoms)}", f"rve_natoms equal {len(rows)}")
ninner = sum(a[1] == "1" for a in atoms)
data.vars_text = data.vars_text.replace(f"rve_ninner equal {ninner}", f"rve_ninner equal {ninner + 1}")
name = out.rsplit("/", 1)[-1]
data.write(out.rsplit("/", 1)[0] if "/" in out else ".", name, rows)
print(probe_id)
