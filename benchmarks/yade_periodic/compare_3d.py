#!/usr/bin/python3
"""Post-processing of the 3D YADE reference (run by run_3d.sh).

    /usr/bin/python3 compare_3d.py [--results DIR] [--rve NAME=RVE_CSV[@IC_ROW] ...]
                                   [--ic-row K] [--plot FILE.png] [--tables FILE.md]
                                   [--pair LABEL=A.csv,B.csv ...] [--no-files]

DIR (default results_3d next to this script) holds the runs of periodic_3d.py,
DIR/PACKING_PATH_rate{1,0.5}.csv (+ _trace.csv), PATH = triaxial | shear.

Without --rve: prints `name value unit` lines for every run found (isotropic
state, q/p or tau/p peak and its strain, servo error, wall time) and the
rate check (base against half rate, same strain points): max |d q/p| (shear:
|d tau/p|) and max |d vol_strain| up to 1 %, up to the base-rate peak (the
largest ratio recorded, which for a still rising curve is the 5 % point) and
up to 5 %.  --pair LABEL=A.csv,B.csv does the same for any two runs
(checks_3d.sh).  Writes DIR/tables_3d.md and, with matplotlib,
DIR/yade_3d.png (ratio and volumetric strain against strain, both paths,
every packing and rate).

--rve NAME=FILE compares an fe2dem-rve rve.csv with the YADE base-rate run
NAME (e.g. lsyf_1000_triaxial or small_3d_shear).  The RVE strain is taken
relative to its isotropic end state ("ic" row): triaxial e_a = 1 - F33/F33_ic,
shear gamma = F12/F22_ic (the (1,2) entry of F F_ic^-1: x offset of the
y period over its height at ic, as gamma in periodic_3d.py).  The ic row is
detected (triaxial: the last row from which the loading rows have uniform
increments of e_a; shear: the last row with F12 = 0), or given by @IC_ROW
(row index in the file, 0 = first data row) or --ic-row K for all files.
The RVE curve is interpolated linearly onto the YADE record strains; printed:
a table (strain, YADE and RVE q/p (shear tau/p), relative difference
(RVE - YADE)/YADE, the axial stress s33 (shear: sigma12) likewise, and the
volumetric strains), the maximum relative difference of the ratio up to the
YADE peak (also only at the YADE strains that are RVE rows, within 1e-4, free
of interpolation error) and the mean |relative difference| (and the mean
signed one) from the peak to 5 %.  The
strain-0 point is left out of relative differences (ratio ~ 0 there).
Stresses: both codes tension positive, Pa.
"""
import argparse
import csv
import math
import os
import sys

from yade_common import read_yade_csv as read_yade

HERE = os.path.dirname(os.path.abspath(__file__))
P = 1.0e5
PATHS = ("triaxial", "shear")
RATES = ("1", "0.5")


def out(name, value, unit="-"):
    if isinstance(value, float):
        value = "%.6g" % value
    print("%s %s %s" % (name, value, unit))


def ratio_key(path):
    return "q_over_p" if path == "triaxial" else "tau_over_p"


def stress_key(path):
    return "sigma33_Pa" if path == "triaxial" else "sigma12_Pa"


# ------------------------------------------------------------------ RVE input
def read_rve(path):
    with open(path) as f:
        rows = [{k: float(v) for k, v in r.items() if v not in ("", None)}
                for r in csv.DictReader(l for l in f if not l.startswith("#"))]
    for r in rows:
        s = [r["sigma11"], r["sigma22"], r["sigma33"]]
        r["p"] = -sum(s) / 3.0
        r["q"] = 0.5 * (s[0] + s[1]) - s[2]
        r["J"] = det3([[r["F%d%d" % (i, j)] for j in (1, 2, 3)] for i in (1, 2, 3)])
    return rows


def det3(a):
    return (a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
            - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
            + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]))


def detect_ic(rows, path):
    if path == "shear":
        k = max(i for i, r in enumerate(rows) if r["F12"] == 0.0)
        return k
    # triaxial: the loading rows have e_a = 1 - F33/F33_ic = k * de; the ic
    # row is the last one from which all following rows fit that pattern
    for j in range(len(rows) - 2):
        f0 = rows[j]["F33"]
        e = [1.0 - rows[i]["F33"] / f0 for i in range(j + 1, len(rows))]
        de = e[0]
        if de > 0 and all(abs(e[k] - (k + 1) * de) < 1e-6 for k in range(len(e))):
            return j
    raise SystemExit("compare_3d.py: cannot detect the isotropic end row; give --ic-row")


