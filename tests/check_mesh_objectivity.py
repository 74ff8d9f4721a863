#!/usr/bin/python3
"""Post-peak mesh objectivity: the spread over meshes of the average stress
ratio |s11 - s22| / |s11 + s22| (summary.csv means), (max - min) / mean at
each load step from the peak of the meshes' mean curve to the last step, for
a local family of runs and a nonlocal one. Passes if the nonlocal family's
mean spread is at most FRACTION (default 0.5) of the local family's.
Usage: check_mesh_objectivity.py LOCAL_OUT... -- NONLOCAL_OUT... [--fraction F]"""
import csv
import sys

import numpy as np

args = sys.argv[1:]
fraction = 0.5
if "--fraction" in args:
    k = args.index("--fraction")
    fraction = float(args[k + 1])
    del args[k:k + 2]
split = args.index("--")
families = {"local": args[:split], "nonlocal": args[split + 1:]}


def curve(out):
    rows = [r for r in csv.DictReader(open(f"{out}/summary.csv")) if r["stage"] == "2"]
    return (np.array([float(r["axial_strain"]) for r in rows]),
            np.array([abs((float(r["sigma11_mean"]) - float(r["sigma22_mean"]))
                          / (float(r["sigma11_mean"]) + float(r["sigma22_mean"]))) for r in rows]))


spreads = {}
for name, outs in families.items():
    curves = [curve(o) for o in outs]
    n = min(len(c[0]) for c in curves)
    r = np.array([c[1][:n] for c in curves])
    eps = curves[0][0][:n]
    peak = int(np.argmax(r.mean(axis=0)))
    s = (r.max(axis=0) - r.min(axis=0)) / r.mean(axis=0)
    spreads[name] = s[peak:]
    print(f"{name}: peak of the mean at {100 * eps[peak]:.2f} %; spread from it to {100 * eps[n - 1]:.2f} %: "
          + " ".join(f"{100 * v:.1f}" for v in s[peak:]) + f" %; mean {100 * s[peak:].mean():.2f} %, "
          f"max {100 * s[peak:].max():.2f} %")
ok = spreads["nonlocal"].mean() <= fraction * spreads["local"].mean()
print(f"nonlocal / local mean spread = {spreads['nonlocal'].mean() / spreads['local'].mean():.3f} "
      f"(required <= {fraction})")
sys.exit(0 if ok else 1)
