#!/usr/bin/env python3
"""Checks an rve.csv written by fe2dem-rve (stdlib only).

Usage: check_rve_csv.py CSV PATH_TYPE PRESSURE ISOTROPIC_STEPS ROWS [free_shear]
Asserts the contract header, the row count, convergence of every row
(r_a <= 1e-4), the agreement of boundary and Love-Weber stress (1 %), and
that stress-controlled components hold the target within the tolerance.
A 3D rve.csv (columns F11 ... F33) is recognised by its header; PATH_TYPE
triaxial holds sigma11 = sigma22 = -p while F33 shortens. With free_shear,
every shear stress of the stress-controlled rows must be zero to 1 % of p.
"""
import csv
import math
import sys

path, kind, pressure = sys.argv[1], sys.argv[2], float(sys.argv[3])
n_iso, rows_expected = int(sys.argv[4]), int(sys.argv[5])
free_shear = len(sys.argv) > 6 and sys.argv[6] == "free_shear"
with open(path) as f:
    dim = 3 if "F33" in f.readline().split(",") else 2
comps = [f"{i}{j}" for i in range(1, dim + 1) for j in range(1, dim + 1)]
diag = [f"{i}{i}" for i in range(1, dim + 1)]
axial = diag[-1]
head = ["step"] + [f"{t}{ij}" for t in ("F", "P", "sigma", "sigmaLW") for ij in comps]
head += ["residual", "ekin_epot", "servo_iterations", "dem_steps", "coordination", "anisotropy",
         "packing_fraction", "wall_s"]
failures = []
with open(path) as f:
    reader = csv.reader(f)
    header = next(reader)
    rows = [dict(zip(header, map(float, r))) for r in reader]
if header[: len(head)] != head:
    failures.append(f"header {header[:len(head)]} != contract {head}")
if len(rows) != rows_expected:
    failures.append(f"{len(rows)} rows, expected {rows_expected}")
for r in rows:
    s = int(r["step"])
    if not r["residual"] <= 1e-4:
        failures.append(f"step {s}: r_a {r['residual']} > 1e-4")
    num = math.sqrt(sum((r[f"sigma{ij}"] - r[f"sigmaLW{ij}"]) ** 2 for ij in comps))
    den = math.sqrt(sum(r[f"sigmaLW{ij}"] ** 2 for ij in comps))
    if num > 0.01 * den:
        failures.append(f"step {s}: boundary vs Love-Weber stress differ by {num/den:.3%}")
    if r["coordination"] <= 0 or not 0 < r["packing_fraction"] < 1:
        failures.append(f"step {s}: implausible coordination/packing fraction")
    if "fabric_deviator" not in r or not 0.0 <= r["fabric_deviator"] < 1.0:
        failures.append(f"step {s}: fabric_deviator missing or outside [0, 1)")
    if r["F_check_error"] > 1e-12:
        failures.append(f"step {s}: F_check differs from F by {r['F_check_error']}")
last = rows[-1]
# Stress control: isotropic rows 1..n_iso reach -p k/n, biaxial rows hold sigma11 = -p
# (tolerance: the prm's 'Stress tolerance' of 1 % plus round-off).
for k, r in enumerate(rows[1 : n_iso + 1], start=1):
    mean, target = sum(r[f"sigma{d}"] for d in diag) / dim, -pressure * k / n_iso
    if abs(mean - target) > 0.0101 * abs(target):
        failures.append(f"isotropic step {k}: mean stress {mean}, target {target}")
if kind in ("biaxial", "triaxial"):
    for r in rows[n_iso + 1 :]:
        for d in diag[:-1]:
            if abs(r[f"sigma{d}"] + pressure) > 0.0101 * pressure:
                failures.append(f"step {int(r['step'])}: lateral stress sigma{d} {r[f'sigma{d}']}, "
                                f"target {-pressure}")
    if not last[f"F{axial}"] < rows[0][f"F{axial}"] or not last[f"sigma{axial}"] < last["sigma11"]:
        failures.append("axial compression did not raise the axial stress above the lateral one")
if free_shear:
    for r in rows[1:]:
        for ij in comps:
            if ij[0] != ij[1] and abs(r[f"sigma{ij}"]) > 0.0101 * pressure:
                failures.append(f"step {int(r['step'])}: free shear, sigma{ij} = {r[f'sigma{ij}']}")
if kind == "shear" and not abs(last["sigma12"]) > 0:
    failures.append("no shear stress under simple shear")
for msg in failures:
    print("FAIL", msg)
print(f"{path}: {len(rows)} rows, {len(failures)} failures")
sys.exit(1 if failures else 0)
