#!/usr/bin/env python3
"""The RVE against YADE's periodic cell over an ensemble of loading rates.

    rate_ensemble.py PATH --yade Y1.csv Y2.csv ... --rve R1.csv R2.csv ... [--to 0.05]
                     [--require TO_PEAK AFTER]

PATH is triaxial or shear. On a packing as small as small_3d (300 spheres)
one constant-rate curve is not a smooth function of strain: slip events
land at different strains at different rates, and YADE's own curves at
0.25 and 0.125 /s differ by up to 7.8 % in q/p before the peak. A rate that
low is already quasi-static (inertial number ~1e-5), so the spread is the
sample's, not the rate's, and the curves at several rates are an ensemble
of the same quasi-static response. This script compares the two ensembles:
at every 0.25 % of strain the mean over rates of q/p (shear: tau/p) and its
spread (max - min over the mean) for YADE and for the RVE, the relative
difference of the means and its standard error se = sqrt(s_Y^2/n_Y +
s_R^2/n_R) / mean_Y (s the sample standard deviations over the members); then the largest |difference| to the peak of
YADE's mean curve, the mean |difference| from there to --to, and YADE's
own scatter (the largest difference between two of its rates to the same
peak) beside it. Prints `name value unit` lines after the table. With --require the exit
status is 1 unless the largest difference to the peak is at most TO_PEAK
and the mean after it at most AFTER (ctest; the issue's 0.03 and 0.05).
Needs only the standard library (reads compare_3d.py's readers).
"""
import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "yade_periodic"))
from compare_3d import detect_ic, interp, read_rve, rve_curve  # noqa: E402
from yade_common import read_yade_csv  # noqa: E402


def yade_curve(path, csv_file):
    meta, rows = read_yade_csv(csv_file)
    key = "q_over_p" if path == "triaxial" else "tau_over_p"
    cur = [{"strain": r["strain"], "ratio": r[key]} for r in rows if r["stage"] == path]
    return float(meta["rate"]), cur


def rve_ratio_curve(path, csv_file):
    rows = read_rve(csv_file)
    cur = rve_curve(rows, detect_ic(rows, path), path)
    if path == "shear":
        for c in cur:
            c["ratio"] = abs(c["ratio"])
    return cur


def stats(values):
    """The mean, the spread (max - min) over the mean, and the sample variance."""
    m = sum(values) / len(values)
    var = sum((v - m) ** 2 for v in values) / (len(values) - 1) if len(values) > 1 else 0.0
    return m, (max(values) - min(values)) / abs(m) if m else float("nan"), var


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("path", choices=("triaxial", "shear"))
    ap.add_argument("--yade", nargs="+", required=True)
    ap.add_argument("--rve", nargs="+", required=True)
    ap.add_argument("--to", type=float, default=0.05)
    ap.add_argument("--require", nargs=2, type=float, metavar=("TO_PEAK", "AFTER"))
    a = ap.parse_args()
    yade = [yade_curve(a.path, f)[1] for f in a.yade]
    rve = [rve_ratio_curve(a.path, f) for f in a.rve]
    strains = [0.0025 * k for k in range(1, int(round(a.to / 0.0025)) + 1)]
    rows = []
    for e in strains:
        y = [interp(c, "ratio", e) for c in yade]
        r = [interp(c, "ratio", e) for c in rve]
        if None in y or None in r:
            break
        rows.append((e, y, r))
    name = "q/p" if a.path == "triaxial" else "tau/p"
    print("| strain | YADE %s, mean of %d rates | YADE spread | RVE %s, mean of %d rates | RVE spread | RVE - YADE "
          "| se |" % (name, len(yade), name, len(rve)))
    print("|---|---|---|---|---|---|---|")
    means = []
    for e, y, r in rows:
        ym, ys, yv = stats(y)
        rm, rs, rv = stats(r)
        se = (yv / len(y) + rv / len(r)) ** 0.5 / ym
        means.append((e, ym, rm, se))
        print("| %.2f %% | %.4f | %.1f %% | %.4f | %.1f %% | %+.2f %% | %.2f %% |"
              % (100 * e, ym, 100 * ys, rm, 100 * rs, 100 * (rm / ym - 1), 100 * se))
    peak = max(range(len(means)), key=lambda i: means[i][1])
    to_peak = [abs(rm / ym - 1) for _, ym, rm, _ in means[:peak + 1]]
    after = [abs(rm / ym - 1) for _, ym, rm, _ in means[peak + 1:]]
    own = 0.0
    for i in range(len(yade)):
        for j in range(i + 1, len(yade)):
            for _, y, _ in rows[:peak + 1]:
                own = max(own, abs(y[i] / y[j] - 1), abs(y[j] / y[i] - 1))
    print()
    print("rates_yade %d -" % len(yade))
    print("rates_rve %d -" % len(rve))
    print("peak_strain_yade_mean %.4f -" % means[peak][0])
    print("peak_yade_mean %.4f -" % means[peak][1])
    print("peak_rve_mean_same_strain %.4f -" % means[peak][2])
    print("largest_rel_diff_to_peak %.4f -" % max(to_peak))
    if after:
        print("mean_abs_rel_diff_after_peak %.4f -" % (sum(after) / len(after)))
    print("yade_own_largest_rel_diff_between_rates_to_peak %.4f -" % own)
    if a.require:
        ok = max(to_peak) <= a.require[0] and (not after or sum(after) / len(after) <= a.require[1])
        print("%s: RVE ensemble against YADE's, largest %.2f %% to the peak (limit %.1f %%), mean %s after "
              "(limit %.1f %%)" % ("PASS" if ok else "FAIL", 100 * max(to_peak), 100 * a.require[0],
                                   "%.2f %%" % (100 * sum(after) / len(after)) if after else "-",
                                   100 * a.require[1]))
        return 0 if ok else 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
