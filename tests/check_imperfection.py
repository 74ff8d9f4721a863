#!/usr/bin/python3
"""subsection Imperfection: the IP nearest 'Point' got the weakened packing.
Usage: check_imperfection.py HISTORY_H5 X Y Z
In the first row of history.h5 (after the preparation at the initial
pressure) the IP nearest (X, Y, Z) must have a solid fraction at least 0.03
below every other IP's (25 of 178 inner spheres removed: about 0.045) and
at most 90 % of the fewest contacts of the others (a wrong IP, or none,
fails both)."""
import sys

import h5py
import numpy as np

history, point = sys.argv[1], np.array([float(v) for v in sys.argv[2:5]])
with h5py.File(history, "r") as h:
    x = h["ip_position"][()]
    phi = h["packing_fraction"][0]
    contacts = h["contacts"][0]
seed = int(np.argmin(np.linalg.norm(x - point, axis=1)))
others = [k for k in range(len(x)) if k != seed]
print(f"seeded IP {seed} at {x[seed]}: solid fraction {phi[seed]:.4f}, contacts {contacts[seed]}; "
      f"others {phi[others]}, {contacts[others]}")
fails = []
if not phi[seed] <= phi[others].min() - 0.03:
    fails.append("the seeded IP's solid fraction is not 0.03 below the others'")
if not contacts[seed] <= 0.9 * contacts[others].min():
    fails.append("the seeded IP does not have 10 % fewer contacts than the others")
for f in fails:
    print("FAIL:", f)
sys.exit(1 if fails else 0)
