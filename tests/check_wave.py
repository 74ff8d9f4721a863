#!/usr/bin/env python3
"""Checks the wave column of tests/dynamics/wave_column*.prm (needs h5py, numpy).

The bottom of a laterally constrained column is moved by a smooth step of
rise time T_RISE; the compressive strain pulse -eps_yy(y, t) travels up at
c = sqrt((lambda + 2 mu)/rho), its centroid in time passing height y at
T_RISE/2 + y/c. From history.h5 (F per IP per load step) and energy.csv
(the time of each load step): the centroid time at every IP with
Y_LO <= y <= Y_HI, a straight-line fit of centroid time against height
(slope 1/c), checked: wave speed within 1 % of the closed form, every
centroid time within 1 % of the travel time of the closed form.

Usage: check_wave.py OUTDIR MU LAMBDA RHO T_RISE Y_LO Y_HI
"""
import csv
import math
import sys

import h5py
import numpy as np

out = sys.argv[1]
mu, lam, rho, t_rise, y_lo, y_hi = map(float, sys.argv[2:8])
c = math.sqrt((lam + 2 * mu) / rho)
times = np.array([float(r["time"]) for r in csv.DictReader(open(f"{out}/energy.csv"))])
with h5py.File(f"{out}/history.h5", "r") as h:
    F = h["F"][:]
    position = h["ip_position"][:]
dim = position.shape[1]
strain = -(F[:, :, dim + 1] - 1.0)  # compressive eps_yy: F22 - 1 (2D index 3, 3D index 4)
if len(times) != strain.shape[0]:
    sys.exit(f"{len(times)} rows in energy.csv, {strain.shape[0]} steps in history.h5")
ys, tc = [], []
for ip in range(position.shape[0]):
    y = position[ip, 1]
    if y_lo <= y <= y_hi:
        s = strain[:, ip]
        ys.append(y)
        tc.append(float(np.sum(times * s) / np.sum(s)))
ys, tc = np.array(ys), np.array(tc)
slope, intercept = np.polyfit(ys, tc, 1)
failures = []
c_measured = 1.0 / slope
print(f"wave speed: fitted {c_measured:.4f}, closed form sqrt((lambda + 2 mu)/rho) = {c:.4f} "
      f"({(c_measured - c) / c:+.3%}); intercept {intercept:.5f} (closed form {t_rise / 2})")
if abs(c_measured - c) > 0.01 * c:
    failures.append(f"wave speed {c_measured} not within 1 % of {c}")
worst = 0.0
for y, t in zip(ys, tc):
    travel = y / c
    err = abs(t - (t_rise / 2 + travel)) / travel
    worst = max(worst, err)
    if err > 0.01:
        failures.append(f"IP at y = {y:.3f}: centroid time {t:.5f}, closed form {t_rise / 2 + travel:.5f}")
print(f"{len(ys)} IPs with {y_lo} <= y <= {y_hi}: worst arrival-time error {worst:.3%} of the travel time")
for f in failures[:10]:
    print("FAIL", f)
print(f"{out}: {len(failures)} failures")
sys.exit(1 if failures else 0)
