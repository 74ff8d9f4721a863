#!/usr/bin/env python3
"""Explicit dynamics with RVEs: every RVE advances exactly the physical time
of the macro steps. From summary.csv: each row's time is a whole number of
DEM steps, its DEM steps are N_IP x (that time's increment) / DT_DEM
exactly, the last row is at END_TIME, and the DEM steps of the whole run are
N_IP x END_TIME / DT_DEM.
Usage: check_dynamic_time.py SUMMARY_CSV N_IP DT_DEM END_TIME"""
import csv
import sys

summary, n_ip, dt_dem, end_time = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
rows = list(csv.DictReader(open(summary)))
if not rows:
    sys.exit(f"FAIL: {summary} has no rows")
fails, t_before, total = 0, 0.0, 0
for r in rows:
    t, dem = float(r["time"]), int(r["dem_steps"])
    steps = (t - t_before) / dt_dem
    if abs(steps - round(steps)) > 1e-6 * max(1.0, steps):
        print(f"FAIL row {r['step']}: time {t} is {steps} DEM steps after the last row, not a whole number")
        fails += 1
    if dem != n_ip * round(steps):
        print(f"FAIL row {r['step']}: {dem} DEM steps, expected {n_ip} x {round(steps)} = {n_ip * round(steps)}")
        fails += 1
    total += dem
    t_before = t
expected = n_ip * round(end_time / dt_dem)
if abs(t_before - end_time) > 1e-12 * end_time:
    print(f"FAIL: the last row is at t = {t_before!r}, not at the end time {end_time!r}")
    fails += 1
if total != expected:
    print(f"FAIL: {total} DEM steps in all, expected {n_ip} x {end_time} / {dt_dem} = {expected}")
    fails += 1
print(f"{len(rows)} rows, {total} DEM steps = {n_ip} RVEs x {total // n_ip} steps of {dt_dem} "
      f"(t = {t_before}): {'FAIL' if fails else 'ok'}")
sys.exit(1 if fails else 0)
