#!/usr/bin/python3
"""[LSYF] problem 3 (issue 37): simple shear with one weakened RVE, local
and nonlocal. Reads RESULTS/problem3_*/ (CASES; run.sh problem3; a run that
stopped counts with its rows), prints the tables of the README and writes
into RESULTS:
  problem3_curves.png  tau/p of the volume average against the shear strain
  problem3_bands.png   the in-plane shear strain increment of the last 2 %
                       of shear at each IP (element centres), the weak IP marked
  problem3_rotation.png  the inner particles' mean rotation at the end at
                       each IP, for the runs that recorded it
  problem3_profiles.png  the band's profile across it: the row means of the
                       shear strain increment of the last 2 % against y, of
                       the elements' F and of what the RVEs saw, for FIXED_R
  problem3_profiles_r.png  the same for AGAINST_R (R = 5, 10, 15 mm on 12x20)
  problem3_width_history.png  the elements' F's profile width of each 4-row
                       window along the runs of CONVERGED and ENSEMBLES
  problem3.csv         per case and IP at the last row: position, band
                       membership, porosity, coordination, sliding fraction,
                       mean particle rotation

Stresses: the mean of the IPs' Cauchy stress (equal element volumes), tau =
|sigma_12|, p = -tr(sigma)/3. The band: benchmarks/lbs2018/band_width.py on
the increment of F's in-plane block over the last four rows (2 % of shear)
(and of F_nonlocal's, what the RVEs saw, in the table against R),
among all directions and among those within 20 degrees of x (ALONG_X);
inside = the IPs whose increment exceeds half the largest. Inside against
outside: porosity 1 - solid fraction, coordination 2C/N, the fraction of
sliding contacts, the inner particles' mean rotation (history.h5's
mean_rotation: mean |theta| accumulated since the RVE was built, in rad;
"-" for runs made before fe2dem recorded it), means over the IPs at the
last row.

Usage: problem3.py RESULTS   (Debian's python3 with numpy, h5py, matplotlib)
"""
import csv
import itertools
import os
import re
import sys

import h5py
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from band_tools import band_softening, bw, inplane_band, plot_curves, print_ce_ratios  # noqa: E402

CASES = {"local": "problem3_R0", "R = 15 mm": "problem3_R0.015", "R = 25 mm": "problem3_R0.025",
         "R = 25 mm, local elastic 584 MPa": "problem3_R0.025_le584",
         "R = 25 mm, local elastic 50 MPa": "problem3_R0.025_le50",
         "R = 15 mm, local elastic 0.5 MPa": "problem3_R0.015_le0.5",
         "R = 20 mm, local elastic 0.5 MPa": "problem3_R0.02_le0.5",
         "R = 25 mm, local elastic 0.5 MPa": "problem3_R0.025_le0.5",
         "local, 2 us step": "problem3_R0_dt2us", "local, 1 us step": "problem3_R0_dt1us",
         "local, 12x10": "problem3_R0_12x10",
         "R = 10 mm, local elastic 0.5 MPa, 12x10": "problem3_R0.01_le0.5_12x10",
         "R = 20 mm, local elastic 0.5 MPa, 12x10": "problem3_R0.02_le0.5_12x10",
         "R = 10 mm, local elastic 2 MPa, 12x10": "problem3_R0.01_le2_12x10",
         "R = 15 mm, local elastic 2 MPa, 12x10": "problem3_R0.015_le2_12x10",
         "R = 15 mm, local elastic 2 MPa": "problem3_R0.015_le2",
         "R = 20 mm, local elastic 2 MPa": "problem3_R0.02_le2",
         "R = 6.75 mm, local elastic 2 MPa, 12x15": "problem3_R0.00675_le2_12x15",
         "R = 5 mm, local elastic 2 MPa, 12x20": "problem3_R0.005_le2_12x20",
         "R = 15 mm, local elastic 2 MPa, 12x10, seed box": "problem3_R0.015_le2_12x10_box",
         "R = 10 mm, local elastic 2 MPa, 12x10, seed box": "problem3_R0.01_le2_12x10_box",
         "R = 10 mm, local elastic 2 MPa, 12x20, seed box": "problem3_R0.01_le2_12x20_box",
         "R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume": "problem3_R0.01_le2_12x10_box_own",
         "R = 10 mm, local elastic 2 MPa, 12x20, seed box, own volume": "problem3_R0.01_le2_12x20_box_own",
         "R = 15 mm, local elastic 2 MPa, 12x10, own volume": "problem3_R0.015_le2_12x10_own",
         "R = 15 mm, local elastic 2 MPa, 12x20, seed box, own volume": "problem3_R0.015_le2_12x20_box_own",
         "R = 5 mm, local elastic 2 MPa, 12x20, seed box, own volume": "problem3_R0.005_le2_12x20_box_own",
         "R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume, 1 us step":
             "problem3_R0.01_le2_12x10_box_own_dt1us",
         "R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume, 2 /s": "problem3_R0.01_le2_12x10_box_own_rate2",
         "R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume, 0.5 us step":
             "problem3_R0.01_le2_12x10_box_own_dt0.5us",
         "R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume, 1 us step, checks of 5":
             "problem3_R0.01_le2_12x10_box_own_dt1us_ci5",
         **{f"R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume, top pressure +{k} ppm":
            f"problem3_R0.01_le2_12x10_box_own_p{k}" for k in range(1, 5)},
         **{f"R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume, 0.5 us step, top pressure +{k} ppm":
            f"problem3_R0.01_le2_12x10_box_own_dt0.5us_p{k}" for k in range(1, 4)},
         "R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume, 0.2 us step":
             "problem3_R0.01_le2_12x10_box_own_dt0.2us",
         **{f"R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume, 0.2 us step, top pressure +{k} ppm":
            f"problem3_R0.01_le2_12x10_box_own_dt0.2us_p{k}" for k in range(1, 4)},
         **{f"R = {r} mm, local elastic 2 MPa, 12x10, seed box, own volume{f', top pressure +{k} ppm' if k else ''}":
            f"problem3_R{radius}_le2_12x10_box_own{f'_p{k}' if k else ''}"
            for r, radius in ((15, "0.015"), (20, "0.02")) for k in range(4)},
         "R = 20 mm, local elastic 2 MPa, 12x10, seed box": "problem3_R0.02_le2_12x10_box",
         **{f"R = {r} mm, local elastic 2 MPa, 12x10, seed box, top pressure +{k} ppm":
            f"problem3_R{radius}_le2_12x10_box_p{k}"
            for r, radius in ((10, "0.01"), (15, "0.015"), (20, "0.02")) for k in range(1, 3)},
         **{f"R = {r} mm, local elastic 2 MPa, 12x10, seed box, own volume, 1 us step":
            f"problem3_R{radius}_le2_12x10_box_own_dt1us" for r, radius in ((15, "0.015"), (20, "0.02"))},
         **{f"R = {r} mm, local elastic 2 MPa, 12x10, seed box, own volume, 1 us step, top pressure +{k} ppm":
            f"problem3_R{radius}_le2_12x10_box_own_dt1us_p{k}" for r, radius in ((15, "0.015"), (20, "0.02"))
            for k in range(1, 4)},
         # session 45's build: the last check's stress (the runs above at 2 us had the mean of two checks)
         **{f"R = {r} mm, local elastic 2 MPa, 12x10, seed box, own volume, last check":
            f"problem3_R{radius}_le2_12x10_box_own_last" for r, radius in ((15, "0.015"), (20, "0.02"))},
         # ... and at half the rate (session 46, run.sh problem3_half_rate)
         **{f"R = {r} mm, local elastic 2 MPa, 12x10, seed box, own volume, last check, 2 /s":
            f"problem3_R{radius}_le2_12x10_box_own_last_rate2" for r, radius in ((15, "0.015"), (20, "0.02"))}}
