#!/usr/bin/python3
"""The wave column of dealii_app/examples/wave_column_3d_rve.prm: its front
speed within TOL of sqrt(M/rho), M the same RVE's constrained modulus under
a 2.5 kHz sine (ctest macro_dynamic_rve_modulus_2.5kHz). Arrivals and the
front speed as in benchmarks/lsyf2016/wave.py (a fifth of the driving
strain amplitude, a straight-line fit of distance against arrival), at
every element of the column.

Usage: check_wave_front.py COLUMN_OUT MODULUS_OUT AMPLITUDE TOL"""
import importlib.util
import math
import os
import sys

here = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "benchmarks", "lsyf2016")


def load(name):
    spec = importlib.util.spec_from_file_location("lsyf_" + name, os.path.join(here, name + ".py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


if len(sys.argv) != 5:
    sys.exit(__doc__)
wave, dynamic_modulus = load("wave"), load("dynamic_modulus")
out, modulus_out, amplitude, tol = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
M = dynamic_modulus.fit(modulus_out, 2.5e3, 4e-4)[0]
c = math.sqrt(M / wave.RHO)
run = wave.column(out)
ips = run[1]
wave.L = float(ips.max() + wave.H / 2)  # the driven end
wave.DISTANCES = sorted(float(wave.L - y) for y in ips)
arrivals, speed = wave.front_speed(run, 2 * math.pi * wave.FREQ * amplitude / c / 5)
print("distance from the driven end (mm): " + ", ".join(f"{1e3 * d:.0f}" for d in wave.DISTANCES))
print("arrival (us): " + ", ".join(f"{1e6 * t:.1f}" for t in arrivals))
print(f"M = {M / 1e6:.0f} MPa, c = {c:.0f} m/s; front speed {speed:.0f} m/s = {100 * (speed / c - 1):+.1f} % "
      f"(allowed {100 * tol:g} %)")
sys.exit(0 if abs(speed / c - 1) <= tol else 1)
