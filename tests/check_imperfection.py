#!/usr/bin/python3
"""subsection Imperfection: the IPs that should have the weakened packing got
it, and no other.
Usage: check_imperfection.py HISTORY_H5 X Y Z [SX SY SZ]
Without a size the seeded IP is the one nearest (X, Y, Z); with one, every
IP in the box of edges SX x SY x SZ centred there (the box must leave at
least one IP outside). In the first row of history.h5 (after the
preparation at the initial pressure) each seeded IP must have a solid
fraction at least 0.03 below every other IP's (25 of 178 inner spheres
removed: about 0.045) and at most 90 % of the fewest contacts of the others
(a wrong IP, a missing or an extra one fails both)."""
import sys

import h5py
import numpy as np

if len(sys.argv) not in (5, 8):
    sys.exit(__doc__)
history, point = sys.argv[1], np.array([float(v) for v in sys.argv[2:5]])
with h5py.File(history, "r") as h:
    x = h["ip_position"][()]
    phi = h["packing_fraction"][0]
    contacts = h["contacts"][0]
if len(sys.argv) == 8:
    size = np.array([float(v) for v in sys.argv[5:8]])
    seeds = [k for k in range(len(x)) if np.all(np.abs(x[k] - point) <= 0.5 * size)]
else:
    seeds = [int(np.argmin(np.linalg.norm(x - point, axis=1)))]
others = [k for k in range(len(x)) if k not in seeds]
if not seeds or not others:
    sys.exit(f"check_imperfection.py: the box leaves {len(seeds)} IPs inside and {len(others)} outside; "
             "it must leave at least one of each")
print(f"seeded IPs {seeds} at {x[seeds].tolist()}: solid fraction {phi[seeds]}, contacts {contacts[seeds]}; "
      f"others {phi[others]}, {contacts[others]}")
fails = []
if not phi[seeds].max() <= phi[others].min() - 0.03:
    fails.append("a seeded IP's solid fraction is not 0.03 below every other's")
if not contacts[seeds].max() <= 0.9 * contacts[others].min():
    fails.append("a seeded IP does not have 10 % fewer contacts than every other")
for f in fails:
    print("FAIL:", f)
sys.exit(1 if fails else 0)
