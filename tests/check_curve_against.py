#!/usr/bin/env python3
"""The stress ratio of a run against a reference run, row by row.

Usage: check_curve_against.py SUMMARY REFERENCE_SUMMARY TOLERANCE
Every loading row of SUMMARY (axial_strain > 0) must have a reference row
of the same step and axial strain, and its mean stress ratio must lie
within TOLERANCE x the reference's value. Prints each row.
"""
import csv
import sys

rows = [r for r in csv.DictReader(open(sys.argv[1])) if float(r["axial_strain"]) > 0.0]
ref = {r["step"]: r for r in csv.DictReader(open(sys.argv[2]))}
tol = float(sys.argv[3])
failures = []
if not rows:
    failures.append("no loading row (axial_strain > 0) in " + sys.argv[1])
for r in rows:
    b = ref.get(r["step"])
    if b is None or abs(float(b["axial_strain"]) - float(r["axial_strain"])) > 1e-12:
        failures.append(f"step {r['step']}: no reference row at axial strain {r['axial_strain']}")
        continue
    a, e = float(r["stress_ratio_mean"]), float(b["stress_ratio_mean"])
    rel = (a - e) / e
    ok = abs(rel) <= tol
    print(f"{'ok  ' if ok else 'FAIL'} step {r['step']} axial strain {float(r['axial_strain']):.4f}: "
          f"stress ratio {a:.6f}, reference {e:.6f} ({100 * rel:+.2f} %)")
    if not ok:
        failures.append(f"step {r['step']}: {100 * rel:+.2f} % > {100 * tol:.1f} %")
for f in failures:
    print("FAIL", f)
print(f"{len(rows)} rows checked against {100 * tol:.1f} %: {len(failures)} failures")
sys.exit(1 if failures else 0)
