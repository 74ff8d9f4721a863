#!/usr/bin/env python3
"""[LSYF] problem 2, the wave column (run.sh wave; needs h5py, numpy, matplotlib).

  wave.py modulus MODULUS_OUT
      M = d sigma_yy / d eps_yy of constrained_modulus.prm: the slope of a
      straight-line fit of sigma_yy against eps_yy = F22 - 1 over its rows
      (uniaxial strain to 1e-4). Prints M [Pa] on stdout, the fit on stderr.

  wave.py column MODULUS_OUT RVE_OUT ELASTIC_OUT PNG AMPLITUDE
      The column along y (bottom fixed at y = 0, top driven), one point per
      element: nodal displacements u_y = cumulative sum of (F22 - 1) h from
      the bottom. Arrival time at five stations (the IPs 5, 25, 45, 65 and
      85 mm from the driven end): the first output time at which
      |eps_yy - eps_yy(t=0)| reaches a fifth of the driving strain amplitude
      omega A / c_M (c_M = sqrt(M / rho)), interpolated linearly between
      outputs. Front speed: a straight-line fit of distance against arrival
      time. The amplitude: the largest |u_y| at the station before the wave
      reflected from the fixed end can return ((2 L - d) / c_M). The PNG
      shows u_y along the column at five times (25, 75, 125, 175, 975 us: the driven end at its
      extremes), RVE column against elastic.

  wave.py column ... AMPLITUDE RAMP_OUT
      As above, and the speeds a nonlinear front would have at the arrival
      threshold strain eps_t, from the same RVE's sigma_yy(eps_yy) of a slower
      ramp to 1 % (RAMP_OUT: constrained_modulus.prm to 1 % at 0.5 /s):
      sqrt(M_t(eps_t) / rho) for a simple wave (the tangent, each strain
      level travelling at its own speed) and sqrt(M_c / rho) for a shock
      (the chord from 0 to eps_t).

  wave.py speed MODULUS_OUT RVE_OUT AMPLITUDE TOL
      The check of ctest macro_lsyf_wave_column_*: the RVE column's front
      speed (as above) within TOL of c_M; exit status 1 if not.
"""
import csv
import math
import sys

import h5py
import numpy as np

RHO, FREQ, L, H = 1650.0, 1e4, 0.1, 0.01
DISTANCES = [0.005, 0.025, 0.045, 0.065, 0.085]


def modulus(out):
    with h5py.File(f"{out}/history.h5", "r") as h:
        eps = h["F"][:, 0, 4] - 1.0
        syy = h["sigma"][:, 0, 4]
    slope, intercept = np.polyfit(eps, syy, 1)
    first = (syy[1] - syy[0]) / (eps[1] - eps[0])
    print(f"M from {len(eps)} rows, eps_yy {eps[0]:.3g} .. {eps[-1]:.3g}: {slope:.6g} Pa "
          f"(sigma_yy at eps = 0: {intercept:.6g} Pa; first two rows alone {first:.6g} Pa)", file=sys.stderr)
    return slope


def column(out):
    times = np.array([float(r["time"]) for r in csv.DictReader(open(f"{out}/energy.csv"))])
    with h5py.File(f"{out}/history.h5", "r") as h:
        F22 = h["F"][:, :, 4]
        y = h["ip_position"][:, 1]
    order = np.argsort(y)
    y, F22 = y[order], F22[:, order]
    eps = F22 - 1.0
    u = np.concatenate([np.zeros((len(times), 1)), np.cumsum(eps * H, axis=1)], axis=1)
    return times, y, eps, u


def arrivals(times, y, eps, threshold):
    """Arrival time at each station: first crossing of |eps - eps(0)| = threshold (eps(0) = 0 here)."""
    result = []
    for d in DISTANCES:
        k = int(np.argmin(np.abs(y - (L - d))))
        e = np.abs(eps[:, k])
        hit = np.nonzero(e >= threshold)[0]
        if len(hit) == 0:
            result.append(math.nan)
            continue
        i = hit[0]
        t0, e0 = (times[i - 1], e[i - 1]) if i > 0 else (0.0, 0.0)
        result.append(t0 + (threshold - e0) / (e[i] - e0) * (times[i] - t0))
    return result


def front_speed(run, threshold):
    """(arrival times at DISTANCES, the fitted front speed) of column()'s RUN."""
    times, y, eps, u = run
    t_arr = arrivals(times, y, eps, threshold)
    ok = [i for i, t in enumerate(t_arr) if not math.isnan(t)]
    speed = np.polyfit([t_arr[i] for i in ok], [DISTANCES[i] for i in ok], 1)[0] if len(ok) >= 2 else math.nan
    return t_arr, speed


