#!/usr/bin/python3
"""The [LBS] biaxial test by slow loading against relaxed steps (issue 37, session 54).

Every other table of this study runs [LBS]'s scheme, each load step relaxed
to rest, whose drop moves with the step (load_step_study.py). Here member
K = 0 of the local and the local elastic R = 5 mm families runs by fe2dem's
default quasi-static scheme with RVEs, slow loading at a nominal strain rate
(run.sh CASE_quarter_slRATE: 0.125 % rows), on 2x4 at 0.25 and 0.125 /s and
on 4x8 and 8x16 one point at 0.25 /s.

Usage: slow_loading_study.py   (Debian's python3 with numpy)

Reads results/slow_loading_curves.csv (updated from runs/CASE/summary.csv,
so that the tables regenerate without runs/), results/ensemble_curves.csv
and results/load_step_curves.csv (the relaxed steps), and prints:
- every slow-loading run's peak (ratio, axial strain), onset (the row 0.02
  below the peak) and ratio at 10 %;
- per family, mesh and rate the spread of the members K after the peak of
  their mean, beside the relaxed members' at 0.125 % (the same K);
- per family and mesh the two rates against each other: the largest
  relative difference of the stress ratio up to 5 % and the spread measure
  of the criterion ((max - min)/mean from the peak of their mean to 10 %);
- per family on 2x4 the slow-loading run at each rate against the relaxed
  steps' member K = 0 and mean of K = 0-3 at 0.125, 0.0625 and 0.03125 %
  (where run), in the same two measures;
- the spread of member K = 0 over 2x4 and 4x8 and over the three meshes
  (8x16 one point at 0.25 /s), slow loading and relaxed steps, local
  against R = 5 mm, to 10 % or, where a slow-loading run of the set
  stopped before (an RVE failed; its rows are stored too), to that stop;
  from session 55 also of each member K that every mesh ran, and of the
  means of those members;
- every run's half-share band width (band_width.py, the measure of the
  ensembles) over 7.5-8.5 % and 7.5-10 %, kept in
  results/slow_loading_widths.csv;
- every run at 'Stability modulus' 2e7 (run.sh ..._sm2e7, session 58)
  against the same member at 1e7, beside members K = 0 and 1 at 1e7
  against each other on the same rows;
and draws results/slow_loading.png.

Only runs made with the timed servo's anti-windup (session 56, from commit
ANTI_WINDUP on; results/runs.csv names each run's commit) enter: before it a
frame pair without contact coasted out of the cell, which ended four local
runs early (session 55's curves: results/slow_loading_curves_s55.csv). The
runs left out are listed first.
"""
import csv
import datetime
import os
import subprocess
import sys

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import analyse  # noqa: E402
import band_study  # noqa: E402  (the shear strain increment of a run over an interval)
import band_width as bw  # noqa: E402  (the half-share width)
import ensemble_study as es  # noqa: E402  (names, members, means, onsets)
import load_step_study as ls  # noqa: E402  (the relaxed steps at every load step)

RATES = [("_quarter_sl0.25", "0.25 /s", "tab:red"), ("_quarter_sl0.125", "0.125 /s", "tab:purple")]
CURVES = os.path.join(analyse.results, "slow_loading_curves.csv")
PRE_PEAK = 0.05  # the rows compared before the peak: 0.5 % to 5 %
WIDTHS = os.path.join(analyse.results, "slow_loading_widths.csv")
# the half-share width's intervals of axial strain: band_study's 7.5-10 % and, like for like with
# the local 8x16 run that stopped at 8.5 %, 7.5-8.5 %
WIDTH_INTERVALS = [(0.075, 0.085), (0.075, 0.10)]
ANTI_WINDUP = "2a8c723"  # the first commit with the timed servo's anti-windup
# session 58: run.sh's _sm2e7, 'Stability modulus' 2e7 instead of lbs2018.prm's 1e7 at 0.25 /s
STABILITY = "_quarter_sl0.25_sm2e7"


