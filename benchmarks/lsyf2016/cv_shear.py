#!/usr/bin/python3
"""Constant-volume simple shear of problem 3's RVEs, fe2dem-rve against YADE (issue 37, session
38; run.sh BUILD cv_shear): the independent check of why a weak RVE driven by its neighbours'
average loses its pressure (README, problem 3: "Why the weak element takes an increment its RVE
does not see").

  RVE   RESULTS/RVE_RUNS[(PACKING, RATE)]/rve.csv: fe2dem-rve, the frame RVE of rve_setup_3d with
        the [LSYF] Hertz grains, prepared at 416 kPa, then F12 = gamma to 8 % at RATE (4 or 1 /s)
        with F11, F22, F33 held (Path 'simple shear')
  YADE  YADE_RESULTS/PACKING_shear_cv_rateF_*.csv: benchmarks/yade_periodic/periodic_3d.py on
        PACKING.rve.data read as the periodic packing it stands for, Hertz-Mindlin contacts of the
        same grains, isotropic to 416 kPa, then velGrad_xy alone (constant volume) at F x 0.25 /s

for PACKING lsyf_300 and lsyf_300_weak (25 inner spheres removed: solid fraction 0.608 against
0.653). Prints p and tau/p of both codes every 1 % of shear and writes RESULTS/cv_shear.png.
Then the weak RVE of a problem-3 run (REPLAYS) against fe2dem-rve replaying the averaged F its IP
saw, RESULTS/weak_replay_CASE/rve.csv (weak_replay.prm): the pressure of its RVE (Love-Weber) at
each row of the macro run and of the replay, and the row's det F_nonlocal - 1.
gamma: the RVE's F12 from the last row with F12 = 0; YADE's H_xy / Ly_ic. Stresses: p = -tr(sigma)/3,
tau = |sigma_12| (RVE: its boundary stress 'sigma').

Usage: cv_shear.py RESULTS YADE_RESULTS   (Debian's python3 with numpy, matplotlib)
"""
import csv
import glob
import os
import sys

import h5py

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "yade_periodic"))
from yade_common import read_yade_csv  # noqa: E402

PACKINGS = ("lsyf_300", "lsyf_300_weak")
RVE_RUNS = {("lsyf_300", 4): "step_shear_rve", ("lsyf_300_weak", 4): "cv_shear_rve_lsyf_300_weak",
            ("lsyf_300_weak", 1): "cv_shear_rve_lsyf_300_weak_rate1"}  # run.sh shear_rve
REPLAYS = ("problem3_R0.015_le2_12x10", "problem3_R0_12x10")  # one-IP seed: R = 15 mm (E = 2 MPa), local
EVERY = 0.01      # the table's rows


def rve_curve(path):
    """(gamma, p, tau/p) of fe2dem-rve's rows from the start of the shear."""
    with open(path) as f:
        rows = list(csv.DictReader(f))
    start = max(k for k, r in enumerate(rows) if float(r["F12"]) == 0.0)
    rows = rows[start:]
    g = np.array([float(r["F12"]) for r in rows])
    p = np.array([-(float(r["sigma11"]) + float(r["sigma22"]) + float(r["sigma33"])) / 3 for r in rows])
    tau = np.array([abs(float(r["sigma12"])) for r in rows])
    return g, p, tau / p


def yade_curves(results, packing):
    """{rate in 1/s: (gamma, p, tau/p)} of the YADE runs of @p packing."""
    curves = {}
    for path in sorted(glob.glob(os.path.join(results, f"{packing}_shear_cv_rate*.csv"))):
        meta, rows = read_yade_csv(path)
        rows = [r for r in rows if r["stage"] in ("isotropic", "shear_cv")]
        g = np.array([r["strain"] for r in rows])
        p = np.array([r["p_Pa"] for r in rows])
        curves[float(meta["rate"])] = (g, p, np.abs(np.array([r["sigma12_Pa"] for r in rows])) / p)
    return curves


def lw_pressure(sigma):
    """p = -tr(sigma)/3 of Love-Weber stresses [rows, 9]."""
    return -(sigma[:, 0] + sigma[:, 4] + sigma[:, 8]) / 3.0