# the band width against R and the mesh: (R in mm, element height in mm, case)
# The macro step is fe2dem's default (5 us on 12x5, 2 us on 12x10 and 12x15, 1 us on 12x20) but where the
# case names it (run.sh problem3_step_cases, problem3_band_cases, problem3_scaled_cases; README,
# 'The rate, and the macro step')
RADII = [(0.0, 10.1, "local"), (15.0, 10.1, "R = 15 mm, local elastic 0.5 MPa"),
         (20.0, 10.1, "R = 20 mm, local elastic 0.5 MPa"), (25.0, 10.1, "R = 25 mm, local elastic 0.5 MPa"),
         (0.0, 5.06, "local, 12x10"), (10.0, 5.06, "R = 10 mm, local elastic 0.5 MPa, 12x10"),
         (20.0, 5.06, "R = 20 mm, local elastic 0.5 MPa, 12x10"),
         (10.0, 5.06, "R = 10 mm, local elastic 2 MPa, 12x10"), (15.0, 5.06, "R = 15 mm, local elastic 2 MPa, 12x10"),
         (15.0, 10.1, "R = 15 mm, local elastic 2 MPa"), (20.0, 10.1, "R = 20 mm, local elastic 2 MPa"),
         (6.75, 3.37, "R = 6.75 mm, local elastic 2 MPa, 12x15"), (5.0, 2.53, "R = 5 mm, local elastic 2 MPa, 12x20"),
         (15.0, 5.06, "R = 15 mm, local elastic 2 MPa, 12x10, seed box"),
         (10.0, 5.06, "R = 10 mm, local elastic 2 MPa, 12x10, seed box"),
         (10.0, 2.53, "R = 10 mm, local elastic 2 MPa, 12x20, seed box"),
         (10.0, 5.06, "R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume"),
         (10.0, 2.53, "R = 10 mm, local elastic 2 MPa, 12x20, seed box, own volume"),
         (15.0, 5.06, "R = 15 mm, local elastic 2 MPa, 12x10, own volume"),
         (15.0, 2.53, "R = 15 mm, local elastic 2 MPa, 12x20, seed box, own volume"),
         (5.0, 2.53, "R = 5 mm, local elastic 2 MPa, 12x20, seed box, own volume")]
# the band over meshes at a fixed R (run.sh problem3_fixed_r), beside the local band on two meshes:
# the profiles across the band in problem3_profiles.png
FIXED_R = ["local", "local, 12x10", "R = 10 mm, local elastic 2 MPa, 12x10, seed box",
           "R = 10 mm, local elastic 2 MPa, 12x20, seed box",
           "R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume",
           "R = 10 mm, local elastic 2 MPa, 12x20, seed box, own volume"]
# the band against R on one mesh (12x20, the seed box, own volume): problem3_profiles_r.png
AGAINST_R = ["R = 5 mm, local elastic 2 MPa, 12x20, seed box, own volume",
             "R = 10 mm, local elastic 2 MPa, 12x20, seed box, own volume",
             "R = 15 mm, local elastic 2 MPa, 12x20, seed box, own volume"]
# ... and their profiles' widths (print_profile_widths) with the one-IP seed at R = 15 mm on 12x10
PROFILE_CASES = FIXED_R + ["R = 5 mm, local elastic 2 MPa, 12x20", "R = 15 mm, local elastic 2 MPa, 12x10",
                           "R = 15 mm, local elastic 2 MPa, 12x10, own volume",
                           "R = 15 mm, local elastic 2 MPa, 12x20, seed box, own volume",
                           "R = 5 mm, local elastic 2 MPa, 12x20, seed box, own volume"]
# the banded answer's convergence (run.sh problem3_converged): the reference (default macro step 2 us,
# 4 /s) and the same case at half and a quarter of the macro step (the quarter with servo checks of 5
# DEM steps, not 10), at half the step with checks of 5, and at half the rate
CONVERGED = ("R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume",
             "R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume, 1 us step",
             "R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume, 0.5 us step",
             "R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume, 1 us step, checks of 5",
             "R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume, 2 /s")
# ... and at a tenth of the default step (0.2 us = 2 DEM steps, servo checks of 2; run.sh problem3_fine_step)
FINE_STEP = "R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume, 0.2 us step"
# ... and the reference with the top's pressure 1-4 parts per million higher, the quarter step with 1-3
# (run.sh problem3_perturbed) and the tenth with 1-3 (problem3_fine_step): the scatter at one step and
# rate, {step: (unperturbed, perturbed)}, from the largest step to the smallest
ENSEMBLES = {step: (base, tuple(k for k in CASES if k.startswith(base + ", top pressure")))
             for step, base in (("2 us", CONVERGED[0]), ("0.5 us", CONVERGED[2]), ("0.2 us", FINE_STEP))}
PERTURBED = sum((e[1] for e in ENSEMBLES.values()), ())
# ... and the 2 us ensemble at R = 15 and 20 mm beside R = 10 mm's, with each RVE's own volume (run.sh
# problem3_against_r) and with the averaged one (problem3_against_r_averaged; session 44): the band's
# width against R from ensemble means, {family: {R in mm: (unperturbed, perturbed)}}
R_FAMILIES = {family: {r: (base, tuple(k for k in CASES if k.startswith(base + ", top pressure")))
                       for r, base in ((r, f"R = {r:g} mm, local elastic 2 MPa, 12x10, seed box{suffix}")
                                       for r in (10.0, 15.0, 20.0))}
              for family, suffix in (("own volume", ", own volume"), ("averaged volume", ""))}
# ... and own volume at one check per macro step, where the mean of a step's checks (fe2dem before session
# 45) and the last check's stress (since) are the same bits: R = 10 mm at 0.2 us (checks of 2), R = 15
# and 20 mm at 1 us (run.sh problem3_own_half_step, problem3_against_r_half_step)
R_FAMILIES["own volume, one check per step"] = {
    r: (base, tuple(k for k in CASES if k.startswith(base + ", top pressure")))
    for r, base in ((r, f"R = {r:g} mm, local elastic 2 MPa, 12x10, seed box, own volume, {step} step")
                    for r, step in ((10.0, "0.2 us"), (15.0, "1 us"), (20.0, "1 us")))}
# the ensembles' macro step, where not fe2dem's default 2 us on 12x10
FAMILY_STEP = {"own volume, one check per step": "0.2 us at R = 10 mm, 1 us at 15 and 20 mm"}
APPLIED = 4.16e5  # Pa, the top's vertical stress (problem3.prm)
# ... and own volume at 1 us, (R in mm, case) (run.sh problem3_own_half_step; R = 10 mm's is CONVERGED[1])
HALF_STEP = [(10.0, CONVERGED[1]),
             *((r, f"R = {r:g} mm, local elastic 2 MPa, 12x10, seed box, own volume, 1 us step") for r in (15.0, 20.0)),
             (20.0, "R = 20 mm, local elastic 2 MPa, 12x10, seed box, own volume, 1 us step, top pressure +1 ppm")]
# ... and own volume at the default 2 us with the last check's stress (session 45's build), at 4 and 2 /s
# (run.sh problem3_last_check, problem3_half_rate): (R in mm, case, label)
LAST_CHECK = [(r, f"R = {r:g} mm, local elastic 2 MPa, 12x10, seed box, own volume, last check{suffix}", label)
              for r in (15.0, 20.0) for suffix, label in (("", "2 us, 4 /s"), (", 2 /s", "2 us, 2 /s"))]
