#!/usr/bin/python3
"""Turns the runs of benchmarks/lbs2018/run.sh into the committed results.

Usage: analyse.py [DIR]   (Debian's python3 with numpy, matplotlib, h5py)
DIR holds runs/ and results/: benchmarks/lbs2018 (default) or its fast/.

Reads runs/CASE/{summary.csv,history.h5,solution-*.vtu,particles/} of the
multiscale cases and runs/dns_*/rve.csv of the DNS, and results/runs.csv
(wall time and cores of each case). Writes to results/:

  curves.csv            every case: axial strain, average stress ratio,
                        volumetric strain, coordination, anisotropy
  studies.csv           per study and case: peak stress ratio, axial strain
                        at peak, maximum compaction, coordination and
                        anisotropy at peak, end strain, cores, wall time
  mesh_convergence.png, friction.png, rotation.png, anisotropy.png
  ip_stress_ratio_MESH.{csv,png}     every IP, highest and lowest at 9 % marked
  equivalent_strain_MESH.png         incremental equivalent strain of the last
                                     step on the deformed mesh
  particles_MESH.png                 highest- and lowest-stress IP at 9 %
and prints the tables (markdown) and the pre-peak spread of the mesh study.
Missing runs are skipped with a note, so a partial rerun still plots.
"""
import base64
import csv
import os
import struct
import sys
import xml.etree.ElementTree as ET
import zlib

import matplotlib

matplotlib.use("Agg")
import h5py
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import PolyCollection

here = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from plot_particles import draw as draw_particles  # noqa: E402

runs, results = os.path.join(here, "runs"), os.path.join(here, "results")
ISO_STEPS = 10        # Isotropic steps of lbs2018.prm and dns.prm
DUMP_STEP = 28        # Particle dumps / Every of run.sh: 9 % axial strain
PRE_PEAK = 0.05       # the pre-peak range (axial strain <= 5 %)

STUDIES = {
    "mesh_convergence": [("mesh_1x1", "1x1 (4 IPs)"), ("mesh_1x2", "1x2 (8 IPs)"),
                         ("mesh_2x4", "2x4 (32 IPs)"), ("mesh_4x8", "4x8 (128 IPs)"),
                         ("dns_A", "DNS A (1x2 tiles)"), ("dns_B", "DNS B (2x4 tiles)")],
    "friction": [("mu0.2", "mu = 0.2"), ("mesh_2x4", "mu = 0.4"), ("mu0.6", "mu = 0.6")],
    "rotation": [("mesh_2x4", "rotation free"), ("locked", "rotation locked")],
    "anisotropy": [("mesh_2x4", "A0 = 0.02 (lbs_ref)"), ("a005", "A0 = 0.05 (lbs_a005)"),
                   ("a008", "A0 = 0.08 (lbs_a008)")],
    "load_step": [("mesh_4x8", "4x8, stage 2 in 0.5 % steps"), ("mesh_4x8_steps22", "4x8, 0.25 % steps")],
    "dns_tolerance": [("dns_B_tol1e-3", "DNS B, tol 1e-3"), ("dns_B_tol1e-4", "DNS B, tol 1e-4"),
                      ("dns_B", "DNS B, tol 1e-5 (dns.prm)"), ("mesh_2x4", "2x4 multiscale")],
}
QUANTITIES = [("stress_ratio", "average stress ratio |s11-s22|/|s11+s22|"),
              ("volumetric_strain", "volumetric strain J/J_ic - 1 (< 0: compaction)"),
              ("coordination", "coordination number 2C/N"),
              ("anisotropy", "fabric anisotropy A")]


def ratio(s11, s22):
    return abs((s11 - s22) / (s11 + s22))


