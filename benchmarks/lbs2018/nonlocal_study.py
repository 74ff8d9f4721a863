#!/usr/bin/python3
"""The [LBS] biaxial test local against nonlocal (issue 37): the meshes'
spread after the peak, the shear-band width on each mesh and in DNS B, maps
of the strain increment after the peak.

Usage: nonlocal_study.py [DIR]   (Debian's python3 with numpy, matplotlib, h5py)

Reads runs/{mesh,nonlocal}_{1x1,1x2,2x4,4x8,8x16}/ and runs/dns_B/particles/
(run.sh), writes into results/:
  nonlocal_curves.png         stress ratio against axial strain, every family
  nonlocal_spread.csv         per step from the peak to 10 %: (max - min)/mean
                              of the stress ratio over the meshes, local and nonlocal
  nonlocal_band_width.csv     band width (band_width.py) per case and in DNS B
  nonlocal_bands.png          shear strain increment of the last step per IP
and prints the tables of the README. The band is measured on the increment
of the last load step (9.5 to 10 % axial strain, or the last step a run
reached): bands move after the peak, and over several steps the increments
of successive bands add up. DNS B: its dumps at 9 and 10 %.
"""
import csv
import os
import sys

import h5py
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import analyse  # noqa: E402  (curve(), run_info(): the same reading as the study's)
import band_width as bw  # noqa: E402

runs, results = analyse.runs, analyse.results
MESHES = ["1x1", "1x2", "2x4", "4x8", "8x16"]
BAND_FROM, BAND_TO = 0.09, 0.10    # DNS B: the dumps around the last step (every second row)
FAMILIES = {"local": ("mesh_{}", "local"),                      # case pattern, label
            "nonlocal R = 2.5 mm": ("nonlocal_{}", "R 2.5"),
            "nonlocal R = 5 mm": ("nonlocal_{}_R5", "R 5"),
            "local, one point": ("mesh_{}_op", "local 1pt"),
            "nonlocal R = 2.5 mm, one point": ("nonlocal_{}_op", "R 2.5 1pt"),
            "local elastic R = 2.5 mm": ("nonlocal_{}_le", "LE 2.5"),
            "local elastic R = 5 mm": ("nonlocal_{}_R5_le", "LE 5"),
            "local elastic R = 5 mm, one point": ("nonlocal_{}_op_R5_le", "LE 5 1pt"),
            "local elastic R = 2.5 mm, C_e / 2": ("nonlocal_{}_le3e6", "LE 2.5 C/2"),
            "local, 0.25 % steps": ("mesh_{}_half", "local 0.25"),
            "local elastic R = 2.5 mm, 0.25 % steps": ("nonlocal_{}_le_half", "LE 2.5 0.25"),
            "local, 0.125 % steps": ("mesh_{}_quarter", "local 0.125"),
            "local elastic R = 2.5 mm, 0.125 % steps": ("nonlocal_{}_le_quarter", "LE 2.5 0.125")}
STEP_SUFFIXES = {"": "0.5 %", "_half": "0.25 %", "_quarter": "0.125 %"}  # stage 2's load step


def relative_spread(r, axis=None):
    """(max - min) / mean of the stress ratios `r` (over `axis`)."""
    r = np.asarray(r)
    return (r.max(axis=axis) - r.min(axis=axis)) / r.mean(axis=axis)


def spread_after_peak(curves, cases):
    """[(axial strain, (max - min)/mean)] over `cases` from the peak of their mean to the end."""
    have = [c for c in cases if curves.get(c)]
    if len(have) < 2:
        return [], have
    n = min(len(curves[c]["stress_ratio"]) for c in have)
    r = np.array([curves[c]["stress_ratio"][:n] for c in have])
    eps = np.array(curves[have[0]]["axial_strain"][:n])
    peak = int(np.argmax(r.mean(axis=0)))
    s = relative_spread(r, axis=0)
    return [(eps[k], s[k]) for k in range(peak, n)], have


def dns_band():
    """(points, gamma, width, angle) of DNS B from 9 % to 10 % (rows 10 + 18 and 10 + 20)."""
    rows = [analyse.ISO_STEPS + round(e / 0.005) for e in (BAND_FROM, BAND_TO)]
    paths = [os.path.join(runs, "dns_B", "particles", f"step{r:04d}.particles") for r in rows]
    if not all(os.path.exists(p) for p in paths):
        return None
    pts, g = bw.particle_field(*paths)
    w, ang, _ = bw.band_width(pts, g)
    return pts, g, w, ang


