#!/usr/bin/python3
"""The band width in mm over the meshes of the [LBS] test, local against the
local elastic operator (issue 37), measured on the strain increment
accumulated after the peak rather than on one load step.

Usage (Debian's python3 with numpy, matplotlib, h5py):
  run.sh mesh_2x4_quarter mesh_4x8_quarter mesh_4x8_op_quarter mesh_8x16_op_quarter \
         nonlocal_2x4_le_quarter nonlocal_4x8_le_quarter nonlocal_2x4_le1e6_quarter nonlocal_4x8_le1e6_quarter \
         nonlocal_4x8_op_le_quarter nonlocal_8x16_op_le_quarter nonlocal_8x16_op_le1e6_quarter
  band_study.py        (cases not in runs/ are left out of every table)

Reads runs/CASE/{history.h5,summary.csv} of the cases below (run.sh; stage 2
in 0.125 % steps, the load step at which the post-peak curves move least,
README "The load step"), writes results/band_study.csv and
results/band_study.png, and prints the README's tables.

- The band: band_width.py's full width at half maximum of the shear strain
  increment of F over an interval, on the IPs' reference positions, among
  the inclined band directions (band_width.INCLINED, 20-70 and 110-160 deg
  from x) and, beside them, among all. Intervals: the last 1 % (9 to 10 %)
  and the last 2.5 % (7.5 to 10 %: every run has dropped from its peak by
  7.5 %). Both were fixed before the runs, as in [LSYF] problem 4
  (../lsyf2016/README.md). One load step's increment (nonlocal_study.py) is
  too diffuse on this specimen to carry a band.
- The half-share width (band_width.half_share_width, chosen in session 37 after the runs, where
  the profile of the diffuse increments of the local elastic runs does not fall to half its peak
  on both sides inside this 10 mm wide specimen): the smallest share of the IPs holding half of
  the increment, read as the width of a uniform band crossing the specimen at the run's Coulomb
  angle 45 deg + phi / 2 (phi = asin of its peak stress ratio); the CSV rows "half share S" hold
  it, with that angle. Checked on known bands by ctest benchmark_band_width_known_bands.
- The band's softening modulus in shear of each local run,
  H_s = (tau_peak - tau_end) / gamma_band, tau = (|sigma22| - |sigma11|) / 2
  of the IPs' mean stress, gamma_band the largest IP shear strain increment
  from the peak to the end: against C_e's shear modulus it predicts the
  band's width on the softening bar (ctest macro_nonlocal_softening_bar:
  1.1 R at C_e / H = 2.7, 2.1 R at 9).
"""
import csv
import os
import sys

import h5py
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import analyse  # noqa: E402  (curve(): the study's reading of summary.csv)
import band_width as bw  # noqa: E402
from nonlocal_study import spread_after_peak  # noqa: E402

here = os.path.dirname(os.path.abspath(__file__))
runs, results = os.path.join(here, "runs"), os.path.join(here, "results")
# (family, [(case, mesh label, element size in mm)]): 2x4 and 4x8 with 2x2 Gauss points, 8x16 with
# one point per element (its 128 RVEs fit in the hour that 8x16 with 512 does not)
FAMILIES = [("local", [("mesh_2x4_quarter", "2x4", 5.0), ("mesh_4x8_quarter", "4x8", 2.5),
                       ("mesh_8x16_op_quarter", "8x16, one point", 1.25)]),
            ("local elastic R = 2.5 mm", [("nonlocal_2x4_le_quarter", "2x4", 5.0),
                                          ("nonlocal_4x8_le_quarter", "4x8", 2.5),
                                          ("nonlocal_8x16_op_le_quarter", "8x16, one point", 1.25)]),
            ("local elastic R = 2.5 mm, E = 1e6 N/m", [("nonlocal_2x4_le1e6_quarter", "2x4", 5.0),
                                                       ("nonlocal_4x8_le1e6_quarter", "4x8", 2.5),
                                                       ("nonlocal_8x16_op_le1e6_quarter", "8x16, one point", 1.25)]),
            ("local, one point", [("mesh_4x8_op_quarter", "4x8, one point", 2.5),
                                  ("mesh_8x16_op_quarter", "8x16, one point", 1.25)]),
            # 4x8 one point with R = 2.5 mm: the neighbours sit at R, where the weight is 0, so F_nonlocal = F
            # and the run is local but for rounding (README, "The band width over the meshes")
            ("local elastic R = 2.5 mm, one point",
             [("nonlocal_4x8_op_le_quarter", "4x8, one point, no neighbours", 2.5),
              ("nonlocal_8x16_op_le_quarter", "8x16, one point", 1.25)])]
