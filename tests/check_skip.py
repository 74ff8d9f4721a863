#!/usr/bin/env python3
"""Skip tolerance: fewer RVE solves than the reference run, and the same
curve within a tolerance.

Usage: check_skip.py SKIP_SUMMARY REFERENCE_SUMMARY TOLERANCE
Asserts the same number of rows, strictly fewer RVE solves in total, and
|stress ratio - reference| <= TOLERANCE x (reference peak) at every step.
"""
import csv
import sys

skip = list(csv.DictReader(open(sys.argv[1])))
ref = list(csv.DictReader(open(sys.argv[2])))
tol = float(sys.argv[3])
failures = []
solves = [sum(int(r["rve_solves"]) for r in rows) for rows in (skip, ref)]
peak = max(float(r["stress_ratio_mean"]) for r in ref)
diff = max(abs(float(a["stress_ratio_mean"]) - float(b["stress_ratio_mean"])) for a, b in zip(skip, ref))
print(f"RVE solves {solves[0]} with skipping, {solves[1]} without ({solves[0] / solves[1]:.3f}); "
      f"largest stress-ratio difference {diff / peak:.4f} of the peak {peak:.4f}")
if len(skip) != len(ref):
    failures.append(f"{len(skip)} rows, reference {len(ref)}")
if not solves[0] < solves[1]:
    failures.append("skipping did not save any RVE solve")
if diff > tol * peak:
    failures.append(f"difference {diff / peak:.4f} of the peak > {tol}")
for f in failures:
    print("FAIL", f)
sys.exit(1 if failures else 0)
