#!/usr/bin/python3
"""[LSYF] problem 4 (issue 37): plane-strain biaxial compression, local
against nonlocal on three meshes each (FAMILIES; the spreads tabled: SPREADS). Reads
RESULTS/problem4_{local,R11.8,R11.8_le5,R11.8_le1}_MESH/, the single local elastic runs
problem4_R*_le{50,2,1,0.5}_*/ and problem4_2x4_rate{4,1}/ (run.sh problem4), prints the tables of the
README and writes into RESULTS:
  problem4_curves.png   stress ratio against axial strain, every case
  problem4_bands.png    the in-plane shear strain increment over the last 1 %
                        (top row) and 4 % (bottom row) at each IP (one-point
                        elements: the element centres)
  problem4.csv          per case and row: axial strain, sigma_a, ratio

The specimen's stress ratio is the platens': sigma_a = |top force| / (W D)
(nominal, W = 40 mm, D = 5 mm), the confining stress p_c = 416 kPa applied
on the sides, ratio (sigma_a - p_c) / (sigma_a + p_c), the [LBS] measure
|(s11 - s22)/(s11 + s22)| of the boundary stresses. (The volume average of
sigma_11 is not p_c: the rough platens' shear tractions add to it.)

Spread of a family: at each row from the peak of the family's mean curve
to the end of its shortest run, (max - min) / mean of the ratio over its
meshes. A run that stopped (an RVE lost a particle) counts with the rows
it converged. Band width:
benchmarks/lbs2018/band_width.py on the increment of F's in-plane block
(x, y) over the last 4 and 16 rows (1 and 4 % of axial strain), at the
IPs' reference positions, among the inclined directions (INCLINED) and,
beside it, among all; and the half-share width of the same increments
(band_width.half_share_width, session 38, as benchmarks/lbs2018's since
session 37): the smallest share of the IPs that holds half the increment,
read as a uniform band crossing the specimen at the Coulomb angle of the
run's peak ratio, 2 share H cos(angle), H = 80 mm. It needs no profile
falling to half its peak inside the specimen, which the FWHM does.

The band's softening modulus in shear, H_s = (tau_peak - tau_end) / gamma_band
with tau = (sigma_a - p_c) / 2 and gamma_band the largest shear strain
increment from the peak row to the end, is what C_e's shear modulus is
measured against (the softening bar of tests/test_nonlocal_softening_bar.cpp:
the band's width in R grows with C_e / H).

Usage: problem4.py RESULTS   (Debian's python3 with numpy, h5py, matplotlib)
"""
import csv
import os
import sys

import h5py
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import band_tools  # noqa: E402
from band_tools import bw, inplane_band, plot_curves, print_ce_ratios, shear_modulus  # noqa: E402

WIDTH, DEPTH, HEIGHT, P_CONFINING = 0.04, 0.005, 0.08, 4.16e5
MESHES_R = ["6x12", "8x16", "10x20"]  # the meshes whose IPs R = 11.8 mm reaches
# families: case-name pattern and meshes (le5, le1: the local elastic formulation, C_e of E = 5, 1 MPa)
FAMILIES = {"local": ("problem4_local_{}", ["4x8"] + MESHES_R),
            "nonlocal R = 11.8 mm": ("problem4_R11.8_{}", ["4x8"] + MESHES_R),
            "local elastic 5 MPa, R = 11.8 mm": ("problem4_R11.8_le5_{}", MESHES_R),
            "local elastic 1 MPa, R = 11.8 mm": ("problem4_R11.8_le1_{}", MESHES_R)}
# the mesh spreads tabled: [LSYF]'s three meshes, and the three whose IPs R = 11.8 mm reaches
SPREADS = [("local", ["4x8", "6x12", "8x16"]), ("nonlocal R = 11.8 mm", ["4x8", "6x12", "8x16"])] + [
    (fam, MESHES_R) for fam in FAMILIES]
# single runs of the local elastic formulation
LOCAL_ELASTIC = {"local elastic 50 MPa, R = 11.8 mm 8x16": "problem4_R11.8_le50_8x16",
                 "local elastic 50 MPa, R = 20 mm 4x8": "problem4_R20_le50_4x8",
                 "local elastic 1 MPa, R = 8 mm 10x20": "problem4_R8_le1_10x20",
                 "local elastic 1 MPa, R = 16 mm 10x20": "problem4_R16_le1_10x20",
                 "local elastic 2 MPa, R = 11.8 mm 10x20": "problem4_R11.8_le2_10x20",
                 "local elastic 0.5 MPa, R = 11.8 mm 10x20": "problem4_R11.8_le0.5_10x20"}
