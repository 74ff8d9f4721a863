#!/usr/bin/env python3
"""check_lsyf_moduli.py RVE_CSV: the small-strain Young's modulus and Poisson
ratio of benchmarks/rve_triaxial_3d/hertz_lsyf_1000.prm against [LSYF] §3.2
(E = 584 MPa, nu = 0.2 for their 4096-sphere assembly at 416 kPa).

From the second triaxial step (it starts and ends at the lateral stress, as in
plot.py): E = -d sigma33 / d eps_axial, nu = d eps_lateral / d eps_axial
(logarithmic strains). Tolerances: 10 % on E and 0.05 on nu, because the
packing is [LSYF]-like, not theirs (porosity 0.346 against 0.338, uniform
diameters, 1000 spheres); measured 2026-11-23: E = 595 MPa, nu = 0.214.
The 4096-sphere lsyf_4096 of the same protocol gives 469 MPa and 0.279, so
this guards the Hertz RVE pipeline against errors larger than the packing
scatter; it does not claim [LSYF]'s value to 10 % for every packing.
"""
import csv
import math
import sys

rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(open(sys.argv[1]))]
iso = max(i for i, r in enumerate(rows) if abs(r["F33"] - r["F11"]) < 1e-12)
if len(rows) < iso + 3:
    sys.exit(f"FAIL: {sys.argv[1]} has {len(rows)} rows, need two triaxial steps after row {iso}")
a, b = rows[iso + 1], rows[iso + 2]
d_ax = -math.log(b["F33"] / a["F33"])
d_lat = 0.5 * (math.log(b["F11"] / a["F11"]) + math.log(b["F22"] / a["F22"]))
E = -(b["sigma33"] - a["sigma33"]) / d_ax
nu = d_lat / d_ax
p = -(b["sigma11"] + b["sigma22"] + b["sigma33"]) / 3
print(f"E = {E / 1e6:.1f} MPa (LSYF 584), nu = {nu:.3f} (LSYF 0.2), lateral stress {b['sigma11']:.0f} Pa, "
      f"mean stress {p:.0f} Pa, coordination {b['coordination']:.3f}, solid fraction {b['packing_fraction']:.4f}")
failures = []
if not abs(E - 584e6) <= 0.10 * 584e6:
    failures.append(f"E = {E:.4g} Pa is not within 10 % of 584 MPa")
if not abs(nu - 0.2) <= 0.05:
    failures.append(f"nu = {nu:.4f} is not within 0.05 of 0.2")
for f in failures:
    print("FAIL:", f)
print("PASS" if not failures else f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
