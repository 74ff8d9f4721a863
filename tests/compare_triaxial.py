#!/usr/bin/env python3
"""One-element triaxial check (issue 35): the Cauchy stress of IP 0 in
fe2dem's history.h5 against fe2dem-rve's rve.csv, row by row: the axial
stress sigma_22 (axial direction y) and the deviator q = sigma_22 - (sigma_11
+ sigma_33) / 2 must agree within TOL (relative to the rve.csv value).
Usage: compare_triaxial.py HISTORY_H5 RVE_CSV SKIP_ROWS TOL [ROWS]
  HISTORY_H5 may also be another rve.csv (its rows after SKIP_ROWS).
  Either argument may be a comma-separated list of runs of one kind: the
  mean stress over them at each row (an ensemble, e.g. of rates a few per
  cent apart, whose stress drops after a peak fall at different strains).
  SKIP_ROWS: rve.csv rows before the first one compared (F = I and the
  isotropic stage); ROWS: compare only the first ROWS rows (e.g. to the
  peak); the others are printed. With an ensemble on either side each row
  also gives the standard error of the difference in q, sqrt(s_1^2/n_1 +
  s_2^2/n_2) / |q_ref| (s the sample standard deviations of q over each list)."""
import csv
import sys

import h5py

history, rve_csv, skip, tol = sys.argv[1], sys.argv[2], int(sys.argv[3]), float(sys.argv[4])
n_checked = int(sys.argv[5]) if len(sys.argv) > 5 else None
a, lateral = 1, [0, 2]
names = [f"sigma{i}{j}" for i in range(1, 4) for j in range(1, 4)]


def read_run(path):
    """The nine stress components at each row of one history.h5 or rve.csv."""
    if path.endswith(".csv"):
        return [[float(r[n]) for n in names] for r in list(csv.DictReader(open(path)))[skip:]]
    with h5py.File(path, "r") as f:
        return [list(s) for s in f["sigma"][:, 0, :]]


def mean_of(paths):
    """The row-wise mean over the comma-separated runs in PATHS (all of one length), and at each
    row the sample variance of q over the runs over their number (0 for one run)."""
    runs = [read_run(p) for p in paths.split(",")]
    if len({len(r) for r in runs}) != 1:
        print(f"FAIL: the runs of {paths} have {[len(r) for r in runs]} rows")
        sys.exit(1)
    n = len(runs)
    means = [[sum(r[k][c] for r in runs) / n for c in range(9)] for k in range(len(runs[0]))]
    q_var = [sum((axial_and_q(r[k])[1] - axial_and_q(m)[1]) ** 2 for r in runs) / (n - 1) / n if n > 1 else 0.0
             for k, m in enumerate(means)]
    return means, q_var


def axial_and_q(s):
    axial = s[4 * a]
    return axial, axial - 0.5 * (s[4 * lateral[0]] + s[4 * lateral[1]])


macro, macro_q_var = mean_of(history)
ref_means, ref_q_var = mean_of(rve_csv)
rows = [dict(zip(names, map(str, s))) for s in ref_means]
ensemble = "," in history or "," in rve_csv
if len(rows) != len(macro) or not rows:
    print(f"FAIL: {len(macro)} history.h5 steps vs {len(rows)} rve.csv rows")
    sys.exit(1)


fails, worst = 0, 0.0
for k, (m, r) in enumerate(zip(macro, rows), 1):
    ref = [float(r[n]) for n in names]
    (am, qm), (ar, qr) = axial_and_q(m), axial_and_q(ref)
    da, dq = (am - ar) / ar, (qm - qr) / qr  # > 0: larger in magnitude than the reference
    checked = n_checked is None or k <= n_checked
    ok = abs(da) <= tol and abs(dq) <= tol
    fails += checked and not ok
    if checked:
        worst = max(worst, abs(da), abs(dq))
    se = f" ± {100 * (macro_q_var[k - 1] + ref_q_var[k - 1]) ** 0.5 / abs(qr):.2f}" if ensemble else ""
    print(f"{('ok  ' if ok else 'FAIL') if checked else '    '} row {k}: axial {am:.6g} vs {ar:.6g} ({100 * da:+.2f} %), "
          f"q {qm:.6g} vs {qr:.6g} ({100 * dq:+.2f}{se} %), lateral {m[4 * lateral[0]]:.6g} {m[4 * lateral[1]]:.6g}")
n = len(rows) if n_checked is None else min(n_checked, len(rows))
print(f"{n - fails} of {n} rows checked within {tol}; largest difference {100 * worst:.2f} %")
sys.exit(1 if fails else 0)
