#!/usr/bin/python3
"""compare.py -- the frame RVE (runs/PACKING/CASE/rve.csv of run.sh) against
the YADE periodic cell (../yade_periodic/results/PACKING_rate1.csv) along the
same biaxial path, at every 0.5 % of axial strain.

Usage: benchmarks/frame_vs_periodic/compare.py [PACKING ...]   (default: lbs_ref lbs_a005)

Writes results/PACKING.csv (one row per 0.5 % step: the YADE values, then
per RVE case stress ratio, sigma22 and J_rel), results/summary.csv (per
packing and case: largest relative difference of the stress ratio and of
sigma22 to 5 % and to 10 %, largest difference of J_rel in % points, peaks)
and results/PACKING.png; prints the tables in Markdown.

Quantities: stress ratio |s11 - s22| / |s11 + s22| of the Cauchy stress
(RVE: boundary stress R7), sigma22 in N/m (tension positive), axial strain
1 - F22/F22_ic (YADE: 1 - Ly/Ly_ic), J_rel = J/J_ic - 1, with ic = the end of
the isotropic stage.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
CASES = ["default", "steps0.1", "servo1e-6", "relax1e-6", "force", "affine", "tight"]
ISOTROPIC_STEPS = 10  # biaxial.prm
STEPS = [round(0.005 * k, 4) for k in range(0, 21)]


def ratio(s11, s22):
    return abs((s11 - s22) / (s11 + s22))


def yade_curve(packing):
    path = os.path.join(HERE, "..", "yade_periodic", "results", f"{packing}_rate1.csv")
    rows = [r for r in csv.DictReader(l for l in open(path) if not l.startswith("#"))
            if r["stage"] == "biaxial"]
    out = {}
    for e in STEPS:
        r = min(rows, key=lambda r: abs(float(r["axial_strain"]) - e))
        if abs(float(r["axial_strain"]) - e) < 1e-4:
            s11, s22 = float(r["sigma11_Npm"]), float(r["sigma22_Npm"])
            out[e] = (ratio(s11, s22), s22, float(r["J_rel"]))
    return out


def rve_curve(packing, case):
    path = os.path.join(HERE, "runs", packing, case, "rve.csv")
    if not os.path.exists(path):
        return None
    rows = list(csv.DictReader(open(path)))
    if len(rows) <= ISOTROPIC_STEPS:
        return None
    ic = rows[ISOTROPIC_STEPS]
    f22_ic = float(ic["F22"])
    j_ic = float(ic["F11"]) * f22_ic - float(ic["F12"]) * float(ic["F21"])
    out = {}
    for r in rows[ISOTROPIC_STEPS:]:
        e = round(1.0 - float(r["F22"]) / f22_ic, 4)
        if e in STEPS:
            j = float(r["F11"]) * float(r["F22"]) - float(r["F12"]) * float(r["F21"])
            out[e] = (ratio(float(r["sigma11"]), float(r["sigma22"])), float(r["sigma22"]), j / j_ic - 1.0)
    return out


def worst(ref, cur, index, upto, relative=True):
    diffs = []
    for e in STEPS[1:]:
        if e <= upto + 1e-9 and e in ref and e in cur:
            d = cur[e][index] - ref[e][index]
            diffs.append((abs(d / ref[e][index]) if relative else abs(d), e))
    return max(diffs) if diffs else (float("nan"), float("nan"))


def main():
    packings = sys.argv[1:] or ["lbs_ref", "lbs_a005"]
    os.makedirs(os.path.join(HERE, "results"), exist_ok=True)
    summary = []
    for p in packings:
        ref = yade_curve(p)
        curves = {c: rve_curve(p, c) for c in CASES}
        curves = {c: v for c, v in curves.items() if v}
        with open(os.path.join(HERE, "results", f"{p}.csv"), "w") as fh:
            w = csv.writer(fh)
            w.writerow(["axial_strain", "yade_ratio", "yade_sigma22", "yade_J_rel"] +
                       [f"{c}_{q}" for c in curves for q in ("ratio", "sigma22", "J_rel")])
            for e in STEPS:
                row = [e] + [f"{v:.6g}" for v in ref.get(e, ("",) * 3) if v != ""]
                for c, cur in curves.items():
                    row += [f"{v:.6g}" for v in cur[e]] if e in cur else ["", "", ""]
                w.writerow(row)
        print(f"\n### {p}: stress ratio at each 0.5 % step (YADE periodic cell and frame RVE cases)\n")
        print("| axial strain | YADE | " + " | ".join(curves) + " |")
        print("| --- " * (2 + len(curves)) + "|")
        for e in STEPS[1:]:
            cells = [f"{ref[e][0]:.4f}" if e in ref else "-"]
            cells += [f"{cur[e][0]:.4f}" if e in cur else "-" for cur in curves.values()]
            print(f"| {100 * e:.1f} % | " + " | ".join(cells) + " |")
        peak_ref = max((ref[e][0], e) for e in ref)
        for c, cur in curves.items():
            peak = max((cur[e][0], e) for e in cur)
            summary.append({
                "packing": p, "case": c,
                "ratio_maxrel_to5": worst(ref, cur, 0, 0.05)[0],
                "ratio_maxrel_to5_at": worst(ref, cur, 0, 0.05)[1],
                "sigma22_maxrel_to5": worst(ref, cur, 1, 0.05)[0],
                "J_rel_maxabs_to5_pct": 100 * worst(ref, cur, 2, 0.05, relative=False)[0],
                "ratio_maxrel_to10": worst(ref, cur, 0, 0.10)[0],
                "peak": peak[0], "peak_at": peak[1],
                "yade_peak": peak_ref[0], "yade_peak_at": peak_ref[1]})
        fig, ax = plt.subplots(1, 3, figsize=(15, 4.2))
        xs = [100 * e for e in STEPS if e in ref]
        for k, (label, idx, scale) in enumerate([("stress ratio", 0, 1.0), ("sigma22 [kN/m]", 1, 1e-3),
                                                 ("J_rel [%]", 2, 100.0)]):
            ax[k].plot(xs, [ref[e][idx] * scale for e in STEPS if e in ref], "k-o", lw=2.5, ms=4,
                       label="YADE periodic cell")
            for c, cur in curves.items():
                es = [e for e in STEPS if e in cur]
                ax[k].plot([100 * e for e in es], [cur[e][idx] * scale for e in es], "-", lw=1.2,
                           label=f"frame RVE, {c}")
            ax[k].set_xlabel("axial strain [%]")
            ax[k].set_ylabel(label)
            ax[k].grid(alpha=0.3)
        ax[0].legend(fontsize=8)
        fig.suptitle(f"{p}: frame RVE (fix rve/servo) vs YADE periodic cell, biaxial at 150 kN/m")
        fig.tight_layout()
        fig.savefig(os.path.join(HERE, "results", f"{p}.png"), dpi=90)
        plt.close(fig)
    with open(os.path.join(HERE, "results", "summary.csv"), "w") as fh:
        w = csv.DictWriter(fh, fieldnames=list(summary[0]))
        w.writeheader()
        for s in summary:
            w.writerow({k: (f"{v:.4g}" if isinstance(v, float) else v) for k, v in s.items()})
    print("\n### Largest differences from the YADE cell\n")
    print("| packing | case | stress ratio, to 5 % (at) | sigma22, to 5 % | J_rel, to 5 % | stress ratio, to 10 % | peak (at) | YADE peak (at) |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- |")
    for s in summary:
        print(f"| {s['packing']} | {s['case']} | {100 * s['ratio_maxrel_to5']:.1f} % ({100 * s['ratio_maxrel_to5_at']:.1f} %) "
              f"| {100 * s['sigma22_maxrel_to5']:.1f} % | {s['J_rel_maxabs_to5_pct']:.2f} %-pts "
              f"| {100 * s['ratio_maxrel_to10']:.1f} % | {s['peak']:.3f} ({100 * s['peak_at']:.1f} %) "
              f"| {s['yade_peak']:.3f} ({100 * s['yade_peak_at']:.1f} %) |")


if __name__ == "__main__":
    main()