INTERVALS = [(0.09, 0.10), (0.075, 0.10)]  # axial strain from, to
HEIGHT = 0.02                               # lbs2018.prm: the specimen's height (m)
C_E = (6e6, 1e6), 0.2                      # run.sh's _le and _le1e6: E (N/m); Poisson ratio


def rows_at(history, strains):
    """Rows of history.h5 whose stage-2 axial strain is each of `strains` (within 1e-6)."""
    with h5py.File(history, "r") as h:
        eps = h["axial_strain"][()]
    rows = []
    for e in strains:
        k = int(np.argmin(np.abs(eps - e)))
        if abs(eps[k] - e) > 1e-6:
            raise ValueError(f"{history}: no row at axial strain {e} (nearest {eps[k]})")
        rows.append(k)
    return rows


def stage2(case):
    """(axial strain, stress ratio, tau) of the IPs' mean stress in stage 2 (summary.csv)."""
    rows = [r for r in csv.DictReader(open(os.path.join(runs, case, "summary.csv"))) if r["stage"] == "2"]
    s11 = np.array([float(r["sigma11_mean"]) for r in rows])
    s22 = np.array([float(r["sigma22_mean"]) for r in rows])
    return np.array([float(r["axial_strain"]) for r in rows]), analyse.ratio(s11, s22), np.abs(s11 - s22) / 2


def increment(case, start, end):
    """(points, gamma) of F's shear strain increment from `start` to `end` axial strain."""
    history = os.path.join(runs, case, "history.h5")
    return bw.ip_field(history, *rows_at(history, (start, end)))


def softening_modulus(case):
    """(peak strain, tau peak, tau end, gamma in the band, H_s) from the peak of the ratio to the end."""
    eps, ratio, tau = stage2(case)
    k = int(np.argmax(ratio))
    _, g = increment(case, eps[k], eps[-1])
    return eps[k], tau[k], tau[-1], g.max(), (tau[k] - tau[-1]) / g.max()


def width_text(w):
    return "none" if np.isnan(w) else f"{1e3 * w:.1f} mm"


