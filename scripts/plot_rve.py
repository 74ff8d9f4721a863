#!/usr/bin/python3
"""Plots an rve.csv of fe2dem-rve: stress ratio, volumetric strain,
coordination and anisotropy against axial strain. Debian's python3 with
python3-matplotlib. Usage: plot_rve.py RVE_CSV OUT_PNG"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = list(csv.DictReader(open(sys.argv[1])))
f = lambda k: [float(r[k]) for r in rows]
F11, F22, s11, s22 = f("F11"), f("F22"), f("sigma11"), f("sigma22")
J = [a * b - float(r["F12"]) * float(r["F21"]) for a, b, r in zip(F11, F22, rows)]
axial = [1.0 - x for x in F22]
ratio = [abs((a - b) / (a + b)) if a + b != 0 else 0.0 for a, b in zip(s11, s22)]
fig, ax = plt.subplots(2, 2, figsize=(9, 6.5))
for a, y, label in [(ax[0][0], ratio, "stress ratio |(s11-s22)/(s11+s22)|"),
                    (ax[0][1], [j - 1.0 for j in J], "volumetric strain det F - 1"),
                    (ax[1][0], f("coordination"), "coordination number"),
                    (ax[1][1], f("anisotropy"), "fabric anisotropy")]:
    a.plot(axial, y, "o-", ms=3)
    a.set_xlabel("axial strain 1 - F22")
    a.set_ylabel(label)
    a.grid(alpha=0.3)
fig.suptitle(sys.argv[1])
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=110)
print("wrote", sys.argv[2])
