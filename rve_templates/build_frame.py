#!/usr/bin/env python3
"""build_frame.py -- build the FE2DEM RVE frame from a periodic 2D packing.

Reads a periodic packing written by LIGGGHTS ``write_data`` (atom_style sphere:
``id type diameter density x y z [ix iy iz]``; the Velocities section and any
other section is ignored) and builds the RVE frame of physics.md §2.1:

* every particle is shifted periodically so that the corner particle (the one
  closest to the cell origin (xlo, ylo), or ``--corner-id``) sits at (0, 0);
  positions are wrapped into [0, Lx) x [0, Ly);
* the corner and its three periodic images at (Lx,0), (Lx,Ly), (0,Ly);
* particles whose disc cuts the line x = 0 (periodically) become left-edge
  particles with x in (-r, r) plus their image at x + Lx (right edge); those
  cutting y = 0 become bottom-edge particles with their image at y + Ly (top);
* all other particles are inner particles, centres in (0, Lx) x (0, Ly).

Outputs (``--outdir``, default: the input's folder):

``NAME.rve.data``    LIGGGHTS data file (atom_style sphere, ``id type diameter
                     density x y z``), type 1 = inner, type 2 = frame, ids
                     1..P inner (in the order of the periodic ids), then the
                     frame counter-clockwise from the corner (0,0): bottom edge
                     left->right, corner (Lx,0), right edge bottom->top, corner
                     (Lx,Ly), top edge right->left, corner (0,Ly), left edge
                     top->bottom. Non-periodic box = cell + 50 % of Lx (Ly) on
                     each side in x (y), the minimum of the template's
                     shrink-wrapped box; z = the input's slab.
``NAME.vars``        LIGGGHTS include file (rve_Lx, rve_Ly, rve_natoms, ...).
``NAME.stats.txt``   ``key value`` lines (also printed).
``NAME.frame.txt``   frame particles: rve id, role, pair, periodic id, X, Y, R.

Statistics are computed on the periodic packing (minimum image): coordination
2C/N over contacts with overlap > 0, each physical particle and contact once
(the RVE's contacts are checked to be exactly these once the second copies of
frame-frame contacts are left out, as fix rve/servo does), mechanical coordination
(2C - N1)/(N - N0 - N1) (N0, N1 = particles with 0 and 1 contacts), fabric
Pi = (1/C) sum_c n_c (x) n_c, anisotropy A = Pi_1/Pi_2 - 1, overlaps.

stdlib only; python >= 3.9.  Exit code 0 = success, 1 = error (message on
stderr naming the file, the line and what to do).
"""

import argparse
import math
import os
import sys

SECTION_WORDS = {
    "Atoms", "Velocities", "Masses", "Bonds", "Angles", "Dihedrals", "Impropers",
    "Ellipsoids", "Lines", "Triangles", "Bodies", "Pair Coeffs", "PairIJ Coeffs",
    "Bond Coeffs", "Angle Coeffs", "Dihedral Coeffs", "Improper Coeffs",
}


class FrameError(Exception):
    pass


def fail(msg):
    raise FrameError(msg)


