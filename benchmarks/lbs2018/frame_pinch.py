#!/usr/bin/python3
"""How an inner particle is lost at the frame of lbs_ref (issue 37, session 56).

Usage: frame_pinch.py [RUNS_DIR]   (default: runs/band_rve_replay next to this file)

Reads the particle dumps band_rve_replay.sh writes after every row of the
three replays of IP 0's path (5 ms a row at full precision and rounded to
10 digits, and 10 ms a row; before the servo's anti-windup the first failed
in row 71, the second held to row 82) and prints, per row:
- |F e1|, |F e2|: how much the bottom/top and the left/right edges of the
  cell are stretched (the frame particles sit at F X plus a fluctuation);
- the largest frame-frame overlap on the left/right edges and on the
  bottom/top edges, over the smaller radius;
- the largest gap between neighbours along the frame (surface to surface,
  in mm) and which two; a gap wider than an inner particle is a hole;
- for inner particles 15 and 129 (the ones lost in the replay and in the
  macro runs): their reference-cell x coordinate (F^-1 (x - x_corner)) over
  the cell side, the number of frame particles they touch and the largest
  overlap over the smaller radius with a frame particle (and which).
and, for each case's last dump, the holes: neighbours along the frame
further apart than an inner particle's diameter with that particle's centre
within its radius of the line between them (the frame membrane's band), and
the particle's contacts. Writes results/frame_pinch.csv and results/frame_pinch.png (the right edge
around both particles in the full-precision replay's last dump, and in the
rounded replay's same row). results/frame_pinch_windup.png is that figure
made with the servo before its anti-windup (session 56, before 2a8c723),
when the full-precision replay failed in row 71.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "scripts"))
import plot_particles  # noqa: E402

WATCHED = (15, 129)
CASES = ("ip0_path_5ms", "ip0_path_5ms_rounded", "ip0_path_10ms")
FIGURE_CASES = CASES[:2]  # the figure's two columns
PACKING = os.path.join(here, "..", "..", "rve_templates", "packings", "lbs_ref")
FRAME_FILE = PACKING + ".frame.txt"
RMIN = next(float(l.split()[3]) for l in open(PACKING + ".vars") if l.startswith("variable rve_Rmin "))


def frame_roles():
    """rve id -> role (corner_*, bottom, right, top, left) of lbs_ref's frame, in frame order."""
    roles = {}
    for line in open(FRAME_FILE):
        if not line.startswith("#"):
            f = line.split()
            roles[int(f[0])] = f[1]
    return roles


def frame_gaps(particles, order):
    """(gap in m, id, id) of each pair of neighbours along the closed frame @p order, surface to
    surface."""
    for a, b in zip(order, order[1:] + order[:1]):
        pa, pb = particles[a], particles[b]
        yield np.hypot(pa["x"] - pb["x"], pa["y"] - pb["y"]) - pa["radius"] - pb["radius"], a, b


def largest_gap(particles, order):
    """(gap in m, id, id) of the widest surface gap between neighbours along the closed frame."""
    return max(frame_gaps(particles, order))


def holes(prefix, roles):
    """[(inner id, its diameter, frame a, frame b, gap)] (m) of the dump @p prefix: inner particles
    in the membrane band of two neighbours along the frame whose gap is wider than their diameter."""
    particles = {int(p["id"]): p for p in plot_particles.read(prefix + ".particles")}
    found = []
    for gap, a, b in frame_gaps(particles, list(roles)):
        xa = np.array([particles[a]["x"], particles[a]["y"]])
        e = np.array([particles[b]["x"], particles[b]["y"]]) - xa
        for i, p in particles.items():
            if i in roles or 2 * p["radius"] >= gap:
                continue
            d = np.array([p["x"], p["y"]]) - xa
            t = d @ e / (e @ e)
            if 0 < t < 1 and np.linalg.norm(d - t * e) < p["radius"]:
                found.append((i, 2 * p["radius"], a, b, gap))
    return found


def read_F(case_dir):
    """Row number -> F (2x2) from rve.csv."""
    out = {}
    with open(os.path.join(case_dir, "rve.csv")) as f:
        for row in csv.DictReader(f):
            out[int(row["step"])] = np.array([[float(row["F11"]), float(row["F12"])],
                                              [float(row["F21"]), float(row["F22"])]])
    return out