def before_anti_windup(case):
    """Whether results/runs.csv dates @p case's last run to a commit without the anti-windup (or has
    no row for it)."""
    row = analyse.run_info().get(case)
    if not row:
        return True
    ancestor = subprocess.run(["git", "merge-base", "--is-ancestor", ANTI_WINDUP, row["commit"]],
                              cwd=os.path.dirname(os.path.abspath(__file__)), capture_output=True)
    if ancestor.returncode not in (0, 1):
        sys.exit(f"slow_loading_study.py: git cannot place commit {row['commit']} of {case} "
                 f"(results/runs.csv): {ancestor.stderr.decode().strip()}")
    return ancestor.returncode == 1


def stopped(case):
    """Whether run.sh recorded @p case as ended without reaching 10 % (results/runs.csv: completed 0)
    after the last write of its runs/CASE/summary.csv, i.e. that row is this run's and not a rerun's."""
    row = analyse.run_info().get(case)
    path = os.path.join(analyse.runs, case, "summary.csv")
    if not row or row["completed"] != "0" or not os.path.exists(path):
        return False
    ended = datetime.datetime.strptime(row["date"], "%Y-%m-%dT%H:%M:%SZ").replace(tzinfo=datetime.timezone.utc)
    return ended.timestamp() >= os.path.getmtime(path) - 1.0


def pre_peak_difference(a, b):
    """The largest |a - b| / mean of the stress ratios of curves @p a and @p b (shared rows) from 0.5 %
    to PRE_PEAK."""
    e = np.array(a["axial_strain"])
    ra, rb = np.array(a["stress_ratio"]), np.array(b["stress_ratio"][:len(e)])
    keep = (e >= 0.005 - 1e-9) & (e <= PRE_PEAK + 1e-9)
    return float(np.max(np.abs(ra[keep] - rb[keep]) / (0.5 * (ra[keep] + rb[keep]))))


def compare(a, b):
    """Cells of curves @p a against @p b: the pre-peak difference and ls.spread_of's mean and largest."""
    s = ls.spread_of({"a": a, "b": b})
    return f"{100 * pre_peak_difference(a, b):.3g} % | {ls.pct(s)}"


def print_runs(curves):
    """Peak, onset and end of every slow-loading run, member by member."""
    print("\n| family | mesh | rate | K | peak | at | 0.02 below it at | ratio at 10 % |\n" + "|---" * 8 + "|")
    for fam in ls.FAMILIES:
        for m, _ in es.MESHES:
            for step, label, _ in RATES:
                for k in es.MEMBERS:
                    c = curves.get(es.case_name(fam, m, k, step))
                    if c:
                        r, e = c["stress_ratio"], c["axial_strain"]
                        i = int(np.argmax(r))
                        end = (f"{r[-1]:.3f}" if es.reached_end(c)
                               else f"stopped after {100 * e[-1]:.4g} % ({r[-1]:.3f})")
                        print(f"| {fam[0]} | {m} | {label} | {k} | {r[i]:.4f} | {100 * e[i]:.4g} % "
                              f"| {100 * es.drop_at(c):.4g} % | {end} |")


def print_member_spread(curves):
    """Per family, mesh and rate with two members or more: their spread after the peak of their mean
    (to the earliest end of a member), beside the relaxed members' at 0.125 % over the same members."""
    print("\n| family | mesh | rate | members | to | slow loading: mean | largest | relaxed 0.125 %, same members: "
          "mean | largest |\n" + "|---" * 9 + "|")
    for fam in ls.FAMILIES:
        for m, _ in es.MESHES:
            for step, label, _ in RATES:
                ks = [k for k in es.MEMBERS if es.case_name(fam, m, k, step) in curves]
                if len(ks) < 2:
                    continue
                end = min(curves[es.case_name(fam, m, k, step)]["axial_strain"][-1] for k in ks)
                slow = ls.spread_of({k: up_to(curves[es.case_name(fam, m, k, step)], end) for k in ks})
                relaxed = "- | -"
                if all(es.finished(curves, es.case_name(fam, m, k, ls.COARSE)) for k in ks):
                    relaxed = ls.pct(ls.spread_of({k: up_to(curves[es.case_name(fam, m, k, ls.COARSE)], end)
                                                   for k in ks}))
                print(f"| {fam[0]} | {m} | {label} | {', '.join(map(str, ks))} | {100 * end:.4g} % "
                      f"| {ls.pct(slow)} | {relaxed} |")


