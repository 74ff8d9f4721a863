#!/usr/bin/python3
"""Plots results/*/rve.csv of run.sh on common axes: stress ratio,
volumetric strain, coordination and anisotropy against the axial strain
after the isotropic stage. Usage: plot.py RESULTS_DIR"""
import csv
import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

out = sys.argv[1]
fig, ax = plt.subplots(2, 2, figsize=(10, 7))
for path in sorted(glob.glob(os.path.join(out, "*", "rve.csv"))):
    rows = list(csv.DictReader(open(path)))
    n_iso = 4
    iso = rows[n_iso]
    J = lambda r: float(r["F11"]) * float(r["F22"]) - float(r["F12"]) * float(r["F21"])
    eps = [1 - float(r["F22"]) / float(iso["F22"]) for r in rows[n_iso:]]
    ratio = [abs((float(r["sigma11"]) - float(r["sigma22"])) / (float(r["sigma11"]) + float(r["sigma22"]))) for r in rows[n_iso:]]
    vol = [(J(r) - J(iso)) / J(iso) for r in rows[n_iso:]]
    label = os.path.basename(os.path.dirname(path))
    for a, y in zip(ax.flat, [ratio, vol, [float(r["coordination"]) for r in rows[n_iso:]],
                              [float(r["anisotropy"]) for r in rows[n_iso:]]]):
        a.plot(eps, y, "-", label=label)
for a, lab in zip(ax.flat, ["stress ratio |s11-s22|/|s11+s22|", "volumetric strain J_rel",
                            "coordination number", "fabric anisotropy"]):
    a.set_xlabel("axial strain (after isotropic stage)")
    a.set_ylabel(lab)
    a.grid(alpha=0.3)
ax[0][0].legend()
fig.suptitle("fe2dem-rve: [LBS] reference RVE, biaxial at 150 kN/m lateral stress")
fig.tight_layout()
fig.savefig(os.path.join(out, "biaxial.png"), dpi=110)
print("wrote", os.path.join(out, "biaxial.png"))
