#!/usr/bin/python3
"""Reads fe2dem-rve's rve.csv (3D) as loading curves and compares them.

Usage:
  curves.py [--iso N] [--prepared P] show RVE_CSV                  the curve, one line per row
  curves.py [--iso N] [--prepared P] compare REF_CSV OTHER_CSV...  each OTHER against REF at REF's strains

REF_CSV and each OTHER_CSV may be a comma-separated list of runs of one
kind (an ensemble, e.g. of rates a few per cent apart): their mean at each
of the first run's strains stands for them, and the table gains the
standard error of the difference of the means, se = sqrt(s_ref^2/n_ref +
s_other^2/n_other) relative to the reference ratio (s the sample standard
deviation over a list; a single run adds nothing).

The loading stage starts at the last row of the isotropic stage: row
--iso N (N = 'Isotropic steps'; N = 0 is the packing as relaxed) or, for a
continuous drive, the row before the first with drive_time_s > 0. Strain: triaxial e_a = 1 - F_aa/F_aa,ic (a the axial direction: the normal
component of F that moved most), simple shear gamma = F12. fe2dem's
summary.csv of a one-element triaxial test (axial y) is read too: the
loading rows after stage 1, strain from its axial_strain column; with
--prepared P (RVEs prepared at 'Initial pressure' P, boundary conditions,
no stage 1) all its rows, after a start at zero strain and sigma = -P I.
Stresses are Cauchy (sigma), tension positive; p = -tr(sigma)/3; triaxial
ratio q/p with q = (lateral sum)/2 - sigma_aa (compression positive),
simple shear ratio tau/p with tau = |sigma12|. Volumetric strain det F/det F_ic - 1.

compare prints, per OTHER, the relative difference of the ratio and of the
driven stress (|sigma33| or |sigma12|) at each REF strain, the largest one
up to REF's peak ratio and the mean from the peak on, as 'name value' lines.
"""
import csv
import sys


def det3(F):
    return (F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6])
            + F[2] * (F[3] * F[7] - F[4] * F[6]))


ISO = None  # --iso N
PREPARED = None  # --prepared PRESSURE


def load_summary(path, raw):
    """fe2dem's summary.csv of a one-element triaxial test (axial y): the rows after stage 1, or
    (boundary conditions, RVEs prepared at a pressure: no stage 1) all rows after a start row
    at zero strain, isotropic at the 'Initial pressure' PRESSURE (--prepared PRESSURE)."""
    if PREPARED is not None:
        start = 0
        raw = [dict(raw[0], axial_strain=0.0, sigma11_mean=-PREPARED, sigma22_mean=-PREPARED,
                    sigma33_mean=-PREPARED, J_rel_mean=0.0)] + raw
    else:
        start = max(k for k, r in enumerate(raw) if r["stage"] == 1)
    rows = []
    for r in raw[start:]:
        s11, s22, s33 = r["sigma11_mean"], r["sigma22_mean"], r["sigma33_mean"]
        p = -(s11 + s22 + s33) / 3.0
        rows.append(dict(strain=r["axial_strain"] - raw[start]["axial_strain"], ratio=((s11 + s33) / 2.0 - s22) / p,
                         stress=-s22, p=p, ev=(1.0 + r["J_rel_mean"]) / (1.0 + raw[start]["J_rel_mean"]) - 1.0,
                         coordination=r["coordination_mean"],
                         error=float("nan")))
    return "triaxial", rows


def load(path):
    """(kind, rows) with rows of dicts: strain, ratio, stress, ev, p, coordination."""
    with open(path) as f:
        raw = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    if "stress_ratio_mean" in raw[0]:
        return load_summary(path, raw)
    if "F33" not in raw[0]:
        sys.exit(f"{path}: not a 3D rve.csv (no F33 column)")
    # simple shear drives F12; triaxial a normal component (Free shear moves F12 a little too)
    shear = max(abs(r["F12"]) for r in raw) > max(abs(r[f"F{i}{i}"] - 1.0) for r in raw for i in (1, 2, 3))
    if ISO is not None:
        start = ISO
    elif any(r.get("drive_time_s", 0.0) > 0.0 for r in raw):
        start = next(k for k, r in enumerate(raw) if r["drive_time_s"] > 0.0) - 1
    else:
        sys.exit(f"{path}: a stepped path; give the isotropic row with --iso N")
    ic = raw[start]
    J_ic = det3([ic[f"F{i}{j}"] for i in (1, 2, 3) for j in (1, 2, 3)])
    # the axial direction: the normal component of F that moved most in the loading stage
    a = max((1, 2, 3), key=lambda i: abs(raw[-1][f"F{i}{i}"] / ic[f"F{i}{i}"] - 1.0))
    lat = [i for i in (1, 2, 3) if i != a]
    rows = []
    for r in raw[start:]:
        s = [r[f"sigma{i}{j}"] for i in (1, 2, 3) for j in (1, 2, 3)]
        p = -(s[0] + s[4] + s[8]) / 3.0
        diag = {i: s[4 * (i - 1)] for i in (1, 2, 3)}
        if shear:
            strain, stress = r["F12"] - ic["F12"], abs(s[1])
        else:
            strain, stress = 1.0 - r[f"F{a}{a}"] / ic[f"F{a}{a}"], -diag[a]
        ratio = stress / p if shear else ((diag[lat[0]] + diag[lat[1]]) / 2.0 - diag[a]) / p
        J = det3([r[f"F{i}{j}"] for i in (1, 2, 3) for j in (1, 2, 3)])
        rows.append(dict(strain=strain, ratio=ratio, stress=stress, p=p, ev=J / J_ic - 1.0,
                         coordination=r["coordination"], error=r.get("control_error", float("nan"))))
    return ("shear" if shear else "triaxial"), rows


