"""problem3.py's tables over ensembles (a run and its runs with the top's pressure a few ppm
higher): the width's scatter at one macro step and against the step, its history along the runs,
and the width against R with the inside of the band against its outside (ensemble means)."""
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from band_tools import inplane_band  # noqa: E402
from ensemble_stats import linear_fit, mean_difference, permutation_p  # noqa: E402
from problem3_cases import (BAND_ROWS, CASES, CONVERGED, ENSEMBLES, FAMILY_STEP, HALF_STEP,  # noqa: E402
                            LAST_CHECK, LOAD_STEPS, PERTURBED, R_FAMILIES, SHEAR)
from problem3_plots import plot_against_r  # noqa: E402
from problem3_runs import (curve, largest_difference, micro_fields, print_run_header, print_run_row,  # noqa: E402
                           profile)


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


def print_step_fit(stats):
    """The ensembles' mean widths against the macro step, w = w0 + k dt (@p stats: {"at STEP us":
    widths [runs, (elements' F, averaged F)] in mm}; linear_fit): w0 is the width extrapolated to
    dt = 0."""
    dt = np.array([float(label.split()[1]) for label in stats])
    for name, (w0, k, chi2) in linear_fit(dt, stats.values()):
        print(f"- {name}: fit of the means against the step, w0 = {w0[0]:.1f} +- {w0[1]:.1f} mm "
              f"at dt = 0, k = {k[0]:+.1f} +- {k[1]:.1f} mm/us; chi^2 {chi2:.1f} on {len(dt) - 2} "
              "degree(s) of freedom")


def print_step_permutation(stats, what="the step", groups="steps"):
    """Does @p what (the step) matter at all? The exact permutation test of the one-way layout: every
    split of the pooled runs into groups of the ensembles' sizes, and the fraction whose between-group
    sum of squares reaches the measured one (the p value: how often @p groups that did not matter
    would look as different by chance). Added in session 43 after three of the four 0.2 us runs were
    seen, beside the fit (print_step_fit), which assumes the width moves monotonically."""
    for col, name in enumerate(("elements' F", "averaged F")):
        reached, total = permutation_p([w[:, col] for w in stats.values()])
        print(f"- {name}: is {what}'s effect more than chance? exact permutation test over the "
              f"{len(stats)} {groups}: p = {reached / total:.3f} ({reached} of {total} splits as far apart)")


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