def main():
    done = [(fam, c, m, h) for fam, cases in FAMILIES for c, m, h in cases
            if os.path.exists(os.path.join(runs, c, "summary.csv"))
            and np.isclose(stage2(c)[0][-1:], INTERVALS[0][1], rtol=0, atol=1e-6).any()]
    if not done:
        sys.exit("band_study.py: none of the cases has reached 10 % in runs/ (run.sh CASE...)")
    finished = {c for _, c, _, _ in done}

    print("\n| family | mesh | element | ratio at the peak | at 10 % | "
          + " | ".join(f"band {100 * a:g}-{100 * b:g} %, inclined | all directions | half-share width"
                       for a, b in INTERVALS) + " |")
    print("|---" * (5 + 3 * len(INTERVALS)) + "|")
    maps = []
    with open(os.path.join(results, "band_study.csv"), "w") as fh:
        fh.write("case,family,mesh,element_mm,from_axial_strain,to_axial_strain,directions,band_width_mm,"
                 "band_angle_deg\n")
        for fam, c, m, h in done:
            eps, ratio, _ = stage2(c)
            coulomb = bw.coulomb_angle(ratio.max())  # the half-share width's band angle
            cells = []
            for a, b in INTERVALS:
                pts, g = increment(c, a, b)
                share, w_half = bw.half_share(g), bw.half_share_width(g, HEIGHT, coulomb)
                for name, angles in (("inclined", bw.INCLINED), ("all", range(180))):
                    w, ang, _ = bw.band_width(pts, g, band_angles=angles)
                    fh.write(f"{c},{fam},{m},{h:g},{a:g},{b:g},{name},{1e3 * w:.4g},{ang:.0f}\n")
                    cells.append(f"{width_text(w)} at {ang:.0f} deg")
                    if (a, b, name) == (*INTERVALS[-1], "inclined"):
                        maps.append((fam, m, pts, g, w, ang, w_half))
                fh.write(f"{c},{fam},{m},{h:g},{a:g},{b:g},half share {share:.4f},{1e3 * w_half:.4g},{coulomb:.0f}\n")
                cells.append(f"{width_text(w_half)} ({share:.3f})")
            print(f"| {fam} | {m} | {h:g} mm | {ratio.max():.3f} at {100 * eps[np.argmax(ratio)]:.3g} % | "
                  f"{ratio[-1]:.3f} | " + " | ".join(cells) + " |")

    # the same model twice: 4x8 one point local, and with R = 2.5 mm, where it has no neighbours
    # (F_nonlocal = F): what rounding alone does to the post-peak curve
    rounding = ("rounding (the same model)", [("mesh_4x8_op_quarter", "4x8, one point", 2.5),
                                              ("nonlocal_4x8_op_le_quarter", "4x8, one point, no neighbours", 2.5)])
    print(f"\n| family | meshes | peak of the mean at | spread after it: mean | largest | "
          f"from {100 * INTERVALS[-1][0]:g} %: mean | largest |\n" + "|---" * 7 + "|")
    for fam, cases in FAMILIES + [rounding]:
        for meshes in ([cases[:2], cases] if len(cases) > 2 else [cases]):
            if len(meshes) < 2 or any(c not in finished for c, _, _ in meshes):
                continue
            pts, _ = spread_after_peak({c: analyse.curve(c) for c, _, _ in meshes}, [c for c, _, _ in meshes])
            if pts:
                e, s = np.array(pts).T
                late = s[e >= INTERVALS[-1][0] - 1e-9]
                print(f"| {fam} | {', '.join(m for _, m, _ in meshes)} | {100 * e[0]:.3g} % | "
                      f"{100 * s.mean():.1f} % | {100 * s.max():.1f} % | {100 * late.mean():.1f} % | "
                      f"{100 * late.max():.1f} % |")

    mu_e = [E / (2 * (1 + C_E[1])) for E in C_E[0]]
    print("\n| local run | peak at | tau peak -> end (kN/m) | gamma in the band | H_s (MN/m) | "
          + " | ".join(f"mu_e / H_s, E = {E:g} N/m" for E in C_E[0]) + " |\n" + "|---" * (5 + len(mu_e)) + "|")
    local_runs = {c: m for fam, c, m, _ in done if not fam.startswith("local elastic")}  # once each
    for c, m in local_runs.items():
        e, t0, t1, g, hs = softening_modulus(c)
        print(f"| {m} | {100 * e:.3g} % | {t0 / 1e3:.1f} -> {t1 / 1e3:.1f} | {g:.3f} | {hs / 1e6:.3f} | "
              + " | ".join(f"{mu / hs:.1f}" for mu in mu_e) + " |")

    fams = [f for f, _ in FAMILIES if any(d[0] == f for d in done)]
    cols = max(sum(d[0] == f for d in done) for f in fams)
    fig, axs = plt.subplots(len(fams), cols, figsize=(2.6 * cols, 4.2 * len(fams)), squeeze=False)
    for row, fam in enumerate(fams):
        mine = [x for x in maps if x[0] == fam]
        for col in range(cols):
            a = axs[row][col]
            if col >= len(mine):
                a.axis("off")
                continue
            _, m, pts, g, w, ang, w_half = mine[col]
            sc = a.scatter(1e3 * pts[:, 0], 1e3 * pts[:, 1], c=g, s=2400 / len(pts) ** 0.9 + 4, marker="s",
                           cmap="viridis")
            a.set_title(f"{fam}\n{m}: band {width_text(w)} at {ang:.0f} deg,\nhalf-share width {width_text(w_half)}",
                        fontsize=7)
            a.set_aspect("equal")
            a.set_xlim(0, 10)
            a.set_ylim(0, 20)
            fig.colorbar(sc, ax=a, shrink=0.6)
    a, b = INTERVALS[-1]
    fig.suptitle(f"shear strain increment from {100 * a:g} to {100 * b:g} % axial strain "
                 "(0.125 % steps; reference positions, mm)", fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(results, "band_study.png"), dpi=110)


if __name__ == "__main__":
    main()
