#!/usr/bin/python3
"""history.h5 describes itself and holds every statistic of the one field list.

1. Every dataset has non-empty string attributes `unit` and `description`;
   the root group describes the run: created_by (fe2dem, version, git
   commit), created, parameter_file and parameters (that file's text, byte
   for byte), dimension, tensor_layout, sign_convention, stress_unit.
2. Every statistic named in coupler/rve_statistics.h (read from the header,
   not from the writer) is a dataset of [n_steps][n_ip](...) rows.
3. mean_overlap (the statistic added through that list alone) equals the
   mean overlap / smaller radius recomputed here from the particle dumps
   (positions and radii of each contact), for every dumped IP and step.
Usage: check_history_h5.py HISTORY_H5 RVE_STATISTICS_H PARTICLES_DIR
"""
import glob
import os
import re
import sys

import h5py
import numpy as np

failures = 0


def check(name, ok, detail=""):
    global failures
    print(("PASS " if ok else "FAIL ") + name + (f": {detail}" if detail else ""))
    failures += not ok


def text(v):
    return v.decode() if isinstance(v, bytes) else str(v)


def dump_mean_overlap(contacts_file, particles_file):
    radius = {}
    with open(particles_file) as f:
        lines = f.read().split("\n")
    start = next(k for k, l in enumerate(lines) if l.startswith("ITEM: ATOMS")) + 1
    for l in lines[start:]:
        if l.strip():
            w = l.split()
            radius[int(w[0])] = float(w[3])
    with open(contacts_file) as f:
        lines = f.read().split("\n")
    start = next(k for k, l in enumerate(lines) if l.startswith("ITEM: ENTRIES")) + 1
    ratios = []
    for l in lines[start:]:
        if not l.strip():
            continue
        w = l.split()
        i, j = int(w[0]), int(w[1])
        x1, y1, x2, y2 = map(float, w[2:6])
        overlap = radius[i] + radius[j] - np.hypot(x2 - x1, y2 - y1)
        if overlap > 0.0:
            ratios.append(overlap / min(radius[i], radius[j]))
    return np.mean(ratios), len(ratios)


def main(h5_file, header, particles):
    names = re.findall(r"X\((?:tensor|scalar|count), (\w+),", open(header).read())
    check("the field list names statistics", len(names) >= 10, ", ".join(names))
    with h5py.File(h5_file, "r") as f:
        n_steps = f["step"].shape[0]
        n_ip = f["ip_position"].shape[0]
        for name, d in f.items():
            unit, desc = text(d.attrs.get("unit", "")), text(d.attrs.get("description", ""))
            check(f"{name} has unit and description", unit != "" and desc != "", f"[{unit}] {desc}")
        root = {k: text(v) for k, v in f.attrs.items()}
        for key in ("created_by", "created", "parameter_file", "parameters", "dimension",
                    "tensor_layout", "sign_convention", "stress_unit"):
            check(f"root attribute {key}", root.get(key, "") != "", root.get(key, "missing")[:70])
        check("created_by names fe2dem, its version and commit",
              re.match(r"^fe2dem \d+\.\d+\.\d+ \(git \S+\)$", root.get("created_by", "")) is not None,
              root.get("created_by", ""))
        prm = root.get("parameter_file", "")
        check("parameters is the parameter file's text", os.path.isfile(prm) and
              open(prm).read() == root.get("parameters"), prm)
        for name in names:
            ok = name in f and f[name].shape[:2] == (n_steps, n_ip)
            check(f"statistic {name} in history.h5 as [steps][IPs]", ok,
                  str(f[name].shape) if name in f else "missing")
        steps = list(f["step"][()])
        overlap = f["mean_overlap"][()] if "mean_overlap" in f else None
    compared = 0
    for contacts in sorted(glob.glob(os.path.join(particles, "ip*-step*.contacts"))):
        m = re.search(r"ip(\d+)-step(\d+)\.contacts$", contacts)
        ip, step = int(m.group(1)), int(m.group(2))
        expected, n = dump_mean_overlap(contacts, contacts.replace(".contacts", ".particles"))
        got = overlap[steps.index(step), ip]
        check(f"mean_overlap of IP {ip} at step {step} = dump's ({n} contacts)",
              abs(got - expected) <= 1e-4 * expected, f"{got:.9g} vs {expected:.9g}")
        compared += 1
    check("particle dumps compared", compared >= 2, str(compared))
    print(f"{failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:4]))
