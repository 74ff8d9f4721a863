#!/usr/bin/python3
"""[LSYF] problem 3 (issue 37): simple shear with one weakened RVE, local
and nonlocal. Reads RESULTS/problem3_*/ (CASES; run.sh problem3; a run that
stopped counts with its rows), prints the tables of the README and writes
into RESULTS:
  problem3_curves.png  tau/p of the volume average against the shear strain
  problem3_bands.png   the in-plane shear strain increment of the last 2 %
                       of shear at each IP (element centres), the weak IP marked
  problem3_rotation.png  the inner particles' mean rotation at the end at
                       each IP, for the runs that recorded it
  problem3_profiles.png  the band's profile across it: the row means of the
                       shear strain increment of the last 2 % against y, of
                       the elements' F and of what the RVEs saw, for FIXED_R
  problem3_profiles_r.png  the same for AGAINST_R (R = 5, 10, 15 mm on 12x20)
  problem3_width_history.png  the elements' F's profile width of each 4-row
                       window along the runs of CONVERGED and ENSEMBLES
  problem3.csv         per case and IP at the last row: position, band
                       membership, porosity, coordination, sliding fraction,
                       mean particle rotation

Stresses: the mean of the IPs' Cauchy stress (equal element volumes), tau =
|sigma_12|, p = -tr(sigma)/3. The band: benchmarks/lbs2018/band_width.py on
the increment of F's in-plane block over the last four rows (2 % of shear)
(and of F_nonlocal's, what the RVEs saw, in the table against R),
among all directions and among those within 20 degrees of x (ALONG_X);
inside = the IPs whose increment exceeds half the largest. Inside against
outside: porosity 1 - solid fraction, coordination 2C/N, the fraction of
sliding contacts, the inner particles' mean rotation (history.h5's
mean_rotation: mean |theta| accumulated since the RVE was built, in rad;
"-" for runs made before fe2dem recorded it), means over the IPs at the
last row.

Usage: problem3.py RESULTS   (Debian's python3 with numpy, h5py, matplotlib)
"""
import csv
import os
import re
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from band_tools import band_softening, inplane_band, plot_curves, print_ce_ratios  # noqa: E402
from problem3_cases import (AGAINST_R, ALONG_X, APPLIED, BACKWARDS, BAND_ROWS, CASES, CONVERGED, FINE_STEP,  # noqa: E402
                            FIXED_R, NU_E, OFF_BAND, PROBES, PROFILE_CASES, R_FAMILIES, RADII)
from problem3_ensembles import (ensemble_runs, print_against_r, print_half_step, print_last_check,  # noqa: E402
                                print_scatter, print_width_history)
from problem3_plots import plot_profiles  # noqa: E402
from problem3_runs import (curve, energy_shares, equilibrium, largest_difference, micro_fields,  # noqa: E402
                           nonlocal_weights, profile, read, rows_departure, shear_increment, weak_ip, weak_ips,
                           weak_stress)


def print_seed(results, done):
    """The weak RVEs at the end: their share of their own average (the run's weights of the weak IPs
    over those of all IPs, seen from the first weak one; 1 when local), the
    pressure and shear stress of their RVEs (Love-Weber) at the start and the end, and the volume
    change of the element (det F) against the one the RVE saw (det F_nonlocal)."""
    print("\n## the weak RVE(s), each (in the order of the IPs): their share of their own average, and what "
          "their RVE saw")
    print("| case | weak IPs | share of the weak IPs in the average | RVE's p, first row -> end (kPa) "
          "| RVE's tau at the end (kPa) | element's det F | RVE's det F |")
    print("|---|---|---|---|---|---|---|")
    for k, d in done.items():
        weak = weak_ips(d)
        x = d["ip_position"][:, :2]
        a = nonlocal_weights(os.path.join(results, CASES[k]), np.linalg.norm(x - x[weak[0]], axis=1))
        share = a[weak].sum() / a.sum()
        s, p = weak_stress(d)
        F, Fn = (d[f].reshape(len(d["step"]), -1, 3, 3)[-1, weak] for f in ("F", "F_nonlocal"))

        def each(v, fmt):
            return ", ".join(fmt.format(x) for x in v)

        print(f"| {k} | {len(weak)} | {share:.2f} | {each(p[0] / 1e3, '{:.0f}')} -> {each(p[-1] / 1e3, '{:.0f}')} "
              f"| {each(np.abs(s[-1, :, 0, 1]) / 1e3, '{:.0f}')} "
              f"| {each(np.linalg.det(F), '{:.3f}')} | {each(np.linalg.det(Fn), '{:.3f}')} |")


