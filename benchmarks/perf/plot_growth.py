#!/usr/bin/python3
"""Plots results/growth.csv of growth.sh: wall time against IPs and against
particles per RVE (log-log, with the linear trend through the first point)."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = list(csv.DictReader(open(sys.argv[1])))
fig, axes = plt.subplots(1, 2, figsize=(10, 4))
for ax, series, key, label in ((axes[0], "ips", "ips", "quadrature points (RVEs)"),
                               (axes[1], "particles", "particles_per_rve", "particles per RVE")):
    r = [x for x in rows if x["series"] == series]
    x = [float(v[key]) for v in r]
    y = [float(v["wall_s"]) for v in r]
    ax.loglog(x, y, "o-", label="measured")
    ax.loglog(x, [y[0] * xi / x[0] for xi in x], "k--", lw=0.8, label="linear from the first point")
    for xi, yi in zip(x, y):
        ax.annotate(f"{yi:.0f} s", (xi, yi), textcoords="offset points", xytext=(4, -12), fontsize=8)
    ax.set_xlabel(label)
    ax.set_ylabel("wall time, first 4 load steps [s]")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
axes[0].set_title("2 ranks, lbs_ref (228 particles)")
axes[1].set_title("2 ranks, 1x1 mesh (4 RVEs)")
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=120)
print(sys.argv[2])