# the R = 20 mm own-volume case for its first 1 % of shear, one ingredient changed at a time (run.sh
# problem3_hourglass_probe; two rows, so not in CASES): {label: directory}
PROBES = {"R = 20 mm, own volume, seed box, 2 us (as problem3_against_r)": "probe_R0.02_own_box",
          "... without the seed": "probe_R0.02_own_no_seed",
          "... without C_e (total strain)": "probe_R0.02_own_box_total_strain",
          "... with the averaged volume": "probe_R0.02_averaged_box",
          "... at 1 us": "probe_R0.02_own_box_dt1us",
          "as run, 2 us, with the last check's stress (session 45's build)": "probe_R0.02_own_box_last"}
BACKWARDS = -0.01  # a shear increment below this over the last BAND_ROWS rows: an IP shearing backwards
# the band's directions in simple shear: along the shear, within 20 degrees of x (the local runs' band
# is at 4 degrees); among all directions the finder can return a hot spot around the weak RVE
ALONG_X = list(range(0, 21)) + list(range(160, 180))
NU_E = 0.2  # C_e's Poisson ratio (run.sh local_elastic)
HEIGHT, SHEAR = 0.0506, 0.08           # the top's displacement is SHEAR * HEIGHT at the end
LOAD_STEPS = 16                        # problem3.prm: rows at SHEAR * step / LOAD_STEPS
BAND_ROWS = 4
OFF_BAND = 0.012  # m from the weak IP's row: outside the local runs' bands on both meshes


def read(case_dir):
    """Everything of one run's history.h5 that the tables need."""
    with h5py.File(os.path.join(case_dir, "out", "history.h5"), "r") as h:
        d = {k: h[k][()] for k in ("ip_position", "sigma", "sigma_lw", "packing_fraction", "coordination",
                                   "contacts", "sliding_contacts", "step", "F")}
        d["F_nonlocal"] = h["F_nonlocal"][()] if "F_nonlocal" in h else d["F"]  # what the RVEs saw
        d["mean_rotation"] = h["mean_rotation"][()] if "mean_rotation" in h else None
    d["gamma_macro"] = SHEAR * d["step"] / LOAD_STEPS  # load steps are equal in time; a stopped run has fewer
    return d


def curve(d):
    """(shear strain, tau/p) of the mean stress, from the start."""
    s = d["sigma"].mean(axis=1)  # [rows, 9]
    p = -(s[:, 0] + s[:, 4] + s[:, 8]) / 3.0
    return np.concatenate([[0.0], d["gamma_macro"]]), np.concatenate([[0.0], np.abs(s[:, 1]) / p])


def shear_increment(F, rows):
    """dF12 + dF21 of each IP over the last BAND_ROWS of @p rows rows of F (history.h5's layout)."""
    F = F.reshape(rows, -1, 3, 3)
    dF = F[-1] - F[-1 - BAND_ROWS]
    return dF[:, 0, 1] + dF[:, 1, 0]


def weak_ips(d):
    """The IPs of the weakened packing (one, or those of subsection Imperfection's box): a solid
    fraction after the preparation more than 0.02 below the median (25 of 178 inner spheres
    removed: about 0.045 lower; tests/check_imperfection.py)."""
    phi = d["packing_fraction"][0]
    return np.flatnonzero(phi < np.median(phi) - 0.02)


def weak_stress(d):
    """(Love-Weber stress of the weak RVEs [rows, weak IPs, 3, 3], their pressure -tr/3 [rows, weak IPs])."""
    s = d["sigma_lw"].reshape(len(d["step"]), -1, 3, 3)[:, weak_ips(d)]
    return s, -np.trace(s, axis1=2, axis2=3) / 3


def nonlocal_weights(case_dir, r):
    """The unnormalised weights of subsection Nonlocal in the run's macro.prm at distances @p r (m):
    Wendland's (1 - r/R)^4 (4 r/R + 1), fe2dem's default, or the bell (1 - r^2/R^2)^2; zero
    beyond R; with no radius (local) 1 at r = 0 and 0 elsewhere."""
    text = open(os.path.join(case_dir, "macro.prm")).read()
    m = re.search(r"set Interaction radius\s*=\s*(\S+)", text)
    radius = float(m.group(1)) if m else 0.0
    if radius <= 0:
        return (r == 0).astype(float)
    q = np.minimum(r / radius, 1.0)
    bell = re.search(r"set Weight\s*=\s*bell", text) is not None
    return (1 - q ** 2) ** 2 if bell else (1 - q) ** 4 * (4 * q + 1)


def print_seed(results, done):
    """The weak RVEs at the end: their share of their own average (the run's weights of the weak IPs
    over those of all IPs, seen from the first weak one; 1 when local), the
    pressure and shear stress of their RVEs (Love-Weber) at the start and the end, and the volume
    change of the element (det F) against the one the RVE saw (det F_nonlocal)."""
    print("\n## the weak RVE(s), each (in the order of the IPs): their share of their own average, and what "
          "their RVE saw")
    print("| case | weak IPs | share of the weak IPs in the average | RVE's p, first row -> end (kPa) "
          "| RVE's tau at the end (kPa) | element's det F | RVE's det F |")
    print("|---|---|---|---|---|---|---|")
    for k, d in done.items():
        weak = weak_ips(d)
        x = d["ip_position"][:, :2]
        a = nonlocal_weights(os.path.join(results, CASES[k]), np.linalg.norm(x - x[weak[0]], axis=1))
        share = a[weak].sum() / a.sum()
        s, p = weak_stress(d)
        F, Fn = (d[f].reshape(len(d["step"]), -1, 3, 3)[-1, weak] for f in ("F", "F_nonlocal"))

        def each(v, fmt):
            return ", ".join(fmt.format(x) for x in v)

        print(f"| {k} | {len(weak)} | {share:.2f} | {each(p[0] / 1e3, '{:.0f}')} -> {each(p[-1] / 1e3, '{:.0f}')} "
              f"| {each(np.abs(s[-1, :, 0, 1]) / 1e3, '{:.0f}')} "
              f"| {each(np.linalg.det(F), '{:.3f}')} | {each(np.linalg.det(Fn), '{:.3f}')} |")


def weak_ip(d):
    """The index of the (first) weakened RVE's IP."""
    return int(weak_ips(d)[0])


def ip_map(fig, ax, x, values, weak, title, cmap, weak_marker):
    """One panel: @p values at the IPs @p x (element centres, m) over the specimen, the weak IP marked."""
    sc = ax.scatter(1e3 * x[:, 0], 1e3 * x[:, 1], c=values, s=9600 / len(x), marker="s", cmap=cmap)
    ax.plot(1e3 * x[weak, 0], 1e3 * x[weak, 1], weak_marker)
    ax.set_title(title, fontsize=8)
    ax.set_aspect("equal")
    ax.set_xlim(0, 118)
    ax.set_ylim(0, 50.6)
    fig.colorbar(sc, ax=ax, shrink=0.8)


def plot_rotation(cases, path):
    """The mean particle rotation at the end at each IP, one panel per case."""
    if not cases:
        return
    fig, axes = plt.subplots(len(cases), 1, figsize=(7, 2.2 * len(cases)), squeeze=False)
    for ax, (k, d) in zip(axes[:, 0], cases.items()):
        ip_map(fig, ax, d["ip_position"], d["mean_rotation"][-1], weak_ip(d),
               f"{k}: mean particle rotation at the end (rad; x: the weak RVE)", "magma", "cx")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def row_means(x, gamma):
    """(y of each row of IPs, the mean of @p gamma over the row): a structured mesh's profile across
    a band along x."""
    y, row = np.unique(np.round(x[:, 1], 6), return_inverse=True)
    return y, np.bincount(row, weights=gamma) / np.bincount(row)


