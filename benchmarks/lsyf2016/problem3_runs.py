"""One run of [LSYF] problem 3 as problem3.py's tables read it: its history.h5 (read), the curve
of tau/p, the weak RVEs, the band's row-mean profile, the micro-structure at the IPs and the
equilibrium checks (the hourglass share, the rows' sigma_22), and the table row that the
ensemble tables share (print_run_row)."""
import csv
import os
import re

import h5py
import numpy as np

from band_tools import bw, inplane_band, row_means
from problem3_cases import ALONG_X, APPLIED, BAND_ROWS, CASES, LOAD_STEPS, SHEAR


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


def weak_ip(d):
    """The index of the (first) weakened RVE's IP."""
    return int(weak_ips(d)[0])


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


def profile(results, k, field, end=-1, rows=BAND_ROWS):
    """(width above half its peak, y of the peak) in m of case @p k's row-mean profile of the shear
    strain increment over the @p rows rows up to row index @p end (the last by default), of
    @p field (F: the elements', F_nonlocal: the averaged F)."""
    x, gamma, _, _, _ = inplane_band(os.path.join(results, CASES[k], "out", "history.h5"), rows,
                                     ALONG_X, field, end)
    y, means = row_means(x, gamma)
    return bw.half_maximum_width(y, means), y[int(np.argmax(means))]


def largest_difference(d, base):
    """(difference of tau/p from run @p base's at the row where it is largest, that row's shear strain),
    over the rows both runs have."""
    (g, tp), (_, tp_base) = curve(d), curve(base)
    n = min(len(tp), len(tp_base))
    worst = int(np.argmax(np.abs(tp[:n] - tp_base[:n])))
    return tp[worst] - tp_base[worst], g[worst]


def micro_fields(d):
    """{quantity: its value at each IP at the last row of run @p d}: porosity 1 - solid fraction,
    coordination 2C/N, the fraction of sliding contacts and the inner particles' mean rotation (rad;
    NaN for runs made before fe2dem recorded it)."""
    rotation = d["mean_rotation"][-1] if d["mean_rotation"] is not None else np.full(len(d["ip_position"]), np.nan)
    return {"porosity": 1.0 - d["packing_fraction"][-1], "coordination": d["coordination"][-1],
            "sliding fraction": d["sliding_contacts"][-1] / np.maximum(d["contacts"][-1], 1),
            "mean rotation (rad)": rotation}


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
