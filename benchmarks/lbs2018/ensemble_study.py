#!/usr/bin/python3
"""The spread over the meshes after the peak from ensemble means (issue 37).

A single post-peak curve of this specimen moves by up to 29 % at one step
from rounding alone (README, "The band width over three meshes, and what
rounding does"): the row at which one run has dropped and another not yet
sets the largest spread of single runs. Here each mesh of the local and the
local elastic families (R = 2.5 mm; R = 5 mm from session 49; 2x4, 4x8, 8x16
one point; 0.125 % steps) runs as an ensemble whose members differ only in
the sixth digit of the lateral pressure (run.sh CASE_pK), and the spread
over the meshes is taken of the ensembles' mean curves.

Usage: ensemble_study.py   (Debian's python3 with numpy)

Reads results/ensemble_curves.csv (every member's stage-2 stress ratio, so
that the tables regenerate without runs/, which is not committed), updates it
with the members in runs/CASE[_pK]/summary.csv (run.sh), and prints:
- per family and member K the single-run spread over the meshes (every mesh's
  member K), beside the spread of the ensemble means, from the peak of the
  family's mean curve to 10 %: mean and largest, and from 7.5 % on; over the
  three meshes, over 2x4 and 4x8 alone (session 30's pair), and over 4x8 and 8x16
  one point (the meshes that resolve R); beside each spread of means its ratios to the
  local family's over the same members (the criterion: at most 0.5), and with four members
  the spread of the means of every three of them;
- per mesh the members' own spread (max - min over mean at each step, from
  the peak of their mean): what one mesh scatters by, the noise under a
  single-run spread;
- every member's peak (ratio and axial strain), the first row DROP below it (the onset of
  softening) and its ratio at 10 %;
- per mesh the members' band widths (band_study.py's half-share width and inclined FWHM of the
  shear strain increment over 7.5-10 % and 9-10 %), each and their mean and standard deviation,
  stored in results/ensemble_widths.csv (computed from runs/CASE/history.h5, kept without it);
and draws results/ensemble_curves.png: per family every finished member
(thin) and each mesh's mean of two or more members (thick), from 4 %.
"""
import csv
import os
import sys

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import analyse  # noqa: E402  (curve(): the study's reading of summary.csv)
import band_study  # noqa: E402  (the band width of one run over an interval)
import band_width as bw  # noqa: E402
from nonlocal_study import spread_after_peak  # noqa: E402

CURVES = os.path.join(analyse.results, "ensemble_curves.csv")
WIDTHS = os.path.join(analyse.results, "ensemble_widths.csv")
MESHES = [("2x4", "2x4"), ("4x8", "4x8"), ("8x16, one point", "8x16_op")]  # label, run.sh's mesh part
# label, prefix, suffix; R = 5 mm (session 49): the R at which 2x4 resolves R too (README)
FAMILIES = [("local", "mesh", ""), ("local elastic R = 2.5 mm", "nonlocal", "_le"),
            ("local elastic R = 5 mm", "nonlocal", "_R5_le")]
# element size (mm) per mesh label, from band_study.py's cases (the same labels)
ELEMENT_MM = {m: h for _, cases in band_study.FAMILIES for _, m, h in cases}
MEMBERS = (0, 1, 2, 3)  # K: the lateral pressure 1.5e5 (1 + K 1e-6) N/m (run.sh _pK); K = 0 the case itself
DROP = 0.02         # the onset of softening: the first row this far below the curve's peak
LATE = 0.075         # band_study.py's second interval: every run has dropped by 7.5 %


def case_name(family, mesh, k, step="_quarter"):
    """run.sh's name of member @p k of @p family on the mesh labelled @p mesh at stage 2's load
    step @p step (run.sh's _quarter: 0.125 %, _eighth: 0.0625 %), e.g. nonlocal_8x16_op_le_quarter_p2."""
    _, prefix, suffix = family
    return f"{prefix}_{dict(MESHES)[mesh]}{suffix}{step}" + (f"_p{k}" if k else "")


