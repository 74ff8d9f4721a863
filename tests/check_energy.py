#!/usr/bin/env python3
"""Checks energy conservation of an undamped explicit-dynamics run (stdlib only).

energy.csv holds per load step the kinetic energy, the work of the internal,
external and hourglass forces, and the material's stored energy
strain_energy = sum of W(F) dV, computed from F alone (not from the forces).
The total energy kinetic + strain_energy (+ hourglass work of the stiffness
form) must equal the work the external forces did: at every row within
TOL x the largest external work. The run must vibrate freely after the load
ends at T_LOAD (kinetic energy above 10 % of that work at some later row).

Usage: check_energy.py ENERGY_CSV TOL T_LOAD
"""
import csv
import sys

path, tol, t_load = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
rows = list(csv.DictReader(open(path)))
scale = max(abs(float(r["external_work"])) for r in rows)
failures, worst = [], 0.0
for r in rows:
    total = float(r["kinetic_energy"]) + float(r["strain_energy"]) + float(r["hourglass_work"])
    error = abs(total - float(r["external_work"]))
    worst = max(worst, error)
    if not error <= tol * scale:
        failures.append(f"t = {r['time']}: kinetic + strain energy {total}, external work {r['external_work']}")
free = [float(r["kinetic_energy"]) for r in rows if float(r["time"]) > t_load]
print(f"{len(rows)} rows, {len(free)} after the load; largest external work {scale:.6g}; largest "
      f"|kinetic + strain energy - external work| = {worst / scale:.3e} of it; kinetic energy in free "
      f"vibration {min(free):.4g} .. {max(free):.4g}")
if not (free and max(free) > 0.1 * scale):
    failures.append("no free vibration after the load")
for f in failures[:10]:
    print("FAIL", f)
print(f"{path}: {len(failures)} failures")
sys.exit(1 if failures else 0)
