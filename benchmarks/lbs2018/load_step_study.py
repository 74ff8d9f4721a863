#!/usr/bin/python3
"""The ensembles' drop at half the load step (issue 37, session 52).

Every ensemble of ensemble_study.py runs stage 2 in 0.125 % steps, and the
largest rows of its spreads lie in the drop. Here the same members K run at
0.0625 % (run.sh CASE_eighth[_pK]) and are compared with their 0.125 %
selves on the 0.125 % rows. The measure of a difference is the one of the
spread over the meshes: (max - min)/mean of the two curves at each row,
from the peak of their mean to 10 %.

Usage: load_step_study.py   (Debian's python3 with numpy)

Reads results/ensemble_curves.csv (0.125 %) and results/load_step_curves.csv
(0.0625 %, updated from runs/CASE_eighth[_pK]/summary.csv, so that the tables
regenerate without runs/), and prints:
- every 0.0625 % member's peak (ratio, axial strain), the row 0.02 below it
  (the onset) and its ratio at 10 %, beside the range of its mesh's 0.125 %
  members;
- per family and mesh the difference between the mean of the 0.0625 %
  members and the mean of the same members K at 0.125 %, beside the 0.125 %
  members' own spread (the rounding floor at one step) and the 0.0625 %
  members' own; where a mesh has fewer members at 0.0625 %, also against
  the mean of all its 0.125 % members;
- the criterion over the three meshes with each family's 2x4 mean at
  0.0625 % in place of its 0.125 % one (4x8 and 8x16 one point at 0.125 %),
  against all at 0.125 %; and, where 4x8's member K = 0 ran at 0.0625 % in
  both families, the spread over 2x4 and 4x8 of the K = 0 runs at each step;
and draws results/load_step_ensembles.png.
"""
import os
import sys

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import analyse  # noqa: E402
import ensemble_study as es  # noqa: E402  (the members, their names, means and spreads)
from nonlocal_study import spread_after_peak  # noqa: E402

FINE, COARSE = "_eighth", "_quarter"  # run.sh's stage-2 steps: 0.0625 % and 0.125 %
CURVES = os.path.join(analyse.results, "load_step_curves.csv")
FAMILIES = [es.FAMILIES[0], es.FAMILIES[2]]  # local and local elastic R = 5 mm (the criterion's pass)
COARSE_STEP = 0.00125  # 0.125 % of axial strain


def on_coarse_rows(curve):
    """@p curve (0.0625 % rows) on the 0.125 % rows: the stage-1 end and every second row."""
    keep = [i for i, e in enumerate(curve["axial_strain"])
            if abs(e / COARSE_STEP - round(e / COARSE_STEP)) < 1e-6]
    return {k: [curve[k][i] for i in keep] for k in ("axial_strain", "stress_ratio")}


def members(curves, fam, mesh, step):
    """The members K of @p fam on @p mesh that reached 10 % at @p step."""
    return [k for k in es.MEMBERS if es.finished(curves, es.case_name(fam, mesh, k, step))]


def mean_of(curves, fam, mesh, ks, step):
    """The mean curve of @p fam's members @p ks on @p mesh at @p step, on the 0.125 % rows."""
    mean = es.mean_curve(curves, [es.case_name(fam, mesh, k, step) for k in ks])
    return on_coarse_rows(mean) if step == FINE else mean


def spread_of(named):
    """es.summary() of the spread over the curves of dict @p named (label: curve)."""
    return es.summary(spread_after_peak(named, list(named))[0])


def pct(s):
    """A summary's mean and largest as table cells."""
    return f"{100 * s[1]:.3g} % | {100 * s[2]:.3g} %"


def print_members(curves):
    """Peak, onset and end of every 0.0625 % member beside its mesh's 0.125 % range."""
    print("\n| family | mesh | K | peak | at | 0.02 below it at | ratio at 10 % | "
          "0.125 % members: peaks | onsets |\n" + "|---" * 9 + "|")
    for fam in FAMILIES:
        for m, _ in es.MESHES:
            coarse = [curves[es.case_name(fam, m, k)] for k in members(curves, fam, m, COARSE)]
            peaks = [max(c["stress_ratio"]) for c in coarse]
            onsets = [100 * es.drop_at(c) for c in coarse]
            for k in members(curves, fam, m, FINE):
                c = curves[es.case_name(fam, m, k, FINE)]
                r, e = c["stress_ratio"], c["axial_strain"]
                i = int(np.argmax(r))
                print(f"| {fam[0]} | {m} | {k} | {r[i]:.4f} | {100 * e[i]:.4g} % | {100 * es.drop_at(c):.4g} % "
                      f"| {r[-1]:.3f} | {min(peaks):.4f}-{max(peaks):.4f} | {min(onsets):.4g}-{max(onsets):.4g} % |")