def ip_map(fig, ax, x, values, weak, title, cmap, weak_marker):
    """One panel: @p values at the IPs @p x (element centres, m) over the specimen, the weak IP marked."""
    sc = ax.scatter(1e3 * x[:, 0], 1e3 * x[:, 1], c=values, s=9600 / len(x), marker="s", cmap=cmap)
    ax.plot(1e3 * x[weak, 0], 1e3 * x[weak, 1], weak_marker)
    ax.set_title(title, fontsize=8)
    ax.set_aspect("equal")
    ax.set_xlim(0, 118)
    ax.set_ylim(0, 50.6)
    fig.colorbar(sc, ax=ax, shrink=0.8)


def plot_rotation(cases, path):
    """The mean particle rotation at the end at each IP, one panel per case."""
    if not cases:
        return
    fig, axes = plt.subplots(len(cases), 1, figsize=(7, 2.2 * len(cases)), squeeze=False)
    for ax, (k, d) in zip(axes[:, 0], cases.items()):
        ip_map(fig, ax, d["ip_position"], d["mean_rotation"][-1], weak_ip(d),
               f"{k}: mean particle rotation at the end (rad; x: the weak RVE)", "magma", "cx")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def print_profile_widths(results, cases):
    """The band as its row means across y (the profiles of problem3_profiles.png): the width above half
    the peak row mean, of the elements' F and of the averaged F. Chosen in session 39 after the
    finder (band_width.py) read 2 mm on 12x20: its bins, 1 degree off x and half a row high, held
    alternately more and fewer band IPs, so its half maximum was crossed one bin from the peak."""
    if not cases:
        return
    print(f"\n## the band's profile across y (row means of the shear strain increment of the last "
          f"{BAND_ROWS} rows): width above half its peak")
    print("| case | elements' F: width (mm) | at y (mm) | averaged F: width (mm) | at y (mm) |")
    print("|---|---|---|---|---|")
    for k in cases:
        cells = [f"{1e3 * v:.1f}" for field in ("F", "F_nonlocal") for v in profile(results, k, field)]
        print(f"| {k} | " + " | ".join(cells) + " |")


def print_convergence(results, done):
    """The banded answer at smaller macro steps and at half the rate against the reference
    (CONVERGED[0]; and FINE_STEP): tau/p of the mean stress at every row, the weak RVEs' pressure at
    the end, the row-mean profile and the IPs shearing backwards. Rows are equal fractions of the
    shear, so the half-rate run's rows are at the reference's strains."""
    ref, *variants = *CONVERGED, FINE_STEP
    if ref not in done or not any(k in done for k in variants):
        return

    def at_row(tp, row):
        return f"{tp[row]:.3f}" if row < len(tp) else "-"

    print("\n## converged? the reference (default macro step, 4 /s) at smaller macro steps and at half the rate")
    print("| case | largest difference of tau/p from the reference over the rows (at shear) | tau/p at 4 / 8 % "
          "| weak RVEs' p at the end (kPa) | profile width (mm): elements' / averaged F | its peak at y (mm) "
          f"| IPs below {BACKWARDS} | wall (s) |")
    print("|---|---|---|---|---|---|---|---|")
    for k in (ref, *variants):
        if k not in done:
            continue
        d = done[k]
        _, tp = curve(d)
        diff, at = largest_difference(d, done[ref])
        p = weak_stress(d)[1][-1]
        (w, y), (w_seen, y_seen) = (profile(results, k, f) for f in ("F", "F_nonlocal"))
        gamma = shear_increment(d["F"], len(d["step"]))
        wall = float(open(os.path.join(results, CASES[k], "wall_s")).read())
        print(f"| {k} | {diff:+.4f} ({100 * at:.1f} %) | {at_row(tp, 8)} / {at_row(tp, 16)} "
              f"| {', '.join(f'{v / 1e3:.0f}' for v in p)} | {1e3 * w:.1f} / {1e3 * w_seen:.1f} "
              f"| {1e3 * y:.1f} / {1e3 * y_seen:.1f} | {int((gamma < BACKWARDS).sum())} of {len(gamma)} | {wall:.0f} |")


