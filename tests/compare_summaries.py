#!/usr/bin/env python3
"""Two fe2dem summary.csv files hold the same values (wall-time columns,
those ending in _s, aside), byte for byte as printed.
Usage: compare_summaries.py A B"""
import csv
import sys

a, b = (list(csv.DictReader(open(p))) for p in sys.argv[1:3])
bad = [(i, k, ra[k], rb[k]) for i, (ra, rb) in enumerate(zip(a, b)) for k in ra
       if not k.endswith("_s") and ra[k] != rb[k]]
if len(a) != len(b) or not a:
    bad.append(("rows", len(a), len(b), ""))
for x in bad:
    print("FAIL", x)
print(f"{len(a)} rows compared, {len(bad)} differences")
sys.exit(1 if bad else 0)