def print_step_differences(curves):
    """Per family and mesh: the mean at 0.0625 % against the mean at 0.125 % of the same members."""
    print("\n| family | mesh | members K | 0.0625 % against 0.125 % mean: mean | largest | from 7.5 %: mean "
          "| largest | 0.125 % members' own spread: mean | largest | 0.0625 % members' own: mean | largest |\n"
          + "|---" * 11 + "|")
    for fam in FAMILIES:
        for m, _ in es.MESHES:
            ks = [k for k in members(curves, fam, m, FINE) if k in members(curves, fam, m, COARSE)]
            if not ks:
                continue
            d = spread_of({"0.0625": mean_of(curves, fam, m, ks, FINE), "0.125": mean_of(curves, fam, m, ks, COARSE)})
            own = [" | "] * 2  # two empty cells each
            if len(ks) >= 2:
                for j, step in enumerate((COARSE, FINE)):
                    named = {k: (on_coarse_rows if step == FINE else dict)(curves[es.case_name(fam, m, k, step)])
                             for k in ks}
                    own[j] = pct(spread_of(named))
            print(f"| {fam[0]} | {m} | {', '.join(map(str, ks))} | {pct(d)} | {100 * d[3]:.3g} % | {100 * d[4]:.3g} % "
                  f"| {own[0]} | {own[1]} |")
            every = members(curves, fam, m, COARSE)
            if every != ks:  # fewer members at 0.0625 %: also against the mean of every 0.125 % member
                d = spread_of({"0.0625": mean_of(curves, fam, m, ks, FINE),
                               "0.125": mean_of(curves, fam, m, every, COARSE)})
                print(f"| {fam[0]} | {m} | {', '.join(map(str, ks))} against 0.125 % K = {', '.join(map(str, every))} "
                      f"| {pct(d)} | {100 * d[3]:.3g} % | {100 * d[4]:.3g} % | | | | |")


def print_criterion(curves):
    """The three meshes' spread of means with 2x4 at either step, and 2x4 + 4x8 member K = 0 at each step."""
    meshes = [m for m, _ in es.MESHES]
    print("\n| curves | family | members K | mean | largest | from 7.5 %: mean | largest | against local |\n"
          + "|---" * 8 + "|")
    rows = []
    ks = [k for k in es.MEMBERS if all(k in members(curves, f, "2x4", FINE) for f in FAMILIES)
          and all(k in es.common_members(curves, f, meshes) for f in FAMILIES)]
    if len(ks) >= 2:
        for label, step in (("three meshes, 2x4 at 0.125 %", COARSE), ("three meshes, 2x4 at 0.0625 %", FINE)):
            rows.append((label, ks, [spread_of({m: mean_of(curves, f, m, ks, step if m == "2x4" else COARSE)
                                                for m in meshes}) for f in FAMILIES]))
    pair = meshes[:2]
    if all(es.finished(curves, es.case_name(f, m, 0, FINE)) for f in FAMILIES for m in pair):
        for label, step in (("2x4, 4x8 at 0.125 %", COARSE), ("2x4, 4x8 at 0.0625 %", FINE)):
            rows.append((label, [0], [spread_of({m: mean_of(curves, f, m, [0], step) for m in pair})
                                      for f in FAMILIES]))
    for label, used, (local, elastic) in rows:
        print(f"| {label} | {FAMILIES[0][0]} | {', '.join(map(str, used))} | {pct(local)} | "
              f"{100 * local[3]:.3g} % | {100 * local[4]:.3g} % | |")
        print(f"| {label} | {FAMILIES[1][0]} | {', '.join(map(str, used))} | {pct(elastic)} | "
              f"{100 * elastic[3]:.3g} % | {100 * elastic[4]:.3g} % | "
              f"{elastic[1] / local[1]:.2f}, {elastic[2] / local[2]:.2f} |")


def plot(curves):
    """results/load_step_ensembles.png: per family and mesh with 0.0625 % members, every member at
    both steps (thin) and the means of the same members (thick), from 5 %."""
    panels = [(f, m) for f in FAMILIES for m, _ in es.MESHES if members(curves, f, m, FINE)]
    if not panels:
        return
    fig, axs = plt.subplots(1, len(panels), figsize=(4 * len(panels), 4.5), sharey=True, squeeze=False)
    for ax, (fam, m) in zip(axs[0], panels):
        ks = members(curves, fam, m, FINE)
        for step, colour, label in ((COARSE, "tab:blue", "0.125 %"), (FINE, "tab:orange", "0.0625 %")):
            for k in ks:
                c = curves.get(es.case_name(fam, m, k, step))
                if c:
                    ax.plot(100 * np.array(c["axial_strain"]), c["stress_ratio"], color=colour, lw=0.7, alpha=0.5)
            if all(es.finished(curves, es.case_name(fam, m, k, step)) for k in ks):
                mean = es.mean_curve(curves, [es.case_name(fam, m, k, step) for k in ks])
                ax.plot(100 * np.array(mean["axial_strain"]), mean["stress_ratio"], color=colour, lw=2.2,
                        label=f"{label} steps, mean of K = {', '.join(map(str, ks))}")
        ax.set_xlim(5, 10)
        ax.set_ylim(0.24, 0.43)
        ax.set_title(f"{fam[0]}, {m}", fontsize=10)
        ax.set_xlabel("axial strain (%)")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    axs[0][0].set_ylabel("stress ratio (σ1 − σ2)/(σ1 + σ2)")
    fig.suptitle("[LBS] biaxial: the ensemble members at 0.125 % and 0.0625 % steps")
    fig.tight_layout()
    fig.savefig(os.path.join(analyse.results, "load_step_ensembles.png"), dpi=120)


def main():
    curves = es.stored_curves()
    curves.update(es.stored_curves(CURVES, FINE))
    plot(curves)
    print_members(curves)
    print_step_differences(curves)
    print_criterion(curves)
    return 0


if __name__ == "__main__":
    sys.exit(main())
