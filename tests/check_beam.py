#!/usr/bin/env python3
"""Checks the cantilever runs of check_beam.sh (their energy.csv; stdlib only).

Usage: check_beam.py WORKDIR
"""
import csv
import sys

work = sys.argv[1]
traction, length, height, mu, lam = 150.0, 10.0, 1.0, 1e6, 2e6


def last(name):
    return list(csv.DictReader(open(f"{work}/{name}/energy.csv")))[-1]


def deflection(row):
    """Mean tip deflection: one load step, so W_ext = traction * height * deflection / 2."""
    return 2.0 * float(row["external_work"]) / (traction * height)


failures = []
E = mu * (3 * lam + 2 * mu) / (lam + mu)
nu = lam / (2 * (lam + mu))
E_ps = E / (1 - nu * nu)  # plane strain
P, I = traction * height, height ** 3 / 12
beam = P * length ** 3 / (3 * E_ps * I) + P * length / (5 / 6 * mu * height)
ref = deflection(last("reference"))
print(f"Timoshenko beam theory: {beam:.5f}; reference (full integration 60 x 12): {ref:.5f} "
      f"({(ref - beam) / beam:+.2%})")
if abs(ref - beam) > 0.03 * beam:
    failures.append(f"reference {ref} not within 3 % of beam theory {beam}")
for name in ("one_point", "one_point_3d"):
    r = last(name)
    d = deflection(r)
    share = float(r["hourglass_work"]) / float(r["internal_work"])
    print(f"{name}: deflection {d:.5f} ({(d - ref) / ref:+.2%} of the reference), hourglass work "
          f"{share:.2%} of the internal work")
    if abs(d - ref) > 0.05 * ref:
        failures.append(f"{name}: deflection {d} not within 5 % of the reference {ref}")
    if not share < 0.05:
        failures.append(f"{name}: hourglass work {share:.2%} of the internal work, not below 5 %")
free = deflection(last("no_control"))
print(f"no_control (20 x 1, no hourglass control): deflection {free:.4f} = {free / ref:.1f} x the reference")
if not free > 2 * ref:
    failures.append(f"no_control: deflection {free} does not show the zero-energy modes (within 2x of {ref})")
r = last("one_layer")
share = float(r["hourglass_work"]) / float(r["internal_work"])
print(f"one_layer (10 x 1, one point, stiffness control): hourglass work {share:.2%} of the internal work")
if not share > 0.1:
    failures.append(f"one_layer: hourglass work {share:.2%} of the internal work, not above 10 %")
for f in failures:
    print("FAIL", f)
print(f"{work}: {len(failures)} failures")
sys.exit(1 if failures else 0)