def print_rates_and_schemes(curves):
    """The two rates against each other, and each against the relaxed steps on the same mesh."""
    print("\n| family | mesh | curve | against | largest difference 0.5-5 % | spread after the peak: mean | largest |\n"
          + "|---" * 7 + "|")
    for fam in ls.FAMILIES:
        for m, _ in es.MESHES:
            slow = {label: curves[es.case_name(fam, m, 0, s)] for s, label, _ in RATES
                    if es.case_name(fam, m, 0, s) in curves}
            if len(slow) == 2:  # to the earlier end where one stopped (an RVE failed)
                end = min(c["axial_strain"][-1] for c in slow.values())
                to = "" if end > 0.10 - 1e-9 else f" (to {100 * end:.4g} %)"
                print(f"| {fam[0]} | {m} | slow 0.125 /s{to} | slow 0.25 /s "
                      f"| {compare(up_to(slow['0.125 /s'], end), up_to(slow['0.25 /s'], end))} |")
            slow = {label: c for label, c in slow.items() if es.reached_end(c)}
            for label, c in slow.items():
                for step, slabel, _ in ls.STEPS:
                    if es.finished(curves, es.case_name(fam, m, 0, step)):
                        print(f"| {fam[0]} | {m} | slow {label} | relaxed {slabel}, K = 0 "
                              f"| {compare(c, ls.member_curve(curves, fam, m, 0, step))} |")
                    ks = ls.members(curves, fam, m, step)
                    if len(ks) >= 2:
                        print(f"| {fam[0]} | {m} | slow {label} | relaxed {slabel}, mean of K = "
                              f"{', '.join(map(str, ks))} | {compare(c, ls.mean_of(curves, fam, m, ks, step))} |")


def print_stability_modulus(curves):
    """Each run at 'Stability modulus' 2e7 (STABILITY) against the same member at 1e7 (0.25 /s),
    beside members K = 0 and 1 at 1e7 against each other, all on the rows every one of them has: what
    the numerical mass and the hourglass stiffness move, against what rounding moves."""
    base = RATES[0][0]
    print("\n| family | mesh | K | 2e7 reached | to | 2e7 against 1e7: largest difference 0.5-5 % | spread "
          "after the peak: mean | largest | 1e7, K = 0 against K = 1: 0.5-5 % | mean | largest |\n"
          + "|---" * 11 + "|")
    for fam in ls.FAMILIES:
        for m, _ in es.MESHES:
            pair = [curves.get(es.case_name(fam, m, k, base)) for k in (0, 1)]
            for k in es.MEMBERS:
                c, b = curves.get(es.case_name(fam, m, k, STABILITY)), curves.get(es.case_name(fam, m, k, base))
                if not (c and b):
                    continue
                end = min(x["axial_strain"][-1] for x in [c, b] + [p for p in pair if p])
                rounding = compare(up_to(pair[0], end), up_to(pair[1], end)) if all(pair) else "- | - | -"
                print(f"| {fam[0]} | {m} | {k} | {100 * c['axial_strain'][-1]:.4g} % | {100 * end:.4g} % "
                      f"| {compare(up_to(c, end), up_to(b, end))} | {rounding} |")


def up_to(curve, end):
    """@p curve's rows up to axial strain @p end."""
    n = sum(1 for e in curve["axial_strain"] if e <= end + 1e-9)
    return {k: curve[k][:n] for k in ("axial_strain", "stress_ratio")}


def ran_by_all(curves, step, meshes):
    """The members K that every mesh of @p meshes ran at @p step in both families (to 10 % or, slow
    loading, to a stop: curves holds no run still under way)."""
    return [k for k in es.MEMBERS
            if all(es.case_name(f, m, k, step) in curves for f in ls.FAMILIES for m in meshes)]


