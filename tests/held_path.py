#!/usr/bin/env python3
"""The continuous path held at rest (issue 35): fe2dem-rve's continuous drive
gives a path F(t); a table path through some of its F, solved quasi-statically
at each row (relaxed, frame balanced), must give the same stresses if
stopping and relaxing loses nothing, as YADE's periodic cell held at fixed
strain after loading at the same rate shows (benchmarks/rve_continuous).

Usage:
  held_path.py table RVE_CSV EVERY OUT [ROWS]
                                           the rows of the isotropic stage and
                                           every EVERY-th row of the continuous
                                           stage of RVE_CSV (of its first ROWS)
                                           as a 3D 'Table file'
  held_path.py check REF_CSV HELD_CSV TOL [Q_TOL]
                                           the held rows against the reference
                                           rows with the same F: the axial
                                           stress within TOL and the deviator
                                           q = sigma_a - (sum of the lateral)/2
                                           within Q_TOL (default TOL), relative
"""
import csv
import sys

F_NAMES = [f"F{i}{j}" for i in range(1, 4) for j in range(1, 4)]


def rows(path):
    return list(csv.DictReader(open(path)))


def F(r):
    return [float(r[n]) for n in F_NAMES]


def table(rve_csv, every, out, n_rows=None):
    rs = rows(rve_csv)
    iso = [r for r in rs[1:] if float(r["drive_time_s"]) == 0.0]
    loading = [r for r in rs[1:] if float(r["drive_time_s"]) > 0.0][:n_rows]
    if not iso or not loading:
        sys.exit(f"held_path.py: {rve_csv} has no isotropic or no continuous rows")
    with open(out, "w") as f:
        f.write(f"# held_path.py: {rve_csv}, isotropic rows and every {every}-th continuous row\n")
        for r in iso + loading[every - 1::every]:
            f.write(" ".join(repr(x) for x in F(r)) + "\n")


def check(ref_csv, held_csv, tol, q_tol):
    ref = [r for r in rows(ref_csv) if float(r["drive_time_s"]) > 0.0]
    a = max(range(3), key=lambda k: abs(F(ref[-1])[4 * k] - 1.0))  # the axial component
    lateral = [k for k in range(3) if k != a]
    sig = lambda r, k: float(r[f"sigma{k + 1}{k + 1}"])
    q = lambda r: sig(r, a) - 0.5 * sum(sig(r, k) for k in lateral)
    checked, worst, failed = 0, 0.0, False
    for h in rows(held_csv):
        match = [r for r in ref if max(abs(x - y) for x, y in zip(F(r), F(h))) < 1e-9]
        if not match:
            continue
        r = match[0]
        d_axial = sig(h, a) / sig(r, a) - 1.0
        d_q = q(h) / q(r) - 1.0
        bad = abs(d_axial) > tol or abs(d_q) > q_tol
        failed |= bad
        worst = max(worst, abs(d_axial), abs(d_q))
        checked += 1
        print(f"{'FAIL' if bad else 'ok  '} F{a + 1}{a + 1} = {F(h)[4 * a]:.6f}: axial {sig(h, a):.6g} vs "
              f"{sig(r, a):.6g} ({100 * d_axial:+.2f} %), q {q(h):.6g} vs {q(r):.6g} ({100 * d_q:+.2f} %)")
    if checked == 0:
        print("FAIL: no held row has the F of a continuous row")
        sys.exit(1)
    print(f"{checked} rows, largest difference {100 * worst:.2f} %, tolerance {100 * tol:.1f}% "
          f"(q {100 * q_tol:.1f}%)")
    if failed:
        print("FAIL: a held row is off the continuous path")
        sys.exit(1)


if __name__ == "__main__":
    if len(sys.argv) in (5, 6) and sys.argv[1] == "table":
        table(sys.argv[2], int(sys.argv[3]), sys.argv[4], int(sys.argv[5]) if len(sys.argv) == 6 else None)
    elif len(sys.argv) in (5, 6) and sys.argv[1] == "check":
        tol = float(sys.argv[4])
        check(sys.argv[2], sys.argv[3], tol, float(sys.argv[5]) if len(sys.argv) == 6 else tol)
    else:
        sys.exit(__doc__)