# --------------------------------------------------------------------------- reading
def read_data(path):
    """Returns dict with box and a list of atoms (id, type, d, rho, x, y, z)."""
    try:
        with open(path, "r") as fh:
            lines = fh.readlines()
    except OSError as exc:
        fail(f"{path}: cannot read the packing file ({exc.strerror}). "
             "Give the path of a data file written by LIGGGHTS write_data.")
    box = {}
    natoms_hdr = None
    atoms = []
    section = None
    section_line = 0
    i = 1  # line 1 is the title, always skipped
    while i < len(lines):
        lineno = i + 1
        raw = lines[i]
        text = raw.split("#", 1)[0].strip()
        i += 1
        if not text:
            continue
        words = text.split()
        # section headers
        if text in SECTION_WORDS or words[0] in SECTION_WORDS:
            section = words[0] if text not in SECTION_WORDS else text
            section_line = lineno
            continue
        if section is None:
            # header
            if len(words) >= 2 and words[1] == "atoms":
                natoms_hdr = _int(words[0], path, lineno)
            elif len(words) == 4 and words[2:] == ["xlo", "xhi"]:
                box["x"] = (_float(words[0], path, lineno), _float(words[1], path, lineno))
            elif len(words) == 4 and words[2:] == ["ylo", "yhi"]:
                box["y"] = (_float(words[0], path, lineno), _float(words[1], path, lineno))
            elif len(words) == 4 and words[2:] == ["zlo", "zhi"]:
                box["z"] = (_float(words[0], path, lineno), _float(words[1], path, lineno))
            elif len(words) == 6 and words[3:] == ["xy", "xz", "yz"]:
                tilt = [_float(w, path, lineno) for w in words[:3]]
                if any(t != 0.0 for t in tilt):
                    fail(f"{path}:{lineno}: triclinic box (tilt factors {words[0]} {words[1]} "
                         f"{words[2]}). The frame needs an orthogonal periodic box: make the "
                         "packing with an orthogonal box (make_packing_2d.liggghts).")
            continue
        if section == "Atoms":
            if len(words) < 7:
                fail(f"{path}:{lineno}: Atoms line has {len(words)} columns, expected at least 7 "
                     "(atom_style sphere: id type diameter density x y z [ix iy iz]). "
                     f"Section started at line {section_line}; write the packing with "
                     "atom_style sphere.")
            aid = _int(words[0], path, lineno)
            atype = _int(words[1], path, lineno)
            d = _float(words[2], path, lineno)
            rho = _float(words[3], path, lineno)
            x = _float(words[4], path, lineno)
            y = _float(words[5], path, lineno)
            z = _float(words[6], path, lineno)
            if d <= 0.0:
                fail(f"{path}:{lineno}: atom {aid} has diameter {d} <= 0. Every particle "
                     "needs a positive diameter.")
            atoms.append({"id": aid, "type": atype, "d": d, "rho": rho,
                          "x": x, "y": y, "z": z, "line": lineno})
        # every other section (Velocities, ...) is ignored
    for k in ("x", "y", "z"):
        if k not in box:
            fail(f"{path}: no '{k}lo {k}hi' line in the header: unknown box. "
                 "Use a data file written by LIGGGHTS write_data.")
    if not atoms:
        fail(f"{path}: no atoms found (no Atoms section or it is empty). "
             "Check that the packing run wrote its particles (write_data).")
    if natoms_hdr is not None and natoms_hdr != len(atoms):
        fail(f"{path}: header says {natoms_hdr} atoms but the Atoms section has {len(atoms)} "
             "lines. The file is truncated or corrupt: regenerate it.")
    ids = set()
    for a in atoms:
        if a["id"] in ids:
            fail(f"{path}:{a['line']}: duplicate atom id {a['id']}.")
        ids.add(a["id"])
    return {"box": box, "atoms": atoms}


def _int(word, path, lineno):
    try:
        return int(word)
    except ValueError:
        fail(f"{path}:{lineno}: expected an integer, found '{word}'.")


def _float(word, path, lineno):
    try:
        value = float(word)
    except ValueError:
        fail(f"{path}:{lineno}: expected a number, found '{word}'.")
    if not math.isfinite(value):
        fail(f"{path}:{lineno}: '{word}' is not a finite number: fix or regenerate the packing.")
    return value