def plot_profiles(results, cases, path):
    """Two panels, the elements' own F and the averaged F (what the RVEs saw): the row means of the
    shear strain increment over the last BAND_ROWS rows against y, one line per case."""
    if not cases:
        return
    fig, axes = plt.subplots(1, 2, figsize=(9, 3.6), sharey=True)
    for ax, field, title in zip(axes, ("F", "F_nonlocal"), ("the elements' F", "the averaged F (what the RVEs saw)")):
        for k in cases:
            x, gamma, _, _, _ = inplane_band(os.path.join(results, CASES[k], "out", "history.h5"), BAND_ROWS,
                                             ALONG_X, field)
            y, g = row_means(x, gamma)
            ax.plot(g, 1e3 * y, "o-", ms=3, label=k)
        ax.set_title(f"{title}, last {BAND_ROWS // 2} % of shear", fontsize=8)
        ax.set_xlabel("row mean of the shear strain increment")
    axes[0].set_ylabel("y (mm)")
    axes[0].legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def profile(results, k, field, end=-1, rows=BAND_ROWS):
    """(width above half its peak, y of the peak) in m of case @p k's row-mean profile of the shear
    strain increment over the @p rows rows up to row index @p end (the last by default), of
    @p field (F: the elements', F_nonlocal: the averaged F)."""
    x, gamma, _, _, _ = inplane_band(os.path.join(results, CASES[k], "out", "history.h5"), rows,
                                     ALONG_X, field, end)
    y, means = row_means(x, gamma)
    return bw.half_maximum_width(y, means), y[int(np.argmax(means))]


def print_profile_widths(results, cases):
    """The band as its row means across y (the profiles of problem3_profiles.png): the width above half
    the peak row mean, of the elements' F and of the averaged F. Chosen in session 39 after the
    finder (band_width.py) read 2 mm on 12x20: its bins, 1 degree off x and half a row high, held
    alternately more and fewer band IPs, so its half maximum was crossed one bin from the peak."""
    if not cases:
        return
    print(f"\n## the band's profile across y (row means of the shear strain increment of the last "
          f"{BAND_ROWS} rows): width above half its peak")
    print("| case | elements' F: width (mm) | at y (mm) | averaged F: width (mm) | at y (mm) |")
    print("|---|---|---|---|---|")
    for k in cases:
        cells = [f"{1e3 * v:.1f}" for field in ("F", "F_nonlocal") for v in profile(results, k, field)]
        print(f"| {k} | " + " | ".join(cells) + " |")


def largest_difference(d, base):
    """(difference of tau/p from run @p base's at the row where it is largest, that row's shear strain),
    over the rows both runs have."""
    (g, tp), (_, tp_base) = curve(d), curve(base)
    n = min(len(tp), len(tp_base))
    worst = int(np.argmax(np.abs(tp[:n] - tp_base[:n])))
    return tp[worst] - tp_base[worst], g[worst]


def print_convergence(results, done):
    """The banded answer at smaller macro steps and at half the rate against the reference
    (CONVERGED[0]; and FINE_STEP): tau/p of the mean stress at every row, the weak RVEs' pressure at
    the end, the row-mean profile and the IPs shearing backwards. Rows are equal fractions of the
    shear, so the half-rate run's rows are at the reference's strains."""
    ref, *variants = *CONVERGED, FINE_STEP
    if ref not in done or not any(k in done for k in variants):
        return

    def at_row(tp, row):
        return f"{tp[row]:.3f}" if row < len(tp) else "-"

    print("\n## converged? the reference (default macro step, 4 /s) at smaller macro steps and at half the rate")
    print("| case | largest difference of tau/p from the reference over the rows (at shear) | tau/p at 4 / 8 % "
          "| weak RVEs' p at the end (kPa) | profile width (mm): elements' / averaged F | its peak at y (mm) "
          f"| IPs below {BACKWARDS} | wall (s) |")
    print("|---|---|---|---|---|---|---|---|")
    for k in (ref, *variants):
        if k not in done:
            continue
        d = done[k]
        _, tp = curve(d)
        diff, at = largest_difference(d, done[ref])
        p = weak_stress(d)[1][-1]
        (w, y), (w_seen, y_seen) = (profile(results, k, f) for f in ("F", "F_nonlocal"))
        gamma = shear_increment(d["F"], len(d["step"]))
        wall = float(open(os.path.join(results, CASES[k], "wall_s")).read())
        print(f"| {k} | {diff:+.4f} ({100 * at:.1f} %) | {at_row(tp, 8)} / {at_row(tp, 16)} "
              f"| {', '.join(f'{v / 1e3:.0f}' for v in p)} | {1e3 * w:.1f} / {1e3 * w_seen:.1f} "
              f"| {1e3 * y:.1f} / {1e3 * y_seen:.1f} | {int((gamma < BACKWARDS).sum())} of {len(gamma)} | {wall:.0f} |")


def ensemble_runs(done):
    """{"at STEP": the finished runs}: each of ENSEMBLES with its unperturbed run and at least one
    perturbed one."""
    ensembles = {}
    for step, (base, perturbed) in ENSEMBLES.items():
        members = [k for k in (base, *perturbed) if k in done]
        if base in done and len(members) >= 2:
            ensembles[f"at {step}"] = members
    return ensembles


def print_scatter(results, done, ensembles, groups):
    """The band's width at one macro step and rate: each of @p ensembles (ensemble_runs) against its
    unperturbed run; the end widths' mean and scatter of every one of @p groups (the ensembles and
    the step series), each smaller step's mean against the next larger one's (and, with three or
    more steps, the smallest's against the largest's; the fit against the step and the permutation
    test): the means' difference, and the largest difference of a run's tau/p from the larger step's
    unperturbed run and of the two ensembles' mean tau/p."""
    if not ensembles:
        return
    print("\n## the width at one step: a run and its runs with the top's pressure 1-4 ppm higher")
    print("| case | largest difference of tau/p from the unperturbed run over the rows (at shear) "
          "| largest difference of an IP's stress from the unperturbed run's at the end, over p "
          "| profile width (mm): elements' / averaged F | its peak at y (mm) | wall (s) |")
    print("|---|---|---|---|---|---|")
    for members in ensembles.values():
        base = done[members[0]]
        s_base = base["sigma"][-1]
        p_base = -(s_base[:, 0] + s_base[:, 4] + s_base[:, 8]).mean() / 3
        for k in members:
            d = done[k]
            diff, at = largest_difference(d, base)
            ds = (np.linalg.norm(d["sigma"][-1] - s_base, axis=1).max() / p_base
                  if len(d["step"]) == len(base["step"]) else np.nan)
            (w, y), (w_seen, y_seen) = (profile(results, k, f) for f in ("F", "F_nonlocal"))
            wall = float(open(os.path.join(results, CASES[k], "wall_s")).read())
            print(f"| {k} | {diff:+.4f} ({100 * at:.1f} %) | {100 * ds:.1f} % "
                  f"| {1e3 * w:.1f} / {1e3 * w_seen:.1f} | {1e3 * y:.1f} / {1e3 * y_seen:.1f} | {wall:.0f} |")
    labels = list(ensembles)
    # each step against the next larger one, and the smallest against the largest
    pairs = list(zip(labels, labels[1:])) + ([(labels[0], labels[-1])] if len(labels) >= 3 else [])
    # the last BAND_ROWS rows (the measure of every table) and the last 2 BAND_ROWS, from about the
    # peak of tau/p (4-5 %): a longer window averages the band's wandering along the run
    for rows in (BAND_ROWS, 2 * BAND_ROWS):
        print(f"\nend widths over the last {rows} rows ({100 * SHEAR * rows / LOAD_STEPS:g} % of shear), "
              "row-mean profile above half its peak:")
        stats = {}
        for label, cases in groups.items():
            w = 1e3 * np.array([[profile(results, k, f, -1, rows)[0] for f in ("F", "F_nonlocal")] for k in cases])
            stats[label] = w
            print(f"- {label}, {len(cases)} runs: elements' F {w[:, 0].min():.1f}-{w[:, 0].max():.1f} mm, span "
                  f"{np.ptp(w[:, 0]):.1f}, mean {w[:, 0].mean():.1f}, standard deviation {w[:, 0].std(ddof=1):.1f}; "
                  f"averaged F {w[:, 1].min():.1f}-{w[:, 1].max():.1f} mm, span {np.ptp(w[:, 1]):.1f}, "
                  f"mean {w[:, 1].mean():.1f}, standard deviation {w[:, 1].std(ddof=1):.1f}")
        for la, lb in pairs:
            dm, se = mean_difference(stats[la], stats[lb])
            print(f"- mean {lb} minus mean {la}: {dm[0]:+.1f} mm (elements' F), "
                  f"{dm[1]:+.1f} mm (averaged F); standard error of the difference {se[0]:.1f} / {se[1]:.1f} mm")
        if len(labels) >= 3:
            print_step_fit({label: stats[label] for label in labels})
            print_step_permutation({label: stats[label] for label in labels})
    if len(labels) > 1:
        print("\ntau/p of each smaller step against the next larger one:")
    for la, lb in zip(labels, labels[1:]):
        base = done[ensembles[la][0]]
        diff, at = max((largest_difference(done[k], base) for k in ensembles[lb]), key=lambda r: abs(r[0]))
        curves = {label: [curve(done[k])[1] for k in ensembles[label]] for label in (la, lb)}
        n = min(len(c) for group in curves.values() for c in group)
        mean_a, mean_b = (np.mean([c[:n] for c in curves[label]], axis=0) for label in (la, lb))
        print(f"- {lb} against {la}: the largest difference of a run's from the unperturbed run {la} "
              f"{diff:+.4f} (at {100 * at:.1f} %); the ensembles' mean tau/p within "
              f"{np.abs(mean_b - mean_a).max():.4f} at every row")