# the band width against R: (R in mm, case) at C_e of E = 1 MPa on the finest mesh (4 mm elements)
RADII = [(8.0, "local elastic 1 MPa, R = 8 mm 10x20"), (11.8, "local elastic 1 MPa, R = 11.8 mm 10x20"),
         (16.0, "local elastic 1 MPa, R = 16 mm 10x20")]
# the band width against C_e (each run's C_e read from its macro.prm) at R = 11.8 mm on the finest mesh
MODULI = ["local elastic 0.5 MPa, R = 11.8 mm 10x20", "local elastic 1 MPa, R = 11.8 mm 10x20",
          "local elastic 2 MPa, R = 11.8 mm 10x20", "local elastic 5 MPa, R = 11.8 mm 10x20"]
# the band of the increment over the last rows: 4 (1 % of axial strain, the band as it is at the end)
# and 16 (4 %, from 2 %: past every run's peak, the band that carried the softening)
BAND_ROWS = (4, 16)
NU_E = 0.2  # C_e's Poisson ratio in every run (run.sh local_elastic), for the moduli not run
INCLINED = bw.INCLINED  # the band directions searched (band_width.py)


def curve(case_dir):
    """(axial strain, sigma_a, ratio) arrays of one run, a row per load step, from the start."""
    with open(os.path.join(case_dir, "out", "summary.csv")) as f:
        rows = list(csv.DictReader(f))
    eps = np.array([0.0] + [float(r["axial_strain"]) for r in rows])
    sigma_a = np.array([P_CONFINING] + [abs(float(r["top_force"])) / (WIDTH * DEPTH) for r in rows])
    return eps, sigma_a, (sigma_a - P_CONFINING) / (sigma_a + P_CONFINING)


def stopped(case_dir):
    """Whether fe2dem stopped this run at a failed RVE (its converged rows are kept)."""
    log = os.path.join(case_dir, "log")
    return os.path.exists(log) and "the run stopped after writing" in open(log).read()


def cost(case_dir):
    """(wall s or where the run stopped, RVEs, RVE solves, DEM steps summed over the RVEs) of one run."""
    with open(os.path.join(case_dir, "out", "summary.csv")) as f:
        rows = list(csv.DictReader(f))
    with h5py.File(os.path.join(case_dir, "out", "history.h5"), "r") as h:
        n_rve = h["ip_position"].shape[0]
    wall = (f"stopped after {100 * float(rows[-1]['axial_strain']):.2f} %" if stopped(case_dir)
            else f"{float(open(os.path.join(case_dir, 'wall_s')).read()):.0f}")
    return wall, n_rve, sum(int(r["rve_solves"]) for r in rows), sum(int(r["dem_steps"]) for r in rows)


def spread(curves, cases, start=None):
    """[(strain, (max - min)/mean)] of the ratio of `cases`, from the peak of their mean (or the
    first row at axial strain `start`) to the end."""
    n = min(len(curves[c][2]) for c in cases)
    r = np.array([curves[c][2][:n] for c in cases])
    eps = curves[cases[0]][0]
    first = int(np.argmax(r.mean(axis=0))) if start is None else int(np.argmax(eps >= start - 1e-9))
    return [(eps[k], (r[:, k].max() - r[:, k].min()) / r[:, k].mean()) for k in range(first, n)]


def ratio_table(curves, names, every):
    """Markdown rows of the ratio of `names` at every `every`-th row (the run's peak in bold)."""
    print("| axial strain | " + " | ".join(names) + " |")
    print("|---" * (len(names) + 1) + "|")
    n = max(len(curves[c][0]) for c in names)
    for k in range(every, n, every):
        cells = []
        for c in names:
            e, _, r = curves[c]
            cells.append("-" if k >= len(r) else (f"**{r[k]:.3f}**" if k == int(np.argmax(r)) else f"{r[k]:.3f}"))
        print(f"| {100 * curves[names[0]][0][min(k, len(curves[names[0]][0]) - 1)]:.2f} % | " + " | ".join(cells) + " |")


