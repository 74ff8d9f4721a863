#!/usr/bin/env python3
"""One-element verification: fe2dem summary.csv (1x1 mesh) against fe2dem-rve
rve.csv on the same packing and path. Axial stress and stress ratio of every
stage-2 step must agree within TOL (relative, default 0.02).
Usage: compare_one_element.py SUMMARY_CSV RVE_CSV[,RVE_CSV...] ISOTROPIC_STEPS [TOL] [STRIDE] [RATIO_TOL]
  RVE_CSV,...: several numerically equivalent fe2dem-rve runs (e.g. other
  neighbour skins) are averaged: one 228-particle RVE run scatters by about
  +-1 % in the stress ratio (2 % from lowest to highest of six such runs at
  1 % axial strain), and the mean is the reference with less of that noise;
  the spread is printed.
  STRIDE: fe2dem-rve loading steps per fe2dem load step (default 1), for a
  reference path in finer steps; every STRIDE-th row is compared.
  RATIO_TOL: tolerance of the stress ratio (default TOL)."""
import csv
import sys

macro = [r for r in csv.DictReader(open(sys.argv[1])) if r["stage"] == "2"]
tol = float(sys.argv[4]) if len(sys.argv) > 4 else 0.02
stride = int(sys.argv[5]) if len(sys.argv) > 5 else 1
ratio_tol = float(sys.argv[6]) if len(sys.argv) > 6 else tol
runs = [list(csv.DictReader(open(f)))[int(sys.argv[3]) + 1:][stride - 1::stride] for f in sys.argv[2].split(",")]
fails = 0
if any(len(macro) != len(rve) for rve in runs) or not macro:
    print(f"FAIL: {len(macro)} macro rows vs {[len(rve) for rve in runs]} RVE rows")
    sys.exit(1)


def ratio(r):
    s11, s22 = float(r["sigma11"]), float(r["sigma22"])
    return abs((s11 - s22) / (s11 + s22))


for k, m in enumerate(macro):
    s22 = [float(rve[k]["sigma22"]) for rve in runs]
    q = [ratio(rve[k]) for rve in runs]
    pairs = [("sigma22", float(m["sigma22_mean"]), s22, tol),
             ("stress ratio", float(m["stress_ratio_mean"]), q, ratio_tol)]
    for name, a, samples, t in pairs:
        b = sum(samples) / len(samples)
        rel = abs(a - b) / abs(b)
        spread = (max(samples) - min(samples)) / abs(b)
        ok = rel <= t
        fails += not ok
        print(f"{'ok  ' if ok else 'FAIL'} axial strain {float(m['axial_strain']):.4f} {name}: "
              f"macro {a:.6g}, RVE {b:.6g} (mean of {len(samples)}, spread {spread:.4f}), "
              f"relative difference {rel:.4f} (tolerance {t})")
print(f"{2 * len(macro) - fails} passed, {fails} failed")
sys.exit(1 if fails else 0)