def nonlinear_speeds(ramp_out, eps_t, speed):
    """The tangent and chord speeds at the strain eps_t of the ramp in RAMP_OUT."""
    with h5py.File(f"{ramp_out}/history.h5", "r") as h:
        eps = 1.0 - h["F"][:, 0, 4]  # compression positive; the rows start at the first output
        syy = -h["sigma"][:, 0, 4]
    s0 = syy[0] - (syy[1] - syy[0]) / (eps[1] - eps[0]) * eps[0]  # extrapolated to eps = 0
    eps, syy = np.concatenate([[0.0], eps]), np.concatenate([[s0], syy])
    k = int(np.searchsorted(eps, eps_t))
    tangent = (syy[k + 1] - syy[k - 1]) / (eps[k + 1] - eps[k - 1])
    chord = (np.interp(eps_t, eps, syy) - syy[0]) / eps_t
    for name, M in (("tangent (a simple wave)", tangent), ("chord from 0 (a shock)", chord)):
        v = math.sqrt(M / RHO)
        print(f"the RVE's own sigma_yy(eps_yy) at the threshold {100 * eps_t:.3g} %: {name} M = {M / 1e6:.0f} MPa, "
              f"sqrt(M/rho) = {v:.1f} m/s; the RVE column's front {100 * (speed / v - 1):+.1f} %")


def check_speed():
    M = modulus(sys.argv[2])
    A, tol = float(sys.argv[4]), float(sys.argv[5])
    c = math.sqrt(M / RHO)
    t_arr, speed = front_speed(column(sys.argv[3]), 2 * math.pi * FREQ * A / c / 5)
    print("arrivals (us): " + ", ".join(f"{1e6 * t:.1f}" for t in t_arr))
    print(f"front speed {speed:.1f} m/s, c_M = {c:.1f} m/s: {100 * (speed / c - 1):+.1f} % (allowed {100 * tol:g} %)")
    sys.exit(0 if abs(speed / c - 1) <= tol else 1)


def main():
    if sys.argv[1] == "modulus":
        print(f"{modulus(sys.argv[2]):.6g}")
        return
    if sys.argv[1] == "speed":
        check_speed()
    M = modulus(sys.argv[2])
    A = float(sys.argv[6])
    c = math.sqrt(M / RHO)
    eps_a = 2 * math.pi * FREQ * A / c
    runs = {"RVE column": column(sys.argv[3]), "elastic column": column(sys.argv[4])}
    print(f"driving amplitude A = {1e3 * A:.4g} mm; M = {M:.4g} Pa (constrained_modulus.prm), rho = {RHO} kg/m^3: c_M = sqrt(M/rho) = {c:.1f} m/s; "
          f"driving strain amplitude omega A / c_M = {eps_a:.3g}, arrival threshold {eps_a / 5:.3g}")
    table = {}
    for name, run in runs.items():
        times, y, eps, u = run
        t_arr, speed = front_speed(run, eps_a / 5)
        amplitude = []
        for d in DISTANCES:
            k = int(np.argmin(np.abs(y - (L - d)))) + 1  # the node above the IP
            before = times <= (2 * L - d) / c
            amplitude.append(np.abs(u[before, k]).max())
        table[name] = (t_arr, speed, amplitude)
    print("\n| station (distance from the driven end) | " + " | ".join(f"{1e3 * d:.0f} mm" for d in DISTANCES) + " |")
    print("|---|" + "---|" * len(DISTANCES))
    print("| d / c_M (us) | " + " | ".join(f"{1e6 * d / c:.1f}" for d in DISTANCES) + " |")
    for name, (t_arr, speed, amplitude) in table.items():
        print(f"| arrival, {name} (us) | " + " | ".join(f"{1e6 * t:.1f}" for t in t_arr) + " |")
    for name, (t_arr, speed, amplitude) in table.items():
        print(f"| largest u_y before the reflection, {name} (mm) | "
              + " | ".join(f"{1e3 * a:.4f}" for a in amplitude) + " |")
    print()
    for name, (t_arr, speed, amplitude) in table.items():
        print(f"front speed, {name}: {speed:.1f} m/s = {100 * (speed / c - 1):+.1f} % of c_M")
    if len(sys.argv) > 7:
        nonlinear_speeds(sys.argv[7], eps_a / 5, table["RVE column"][1])

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    times, y, eps, u = runs["RVE column"]
    te, _, _, ue = runs["elastic column"]
    nodes = np.linspace(0.0, L, u.shape[1])
    fig, ax = plt.subplots(figsize=(8, 5))
    for n, t in enumerate([2.5e-5, 7.5e-5, 1.25e-4, 1.75e-4, 9.75e-4]):
        i, j = int(np.argmin(np.abs(times - t))), int(np.argmin(np.abs(te - t)))
        colour = f"C{n}"
        ax.plot(1e3 * nodes, 1e3 * u[i], "-o", color=colour, ms=3, label=f"RVEs, t = {1e6 * times[i]:.0f} us")
        ax.plot(1e3 * nodes, 1e3 * ue[j], "--", color=colour, label=f"elastic, t = {1e6 * te[j]:.0f} us")
    ax.set_xlabel("y (mm), bottom fixed, top driven")
    ax.set_ylabel("u_y (mm)")
    ax.axhline(0.0, color="grey", lw=0.5)
    ax.set_title(f"wave column driven at {1e3 * A:.3g} mm: lsyf_4096 Hertz RVEs at 416 kPa\n"
                 f"against an elastic column with M = {M / 1e6:.0f} MPa", fontsize=10)
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(sys.argv[5], dpi=120)


if __name__ == "__main__":
    main()
