#!/usr/bin/python3
"""Plots fe2dem summary.csv files: stress ratio and volumetric strain (and
coordination, anisotropy when present) against axial strain, stage 2 only.
Debian's python3 with python3-matplotlib.
Usage: plot_summary.py OUT_PNG LABEL=SUMMARY_CSV [LABEL=SUMMARY_CSV ...]"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

fig, ax = plt.subplots(2, 2, figsize=(10, 7))
keys = [("stress_ratio_mean", "stress ratio (mean over IPs)"), ("J_rel_mean", "volumetric strain J_rel"),
        ("coordination_mean", "coordination number"), ("anisotropy_mean", "fabric anisotropy")]
for arg in sys.argv[2:]:
    label, path = arg.split("=", 1)
    all_rows = list(csv.DictReader(open(path)))
    rows = [r for r in all_rows if r["stage"] == "2"]
    first = [r for r in all_rows if r["stage"] == "1"]
    x = [0.0] + [float(r["axial_strain"]) for r in rows]
    for a, (k, _) in zip(ax.flat, keys):
        y0 = float(first[-1][k]) if first and k != "J_rel_mean" else (0.0 if k == "J_rel_mean" else float(rows[0][k]))
        a.plot(x, [y0] + [float(r[k]) for r in rows], "o-", ms=3, label=label)
for a, (_, lab) in zip(ax.flat, keys):
    a.set_xlabel("axial strain")
    a.set_ylabel(lab)
    a.grid(alpha=0.3)
ax[0][0].legend()
fig.suptitle("fe2dem biaxial test ([LBS] reference RVE, 150 kN/m confinement)")
fig.tight_layout()
fig.savefig(sys.argv[1], dpi=110)
print("wrote", sys.argv[1])