def mean_difference(a, b):
    """(mean of @p b minus mean of @p a, the standard error of that difference), per column of the
    ensembles' widths @p a, @p b [runs, (elements' F, averaged F)]."""
    se = np.sqrt(a.var(axis=0, ddof=1) / len(a) + b.var(axis=0, ddof=1) / len(b))
    return b.mean(axis=0) - a.mean(axis=0), se


def print_step_fit(stats):
    """The ensembles' mean widths against the macro step, w = w0 + k dt (@p stats: {"at STEP us":
    widths [runs, (elements' F, averaged F)] in mm}; linear_fit): w0 is the width extrapolated to
    dt = 0."""
    dt = np.array([float(label.split()[1]) for label in stats])
    for name, (w0, k, chi2) in linear_fit(dt, stats.values()):
        print(f"- {name}: fit of the means against the step, w0 = {w0[0]:.1f} +- {w0[1]:.1f} mm "
              f"at dt = 0, k = {k[0]:+.1f} +- {k[1]:.1f} mm/us; chi^2 {chi2:.1f} on {len(dt) - 2} "
              "degree(s) of freedom")


def linear_fit(x, widths):
    """[(field, ((a, its standard error), (b, its standard error), chi^2))] of the ensembles' mean
    widths against @p x, w = a + b x, fitted by least squares weighted with the means' standard
    errors (@p widths: per ensemble an array [runs, (elements' F, averaged F)] in mm); chi^2 against
    its len(x) - 2 degrees of freedom says whether the means are linear in x."""
    fits = []
    for col, name in enumerate(("elements' F", "averaged F")):
        mean = np.array([w[:, col].mean() for w in widths])
        se = np.array([w[:, col].std(ddof=1) / np.sqrt(len(w)) for w in widths])
        X = np.column_stack([np.ones_like(x), x]) / se[:, None]
        cov = np.linalg.inv(X.T @ X)
        a, b = cov @ X.T @ (mean / se)
        chi2 = float(np.sum(((mean - a - b * x) / se) ** 2))
        fits.append((name, ((a, np.sqrt(cov[0, 0])), (b, np.sqrt(cov[1, 1])), chi2)))
    return fits


def between_steps(groups):
    """The between-group sum of squares of @p groups (arrays of widths), the one-way layout's
    statistic for a fixed pooled set (the F ratio grows with it)."""
    grand = np.concatenate(groups).mean()
    return sum(len(g) * (g.mean() - grand) ** 2 for g in groups)


def print_step_permutation(stats, what="the step", groups="steps"):
    """Does @p what (the step) matter at all? The exact permutation test of the one-way layout: every
    split of the pooled runs into groups of the ensembles' sizes, and the fraction whose between-group
    sum of squares reaches the measured one (the p value: how often @p groups that did not matter
    would look as different by chance). Added in session 43 after three of the four 0.2 us runs were
    seen, beside the fit (print_step_fit), which assumes the width moves monotonically."""
    sizes = [len(w) for w in stats.values()]
    for col, name in enumerate(("elements' F", "averaged F")):
        pooled = np.concatenate([w[:, col] for w in stats.values()])
        measured = between_steps([w[:, col] for w in stats.values()])
        reached = total = 0
        for split in splits(list(range(len(pooled))), sizes):
            total += 1
            reached += between_steps([pooled[list(g)] for g in split]) >= measured * (1 - 1e-12)
        print(f"- {name}: is {what}'s effect more than chance? exact permutation test over the "
              f"{len(sizes)} {groups}: p = {reached / total:.3f} ({reached} of {total} splits as far apart)")


def splits(items, sizes):
    """Every split of @p items into groups of @p sizes, in order (the groups as tuples)."""
    if len(sizes) == 1:
        yield (tuple(items),)
        return
    for first in itertools.combinations(items, sizes[0]):
        rest = [i for i in items if i not in first]
        for tail in splits(rest, sizes[1:]):
            yield (first, *tail)


def print_width_history(results, done, groups, path):
    """The elements' F's profile width of each BAND_ROWS window along every run of @p groups
    (the ensembles and the step series), the span of each group at each window (table), plotted
    into @p path."""
    if not groups:
        return
    cases = list(dict.fromkeys(k for members in groups.values() for k in members))
    ref = CONVERGED[0]
    ends_at = range(BAND_ROWS, len(done[ref]["step"]))
    strains = [100 * SHEAR * (e + 1) / LOAD_STEPS for e in ends_at]
    history = {k: [1e3 * profile(results, k, "F", e)[0] if e < len(done[k]["step"]) else np.nan for e in ends_at]
               for k in cases}
    print(f"\n## the width along the run: the elements' F's row-mean profile over the {BAND_ROWS} rows up to each "
          "row (mm)")
    print("| case | " + " | ".join(f"{v:g} %" for v in strains) + " |")
    print("|---" * (len(ends_at) + 1) + "|")
    for k in cases:
        print(f"| {k} | " + " | ".join(f"{v:.1f}" for v in history[k]) + " |")
    for label, group in groups.items():
        h = np.array([history[k] for k in group])
        print(f"| span, {label} | " + " | ".join(f"{v:.1f}" for v in np.ptp(h, axis=0)) + " |")
    plt.figure(figsize=(6, 4))
    # one colour per step ensemble (its runs dashed), the other single runs in the colours after them
    colour = {k: f"C{i}" for i, (base, perturbed) in enumerate(ENSEMBLES.values()) for k in (base, *perturbed)}
    singles = [k for k in cases if k not in colour]
    colour.update({k: f"C{len(ENSEMBLES) + i}" for i, k in enumerate(singles)})
    for k in cases:
        plt.plot(strains, history[k], "--" if k in PERTURBED else "-o", color=colour[k], ms=3,
                 label=k.replace("R = 10 mm, local elastic 2 MPa, 12x10, ", ""))
    plt.xlabel(f"shear strain at the end of the {BAND_ROWS}-row window (%)")
    plt.ylabel("row-mean profile width, elements' F (mm)")
    plt.legend(fontsize=5)
    plt.tight_layout()
    plt.savefig(path, dpi=120)