def curve(case):
    """Stage-2 curve of a case (axial strain 0 = end of stage 1), or None."""
    d = os.path.join(runs, case)
    if os.path.exists(os.path.join(d, "summary.csv")):
        rows = list(csv.DictReader(open(os.path.join(d, "summary.csv"))))
        iso = [r for r in rows if r["stage"] == "1"]
        rows = ([iso[-1]] if iso else []) + [r for r in rows if r["stage"] == "2"]
        return {"axial_strain": [float(r["axial_strain"]) if r["stage"] == "2" else 0.0 for r in rows],
                "stress_ratio": [ratio(float(r["sigma11_mean"]), float(r["sigma22_mean"])) for r in rows],
                "volumetric_strain": [float(r["J_rel_mean"]) if r["stage"] == "2" else 0.0 for r in rows],
                "coordination": [float(r["coordination_mean"]) for r in rows],
                "anisotropy": [float(r["anisotropy_mean"]) for r in rows]}
    if os.path.exists(os.path.join(d, "rve.csv")):
        rows = list(csv.DictReader(open(os.path.join(d, "rve.csv"))))[ISO_STEPS:]
        det = lambda r: float(r["F11"]) * float(r["F22"]) - float(r["F12"]) * float(r["F21"])  # noqa: E731
        f22_ic, j_ic = float(rows[0]["F22"]), det(rows[0])
        return {"axial_strain": [1.0 - float(r["F22"]) / f22_ic for r in rows],
                "stress_ratio": [ratio(float(r["sigma11"]), float(r["sigma22"])) for r in rows],
                "volumetric_strain": [det(r) / j_ic - 1.0 for r in rows],
                "coordination": [float(r["coordination"]) for r in rows],
                "anisotropy": [float(r["anisotropy"]) for r in rows]}
    return None


def run_info():
    info = {}
    path = os.path.join(results, "runs.csv")
    if os.path.exists(path):
        for r in csv.DictReader(open(path)):
            info[r["case"]] = r
    return info


def cost(case, info):
    """Wall time, cores, DEM steps, macro iterations and, for fe2dem, the share
    of the wall time in RVE solves and the load imbalance (max / mean rank)."""
    d, r = os.path.join(runs, case), info.get(case, {})
    out = {"cores": r.get("cores", ""), "wall_s": r.get("wall_s", ""), "completed": r.get("completed", "")}
    if os.path.exists(os.path.join(d, "summary.csv")):
        rows = list(csv.DictReader(open(os.path.join(d, "summary.csv"))))
        out["dem_steps"] = sum(int(float(x["dem_steps"])) for x in rows)
        out["macro_iterations"] = sum(int(x["macro_iterations"]) for x in rows)
        rve_max = sum(float(x["rve_rank_max_s"]) for x in rows)
        rve_mean = sum(float(x["rve_rank_mean_s"]) for x in rows)
        out["rve_share"] = rve_max / float(rows[-1]["wall_s"])
        out["imbalance"] = rve_max / rve_mean
    elif os.path.exists(os.path.join(d, "rve.csv")):
        rows = list(csv.DictReader(open(os.path.join(d, "rve.csv"))))
        out["dem_steps"] = sum(int(float(x["dem_steps"])) for x in rows)
        out["macro_iterations"] = sum(int(float(x["stress_iterations"])) for x in rows)
    return out


def key_figures(c):
    i = int(np.argmax(c["stress_ratio"]))
    return {"peak_stress_ratio": c["stress_ratio"][i], "axial_strain_at_peak": c["axial_strain"][i],
            "max_compaction": -min(c["volumetric_strain"]), "coordination_at_peak": c["coordination"][i],
            "anisotropy_at_peak": c["anisotropy"][i], "end_axial_strain": c["axial_strain"][-1]}


def plot_study(name, cases, curves):
    fig, ax = plt.subplots(2, 2, figsize=(11, 8))
    for case, label in cases:
        c = curves.get(case)
        if c is None:
            continue
        style = "s--" if case.startswith("dns") else "o-"
        for a, (q, _) in zip(ax.flat, QUANTITIES):
            a.plot(c["axial_strain"], c[q], style, ms=3, label=label)
    for a, (_, lab) in zip(ax.flat, QUANTITIES):
        a.set_xlabel("axial strain")
        a.set_ylabel(lab, fontsize=9)
        a.grid(alpha=0.3)
    ax[0][0].legend(fontsize=8)
    fig.suptitle(f"[LBS] biaxial test, {name.replace('_', ' ')} (benchmarks/lbs2018)")
    fig.tight_layout()
    fig.savefig(os.path.join(results, name + ".png"), dpi=120)
    plt.close(fig)


