#!/usr/bin/env python3
"""A slower dynamic run is closer to the quasi-static path: the largest
difference of any Cauchy stress component of IP 0 from fe2dem-rve's rows
(relative to |sigma| of the row, over all rows) is smaller for SLOW_H5 than
for FAST_H5.
Usage: check_rate_convergence.py SLOW_H5 FAST_H5 RVE_CSV SKIP_ROWS"""
import csv
import math
import sys

import h5py


def largest_difference(history, rows):
    with h5py.File(history, "r") as f:
        macro = f["sigma"][:, 0, :]
    dim = math.isqrt(macro.shape[1])
    names = [f"sigma{i}{j}" for i in range(1, dim + 1) for j in range(1, dim + 1)]
    worst = 0.0
    for m, r in zip(macro, rows):
        ref = [float(r[n]) for n in names]
        norm = math.sqrt(sum(x * x for x in ref))
        worst = max(worst, max(abs(a - b) for a, b in zip(m, ref)) / norm)
    return worst


slow, fast, rve_csv, skip = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
rows = list(csv.DictReader(open(rve_csv)))[skip:]
e_slow, e_fast = largest_difference(slow, rows), largest_difference(fast, rows)
ok = e_slow < e_fast
print(f"{'ok' if ok else 'FAIL'}: largest difference from the quasi-static path {e_slow:.4f} of |sigma| "
      f"(slow) vs {e_fast:.4f} (fast)")
sys.exit(0 if ok else 1)
