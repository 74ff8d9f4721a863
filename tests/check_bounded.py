#!/usr/bin/env python3
"""Multiple time stepping ('DEM steps per iteration'): bounded RVE solves
did stop unconverged, and the curve still matches the reference run.

Usage: check_bounded.py SUMMARY RUN_LOG REFERENCE_SUMMARY TOLERANCE
Asserts the same number of rows, at least one unconverged RVE return in the
progress lines of RUN_LOG (so the bound acted), and |stress ratio -
reference| <= TOLERANCE x (reference peak) at every step.
"""
import csv
import re
import sys

rows = list(csv.DictReader(open(sys.argv[1])))
unconverged = [int(m) for m in re.findall(r"unconverged RVE returns (\d+)", open(sys.argv[2]).read())]
ref = list(csv.DictReader(open(sys.argv[3])))
tol = float(sys.argv[4])
failures = []
peak = max(float(r["stress_ratio_mean"]) for r in ref)
diff = max(abs(float(a["stress_ratio_mean"]) - float(b["stress_ratio_mean"])) for a, b in zip(rows, ref))
steps = [sum(int(r["dem_steps"]) for r in x) for x in (rows, ref)]
print(f"unconverged RVE returns per load step {unconverged}; DEM steps {steps[0]} bounded, "
      f"{steps[1]} reference; largest stress-ratio difference {diff / peak:.4f} of the peak {peak:.4f}")
if len(rows) != len(ref):
    failures.append(f"{len(rows)} rows, reference {len(ref)}")
if len(unconverged) != len(rows):
    failures.append(f"{len(unconverged)} progress lines with unconverged counts for {len(rows)} rows")
if not sum(unconverged) > 0:
    failures.append("no RVE solve stopped at the step limit: the bound never acted")
if diff > tol * peak:
    failures.append(f"difference {diff / peak:.4f} of the peak > {tol}")
for f in failures:
    print("FAIL", f)
sys.exit(1 if failures else 0)