def areal_density(atoms, path, override):
    """LIGGGHTS 3.8 write_data stores rmass/(4/3 pi r^3) also in 2D. Detect it."""
    if override is not None:
        return [override] * len(atoms), "override"
    rho = [a["rho"] for a in atoms]
    r = [0.5 * a["d"] for a in atoms]
    if max(rho) <= 0.0:
        fail(f"{path}: non-positive densities; give --density RHO (kg/m^2).")

    def spread(v):
        m = sum(v) / len(v)
        return max(abs(x - m) for x in v) / m

    conv = [q * 4.0 / 3.0 * s for q, s in zip(rho, r)]
    if spread(rho) < 1e-6:
        return rho, "file"
    if spread(conv) < 1e-6:
        print(f"build_frame: note: {path}: the density column is rmass/(4/3 pi r^3) "
              "(LIGGGHTS write_data in 2D); converted to the areal density "
              f"{conv[0]:.6g} kg/m^2.", file=sys.stderr)
        return conv, "converted-from-3d"
    return rho, "file-per-particle"


# --------------------------------------------------------------------------- geometry
def wrap(v, L):
    w = v % L
    if w >= L:  # v % L can round up to L
        w -= L
    return w


def min_image(d, L):
    return d - L * round(d / L)


def build_cells(pos, Lx, Ly, cut):
    nx = max(1, int(Lx / cut))
    ny = max(1, int(Ly / cut))
    cells = {}
    for k, (x, y) in enumerate(pos):
        cx = min(nx - 1, int(wrap(x, Lx) / Lx * nx))
        cy = min(ny - 1, int(wrap(y, Ly) / Ly * ny))
        cells.setdefault((cx, cy), []).append(k)
    return cells, nx, ny


def periodic_contacts(pos, rad, Lx, Ly):
    """All pairs with overlap > 0, minimum image. Returns list (i, j, nx, ny, overlap, dist)."""
    cut = 2.0 * max(rad)
    cells, nx, ny = build_cells(pos, Lx, Ly, cut)
    out = []
    seen = set()
    for (cx, cy), members in cells.items():
        neigh = set()
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                neigh.add(((cx + dx) % nx, (cy + dy) % ny))
        cand = []
        for c in neigh:
            cand.extend(cells.get(c, ()))
        for i in members:
            for j in cand:
                if j <= i or (i, j) in seen:
                    continue
                seen.add((i, j))
                dx = min_image(pos[j][0] - pos[i][0], Lx)
                dy = min_image(pos[j][1] - pos[i][1], Ly)
                dist = math.hypot(dx, dy)
                ov = rad[i] + rad[j] - dist
                if ov > 0.0:
                    if dist == 0.0:
                        fail(f"particles {i} and {j} coincide.")
                    out.append((i, j, dx / dist, dy / dist, ov, dist))
    return out


def eig_sym2(a, b, c):
    """Eigenvalues (l1 >= l2) and angle of the l1 eigenvector of [[a, b], [b, c]]."""
    m = 0.5 * (a + c)
    rr = math.hypot(0.5 * (a - c), b)
    ang = 0.5 * math.degrees(math.atan2(2.0 * b, a - c))
    return m + rr, m - rr, ang


