#!/usr/bin/python3
"""Checks the particle dumps of fe2dem against its history.h5.

Usage: check_particle_dump.py OUTPUT_DIR IP STEP [OTHER_OUTPUT_DIR]
       check_particle_dump.py OUTPUT_DIR rve ROW    (fe2dem-rve: 'Particle dumps every')
For IP at load STEP (or fe2dem-rve's row ROW of rve.csv): the dump files exist and parse, every contact joins two
listed particles at their listed centres, fn > 0 (the dump lists touching
pairs, which carry compression), and 2 C / N equals the coordination in
history.h5 (same contact count; N counts each physical particle once: the
inner particles, one per edge pair of frame images and one corner), or the
coordination of rve.csv at that row. With OTHER_OUTPUT_DIR the files must be
byte-identical there (rank-count independence).
"""
import csv
import filecmp
import sys

import h5py

out, single_rve, step = sys.argv[1], sys.argv[2] == "rve", int(sys.argv[3])
ip = 0 if single_rve else int(sys.argv[2])
prefix = f"{out}/particles/step{step:04d}" if single_rve else f"{out}/particles/ip{ip:04d}-step{step:04d}"
failures = []


def read_dump(path, count_item):
    lines = open(path).read().splitlines()
    n = int(lines[lines.index(count_item) + 1])
    header = next(i for i, l in enumerate(lines) if l.startswith(("ITEM: ATOMS", "ITEM: ENTRIES")))
    columns = lines[header].split()[2:]
    rows = [dict(zip(columns, map(float, l.split()))) for l in lines[header + 1:]]
    if len(rows) != n:
        failures.append(f"{path}: {len(rows)} rows, header says {n}")
    if int(lines[lines.index("ITEM: TIMESTEP") + 1]) != step:
        failures.append(f"{path}: TIMESTEP is not {step}")
    return rows


particles = {int(p["id"]): p for p in read_dump(prefix + ".particles", "ITEM: NUMBER OF ATOMS")}
contacts = read_dump(prefix + ".contacts", "ITEM: NUMBER OF ENTRIES")
for c in contacts:
    for k in ("1", "2"):
        p = particles.get(int(c["id" + k]))
        if p is None or abs(p["x"] - c["x" + k]) > 1e-12 or abs(p["y"] - c["y" + k]) > 1e-12:
            failures.append(f"contact {int(c['id1'])}-{int(c['id2'])}: end {k} not at its particle")
    if not c["fn"] > 0:
        failures.append(f"contact {int(c['id1'])}-{int(c['id2'])}: fn = {c['fn']} not > 0")
if single_rve:
    coordination = float(next(r for r in csv.DictReader(open(f"{out}/rve.csv")) if int(r["step"]) == step)
                         ["coordination"])
else:
    with h5py.File(f"{out}/history.h5", "r") as h:
        row = list(h["step"][:]).index(step)
        coordination = h["coordination"][row, ip]
n_frame = round(sum(p["frame"] for p in particles.values()))
n_physical = len(particles) - n_frame + (n_frame - 4) // 2 + 1
z = 2.0 * len(contacts) / n_physical
print(f"{prefix}: {len(particles)} particles ({n_frame} frame, {n_physical} physical), "
      f"{len(contacts)} contacts, 2C/N = {z:.6f}, {'rve.csv' if single_rve else 'history.h5'} "
      f"coordination = {coordination:.6f}")
if abs(z - coordination) > (1e-9 if single_rve else 1e-12):  # rve.csv prints 12 digits
    failures.append(f"2C/N = {z} differs from the coordination {coordination}")
if len(sys.argv) > 4:
    for ext in (".particles", ".contacts"):
        other = f"{sys.argv[4]}/particles/ip{ip:04d}-step{step:04d}{ext}"
        if not filecmp.cmp(prefix + ext, other, shallow=False):
            failures.append(f"{prefix + ext} differs from {other}")
for f in failures:
    print("FAIL", f)
sys.exit(1 if failures else 0)
