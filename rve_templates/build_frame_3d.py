#!/usr/bin/env python3
"""build_frame_3d.py -- build the FE2DEM RVE frame from a periodic 3D packing.

Reads a periodic packing written by LIGGGHTS ``write_data`` (atom_style
sphere: ``id type diameter density x y z [ix iy iz]``, orthogonal box) and
builds the 3D frame of physics.md §2.1:

* every particle is shifted periodically so that the corner particle (the one
  closest to the box origin whose three planes no other particle cuts all of,
  or ``--corner-id``) sits at (0, 0, 0);
* a particle whose sphere cuts the plane x_k = 0 (periodically) is a frame
  particle, written with x_k in (-r, r) plus its images at +L_k; cutting one
  plane gives a face pair, two planes an edge group of four images, three
  planes (the corner) eight images;
* all other particles are inner particles, centres in (r, L - r).

Outputs (``--outdir``, default: the input's folder):

``NAME.rve.data``   LIGGGHTS data file (atom_style sphere), type 1 = inner,
                    type 2 = frame; ids 1..P inner (periodic id order), then
                    the corner's eight images, then each frame particle's
                    images (periodic id order). Non-periodic box = cell + 50 %
                    of each side on both sides (the minimum of the
                    templates' shrink-wrapped box, 'boundary m m m').
``NAME.vars``       LIGGGHTS include file (rve_Lx, rve_Ly, rve_Lz, rve_natoms, ...).
``NAME.stats.txt``  ``key value`` lines (also printed).

Statistics on the periodic packing (minimum image), each physical particle
and contact once: coordination 2C/N, mechanical coordination
(2C - N1)/(N - N0 - N1), fabric Pi = (1/C) sum n (x) n, anisotropy
Pi_max/Pi_min - 1, deviatoric invariant sqrt(3/2 Pi':Pi'), solid fraction,
overlaps.

stdlib only; python >= 3.9. Exit code 0 = success, 1 = error (message on
stderr naming the file, the line and what to do).
"""

import argparse
import math
import os
import sys

from build_frame import FrameError, fail, read_data, wrap, min_image


def contacts_periodic(pos, rad, L):
    """Pairs (i, j, overlap, unit normal i->j) with overlap > 0, minimum image, cell lists."""
    cut = 2.0 * max(rad)
    n = [max(1, int(L[k] / cut)) for k in range(3)]
    cells = {}
    for p, x in enumerate(pos):
        c = tuple(min(n[k] - 1, int(wrap(x[k], L[k]) / L[k] * n[k])) for k in range(3))
        cells.setdefault(c, []).append(p)
    out = []
    seen = set()
    for c, members in cells.items():
        near = set()
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    near.update(cells.get(((c[0] + dx) % n[0], (c[1] + dy) % n[1],
                                           (c[2] + dz) % n[2]), []))
        for i in members:
            for j in near:
                if j <= i or (i, j) in seen:
                    continue
                d = [min_image(pos[j][k] - pos[i][k], L[k]) for k in range(3)]
                dist = math.sqrt(sum(v * v for v in d))
                ov = rad[i] + rad[j] - dist
                if ov > 0.0:
                    seen.add((i, j))
                    out.append((i, j, ov, [v / dist for v in d]))
    return out


def sym_eigenvalues(a):
    """Eigenvalues of a symmetric 3x3 (row-major list), largest first."""
    m = (a[0] + a[4] + a[8]) / 3.0
    b = [a[0] - m, a[1], a[2], a[3], a[4] - m, a[5], a[6], a[7], a[8] - m]
    p2 = (b[0] ** 2 + b[4] ** 2 + b[8] ** 2 + 2 * (a[1] ** 2 + a[2] ** 2 + a[5] ** 2)) / 6.0
    if p2 <= 0.0:
        return [m, m, m]
    p = math.sqrt(p2)
    det = (b[0] * (b[4] * b[8] - b[5] * b[7]) - b[1] * (b[3] * b[8] - b[5] * b[6])
           + b[2] * (b[3] * b[7] - b[4] * b[6]))
    r = max(-1.0, min(1.0, det / (2.0 * p2 * p)))
    phi = math.acos(r) / 3.0
    e1 = m + 2 * p * math.cos(phi)
    e3 = m + 2 * p * math.cos(phi + 2 * math.pi / 3)
    return [e1, 3 * m - e1 - e3, e3]