def row_measures(prefix, F, roles):
    """The measures of one dump (see the module doc) as a dict."""
    particles = {int(p["id"]): p for p in plot_particles.read(prefix + ".particles")}
    contacts = plot_particles.read(prefix + ".contacts")
    corner = particles[min(i for i, r in roles.items() if r == "corner_00")]
    Finv = np.linalg.inv(F)
    vertical = ("left", "right")
    gap, a, b = largest_gap(particles, list(roles))
    m = {"F_e1": np.linalg.norm(F[:, 0]), "F_e2": np.linalg.norm(F[:, 1]),
         "ff_vertical": 0.0, "ff_horizontal": 0.0, "gap_mm": gap * 1e3, "gap_between": f"{a}-{b}"}
    for w in WATCHED:
        p = particles[w]
        xi = Finv @ np.array([p["x"] - corner["x"], p["y"] - corner["y"]])
        m[f"p{w}_xi"] = xi[0] / 5e-3
        m[f"p{w}_frame_contacts"] = 0
        m[f"p{w}_frame_overlap"] = 0.0
        m[f"p{w}_partner"] = -1
    for c in contacts:
        i, j = int(c["id1"]), int(c["id2"])
        pi, pj = particles[i], particles[j]
        d = np.hypot(pi["x"] - pj["x"], pi["y"] - pj["y"])
        rel = (pi["radius"] + pj["radius"] - d) / min(pi["radius"], pj["radius"])
        if i in roles and j in roles:
            key = "ff_vertical" if roles[i] in vertical and roles[j] in vertical else "ff_horizontal"
            m[key] = max(m[key], rel)
        for w, other in ((i, j), (j, i)):
            if w in WATCHED and other in roles:
                m[f"p{w}_frame_contacts"] += 1
                if rel > m[f"p{w}_frame_overlap"]:
                    m[f"p{w}_frame_overlap"], m[f"p{w}_partner"] = rel, other
    return m


def zoom(ax, prefix, centre, title):
    plot_particles.draw(ax, prefix, title)
    half = 1.2e-3
    ax.set_xlim(centre[0] - half, centre[0] + half)
    ax.set_ylim(centre[1] - half, centre[1] + half)
    particles = {int(p["id"]): p for p in plot_particles.read(prefix + ".particles")}
    for i in list(WATCHED) + [189, 191, 196]:
        p = particles[i]
        if abs(p["x"] - centre[0]) < half and abs(p["y"] - centre[1]) < half:
            ax.annotate(str(i), (p["x"], p["y"]), ha="center", va="center", fontsize=7)


def main():
    runs = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "runs", "band_rve_replay")
    roles = frame_roles()
    rows, last = [], {}
    for case in CASES:
        d = os.path.join(runs, case)
        F = read_F(d)
        last[case] = max(F)
        for step in sorted(F):
            prefix = os.path.join(d, "particles", f"step{step:04d}")
            if os.path.exists(prefix + ".contacts"):
                rows.append({"case": case, "row": step, **row_measures(prefix, F[step], roles)})
    keys = list(rows[0].keys())
    out_csv = os.path.join(here, "results", "frame_pinch.csv")
    with open(out_csv, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.4g}" if isinstance(v, float) else v) for k, v in r.items()})
    print("| case | row | abs(F e1) | abs(F e2) | frame-frame overlap, left/right edges | bottom/top "
          "| largest gap along the frame, mm (between) |"
          + "".join(f" {w}: x/L, frame contacts, largest overlap (with) |" for w in WATCHED))
    print("|---|---|---|---|---|---|---|" + "---|" * len(WATCHED))
    for r in rows:
        if r["row"] in (0, 40, 60, 66, 67, 70, 75, 80, 82) or r["row"] == last[r["case"]]:
            cells = "".join(f" {r[f'p{w}_xi']:.3f}, {r[f'p{w}_frame_contacts']}, "
                            f"{r[f'p{w}_frame_overlap']:.2f} ({r[f'p{w}_partner']}) |" for w in WATCHED)
            print(f"| {r['case']} | {r['row']} | {r['F_e1']:.3f} | {r['F_e2']:.3f} | "
                  f"{r['ff_vertical']:.2f} | {r['ff_horizontal']:.2f} | {r['gap_mm']:.3f} ({r['gap_between']}) |"
                  f"{cells}")
    failed = min(last[CASES[0]], 70)
    fig, axes = plt.subplots(2, 2, figsize=(9, 9))
    for col, case in enumerate(FIGURE_CASES):
        prefix = os.path.join(runs, case, "particles", f"step{failed:04d}")
        particles = {int(p["id"]): p for p in plot_particles.read(prefix + ".particles")}
        for row, w in enumerate(WATCHED):
            zoom(axes[row, col], prefix, (particles[w]["x"], particles[w]["y"]),
                 f"{case}, row {failed}: around inner particle {w}")
    png = os.path.join(here, "results", "frame_pinch.png")
    fig.savefig(png, dpi=130, bbox_inches="tight")
    widest = max(rows, key=lambda r: r["gap_mm"])
    print(f"widest gap of all rows: {widest['gap_mm']:.3f} mm ({widest['gap_between']}, {widest['case']} "
          f"row {widest['row']}); smallest inner diameter {2e3 * RMIN:.3f} mm")
    for case in CASES:
        prefix = os.path.join(runs, case, "particles", f"step{last[case]:04d}")
        contacts = plot_particles.read(prefix + ".contacts")
        for i, diameter, a, b, gap in holes(prefix, roles):
            touching = sorted(int(c["id2"]) if int(c["id1"]) == i else int(c["id1"]) for c in contacts
                              if i in (int(c["id1"]), int(c["id2"])))
            print(f"{case}, row {last[case]}: inner particle {i} ({diameter * 1e3:.3f} mm) in the "
                  f"{gap * 1e3:.3f} mm gap between frame particles {a} and {b}; touches {touching or 'nothing'}")
    print(out_csv)
    print(png)


if __name__ == "__main__":
    main()
