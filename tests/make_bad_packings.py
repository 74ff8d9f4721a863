#!/usr/bin/env python3
"""Broken copies of a shipped RVE packing for the bad-input tests.

Usage: make_bad_packings.py SOURCE_PREFIX OUT_DIR
Writes OUT_DIR/{no_frame,unpaired,overlap}.{rve.data,vars}:
  no_frame  every particle inner (type 1): the frame group is empty;
  unpaired  one bottom-edge frame particle removed: its top image has no pair;
  overlap   an inner particle moved onto another one.
"""
import os
import sys

src, out = sys.argv[1], sys.argv[2]
os.makedirs(out, exist_ok=True)
lines = open(src + ".rve.data").read().splitlines()
vars_text = open(src + ".vars").read()
first = next(i for i, l in enumerate(lines) if l.startswith("Atoms")) + 2
atoms = [l.split() for l in lines[first:] if l.strip()]


def write(name, rows):
    head = [l if not l.endswith(" atoms") else f"{len(rows)} atoms" for l in lines[:first]]
    with open(f"{out}/{name}.rve.data", "w") as f:
        f.write("\n".join(head + [" ".join(r) for r in rows]) + "\n")
    with open(f"{out}/{name}.vars", "w") as f:
        f.write(vars_text)


write("no_frame", [[r[0], "1"] + r[2:] for r in atoms])
frame = [r for r in atoms if r[1] == "2"]
Lx = float(next(l for l in vars_text.splitlines() if "rve_Lx" in l).split()[-1])
Ly = float(next(l for l in vars_text.splitlines() if "rve_Ly" in l).split()[-1])


def has_image(r, dx, dy):
    x, y = float(r[4]) + dx, float(r[5]) + dy
    return any(abs(float(o[4]) - x) < 1e-9 and abs(float(o[5]) - y) < 1e-9 for o in frame)


# a bottom-edge particle (its image sits Ly above) that is not a corner
victim = next(r for r in frame if has_image(r, 0, Ly) and not has_image(r, Lx, 0) and not has_image(r, -Lx, 0))
write("unpaired", [r for r in atoms if r is not victim])
inner = [r for r in atoms if r[1] == "1"]
moved = [list(r) for r in atoms]
target = next(r for r in moved if r[0] == inner[1][0])
target[4] = f"{float(inner[0][4]) + 1e-6:.16e}"
target[5] = inner[0][5]
write("overlap", moved)
print(f"wrote {out}/{{no_frame,unpaired,overlap}} from {src} (removed frame particle {victim[0]}, "
      f"moved particle {inner[1][0]} onto {inner[0][0]})")
