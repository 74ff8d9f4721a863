#!/usr/bin/python3
"""One picture of an example's output for docs/gallery.md (scripts/make-gallery.sh).
Debian's python3 with python3-matplotlib and python3-h5py.

Usage: plot_gallery.py KIND OUTPUT_DIR OUT_PNG TITLE

KIND says what is drawn from OUTPUT_DIR:
  rve      rve.csv of fe2dem-rve: the normal stresses (and sigma12 when F12
           moves) and det F - 1 along the path's rows;
  macro    summary.csv of an RVE run: mean stress ratio and J_rel against
           the axial strain;
  elastic  summary.csv without RVEs: top force and sigma22 against the
           axial strain;
  shear    a simple-shear run of one element: sigma12 and the mean stress p,
           and sigma12 / p, against gamma = F12 of IP 0 (history.h5);
  wave     a dynamic run: the change of sigma22 of every element against
           time (history.h5), kinetic energy and external work (energy.csv)."""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

kind, out, png, title = sys.argv[1:5]


def rows(name):
    return list(csv.DictReader(open(os.path.join(out, name))))


def column(rs, key):
    return [float(r[key]) for r in rs]


def rve_path(ax):
    rs = rows("rve.csv")
    n = 3 if "F33" in rs[0] else 2
    row = range(len(rs))
    for i in range(1, n + 1):
        ax[0].plot(row, [-v / 1e3 for v in column(rs, "sigma%d%d" % (i, i))], "o-", ms=3,
                   label="-sigma%d%d" % (i, i))
    if max(abs(v) for v in column(rs, "F12")) > 1e-9:  # shear
        ax[0].plot(row, [v / 1e3 for v in column(rs, "sigma12")], "o-", ms=3, label="sigma12")
    ax[0].set_xlabel("path row")
    ax[0].set_ylabel("stress [kPa, 3D] or [kN/m, 2D]")
    ax[0].legend(fontsize=7)
    dets = []
    for r in rs:
        F = [[float(r["F%d%d" % (i + 1, j + 1)]) for j in range(n)] for i in range(n)]
        if n == 2:
            dets.append(F[0][0] * F[1][1] - F[0][1] * F[1][0])
        else:
            dets.append(F[0][0] * (F[1][1] * F[2][2] - F[1][2] * F[2][1]) -
                        F[0][1] * (F[1][0] * F[2][2] - F[1][2] * F[2][0]) +
                        F[0][2] * (F[1][0] * F[2][1] - F[1][1] * F[2][0]))
    ax[1].plot(row, [d - 1.0 for d in dets], "o-", ms=3)
    ax[1].set_xlabel("path row")
    ax[1].set_ylabel("volumetric strain det F - 1")


def against_axial_strain(ax, panels):
    """summary.csv columns (key, label) against the axial strain, one per
    panel. A biaxial run (stages 1 and 2) from the end of stage 1 on, where
    J_rel starts again from 0 (as scripts/plot_summary.py draws it)."""
    rs = rows("summary.csv")
    stage2 = [r for r in rs if r["stage"] == "2"]
    if stage2:
        rs = [r for r in rs if r["stage"] == "1"][-1:] + stage2
    x = column(rs, "axial_strain")
    for a, (key, label) in zip(ax, panels):
        y = column(rs, key)
        if stage2 and key == "J_rel_mean":
            y[0] = 0.0
        a.plot(x, y, "o-", ms=3)
        a.set_xlabel("axial strain")
        a.set_ylabel(label)


def macro_rve(ax):
    against_axial_strain(ax, [("stress_ratio_mean", "stress ratio (mean over IPs)"),
                              ("J_rel_mean", "volumetric strain J_rel")])


def macro_elastic(ax):
    against_axial_strain(ax, [("top_force", "top force"), ("sigma22_mean", "sigma22 (mean) [Pa]")])


def macro_dynamic(ax):
    import h5py

    times = column(rows("summary.csv"), "time")
    with h5py.File(os.path.join(out, "history.h5")) as h:
        sigma, pos = h["sigma"][...], h["ip_position"][...]
        dim = int(h.attrs["dimension"])
    axial = (dim + 1) * 1  # index of sigma22 in the row-major tensor
    for ip in range(sigma.shape[1]):
        ax[0].plot([t * 1e6 for t in times], sigma[:, ip, axial] - sigma[0, ip, axial],
                   label="y = %.0f mm" % (pos[ip][1] * 1e3))
    ax[0].set_xlabel("time [us]")
    ax[0].set_ylabel("sigma22 - sigma22(0) [Pa]")
    ax[0].legend(fontsize=7)
    e = rows("energy.csv")
    ax[1].plot([float(r["time"]) * 1e6 for r in e], column(e, "kinetic_energy"), label="kinetic")
    ax[1].plot([float(r["time"]) * 1e6 for r in e], column(e, "external_work"), label="external work")
    ax[1].set_xlabel("time [us]")
    ax[1].set_ylabel("energy [J]")
    ax[1].legend(fontsize=7)


def macro_shear(ax):
    import h5py

    with h5py.File(os.path.join(out, "history.h5")) as h:
        sigma, F = h["sigma"][:, 0, :], h["F"][:, 0, :]
        dim = int(h.attrs["dimension"])
    gamma = list(F[:, 1])  # F12, row-major
    tau = [s[1] / 1e3 for s in sigma]
    p = [-sum(s[k * (dim + 1)] for k in range(dim)) / dim / 1e3 for s in sigma]
    ax[0].plot(gamma, tau, "o-", ms=3, label="sigma12")
    ax[0].plot(gamma, p, "o-", ms=3, label="p = -tr(sigma)/3")
    ax[0].set_xlabel("shear strain gamma = F12")
    ax[0].set_ylabel("stress [kPa]")
    ax[0].legend(fontsize=7)
    ax[1].plot(gamma, [t / q for t, q in zip(tau, p)], "o-", ms=3)
    ax[1].set_xlabel("shear strain gamma = F12")
    ax[1].set_ylabel("sigma12 / p")


fig, ax = plt.subplots(1, 2, figsize=(10, 3.8))
{"rve": rve_path, "macro": macro_rve, "elastic": macro_elastic, "wave": macro_dynamic,
 "shear": macro_shear}[kind](ax)
for a in ax:
    a.grid(alpha=0.3)
fig.suptitle(title)
fig.tight_layout()
fig.savefig(png, dpi=90)
print("wrote", png)
