#!/usr/bin/env python3
"""Checks corotational runs of fe2dem from history.h5 (needs h5py, numpy).

Usage: check_corotational.py rotation OUT MODULUS TOL
         every P and Cauchy stress of every IP and step below TOL x MODULUS
       check_corotational.py compare OUT_COROTATIONAL OUT_TOTAL_LAGRANGIAN TOL
         the Cauchy stresses of every IP and step agree within TOL x the
         largest stress of the total Lagrangian run (same F: checked to 1e-8)
"""
import sys

import h5py
import numpy as np

mode = sys.argv[1]
failures = []
if mode == "rotation":
    out, modulus, tol = sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
    with h5py.File(f"{out}/history.h5", "r") as h:
        P, sigma, F = h["P"][:], h["sigma"][:], h["F"][:]
    dim = int(round(F.shape[2] ** 0.5))
    angle = np.degrees(np.arctan2(F[-1, 0, dim], F[-1, 0, 0]))  # F21 / F11 of the last step
    worst = max(np.abs(P).max(), np.abs(sigma).max())
    print(f"{out}: {F.shape[0]} steps, {F.shape[1]} IPs, rotated by {angle:.6f} degrees at the end; "
          f"largest |P|, |sigma| = {worst:.3e} = {worst / modulus:.3e} of the modulus")
    if abs(angle - 90.0) > 1e-6:
        failures.append(f"final rotation {angle} degrees, not 90")
    if not worst < tol * modulus:
        failures.append(f"stress {worst} not below {tol} x {modulus}")
elif mode == "compare":
    a, b, tol = sys.argv[2], sys.argv[3], float(sys.argv[4])
    with h5py.File(f"{a}/history.h5", "r") as ha, h5py.File(f"{b}/history.h5", "r") as hb:
        sa, sb, Fa, Fb = ha["sigma"][:], hb["sigma"][:], ha["F"][:], hb["F"][:]
    if sa.shape != sb.shape:
        sys.exit(f"shapes differ: {sa.shape} vs {sb.shape}")
    scale = np.abs(sb).max()
    diff = np.abs(sa - sb).max()
    fdiff = np.abs(Fa - Fb).max()
    print(f"{sa.shape[0]} steps, {sa.shape[1]} IPs: largest |sigma_corotational - sigma_TL| = {diff:.3e} = "
          f"{diff / scale:.3e} of the largest stress {scale:.4g}; largest |F difference| {fdiff:.2e}")
    if not diff <= tol * scale:
        failures.append(f"stresses differ by {diff / scale:.3e} of the largest, above {tol}")
    if not fdiff <= 1e-8:
        failures.append(f"the two runs' F differ by {fdiff}")
for f in failures:
    print("FAIL", f)
print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)