def mean_up_to(curves, fam, mesh, ks, step, end):
    """The mean of @p fam's members @p ks on @p mesh at @p step, on the 0.125 % rows, to @p end."""
    runs = [up_to(ls.member_curve(curves, fam, mesh, k, step), end) for k in ks]
    return {"axial_strain": runs[0]["axial_strain"],
            "stress_ratio": list(np.mean([c["stress_ratio"] for c in runs], axis=0))}


def print_mesh_spread(curves):
    """The spread over 2x4 and 4x8, and over the three meshes, of each member K that every mesh ran
    by slow loading, and of the means of those members (two or more): slow loading at each rate,
    and relaxed steps at each load step over the same members. Where a slow-loading run of a set of
    members stopped before 10 %, every row of that set is taken to the earliest such stop, like for
    like."""
    print("\n| curves | meshes | members | to | local: mean | largest | R = 5 mm: mean | largest | against local |\n"
          + "|---" * 9 + "|")
    for meshes in ([m for m, _ in es.MESHES[:2]], [m for m, _ in es.MESHES]):
        for rate, rate_label, _ in RATES:
            ks = ran_by_all(curves, rate, meshes)
            if not ks:
                continue
            sets = [[k] for k in ks] + ([ks] if len(ks) >= 2 else [])
            if len(ks) >= 3:  # with the means of the first two as well, to their own end
                sets.append(ks[:2])
            rows = [(f"slow loading {rate_label}", rate)] + [(f"relaxed {label}", s) for s, label, _ in ls.STEPS]
            for members in sets:
                end = min(curves[es.case_name(f, m, k, rate)]["axial_strain"][-1]
                          for f in ls.FAMILIES for m in meshes for k in members)
                for label, step in rows:
                    if not set(members) <= set(ran_by_all(curves, step, meshes)) or any(
                            curves[es.case_name(f, m, k, step)]["axial_strain"][-1] < end - 1e-9
                            for f in ls.FAMILIES for m in meshes for k in members):
                        continue
                    local, elastic = (ls.spread_of({m: mean_up_to(curves, f, m, members, step, end) for m in meshes})
                                      for f in ls.FAMILIES)
                    what = f"K = {members[0]}" if len(members) == 1 else f"mean of K = {', '.join(map(str, members))}"
                    print(f"| {label} | {', '.join(meshes)} | {what} | {100 * end:.4g} % | {ls.pct(local)} "
                          f"| {ls.pct(elastic)} | {elastic[1] / local[1]:.2f}, {elastic[2] / local[2]:.2f} |")


