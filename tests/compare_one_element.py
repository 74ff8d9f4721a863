#!/usr/bin/env python3
"""One-element verification: fe2dem summary.csv (1x1 mesh) against fe2dem-rve
rve.csv on the same packing and path. Axial stress and stress ratio of every
stage-2 step must agree within TOL (relative, default 0.02).
Usage: compare_one_element.py SUMMARY_CSV RVE_CSV ISOTROPIC_STEPS [TOL] [STRIDE]
  STRIDE: fe2dem-rve loading steps per fe2dem load step (default 1), for a
  reference path in finer steps; every STRIDE-th row is compared."""
import csv
import sys

macro = [r for r in csv.DictReader(open(sys.argv[1])) if r["stage"] == "2"]
tol = float(sys.argv[4]) if len(sys.argv) > 4 else 0.02
stride = int(sys.argv[5]) if len(sys.argv) > 5 else 1
rve = list(csv.DictReader(open(sys.argv[2])))[int(sys.argv[3]) + 1:][stride - 1::stride]
fails = 0
if len(macro) != len(rve) or not macro:
    print(f"FAIL: {len(macro)} macro rows vs {len(rve)} RVE rows")
    sys.exit(1)
for m, r in zip(macro, rve):
    s11, s22 = float(r["sigma11"]), float(r["sigma22"])
    pairs = [("sigma22", float(m["sigma22_mean"]), s22),
             ("stress ratio", float(m["stress_ratio_mean"]), abs((s11 - s22) / (s11 + s22)))]
    for name, a, b in pairs:
        rel = abs(a - b) / abs(b)
        ok = rel <= tol
        fails += not ok
        print(f"{'ok  ' if ok else 'FAIL'} axial strain {float(m['axial_strain']):.4f} {name}: "
              f"macro {a:.6g}, RVE {b:.6g}, relative difference {rel:.4f}")
print(f"{2 * len(macro) - fails} passed, {fails} failed")
sys.exit(1 if fails else 0)