def print_replays(results):
    """The weak RVE's pressure in the macro run and in fe2dem-rve's replay of its averaged F."""
    done = [c for c in REPLAYS if os.path.exists(os.path.join(results, f"weak_replay_{c}", "wall_s"))]
    if not done:
        return
    print("\n## the weak RVE along the averaged F its IP saw: p (kPa) in the macro run / in the replay, "
          "det F_nonlocal - 1")
    for c in done:
        with h5py.File(os.path.join(results, c, "out", "history.h5"), "r") as h:
            phi = h["packing_fraction"][0]
            weak = int(np.flatnonzero(phi < np.median(phi) - 0.02)[0])  # problem3.weak_ips
            macro = lw_pressure(h["sigma_lw"][:, weak, :])
            F = h["F_nonlocal"][:, weak, :].reshape(-1, 3, 3) if "F_nonlocal" in h else \
                h["F"][:, weak, :].reshape(-1, 3, 3)
        with open(os.path.join(results, f"weak_replay_{c}", "rve.csv")) as f:
            rows = list(csv.DictReader(f))[-len(macro):]  # the table's rows, after the isotropic stage
        replay = lw_pressure(np.array([[float(r[f"sigmaLW{i}{j}"]) for i in "123" for j in "123"] for r in rows]))
        print(f"\n{c} (weak IP {weak})")
        print("| row | F12 | det F - 1 | macro run p | replay p |")
        print("|---|---|---|---|---|")
        for k in range(len(macro)):
            print(f"| {k + 1} | {F[k, 0, 1]:.4f} | {np.linalg.det(F[k]) - 1:+.5f} | {macro[k] / 1e3:.0f} | "
                  f"{replay[k] / 1e3:.0f} |")


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    results, yade_results = sys.argv[1], sys.argv[2]
    rve = {k: rve_curve(os.path.join(results, c, "rve.csv")) for k, c in RVE_RUNS.items()
           if os.path.exists(os.path.join(results, c, "wall_s"))}
    yade = {k: yade_curves(yade_results, k) for k in PACKINGS}
    columns = [(f"RVE {k}, {rate:g} /s", rve[(k, rate)]) for k, rate in RVE_RUNS if (k, rate) in rve]
    columns += [(f"YADE {k}, {rate:g} /s", c) for k in PACKINGS for rate, c in sorted(yade[k].items(), reverse=True)]
    if not columns:
        sys.exit("cv_shear.py: no run in " + results + " or " + yade_results)

    grid = np.arange(0.0, 0.08 + 1e-9, EVERY)
    print("## constant-volume simple shear at 416 kPa: p (kPa) and tau/p")
    print("| shear strain | " + " | ".join(f"{name}: p | tau/p" for name, _ in columns) + " |")
    print("|---" * (1 + 2 * len(columns)) + "|")
    for g in grid:
        cells = []
        for _, (gc, p, r) in columns:
            inside = g <= gc[-1] + 1e-9
            cells += [f"{np.interp(g, gc, p) / 1e3:.0f}" if inside else "-", f"{np.interp(g, gc, r):.3f}" if inside else "-"]
        print(f"| {100 * g:.0f} % | " + " | ".join(cells) + " |")

    print("\n## p at the end over p at the start of the shear, and the lowest p on the way")
    print("| run | p start (kPa) | p end (kPa) | end / start | lowest p (kPa) at |")
    print("|---|---|---|---|---|")
    for name, (g, p, _) in columns:
        k = int(np.argmin(p))
        print(f"| {name} | {p[0] / 1e3:.0f} | {p[-1] / 1e3:.0f} | {p[-1] / p[0]:.2f} | {p[k] / 1e3:.0f} at {100 * g[k]:.2f} % |")

    fig, axes = plt.subplots(1, 2, figsize=(9, 3.6))
    for name, (g, p, r) in columns:
        style = "o-" if name.startswith("RVE") else "-"
        axes[0].plot(100 * g, p / 1e3, style, ms=3, label=name)
        axes[1].plot(100 * g, r, style, ms=3, label=name)
    axes[0].set_ylabel("p (kPa)")
    axes[1].set_ylabel("tau/p")
    for ax in axes:
        ax.set_xlabel("shear strain (%)")
    axes[0].legend(fontsize=6)
    fig.suptitle("constant-volume simple shear from 416 kPa: the RVE (fe2dem-rve) against a periodic YADE cell",
                 fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(results, "cv_shear.png"), dpi=110)
    print_replays(results)
    return 0


if __name__ == "__main__":
    sys.exit(main())
