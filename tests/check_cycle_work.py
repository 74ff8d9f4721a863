#!/usr/bin/env python3
"""Checks that a strain cycle dissipates: in energy.csv (one row per load
step, each a whole period of a closed strain cycle) the internal work must
grow over every row by more than MIN joules. A passive material cannot give
back more work than it was given over a closed cycle.
Usage: check_cycle_work.py ENERGY_CSV MIN"""
import csv
import sys

rows = list(csv.DictReader(open(sys.argv[1])))
least = float(sys.argv[2])
if len(rows) < 2:
    sys.exit(f"FAIL: {len(rows)} rows in {sys.argv[1]}, want one per period and at least 2")
work = [0.0] + [float(r["internal_work"]) for r in rows]
per_cycle = [b - a for a, b in zip(work, work[1:])]
bad = [k + 1 for k, w in enumerate(per_cycle) if not w > least]
print("internal work per cycle [J]: " + ", ".join(f"{w:.3e}" for w in per_cycle))
if bad:
    sys.exit(f"FAIL: the cycle(s) {bad} gave back energy or dissipated at most {least:g} J")
print(f"ok: every one of {len(per_cycle)} cycles dissipated more than {least:g} J")
