#!/usr/bin/env python3
"""Checks a summary.csv of fe2dem against exact answers (stdlib only).

Usage: check_macro.py patch SUMMARY [TOL]
       check_macro.py elastic SUMMARY MU LAMBDA AXIAL_STRAIN STEPS MAX_ITERATIONS
       check_macro.py triaxial SUMMARY MU LAMBDA PRESSURE AXIAL_STRAIN ISO_STEPS STEPS MAX_ITERATIONS
       check_macro.py traction SUMMARY MU LAMBDA TRACTION STEPS DIM
       check_macro.py hydrostatic SUMMARY MU LAMBDA PRESSURE STEPS
patch:    the affine field is reproduced (affine_deviation <= TOL, default 1e-8).
elastic:  plane-strain neo-Hookean block, free sides: sigma22 and J - 1 of
          every load step within 1e-3 relative of the closed form, sigma11 ~ 0,
          and every step converged by (M9) within the iteration budget.
triaxial: 3D neo-Hookean block, follower pressure on the sides (and the top in
          stage 1): stage 1 F = l I with sigma = -p (fraction of the stage);
          stage 2 F = diag(l1, l2, l1), l2 = l_ic (1 - axial strain), sigma11 =
          sigma33 = -p. sigma11, sigma22, sigma33, J_rel and the stress ratio
          of every step within 1e-3 relative of the closed form.
traction: neo-Hookean block under a dead nominal traction -TRACTION t on the top
          (t = step/STEPS), lateral faces free: P22 = -TRACTION t, P11 (= P33) = 0;
          sigma22 and J - 1 within 1e-3 relative, sigma11 (sigma33) ~ 0.
hydrostatic: 3D neo-Hookean block under a follower pressure PRESSURE t on the
          right, front and top faces (symmetry on the others): F = l I,
          sigma11 = sigma22 = sigma33 = -PRESSURE t within 1e-3, J - 1 likewise.
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
elif mode == "hydrostatic":
    mu, lam, p, steps = map(float, sys.argv[3:7])
    if len(rows) != int(steps):
        failures.append(f"{len(rows)} rows, expected {int(steps)}")
    for r in rows:
        target = -p * int(r["step"]) / steps
        lo, hi = 0.5, 1.5  # bisection on sigma(l) = (mu (l^2 - 1) + lam ln l^3) / l^3 = target
        for _ in range(200):
            l = 0.5 * (lo + hi)
            sig = (mu * (l * l - 1) + lam * math.log(l ** 3)) / l ** 3
            lo, hi = (l, hi) if sig < target else (lo, l)
        for name in ("sigma11_mean", "sigma22_mean", "sigma33_mean"):
            if abs(float(r[name]) - target) > 1e-3 * abs(target):
                failures.append(f"step {r['step']}: {name} {r[name]}, closed form {target}")
        if abs(float(r["J_rel_mean"]) - (l ** 3 - 1)) > 1e-3 * abs(l ** 3 - 1):
            failures.append(f"step {r['step']}: J - 1 {r['J_rel_mean']}, closed form {l ** 3 - 1}")
        print(f"step {r['step']}: sigma11/22/33 {r['sigma11_mean']} {r['sigma22_mean']} {r['sigma33_mean']} "
              f"vs {target}, J - 1 {r['J_rel_mean']} vs {l ** 3 - 1:.6g}")
elif mode == "traction":
    mu, lam, traction, steps, dim = map(float, sys.argv[3:8])
    if len(rows) != int(steps):
        failures.append(f"{len(rows)} rows, expected {int(steps)}")
    for r in rows:
        P22 = -traction * int(r["step"]) / steps
        l1 = l2 = 1.0
        for _ in range(100):  # Newton on (P11(l1, l2), P22(l1, l2)) = (0, P22), F = diag(l1, l2[, l1])
            J = l1 ** (dim - 1) * l2
            g1 = mu * (l1 - 1 / l1) + lam * math.log(J) / l1
            g2 = mu * (l2 - 1 / l2) + lam * math.log(J) / l2 - P22
            a11 = mu * (1 + 1 / l1**2) + lam * ((dim - 1) - math.log(J)) / l1**2
            a12 = lam / (l1 * l2)
            a21 = lam * (dim - 1) / (l1 * l2)
            a22 = mu * (1 + 1 / l2**2) + lam * (1 - math.log(J)) / l2**2
            det = a11 * a22 - a12 * a21
            l1 -= (a22 * g1 - a12 * g2) / det
            l2 -= (a11 * g2 - a21 * g1) / det
        J = l1 ** (dim - 1) * l2
        s22 = P22 * l2 / J
        got = float(r["sigma22_mean"])
        if abs(got - s22) > 1e-3 * abs(s22):
            failures.append(f"step {r['step']}: sigma22 {got}, closed form {s22}")
        lateral = ["sigma11_mean"] + (["sigma33_mean"] if dim == 3 else [])
        for name in lateral:
            if abs(float(r[name])) > 1e-3 * abs(s22):
                failures.append(f"step {r['step']}: {name} {r[name]} not ~ 0")
        if abs(float(r["J_rel_mean"]) - (J - 1)) > 1e-3 * abs(J - 1):
            failures.append(f"step {r['step']}: J - 1 {r['J_rel_mean']}, closed form {J - 1}")
        print(f"step {r['step']}: sigma22 {got:.6f} vs closed form {s22:.6f} (rel. "
              f"{abs(got - s22) / abs(s22):.2e}), J - 1 {float(r['J_rel_mean']):.6g} vs {J - 1:.6g}")
elif mode == "triaxial":
    mu, lam, p, strain, iso_steps, steps, max_it = map(float, sys.argv[3:10])

    def cauchy(l1, l2):
        """sigma11 (= sigma33) and sigma22 of F = diag(l1, l2, l1)."""
        J = l1 * l1 * l2
        return ((mu * (l1 * l1 - 1) + lam * math.log(J)) / J,
                (mu * (l2 * l2 - 1) + lam * math.log(J)) / J)

    def solve(f, target):
        """l in [0.5, 2] with f(l) = target, f increasing (bisection)."""
        lo, hi = 0.5, 2.0
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if f(mid) < target else (lo, mid)
        return 0.5 * (lo + hi)

    def close(name, got, want, scale):
        if abs(got - want) > 1e-3 * scale:
            failures.append(f"step {r['step']}: {name} {got}, closed form {want}")

    if len(rows) != int(iso_steps + steps):
        failures.append(f"{len(rows)} rows, expected {int(iso_steps + steps)}")
    l_ic = solve(lambda l: cauchy(l, l)[0], -p)
    for r in rows:
        stage = int(r["stage"])
        if stage == 1:
            frac = int(r["step"]) / iso_steps
            l = solve(lambda l: cauchy(l, l)[0], -frac * p)
            l1 = l2 = l
            j_rel = l ** 3 - 1
        else:
            l2 = l_ic * (1 - float(r["axial_strain"]))
            l1 = solve(lambda l: cauchy(l, l2)[0], -p)
            j_rel = l1 * l1 * l2 / l_ic ** 3 - 1
        s11, s22 = cauchy(l1, l2)
        scale = max(abs(s11), abs(s22))
        close("sigma11", float(r["sigma11_mean"]), s11, scale)
        close("sigma33", float(r["sigma33_mean"]), s11, scale)
        close("sigma22", float(r["sigma22_mean"]), s22, scale)
        close("J_rel", float(r["J_rel_mean"]), j_rel, max(abs(j_rel), 1e-12))
        ratio = abs(s11 - s22) / abs(s11 + s22)
        close("stress ratio", float(r["stress_ratio_mean"]), ratio, max(ratio, 0.1))
        if not int(r["macro_iterations"]) < max_it:
            failures.append(f"step {r['step']}: no (M9) convergence within the budget")
        print(f"step {r['step']} (stage {stage}): sigma11 {float(r['sigma11_mean']):.3f} vs {s11:.3f}, "
              f"sigma22 {float(r['sigma22_mean']):.3f} vs {s22:.3f}, J_rel {float(r['J_rel_mean']):.6g} "
              f"vs {j_rel:.6g}, DR iterations {r['macro_iterations']}")
    if stage == 2 and abs(float(rows[-1]["axial_strain"]) - strain) > 1e-12:
        failures.append(f"final axial strain {rows[-1]['axial_strain']}, expected {strain}")
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
