#!/usr/bin/env python3
"""An acceleration of the multiscale solver acted and kept the curve.

Usage: check_acceleration.py skip SUMMARY REFERENCE_SUMMARY TOLERANCE
       check_acceleration.py bounded SUMMARY REFERENCE_SUMMARY TOLERANCE RUN_LOG
Asserts the same number of rows as the reference run and |stress ratio -
reference| <= TOLERANCE x (reference peak) at every step, and that the
acceleration acted:
  skip     ('Skip tolerance'): strictly fewer RVE solves in total;
  bounded  ('DEM steps per iteration'): at least one RVE solve stopped at
           its step limit (the progress lines of RUN_LOG count them).
"""
import csv
import re
import sys

mode, rows, ref = sys.argv[1], list(csv.DictReader(open(sys.argv[2]))), list(csv.DictReader(open(sys.argv[3])))
tol = float(sys.argv[4])
failures = []
peak = max(float(r["stress_ratio_mean"]) for r in ref)
diff = max(abs(float(a["stress_ratio_mean"]) - float(b["stress_ratio_mean"])) for a, b in zip(rows, ref))
if mode == "skip":
    solves = [sum(int(r["rve_solves"]) for r in x) for x in (rows, ref)]
    print(f"RVE solves {solves[0]} with skipping, {solves[1]} without ({solves[0] / solves[1]:.3f})")
    if not solves[0] < solves[1]:
        failures.append("skipping did not save any RVE solve")
elif mode == "bounded":
    unconverged = [int(m) for m in re.findall(r"unconverged RVE returns (\d+)", open(sys.argv[5]).read())]
    steps = [sum(int(r["dem_steps"]) for r in x) for x in (rows, ref)]
    print(f"unconverged RVE returns per load step {unconverged}; DEM steps {steps[0]} bounded, "
          f"{steps[1]} reference")
    if len(unconverged) != len(rows):
        failures.append(f"{len(unconverged)} progress lines with unconverged counts for {len(rows)} rows")
    if not sum(unconverged) > 0:
        failures.append("no RVE solve stopped at the step limit: the bound never acted")
else:
    sys.exit(f"check_acceleration.py: unknown mode '{mode}' (skip | bounded)")
print(f"largest stress-ratio difference {diff / peak:.4f} of the peak {peak:.4f}")
if len(rows) != len(ref):
    failures.append(f"{len(rows)} rows, reference {len(ref)}")
if diff > tol * peak:
    failures.append(f"difference {diff / peak:.4f} of the peak > {tol}")
for f in failures:
    print("FAIL", f)
sys.exit(1 if failures else 0)
