#!/usr/bin/python3
"""Particle picture with contact force chains of one RVE dump of fe2dem.

Usage: plot_particles.py PREFIX [PNG] [TITLE]
  PREFIX: OUTPUT/particles/ipNNNN-stepNNNN (reads .particles and .contacts)
Frame particles are grey, inner particles white; each contact is a line
between the centres with width proportional to its normal force.
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import LineCollection, PatchCollection
from matplotlib.patches import Circle


def read(path):
    lines = open(path).read().splitlines()
    head = next(i for i, l in enumerate(lines) if l.startswith(("ITEM: ATOMS", "ITEM: ENTRIES")))
    cols = lines[head].split()[2:]
    return [dict(zip(cols, map(float, l.split()))) for l in lines[head + 1:]]


def draw(ax, prefix, title=None):
    """Draws the dump PREFIX.{particles,contacts} into the matplotlib axes AX."""
    particles, contacts = read(prefix + ".particles"), read(prefix + ".contacts")
    for frame, colour in ((1, "0.7"), (0, "white")):
        discs = [Circle((p["x"], p["y"]), p["radius"]) for p in particles if p["frame"] == frame]
        ax.add_collection(PatchCollection(discs, facecolor=colour, edgecolor="0.4", linewidth=0.4))
    if contacts:
        fmax = max(c["fn"] for c in contacts)
        segments = [((c["x1"], c["y1"]), (c["x2"], c["y2"])) for c in contacts]
        widths = [0.3 + 4.0 * c["fn"] / fmax for c in contacts]
        ax.add_collection(LineCollection(segments, linewidths=widths, colors="firebrick"))
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.set_axis_off()
    ax.set_title(title if title else prefix.split("/")[-1]
                 + f": {len(particles)} particles, {len(contacts)} contacts")


if __name__ == "__main__":
    prefix = sys.argv[1]
    png = sys.argv[2] if len(sys.argv) > 2 else prefix + ".png"
    fig, ax = plt.subplots(figsize=(6, 6))
    draw(ax, prefix, sys.argv[3] if len(sys.argv) > 3 else None)
    fig.savefig(png, dpi=150, bbox_inches="tight")
    print(png)