def against_r_runs(done, family):
    """{R in mm: the finished runs of @p family's ensemble at R} (a value of R_FAMILIES), for the radii
    whose unperturbed run and at least one perturbed run are finished."""
    runs = {r: [k for k in (base, *perturbed) if k in done] for r, (base, perturbed) in family.items()}
    return {r: members for r, members in runs.items() if family[r][0] in done and len(members) >= 2}


def energy_shares(case_dir):
    """(hourglass share, kinetic share) per row of the run's energy.csv: the hourglass forces' work and
    the kinetic energy over the larger of the internal and external work (fe2dem's
    EnergyBalance::hourglass_share; fe2dem warns above 0.1)."""
    with open(os.path.join(case_dir, "out", "energy.csv")) as f:
        rows = list(csv.DictReader(f))
    work = np.array([max(abs(float(r["internal_work"])), abs(float(r["external_work"]))) for r in rows])
    return (np.array([abs(float(r["hourglass_work"])) for r in rows]) / work,
            np.array([float(r["kinetic_energy"]) for r in rows]) / work)


def rows_departure(d, row):
    """The largest departure of a row of IPs' mean sigma_22 from the applied APPLIED at history.h5's
    row @p row of run @p d, over APPLIED. The rows' sigma_22 must equal the top's stress in
    equilibrium (the sides are free in y), so a large departure says the points' stresses do not
    carry the load: the hourglass forces do."""
    s22 = -d["sigma"].reshape(len(d["step"]), -1, 9)[row, :, 4]
    return np.abs(row_means(d["ip_position"], s22)[1] - APPLIED).max() / APPLIED


def equilibrium(results, k, d):
    """(hourglass share at the end, largest rows_departure over all rows) of case @p k."""
    share = energy_shares(os.path.join(results, CASES[k]))[0][-1]
    return share, max(rows_departure(d, row) for row in range(len(d["step"])))


def print_probes(results):
    """PROBES that exist: per row the hourglass share and the kinetic energy over the
    larger of the internal and external work, and the rows' sigma_22 departure at the last row."""
    probes = {k: c for k, c in PROBES.items() if os.path.exists(os.path.join(results, c, "wall_s"))}
    if not probes:
        return
    print("\n## which ingredient makes the hourglass forces do the work: the R = 20 mm own-volume case over its "
          "first 1 % of shear (two rows)")
    print("| case | hourglass share, row 1 / row 2 | kinetic energy / work, row 1 / row 2 "
          "| rows' sigma_22: largest departure / applied, row 2 | wall (s) |")
    print("|---|---|---|---|---|")
    for k, c in probes.items():
        share, kinetic = energy_shares(os.path.join(results, c))
        departure = rows_departure(read(os.path.join(results, c)), -1)
        wall = float(open(os.path.join(results, c, "wall_s")).read())
        print(f"| {k} | {' / '.join(f'{v:.3f}' for v in share)} | {' / '.join(f'{v:.3f}' for v in kinetic)} "
              f"| {departure:.2f} | {wall:.0f} |")


def print_equilibrium(results, done):
    """Every case's equilibrium (equilibrium()): the hourglass share and the rows' sigma_22."""
    print("\n## equilibrium of the points' stresses: the hourglass work's share of the work at the end "
          "(fe2dem warns above 0.1), and the largest departure of a row's mean sigma_22 from the applied "
          f"{APPLIED / 1e3:.0f} kPa over the run")
    print("| case | hourglass share | rows' sigma_22: largest departure / applied |")
    print("|---|---|---|")
    for k, d in done.items():
        share, rows = equilibrium(results, k, d)
        print(f"| {k} | {share:.3f}{' **(above 0.1)**' if share > 0.1 else ''} | {rows:.2f} |")


def micro_fields(d):
    """{quantity: its value at each IP at the last row of run @p d}: porosity 1 - solid fraction,
    coordination 2C/N, the fraction of sliding contacts and the inner particles' mean rotation (rad;
    NaN for runs made before fe2dem recorded it)."""
    rotation = d["mean_rotation"][-1] if d["mean_rotation"] is not None else np.full(len(d["ip_position"]), np.nan)
    return {"porosity": 1.0 - d["packing_fraction"][-1], "coordination": d["coordination"][-1],
            "sliding fraction": d["sliding_contacts"][-1] / np.maximum(d["contacts"][-1], 1),
            "mean rotation (rad)": rotation}


def print_run_header():
    """The header of print_run_row's table."""
    print("| R (mm) | run | tau/p at 8 % | weak RVEs' p at the end (kPa) | hourglass share | width, last 4 rows (mm): "
          "elements' / averaged F | last 8 rows | peak at y (mm) |")
    print("|---|---|---|---|---|---|---|---|")


def print_run_row(results, k, d, r, run):
    """One row of case @p k (@p d its read()), R = @p r mm, labelled @p run: tau/p at the end, the
    weak RVEs' pressure, the hourglass share (energy_shares()), the end widths over the last BAND_ROWS
    and 2 BAND_ROWS rows (nan: the profile does not fall to half its peak inside the specimen) and
    the profile's peak. Returns the hourglass share."""
    _, tp = curve(d)
    p = weak_stress(d)[1][-1]
    (w4, y), (w4_seen, _) = (profile(results, k, f) for f in ("F", "F_nonlocal"))
    w8, w8_seen = (profile(results, k, f, -1, 2 * BAND_ROWS)[0] for f in ("F", "F_nonlocal"))
    share = energy_shares(os.path.join(results, CASES[k]))[0][-1]
    print(f"| {r:g} | {run} | {tp[-1]:.3f} | {', '.join(f'{v / 1e3:.0f}' for v in p)} | {share:.3f} "
          f"| {1e3 * w4:.1f} / {1e3 * w4_seen:.1f} | {1e3 * w8:.1f} / {1e3 * w8_seen:.1f} | {1e3 * y:.1f} |")
    return share


def print_half_step(results, done):
    """The own-volume runs at 1 us (HALF_STEP), after the 2 us runs at R = 15 and 20 mm were
    hourglass-dominated (run.sh problem3_own_half_step), in print_run_row's table."""
    runs = [(r, k) for r, k in HALF_STEP if k in done]
    if not runs:
        return
    print("\n## the own-volume case at half the default step, 1 us (12x10, seed box, C_e of E = 2 MPa)")
    print_run_header()
    for r, k in runs:
        print_run_row(results, k, done[k], r, k.split(", ")[-1] if "ppm" in k else "unperturbed")


def print_last_check(results, done):
    """The own-volume runs at the default 2 us with the last check's stress, at 4 and 2 /s
    (LAST_CHECK), in print_run_row's table, each radius beside its ensemble at one check per step
    (R_FAMILIES["own volume, one check per step"]): that ensemble's range and mean of tau/p at 8 % and
    of the end width (elements' F) over the last 2 BAND_ROWS rows, what a single run is a draw from."""
    runs = [(r, k, label) for r, k, label in LAST_CHECK if k in done]
    if not runs:
        return
    print("\n## the own-volume case at the default 2 us with the last check's stress (session 45's build), "
          "at 4 and 2 /s, beside the 1 us ensembles (12x10, seed box, C_e of E = 2 MPa)")
    print_run_header()
    for r, k, label in runs:
        print_run_row(results, k, done[k], r, label)
    ensembles = against_r_runs(done, R_FAMILIES["own volume, one check per step"])
    for r in sorted({r for r, _, _ in runs} & ensembles.keys()):
        members = ensembles[r]
        tp = np.array([curve(done[k])[1][-1] for k in members])
        w8 = 1e3 * np.array([profile(results, k, "F", -1, 2 * BAND_ROWS)[0] for k in members])
        print(f"- R = {r:g} mm, the {len(members)} runs at 1 us: tau/p at 8 % {tp.min():.3f}-{tp.max():.3f} "
              f"(mean {tp.mean():.4f}), width over the last {2 * BAND_ROWS} rows (elements' F) "
              f"{w8.min():.1f}-{w8.max():.1f} mm (mean {w8.mean():.1f})")


