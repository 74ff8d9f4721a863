#!/usr/bin/env python3
"""A deformation path as a 'Table file' for fe2dem-rve (Type = table): one
row per step, the dim^2 components of F row by row.

  history_to_table.py HISTORY_H5 IP OUT_TXT [DATASET]
      F of integration point IP in each step of an fe2dem history.h5 (the
      macro F: with 'Initial pressure' it is relative to the prepared RVE);
      DATASET F_nonlocal: the averaged F, what the IP's RVE saw (F itself
      in a local run, which stores no F_nonlocal).
  history_to_table.py RVE_CSV START_ROW OUT_TXT
      F of each rve.csv row after START_ROW, relative to that row's F:
      F_row = F_k F_start^-1 (e.g. START_ROW the last isotropic row).

With rows at equal times (explicit dynamics writes one per load step of
'End time' / 'Load steps'; a continuous drive one per 'Loading steps' row),
'Table row time' set and 'Table start' = isotropic stage, fe2dem-rve
replays the path continuously from an RVE prepared at 'Pressure' as the
macro run prepares it (issue 35: the quasi-static RVE along the very
kinematics of a macro run)."""
import csv
import sys

import numpy as np

if len(sys.argv) not in (4, 5) or (len(sys.argv) == 5 and sys.argv[4] not in ("F", "F_nonlocal")):
    sys.exit(__doc__)
source, index, out = sys.argv[1], int(sys.argv[2]), sys.argv[3]
dataset = sys.argv[4] if len(sys.argv) == 5 else "F"
if source.endswith(".csv"):
    rows = list(csv.DictReader(open(source)))
    dim = 3 if "F33" in rows[0] else 2
    names = [f"F{i}{j}" for i in range(1, dim + 1) for j in range(1, dim + 1)]
    Fs = [np.array([float(r[n]) for n in names]).reshape(dim, dim) for r in rows]
    if not 0 <= index < len(Fs) - 1:
        sys.exit(f"{source}: START_ROW = {index} must be a row before the last ({len(Fs)} rows)")
    start_inverse = np.linalg.inv(Fs[index])
    F = np.array([(Fk @ start_inverse).ravel() for Fk in Fs[index + 1:]])
    what = f"rows {index + 1}.. of {source} relative to row {index}"
else:
    import h5py

    with h5py.File(source, "r") as f:
        if dataset not in f:  # a local run: its RVEs saw F
            dataset = "F"
        F = f[dataset][:, index, :]
    dim = int(round(F.shape[1] ** 0.5))
    what = f"IP {index} of {source}"
with open(out, "w") as t:
    t.write(f"# {dataset if not source.endswith('.csv') else 'F'} of {what}: {len(F)} rows of {dim * dim} components (row by row)\n")
    for row in F:
        t.write(" ".join(f"{v:.17g}" for v in row) + "\n")
print(f"{out}: {len(F)} rows")
