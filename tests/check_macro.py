#!/usr/bin/env python3
"""Checks a summary.csv of fe2dem against exact answers (stdlib only).

Usage: check_macro.py patch SUMMARY [TOL]
       check_macro.py elastic SUMMARY MU LAMBDA AXIAL_STRAIN STEPS MAX_ITERATIONS
patch:   the affine field is reproduced (affine_deviation <= TOL, default 1e-8).
elastic: plane-strain neo-Hookean block, free sides: sigma22 and J - 1 of
         every load step within 1e-3 relative of the closed form, sigma11 ~ 0,
         and every step converged by (M9) within the iteration budget.
"""
import csv
import math
import sys

mode, path = sys.argv[1], sys.argv[2]
rows = list(csv.DictReader(open(path)))
failures = []
if mode == "patch":
    tol = float(sys.argv[3]) if len(sys.argv) > 3 else 1e-8
    for r in rows:
        if not float(r["affine_deviation"]) <= tol:
            failures.append(f"step {r['step']}: affine deviation {r['affine_deviation']} > {tol}")
else:
    mu, lam, strain, steps, max_it = map(float, sys.argv[3:8])
    if abs(float(rows[-1]["axial_strain"]) - strain) > 1e-12:
        failures.append(f"final axial strain {rows[-1]['axial_strain']}, expected {strain}")
    if len(rows) != int(steps):
        failures.append(f"{len(rows)} rows, expected {int(steps)}")
    for r in rows:
        l2 = 1.0 - float(r["axial_strain"])  # measured from the top edge
        l1 = 1.0
        for _ in range(60):  # Newton on P11(l1) = 0
            g = mu * (l1 - 1 / l1) + lam * math.log(l1 * l2) / l1
            dg = mu * (1 + 1 / l1**2) + lam * (1 - math.log(l1 * l2)) / l1**2
            l1 -= g / dg
        s22 = (mu * (l2 - 1 / l2) + lam * math.log(l1 * l2) / l2) / l1
        got = float(r["sigma22_mean"])
        if abs(got - s22) > 1e-3 * abs(s22):
            failures.append(f"step {r['step']}: sigma22 {got}, closed form {s22}")
        if abs(float(r["sigma11_mean"])) > 1e-3 * abs(s22):
            failures.append(f"step {r['step']}: sigma11 {r['sigma11_mean']} not ~ 0")
        j = l1 * l2 - 1
        if abs(float(r["J_rel_mean"]) - j) > 1e-3 * abs(j):
            failures.append(f"step {r['step']}: J - 1 {r['J_rel_mean']}, closed form {j}")
        if not int(r["macro_iterations"]) < max_it:
            failures.append(f"step {r['step']}: no (M9) convergence within the budget")
        print(f"step {r['step']}: sigma22 {got:.6f} vs closed form {s22:.6f} "
              f"(rel. {abs(got - s22) / abs(s22):.2e}), DR iterations {r['macro_iterations']}")
for f in failures:
    print("FAIL", f)
print(f"{path}: {len(rows)} rows, {len(failures)} failures")
sys.exit(1 if failures else 0)
