"""Two rve.csv files equal in every column but the wall-clock one (wall_s).

Usage: same_rve_csv.py A.csv B.csv; exit 1 naming the first differing cell.
"""
import csv
import sys


def rows(path):
    with open(path, newline="") as f:
        table = list(csv.reader(f))
    skip = table[0].index("wall_s") if "wall_s" in table[0] else -1
    return [[c for i, c in enumerate(r) if i != skip] for r in table], table[0]


a, header = rows(sys.argv[1])
b, _ = rows(sys.argv[2])
if len(a) != len(b):
    sys.exit(f"FAIL: {sys.argv[1]} has {len(a)} rows, {sys.argv[2]} {len(b)}")
for n, (ra, rb) in enumerate(zip(a, b)):
    for i, (x, y) in enumerate(zip(ra, rb)):
        if x != y:
            sys.exit(f"FAIL: row {n} column {i}: {x} != {y}")
print(f"same: {len(a) - 1} rows, {len(a[0])} columns (wall_s left out)")
