#!/usr/bin/env python3
"""Broken copies of a 3D RVE packing (build_frame_3d.py layout) for the bad-input tests.

Usage: make_bad_packings_3d.py SOURCE_PREFIX OUT_DIR
Writes OUT_DIR/{unpaired_3d,no_corner_3d}.{rve.data,vars}:
  unpaired_3d   the +L image of one face particle removed: its original has no pair;
  no_corner_3d  the corner particle and its seven images removed.
build_frame_3d.py gives ids to the inner particles first, then the corner's
eight images, then each frame particle's images, original first (the lines
are in spatial order, so the rows are taken in id order here).
"""
import sys

from rve_data_copy import RveData

src, out = sys.argv[1], sys.argv[2]
data = RveData(src)
atoms = data.atoms
L = [data.cell_side(a) for a in "xyz"]


def write(name, rows):
    data.write(out, name, rows)


frame = sorted((r for r in atoms if r[1] == "2"), key=lambda r: int(r[0]))
pos = [[float(v) for v in r[4:7]] for r in frame]


def image_of(k, axis):
    """Index in frame of the +L_axis image of frame[k], or -1."""
    want = [pos[k][a] + (L[a] if a == axis else 0.0) for a in range(3)]
    for j, p in enumerate(pos):
        if all(abs(p[a] - want[a]) < 1e-9 for a in range(3)):
            return j
    return -1


# a face particle: exactly one image along one axis (after the 8 corner images)
victim = next(image_of(k, a) for k in range(8, len(frame)) for a in range(3)
              if image_of(k, a) >= 0 and sum(image_of(k, b) >= 0 for b in range(3)) == 1)
write("unpaired_3d", [r for r in atoms if r is not frame[victim]])
corner_ids = {r[0] for r in frame[:8]}
write("no_corner_3d", [r for r in atoms if r[0] not in corner_ids])
print(f"wrote {out}/{{unpaired_3d,no_corner_3d}} from {src} (removed face image {frame[victim][0]}, "
      f"corner ids {sorted(corner_ids, key=int)})")