def local_elastic_law(case_dir):
    """(lambda, mu) of C_e from the run's macro.prm, None for the total-strain or local runs."""
    entries = dict(line.strip()[4:].split(" = ", 1) for line in open(os.path.join(case_dir, "macro.prm"))
                   if line.strip().startswith("set ") and " = " in line)
    if entries.get("Formulation") != "local elastic":
        return None
    E, nu = float(entries["Local elastic modulus"]), float(entries["Local Poisson ratio"])
    return E * nu / ((1 + nu) * (1 - 2 * nu)), shear_modulus(E, nu)


def stress_parts(case_dir, row):
    """IP means at `row` (0-based) of |yy of F (C_e : (E - Ebar))| (0 without C_e), |P_yy|, the RVEs'
    -sigma_11 and det F - 1."""
    with h5py.File(os.path.join(case_dir, "out", "history.h5"), "r") as h:
        F = h["F"][row].reshape(-1, 3, 3)
        F_bar = h["F_nonlocal"][row].reshape(-1, 3, 3) if "F_nonlocal" in h else F
        P, sigma = h["P"][row].reshape(-1, 3, 3), h["sigma"][row].reshape(-1, 3, 3)
    law, term = local_elastic_law(case_dir), np.zeros(len(F))
    if law is not None:
        dE = 0.5 * (np.einsum("nji,njk->nik", F, F) - np.einsum("nji,njk->nik", F_bar, F_bar))
        S = 2 * law[1] * dE + law[0] * np.trace(dE, axis1=1, axis2=2)[:, None, None] * np.eye(3)
        term = np.abs(np.einsum("nij,njk->nik", F, S)[:, 1, 1])
    return term.mean(), np.abs(P[:, 1, 1]).mean(), -sigma[:, 0, 0].mean(), (np.linalg.det(F) - 1).mean()


def band_softening(curves, case_dir, k):
    """(peak strain, tau_peak, tau_end, gamma_band, H_s) of case `k`: the band's softening modulus in
    shear from the platens' peak to the end (module docstring)."""
    e, s, _ = curves[k]
    tau = (s - P_CONFINING) / 2
    peak, gamma, h_s = band_tools.band_softening(os.path.join(case_dir, "out", "history.h5"), tau[1:])
    return e[peak + 1], tau[peak + 1], tau[-1], gamma, h_s


def print_spreads(curves):
    print("\n## spread over the meshes from the peak of the family's mean: (max - min) / mean of the ratio")
    print("| family | meshes | peak of the mean at | largest | mean | at the end | largest from 1 % |")
    print("|---|---|---|---|---|---|---|")
    for fam, meshes in SPREADS:
        have = [f"{fam} {m}" for m in meshes if f"{fam} {m}" in curves]
        if len(have) < 2:
            continue
        s, s1 = spread(curves, have), spread(curves, have, 0.01)
        print(f"| {fam} | {', '.join(h.split()[-1] for h in have)} | {100 * s[0][0]:.2f} % | "
              f"{100 * max(v for _, v in s):.1f} % | {100 * np.mean([v for _, v in s]):.1f} % | "
              f"{100 * s[-1][1]:.1f} % | {100 * max(v for _, v in s1):.1f} % |")
    if {"local 2x4, 4 /s", "local 2x4, 1 /s"} <= set(curves):
        e, r4 = curves["local 2x4, 4 /s"][0], curves["local 2x4, 4 /s"][2]
        r1 = curves["local 2x4, 1 /s"][2]
        late = e >= 0.02
        print(f"\nrate (local 2x4): from 2 % the ratio at 4 /s is {r4[late].min():.3f}-{r4[late].max():.3f} "
              f"(mean {r4[late].mean():.3f}), at 1 /s {r1[late].min():.3f}-{r1[late].max():.3f} (mean {r1[late].mean():.3f})")


def print_softening(curves, done):
    print("\n## the band's softening modulus in shear, H_s (local runs), against C_e's shear modulus")
    print("| case | peak at | tau peak -> end (kPa) | gamma in the band | H_s (MPa) |")
    print("|---|---|---|---|---|")
    moduli = []
    for k in [f"local {m}" for m in MESHES_R]:
        if k in done:
            e, t0, t1, g, h = band_softening(curves, done[k], k)
            moduli.append(h)
            print(f"| {k} | {100 * e:.2f} % | {t0 / 1e3:.0f} -> {t1 / 1e3:.0f} | {g:.3f} | {h / 1e6:.2f} |")
    print_ce_ratios((50e6, 5e6, 1e6), NU_E, moduli)