def ip_stress_ratios(case):
    """(axial strain per step, stress ratio [step, ip]) of stage 2 from history.h5."""
    with h5py.File(os.path.join(runs, case, "history.h5"), "r") as h:
        sigma, steps, axial = h["sigma"][...], h["step"][...], h["axial_strain"][...]
    r = np.abs((sigma[:, :, 0] - sigma[:, :, 3]) / (sigma[:, :, 0] + sigma[:, :, 3]))
    keep = steps >= ISO_STEPS
    return steps[keep], axial[keep], r[keep]


def plot_ip_stress_ratios(mesh):
    case = "mesh_" + mesh
    steps, axial, r = ip_stress_ratios(case)
    at = int(np.where(steps == DUMP_STEP)[0][0])
    hi, lo = int(np.argmax(r[at])), int(np.argmin(r[at]))
    with open(os.path.join(results, f"ip_stress_ratio_{mesh}.csv"), "w") as fh:
        fh.write("axial_strain," + ",".join(f"ip{p}" for p in range(r.shape[1])) + "\n")
        for a, row in zip(axial, r):
            fh.write(f"{a:.6g}," + ",".join(f"{v:.6g}" for v in row) + "\n")
    fig, ax = plt.subplots(figsize=(7, 5))
    for p in range(r.shape[1]):
        ax.plot(axial, r[:, p], color="0.75", lw=0.7)
    ax.plot(axial, r[:, hi], "r-o", ms=3, label=f"highest at 9 %: IP {hi}")
    ax.plot(axial, r[:, lo], "b-o", ms=3, label=f"lowest at 9 %: IP {lo}")
    ax.plot(axial, r.mean(axis=1), "k--", label="mean over IPs")
    ax.set_xlabel("axial strain")
    ax.set_ylabel("stress ratio of each IP")
    ax.set_title(f"{mesh} mesh: stress ratio of all {r.shape[1]} IPs")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(results, f"ip_stress_ratio_{mesh}.png"), dpi=120)
    plt.close(fig)
    return hi, lo, r[at, hi], r[at, lo]


def plot_particles(mesh, hi, lo, r_hi, r_lo):
    fig, ax = plt.subplots(1, 2, figsize=(12, 6))
    for a, ip, r, what in ((ax[0], hi, r_hi, "highest"), (ax[1], lo, r_lo, "lowest")):
        prefix = os.path.join(runs, "mesh_" + mesh, "particles", f"ip{ip:04d}-step{DUMP_STEP:04d}")
        draw_particles(a, prefix, f"{mesh}: IP {ip}, {what} stress ratio at 9 % ({r:.3f})")
    fig.suptitle("particles (frame grey) and normal contact forces (line width)")
    fig.tight_layout()
    fig.savefig(os.path.join(results, f"particles_{mesh}.png"), dpi=110)
    plt.close(fig)


