#!/usr/bin/env python3
"""Copies an RVE packing (NAME.rve.data, NAME.vars) with its non-periodic box
shrunk to the particles' extent plus MARGIN x L, so that a small deformation
takes the frame out of the data file's box (ctest rve_box_follows_the_frame_*).

  tighten_box.py SRC_PREFIX OUT_PREFIX MARGIN
"""
import shutil
import sys

if len(sys.argv) != 4:
    sys.exit(__doc__)
src, out, margin = sys.argv[1], sys.argv[2], float(sys.argv[3])
lines = open(src + ".rve.data").read().split("\n")
start = next(i for i, l in enumerate(lines) if l.startswith("Atoms")) + 2
atoms = [l.split() for l in lines[start:] if l.strip()]
L = {k: float(v) for k, v in (l.split()[1::2] for l in open(src + ".vars") if l.startswith("variable rve_L"))}
for i, line in enumerate(lines[:start]):
    words = line.split()
    if len(words) == 4 and words[2][1:] == "lo" and words[2][0] in "xyz":
        axis = "xyz".index(words[2][0])
        key = "rve_L" + words[2][0]
        if key not in L:  # 2D: z keeps its (periodic) extent
            continue
        x = [float(a[4 + axis]) for a in atoms]
        lo, hi = min(x) - margin * L[key], max(x) + margin * L[key]
        lines[i] = f"{lo!r} {hi!r} {words[2]} {words[3]}"
open(out + ".rve.data", "w").write("\n".join(lines))
shutil.copy(src + ".vars", out + ".vars")
