#!/usr/bin/env python3
"""ctest rve_3d_membrane_holds_a_ridge: the shear run reached its last row
and the membrane acted on the way (it is the membrane that held the frame).

Usage: check_membrane_ridge.py RVE_CSV ROWS LAST_F12
"""
import csv
import sys

rows = list(csv.DictReader(open(sys.argv[1])))
n, last = int(sys.argv[2]), float(sys.argv[3])
failures = []
if len(rows) != n:
    failures.append(f"{len(rows)} rows written, expected {n} (a particle left the frame?)")
elif abs(float(rows[-1]["F12"]) - last) > 1e-9:
    failures.append(f"last F12 = {rows[-1]['F12']}, expected {last}")
acted = [r["step"] for r in rows if int(r["membrane_steps"]) > 0]
if not acted:
    failures.append("the membrane never acted: the run does not test it")
print(f"{len(rows)} rows; membrane contacts in the last solve of rows {acted}")
for f in failures:
    print("FAIL", f)
sys.exit(1 if failures else 0)