def vtu_arrays(path):
    """Points, cell connectivity and point data of a deal.II binary (zlib) VTU."""
    def decode(el):
        text = "".join(el.text.split())
        dtype = {"Float32": "<f4", "Float64": "<f8", "Int32": "<i4", "Int64": "<i8",
                 "UInt8": "u1", "UInt32": "<u4"}[el.get("type")]
        first = base64.b64decode(text[:8])                    # nblocks, block size, ...
        nblocks = struct.unpack("<I", first[:4])[0]
        hlen = 4 * ((4 * (3 + nblocks) + 2) // 3)             # base64 length of the header
        header = struct.unpack(f"<{3 + nblocks}I", base64.b64decode(text[:hlen]))
        raw, pos, data = base64.b64decode(text[hlen:]), 0, b""
        for size in header[3:]:
            data += zlib.decompress(raw[pos:pos + size])
            pos += size
        a = np.frombuffer(data, dtype=dtype)
        n = int(el.get("NumberOfComponents", "1"))
        return a.reshape(-1, n) if n > 1 else a
    root = ET.parse(path).getroot()
    piece = root.find("UnstructuredGrid/Piece")
    points = decode(piece.find("Points/DataArray"))
    cells = {e.get("Name"): decode(e) for e in piece.find("Cells")}
    data = {e.get("Name"): decode(e) for e in piece.find("PointData")}
    return points, cells, data


def plot_equivalent_strain(mesh):
    """Incremental equivalent strain |F_n - F_(n-1)| (Frobenius, the VTU's
    equivalent_strain_increment per IP instead of per cell) of the last step
    on the deformed mesh: each Q1 cell is split into the four quarters around
    its 2x2 Gauss points (history.h5 order: cell by cell as in the VTU,
    points lexicographic)."""
    d = os.path.join(runs, "mesh_" + mesh)
    vtus = sorted(f for f in os.listdir(d) if f.startswith("solution-") and f.endswith(".vtu"))
    points, cells, data = vtu_arrays(os.path.join(d, vtus[-1]))
    x = 1e3 * (points[:, :2] + data["displacement"][:, :2])  # mm
    conn, offsets = cells["connectivity"], cells["offsets"]
    with h5py.File(os.path.join(d, "history.h5"), "r") as h:
        F = h["F"][-2:]
    increment = np.linalg.norm(F[1] - F[0], axis=1)
    polys, values = [], []
    for c, s in enumerate(np.concatenate(([0], offsets[:-1]))):
        v = x[conn[s:s + 4]][[0, 1, 3, 2]]        # VTK quad order -> lexicographic vertices
        mid = lambda a, b: 0.5 * (v[a] + v[b])      # noqa: E731
        centre = v.mean(axis=0)
        for q, (corner, e1, e2) in enumerate(((0, (0, 1), (0, 2)), (1, (0, 1), (1, 3)),
                                              (2, (2, 3), (0, 2)), (3, (2, 3), (1, 3)))):
            polys.append([v[corner], mid(*e1), centre, mid(*e2)])
            values.append(increment[4 * c + q])
    fig, ax = plt.subplots(figsize=(5.5, 7))
    pc = PolyCollection(polys, array=np.array(values), cmap="viridis", edgecolors="none")
    ax.add_collection(pc)
    ax.add_collection(PolyCollection([x[conn[s:s + 4]] for s in np.concatenate(([0], offsets[:-1]))],
                                     facecolors="none", edgecolors="k", linewidths=0.6))
    ax.autoscale_view()
    ax.set_aspect("equal")
    fig.colorbar(pc, ax=ax, label="equivalent strain increment |F_n - F_(n-1)| per IP, last step")
    ax.set_title(f"{mesh}: deformed mesh at the end ({vtus[-1]})", fontsize=9)
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")
    fig.tight_layout()
    fig.savefig(os.path.join(results, f"equivalent_strain_{mesh}.png"), dpi=120)
    plt.close(fig)


def pre_peak_spread(curves, cases, csv_name):
    """Largest (max - min) / mean over CASES of the stress ratio at the common
    stage-2 strains in (0, PRE_PEAK], interpolated onto the multiscale strains;
    each strain's spread and values go to results/CSV_NAME."""
    have = [c for c in cases if curves.get(c)]
    if len(have) < 2:
        return None
    grid = [e for e in curves[have[0]]["axial_strain"] if 0.0 < e <= PRE_PEAK + 1e-9]
    worst = (0.0, None)
    with open(os.path.join(results, csv_name), "w") as fh:
        fh.write("axial_strain,spread," + ",".join(have) + "\n")
        for e in grid:
            vals = [np.interp(e, curves[c]["axial_strain"], curves[c]["stress_ratio"]) for c in have]
            s = (max(vals) - min(vals)) / np.mean(vals)
            fh.write(f"{e:.6g},{s:.4f}," + ",".join(f"{v:.6g}" for v in vals) + "\n")
            if s > worst[0]:
                worst = (s, e)
    return worst, have


def main():
    os.makedirs(results, exist_ok=True)
    all_cases = sorted({c for cases in STUDIES.values() for c, _ in cases})
    info = run_info()
    # a case is analysed once run.sh has recorded it (not while it runs)
    curves = {c: curve(c) if c in info else None for c in all_cases}
    for c in all_cases:
        if curves[c] is None:
            print(f"analyse.py: no finished output in runs/{c}: run 'run.sh {c}' (skipped)")
    with open(os.path.join(results, "curves.csv"), "w") as fh:
        fh.write("case,axial_strain," + ",".join(q for q, _ in QUANTITIES) + "\n")
        for c in all_cases:
            for i in range(len(curves[c]["axial_strain"]) if curves[c] else 0):
                fh.write(f"{c}," + ",".join(f"{curves[c][k][i]:.6g}" for k in
                                             ["axial_strain"] + [q for q, _ in QUANTITIES]) + "\n")
    cols = ["peak_stress_ratio", "axial_strain_at_peak", "max_compaction", "coordination_at_peak",
            "anisotropy_at_peak", "end_axial_strain"]
    with open(os.path.join(results, "studies.csv"), "w") as fh:
        fh.write("study,case," + ",".join(cols) + ",cores,wall_s\n")
        for study, cases in STUDIES.items():
            plot_study(study, cases, curves)
            print(f"\n{study}\n\n| case | peak stress ratio | axial strain at peak | max compaction "
                  "| coordination at peak | anisotropy at peak | end strain | cores | wall |\n"
                  "| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
            for c, label in cases:
                if not curves[c]:
                    continue
                k, r = key_figures(curves[c]), info.get(c, {})
                fh.write(f"{study},{c}," + ",".join(f"{k[q]:.6g}" for q in cols)
                         + f",{r.get('cores', '')},{r.get('wall_s', '')}\n")
                print(f"| {label} | {k['peak_stress_ratio']:.3f} | {100 * k['axial_strain_at_peak']:.1f} % "
                      f"| {100 * k['max_compaction']:.2f} % | {k['coordination_at_peak']:.2f} "
                      f"| {k['anisotropy_at_peak']:.3f} | {100 * k['end_axial_strain']:.1f} % "
                      f"| {r.get('cores', '?')} | {r.get('wall_s', '?')} s |")
    for mesh in ("2x4", "4x8"):
        if curves.get("mesh_" + mesh):
            hi, lo, r_hi, r_lo = plot_ip_stress_ratios(mesh)
            print(f"\n{mesh}: highest IP at 9 %: {hi} ({r_hi:.3f}), lowest: {lo} ({r_lo:.3f})")
            plot_particles(mesh, hi, lo, r_hi, r_lo)
            plot_equivalent_strain(mesh)
    with open(os.path.join(results, "cost.csv"), "w") as fh:
        keys = ["cores", "wall_s", "completed", "dem_steps", "macro_iterations", "rve_share", "imbalance"]
        fh.write("case," + ",".join(keys) + "\n")
        print("\ncost\n\n| case | cores | wall | DEM steps | macro iterations (DNS: stress iterations) "
              "| RVE share of wall | imbalance max/mean |\n| --- | --- | --- | --- | --- | --- | --- |")
        for c in all_cases:
            if not curves[c]:
                continue
            k = cost(c, info)
            fh.write(c + "," + ",".join(str(k.get(q, "")) for q in keys) + "\n")
            share = f"{k['rve_share']:.2f}" if "rve_share" in k else "-"
            imb = f"{k['imbalance']:.3f}" if "imbalance" in k else "-"
            print(f"| {c} | {k['cores']} | {k['wall_s']} s | {k['dem_steps']:,} | {k['macro_iterations']:,} "
                  f"| {share} | {imb} |")
    meshes = ["mesh_1x1", "mesh_1x2", "mesh_2x4", "mesh_4x8"]
    spread = pre_peak_spread(curves, meshes, "prepeak_spread_meshes.csv")
    if spread:
        print(f"\npre_peak_stress_ratio_spread_meshes {spread[0][0]:.4f} 1  (the meshes alone; at {spread[0][1]})")
    # the criterion with DNS B as in dns.prm, then with the looser
    # DNS tolerances in its place, to show how much the DNS's own scatter weighs
    for dns in ["dns_B", "dns_B_tol1e-3", "dns_B_tol1e-4"]:
        if not curves.get(dns):
            continue
        suffix = dns[len("dns_B"):]
        spread = pre_peak_spread(curves, meshes + [dns], f"prepeak_spread{suffix}.csv")
        if spread:
            (s, e), have = spread
            print(f"\npre_peak_stress_ratio_spread{suffix} {s:.4f} 1  (largest (max-min)/mean "
                  f"over {', '.join(have)} at axial strain <= {PRE_PEAK:g}; at {e})")
    total = sum(float(r["wall_s"]) for r in info.values())
    print(f"suite_wall {total:.0f} s  ({len(info)} cases in results/runs.csv)")


if __name__ == "__main__":
    main()
