#!/usr/bin/env python3
"""Broken copies of a shipped RVE packing for the bad-input tests.

Usage: make_bad_packings.py SOURCE_PREFIX OUT_DIR
Writes OUT_DIR/{no_frame,unpaired,overlap}.{rve.data,vars}:
  no_frame  every particle inner (type 1): the frame group is empty;
  unpaired  one bottom-edge frame particle removed: its top image has no pair;
  overlap   an inner particle moved onto another one;
and, for LIGGGHTS' own messages (issue 16), negative_radius, zero_density,
text_type (a word in the type column) and no_ly (a vars file without rve_Ly);
and 'with space/spaced', a valid copy in a directory whose name has a space;
and, for fe2dem's own check of the data file (issue 39), zero_radius,
text_radius ('0.00x7' as a diameter), nan_coordinate and inf_coordinate.
"""
import sys

from rve_data_copy import RveData

src, out = sys.argv[1], sys.argv[2]
data = RveData(src)
atoms = data.atoms


def write(name, rows):
    data.write(out, name, rows)


write("no_frame", [[r[0], "1"] + r[2:] for r in atoms])
frame = [r for r in atoms if r[1] == "2"]
Lx, Ly = data.cell_side("x"), data.cell_side("y")


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
data.write(out + "/with space", "spaced", atoms)
first = [list(r) for r in atoms]
write("negative_radius", [first[0][:2] + ["-" + first[0][2]] + first[0][3:]] + atoms[1:])
write("zero_density", [first[0][:3] + ["0"] + first[0][4:]] + atoms[1:])
write("text_type", [[first[0][0], "x"] + first[0][2:]] + atoms[1:])
write("zero_radius", [first[0][:2] + ["0"] + first[0][3:]] + atoms[1:])
write("text_radius", [first[1]] + [first[2][:2] + ["0.00x7"] + first[2][3:]] + atoms[2:] + [first[0]])
write("nan_coordinate", [first[0][:4] + ["nan"] + first[0][5:]] + atoms[1:])
write("inf_coordinate", [first[0][:5] + ["-inf"] + first[0][6:]] + atoms[1:])
write("no_ly", atoms)
with open(f"{out}/no_ly.vars", "w") as f:
    f.write("\n".join(l for l in data.vars_text.splitlines() if "rve_Ly" not in l) + "\n")
print(f"wrote {out}/{{no_frame,unpaired,overlap,negative_radius,zero_density,text_type,no_ly}} from {src} (removed frame particle {victim[0]}, "
      f"moved particle {inner[1][0]} onto {inner[0][0]})")
