#!/usr/bin/env python3
"""fe2dem-rve's continuous triaxial path against YADE's periodic cell (issue 35), stdlib only.

Usage: check_against_yade.py RVE_CSV YADE_CSV TOLERANCE
YADE_CSV: a benchmarks/yade_periodic/results_3d triaxial run (the committed
anchor: same packing, contacts, damping, time step, loaded continuously).
At every YADE record from the first 0.25 % of axial strain to the RVE's
last row, q/p and the axial stress sigma33 of the RVE (interpolated
linearly between its rows) must be within TOLERANCE (relative) of YADE's.
"""
import csv
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "benchmarks", "rve_continuous"))
import curves  # noqa: E402

rve_path, yade_path, tol = sys.argv[1], sys.argv[2], float(sys.argv[3])
_, rve = curves.load(rve_path)
with open(yade_path) as f:
    yade = [r for r in csv.DictReader(l for l in f if not l.startswith("#")) if r["stage"] == "triaxial"]
failures, compared = [], 0
for y in yade:
    e = float(y["strain"])
    if e < 0.002 or e > rve[-1]["strain"] + 1e-6:  # YADE's records fall within 1e-6 of the 0.25 % marks
        continue
    x = min(e, rve[-1]["strain"])
    ratio, stress = curves.interp(rve, "ratio", x), curves.interp(rve, "stress", x)
    y_ratio, y_stress = float(y["q_over_p"]), -float(y["sigma33_Pa"])
    d_ratio, d_stress = ratio / y_ratio - 1.0, stress / y_stress - 1.0
    compared += 1
    print(f"strain {e:.4f}: q/p YADE {y_ratio:.4f} RVE {ratio:.4f} ({d_ratio:+.2%}), "
          f"sigma33 YADE {y_stress:.0f} RVE {stress:.0f} Pa ({d_stress:+.2%})")
    if abs(d_ratio) > tol or abs(d_stress) > tol:
        failures.append(f"strain {e:.4f}: q/p {d_ratio:+.2%}, sigma33 {d_stress:+.2%} (tolerance {tol:.1%})")
if compared < 3:
    failures.append(f"only {compared} YADE records within the RVE path")
if failures:
    print("FAIL:\n  " + "\n  ".join(failures))
    sys.exit(1)
print(f"PASS: {compared} records")