def print_probes(results):
    """PROBES that exist: per row the hourglass share and the kinetic energy over the
    larger of the internal and external work, and the rows' sigma_22 departure at the last row."""
    probes = {k: c for k, c in PROBES.items() if os.path.exists(os.path.join(results, c, "wall_s"))}
    if not probes:
        return
    print("\n## which ingredient makes the hourglass forces do the work: the R = 20 mm own-volume case over its "
          "first 1 % of shear (two rows)")
    print("| case | hourglass share, row 1 / row 2 | kinetic energy / work, row 1 / row 2 "
          "| rows' sigma_22: largest departure / applied, row 2 | wall (s) |")
    print("|---|---|---|---|---|")
    for k, c in probes.items():
        share, kinetic = energy_shares(os.path.join(results, c))
        departure = rows_departure(read(os.path.join(results, c)), -1)
        wall = float(open(os.path.join(results, c, "wall_s")).read())
        print(f"| {k} | {' / '.join(f'{v:.3f}' for v in share)} | {' / '.join(f'{v:.3f}' for v in kinetic)} "
              f"| {departure:.2f} | {wall:.0f} |")


def print_equilibrium(results, done):
    """Every case's equilibrium (equilibrium()): the hourglass share and the rows' sigma_22."""
    print("\n## equilibrium of the points' stresses: the hourglass work's share of the work at the end "
          "(fe2dem warns above 0.1), and the largest departure of a row's mean sigma_22 from the applied "
          f"{APPLIED / 1e3:.0f} kPa over the run")
    print("| case | hourglass share | rows' sigma_22: largest departure / applied |")
    print("|---|---|---|")
    for k, d in done.items():
        share, rows = equilibrium(results, k, d)
        print(f"| {k} | {share:.3f}{' **(above 0.1)**' if share > 0.1 else ''} | {rows:.2f} |")


def print_softening(results, done):
    """The band's softening modulus in shear of the runs without C_e (band_tools.band_softening, tau
    = |sigma_12| of the mean stress) against C_e's shear modulus of the local elastic runs."""
    print("\n## the band's softening modulus in shear, H_s, against C_e's shear modulus")
    print("| case | peak at (shear) | tau peak -> end (kPa) | gamma in the band | H_s (MPa) |")
    print("|---|---|---|---|---|")
    moduli = []
    for k in ("local", "R = 15 mm", "local, 12x10"):
        if k not in done:
            continue
        tau = np.abs(done[k]["sigma"].mean(axis=1)[:, 1])
        peak, gamma, h_s = band_softening(os.path.join(results, CASES[k], "out", "history.h5"), tau)
        moduli.append(h_s)
        print(f"| {k} | {100 * done[k]['gamma_macro'][peak]:.1f} % | {tau[peak] / 1e3:.0f} -> {tau[-1] / 1e3:.0f} | "
              f"{gamma:.3f} | {h_s / 1e6:.3f} |")
    print_ce_ratios((5.84e8, 5e7, 2e6, 5e5), NU_E, moduli)