def build(args):
    data = read_data(args.packing)
    box, atoms = data["box"], data["atoms"]
    L = [box[k][1] - box[k][0] for k in "xyz"]
    lo = [box[k][0] for k in "xyz"]
    if min(L) <= 0.0:
        fail(f"{args.packing}: box size {L} is not positive in every direction.")
    rad = [0.5 * a["d"] for a in atoms]
    for a, r in zip(atoms, rad):
        for k, axis in enumerate("xyz"):
            if not math.isfinite(a[axis]):
                fail(f"{args.packing}:{a['line']}: atom {a['id']} has a non-finite {axis} "
                     "coordinate; regenerate the packing.")
        if 2.0 * r >= 0.5 * min(L):
            fail(f"{args.packing}:{a['line']}: atom {a['id']} has diameter {a['d']}, more than "
                 f"half the smallest cell side {min(L)}: the cell is too small for a frame.")
    def classify(corner):
        """Positions relative to @p corner and (inner, frame, atom cutting all three planes)."""
        c0 = [atoms[corner][ax] for ax in "xyz"]
        pos = [[wrap(a[ax] - c0[k], L[k]) for k, ax in enumerate("xyz")] for a in atoms]
        pos[corner] = [0.0, 0.0, 0.0]
        inner, frame, second_corner = [], [], None  # frame: (atom index, base position, cut axes)
        for i, (x, r) in enumerate(zip(pos, rad)):
            base, cuts = list(x), []
            for k in range(3):
                if x[k] < r:
                    cuts.append(k)
                elif x[k] > L[k] - r:
                    base[k] = x[k] - L[k]
                    cuts.append(k)
            if i == corner:
                cuts = [0, 1, 2]
            elif len(cuts) == 3 and second_corner is None:
                second_corner = i
            (frame if cuts else inner).append((i, base, cuts))
        return pos, inner, frame, second_corner

    if args.corner_id is not None:
        ids = [a["id"] for a in atoms]
        if args.corner_id not in ids:
            fail(f"{args.packing}: --corner-id {args.corner_id} is not an atom id of the packing.")
        candidates = [ids.index(args.corner_id)]
    else:
        # The particle nearest the box origin whose three planes no other particle
        # cuts all of (the nearest one shared its corner in a 1000-sphere packing).
        def dist0(a):
            return sum(min_image(a[ax] - lo[k], L[k]) ** 2 for k, ax in enumerate("xyz"))
        candidates = sorted(range(len(atoms)), key=lambda i: dist0(atoms[i]))
    for corner in candidates:
        pos, inner, frame, second = classify(corner)
        if second is None:
            break
    else:
        how = ("choose another --corner-id or regenerate the packing" if args.corner_id is not None
               else "no particle of the packing can be the corner; regenerate the packing")
        fail(f"{args.packing}:{atoms[second]['line']}: atom {atoms[second]['id']} cuts all three "
             "planes x = 0, y = 0, z = 0 like the corner particle "
             f"{atoms[corner]['id']}; a frame has one corner: {how}.")
    frame.sort(key=lambda f: (f[0] != corner, atoms[f[0]]["id"]))

    rho = [a["rho"] for a in atoms]
    out_atoms = []  # (type, diameter, density, x, y, z, periodic id, role)
    for i in sorted((f[0] for f in inner), key=lambda i: atoms[i]["id"]):
        out_atoms.append((1, 2 * rad[i], rho[i], *pos[i], atoms[i]["id"], "inner"))
    n_groups = {1: 0, 2: 0, 3: 0}
    for i, base, cuts in frame:
        n_groups[len(cuts)] += 1
        for bits in range(8):
            if any(bits >> k & 1 and k not in cuts for k in range(3)):
                continue
            x = [base[k] + (L[k] if bits >> k & 1 else 0.0) for k in range(3)]
            role = {1: "face", 2: "edge", 3: "corner"}[len(cuts)]
            out_atoms.append((2, 2 * rad[i], rho[i], *x, atoms[i]["id"], role))

    # statistics on the periodic packing
    cs = contacts_periodic(pos, rad, L)
    N = len(atoms)
    count = [0] * N
    fabric = [0.0] * 9
    for i, j, ov, nrm in cs:
        count[i] += 1
        count[j] += 1
        for a in range(3):
            for b in range(3):
                fabric[3 * a + b] += nrm[a] * nrm[b]
    C = len(cs)
    if C:
        fabric = [f / C for f in fabric]
    ev = sym_eigenvalues(fabric) if C else [0.0, 0.0, 0.0]
    tr = fabric[0] + fabric[4] + fabric[8]
    dev = [fabric[k] - (tr / 3.0 if k in (0, 4, 8) else 0.0) for k in range(9)]
    n0, n1 = count.count(0), count.count(1)
    V = L[0] * L[1] * L[2]
    solid = sum(4.0 / 3.0 * math.pi * r ** 3 for r in rad)
    stats = {
        "source": os.path.basename(args.packing),
        "n_periodic": N,
        "n_inner": len(inner),
        "n_face_pairs": n_groups[1],
        "n_edge_groups": n_groups[2],
        "n_corner": 8,
        "n_frame": len(out_atoms) - len(inner),
        "n_rve_total": len(out_atoms),
        "corner_periodic_id": atoms[corner]["id"],
        "Lx": L[0], "Ly": L[1], "Lz": L[2],
        "R_min": min(rad), "R_max": max(rad), "R_mean": sum(rad) / N,
        "mass_min": min(4.0 / 3.0 * math.pi * r ** 3 * q for r, q in zip(rad, rho)),
        "solid_fraction": solid / V,
        "porosity": 1.0 - solid / V,
        "n_contacts": C,
        "coordination": 2.0 * C / N,
        "coordination_mechanical": (2.0 * C - n1) / (N - n0 - n1) if N - n0 - n1 > 0 else 0.0,
        "n_rattlers_0_contacts": n0,
        "n_1_contact": n1,
        "fabric_11": fabric[0], "fabric_22": fabric[4], "fabric_33": fabric[8],
        "fabric_12": fabric[1], "fabric_13": fabric[2], "fabric_23": fabric[5],
        "anisotropy": ev[0] / ev[2] - 1.0 if ev[2] > 0.0 else 0.0,
        "fabric_deviator": math.sqrt(1.5 * sum(v * v for v in dev)) / tr if tr > 0 else 0.0,
        "overlap_max_over_R_mean": max((c[2] for c in cs), default=0.0) / (sum(rad) / N),
        "overlap_mean_over_R_mean": (sum(c[2] for c in cs) / C if C else 0.0) / (sum(rad) / N),
    }
    worst = max((c[2] / min(rad[c[0]], rad[c[1]]) for c in cs), default=0.0)
    if worst > args.max_overlap:
        fail(f"{args.packing}: largest overlap {worst:.3g} of the smaller radius exceeds "
             f"--max-overlap {args.max_overlap}: the packing is not at rest or not periodic.")
    return L, out_atoms, stats


