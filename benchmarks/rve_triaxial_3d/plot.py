#!/usr/bin/env python3
"""plot.py RVE_CSV PNG [TITLE]: deviatoric ratio q/p and volumetric strain against
axial strain of a 3D triaxial rve.csv (axial = z; tension positive in the
file, compression positive in the plot). Prints the peak and, from the
second loading step (which starts and ends at the lateral stress of the
path, unlike the first, which starts from the isotropic stage's mean-stress
state), the secant Young's modulus and Poisson ratio of that step."""
import csv
import math
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = list(csv.DictReader(open(sys.argv[1])))
rows = [{k: float(v) for k, v in r.items()} for r in rows]
iso = max(i for i, r in enumerate(rows) if abs(r["F33"] - r["F11"]) < 1e-12)
r0 = rows[iso]
ea, ev, qp = [], [], []
for r in rows[iso:]:
    e_ax = -math.log(r["F33"] / r0["F33"])
    e_lat = -math.log(r["F11"] / r0["F11"]) - math.log(r["F22"] / r0["F22"])
    p = -(r["sigma11"] + r["sigma22"] + r["sigma33"]) / 3
    q = -r["sigma33"] + 0.5 * (r["sigma11"] + r["sigma22"])
    ea.append(100 * e_ax)
    ev.append(100 * (e_ax + e_lat))
    qp.append(q / p)
k = max(range(len(qp)), key=lambda i: qp[i])
a, b = rows[iso + 1], rows[iso + 2]
d_ax = -math.log(b["F33"] / a["F33"])
d_lat = 0.5 * (math.log(b["F11"] / a["F11"]) + math.log(b["F22"] / a["F22"]))
E = (-(b["sigma33"] - a["sigma33"])) / d_ax
nu = d_lat / d_ax
print(f"peak q/p {qp[k]:.4f} at axial strain {ea[k]:.2f} %; second loading step (axial strain "
      f"{100 * d_ax:.3g} %, lateral stress {a['sigma11']:.4g} -> {b['sigma11']:.4g} Pa): "
      f"E {E:.4g} Pa, nu {nu:.3f}")
fig, (a1, a2) = plt.subplots(2, 1, figsize=(6, 7), sharex=True)
a1.plot(ea, qp, "o-")
a1.set_ylabel("q/p")
a1.grid(True)
a2.plot(ea, ev, "o-")
a2.set_ylabel("volumetric strain (%) (compaction > 0)")
a2.set_xlabel("axial strain (%)")
a2.grid(True)
fig.suptitle(sys.argv[3] if len(sys.argv) > 3 else "3D RVE small_3d, triaxial at 100 kPa (linear contacts, mu = 0.5)")
fig.savefig(sys.argv[2], dpi=120)