def interp(rows, key, x):
    xs = [r["strain"] for r in rows]
    tol = 1e-9  # strains from F differ from a row's nominal strain by round-off (4e-12 seen)
    if x < xs[0] - tol or x > xs[-1] + tol:
        return None
    for k in range(1, len(xs)):
        if x <= xs[k] + tol:
            t = (x - xs[k - 1]) / (xs[k] - xs[k - 1])
            return rows[k - 1][key] + t * (rows[k][key] - rows[k - 1][key])
    return rows[-1][key]


def load_mean(paths):
    """(kind, rows) of one run, or of the comma-separated runs in PATHS: at each strain of the first
    run the mean over the runs of ratio, stress and ev, and n and the sample variance of the ratio."""
    runs = [load(p) for p in paths.split(",")]
    kind, first = runs[0]
    if any(k != kind for k, _ in runs):
        sys.exit(f"{paths}: runs of different kinds")
    rows = []
    for r in first:
        values = {key: [interp(run, key, r["strain"]) for _, run in runs] for key in ("ratio", "stress", "ev")}
        if any(v is None for vs in values.values() for v in vs):
            break  # past the end of the shortest run
        row = dict(strain=r["strain"], n=len(runs), **{key: sum(vs) / len(vs) for key, vs in values.items()})
        row["ratio_var"] = (sum((v - row["ratio"]) ** 2 for v in values["ratio"]) / (len(runs) - 1)
                            if len(runs) > 1 else 0.0)
        rows.append(row)
    return kind, rows


def compare(ref_path, others):
    kind, ref = load_mean(ref_path)
    peak = max(range(1, len(ref)), key=lambda k: ref[k]["ratio"])
    print(f"# reference {ref_path} ({kind}): peak ratio {ref[peak]['ratio']:.4f} at {ref[peak]['strain']:.4%}")
    for path in others:
        _, other = load_mean(path)
        ensemble = ref[0]["n"] > 1 or other[0]["n"] > 1
        print(f"# {path}" if not ensemble else
              f"# the mean of {other[0]['n']} run(s) against the mean of {ref[0]['n']}: {path}")
        print("strain  ratio_ref  ratio  d_ratio  stress_ref  stress  d_stress  ev_ref  ev" + ("  se" if ensemble else ""))
        upto, after = [], []
        for k, r in enumerate(ref[1:], start=1):
            ratio, stress, ev, var = (interp(other, key, r["strain"]) for key in ("ratio", "stress", "ev", "ratio_var"))
            if ratio is None:
                continue
            d_ratio = ratio / r["ratio"] - 1.0
            d_stress = stress / r["stress"] - 1.0
            se = (r["ratio_var"] / r["n"] + var / other[0]["n"]) ** 0.5 / r["ratio"]
            (upto if k <= peak else after).append((abs(d_ratio), abs(d_stress), d_ratio))
            print(f"{r['strain']:.4f}  {r['ratio']:.4f}  {ratio:.4f}  {d_ratio:+.2%}  {r['stress']:.0f}  "
                  f"{stress:.0f}  {d_stress:+.2%}  {r['ev']:+.5f}  {ev:+.5f}" + (f"  {se:.2%}" if ensemble else ""))
        if upto:
            print(f"max_abs_d_ratio_to_peak {max(u[0] for u in upto):.4f}")
            print(f"max_abs_d_stress_to_peak {max(u[1] for u in upto):.4f}")
        if after:
            print(f"mean_abs_d_ratio_after_peak {sum(a[0] for a in after) / len(after):.4f}")
            print(f"mean_d_ratio_after_peak {sum(a[2] for a in after) / len(after):+.4f}")


if __name__ == "__main__":
    while len(sys.argv) >= 3 and sys.argv[1] in ("--iso", "--prepared"):
        if sys.argv[1] == "--iso":
            ISO = int(sys.argv[2])
        else:
            PREPARED = float(sys.argv[2])
        del sys.argv[1:3]
    if len(sys.argv) >= 3 and sys.argv[1] == "show":
        kind, rows = load(sys.argv[2])
        print(f"# {kind}")
        for r in rows:
            print(f"{r['strain']:.4f} ratio {r['ratio']:.4f} stress {r['stress']:.0f} p {r['p']:.0f} "
                  f"ev {r['ev']:+.5f} Z {r['coordination']:.3f} control_error {r['error']:.2e}")
    elif len(sys.argv) >= 4 and sys.argv[1] == "compare":
        compare(sys.argv[2], sys.argv[3:])
    else:
        sys.exit(__doc__)
