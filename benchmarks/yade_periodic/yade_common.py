"""Helpers shared by the YADE reference scripts: biaxial_periodic.py (2D)
and periodic_3d.py (3D), and by their post-processing (compare.py,
compare_3d.py; read_yade_csv). They run under `yade -x SCRIPT`, where __file__ is
yade's own launcher, so each script puts its folder (sys.argv[0]) on
sys.path before importing this module."""
import csv
import math
import os
import sys


def make_fail(script):
    """An error reporter that names @p script and ends YADE at once (exit 2)."""
    def fail(msg):
        print("%s: ERROR: %s" % (script, msg), file=sys.stderr)
        sys.stdout.flush()
        sys.stderr.flush()
        os._exit(2)
    return fail


def apply_overrides(args, namespace, fail):
    """NAME=VALUE overrides of the numeric upper-case parameters in @p namespace
    (a script's globals()), for checks only. Returns them as 'NAME=value' strings."""
    done = []
    for a in args:
        k, _, v = a.partition("=")
        if k not in namespace or k.upper() != k or not isinstance(namespace[k], (int, float)):
            fail("unknown parameter override " + a)
        namespace[k] = type(namespace[k])(float(v))
        done.append("%s=%s" % (k, namespace[k]))
    return done


def read_lammps_data(path, fail, axes):
    """A LIGGGHTS write_data file of atom style sphere: the box {'x': (lo, hi), ...}
    (every axis of @p axes required) and the atoms, sorted by id, as tuples
    (id, radius, density, x, y, z)."""
    box, atoms, sec = {}, [], None
    natoms = None
    with open(path) as f:
        for ln in f:
            t = ln.split()
            if not t:
                continue
            if len(t) == 2 and t[1] == "atoms":
                natoms = int(t[0])
            elif len(t) == 4 and t[2] in ("xlo", "ylo", "zlo"):
                box[t[2][0]] = (float(t[0]), float(t[1]))
            elif t[0] in ("Atoms", "Velocities", "Bonds", "Masses"):
                sec = t[0]
            elif sec == "Atoms" and len(t) >= 7:
                # id type diameter density x y z [ix iy iz]
                atoms.append((int(t[0]), 0.5 * float(t[2]), float(t[3]),
                              float(t[4]), float(t[5]), float(t[6])))
    if natoms is None or len(atoms) != natoms:
        fail(f"{path}: read {len(atoms)} atoms, header says {natoms}")
    if any(c not in box for c in axes):
        fail(f"{path}: no {'/'.join(c + 'lo' for c in axes)} box lines")
    return box, sorted(atoms)


def fmt(v):
    """A CSV field: strings as they are, integers exactly, floats with 10 digits."""
    if isinstance(v, str):
        return v
    if isinstance(v, int):
        return str(v)
    return "%.10g" % v


def write_csv(path, rows, header_lines, columns):
    """'# ' header lines, the column names, then one line per row (dicts)."""
    with open(path, "w") as f:
        for h in header_lines:
            f.write("# " + h + "\n")
        f.write(",".join(columns) + "\n")
        for r in rows:
            f.write(",".join(fmt(r[c]) for c in columns) + "\n")


def pi_rate(err, integ, k, ti, tau, dmax):
    """PI servo: the strain rate (err + integ/ti)/(k tau), bounded by +-dmax."""
    d = (err + integ / ti) / (k * tau)
    return max(-dmax, min(dmax, d))


def read_yade_csv(path):
    """A CSV the scripts wrote: the 'key value key value ...' pairs of its '#'
    header lines (the first value of a key wins) and its rows, every column
    a float but 'stage'."""
    meta, lines = {}, []
    with open(path) as f:
        for ln in f:
            if ln.startswith("#"):
                t = ln[1:].split()
                for k, v in zip(t[0::2], t[1::2]):
                    meta.setdefault(k, v)
            else:
                lines.append(ln)
    rows = [{k: (v if k == "stage" else float(v)) for k, v in r.items()} for r in csv.DictReader(lines)]
    return meta, rows


def dt_estimate(bodies, interactions, n, axis):
    """Stiffness-based critical steps (as GlobalStiffnessTimeStepper, no safety):
    min sqrt(m / sum kn) and min sqrt(I / sum ks r^2) over the @p n bodies,
    I the inertia about @p axis (2D discs: z; spheres: any)."""
    ksum = [0.0] * n
    krot = [0.0] * n
    for i in interactions:
        for bid in (i.id1, i.id2):
            r = bodies[bid].shape.radius
            ksum[bid] += i.phys.kn
            krot[bid] += i.phys.ks * r * r
    dtt = min(math.sqrt(bodies[k].state.mass / ksum[k]) for k in range(n) if ksum[k] > 0)
    dtr = min(math.sqrt(bodies[k].state.inertia[axis] / krot[k]) for k in range(n) if krot[k] > 0)
    return dtt, dtr