def stored_curves(path=CURVES, step="_quarter", ended=None):
    """{case: {axial_strain, stress_ratio}} of every member at load step @p step: the file @p path,
    updated with the finished members that runs/ holds (and written back, so that a partial runs/
    never drops a stored member). @p ended(case): also store that case's run if it ended before 10 %
    (default: none is)."""
    out = {}
    if os.path.exists(path):
        for r in csv.DictReader(open(path)):
            v = out.setdefault(r["case"], {"axial_strain": [], "stress_ratio": []})
            v["axial_strain"].append(float(r["axial_strain"]))
            v["stress_ratio"].append(float(r["stress_ratio"]))
    names = [case_name(f, m, k, step) for f in FAMILIES for m, _ in MESHES for k in MEMBERS]
    # Only runs that are over: a run still under way must not be stored as a member.
    ran = {c: v for c, v in ((c, analyse.curve(c)) for c in names) if is_over(c, v, ended)}
    if ran:
        out.update({c: {k: ran[c][k] for k in ("axial_strain", "stress_ratio")} for c in ran})
        with open(path, "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(["case", "axial_strain", "stress_ratio"])
            for c in sorted(out):
                w.writerows([c, f"{e:.6g}", f"{r:.6g}"] for e, r in zip(out[c]["axial_strain"], out[c]["stress_ratio"]))
    if not out:
        sys.exit(f"{os.path.basename(sys.argv[0])}: no member in runs/ and no {path} (run.sh CASE_pK ...)")
    return out


def member_widths(case):
    """{(from, to): (half-share width, inclined FWHM)} in m of @p case's shear strain increment
    (band_study.py's measures; the FWHM is nan where the profile does not fall to half on both
    sides)."""
    _, ratio, _ = band_study.stage2(case)
    coulomb = bw.coulomb_angle(ratio.max())
    out = {}
    for a, b in band_study.INTERVALS:
        pts, g = band_study.increment(case, a, b)
        out[(a, b)] = (bw.half_share_width(g, band_study.HEIGHT, coulomb),
                       bw.band_width(pts, g, band_angles=bw.INCLINED)[0])
    return out


def stored_widths(curves):
    """{case: member_widths(case)} of every finished member: WIDTHS, updated with the members
    whose history.h5 runs/ holds (and written back)."""
    out = {}
    if os.path.exists(WIDTHS):
        for r in csv.DictReader(open(WIDTHS)):
            out.setdefault(r["case"], {})[(float(r["from"]), float(r["to"]))] = (
                float(r["half_share_width_m"]), float(r["fwhm_inclined_m"]))
    names = [case_name(f, m, k) for f in FAMILIES for m, _ in MESHES for k in MEMBERS]
    fresh = [c for c in names if finished(curves, c)
             and os.path.exists(os.path.join(band_study.runs, c, "history.h5"))]
    if fresh:
        out.update({c: member_widths(c) for c in fresh})
        with open(WIDTHS, "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(["case", "from", "to", "half_share_width_m", "fwhm_inclined_m"])
            for c in sorted(out):
                w.writerows([c, f"{a:g}", f"{b:g}", f"{h:.6g}", f"{f:.6g}"] for (a, b), (h, f) in sorted(out[c].items()))
    return out


def print_widths(curves, widths):
    """The members' band widths per mesh, and the spread of the meshes' means per family."""
    ivs = sorted(band_study.INTERVALS)  # 7.5-10 % first
    print("\n| family | mesh | element | members | "
          + " | ".join(f"half share {100 * a:g}-{100 * b:g} %: members (mm) | mean ± sd" for a, b in ivs)
          + f" | inclined FWHM {100 * ivs[0][0]:g}-{100 * ivs[0][1]:g} % found |\n" + "|---" * (5 + 2 * len(ivs)) + "|")
    for fam in FAMILIES:
        means = []
        for m, _ in MESHES:
            cases = [c for c in finished_members(curves, fam, m) if c in widths]
            if not cases:
                continue
            cells = []
            for iv in ivs:
                v = 1e3 * np.array([widths[c][iv][0] for c in cases])
                sd = f" ± {v.std(ddof=1):.1f}" if len(v) > 1 else ""
                cells += [" / ".join(f"{x:.1f}" for x in v), f"{v.mean():.1f}{sd}"]
                if iv == ivs[0]:
                    means.append(v.mean())
            found = sum(not np.isnan(widths[c][ivs[0]][1]) for c in cases)
            print(f"| {fam[0]} | {m} | {ELEMENT_MM[m]:g} mm | {len(cases)} | " + " | ".join(cells)
                  + f" | {found} of {len(cases)} |")
        if len(means) > 1:
            print(f"| {fam[0]} | range of the means, {100 * ivs[0][0]:g}-{100 * ivs[0][1]:g} % | | | "
                  f"{max(means) - min(means):.1f} mm |" + " |" * (2 * len(ivs)))


def reached_end(curve):
    """Whether @p curve (analyse.curve's dict) reached 10 % axial strain (a run just started has no rows)."""
    return bool(curve["axial_strain"]) and abs(curve["axial_strain"][-1] - 0.10) < 1e-6


def is_over(case, curve, ended=None):
    """Whether run @p case, whose summary.csv reads as @p curve (analyse.curve), is over: it reached
    10 %, or @p ended(case) says it ended before (stored_curves)."""
    return bool(curve) and (reached_end(curve) or (ended is not None and ended(case)))


def finished(curves, c):
    """Whether case @p c reached 10 % axial strain."""
    return c in curves and reached_end(curves[c])


def finished_members(curves, fam, mesh):
    """The cases of @p fam's members on @p mesh that reached 10 %, in the order of MEMBERS."""
    return [case_name(fam, mesh, k) for k in MEMBERS if finished(curves, case_name(fam, mesh, k))]


def mean_curve(curves, cases):
    """{axial_strain, stress_ratio}: the mean over @p cases, which share their rows (the same steps)."""
    return {"axial_strain": curves[cases[0]]["axial_strain"],
            "stress_ratio": list(np.mean([curves[c]["stress_ratio"] for c in cases], axis=0))}


def drop_at(curve):
    """The axial strain of the first row DROP below @p curve's highest ratio up to that row: where it
    softens, also when a plateau's second maximum is the highest."""
    r = np.array(curve["stress_ratio"])
    below = r < np.maximum.accumulate(r) - DROP
    return curve["axial_strain"][int(np.argmax(below))] if below.any() else float("nan")  # nan: never softens


def summary(pts):
    """(peak at, mean, largest, mean from LATE, largest from LATE) of spread_after_peak's points (the
    last two nan if the points end before LATE)."""
    e, s = np.array(pts).T
    late = s[e >= LATE - 1e-9]
    if not late.size:
        return e[0], s.mean(), s.max(), float("nan"), float("nan")
    return e[0], s.mean(), s.max(), late.mean(), late.max()


def common_members(curves, fam, meshes):
    """The members K of @p fam that every mesh labelled @p meshes finished."""
    return [k for k in MEMBERS if all(finished(curves, case_name(fam, m, k)) for m in meshes)]


def spread_of_means(curves, fam, meshes, members):
    """summary() of the spread over @p meshes of @p fam's mean curves of @p members (one member:
    its own curves)."""
    means = {m: mean_curve(curves, [case_name(fam, m, k) for k in members]) for m in meshes}
    return summary(spread_after_peak(means, list(meshes))[0])


def against_local(curves, fam, meshes, members, s):
    """The criterion's ratios of summary @p s (mean, largest) to the local family's over the same
    @p members and meshes, like for like; '' for one member, for local itself, or where local
    lacks one of the members."""
    local = FAMILIES[0]
    if fam is local or len(members) < 2 or not set(members) <= set(common_members(curves, local, meshes)):
        return ""
    ref = spread_of_means(curves, local, meshes, members)
    return f"{s[1] / ref[1]:.2f}, {s[2] / ref[2]:.2f} (local {100 * ref[1]:.3g} / {100 * ref[2]:.3g} %)"


def print_spread_over(curves, meshes):
    """The first table's rows for the meshes labelled @p meshes: every member K that all of them
    finished (its single-run spread over them); with two such members or more, the spread over
    them of their ensemble means, against local's over the same members; with four or more, also
    the means of every set that leaves one member out (how much one member moves the ratio)."""
    for fam in FAMILIES:
        members = common_members(curves, fam, meshes)
        sets = [(f"member K = {k}", [k]) for k in members]
        if len(members) >= 2:
            sets.append((f"ensemble means of K = {', '.join(map(str, members))}", members))
        if len(members) >= 4:
            sets += [(f"means without K = {k}", [j for j in members if j != k]) for k in members]
        for label, ks in sets:
            s = spread_of_means(curves, fam, meshes, ks)
            print(f"| {fam[0]} | {', '.join(meshes)} | {label} | "
                  + " | ".join(f"{100 * v:.3g} %" for v in s) + f" | {against_local(curves, fam, meshes, ks, s)} |")


def plot(curves):
    """results/ensemble_curves.png: the members and their means, one panel per family."""
    fig, axs = plt.subplots(1, len(FAMILIES), figsize=(4 * len(FAMILIES), 4.5), sharey=True)
    for ax, fam in zip(axs, FAMILIES):
        for (m, _), colour in zip(MESHES, ("tab:blue", "tab:orange", "tab:green")):
            done = finished_members(curves, fam, m)
            for c in done:
                ax.plot(100 * np.array(curves[c]["axial_strain"]), curves[c]["stress_ratio"], color=colour,
                        lw=0.7, alpha=0.6)
            if len(done) >= 2:
                mean = mean_curve(curves, done)
                ax.plot(100 * np.array(mean["axial_strain"]), mean["stress_ratio"], color=colour, lw=2.2,
                        label=f"{m}: mean of {len(done)}")
            elif done:
                ax.lines[-1].set_label(f"{m}: one member")
        ax.set_xlim(4, 10)
        ax.set_ylim(0.24, 0.43)
        ax.set_title(fam[0])
        ax.set_xlabel("axial strain (%)")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    axs[0].set_ylabel("stress ratio (σ1 − σ2)/(σ1 + σ2)")
    fig.suptitle("[LBS] biaxial, 0.125 % steps: ensemble members (lateral pressure +K ppm) and their means")
    fig.tight_layout()
    fig.savefig(os.path.join(analyse.results, "ensemble_curves.png"), dpi=120)


def main():
    curves = stored_curves()
    plot(curves)
    print(f"\n| family | meshes | curves | peak of the mean at | spread after it: mean | largest | "
          f"from {100 * LATE:g} %: mean | largest | against local (same members): mean, largest |\n"
          + "|---" * 9 + "|")
    print_spread_over(curves, [m for m, _ in MESHES])
    print_spread_over(curves, [m for m, _ in MESHES[:2]])  # 2x4, 4x8: session 30's pair of meshes
    # 4x8, 8x16 one point: the two meshes that resolve R = 2.5 mm (an interior IP keeps 0.51-0.54 of
    # its own average there, 0.995 on 2x4: README, session 47); added in session 48, after 2x4 was
    # found unresolved, beside the criterion's meshes rather than instead of them
    print_spread_over(curves, [m for m, _ in MESHES[1:]])

    print("\n| family | mesh | members | their spread after the peak of their mean: mean | largest |\n"
          + "|---" * 5 + "|")
    for fam in FAMILIES:
        for m, _ in MESHES:
            cases = finished_members(curves, fam, m)
            if len(cases) < 2:
                continue
            pts, _ = spread_after_peak(curves, cases)
            e, s = np.array(pts).T
            print(f"| {fam[0]} | {m} | {len(cases)} | {100 * s.mean():.3g} % | {100 * s.max():.3g} % |")

    print(f"\n| family | mesh | member K | peak | at | {DROP:g} below it at | ratio at 10 % |\n" + "|---" * 7 + "|")
    for fam in FAMILIES:
        for m, _ in MESHES:
            for k in MEMBERS:
                c = case_name(fam, m, k)
                if finished(curves, c):
                    r, e = curves[c]["stress_ratio"], curves[c]["axial_strain"]
                    i = int(np.argmax(r))
                    print(f"| {fam[0]} | {m} | {k} | {r[i]:.4f} | {100 * e[i]:.4g} % | {100 * drop_at(curves[c]):.4g} % "
                          f"| {r[-1]:.3f} |")

    print_widths(curves, stored_widths(curves))
    return 0


if __name__ == "__main__":
    sys.exit(main())
