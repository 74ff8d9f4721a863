#!/usr/bin/python3
"""How fast the band's RVEs are driven under slow loading (issue 37, session 55).

Slow loading holds the nominal strain rate of the specimen, not of its
RVEs: after the peak the shortening goes into the band, so a band one
element wide (local) is driven faster on every finer mesh, while a band of
the operator's width (R = 5 mm) keeps its rate. This prints, for every
slow-loading run of slow_loading_study.py's cases that runs/ holds, the
band rate: in each load step of stage 2 the largest norm over the IPs of
the rate of deformation, |sym(ΔF F⁻¹)| / Δt with Δt = 0.125 % / rate the
time of one load step (history.h5's F: the macro F; for the nonlocal runs
also F_nonlocal, what their RVEs saw), its median over the steps after
6 % and its largest; the largest principal stretch of any IP in any
step (the lbs_ref band RVEs that failed were at 1.2-1.4); and the
inertial number of that median,
rate × d_mean × √(ρ/p) (d_mean 0.37 mm, ρ 2000 kg/m², p 150 kPa: the
user guide's quasi-static bound is about 1e-4).

Usage: band_rate.py   (Debian's python3 with numpy and h5py)

Keeps results/band_rate.csv (updated from runs/CASE/history.h5, so that the
table regenerates without runs/).
"""
import csv
import os
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import analyse  # noqa: E402
import ensemble_study as es  # noqa: E402  (names and members)
import load_step_study as ls  # noqa: E402  (the two families)
import slow_loading_study as sl  # noqa: E402  (the rates)

TABLE = os.path.join(analyse.results, "band_rate.csv")
FIELDS = ["case", "dataset", "steps", "last_axial_strain", "median_after_6pc", "largest", "largest_stretch"]
AFTER = 0.06        # the band rate's median is over the steps after this axial strain
ROW = 0.00125       # axial strain of one load step of stage 2 (run.sh _quarter)
D_MEAN, RHO, P = 3.67e-4, 2000.0, 1.5e5  # lbs_ref: mean diameter [m], areal density [kg/m^2], pressure [N/m]


def read_history(path):
    """(axial strain of each step, {dataset: F, steps x IPs x 2 x 2}) of history.h5 @p path, for the
    datasets F and, in a nonlocal run, F_nonlocal."""
    with h5py.File(path, "r") as f:
        return f["axial_strain"][:], {d: f[d][:].reshape(f[d].shape[0], -1, 2, 2)
                                      for d in ("F", "F_nonlocal") if d in f}


def largest_stretch(F):
    """The largest principal stretch of @p F (steps x IPs x 2 x 2) over the IPs and steps: how far
    the most deformed RVE was taken."""
    return float(np.sqrt(np.linalg.eigvalsh(np.swapaxes(F, -1, -2) @ F)[..., -1].max()))


def band_rates(F, rate):
    """The largest rate of deformation [1/s] over the IPs in each step after the first of @p F
    (steps x IPs x 2 x 2), the steps ROW of axial strain apart at nominal @p rate."""
    dF = np.diff(F, axis=0) @ np.linalg.inv(F[:-1])
    D = 0.5 * (dF + np.swapaxes(dF, -1, -2))
    return np.linalg.norm(D, axis=(-2, -1)).max(axis=1) / (ROW / rate)


def measured():
    """Rows of FIELDS for every slow-loading run in runs/ that is over."""
    rows = []
    for fam in ls.FAMILIES:
        for m, _ in es.MESHES:
            for step, _, _ in sl.RATES:
                rate = float(step.split("_sl")[1])
                for k in es.MEMBERS:
                    case = es.case_name(fam, m, k, step)
                    path = os.path.join(analyse.runs, case, "history.h5")
                    # a run under way holds history.h5 open: only runs that are over
                    if not os.path.exists(path) or not es.is_over(case, analyse.curve(case), sl.stopped):
                        continue
                    strain, fields = read_history(path)
                    e = strain[1:]
                    for d, F in fields.items():
                        r = band_rates(F, rate)
                        after = r[e > AFTER + 1e-9]
                        rows.append({"case": case, "dataset": d, "steps": len(strain), "last_axial_strain": f"{e[-1]:.6g}",
                                     "median_after_6pc": f"{np.median(after):.4g}" if after.size else "nan",
                                     "largest": f"{r.max():.4g}", "largest_stretch": f"{largest_stretch(F):.4g}"})
    return rows


def main():
    stored = {}
    if os.path.exists(TABLE):
        stored = {(r["case"], r["dataset"]): r for r in csv.DictReader(open(TABLE))}
    stored.update({(r["case"], r["dataset"]): r for r in measured()})
    if not stored:
        sys.exit("band_rate.py: no slow-loading run in runs/ and no results/band_rate.csv")
    with open(TABLE, "w", newline="") as fh:
        w = csv.DictWriter(fh, FIELDS)
        w.writeheader()
        w.writerows(stored[key] for key in sorted(stored))
    print("\n| case | F | to | band rate: median after 6 % | largest | inertial number of the median "
          "| largest principal stretch |\n" + "|---" * 7 + "|")
    for (case, d), r in sorted(stored.items()):
        med = float(r["median_after_6pc"])
        print(f"| {case} | {d} | {100 * float(r['last_axial_strain']):.4g} % | {med:.3g} /s | {float(r['largest']):.3g} /s "
              f"| {med * D_MEAN * np.sqrt(RHO / P):.2g} | {r.get('largest_stretch') or '-'} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
