#!/usr/bin/env python3
"""The stress ratio of a run against a curve of benchmarks/lbs2018/results/curves.csv.

Usage: check_against_curve.py SUMMARY CURVES_CSV CASE MAX_AXIAL_STRAIN TOLERANCE
Every loading row of SUMMARY (0 < axial_strain <= MAX_AXIAL_STRAIN) must
meet a point of CASE at the same axial strain, and its mean stress ratio
must lie within TOLERANCE x the curve's value; so must the largest stress
ratio of the whole run against the curve's, if the run goes past the
curve's peak. Prints each row.
"""
import csv
import sys

summary, curves, case, max_strain, tol = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4]), float(sys.argv[5])
run = list(csv.DictReader(open(summary)))
curve = {round(float(r["axial_strain"]), 9): float(r["stress_ratio"]) for r in csv.DictReader(open(curves))
         if r["case"] == case}
failures = []
if not curve:
    failures.append(f"no case '{case}' in {curves}")
checked = 0
for r in run:
    e = float(r["axial_strain"])
    if e <= 0.0 or e > max_strain + 1e-12:
        continue
    ref = curve.get(round(e, 9))
    if ref is None:
        failures.append(f"step {r['step']}: no point of '{case}' at axial strain {e}")
        continue
    a = float(r["stress_ratio_mean"])
    rel = (a - ref) / ref
    ok = abs(rel) <= tol
    checked += 1
    print(f"{'ok  ' if ok else 'FAIL'} axial strain {e:.4f}: stress ratio {a:.6f}, {case} {ref:.6f} ({100 * rel:+.2f} %)")
    if not ok:
        failures.append(f"axial strain {e}: {100 * rel:+.2f} % > {100 * tol:.1f} %")
if checked == 0:
    failures.append(f"no loading row up to axial strain {max_strain} in {summary}")
past_peak = run and curve and float(run[-1]["axial_strain"]) >= max(curve, key=curve.get)
if past_peak:
    peak, ref_peak = max(float(r["stress_ratio_mean"]) for r in run), max(curve.values())
    rel = (peak - ref_peak) / ref_peak
    print(f"{'ok  ' if abs(rel) <= tol else 'FAIL'} peak: {peak:.6f}, {case} {ref_peak:.6f} ({100 * rel:+.2f} %)")
    if abs(rel) > tol:
        failures.append(f"peak: {100 * rel:+.2f} % > {100 * tol:.1f} %")
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
