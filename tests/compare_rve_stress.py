#!/usr/bin/env python3
"""One-element check on the full stress tensor: the Cauchy stress of IP 0 in
fe2dem's history.h5 against fe2dem-rve's rve.csv, step by step. Every
component must agree within TOL of the stress norm |sigma| (Frobenius) of
the fe2dem-rve row, and the largest shear component within SHEAR_TOL (default
TOL) of itself.
Usage: compare_rve_stress.py HISTORY_H5 RVE_CSV SKIP_ROWS [TOL [SHEAR_TOL]]
  SKIP_ROWS: rve.csv rows before the first one compared (row 0 is F = I)."""
import csv
import math
import sys

import h5py

history, rve_csv, skip = sys.argv[1], sys.argv[2], int(sys.argv[3])
tol = float(sys.argv[4]) if len(sys.argv) > 4 else 0.02
shear_tol = float(sys.argv[5]) if len(sys.argv) > 5 else tol
with h5py.File(history, "r") as f:
    macro = f["sigma"][:, 0, :]
rows = list(csv.DictReader(open(rve_csv)))[skip:]
dim = math.isqrt(macro.shape[1])
names = [f"sigma{i}{j}" for i in range(1, dim + 1) for j in range(1, dim + 1)]
if len(rows) != len(macro) or not rows:
    print(f"FAIL: {len(macro)} history.h5 steps vs {len(rows)} rve.csv rows")
    sys.exit(1)
fails = 0
for s, (m, r) in enumerate(zip(macro, rows), 1):
    ref = [float(r[n]) for n in names]
    norm = math.sqrt(sum(x * x for x in ref))
    worst = max(range(len(names)), key=lambda k: abs(m[k] - ref[k]))
    err = abs(m[worst] - ref[worst]) / norm
    shear = max((k for k in range(len(names)) if names[k][-2] != names[k][-1]), key=lambda k: abs(ref[k]))
    err_shear = abs(m[shear] - ref[shear]) / abs(ref[shear])
    ok = err <= tol and err_shear <= shear_tol
    fails += not ok
    print(f"{'ok  ' if ok else 'FAIL'} step {s}: largest difference {names[worst]} {err:.4f} of |sigma| "
          f"= {norm:.6g}; {names[shear]} macro {m[shear]:.6g}, RVE {ref[shear]:.6g} ({err_shear:.4f})")
print(f"{len(rows) - fails} of {len(rows)} steps within {tol} (shear {shear_tol})")
sys.exit(1 if fails else 0)