def stored_widths(curves):
    """{(case, from, to): half-share width [m]} of every slow-loading run of @p curves (ended) over
    each WIDTH_INTERVALS it reached: WIDTHS, updated from runs/CASE/history.h5 (and written back)."""
    out = {}
    if os.path.exists(WIDTHS):
        out = {(r["case"], float(r["from"]), float(r["to"])): float(r["half_share_width_m"])
               for r in csv.DictReader(open(WIDTHS))}
    fresh = [c for c in curves if "_sl" in c and os.path.exists(os.path.join(analyse.runs, c, "history.h5"))]
    for c in fresh:
        eps, ratio, _ = band_study.stage2(c)
        for a, b in WIDTH_INTERVALS:
            if eps[-1] >= b - 1e-9:
                _, g = band_study.increment(c, a, b)
                out[(c, a, b)] = bw.half_share_width(g, band_study.HEIGHT, bw.coulomb_angle(ratio.max()))
    if fresh:
        with open(WIDTHS, "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(["case", "from", "to", "half_share_width_m"])
            w.writerows([c, f"{a:g}", f"{b:g}", f"{v:.6g}"] for (c, a, b), v in sorted(out.items()))
    return out


def print_widths(widths):
    """Per family, rate and mesh the members' half-share widths over each of WIDTH_INTERVALS, their
    mean, and the range of the meshes' means (over the meshes that have the interval)."""
    print("\n| family | rate | mesh | element | "
          + " | ".join(f"half share {100 * a:g}-{100 * b:g} %: K = ... (mm) | mean" for a, b in WIDTH_INTERVALS)
          + " |\n" + "|---" * (4 + 2 * len(WIDTH_INTERVALS)) + "|")
    for fam in ls.FAMILIES:
        for step, label, _ in RATES:
            means = {iv: [] for iv in WIDTH_INTERVALS}
            for m, _ in es.MESHES:
                cells, any_run = [], False
                for a, b in WIDTH_INTERVALS:
                    v = [(k, 1e3 * widths[(es.case_name(fam, m, k, step), a, b)]) for k in es.MEMBERS
                         if (es.case_name(fam, m, k, step), a, b) in widths]
                    any_run = any_run or bool(v)
                    if v:
                        means[(a, b)].append(np.mean([x for _, x in v]))
                    cells += [" / ".join(f"{x:.1f} ({k})" for k, x in v) or "-",
                              f"{np.mean([x for _, x in v]):.1f}" if v else "-"]
                if any_run:
                    print(f"| {fam[0]} | {label} | {m} | {es.ELEMENT_MM[m]:g} mm | " + " | ".join(cells) + " |")
            ranges = [f"{max(v) - min(v):.1f} mm over {len(v)} meshes" if len(v) > 1 else "-" for v in means.values()]
            if any(len(v) > 1 for v in means.values()):
                print(f"| {fam[0]} | {label} | range of the means | | " + " | | ".join(ranges) + " | |")


def plot(curves):
    """results/slow_loading.png: per family the slow-loading runs and the relaxed 2x4 K = 0 runs."""
    fig, axs = plt.subplots(1, len(ls.FAMILIES), figsize=(6 * len(ls.FAMILIES), 4.5), sharey=True)
    for ax, fam in zip(axs, ls.FAMILIES):
        for step, label, colour in ls.STEPS:
            c = curves.get(es.case_name(fam, "2x4", 0, step))
            if c:
                ax.plot(100 * np.array(c["axial_strain"]), c["stress_ratio"], color=colour, lw=0.9,
                        label=f"2x4 relaxed steps of {label}")
        for step, label, colour in RATES:
            for m, style in (("2x4", "-"), ("4x8", "--"), ("8x16, one point", ":")):
                c = curves.get(es.case_name(fam, m, 0, step))
                if c:
                    ax.plot(100 * np.array(c["axial_strain"]), c["stress_ratio"], style, color=colour, lw=2,
                            label=f"{m} slow loading {label}")
        ax.set_xlim(3, 10)
        ax.set_ylim(0.24, 0.43)
        ax.set_title(f"{fam[0]}, member K = 0", fontsize=10)
        ax.set_xlabel("axial strain (%)")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    axs[0].set_ylabel("stress ratio (σ1 − σ2)/(σ1 + σ2)")
    fig.suptitle("[LBS] biaxial: slow loading against relaxed steps")
    fig.tight_layout()
    fig.savefig(os.path.join(analyse.results, "slow_loading.png"), dpi=120)


def main():
    curves = ls.curves_at_every_step()
    for step in [r[0] for r in RATES] + [STABILITY]:  # with the runs that stopped early, to their stop
        curves.update(es.stored_curves(CURVES, step, ended=stopped))
    old = sorted(c for c in curves if "_sl" in c and before_anti_windup(c))
    print(f"left out, run before the anti-windup ({ANTI_WINDUP}): {', '.join(old) or 'none'}")
    for c in old:
        del curves[c]
    plot(curves)
    print_runs(curves)
    print_member_spread(curves)
    print_rates_and_schemes(curves)
    print_mesh_spread(curves)
    print_widths({key: w for key, w in stored_widths(curves).items() if key[0] in curves})
    print_stability_modulus(curves)
    return 0


if __name__ == "__main__":
    sys.exit(main())
