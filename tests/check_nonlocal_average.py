#!/usr/bin/python3
"""The nonlocal F that drove each IP's material (history.h5 /F_nonlocal) is
the weighted average (Wendland's or the bell weight) of the local F over the
IPs within R, recomputed
here by brute force from /ip_position (independent of the solver's R-tree).
With alpha = 1 and fixed weights the incremental rule of
nonlocal_material.h sums to that total average: Fbar_I = sum_J a*_IJ F_J.
Also requires that the averaging changed F somewhere (the wiring acts).
With 'Volume change' = own (--own-volume) the stored F is scaled to each
IP's own volume at every commit, so the total average no longer holds; then
it requires det Fbar = det F at every IP and row instead (the isochoric part
is checked against the average in test_nonlocal_material.cpp).
Debian's python3 with python3-h5py.
Usage: check_nonlocal_average.py [--own-volume] HISTORY_H5 RADIUS [WEIGHT=wendland|bell] [TOLERANCE=1e-12]"""
import sys

import h5py
import numpy as np

args = sys.argv[1:]
own_volume = args[:1] == ["--own-volume"]
args = args[1:] if own_volume else args
path, radius = args[0], float(args[1])
weight = args[2] if len(args) > 2 else "wendland"
tol = float(args[3]) if len(args) > 3 else 1e-12
h = h5py.File(path, "r")
x = h["ip_position"][()]
F, Fbar = h["F"][()], h["F_nonlocal"][()]
r = np.linalg.norm(x[:, None, :] - x[None, :, :], axis=2)
s = np.minimum(r / radius, 1.0)
a = np.where(r <= radius, (1.0 - s) ** 4 * (4.0 * s + 1.0) if weight == "wendland" else (1.0 - s ** 2) ** 2, 0.0)
a /= a.sum(axis=1, keepdims=True)
sizes = (r <= radius).sum(axis=1)
change = np.abs(Fbar - F).max()
if own_volume:
    d = int(round(np.sqrt(F.shape[-1])))  # the rows store F flattened, d x d

    def det(G):
        return np.linalg.det(G.reshape(G.shape[:-1] + (d, d)))

    error = np.abs(det(Fbar) / det(F) - 1.0).max()
    what = "max |det Fbar / det F - 1|"
else:
    error = np.abs(Fbar - np.einsum("ij,sjk->sik", a, F)).max()
    what = "max |Fbar - sum a F|"
print(f"{weight}: {x.shape[0]} IPs, {F.shape[0]} steps, neighbour sets {sizes.min()}-{sizes.max()}: "
      f"{what} = {error:.3e} (tolerance {tol:g}), max |Fbar - F| = {change:.3e}")
ok = error <= tol and change > 100 * tol and sizes.max() > 1
sys.exit(0 if ok else 1)
