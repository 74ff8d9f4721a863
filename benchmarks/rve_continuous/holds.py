#!/usr/bin/env python3
"""A path held at rest against the same path loaded without stopping
(issue 35): does relaxing at fixed strain lose stress?

Usage:
  holds.py yade CONT_CSV HELD_CSV        YADE periodic cells (periodic_3d.py,
                                         RELAX_EVERY): the held rows
                                         (hold_steps > 0) against the rows of
                                         the continuous run at the same strain
  holds.py rve CONT_CSV HELD_CSV EVERY [TOL SERVO_TOL RELAX_TOL]
                                         fe2dem-rve continuous drives, the
                                         second with 'Hold rows' = EVERY; with
                                         the tolerances a check: every held row
                                         at rest (residual <= SERVO_TOL,
                                         ekin_epot <= RELAX_TOL), no other row
                                         (it is moving), and the held axial
                                         stress within TOL of the continuous one

One line per held row: strain, axial stress of both and their relative
difference, the same for the deviator q, the lateral stresses, and the
fraction of sliding contacts of both. Every held row continues from the
held state of the ones before, so differences accumulate along the path.
"""
import csv
import sys


def yade_rows(path):
    rows = csv.DictReader(line for line in open(path) if not line.startswith("#"))
    return [r for r in rows if r["stage"] in ("triaxial", "shear")]


def line(strain, a, b, qa, qb, lat_a, lat_b, sl_a, sl_b):
    return (f"{strain:.4f}  {a:9.0f} {b:9.0f} {100 * (b / a - 1):+6.2f}%  q {100 * (qb / qa - 1):+6.2f}%  "
            f"lateral {lat_a:8.0f} {lat_b:8.0f}  sliding {sl_a:.3f} {sl_b:.3f}")


def yade(cont, held):
    c = {r["strain"]: r for r in yade_rows(cont)}
    f = lambda r, k: float(r[k])
    for h in yade_rows(held):
        if int(h["hold_steps"]) == 0 or h["strain"] not in c:
            continue
        r = c[h["strain"]]
        print(line(f(h, "strain"), f(r, "sigma33_Pa"), f(h, "sigma33_Pa"), f(r, "q_Pa"), f(h, "q_Pa"),
                   f(r, "sigma11_Pa"), f(h, "sigma11_Pa"), f(r, "sliding_fraction"), f(h, "sliding_fraction")))


def rve(cont, held, every, tols=None):
    def load(path):
        rows = list(csv.DictReader(open(path)))
        first = next(k for k, r in enumerate(rows) if float(r["drive_time_s"]) > 0.0)
        return rows[first - 1], rows[first:]  # the state the drive starts from, the driven rows

    (ic, c), (_, h) = load(cont), load(held)
    F = lambda r, k: float(r[f"F{k + 1}{k + 1}"])
    a = max(range(3), key=lambda k: abs(F(c[-1], k) - F(ic, k)))  # the axial direction
    lat = [k for k in range(3) if k != a]
    s = lambda r, k: float(r[f"sigma{k + 1}{k + 1}"])
    q = lambda r: s(r, a) - 0.5 * sum(s(r, k) for k in lat)
    sl = lambda r: float(r["sliding_contacts"]) / max(float(r["contacts"]), 1.0)
    failures = []
    for k, (r, x) in enumerate(zip(c, h), start=1):
        at_rest = tols and float(x["residual"]) <= tols[1] and float(x["ekin_epot"]) <= tols[2]
        if k % every == 0:
            print(line(1.0 - F(r, a) / F(ic, a), s(r, a), s(x, a), q(r), q(x), s(r, lat[0]), s(x, lat[0]),
                       sl(r), sl(x)))
            if tols and not at_rest:
                failures.append(f"held row {k} is not at rest (r_a {x['residual']}, E_kin/E_pot {x['ekin_epot']})")
            if tols and abs(s(x, a) / s(r, a) - 1.0) > tols[0]:
                failures.append(f"held row {k}: axial stress {100 * (s(x, a) / s(r, a) - 1):+.2f} %")
        elif at_rest:
            failures.append(f"row {k} is not held but at rest: the check cannot tell held rows")
    if tols:
        for f in failures:
            print("FAIL: " + f)
        print(f"{min(len(c), len(h)) // every} held rows, tolerance {100 * tols[0]:.1f}%")
        sys.exit(1 if failures else 0)


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "yade":
        yade(sys.argv[2], sys.argv[3])
    elif len(sys.argv) in (5, 8) and sys.argv[1] == "rve":
        rve(sys.argv[2], sys.argv[3], int(sys.argv[4]), [float(x) for x in sys.argv[5:]] or None)
    else:
        sys.exit(__doc__)