def print_against_r(results, done, name, family, path):
    """The band's width against R from the ensembles of @p family (R_FAMILIES[@p name];
    against_r_runs): each run's tau/p at 8 %, weak RVEs' pressure, hourglass share (energy_shares())
    and end widths; per R the mean width +- its standard error over
    the last BAND_ROWS and 2 BAND_ROWS rows, width / R, each R against the next smaller, the fit w = a
    + b R and the permutation test; the band's inside against its outside as ensemble means (inside:
    the IPs above half the largest increment, as the band table); @p path: the widths against R and
    the ensembles' mean profiles across y."""
    ensembles = against_r_runs(done, family)
    if len(ensembles) < 2:
        return
    print(f"\n## the width against R: the {FAMILY_STEP.get(name, '2 us')} ensembles (12x10, seed box, {name}, "
          "C_e of E = 2 MPa)")
    print_run_header()
    invalid = set()  # the radii with a run whose hourglass share passed 0.1
    for r, members in ensembles.items():
        for k in members:
            if print_run_row(results, k, done[k], r, k[len(family[r][0]) + 2:] or "unperturbed") > 0.1:
                invalid.add(r)
    radii = np.array(list(ensembles))
    for rows in (BAND_ROWS, 2 * BAND_ROWS):
        stats = {r: 1e3 * np.array([[profile(results, k, f, -1, rows)[0] for f in ("F", "F_nonlocal")]
                                    for k in members]) for r, members in ensembles.items()}
        print(f"\nmean end width over the last {rows} rows ({100 * SHEAR * rows / LOAD_STEPS:g} % of shear) "
              "+- its standard error, row-mean profile above half its peak:")
        print("| R (mm) | runs | elements' F (mm) | width / R | averaged F (mm) | width / R |")
        print("|---|---|---|---|---|---|")
        for r, w in stats.items():
            m, se = w.mean(axis=0), w.std(axis=0, ddof=1) / np.sqrt(len(w))
            print(f"| {r:g} | {len(w)} | {m[0]:.1f} +- {se[0]:.1f} | {m[0] / r:.2f} | {m[1]:.1f} +- {se[1]:.1f} "
                  f"| {m[1] / r:.2f} |")
        for ra, rb in zip(radii, radii[1:]):
            dm, se = mean_difference(stats[ra], stats[rb])
            print(f"- R = {rb:g} minus R = {ra:g} mm: {dm[0]:+.1f} +- {se[0]:.1f} mm (elements' F), "
                  f"{dm[1]:+.1f} +- {se[1]:.1f} mm (averaged F)")
        if len(radii) >= 3:
            for field, (a, b, chi2) in linear_fit(radii, stats.values()):
                print(f"- {field}: fit of the means against R, w = {a[0]:.1f} +- {a[1]:.1f} mm + "
                      f"({b[0]:.2f} +- {b[1]:.2f}) R; chi^2 {chi2:.1f} on {len(radii) - 2} degree(s) of freedom")
        print_step_permutation(stats, "R", "radii")
        if rows == 2 * BAND_ROWS:
            widths = stats
    print(f"\ninside against outside the band at the end (increment of the last {BAND_ROWS} rows; ensemble means "
          "+- standard error of the per-run means):")
    print("| R (mm) | runs | IPs inside | porosity in / out | coordination in / out | sliding fraction in / out "
          "| mean rotation (rad) in / out |")
    print("|---|---|---|---|---|---|---|")
    for r, members in ensembles.items():
        per_run, n_in = [], []
        for k in members:
            _, gamma, _, _, _ = inplane_band(os.path.join(results, CASES[k], "out", "history.h5"), BAND_ROWS)
            inside = gamma > 0.5 * gamma.max()
            n_in.append(int(inside.sum()))
            per_run.append([(v[inside].mean(), v[~inside].mean()) for v in micro_fields(done[k]).values()])
        cells = []
        for v in np.array(per_run).transpose(1, 0, 2):  # per quantity [runs, (in, out)]
            if np.isnan(v).any():
                cells.append("-")
                continue
            m, se = v.mean(axis=0), v.std(axis=0, ddof=1) / np.sqrt(len(v))
            cells.append(f"{m[0]:.4f} +- {se[0]:.4f} / {m[1]:.4f} +- {se[1]:.4f}")
        print(f"| {r:g} | {len(members)} | {min(n_in)}-{max(n_in)} of {len(gamma)} | " + " | ".join(cells) + " |")
    plot_against_r(results, ensembles, widths, invalid, f"{name}, {FAMILY_STEP.get(name, '2 us')}", path)


