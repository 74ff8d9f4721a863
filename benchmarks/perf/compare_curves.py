#!/usr/bin/python3
"""Totals of one fe2dem summary.csv and its difference from a reference run.

Usage: compare_curves.py SUMMARY [REFERENCE]
Prints `name value unit` lines: dem_steps, rve_solves, macro_iterations,
peak_stress_ratio, axial_strain_at_peak, rows; with REFERENCE (if it
exists) also peak_difference (relative) and curve_difference (largest
|stress ratio - reference| over common load steps / reference peak;
prepeak_curve_difference: the same up to 5 % axial strain).
"""
import csv
import os
import sys


def load(path):
    rows = list(csv.DictReader(open(path)))
    stage2 = [r for r in rows if r["stage"] == "2"]
    peak = max(stage2, key=lambda r: float(r["stress_ratio_mean"]))
    return rows, float(peak["stress_ratio_mean"]), float(peak["axial_strain"])


rows, peak, at = load(sys.argv[1])
print(f"dem_steps {sum(int(r['dem_steps']) for r in rows)} steps")
print(f"rve_solves {sum(int(r.get('rve_solves', 0) or 0) for r in rows)} solves")
print(f"macro_iterations {sum(int(r['macro_iterations']) for r in rows)} iterations")
print(f"peak_stress_ratio {peak:.4f} 1")
print(f"axial_strain_at_peak {at:.4f} 1")
print(f"rows {len(rows)} rows")
if len(sys.argv) > 2 and os.path.exists(sys.argv[2]):
    ref, ref_peak, _ = load(sys.argv[2])
    diff = max(abs(float(a["stress_ratio_mean"]) - float(b["stress_ratio_mean"]))
               for a, b in zip(rows, ref))
    pre = max(abs(float(a["stress_ratio_mean"]) - float(b["stress_ratio_mean"]))
              for a, b in zip(rows, ref) if float(b["axial_strain"]) <= 0.05)
    print(f"peak_difference {abs(peak - ref_peak) / ref_peak:.4f} 1")
    print(f"curve_difference {diff / ref_peak:.4f} 1")
    print(f"prepeak_curve_difference {pre / ref_peak:.4f} 1")
else:  # no reference run: same columns, no values
    for name in ("peak_difference", "curve_difference", "prepeak_curve_difference"):
        print(f"{name} nan 1")