def rve_curve(rows, ic, path):
    r0 = rows[ic]
    cur = []
    for r in rows[ic:]:
        if path == "triaxial":
            e = 1.0 - r["F33"] / r0["F33"]
            ratio = r["q"] / r["p"]
            sax = r["sigma33"]
        else:
            e = r["F12"] / r0["F22"]
            ratio = r["sigma12"] / r["p"]
            sax = r["sigma12"]
        cur.append({"strain": e, "ratio": ratio, "stress": sax, "p": r["p"],
                    "ev": r["J"] / r0["J"] - 1.0, "step": int(r["step"])})
    return cur


def interp(cur, key, x):
    # the YADE record is taken at the first servo call past the target
    # strain (overshoot < 1e-5); accept the RVE's end points within 1e-4
    if cur and 0.0 < x - cur[-1]["strain"] < 1e-4:
        return cur[-1][key]
    for a, b in zip(cur, cur[1:]):
        if a["strain"] <= x + 1e-12 and x <= b["strain"] + 1e-12:
            w = 0.0 if b["strain"] == a["strain"] else (x - a["strain"]) / (b["strain"] - a["strain"])
            return a[key] + w * (b[key] - a[key])
    return None


# ------------------------------------------------------------------ main
def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--results", default=os.path.join(HERE, "results_3d"))
    ap.add_argument("--rve", action="append", default=[], metavar="NAME=FILE[@IC_ROW]")
    ap.add_argument("--ic-row", type=int, default=None)
    ap.add_argument("--pair", action="append", default=[], metavar="LABEL=A.csv,B.csv",
                    help="extra check: two periodic_3d.py runs of one path (e.g. dt or servo "
                         "variants), compared at their records as in the rate check")
    ap.add_argument("--plot", default=None)
    ap.add_argument("--tables", default=None)
    ap.add_argument("--no-files", action="store_true", help="print only, write no tables or plot")
    a = ap.parse_args()
    res = a.results
    tables = ["# YADE periodic 3D reference: tables (written by compare_3d.py)\n"]

    # ---------------- YADE runs
    runs = {}
    for fn in sorted(os.listdir(res)):
        for path in PATHS:
            for tag in RATES:
                suf = "_%s_rate%s.csv" % (path, tag)
                if fn.endswith(suf):
                    runs[(fn[:-len(suf)], path, tag)] = read_yade(os.path.join(res, fn))
    total_wall = 0.0
    peaks = {}
    for (pack, path, tag) in sorted(runs, key=lambda k: (k[0], k[1], -float(k[2]))):
        meta, rows = runs[(pack, path, tag)]
        key = "%s_%s_rate%s" % (pack, path, tag)
        rk = ratio_key(path)
        ini = [r for r in rows if r["stage"] == "initial"][0]
        iso = [r for r in rows if r["stage"] == "isotropic"][0]
        ld = [r for r in rows if r["stage"] == path]
        if tag == "1" or (pack, path, "1") not in runs:
            out(key + "_initial_contacts", int(ini["n_contacts"]))
            out(key + "_initial_p", ini["p_Pa"], "Pa")
            out(key + "_iso_Lx", float(meta["Lx_ic"]), "m")
            out(key + "_iso_Ly", float(meta["Ly_ic"]), "m")
            out(key + "_iso_Lz", float(meta["Lz_ic"]), "m")
            out(key + "_iso_contacts", int(iso["n_contacts"]))
            out(key + "_iso_coordination", iso["coordination"])
            out(key + "_iso_coordination_mech", iso["coordination_mech"])
            out(key + "_iso_rattlers", int(iso["rattlers"]))
            out(key + "_iso_sigma12", iso["sigma12_Pa"], "Pa")
            out(key + "_iso_steps", int(meta["iso_steps"]), "steps")
        out(key + "_strain_rate", float(meta["rate"]), "1/s")
        pk = max(ld, key=lambda r: r[rk])
        peaks[(pack, path, tag)] = pk
        out(key + "_peak_" + rk, pk[rk])
        out(key + "_strain_at_peak", pk["strain"])
        out(key + "_final_" + rk, ld[-1][rk])
        out(key + "_final_vol_strain", ld[-1]["vol_strain"])
        out(key + "_min_vol_strain", min(r["vol_strain"] for r in ld))
        out(key + "_max_servo_err_records", max(abs(r["lateral_err_rel"]) for r in ld))
        tp = os.path.join(res, "%s_trace.csv" % key)
        if os.path.exists(tp):
            tr = [r for r in read_yade(tp)[1] if r["stage"] == path]
            out(key + "_max_servo_err_trace", max(abs(r["lateral_err_rel"]) for r in tr))
        out(key + "_max_hold_steps", int(max(r["hold_steps"] for r in ld)), "steps")
        if "load_steps" in meta:
            out(key + "_load_steps", int(meta["load_steps"]), "steps")
            out(key + "_wall", float(meta["wall_s"]), "s")
            total_wall += float(meta["wall_s"])

    # ---------------- rate check and tables
    for pack, path in sorted({(k[0], k[1]) for k in runs}):
        if (pack, path, "1") not in runs:
            continue
        rk = ratio_key(path)
        base = [r for r in runs[(pack, path, "1")][1] if r["stage"] == path]
        half = [r for r in runs[(pack, path, "0.5")][1] if r["stage"] == path] if (pack, path, "0.5") in runs else []
        name = "%s_%s" % (pack, path)
        if half:
            m1, m2 = runs[(pack, path, "1")][0], runs[(pack, path, "0.5")][0]
            out(name + "_iso_state_rate_mismatch",
                sum(abs(float(m1[k]) - float(m2[k])) for k in ("Lx_ic", "Ly_ic", "Lz_ic")), "m")
            e_pk = peaks[(pack, path, "1")]["strain"]
            n = min(len(base), len(half))
            for lab, lim in (("to1pct", 0.01 + 1e-6), ("to_peak", e_pk + 1e-6), ("to5pct", 0.05 + 1e-6)):
                idx = [k for k in range(n) if base[k]["strain"] <= lim]
                out("%s_ratecheck_max_d%s_%s" % (name, rk, lab), max(abs(base[k][rk] - half[k][rk]) for k in idx))
                out("%s_ratecheck_max_dvol_strain_%s" % (name, lab),
                    max(abs(base[k]["vol_strain"] - half[k]["vol_strain"]) for k in idx))
            if n < len(base):
                out(name + "_ratecheck_half_rate_rows_missing", len(base) - n)
        tables.append("\n## %s, %s\n" % (pack, path))
        m = runs[(pack, path, "1")][0]
        iso = [r for r in runs[(pack, path, "1")][1] if r["stage"] == "isotropic"][0]
        tables.append("Isotropic state: %d contacts (2C/N = %.3f, mech. %.3f, %d rattlers), "
                      "L_ic = %s, %s, %s m, sigma12 = %.0f Pa.\n"
                      % (iso["n_contacts"], iso["coordination"], iso["coordination_mech"], iso["rattlers"],
                         m["Lx_ic"], m["Ly_ic"], m["Lz_ic"], iso["sigma12_Pa"]))
        lab = "q/p" if path == "triaxial" else "tau/p"
        slab = "s33 (Pa)" if path == "triaxial" else "s12 (Pa)"
        tables.append("| strain | %s | p (Pa) | %s | vol. strain | 2C/N | sliding | servo err | %s, half rate | vol. strain, half rate |"
                      % (lab, slab, lab))
        tables.append("|" + "---|" * 10)
        for k, r in enumerate(base):
            h = half[k] if k < len(half) else None
            tables.append("| %.4f | %.4f | %.0f | %.0f | %.5f | %.3f | %.3f | %.1e | %s | %s |" % (
                r["strain"], r[rk], r["p_Pa"], r[stress_key(path)], r["vol_strain"], r["coordination"],
                r["sliding_fraction"], r["lateral_err_rel"],
                "%.4f" % h[rk] if h else "-", "%.5f" % h["vol_strain"] if h else "-"))
    if total_wall:
        out("wall_total_yade_runs", total_wall, "s")

    # ---------------- extra pairs (dt, servo checks)
    for spec in a.pair:
        label, _, files = spec.partition("=")
        fa, _, fb = files.partition(",")
        ma, ra = read_yade(fa)
        mb, rb = read_yade(fb)
        path = ma["path"]
        rk = ratio_key(path)
        ra = [r for r in ra if r["stage"] == path]
        rb = [r for r in rb if r["stage"] == path]
        e_pk = max(ra, key=lambda r: r[rk])["strain"]
        n = min(len(ra), len(rb))
        for lab, lim in (("to1pct", 0.01 + 1e-6), ("to_peak", e_pk + 1e-6), ("to5pct", 0.05 + 1e-6)):
            idx = [k for k in range(n) if ra[k]["strain"] <= lim]
            out("%s_max_d%s_%s" % (label, rk, lab), max(abs(ra[k][rk] - rb[k][rk]) for k in idx))
            out("%s_max_dvol_strain_%s" % (label, lab), max(abs(ra[k]["vol_strain"] - rb[k]["vol_strain"]) for k in idx))
        for tag, rr in (("a", ra), ("b", rb)):
            pk = max(rr, key=lambda r: r[rk])
            out("%s_%s_peak_%s" % (label, tag, rk), pk[rk])
            out("%s_%s_strain_at_peak" % (label, tag), pk["strain"])

    # ---------------- RVE comparison
    rve_curves = {}
    for spec in a.rve:
        name, _, f = spec.partition("=")
        ic = a.ic_row
        if "@" in f:
            f, _, icr = f.rpartition("@")
            ic = int(icr)
        pack, _, path = name.rpartition("_")
        if (pack, path, "1") not in runs:
            raise SystemExit("compare_3d.py: no YADE run %s_rate1 for --rve %s" % (name, spec))
        rows = read_rve(f)
        if ic is None:
            ic = detect_ic(rows, path)
        cur = rve_curve(rows, ic, path)
        rve_curves[name] = cur
        out("rve_%s_ic_row" % name, ic)
        out("rve_%s_ic_step" % name, cur[0]["step"])
        out("rve_%s_ic_p" % name, cur[0]["p"], "Pa")
        base = [r for r in runs[(pack, path, "1")][1] if r["stage"] == path]
        rk = ratio_key(path)
        sk = stress_key(path)
        e_pk = peaks[(pack, path, "1")]["strain"]
        lab = "q/p" if path == "triaxial" else "tau/p"
        slab = "s33" if path == "triaxial" else "s12"
        print("\n# %s: YADE (rate 1) against %s (ic row %d)" % (name, f, ic))
        print("# %8s %10s %10s %9s %12s %12s %9s %10s %10s" % (
            "strain", "YADE " + lab, "RVE " + lab, "rel.diff", "YADE " + slab, "RVE " + slab, "rel.diff",
            "YADE e_v", "RVE e_v"))
        tab = ["\n## %s: YADE (rate 1) against the RVE `%s` (ic row %d)\n" % (name, f, ic),
               "| strain | YADE %s | RVE %s | rel. diff | YADE %s (Pa) | RVE %s (Pa) | rel. diff | YADE vol. strain | RVE vol. strain |"
               % (lab, lab, slab, slab), "|" + "---|" * 9]
        d_pre, d_post, d_pts = [], [], []
        for r in base:
            e = r["strain"]
            rv = interp(cur, "ratio", e)
            if rv is None:
                continue
            sv = interp(cur, "stress", e)
            ev = interp(cur, "ev", e)
            dr = (rv - r[rk]) / r[rk] if e > 1e-9 else float("nan")
            ds = (sv - r[sk]) / r[sk] if e > 1e-9 or path == "triaxial" else float("nan")
            if e > 1e-9:
                (d_pre if e <= e_pk + 1e-9 else d_post).append(dr)
                if abs(e - e_pk) < 1e-9:
                    d_post.append(dr)
                # YADE strains that are RVE rows (no interpolation error)
                if e <= e_pk + 1e-9 and any(abs(c["strain"] - e) < 1e-4 for c in cur):
                    d_pts.append(dr)
            print("  %8.4f %10.4f %10.4f %9.4f %12.0f %12.0f %9.4f %10.5f %10.5f" % (
                e, r[rk], rv, dr, r[sk], sv, ds, r["vol_strain"], ev))
            tab.append("| %.4f | %.4f | %.4f | %.4f | %.0f | %.0f | %.4f | %.5f | %.5f |" % (
                e, r[rk], rv, dr, r[sk], sv, ds, r["vol_strain"], ev))
        tables.extend(tab)
        if d_pre:
            k = max(range(len(d_pre)), key=lambda i: abs(d_pre[i]))
            out("rve_%s_max_rel_diff_%s_to_peak" % (name, rk), d_pre[k])
        if d_pts:
            k = max(range(len(d_pts)), key=lambda i: abs(d_pts[i]))
            out("rve_%s_max_rel_diff_%s_to_peak_at_rve_rows" % (name, rk), d_pts[k])
        if d_post:
            out("rve_%s_mean_abs_rel_diff_%s_peak_to_5pct" % (name, rk), sum(abs(x) for x in d_post) / len(d_post))
            out("rve_%s_mean_rel_diff_%s_peak_to_5pct" % (name, rk), sum(d_post) / len(d_post))
        rpk = max(cur, key=lambda c: c["ratio"])
        out("rve_%s_peak_%s" % (name, rk), rpk["ratio"])
        out("rve_%s_strain_at_peak" % name, rpk["strain"])

    if a.no_files:
        return
    tpath = a.tables or os.path.join(res, "tables_3d.md" if not a.rve else "tables_3d_rve.md")
    with open(tpath, "w") as f:
        f.write("\n".join(tables) + "\n")
    print("# wrote %s" % tpath)

    # ---------------- plot
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except Exception:
        return
    paths = [p for p in PATHS if any(k[1] == p for k in runs)]
    if not paths:
        return
    fig, ax = plt.subplots(len(paths), 2, figsize=(11, 4.0 * len(paths)), squeeze=False)
    colours = {}
    for row_i, path in enumerate(paths):
        rk = ratio_key(path)
        for (pack, pth, tag) in sorted(runs, key=lambda k: (k[0], -float(k[2]))):
            if pth != path:
                continue
            c = colours.setdefault(pack, "C%d" % len(colours))
            tp = os.path.join(res, "%s_%s_rate%s_trace.csv" % (pack, path, tag))
            rr = read_yade(tp)[1] if os.path.exists(tp) else runs[(pack, path, tag)][1]
            rr = [r for r in rr if r["stage"] == path]
            e = [100 * r["strain"] for r in rr]
            ls = "-" if tag == "1" else "--"
            lab = "YADE %s, %s /s" % (pack, runs[(pack, path, tag)][0]["rate"])
            ax[row_i][0].plot(e, [r[rk] for r in rr], ls, color=c, lw=1.2, label=lab)
            ax[row_i][1].plot(e, [100 * r["vol_strain"] for r in rr], ls, color=c, lw=1.2, label=lab)
        for name, cur in rve_curves.items():
            pack, _, pth = name.rpartition("_")
            if pth != path:
                continue
            c = colours.setdefault(pack, "C%d" % len(colours))
            cc = [q for q in cur if q["strain"] <= 0.0505]
            e = [100 * q["strain"] for q in cc]
            ax[row_i][0].plot(e, [q["ratio"] for q in cc], "o:", color=c, ms=4, label="RVE " + pack)
            ax[row_i][1].plot(e, [100 * q["ev"] for q in cc], "o:", color=c, ms=4, label="RVE " + pack)
        xl = "axial strain e_a (%)" if path == "triaxial" else "shear strain gamma (%)"
        ax[row_i][0].set_ylabel("q/p" if path == "triaxial" else "tau/p = sigma12/p")
        ax[row_i][1].set_ylabel("volumetric strain V/V_ic - 1 (%)")
        for a_ in ax[row_i]:
            a_.set_xlabel(xl)
            a_.grid(alpha=0.3)
            a_.set_xlim(0, 5.0)
        ax[row_i][0].legend(fontsize=7)
        ax[row_i][0].set_title("triaxial: sigma11 = sigma22 = -100 kPa" if path == "triaxial"
                               else "simple shear: sigma22 = -100 kPa, F11, F33 fixed")
    fig.tight_layout()
    ppath = a.plot or os.path.join(res, "yade_3d.png" if not a.rve else "yade_3d_vs_rve.png")
    fig.savefig(ppath, dpi=110)
    print("# wrote %s" % ppath)


if __name__ == "__main__":
    main()
