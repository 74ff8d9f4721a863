#!/usr/bin/python3
"""Post-processing of benchmarks/yade_periodic (run by run.sh).

    /usr/bin/python3 compare.py RESULTS_DIR [NAME ...]

Reads RESULTS_DIR/NAME_rate1.csv and NAME_rate0.5.csv (written by
biaxial_periodic.py), prints `name value unit` lines (initial contacts and
pressure, isotropic state, peak, lateral-stress error, rate-check
differences, wall times), writes RESULTS_DIR/tables.md (the 0.5 % tables)
and, if matplotlib is available, RESULTS_DIR/biaxial_yade.png.

Rate check: at every recorded 0.5 % point the base-rate and half-rate
values are compared: max |d stress_ratio| and max |d sigma22| (N/m), over
axial strain <= 5 % (pre-peak part of the curve, up to about the peak) and
over the whole path (0..10 %).
"""
import os
import sys

from yade_common import read_yade_csv as read


def out(name, value, unit="-"):
    if isinstance(value, float):
        value = "%.6g" % value
    print("%s %s %s" % (name, value, unit))


def main():
    res = sys.argv[1]
    names = sys.argv[2:] or ["lbs_ref", "lbs_a005"]
    P = 1.5e5
    tables = ["# YADE periodic biaxial reference: tables (written by compare.py)\n"]
    curves = {}
    total_wall = 0.0
    for name in names:
        runs = {}
        for tag in ("1", "0.5"):
            p = os.path.join(res, "%s_rate%s.csv" % (name, tag))
            if not os.path.exists(p):
                print("compare.py: missing %s" % p, file=sys.stderr)
                continue
            runs[tag] = read(p)
        if "1" not in runs:
            continue
        meta, rows = runs["1"]
        ini = [r for r in rows if r["stage"] == "initial"][0]
        iso = [r for r in rows if r["stage"] == "isotropic"][0]
        out(name + "_initial_contacts", int(ini["n_contacts"]))
        out(name + "_initial_coordination", ini["coordination"])
        out(name + "_initial_sigma11", ini["sigma11_Npm"], "N/m")
        out(name + "_initial_sigma22", ini["sigma22_Npm"], "N/m")
        out(name + "_initial_sigma12", ini["sigma12_Npm"], "N/m")
        out(name + "_initial_pressure", -(ini["sigma11_Npm"] + ini["sigma22_Npm"]) / 2, "N/m")
        out(name + "_iso_Lx", float(meta["Lx_ic"]), "m")
        out(name + "_iso_Ly", float(meta["Ly_ic"]), "m")
        out(name + "_iso_J_from_initial",
            float(meta["Lx_ic"]) * float(meta["Ly_ic"]) / (float(meta["Lx0"]) * float(meta["Ly0"])) - 1)
        out(name + "_iso_contacts", int(iso["n_contacts"]))
        out(name + "_iso_coordination", iso["coordination"])
        out(name + "_iso_sigma12", iso["sigma12_Npm"], "N/m")
        out(name + "_iso_steps", int(meta["iso_steps"]), "steps")
        for tag, (m, rr) in sorted(runs.items(), reverse=True):
            b = [r for r in rr if r["stage"] == "biaxial"]
            curves[(name, tag)] = b
            pk = max(b, key=lambda r: r["stress_ratio"])
            key = "%s_rate%s" % (name, tag)
            out(key + "_strain_rate", float(m["rate"]), "1/s")
            out(key + "_peak_stress_ratio", pk["stress_ratio"])
            out(key + "_axial_strain_at_peak", pk["axial_strain"])
            out(key + "_final_stress_ratio", b[-1]["stress_ratio"])
            out(key + "_final_J_rel", b[-1]["J_rel"])
            out(key + "_min_J_rel", min(r["J_rel"] for r in b))
            out(key + "_max_lateral_err_records", max(abs(r["lateral_err_rel"]) for r in b))
            out(key + "_max_hold_steps", int(max(r["hold_steps"] for r in b)), "steps")
            out(key + "_biax_steps", int(m["biax_steps"]), "steps")
            out(key + "_wall", float(m["wall_s"]), "s")
            total_wall += float(m["wall_s"])
            tp = os.path.join(res, "%s_rate%s_trace.csv" % (name, tag))
            if os.path.exists(tp):
                tr = read(tp)[1]
                out(key + "_max_lateral_err_trace", max(abs(r["lateral_err_rel"]) for r in tr))
        if "0.5" in runs:
            m2 = runs["0.5"][0]
            # both rates start from the same (deterministic) isotropic stage
            out(name + "_iso_state_rate_mismatch",
                abs(float(m2["Lx_ic"]) - float(meta["Lx_ic"])) + abs(float(m2["Ly_ic"]) - float(meta["Ly_ic"])), "m")
            a = curves[(name, "1")]
            h = curves[(name, "0.5")]
            n = min(len(a), len(h))
            for lab, lim in (("to5pct", 0.05 + 1e-6), ("all", 1.0)):
                idx = [k for k in range(n) if a[k]["axial_strain"] <= lim]
                dq = max(abs(a[k]["stress_ratio"] - h[k]["stress_ratio"]) for k in idx)
                ds = max(abs(a[k]["sigma22_Npm"] - h[k]["sigma22_Npm"]) for k in idx)
                dj = max(abs(a[k]["J_rel"] - h[k]["J_rel"]) for k in idx)
                out("%s_ratecheck_max_dstress_ratio_%s" % (name, lab), dq)
                out("%s_ratecheck_max_dsigma22_%s" % (name, lab), ds, "N/m")
                out("%s_ratecheck_max_dsigma22_rel_%s" % (name, lab), ds / P)
                out("%s_ratecheck_max_dJ_rel_%s" % (name, lab), dj)
        # markdown table
        tables.append("\n## %s\n" % name)
        tables.append("Packing as read: %d contacts (2C/N = %.4f), sigma11 = %.1f, sigma22 = %.1f, "
                      "sigma12 = %.1f N/m. After isotropic compression: %d contacts (2C/N = %.3f), "
                      "sigma12 = %.1f N/m, Lx_ic = %s m, Ly_ic = %s m.\n"
                      % (ini["n_contacts"], ini["coordination"], ini["sigma11_Npm"], ini["sigma22_Npm"],
                         ini["sigma12_Npm"], iso["n_contacts"], iso["coordination"], iso["sigma12_Npm"],
                         meta["Lx_ic"], meta["Ly_ic"]))
        hdr = ("| axial strain | stress ratio | sigma11 (N/m) | sigma22 (N/m) | sigma12 (N/m) | J_rel "
               "| contacts | 2C/N | lateral err | stress ratio, half rate | sigma22, half rate (N/m) | J_rel, half rate |")
        tables.append(hdr)
        tables.append("|" + "---|" * 12)
        a = curves[(name, "1")]
        h = curves.get((name, "0.5"), [])
        for k, r in enumerate(a):
            hr = h[k] if k < len(h) else None
            tables.append("| %.3f | %.4f | %.0f | %.0f | %.0f | %.5f | %d | %.3f | %.1e | %s | %s | %s |" % (
                r["axial_strain"], r["stress_ratio"], r["sigma11_Npm"], r["sigma22_Npm"], r["sigma12_Npm"],
                r["J_rel"], r["n_contacts"], r["coordination"], r["lateral_err_rel"],
                "%.4f" % hr["stress_ratio"] if hr else "-", "%.0f" % hr["sigma22_Npm"] if hr else "-",
                "%.5f" % hr["J_rel"] if hr else "-"))
    out("wall_total_yade_runs", total_wall, "s")
    with open(os.path.join(res, "tables.md"), "w") as f:
        f.write("\n".join(tables) + "\n")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except Exception:
        return
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    colours = {}
    for (name, tag), b in sorted(curves.items(), key=lambda kv: (kv[0][0], -float(kv[0][1]))):
        c = colours.setdefault(name, "C%d" % len(colours))
        e = [100 * r["axial_strain"] for r in b]
        ls = "-" if tag == "1" else "--"
        lab = "%s, rate x%s" % (name, tag)
        ax[0].plot(e, [r["stress_ratio"] for r in b], ls, color=c, marker="." if tag == "1" else "x", label=lab)
        ax[1].plot(e, [100 * r["J_rel"] for r in b], ls, color=c, marker="." if tag == "1" else "x", label=lab)
    ax[0].set_xlabel("axial strain (%)")
    ax[0].set_ylabel("stress ratio |s11-s22|/|s11+s22|")
    ax[1].set_xlabel("axial strain (%)")
    ax[1].set_ylabel("J_rel (%)")
    for a_ in ax:
        a_.grid(alpha=0.3)
    ax[0].legend(fontsize=8)
    fig.suptitle("YADE periodic biaxial, lateral stress -150 kN/m")
    fig.tight_layout()
    fig.savefig(os.path.join(res, "biaxial_yade.png"), dpi=110)


if __name__ == "__main__":
    main()