def spatial_order(out_atoms, bin_size):
    """Indices of @p out_atoms in the order of cubic bins of side @p bin_size
    (x fastest, then y, then z), stable within a bin.

    LIGGGHTS keeps the atoms in the order of the data file: the RVE template
    turns its sorting off so that a restored RVE sums in the same order. In a
    random order the neighbours of an atom are scattered in memory, and
    lsyf_4096 took 13 % longer per step than in LIGGGHTS' own bin order
    (benchmarks/rve_cost/README.md). The order of the ids (inner first, then
    the frame) is unchanged; only the lines are reordered.
    """
    lo = [min(a[3 + k] for a in out_atoms) for k in range(3)]
    nb = [int((max(a[3 + k] for a in out_atoms) - lo[k]) / bin_size) + 1 for k in range(3)]

    def key(n):
        b = [min(int((out_atoms[n][3 + k] - lo[k]) / bin_size), nb[k] - 1) for k in range(3)]
        return (b[2] * nb[1] + b[1]) * nb[0] + b[0]
    return sorted(range(len(out_atoms)), key=key)


def write_outputs(args, L, out_atoms, stats):
    name = args.name or os.path.basename(args.packing).split(".periodic.data")[0].split(".data")[0]
    outdir = args.outdir or os.path.dirname(os.path.abspath(args.packing))
    os.makedirs(outdir, exist_ok=True)
    base = os.path.join(outdir, name)
    margin = [0.5 * l for l in L]
    with open(base + ".rve.data.tmp", "w") as fh:
        fh.write(f"FE2DEM 3D RVE {name} from {stats['source']}\n\n")
        fh.write(f"{len(out_atoms)} atoms\n2 atom types\n\n")
        for k, axis in enumerate("xyz"):
            fh.write(f"{-margin[k]!r} {L[k] + margin[k]!r} {axis}lo {axis}hi\n")
        fh.write("\nAtoms\n\n")
        for n in spatial_order(out_atoms, stats["R_max"]):
            a = out_atoms[n]
            fh.write(f"{n + 1} {a[0]} {a[1]!r} {a[2]!r} {a[3]!r} {a[4]!r} {a[5]!r}\n")
    n_inner = stats["n_inner"]
    with open(base + ".vars.tmp", "w") as fh:
        fh.write(f"# FE2DEM RVE {name}: include after read_data {name}.rve.data\n")
        for key, v in (("rve_Lx", L[0]), ("rve_Ly", L[1]), ("rve_Lz", L[2])):
            fh.write(f"variable {key} equal {v:.16e}\n")
        fh.write(f"variable rve_natoms equal {len(out_atoms)}\n")
        fh.write(f"variable rve_ninner equal {n_inner}\n")
        fh.write(f"variable rve_nframe equal {len(out_atoms) - n_inner}\n")
        fh.write(f"variable rve_Rmin equal {stats['R_min']:.16e}\n")
        fh.write(f"variable rve_Rmax equal {stats['R_max']:.16e}\n")
        fh.write(f"variable rve_massmin equal {stats['mass_min']:.16e}\n")
        fh.write(f"variable rve_phi equal {stats['solid_fraction']:.9f}\n")
    with open(base + ".stats.txt.tmp", "w") as fh:
        for k, v in stats.items():
            fh.write(f"{k} {v!r}\n" if isinstance(v, float) else f"{k} {v}\n")
    # all three files or none
    for ext in (".rve.data", ".vars", ".stats.txt"):
        os.replace(base + ext + ".tmp", base + ext)
    return base


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("packing", help="periodic 3D packing (LIGGGHTS write_data, atom_style sphere)")
    ap.add_argument("name", nargs="?", help="output base name (default: the packing's name "
                    "without .periodic.data)")
    ap.add_argument("--outdir", help="output folder (default: the packing's folder)")
    ap.add_argument("--corner-id", type=int, help="atom id of the corner particle "
                    "(default: the one nearest the box origin that no other particle "
                    "shares the corner with)")
    ap.add_argument("--max-overlap", type=float, default=0.1,
                    help="largest accepted overlap / smaller radius (default 0.1)")
    ap.add_argument("--quiet", action="store_true")
    args = ap.parse_args(argv)
    try:
        L, out_atoms, stats = build(args)
        base = write_outputs(args, L, out_atoms, stats)
    except FrameError as exc:
        print(f"build_frame_3d: error: {exc}", file=sys.stderr)
        return 1
    if not args.quiet:
        for k, v in stats.items():
            print(f"{k} {v}")
        print(f"wrote {base}.rve.data, .vars, .stats.txt")
    return 0


if __name__ == "__main__":
    sys.exit(main())
