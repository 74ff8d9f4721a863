#!/usr/bin/env python3
"""The wave column as a 1D bar with the RVE's own sigma_yy(eps_yy): an
anchor for [LSYF] problem 2 at 0.1 mm, where the wave is not linear.

  column_1d.py table MODULUS_OUT RVE_OUT ELASTIC_OUT RAMP_OUT AMPLITUDE
  column_1d.py speed MODULUS_OUT RVE_OUT RAMP_OUT AMPLITUDE TOL

The macro column of wave_column.prm (10 one-point elements of 10 mm, lateral
strains zero, bottom fixed, top driven by -AMPLITUDE sin(2 pi 10 kHz t),
rho = 1650 kg/m^3, 1 us steps) is, per unit area, a chain of lumped masses
(rho h, half at the ends) joined by bars whose nominal stress in uniaxial
strain is sigma_yy(eps_yy) (P22 = J sigma22 / F22 = sigma22). Advanced here by
central differences with two laws:

  linear      sigma = M eps, M from constrained_modulus (MODULUS_OUT): must
              reproduce fe2dem's elastic column (ELASTIC_OUT) -- the check that
              this bar is the macro discretisation;
  nonlinear   the RVE's own sigma_yy(eps_yy) of a slow ramp to 1 % uniaxial
              strain (RAMP_OUT, constrained_modulus.prm at 0.5 /s), elastic:
              loading and unloading on the same curve; below the prestress
              (tension) the initial tangent, down to zero total stress.

Arrivals and front speed as wave.py (threshold a fifth of omega A / c_M):
the RVE column (RVE_OUT) against the nonlinear bar says whether the RVE
column's front is the one its RVEs' own sigma(eps) makes, at any amplitude.
'table' prints both bars beside fe2dem's two columns; 'speed' is the check of
ctest macro_lsyf_wave_column_0.1mm_front_speed: the RVE column's front speed
within TOL of the nonlinear bar's, exit status 1 if not.
"""
import math
import sys

import h5py
import numpy as np

import wave

N, DT, T_END, OUT_EVERY = 10, 1e-6, 1e-3, 2


def ramp_law(ramp_out):
    """sigma_yy increment over the prestress as a function of eps (compression positive)."""
    with h5py.File(f"{ramp_out}/history.h5", "r") as h:
        eps = 1.0 - h["F"][:, 0, 4]
        syy = -h["sigma"][:, 0, 4]
    s0 = syy[0] - (syy[1] - syy[0]) / (eps[1] - eps[0]) * eps[0]  # extrapolated to eps = 0
    eps, ds = np.concatenate([[0.0], eps]), np.concatenate([[0.0], syy - s0])
    m0 = ds[1] / eps[1]

    def law(e):
        # compression: the ramp (extended with its last tangent); tension: the
        # initial tangent, the total stress not below zero
        out = np.interp(e, eps, ds)
        beyond = e > eps[-1]
        out[beyond] = ds[-1] + (ds[-1] - ds[-2]) / (eps[-1] - eps[-2]) * (e[beyond] - eps[-1])
        below = e < 0.0
        out[below] = np.maximum(m0 * e[below], -s0)
        return out
    return law, s0


def bar(law, amplitude):
    """Central differences on the lumped chain; returns wave.column()'s (times, y, eps, u)."""
    h = wave.L / N
    m = np.full(N + 1, wave.RHO * h)
    m[0] = m[-1] = 0.5 * wave.RHO * h
    u, v = np.zeros(N + 1), np.zeros(N + 1)
    omega = 2 * math.pi * wave.FREQ
    times, strains = [0.0], [np.zeros(N)]
    for n in range(1, int(round(T_END / DT)) + 1):
        t = n * DT
        e = -(u[1:] - u[:-1]) / h  # compression positive
        s = law(e)
        f = np.zeros(N + 1)  # a compressed bar pushes its lower node down, its upper one up
        f[:-1] -= s
        f[1:] += s
        v += DT * f / m
        u += DT * v
        u[0] = 0.0
        u[-1] = -amplitude * math.sin(omega * t)  # as wave_column.prm: compression first
        v[-1] = -amplitude * omega * math.cos(omega * t)
        if n % OUT_EVERY == 0:
            times.append(t)
            strains.append((u[1:] - u[:-1]) / h)
    eps = np.array(strains)
    y = (np.arange(N) + 0.5) * h
    return np.array(times), y, eps, None


def main():
    if len(sys.argv) < 2 or sys.argv[1] not in ("table", "speed") or len(sys.argv) != 7:
        sys.exit(__doc__)
    mode, M = sys.argv[1], wave.modulus(sys.argv[2])
    c = math.sqrt(M / wave.RHO)
    if mode == "table":
        rve_out, elastic_out, ramp_out, A = sys.argv[3], sys.argv[4], sys.argv[5], float(sys.argv[6])
    else:
        rve_out, elastic_out, ramp_out, A = sys.argv[3], None, sys.argv[4], float(sys.argv[5])
    threshold = 2 * math.pi * wave.FREQ * A / c / 5
    law, s0 = ramp_law(ramp_out)
    runs = {"fe2dem, RVE column": wave.column(rve_out)}
    if elastic_out:
        runs["fe2dem, elastic column"] = wave.column(elastic_out)
        runs["bar, linear M"] = bar(lambda e: M * e, A)
    runs["bar, the RVE's sigma(eps)"] = bar(law, A)
    print(f"A = {1e3 * A:.4g} mm, M = {M / 1e6:.0f} MPa, c_M = {c:.1f} m/s, prestress {s0 / 1e3:.0f} kPa, "
          f"arrival threshold {threshold:.3g}")
    print("\n| column | " + " | ".join(f"{1e3 * d:.0f} mm" for d in wave.DISTANCES) + " | front speed | vs c_M |")
    print("|---|" + "---|" * (len(wave.DISTANCES) + 2))
    speeds = {}
    for name, run in runs.items():
        t_arr, speed = wave.front_speed(run, threshold)
        speeds[name] = speed
        print(f"| {name} (us) | " + " | ".join(f"{1e6 * t:.1f}" for t in t_arr)
              + f" | {speed:.0f} m/s | {100 * (speed / c - 1):+.1f} % |")
    print()
    if elastic_out:
        print(f"linear bar against fe2dem's elastic column: "
              f"{100 * (speeds['bar, linear M'] / speeds['fe2dem, elastic column'] - 1):+.2f} %")
    rel = speeds["fe2dem, RVE column"] / speeds["bar, the RVE's sigma(eps)"] - 1
    print(f"RVE column against the bar with the RVE's sigma(eps): {100 * rel:+.2f} %")
    if mode == "speed":
        tol = float(sys.argv[6])
        print(f"allowed {100 * tol:g} %: {'PASS' if abs(rel) <= tol else 'FAIL'}")
        sys.exit(0 if abs(rel) <= tol else 1)


if __name__ == "__main__":
    main()
