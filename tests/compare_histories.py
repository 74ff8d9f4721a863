#!/usr/bin/python3
"""Two fe2dem history.h5 files hold identical datasets (bitwise).
Debian's python3 with python3-h5py. Usage: compare_histories.py A B"""
import sys

import h5py
import numpy as np

a, b = h5py.File(sys.argv[1], "r"), h5py.File(sys.argv[2], "r")
bad = sorted(set(a) ^ set(b))
for k in sorted(set(a) & set(b)):
    if a[k].shape != b[k].shape or not np.array_equal(a[k][()], b[k][()]):
        bad.append(k)
for k in bad:
    print("FAIL dataset differs or is missing:", k)
print(f"{len(a)} datasets compared ({', '.join(sorted(a))}), {len(bad)} differ")
sys.exit(1 if bad or not len(a) else 0)
