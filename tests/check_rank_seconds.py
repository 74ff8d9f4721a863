#!/usr/bin/env python3
"""Checks the RVE-time columns of an fe2dem summary.csv against each other.

Per load step, the busiest rank's seconds summed over iterations
(rve_iteration_max_s) can be no less than the busiest rank's sum
(rve_rank_max_s), which is no less than the mean rank's (rve_rank_mean_s);
on one rank all three are equal. Floating-point rounding is monotone, so
the inequalities hold exactly. The columns are wall times, so only these
relations, not values, can be asserted.

Usage: check_rank_seconds.py SUMMARY_CSV RANKS
"""
import csv
import sys

path, ranks = sys.argv[1], int(sys.argv[2])
rows = list(csv.DictReader(open(path)))
bad = 0
for r in rows:
    it, top, mean = (float(r[k]) for k in ("rve_iteration_max_s", "rve_rank_max_s", "rve_rank_mean_s"))
    ok = it >= top >= mean > 0.0 and (ranks > 1 or it == top == mean)
    if not ok:
        print(f"FAIL {path} step {r['step']}: rve_iteration_max_s {it!r}, rve_rank_max_s {top!r}, "
              f"rve_rank_mean_s {mean!r} on {ranks} rank(s)")
        bad = 1
excess = sum(float(r["rve_iteration_max_s"]) for r in rows) / sum(float(r["rve_rank_mean_s"]) for r in rows)
print(f"{len(rows)} steps; busiest rank per iteration / mean rank: {excess:.4f}")
sys.exit(bad)
