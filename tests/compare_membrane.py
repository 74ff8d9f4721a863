#!/usr/bin/env python3
"""Frame membrane: inert until needed, then it keeps the RVE alive.

Usage: compare_membrane.py WITH.csv WITHOUT.csv STEPS
WITH (membrane yes) must reach all STEPS rows and use the membrane
(membrane_steps > 0 somewhere); WITHOUT (membrane no) stopped early; every
row WITHOUT wrote before WITH first used the membrane is identical in both
(all columns but wall_s), i.e. the membrane changes nothing until it acts.
"""
import csv
import sys

with_rows = list(csv.DictReader(open(sys.argv[1])))
without_rows = list(csv.DictReader(open(sys.argv[2])))
steps = int(sys.argv[3])
failures = []
if len(with_rows) != steps:
    failures.append(f"membrane yes: {len(with_rows)} rows, expected {steps}")
if len(without_rows) >= steps:
    failures.append("membrane no: reached the end; this test needs a case that escapes")
first = next((i for i, r in enumerate(with_rows) if int(r["membrane_steps"]) > 0), None)
if first is None:
    failures.append("membrane yes: never used the membrane")
else:
    print(f"membrane first acts at row {first} of {len(with_rows)}; "
          f"without it the run stopped after {len(without_rows)} rows")
    for a, b in zip(with_rows[:first], without_rows):
        diff = [k for k in a if k not in ("wall_s", "membrane_steps") and a[k] != b[k]]
        if diff:
            failures.append(f"step {a['step']}: {diff} differ before the membrane acted")
            break
for f in failures:
    print("FAIL", f)
sys.exit(1 if failures else 0)
