#!/usr/bin/python3
"""The ensembles' drop at a half and a quarter of the load step (issue 37, sessions 52-54).

Every ensemble of ensemble_study.py runs stage 2 in 0.125 % steps, and the
largest rows of its spreads lie in the drop. Here the same members K run at
0.0625 % and 0.03125 % (run.sh CASE_eighth[_pK], CASE_sixteenth[_pK]) and
are compared with their selves at the next coarser step on the 0.125 % rows.
The measure of a difference is the one of the spread over the meshes: (max -
min)/mean of the two curves at each row, from the peak of their mean to 10 %.

Usage: load_step_study.py   (Debian's python3 with numpy)

Reads results/ensemble_curves.csv (0.125 %) and results/load_step_curves.csv
(the finer steps, updated from runs/CASE_eighth[_pK]/summary.csv and
runs/CASE_sixteenth[_pK]/summary.csv, so that the tables regenerate without
runs/), and prints:
- every finer-step member's peak (ratio, axial strain), the row 0.02 below it
  (the onset) and its ratio at 10 %, beside the range of its mesh's 0.125 %
  members;
- per family and mesh the mean onset and peak strain of the same members at
  every step, the shift at each halving and the ratio of the last two shifts
  (below 1: the onset converges in the step; 0.5: at first order);
- per family and mesh the difference between the mean of a step's members
  and the mean of the same members K at the next coarser step, beside the
  coarser members' own spread (the rounding floor at one step) and the finer
  ones' own; where a mesh has fewer members at 0.0625 %, also against the
  mean of all its 0.125 % members;
- the criterion over the three meshes with each family's 2x4 mean at each
  step (4x8 and 8x16 one point at 0.125 %); and, where 4x8's member K = 0
  ran at a step in both families, the spread over 2x4 and 4x8 of the K = 0
  runs at that step;
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

# run.sh's stage-2 load steps, coarsest first: suffix, label, colour of the plot
STEPS = [("_quarter", "0.125 %", "tab:blue"), ("_eighth", "0.0625 %", "tab:orange"),
         ("_sixteenth", "0.03125 %", "tab:green")]
COARSE = STEPS[0][0]
LABEL = {s: label for s, label, _ in STEPS}
CURVES = os.path.join(analyse.results, "load_step_curves.csv")
FAMILIES = [es.FAMILIES[0], es.FAMILIES[2]]  # local and local elastic R = 5 mm (the criterion's pass)
COARSE_STEP = 0.00125  # 0.125 % of axial strain


def on_coarse_rows(curve):
    """@p curve (a finer step's rows) on the 0.125 % rows: the stage-1 end and every 0.125 %."""
    keep = [i for i, e in enumerate(curve["axial_strain"])
            if abs(e / COARSE_STEP - round(e / COARSE_STEP)) < 1e-6]
    return {k: [curve[k][i] for i in keep] for k in ("axial_strain", "stress_ratio")}


def members(curves, fam, mesh, step):
    """The members K of @p fam on @p mesh that reached 10 % at @p step."""
    return [k for k in es.MEMBERS if es.finished(curves, es.case_name(fam, mesh, k, step))]


def member_curve(curves, fam, mesh, k, step):
    """Member @p k's curve at @p step on the 0.125 % rows."""
    c = curves[es.case_name(fam, mesh, k, step)]
    return c if step == COARSE else on_coarse_rows(c)


def mean_of(curves, fam, mesh, ks, step):
    """The mean curve of @p fam's members @p ks on @p mesh at @p step, on the 0.125 % rows."""
    mean = es.mean_curve(curves, [es.case_name(fam, mesh, k, step) for k in ks])
    return mean if step == COARSE else on_coarse_rows(mean)


def spread_of(named):
    """es.summary() of the spread over the curves of dict @p named (label: curve)."""
    return es.summary(spread_after_peak(named, list(named))[0])


def pct(s):
    """A summary's mean and largest as table cells."""
    return f"{100 * s[1]:.3g} % | {100 * s[2]:.3g} %"


def print_members(curves):
    """Peak, onset and end of every finer-step member beside its mesh's 0.125 % range."""
    print("\n| step | family | mesh | K | peak | at | 0.02 below it at | ratio at 10 % | "
          "0.125 % members: peaks | onsets |\n" + "|---" * 10 + "|")
    for step, label, _ in STEPS[1:]:
        for fam in FAMILIES:
            for m, _ in es.MESHES:
                coarse = [curves[es.case_name(fam, m, k)] for k in members(curves, fam, m, COARSE)]
                peaks = [max(c["stress_ratio"]) for c in coarse]
                onsets = [100 * es.drop_at(c) for c in coarse]
                for k in members(curves, fam, m, step):
                    c = curves[es.case_name(fam, m, k, step)]
                    r, e = c["stress_ratio"], c["axial_strain"]
                    i = int(np.argmax(r))
                    print(f"| {label} | {fam[0]} | {m} | {k} | {r[i]:.4f} | {100 * e[i]:.4g} % "
                          f"| {100 * es.drop_at(c):.4g} % | {r[-1]:.3f} "
                          f"| {min(peaks):.4f}-{max(peaks):.4f} | {min(onsets):.4g}-{max(onsets):.4g} % |")


def print_onsets(curves):
    """Per family and mesh the mean onset (and peak strain) of the same members at every step they
    ran at, the shift at each halving and the ratio of the last two shifts."""
    print("\n| family | mesh | members K | mean onset: " + " | ".join(LABEL[s] for s, _, _ in STEPS)
          + " | shifts | ratio of the last two | mean peak at: " + " | ".join(LABEL[s] for s, _, _ in STEPS)
          + " |\n" + "|---" * (5 + 2 * len(STEPS)) + "|")
    for fam in FAMILIES:
        for m, _ in es.MESHES:
            ran = [s for s, _, _ in STEPS if members(curves, fam, m, s)]
            if len(ran) < 2:
                continue
            ks = [k for k in es.MEMBERS if all(k in members(curves, fam, m, s) for s in ran)]
            onset, peak_at = [], []
            for s in ran:
                cs = [curves[es.case_name(fam, m, k, s)] for k in ks]
                onset.append(100 * np.mean([es.drop_at(c) for c in cs]))
                peak_at.append(100 * np.mean([c["axial_strain"][int(np.argmax(c["stress_ratio"]))] for c in cs]))
            shifts = np.diff(onset)
            cell = {s: (o, p) for s, o, p in zip(ran, onset, peak_at)}
            ratio = f"{shifts[-1] / shifts[-2]:.2f}" if len(shifts) >= 2 and shifts[-2] != 0 else ""
            print(f"| {fam[0]} | {m} | {', '.join(map(str, ks))} | "
                  + " | ".join(f"{cell[s][0]:.4g} %" if s in cell else "" for s, _, _ in STEPS)
                  + f" | {', '.join(f'{d:+.3g} %' for d in shifts)} | {ratio} | "
                  + " | ".join(f"{cell[s][1]:.4g} %" if s in cell else "" for s, _, _ in STEPS) + " |")


def print_step_differences(curves):
    """Per family and mesh: the mean at each finer step against the mean at the next coarser step
    of the same members."""
    print("\n| steps | family | mesh | members K | finer against coarser mean: mean | largest | from 7.5 %: mean "
          "| largest | coarser members' own spread: mean | largest | finer members' own: mean | largest |\n"
          + "|---" * 12 + "|")
    for (coarser, clabel, _), (finer, flabel, _) in zip(STEPS, STEPS[1:]):
        pair = f"{flabel} against {clabel}"
        for fam in FAMILIES:
            for m, _ in es.MESHES:
                ks = [k for k in members(curves, fam, m, finer) if k in members(curves, fam, m, coarser)]
                if not ks:
                    continue
                d = spread_of({finer: mean_of(curves, fam, m, ks, finer), coarser: mean_of(curves, fam, m, ks, coarser)})
                own = [" | "] * 2  # two empty cells each
                if len(ks) >= 2:
                    for j, step in enumerate((coarser, finer)):
                        own[j] = pct(spread_of({k: member_curve(curves, fam, m, k, step) for k in ks}))
                print(f"| {pair} | {fam[0]} | {m} | {', '.join(map(str, ks))} | {pct(d)} | {100 * d[3]:.3g} % "
                      f"| {100 * d[4]:.3g} % | {own[0]} | {own[1]} |")
                every = members(curves, fam, m, coarser)
                if coarser == COARSE and every != ks:  # fewer finer members: also against every 0.125 % one
                    d = spread_of({finer: mean_of(curves, fam, m, ks, finer),
                                   coarser: mean_of(curves, fam, m, every, coarser)})
                    print(f"| {pair} | {fam[0]} | {m} | {', '.join(map(str, ks))} against 0.125 % "
                          f"K = {', '.join(map(str, every))} | {pct(d)} | {100 * d[3]:.3g} % | {100 * d[4]:.3g} % "
                          "| | | | |")


def print_criterion(curves):
    """The three meshes' spread of means with 2x4 at each step, and 2x4 + 4x8 member K = 0 at each
    step."""
    meshes = [m for m, _ in es.MESHES]
    print("\n| curves | family | members K | mean | largest | from 7.5 %: mean | largest | against local |\n"
          + "|---" * 8 + "|")
    rows = []
    for step, label, _ in STEPS:
        ks = [k for k in es.MEMBERS if all(k in members(curves, f, "2x4", step) for f in FAMILIES)
              and all(k in es.common_members(curves, f, meshes) for f in FAMILIES)]
        if len(ks) >= 2:
            rows.append((f"three meshes, 2x4 at {label}", ks,
                         [spread_of({m: mean_of(curves, f, m, ks, step if m == "2x4" else COARSE) for m in meshes})
                          for f in FAMILIES]))
    pair = meshes[:2]
    for step, label, _ in STEPS:
        if all(es.finished(curves, es.case_name(f, m, 0, step)) for f in FAMILIES for m in pair) and \
                any(es.finished(curves, es.case_name(f, "4x8", 0, s)) for f in FAMILIES for s, _, _ in STEPS[1:]):
            rows.append((f"2x4, 4x8 at {label}", [0], [spread_of({m: mean_of(curves, f, m, [0], step) for m in pair})
                                                      for f in FAMILIES]))
    for label, used, (local, elastic) in rows:
        print(f"| {label} | {FAMILIES[0][0]} | {', '.join(map(str, used))} | {pct(local)} | "
              f"{100 * local[3]:.3g} % | {100 * local[4]:.3g} % | |")
        print(f"| {label} | {FAMILIES[1][0]} | {', '.join(map(str, used))} | {pct(elastic)} | "
              f"{100 * elastic[3]:.3g} % | {100 * elastic[4]:.3g} % | "
              f"{elastic[1] / local[1]:.2f}, {elastic[2] / local[2]:.2f} |")


def plot(curves):
    """results/load_step_ensembles.png: per family and mesh with finer-step members, every member at
    every step (thin) and the means of the same members (thick), from 5 %."""
    panels = [(f, m) for f in FAMILIES for m, _ in es.MESHES
              if any(members(curves, f, m, s) for s, _, _ in STEPS[1:])]
    if not panels:
        return
    fig, axs = plt.subplots(1, len(panels), figsize=(4 * len(panels), 4.5), sharey=True, squeeze=False)
    for ax, (fam, m) in zip(axs[0], panels):
        ks = members(curves, fam, m, STEPS[1][0])
        for step, label, colour in STEPS:
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
    fig.suptitle("[LBS] biaxial: the ensemble members at 0.125 %, 0.0625 % and 0.03125 % steps")
    fig.tight_layout()
    fig.savefig(os.path.join(analyse.results, "load_step_ensembles.png"), dpi=120)


def curves_at_every_step():
    """Every member's curve at every load step of STEPS (es.stored_curves of each step's file)."""
    curves = es.stored_curves()
    for step, _, _ in STEPS[1:]:
        curves.update(es.stored_curves(CURVES, step))
    return curves


def main():
    curves = curves_at_every_step()
    plot(curves)
    print_members(curves)
    print_onsets(curves)
    print_step_differences(curves)
    print_criterion(curves)
    return 0


if __name__ == "__main__":
    sys.exit(main())
