#!/usr/bin/python3
"""The macro step against the RVE servo's checks in explicit dynamics (session 33): one element,
one RVE, loaded at 4 /s with the macro step and the RVE's 'Check interval' varied (run.sh
macro_step). Reads RESULTS/step_*/ and prints, per case, the stress ratio of every row and, from
the fifth row on (past the peak), its mean, standard deviation and largest jump between rows; then
problem 4's element at the rates of run.sh problem4_rates, and problem 1's shear element (lsyf_300)
at three macro steps against the single RVE driven continuously (fe2dem-rve), where they exist.

  step_p3_*   problem3.prm as one 118 x 50.6 mm element without the weak RVE: tau/p of sigma
              (simple shear to 8 % under 416 kPa)
  step_p4_*   problem4_element.prm (5 mm, plane strain, 416 kPa): the platen's stress ratio
              (summary.csv's stress_ratio_mean), to 8 % axial strain

Usage: macro_step.py RESULTS   (Debian's python3 with numpy, h5py)
"""
import csv
import glob
import os
import re
import sys

import h5py
import numpy as np


def dem_steps_per_macro_step(case_dir):
    """The DEM steps of one macro step, as fe2dem's log states it."""
    with open(os.path.join(case_dir, "log")) as f:
        return int(re.search(r"\((\d+) DEM steps of", f.read()).group(1))


def ratio(case_dir):
    """The stress ratio per row: tau/p of sigma for problem 3's element, the stress ratio of the
    summary for problem 4's."""
    if "step_p3_" in case_dir:
        with h5py.File(os.path.join(case_dir, "out", "history.h5"), "r") as h:
            s = h["sigma"][()].mean(axis=1)
        return np.abs(s[:, 1]) / (-(s[:, 0] + s[:, 4] + s[:, 8]) / 3.0)
    with open(os.path.join(case_dir, "out", "summary.csv")) as f:
        return np.array([float(r["stress_ratio_mean"]) for r in csv.DictReader(f)])


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    cases = sorted(d for d in glob.glob(os.path.join(sys.argv[1], "step_p*"))
                   if os.path.exists(os.path.join(d, "wall_s")))
    if not cases:
        sys.exit("macro_step.py: no finished run in " + sys.argv[1])
    print("| case | macro step (DEM steps) | checks per macro step | rows 1-16 | mean from row 5 | std | "
          "largest jump |")
    print("|---|---|---|---|---|---|---|")
    for d in cases:
        text = open(os.path.join(d, "macro.prm")).read()
        dem = dem_steps_per_macro_step(d)
        ci = int(re.search(r"set Check interval\s*=\s*(\d+)", text).group(1))
        r = ratio(d)
        late = r[4:]
        print(f"| {os.path.basename(d)} | {dem} | {dem // ci} | {' '.join(f'{v:.3f}' for v in r)} | "
              f"{late.mean():.3f} | {late.std():.3f} | {np.abs(np.diff(late)).max():.3f} |")
    print_rates(sys.argv[1])
    print_shear(sys.argv[1])
    return 0


def print_shear(results):
    """Problem 1's shear element (lsyf_300, 4 /s) at each macro step against the single RVE driven
    continuously on the same F (step_shear_rve/rve.csv, rows after the 3 isotropic ones)."""
    reference = os.path.join(results, "step_shear_rve", "rve.csv")
    runs = sorted(glob.glob(os.path.join(results, "step_shear_*us", "wall_s")))
    if not os.path.exists(reference) or not runs:
        return
    with open(reference) as f:
        ref = np.array([float(r["sigma12"]) for r in list(csv.DictReader(f))[3:]])
    print("\n| shear element | macro step (DEM steps) | sigma12 against the single RVE: rows 1-16 (%) | mean | "
          "largest |")
    print("|---|---|---|---|---|")
    for w in runs:
        d = os.path.dirname(w)
        dem = dem_steps_per_macro_step(d)
        with h5py.File(os.path.join(d, "out", "history.h5"), "r") as h:
            diff = 100 * (h["sigma"][:, 0, 1] / ref - 1)
        print(f"| {os.path.basename(d)} | {dem} | {' '.join(f'{v:+.1f}' for v in diff)} | {diff.mean():+.1f} | "
              f"{diff[np.argmax(np.abs(diff))]:+.1f} |")


def print_rates(results):
    """Problem 4's element at the rates of run.sh problem4_rates (rows every 0.5 %, to 8 %)."""
    runs = sorted(glob.glob(os.path.join(results, "problem4_element_rate*", "wall_s")),
                  key=lambda w: -float(w.split("rate")[-1].split(os.sep)[0]))
    if not runs:
        return
    print("\n| rate (1/s) | macro step (DEM steps) | peak stress ratio | mean 2-8 % | std 2-8 % | largest jump | "
          "wall (s, 1 rank) |")
    print("|---|---|---|---|---|---|---|")
    for w in runs:
        d = os.path.dirname(w)
        dem = dem_steps_per_macro_step(d)
        r = ratio(d)
        late = r[3:]  # from 2 %
        print(f"| {d.split('rate')[-1]} | {dem} | {r.max():.3f} | {late.mean():.3f} | {late.std():.3f} | "
              f"{np.abs(np.diff(late)).max():.3f} | {float(open(w).read()):.0f} |")


if __name__ == "__main__":
    sys.exit(main())