def print_load_parts(curves, done):
    print("\n## what carries the load: IP means of the local elastic term and of the RVEs' stress (kPa)")
    print("| case | axial strain | C_e : (E - Ebar), yy | P_yy | RVEs' sigma_11 | det F - 1 |")
    print("|---|---|---|---|---|---|")
    for k in ["local 8x16", "nonlocal R = 11.8 mm 8x16", "local elastic 5 MPa, R = 11.8 mm 8x16",
              "local elastic 50 MPa, R = 11.8 mm 8x16", "local elastic 1 MPa, R = 11.8 mm 8x16"]:
        if k not in done:
            continue
        for row in (3, 11, 23):
            term, P_yy, s11, dJ = stress_parts(done[k], row)
            print(f"| {k} | {100 * curves[k][0][row + 1]:.0f} % | {term / 1e3:.0f} | {P_yy / 1e3:.0f} | "
                  f"{s11 / 1e3:.0f} | {dJ:.4f} |")


def print_bands(done, curves, path):
    """The band table (inclined directions over the last 1 and 4 %, and all over the last 1 %; the
    half-share widths), the band against R, over the meshes and against C_e, and the PNG of the
    fields (a row per interval)."""
    print("\n## band width (band_width.py; increment over the last 1 % and the last 4 % of axial strain)")
    print("| case | band width (mm), last 1 %, inclined | angle (deg from x) | last 4 %, inclined | angle | "
          "last 1 %, among all directions | angle | gamma max, last 1 % "
          "| half-share width (mm), last 1 % (share) | last 4 % (share) | Coulomb angle (deg) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    fig, axes = plt.subplots(len(BAND_ROWS), len(done), figsize=(2.2 * len(done), 4.6 * len(BAND_ROWS)),
                             squeeze=False)
    widths, half_widths = {}, {}
    for col, (k, d) in enumerate(done.items()):
        history = os.path.join(d, "out", "history.h5")
        bands = [inplane_band(history, rows, INCLINED) for rows in BAND_ROWS]
        _, _, width_all, angle_all, _ = inplane_band(history, BAND_ROWS[0])
        widths[k] = [b[2] for b in bands]
        coulomb = bw.coulomb_angle(curves[k][2].max())
        shares = [bw.half_share(b[1]) for b in bands]
        half_widths[k] = [2 * share * HEIGHT * np.cos(np.radians(coulomb)) for share in shares]
        print(f"| {k} | {1e3 * bands[0][2]:.1f} | {bands[0][3]:.0f} | {1e3 * bands[1][2]:.1f} | {bands[1][3]:.0f} | "
              f"{1e3 * width_all:.1f} | {angle_all:.0f} | {bands[0][1].max():.4f} | "
              + " | ".join(f"{1e3 * w:.1f} ({share:.3f})" for w, share in zip(half_widths[k], shares))
              + f" | {coulomb:.0f} |")
        for ax, rows, (x, g, width, _, _) in zip(axes[:, col], BAND_ROWS, bands):
            sc = ax.scatter(1e3 * x[:, 0], 1e3 * x[:, 1], c=g, s=3000 / len(x), marker="s", cmap="viridis")
            ax.set_title(f"{k}\nlast {rows / 4:g} %: width {1e3 * width:.1f} mm", fontsize=7)
            ax.set_aspect("equal")
            ax.set_xlim(0, 40)
            ax.set_ylim(0, 80)
            ax.tick_params(labelsize=6)
            fig.colorbar(sc, ax=ax, shrink=0.6).ax.tick_params(labelsize=6)
    fig.suptitle("in-plane shear strain increment over the last 1 % (top) and 4 % (bottom) of axial strain "
                 "(x, y in mm)", fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    for title, measure in (("inclined", widths), ("half-share", half_widths)):
        print_width_series(f"band width against R ({title})", "R (mm)",
                           [(k, f"{r:g}", r) for r, k in RADII if k in measure], measure)
        print_width_series(f"band width against C_e ({title}; R = 11.8 mm)",
                           "C_e's shear modulus E / (2 (1 + nu)) (MPa)",
                           [(k, f"{local_elastic_law(done[k])[1] / 1e6:.2f}", 11.8) for k in MODULI if k in measure],
                           measure)
    print_width_over_meshes(half_widths)


def print_width_series(title, column, rows, widths):
    """A table of the band widths (last 1 and 4 %) of `rows`: (case, the varied value, R in mm)."""
    if not rows:
        return
    print(f"\n## {title}")
    print(f"| case | {column} | last 1 % (mm) | width / R | last 4 % (mm) | width / R |")
    print("|---|---|---|---|---|---|")
    for k, value, r in rows:
        w1, w4 = (1e3 * w for w in widths[k])
        print(f"| {k} | {value} | {w1:.1f} | {w1 / r:.2f} | {w4:.1f} | {w4 / r:.2f} |")


def print_width_over_meshes(widths):
    """The half-share widths of each family over its meshes (last 1 % / last 4 %, mm), beside the
    element height, and the change from the coarsest mesh to the finest."""
    print("\n## half-share band width over the meshes (last 1 % / last 4 %, mm)")
    meshes = FAMILIES["local"][1]
    print("| family | " + " | ".join(f"{m} ({1e3 * HEIGHT / int(m.split('x')[1]):.3g} mm)" for m in meshes)
          + " | coarsest -> finest, last 4 % |")
    print("|---" * (len(meshes) + 2) + "|")
    for fam, (_, fam_meshes) in FAMILIES.items():
        have = [m for m in fam_meshes if f"{fam} {m}" in widths]
        if len(have) < 2:
            continue
        cells = [" / ".join(f"{1e3 * w:.1f}" for w in widths[f"{fam} {m}"]) if m in have else "-" for m in meshes]
        first, last = (widths[f"{fam} {m}"][1] for m in (have[0], have[-1]))
        print(f"| {fam} | " + " | ".join(cells) + f" | {100 * (last / first - 1):+.0f} % ({have[0]} -> {have[-1]}) |")


def print_cost(done):
    print("\n## cost (2 ranks on the 2-core VM, walls shared with other runs)")
    print("| case | wall (s) | RVEs | RVE solves | DEM steps (all RVEs) |")
    print("|---|---|---|---|---|")
    for k, d in done.items():
        wall, n_rve, solves, dem = cost(d)
        print(f"| {k} | {wall} | {n_rve} | {solves} | {dem:.3g} |")


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    results = sys.argv[1]
    cases = {f"{fam} {m}": os.path.join(results, pat.format(m)) for fam, (pat, meshes) in FAMILIES.items()
             for m in meshes}
    cases.update({f"local 2x4, {r} /s": os.path.join(results, f"problem4_2x4_rate{r}") for r in (4, 1)})
    cases.update({k: os.path.join(results, c) for k, c in LOCAL_ELASTIC.items()})
    # finished runs, and runs that stopped (an RVE failed) with the rows they converged
    done = {k: d for k, d in cases.items() if os.path.exists(os.path.join(d, "wall_s")) or stopped(d)}
    curves = {k: curve(d) for k, d in done.items()}

    with open(os.path.join(results, "problem4.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case", "axial_strain", "sigma_a_Pa", "stress_ratio"])
        for k, (e, s, r) in curves.items():
            w.writerows([k, f"{a:.5f}", f"{b:.1f}", f"{c:.5f}"] for a, b, c in zip(e, s, r))

    print("## stress ratio of the platens, every 0.25 % (peak in bold)")
    ratio_table(curves, list(curves), 1)
    print("\n## the mesh families, every 0.5 %")
    ratio_table(curves, [f"{fam} {m}" for fam, (_, meshes) in FAMILIES.items() for m in meshes
                         if f"{fam} {m}" in curves], 2)
    print_spreads(curves)
    print_softening(curves, done)
    print_load_parts(curves, done)
    print_bands(done, curves, os.path.join(results, "problem4_bands.png"))
    print_cost(done)
    plot_curves({k: (e, r) for k, (e, _, r) in curves.items()}, "axial strain (%)", "stress ratio (platens)",
                os.path.join(results, "problem4_curves.png"), dashed=lambda k: not k.startswith("local"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