# --------------------------------------------------------------------------- main work
def build(args):
    data = read_data(args.packing)
    path = args.packing
    box = data["box"]
    atoms = sorted(data["atoms"], key=lambda a: a["id"])
    xlo, xhi = box["x"]
    ylo, yhi = box["y"]
    zlo, zhi = box["z"]
    Lx, Ly = xhi - xlo, yhi - ylo
    if Lx <= 0.0 or Ly <= 0.0:
        fail(f"{path}: box extents Lx={Lx}, Ly={Ly} must be positive: unknown box.")
    if abs(Lx - Ly) > args.square_tol * max(Lx, Ly) and not args.allow_rectangular:
        fail(f"{path}: box is not square (Lx={Lx:.9g}, Ly={Ly:.9g}). The reference RVEs are "
             "square; pass --allow-rectangular if a rectangular cell is intended.")
    n = len(atoms)
    rad = [0.5 * a["d"] for a in atoms]
    rho, rho_src = areal_density(atoms, path, args.density)
    rmax = max(rad)
    if 4.0 * rmax >= min(Lx, Ly):
        fail(f"{path}: twice the largest particle diameter {4*rmax:.6g} is not smaller than the cell "
             f"({Lx:.6g} x {Ly:.6g}); use a larger cell.")

    # --- corner particle
    if args.corner_id is not None:
        idx = [k for k, a in enumerate(atoms) if a["id"] == args.corner_id]
        if not idx:
            fail(f"{path}: --corner-id {args.corner_id} is not an atom id of the file.")
        ic = idx[0]
    else:
        best = None
        for k, a in enumerate(atoms):
            dx = min_image(a["x"] - xlo, Lx)
            dy = min_image(a["y"] - ylo, Ly)
            d2 = dx * dx + dy * dy
            if best is None or d2 < best[0]:
                best = (d2, k)
        ic = best[1]
    cx, cy = atoms[ic]["x"], atoms[ic]["y"]
    pos = []
    for k, a in enumerate(atoms):
        if k == ic:
            pos.append((0.0, 0.0))
        else:
            pos.append((wrap(a["x"] - cx, Lx), wrap(a["y"] - cy, Ly)))

    # --- contacts and overlap check on the periodic packing
    contacts = periodic_contacts(pos, rad, Lx, Ly)
    rmean = sum(rad) / n
    bad = []
    for (i, j, _, _, ov, _) in contacts:
        if ov > args.max_overlap * min(rad[i], rad[j]):
            bad.append((ov / min(rad[i], rad[j]), i, j))
    if bad:
        bad.sort(reverse=True)
        f, i, j = bad[0]
        fail(f"{path}: {len(bad)} contact(s) overlap more than {args.max_overlap:g} x the "
             f"smaller radius; worst: atoms {atoms[i]['id']} (line {atoms[i]['line']}) and "
             f"{atoms[j]['id']} (line {atoms[j]['line']}) overlap {f:.3g} x the smaller radius. "
             "The packing is over-compressed or not relaxed: relax it longer, lower the target "
             "packing fraction, or raise kn (or --max-overlap if intended).")

    # --- classify
    inner, left, bottom = [], [], []
    for k in range(n):
        if k == ic:
            continue
        x, y = pos[k]
        r = rad[k]
        cut_x = x < r or x > Lx - r
        cut_y = y < r or y > Ly - r
        if cut_x and cut_y:
            fail(f"{path}:{atoms[k]['line']}: atom {atoms[k]['id']} (r={r:.6g}) cuts both the "
                 f"line x=0 and the line y=0 (relative position {x:.6g}, {y:.6g} from the corner "
                 f"atom {atoms[ic]['id']}). Choose another corner particle with --corner-id, or "
                 "relax the packing (this needs a large overlap with the corner).")
        if cut_x:
            xl = x - Lx if x > Lx - r else x
            left.append((k, xl, y))
        elif cut_y:
            yb = y - Ly if y > Ly - r else y
            bottom.append((k, x, yb))
        else:
            inner.append(k)

    # --- frame, counter-clockwise from the corner at (0,0)
    frame = []  # (periodic index, role, pair, X, Y)
    bottom.sort(key=lambda t: t[1])
    left.sort(key=lambda t: t[2])
    pair_of = {}
    npair = 0
    for (k, x, y) in bottom:
        pair_of[k] = npair
        npair += 1
    for (k, x, y) in left:
        pair_of[k] = npair
        npair += 1
    frame.append((ic, "corner_00", -1, 0.0, 0.0))
    for (k, x, y) in bottom:
        frame.append((k, "bottom", pair_of[k], x, y))
    frame.append((ic, "corner_L0", -1, Lx, 0.0))
    for (k, x, y) in left:
        frame.append((k, "right", pair_of[k], x + Lx, y))
    frame.append((ic, "corner_LL", -1, Lx, Ly))
    for (k, x, y) in reversed(bottom):
        frame.append((k, "top", pair_of[k], x, y + Ly))
    frame.append((ic, "corner_0L", -1, 0.0, Ly))
    for (k, x, y) in reversed(left):
        frame.append((k, "left", pair_of[k], x, y))

    bodies = []  # (periodic index, type, X, Y)
    for k in inner:
        bodies.append((k, 1, pos[k][0], pos[k][1]))
    for (k, role, pr, X, Y) in frame:
        bodies.append((k, 2, X, Y))
    ntot = len(bodies)

    # --- check: every periodic contact is represented by two RVE bodies at the same
    #     branch vector (the frame is complete)
    by_particle = {}
    for b, (k, t, X, Y) in enumerate(bodies):
        by_particle.setdefault(k, []).append((X, Y))
    tol = 1e-9 * max(Lx, Ly)
    missing = 0
    for (i, j, nxc, nyc, ov, dist) in contacts:
        bx, by = nxc * dist, nyc * dist
        found = False
        for (Xi, Yi) in by_particle[i]:
            for (Xj, Yj) in by_particle[j]:
                if abs(Xj - Xi - bx) < tol and abs(Yj - Yi - by) < tol:
                    found = True
                    break
            if found:
                break
        if not found:
            missing += 1
    if missing:
        fail(f"{path}: internal error: {missing} periodic contact(s) are not represented in "
             "the RVE frame. Please report this with the packing file.")

    # --- contacts inside the (non-periodic) RVE. Two bodies that are both +Lx
    #     images (or both +Ly images) touch only as the second copy of the
    #     contact between their originals: fix rve/servo leaves such pairs out
    #     of LIGGGHTS' neighbour lists (rve_frame.h, duplicate_contact), so each
    #     physical contact is counted once. Check that this leaves exactly the
    #     periodic contacts.
    image_x_roles = {"right", "corner_L0", "corner_LL"}
    image_y_roles = {"top", "corner_0L", "corner_LL"}
    flags = [(False, False)] * len(inner) + [(role in image_x_roles, role in image_y_roles)
                                              for (_, role, _, _, _) in frame]
    c_rve = c_dup = 0
    bx_cells = {}
    h = 2.0 * rmax
    for b, (k, t, X, Y) in enumerate(bodies):
        bx_cells.setdefault((math.floor(X / h), math.floor(Y / h)), []).append(b)
    for (ix, iy), members in bx_cells.items():
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for b2 in bx_cells.get((ix + dx, iy + dy), ()):
                    for b1 in members:
                        if b2 <= b1:
                            continue
                        k1, _, X1, Y1 = bodies[b1]
                        k2, _, X2, Y2 = bodies[b2]
                        if math.hypot(X2 - X1, Y2 - Y1) < rad[k1] + rad[k2]:
                            duplicate = ((flags[b1][0] and flags[b2][0]) or
                                         (flags[b1][1] and flags[b2][1]))
                            c_dup += duplicate
                            c_rve += not duplicate
    if c_rve != len(contacts):
        fail(f"{path}: internal error: the RVE holds {c_rve} contacts (each once) but the periodic "
             f"packing {len(contacts)}. Please report this with the packing file.")

    # --- statistics
    C = len(contacts)
    zc = [0] * n
    f11 = f12 = f22 = 0.0
    ovmax = 0.0
    ovsum = 0.0
    for (i, j, nxc, nyc, ov, dist) in contacts:
        zc[i] += 1
        zc[j] += 1
        f11 += nxc * nxc
        f12 += nxc * nyc
        f22 += nyc * nyc
        ovmax = max(ovmax, ov)
        ovsum += ov
    n0 = sum(1 for z in zc if z == 0)
    n1 = sum(1 for z in zc if z == 1)
    coord = 2.0 * C / n
    mech = (2.0 * C - n1) / (n - n0 - n1) if n - n0 - n1 > 0 else 0.0
    if C > 0:
        f11 /= C
        f12 /= C
        f22 /= C
        p1, p2, ang = eig_sym2(f11, f12, f22)
        aniso = p1 / p2 - 1.0 if p2 > 0 else float("inf")
    else:
        p1 = p2 = ang = 0.0
        aniso = 0.0
    area = lambda k: math.pi * rad[k] * rad[k]
    a_inner = sum(area(k) for k in inner)
    a_pairs = sum(area(k) for (k, _, _) in left) + sum(area(k) for (k, _, _) in bottom)
    a_corner = area(ic)
    phi = (a_inner + a_pairs + a_corner) / (Lx * Ly)
    phi_periodic = sum(area(k) for k in range(n)) / (Lx * Ly)
    rmin = min(rad)
    masses = [rho[k] * area(k) for k in range(n)]

    stats = [
        ("source", os.path.basename(path)),
        ("n_periodic", n),
        ("n_inner", len(inner)),
        ("n_edge_pairs", len(left) + len(bottom)),
        ("n_edge_pairs_left_right", len(left)),
        ("n_edge_pairs_bottom_top", len(bottom)),
        ("n_corner", 4),
        ("n_frame", len(frame)),
        ("n_rve_total", ntot),
        ("corner_periodic_id", atoms[ic]["id"]),
        ("Lx", f"{Lx:.12g}"),
        ("Ly", f"{Ly:.12g}"),
        ("R_min", f"{rmin:.9g}"),
        ("R_max", f"{rmax:.9g}"),
        ("R_mean", f"{rmean:.9g}"),
        ("R_min_over_L", f"{rmin / max(Lx, Ly):.6g}"),
        ("R_max_over_R_min", f"{rmax / rmin:.6g}"),
        ("density_areal", f"{sum(rho) / n:.9g}"),
        ("density_source", rho_src),
        ("mass_min", f"{min(masses):.9g}"),
        ("packing_fraction", f"{phi:.6f}"),
        ("n_contacts", C),
        ("coordination", f"{coord:.4f}"),
        ("coordination_mechanical", f"{mech:.4f}"),
        ("n_rattlers_0_contacts", n0),
        ("n_1_contact", n1),
        ("fabric_11", f"{f11:.6f}"),
        ("fabric_12", f"{f12:.6f}"),
        ("fabric_22", f"{f22:.6f}"),
        ("fabric_major", f"{p1:.6f}"),
        ("fabric_minor", f"{p2:.6f}"),
        ("fabric_major_angle_deg", f"{ang:.2f}"),
        ("anisotropy", f"{aniso:.4f}"),
        ("overlap_max_over_R_mean", f"{ovmax / rmean:.5g}"),
        ("overlap_mean_over_R_mean", f"{(ovsum / C if C else 0.0) / rmean:.5g}"),
        ("frame_contacts_missing", missing),
        ("n_contacts_rve", c_rve),
        ("n_contacts_rve_second_copies", c_dup),
    ]
    if abs(phi - phi_periodic) > 1e-9:
        fail(f"{path}: internal error: packing fraction of the frame {phi} differs from the "
             f"periodic one {phi_periodic}.")

    # --- write outputs
    outdir = args.outdir if args.outdir else (os.path.dirname(os.path.abspath(path)))
    name = args.name
    os.makedirs(outdir, exist_ok=True)
    rve_path = os.path.join(outdir, name + ".rve.data")
    mx, my = args.margin * Lx, args.margin * Ly
    with open(rve_path, "w") as fh:
        fh.write(f"FE2DEM RVE {name} from {os.path.basename(path)}: type 1 inner ({len(inner)}), "
                 f"type 2 frame ({len(frame)}, counter-clockwise from corner (0,0)), "
                 f"Lx {Lx:.12g} Ly {Ly:.12g}\n\n")
        fh.write(f"{ntot} atoms\n2 atom types\n\n")
        fh.write(f"{-mx:.16e} {Lx + mx:.16e} xlo xhi\n")
        fh.write(f"{-my:.16e} {Ly + my:.16e} ylo yhi\n")
        fh.write(f"{zlo:.16e} {zhi:.16e} zlo zhi\n\n")
        fh.write("Atoms # sphere: id type diameter density x y z\n\n")
        for b, (k, t, X, Y) in enumerate(bodies):
            fh.write(f"{b + 1} {t} {2.0 * rad[k]:.16e} {rho[k]:.12g} {X:.16e} {Y:.16e} "
                     f"{0.0:.16e}\n")
    frame_path = os.path.join(outdir, name + ".frame.txt")
    with open(frame_path, "w") as fh:
        fh.write("# frame particles of " + name + ".rve.data, counter-clockwise from corner (0,0)\n")
        fh.write("# rve_id role pair periodic_id X Y R\n")
        for q, (k, role, pr, X, Y) in enumerate(frame):
            fh.write(f"{len(inner) + q + 1} {role} {pr} {atoms[k]['id']} {X:.16e} {Y:.16e} "
                     f"{rad[k]:.16e}\n")
    vars_path = os.path.join(outdir, name + ".vars")
    with open(vars_path, "w") as fh:
        fh.write(f"# FE2DEM RVE {name}: include after read_data {name}.rve.data\n")
        fh.write(f"variable rve_Lx equal {Lx:.16e}\n")
        fh.write(f"variable rve_Ly equal {Ly:.16e}\n")
        fh.write(f"variable rve_natoms equal {ntot}\n")
        fh.write(f"variable rve_ninner equal {len(inner)}\n")
        fh.write(f"variable rve_nframe equal {len(frame)}\n")
        fh.write(f"variable rve_nedgepairs equal {len(left) + len(bottom)}\n")
        fh.write(f"variable rve_Rmin equal {rmin:.16e}\n")
        fh.write(f"variable rve_Rmax equal {rmax:.16e}\n")
        fh.write(f"variable rve_massmin equal {min(masses):.16e}\n")
        fh.write(f"variable rve_phi equal {phi:.9f}\n")
    stats_path = os.path.join(outdir, name + ".stats.txt")
    with open(stats_path, "w") as fh:
        for k, v in stats:
            fh.write(f"{k} {v}\n")
    if not args.quiet:
        for k, v in stats:
            print(f"{k} {v}")
        print(f"wrote {rve_path}, {vars_path}, {stats_path}, {frame_path}")
    return 0


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("packing", help="periodic packing (LIGGGHTS write_data, atom_style sphere)")
    ap.add_argument("name", nargs="?", help="output base name (default: packing file name "
                    "without .periodic.data/.data)")
    ap.add_argument("--outdir", help="output folder (default: the packing's folder)")
    ap.add_argument("--corner-id", type=int, help="atom id of the corner particle "
                    "(default: the one closest to the cell origin)")
    ap.add_argument("--density", type=float, help="areal density kg/m^2 to write "
                    "(default: from the file, corrected for LIGGGHTS' 2D write_data)")
    ap.add_argument("--max-overlap", type=float, default=0.1,
                    help="error if an overlap exceeds this fraction of the smaller radius")
    ap.add_argument("--margin", type=float, default=0.5,
                    help="box margin around the cell, fraction of Lx/Ly (default 0.5)")
    ap.add_argument("--allow-rectangular", action="store_true", help="accept Lx != Ly")
    ap.add_argument("--square-tol", type=float, default=1e-9)
    ap.add_argument("--quiet", action="store_true")
    args = ap.parse_args(argv)
    if args.name is None:
        base = os.path.basename(args.packing)
        for suf in (".periodic.data", ".data"):
            if base.endswith(suf):
                base = base[: -len(suf)]
                break
        args.name = base
    try:
        return build(args)
    except FrameError as exc:
        print(f"build_frame: ERROR: {exc}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
