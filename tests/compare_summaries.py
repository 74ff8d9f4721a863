#!/usr/bin/env python3
"""Two fe2dem summary.csv (or fe2dem-rve rve.csv) files hold the same values,
byte for byte as printed, but for the wall-clock columns (WALL; columns such
as rve.csv's drive_time_s, a physical time, are compared).
Usage: compare_summaries.py A B"""
import csv
import sys

WALL = {"wall_s", "rve_rank_max_s", "rve_rank_mean_s", "rve_loop_mean_s", "rve_iteration_max_s"}

a, b = (list(csv.DictReader(open(p))) for p in sys.argv[1:3])
bad = [(i, k, ra[k], rb.get(k)) for i, (ra, rb) in enumerate(zip(a, b)) for k in ra
       if k not in WALL and ra[k] != rb.get(k)]
if a and b and list(a[0]) != list(b[0]):
    bad.append(("columns", list(a[0]), list(b[0]), ""))
if len(a) != len(b) or not a:
    bad.append(("rows", len(a), len(b), ""))
for x in bad:
    print("FAIL", x)
print(f"{len(a)} rows compared, {len(bad)} differences")
sys.exit(1 if bad else 0)