def plot_against_r(results, ensembles, widths, invalid, title, path):
    """Two panels into @p path: each run's end width over the last 2 BAND_ROWS rows and the ensemble
    means +- standard error against R (@p widths: {R: [runs, (elements' F, averaged F)]}, mm; the
    radii in @p invalid, whose runs' hourglass share passed 0.1, hollow), the line width = R and 2 R
    beside them; and each ensemble's mean row profile of the elements' F."""
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(9, 3.8))
    for col, (name, marker) in enumerate((("elements' F", "o"), ("averaged F", "s"))):
        for i, (r, w) in enumerate(widths.items()):
            shift = 0.3 * (col - 0.5)
            face = "none" if r in invalid else f"C{col}"
            ax.plot(np.full(len(w), r + shift), w[:, col], marker, color=f"C{col}", mfc=face, ms=3, alpha=0.5)
            ax.errorbar(r + shift, w[:, col].mean(), w[:, col].std(ddof=1) / np.sqrt(len(w)), fmt=marker,
                        color=f"C{col}", mfc=face, ms=7, capsize=3,
                        label=f"{name}, mean +- s.e." if i == 0 else None)
    ax.set_title(title + (f"; hollow: hourglass share > 0.1 at R = {', '.join(f'{r:g}' for r in sorted(invalid))} mm, "
                          "not equilibria" if invalid else ""), fontsize=7)
    r = np.array([0, max(widths) + 2])
    ax.plot(r, r, "k:", lw=0.8, label="width = R")
    ax.plot(r, 2 * r, "k--", lw=0.8, label="width = 2 R")
    ax.set_xlabel("R (mm)")
    ax.set_ylabel(f"band width, last {100 * SHEAR * 2 * BAND_ROWS / LOAD_STEPS:g} % of shear (mm)")
    ax.legend(fontsize=6)
    for r, members in ensembles.items():
        profiles = []
        for k in members:
            x, gamma, _, _, _ = inplane_band(os.path.join(results, CASES[k], "out", "history.h5"), 2 * BAND_ROWS,
                                             ALONG_X, "F")
            y, g = row_means(x, gamma)
            profiles.append(g)
        bx.plot(np.mean(profiles, axis=0), 1e3 * y, "o-", ms=3, label=f"R = {r:g} mm ({len(members)} runs)")
    bx.set_xlabel(f"row-mean shear increment, last {100 * SHEAR * 2 * BAND_ROWS / LOAD_STEPS:g} % (ensemble mean)")
    bx.set_ylabel("y (mm)")
    bx.legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def print_softening(results, done):
    """The band's softening modulus in shear of the runs without C_e (band_tools.band_softening, tau
    = |sigma_12| of the mean stress) against C_e's shear modulus of the local elastic runs."""
    print("\n## the band's softening modulus in shear, H_s, against C_e's shear modulus")
    print("| case | peak at (shear) | tau peak -> end (kPa) | gamma in the band | H_s (MPa) |")
    print("|---|---|---|---|---|")
    moduli = []
    for k in ("local", "R = 15 mm", "local, 12x10"):
        if k not in done:
            continue
        tau = np.abs(done[k]["sigma"].mean(axis=1)[:, 1])
        peak, gamma, h_s = band_softening(os.path.join(results, CASES[k], "out", "history.h5"), tau)
        moduli.append(h_s)
        print(f"| {k} | {100 * done[k]['gamma_macro'][peak]:.1f} % | {tau[peak] / 1e3:.0f} -> {tau[-1] / 1e3:.0f} | "
              f"{gamma:.3f} | {h_s / 1e6:.3f} |")
    print_ce_ratios((5.84e8, 5e7, 2e6, 5e5), NU_E, moduli)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    results = sys.argv[1]
    done = {k: read(os.path.join(results, c)) for k, c in CASES.items()
            if os.path.exists(os.path.join(results, c, "wall_s"))}
    if not done:
        sys.exit("problem3.py: no finished run in " + results)

    print("## tau/p of the mean stress, every 1 % of shear")
    print("| shear strain | " + " | ".join(done) + " |")
    print("|---" * (len(done) + 1) + "|")
    curves = {k: curve(d) for k, d in done.items()}
    g0 = next(iter(curves.values()))[0]
    for k in range(2, len(g0), 2):
        print(f"| {100 * g0[k]:.0f} % | " + " | ".join(f"{c[1][k]:.3f}" if k < len(c[1]) else "-"
                                                   for c in curves.values()) + " |")

    print_softening(results, done)

    print(f"\n## the band (increment over the last {BAND_ROWS} rows), and inside against outside at the end")
    print("| case | band width (mm) | angle (deg from x) | band middle y (mm) | along x: width (mm) | angle "
          "| weak IP in the band | porosity in / out "
          "| coordination in / out | sliding fraction in / out | mean rotation (rad) in / out |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    fig, axes = plt.subplots(len(done), 1, figsize=(7, 2.2 * len(done)), squeeze=False)
    rows, widths = [], {}
    for ax, (k, d) in zip(axes[:, 0], done.items()):
        history, weak = os.path.join(results, CASES[k], "out", "history.h5"), weak_ip(d)
        x, gamma, width, angle, middle = inplane_band(history, BAND_ROWS)
        _, _, width_x, angle_x, _ = inplane_band(history, BAND_ROWS, ALONG_X)
        _, _, width_seen, _, _ = inplane_band(history, BAND_ROWS, ALONG_X, "F_nonlocal")
        widths[k] = (width_x, width_seen)
        inside = gamma > 0.5 * gamma.max()
        porosity, coordination, sliding, rotation = micro_fields(d).values()

        def in_out(v):
            return "-" if np.isnan(v).all() else f"{v[inside].mean():.3f} / {v[~inside].mean():.3f}"

        print(f"| {k} | {1e3 * width:.1f} | {angle:.0f} | {1e3 * middle:.1f} | {1e3 * width_x:.1f} | {angle_x:.0f} | "
              f"{'yes' if inside[weak] else 'no'} | "
              f"{in_out(porosity)} | {in_out(coordination)} | {in_out(sliding)} | {in_out(rotation)} |")
        rows += [[k, f"{x[i, 0]:.5f}", f"{x[i, 1]:.5f}", int(inside[i]), f"{porosity[i]:.4f}",
                  f"{coordination[i]:.3f}", f"{sliding[i]:.3f}", f"{rotation[i]:.4f}"] for i in range(len(x))]
        ip_map(fig, ax, x, gamma, weak, f"{k}: band along x {1e3 * width_x:.1f} mm wide (x: the weak RVE)",
               "viridis", "rx")
    fig.tight_layout()
    fig.savefig(os.path.join(results, "problem3_bands.png"), dpi=110)
    plot_rotation({k: d for k, d in done.items() if d["mean_rotation"] is not None},
                  os.path.join(results, "problem3_rotation.png"))
    plot_profiles(results, [k for k in FIXED_R if k in done], os.path.join(results, "problem3_profiles.png"))
    plot_profiles(results, [k for k in AGAINST_R if k in done], os.path.join(results, "problem3_profiles_r.png"))
    print_profile_widths(results, [k for k in PROFILE_CASES if k in done])
    print_convergence(results, done)
    ensembles = ensemble_runs(done)
    groups = dict(ensembles)
    if ensembles:
        groups["the step series at 4 /s (2, 1, 0.5 us, 1 us with checks of 5)"] = [k for k in CONVERGED[:-1] if k in done]
    print_scatter(results, done, ensembles, groups)
    print_width_history(results, done, groups, os.path.join(results, "problem3_width_history.png"))
    for name, family in R_FAMILIES.items():
        png = "problem3_against_r.png" if name == "own volume" else f"problem3_against_r_{name.split()[0]}.png"
        print_against_r(results, done, name, family, os.path.join(results, png))
    print_half_step(results, done)
    print_last_check(results, done)
    print_equilibrium(results, done)
    print_probes(results)
    with open(os.path.join(results, "problem3.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case", "x", "y", "in_band", "porosity", "coordination", "sliding_fraction", "mean_rotation"])
        w.writerows(rows)

    radii = [(r, h, k) for r, h, k in RADII if k in widths]
    if radii:
        print("\n## band width (along x) against R and the element (local elastic: C_e of the E named)")
        print("| case | R (mm) | element height (mm) | band width (mm) | width / R | width / element "
              "| from the averaged F (mm) | width / R |")
        print("|---|---|---|---|---|---|---|---|")
        for r, h, k in radii:
            w, w_seen = (1e3 * v for v in widths[k])
            per_r = (lambda v: f"{v / r:.2f}") if r else (lambda v: "-")
            print(f"| {k} | {r:g} | {h:g} | {w:.1f} | {per_r(w)} | {w / h:.2f} | {w_seen:.1f} | {per_r(w_seen)} |")

    # the soft mode of the total-strain average (user guide, 'Nonlocal operator'): the elements' own
    # signed shear increment, the weak one against the rest
    # and off the band (the IPs more than OFF_BAND from the weak IP's row), the element-scale scatter
    # of the increment and of its part the RVEs do not see (own minus averaged)
    print(f"\n## the elements' signed shear increment dF12 + dF21 over the last {BAND_ROWS} rows")
    print("| case | weak IP | mean | largest | smallest | IPs shearing backwards "
          "| std off the band | own - averaged: std off the band |")
    print("|---|---|---|---|---|---|---|---|")
    for k, d in done.items():
        g, g_seen = (shear_increment(d[f], len(d["step"])) for f in ("F", "F_nonlocal"))
        weak = weak_ip(d)
        off = np.abs(d["ip_position"][:, 1] - d["ip_position"][weak, 1]) > OFF_BAND
        print(f"| {k} | {g[weak]:.4f} | {g.mean():.4f} | {g.max():.4f} | {g.min():.4f} "
              f"| {int((g < 0).sum())} of {len(g)} | {g[off].std():.4f} | {(g - g_seen)[off].std():.4f} |")

    print_seed(results, done)

    print("\n## cost (on the 2-core VM, walls shared with other runs)")
    print("| case | ranks | wall (s) | RVEs | DEM steps (all RVEs) |")
    print("|---|---|---|---|---|")
    for k, c in CASES.items():
        if k in done:
            with open(os.path.join(results, c, "out", "summary.csv")) as f:
                dem = sum(int(r["dem_steps"]) for r in csv.DictReader(f))
            wall = float(open(os.path.join(results, c, "wall_s")).read())
            ranks = re.search(r"RVEs on (\d+) rank", open(os.path.join(results, c, "log")).read()).group(1)
            print(f"| {k} | {ranks} | {wall:.0f} | {len(done[k]['ip_position'])} | {dem:.3g} |")

    plot_curves(curves, "shear strain (%)", "tau/p of the mean stress", os.path.join(results, "problem3_curves.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