def main():
    os.makedirs(results, exist_ok=True)
    info = analyse.run_info()
    families = {f: [pattern.format(m) for m in MESHES] for f, (pattern, _) in FAMILIES.items()}
    curves = {c: analyse.curve(c) if c in info else None for f in families.values() for c in f}

    fig, axs = plt.subplots(1, 2, figsize=(12, 4.5), sharey=True)
    local_elastic = [f.startswith("local elastic") for f in families]
    styles = ("--", "-", ":", "-.", (0, (1, 3)), "-", ":", (0, (1, 3)), "-.", (0, (5, 1)), (0, (5, 1)),
              (0, (3, 1, 1, 1)), (0, (3, 1, 1, 1)))
    for fam, style, le in zip(families, styles, local_elastic):
        ax = axs[1] if le else axs[0]
        if fam == "local":  # the reference in both panels
            for k, c in enumerate(families[fam]):
                if curves[c]:
                    axs[1].plot(100 * np.array(curves[c]["axial_strain"]), curves[c]["stress_ratio"],
                                linestyle="--", color=f"C{k}", alpha=0.5, label=f"local {c.split('_')[1]}")
        for k, c in enumerate(families[fam]):
            if curves[c]:
                ax.plot(100 * np.array(curves[c]["axial_strain"]), curves[c]["stress_ratio"], linestyle=style,
                        color=f"C{k}", label=f"{FAMILIES[fam][1]} {c.split('_')[1]}")
    axs[0].set_title("total strain ([LSYF]): local (dashed), R = 2.5 mm (solid), 5 mm (dotted);\n"
                     "one point per element: local (dash-dot), R = 2.5 mm (loose dots)", fontsize=8)
    axs[1].set_title("local elastic: R = 2.5 mm (solid; C_e / 2 dash-dot), 5 mm (dotted),\n"
                     "one point R = 5 mm (loose dots); local (faint dashed)", fontsize=8)
    for ax in axs:
        ax.set_xlabel("axial strain (%)")
        ax.legend(fontsize=7, ncol=2)
        ax.grid(alpha=0.3)
    axs[0].set_ylabel("average stress ratio")
    fig.tight_layout()
    fig.savefig(os.path.join(results, "nonlocal_curves.png"), dpi=120)

    # spread over the meshes able to hold a band (2x4 and finer) and over all
    table = {}
    with open(os.path.join(results, "nonlocal_spread.csv"), "w") as fh:
        fh.write("meshes,family,axial_strain,spread\n")
        for label, meshes in (("2x4-and-finer", MESHES[2:]), ("all", MESHES)):
            for fam in families:
                pts, have = spread_after_peak(curves, [FAMILIES[fam][0].format(m) for m in meshes])
                for e, s in pts:
                    fh.write(f"{label},{fam},{e:.6g},{s:.6g}\n")
                table[(label, fam)] = (pts, have)
    print("\n| meshes | family | cases | peak of the mean at | spread from it to 10 %: mean | max |\n"
          "| --- | --- | --- | --- | --- | --- |")
    for (label, fam), (pts, have) in table.items():
        if pts:
            s = np.array([p[1] for p in pts])
            print(f"| {label} | {fam} | {' '.join(c.split('_')[1] for c in have)} | {100 * pts[0][0]:.1f} % "
                  f"| {100 * s.mean():.1f} % | {100 * s.max():.1f} % |")

    # the same spreads step by step from 5 % on, every family on one window (2x4 and finer)
    print("\n| family (2x4 and finer) | " + " | ".join(f"{e:.1f} %" for e in np.arange(5.0, 10.01, 0.5)) + " |\n"
          + "| --- " * 12 + "|")
    for fam in families:
        have = [c for c in (FAMILIES[fam][0].format(m) for m in MESHES[2:]) if curves.get(c)]
        if len(have) < 2:
            continue
        row = []
        for e in np.arange(0.05, 0.1001, 0.005):
            r = [curves[c]["stress_ratio"][k] for c in have
                 for k in [int(np.argmin(np.abs(np.array(curves[c]["axial_strain"]) - e)))]
                 if abs(curves[c]["axial_strain"][k] - e) < 1e-4]
            row.append(f"{100 * relative_spread(r):.1f} %" if len(r) == len(have) else "-")
        print(f"| {fam} ({' '.join(c.split('_')[1] for c in have)}) | " + " | ".join(row) + " |")

    # the load step: each run at a finer step against the same run at the next coarser one, at the
    # coarser one's rows from 5 %
    print("\n| case | steps | against | largest difference from 5 % | at | mean |\n| --- | --- | --- | --- | --- | --- |")
    suffixes = list(STEP_SUFFIXES)
    for base in ("mesh_{}", "nonlocal_{}_le"):
        for m in MESHES:
            for coarse, fine in zip(suffixes, suffixes[1:]):
                a, b = base.format(m) + coarse, base.format(m) + fine
                if not (curves.get(a) and curves.get(b)):
                    continue
                diffs, fine_strain = [], np.array(curves[b]["axial_strain"])
                for e, r in zip(curves[a]["axial_strain"], curves[a]["stress_ratio"]):
                    k = int(np.argmin(np.abs(fine_strain - e)))
                    if e >= 0.05 - 1e-9 and abs(fine_strain[k] - e) < 1e-4:
                        diffs.append((abs(curves[b]["stress_ratio"][k] - r) / r, e))
                worst = max(diffs)
                print(f"| {base.format(m)} | {STEP_SUFFIXES[fine]} | {STEP_SUFFIXES[coarse]} | {100 * worst[0]:.1f} % "
                      f"| {100 * worst[1]:.1f} % | {100 * np.mean([d for d, _ in diffs]):.1f} % |")

    # band widths: the last load step's increment (bands move: over several steps the
    # increments of different bands add up), of F and, with the operator, of the F the RVEs saw
    widths = []
    for fam, cases in families.items():
        for c in cases:
            if not curves[c] or len(curves[c]["axial_strain"]) < 2:
                continue
            path = os.path.join(runs, c, "history.h5")
            with h5py.File(path, "r") as h:
                n, end_strain, n_ip = len(h["step"]), h["axial_strain"][-1], h["ip_position"].shape[0]
                fields = ["F"] + (["F_nonlocal"] if "F_nonlocal" in h else [])
            if n_ip < 32:
                continue
            cells = c.split("_")[1].split("x")
            for field in fields:
                pts, g = bw.ip_field(path, n - 2, n - 1, field)
                w, ang, _ = bw.band_width(pts, g)
                widths.append((c, fam, field, 10.0 / int(cells[0]), end_strain, w, ang, pts, g))
    dns = dns_band()
    with open(os.path.join(results, "nonlocal_band_width.csv"), "w") as fh:
        fh.write("case,family,field,element_size_mm,last_step_end_axial_strain,band_width_mm,band_angle_deg\n")
        for c, fam, field, h, e, w, ang, _, _ in widths:
            fh.write(f"{c},{fam},{field},{h:g},{e:.4g},{w * 1e3:.3g},{ang:.0f}\n")
        if dns:
            fh.write(f"dns_B,DNS,particles,,{BAND_TO:g},{dns[2] * 1e3:.3g},{dns[3]:.0f}\n")
    print("\n| case | field | element size | last step ends at | band width | band direction |\n"
          "| --- | --- | --- | --- | --- | --- |")
    for c, fam, field, h, e, w, ang, _, _ in widths:
        print(f"| {c} | {field} | {h:g} mm | {100 * e:.1f} % | "
              + ("no two half-maximum crossings" if np.isnan(w) else f"{w * 1e3:.2f} mm") + f" | {ang:.0f} deg |")
    if dns:
        print(f"| dns_B | particles | - | {100 * BAND_TO:g} % | {dns[2] * 1e3:.2f} mm | {dns[3]:.0f} deg |")

    shown = [x for x in widths if x[2] == "F"]
    if shown:
        cols = sorted({x[0].split("_")[1] for x in shown}, key=MESHES.index)
        rows = [f for f in families if any(x[1] == f for x in shown)]
        fig, axs = plt.subplots(len(rows), len(cols) + (dns is not None),
                                figsize=(2.4 * (len(cols) + 1), 4 * len(rows)),
                                squeeze=False)
        for row, fam in enumerate(rows):
            for col, m in enumerate(cols):
                a = axs[row][col]
                hit = [x for x in shown if x[1] == fam and x[0] == FAMILIES[fam][0].format(m)]
                if not hit:
                    a.axis("off")
                    continue
                c, _, _, h, e, w, ang, pts, g = hit[0]
                sc = a.scatter(1e3 * pts[:, 0], 1e3 * pts[:, 1], c=g, s=2400 / len(pts) ** 0.9 + 4,
                               marker="s", cmap="viridis")
                a.set_title(f"{FAMILIES[fam][1]} {m}, step to {100 * e:.1f} %\n"
                            + ("" if np.isnan(w) else f"band {w * 1e3:.1f} mm"), fontsize=8)
                a.set_aspect("equal")
                a.set_xlim(0, 10)
                a.set_ylim(0, 20)
                fig.colorbar(sc, ax=a, shrink=0.6)
            a = axs[row][-1]
            if dns is not None and row == 0:
                pts, g, w, ang = dns
                sc = a.scatter(1e3 * pts[:, 0], 1e3 * pts[:, 1], c=g, s=6, marker="s", cmap="viridis")
                a.set_title(f"DNS B particles, {100 * BAND_FROM:g}-{100 * BAND_TO:g} %\nband {w * 1e3:.1f} mm",
                            fontsize=8)
                a.set_aspect("equal")
                fig.colorbar(sc, ax=a, shrink=0.6)
            elif dns is not None:
                a.axis("off")
        fig.suptitle("shear strain increment of the last load step (reference positions, mm)", fontsize=9)
        fig.tight_layout()
        fig.savefig(os.path.join(results, "nonlocal_bands.png"), dpi=110)

    print("\n| case | cores | wall | DEM steps |\n| --- | --- | --- | --- |")
    for fam, cases in families.items():
        for c in cases:
            if curves[c]:
                k = analyse.cost(c, info)
                print(f"| {c} | {k['cores']} | {k['wall_s']} s | {k['dem_steps']:,} |")


if __name__ == "__main__":
    main()