def print_curve_table(curves):
    """tau/p of the mean stress of every run (@p curves: {case: curve()}) every 1 % of shear."""
    print("## tau/p of the mean stress, every 1 % of shear")
    print("| shear strain | " + " | ".join(curves) + " |")
    print("|---" * (len(curves) + 1) + "|")
    g0 = next(iter(curves.values()))[0]
    for k in range(2, len(g0), 2):
        print(f"| {100 * g0[k]:.0f} % | " + " | ".join(f"{c[1][k]:.3f}" if k < len(c[1]) else "-"
                                                   for c in curves.values()) + " |")


def print_bands(results, done):
    """The band of every run (the increment over the last BAND_ROWS rows: among all directions,
    along x, and of the averaged F) and its inside against its outside at the end (table), the
    maps into problem3_bands.png. Returns (problem3.csv's rows, {case: (width along x, width of the
    averaged F)} in m)."""
    print(f"\n## the band (increment over the last {BAND_ROWS} rows), and inside against outside at the end")
    print("| case | band width (mm) | angle (deg from x) | band middle y (mm) | along x: width (mm) | angle "
          "| weak IP in the band | porosity in / out "
          "| coordination in / out | sliding fraction in / out | mean rotation (rad) in / out |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    fig, axes = plt.subplots(len(done), 1, figsize=(7, 2.2 * len(done)), squeeze=False)
    rows, widths = [], {}
    for ax, (k, d) in zip(axes[:, 0], done.items()):
        history, weak = os.path.join(results, CASES[k], "out", "history.h5"), weak_ip(d)
        x, gamma, width, angle, middle = inplane_band(history, BAND_ROWS)
        _, _, width_x, angle_x, _ = inplane_band(history, BAND_ROWS, ALONG_X)
        _, _, width_seen, _, _ = inplane_band(history, BAND_ROWS, ALONG_X, "F_nonlocal")
        widths[k] = (width_x, width_seen)
        inside = gamma > 0.5 * gamma.max()
        porosity, coordination, sliding, rotation = micro_fields(d).values()

        def in_out(v):
            return "-" if np.isnan(v).all() else f"{v[inside].mean():.3f} / {v[~inside].mean():.3f}"

        print(f"| {k} | {1e3 * width:.1f} | {angle:.0f} | {1e3 * middle:.1f} | {1e3 * width_x:.1f} | {angle_x:.0f} | "
              f"{'yes' if inside[weak] else 'no'} | "
              f"{in_out(porosity)} | {in_out(coordination)} | {in_out(sliding)} | {in_out(rotation)} |")
        rows += [[k, f"{x[i, 0]:.5f}", f"{x[i, 1]:.5f}", int(inside[i]), f"{porosity[i]:.4f}",
                  f"{coordination[i]:.3f}", f"{sliding[i]:.3f}", f"{rotation[i]:.4f}"] for i in range(len(x))]
        ip_map(fig, ax, x, gamma, weak, f"{k}: band along x {1e3 * width_x:.1f} mm wide (x: the weak RVE)",
               "viridis", "rx")
    fig.tight_layout()
    fig.savefig(os.path.join(results, "problem3_bands.png"), dpi=110)
    return rows, widths


def print_widths_against_r(widths):
    """The band width along x of RADII's runs against R and the element (@p widths: print_bands')."""
    radii = [(r, h, k) for r, h, k in RADII if k in widths]
    if not radii:
        return
    print("\n## band width (along x) against R and the element (local elastic: C_e of the E named)")
    print("| case | R (mm) | element height (mm) | band width (mm) | width / R | width / element "
          "| from the averaged F (mm) | width / R |")
    print("|---|---|---|---|---|---|---|---|")
    for r, h, k in radii:
        w, w_seen = (1e3 * v for v in widths[k])
        per_r = (lambda v: f"{v / r:.2f}") if r else (lambda v: "-")
        print(f"| {k} | {r:g} | {h:g} | {w:.1f} | {per_r(w)} | {w / h:.2f} | {w_seen:.1f} | {per_r(w_seen)} |")


def print_signed_increment(done):
    """The soft mode of the total-strain average (user guide, 'Nonlocal operator'): the elements' own
    signed shear increment, the weak one against the rest and off the band (the IPs more than OFF_BAND
    from the weak IP's row), the element-scale scatter of the increment and of its part the RVEs do
    not see (own minus averaged)."""
    print(f"\n## the elements' signed shear increment dF12 + dF21 over the last {BAND_ROWS} rows")
    print("| case | weak IP | mean | largest | smallest | IPs shearing backwards "
          "| std off the band | own - averaged: std off the band |")
    print("|---|---|---|---|---|---|---|---|")
    for k, d in done.items():
        g, g_seen = (shear_increment(d[f], len(d["step"])) for f in ("F", "F_nonlocal"))
        weak = weak_ip(d)
        off = np.abs(d["ip_position"][:, 1] - d["ip_position"][weak, 1]) > OFF_BAND
        print(f"| {k} | {g[weak]:.4f} | {g.mean():.4f} | {g.max():.4f} | {g.min():.4f} "
              f"| {int((g < 0).sum())} of {len(g)} | {g[off].std():.4f} | {(g - g_seen)[off].std():.4f} |")


def print_cost(results, done):
    """Every finished case's ranks, wall, RVE count and DEM steps (summed over the RVEs)."""
    print("\n## cost (on the 2-core VM, walls shared with other runs)")
    print("| case | ranks | wall (s) | RVEs | DEM steps (all RVEs) |")
    print("|---|---|---|---|---|")
    for k, c in CASES.items():
        if k in done:
            with open(os.path.join(results, c, "out", "summary.csv")) as f:
                dem = sum(int(r["dem_steps"]) for r in csv.DictReader(f))
            wall = float(open(os.path.join(results, c, "wall_s")).read())
            ranks = re.search(r"RVEs on (\d+) rank", open(os.path.join(results, c, "log")).read()).group(1)
            print(f"| {k} | {ranks} | {wall:.0f} | {len(done[k]['ip_position'])} | {dem:.3g} |")


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    results = sys.argv[1]
    done = {k: read(os.path.join(results, c)) for k, c in CASES.items()
            if os.path.exists(os.path.join(results, c, "wall_s"))}
    if not done:
        sys.exit("problem3.py: no finished run in " + results)

    curves = {k: curve(d) for k, d in done.items()}
    print_curve_table(curves)
    print_softening(results, done)
    rows, widths = print_bands(results, done)
    plot_rotation({k: d for k, d in done.items() if d["mean_rotation"] is not None},
                  os.path.join(results, "problem3_rotation.png"))
    plot_profiles(results, [k for k in FIXED_R if k in done], os.path.join(results, "problem3_profiles.png"))
    plot_profiles(results, [k for k in AGAINST_R if k in done], os.path.join(results, "problem3_profiles_r.png"))
    print_profile_widths(results, [k for k in PROFILE_CASES if k in done])
    print_convergence(results, done)
    ensembles = ensemble_runs(done)
    groups = dict(ensembles)
    if ensembles:
        groups["the step series at 4 /s (2, 1, 0.5 us, 1 us with checks of 5)"] = [k for k in CONVERGED[:-1] if k in done]
    print_scatter(results, done, ensembles, groups)
    print_width_history(results, done, groups, os.path.join(results, "problem3_width_history.png"))
    for name, family in R_FAMILIES.items():
        png = "problem3_against_r.png" if name == "own volume" else f"problem3_against_r_{name.split()[0]}.png"
        print_against_r(results, done, name, family, os.path.join(results, png))
    print_half_step(results, done)
    print_last_check(results, done)
    print_equilibrium(results, done)
    print_probes(results)
    with open(os.path.join(results, "problem3.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case", "x", "y", "in_band", "porosity", "coordination", "sliding_fraction", "mean_rotation"])
        w.writerows(rows)
    print_widths_against_r(widths)
    print_signed_increment(done)
    print_seed(results, done)
    print_cost(results, done)
    plot_curves(curves, "shear strain (%)", "tau/p of the mean stress", os.path.join(results, "problem3_curves.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
