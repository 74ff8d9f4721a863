#!/usr/bin/env python3
"""Two fe2dem runs of one problem: the first needs at most FRACTION of the
second's dynamic-relaxation iterations over the whole run (sum of the
summary.csv column macro_iterations), with the same number of load steps.
Usage: check_fewer_iterations.py SUMMARY_A SUMMARY_B FRACTION"""
import csv
import sys

a, b = (list(csv.DictReader(open(p))) for p in sys.argv[1:3])
fraction = float(sys.argv[3])
ia, ib = (sum(int(r["macro_iterations"]) for r in rows) for rows in (a, b))
ok = len(a) == len(b) and len(a) > 0 and ia <= fraction * ib
print(f"{'ok' if ok else 'FAIL'}: {ia} against {ib} iterations ({ia / ib:.3f}, at most {fraction}), "
      f"{len(a)} and {len(b)} load steps")
sys.exit(0 if ok else 1)
