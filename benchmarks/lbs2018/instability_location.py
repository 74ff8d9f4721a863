#!/usr/bin/env python3
"""Where a stopped run's macro instability sat against its shear band.

Usage: instability_location.py CASE [SPAN]   (Debian's python3 with numpy, h5py)

Reads the stop message of runs/CASE/run.log ("the macro time step is
unstable ... most often u_x of the node at (x y) m (N steps), ...") and
runs/CASE/history.h5, and prints for each named node the shear strain
increment of F (band_width.ip_field) over the last SPAN rows (default 4:
0.5 % axial strain in 0.125 % steps) at the IPs of the elements around the
node (IPs closer than one element size to it along both axes) against the largest
over the mesh: a node in the band has an element above half the largest.
Then the frame membrane's contacts per row (history.h5 membrane_steps,
mean over the last 20 rows) of the band's IPs (above half the largest
increment) against the others, and the IPs with 35 or more.
"""
import os
import re
import sys

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import band_width as bw  # noqa: E402

RUNS = os.path.join(HERE, "runs")

NODE = re.compile(r"u_([xyz]) of the node at \(([-0-9.e+]+) ([-0-9.e+]+)\) m \((\d+) steps\)")


def named_nodes(log):
    """[(component, x, y, steps)] of the stop message in @p log; exits if there is none."""
    text = open(log).read()
    if "the macro time step is unstable" not in text:
        sys.exit(f"instability_location.py: {log} holds no 'macro time step is unstable' message")
    message = text[text.index("the macro time step is unstable"):].splitlines()[0]  # every rank prints it
    return [(c, float(x), float(y), int(n)) for c, x, y, n in NODE.findall(message)]


def element_size(prm):
    """(width / cells x, height / cells y) of subsection Geometry of @p prm (the last value wins, as
    in deal.II's ParameterHandler reading run.sh's case file)."""
    value = {}
    for line in open(prm):
        m = re.match(r"\s*set\s+(Width|Height|Cells x|Cells y)\s*=\s*([^#\s]+)", line)
        if m:
            value[m.group(1)] = float(m.group(2))
    return value["Width"] / value["Cells x"], value["Height"] / value["Cells y"]


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    case = sys.argv[1]
    span = int(sys.argv[2]) if len(sys.argv) == 3 else 4
    history = os.path.join(RUNS, case, "history.h5")
    with h5py.File(history, "r") as h:
        rows, strain, membrane = len(h["step"]), h["axial_strain"][()], h["membrane_steps"][()]
    x, gamma = bw.ip_field(history, rows - 1 - span, rows - 1)
    h_x, h_y = element_size(os.path.join(RUNS, case, "case.prm"))
    print(f"{case}: shear strain increment from {100 * strain[rows - 1 - span]:.4g} % to "
          f"{100 * strain[rows - 1]:.4g} %, largest {gamma.max():.4g} at the IP at "
          f"({1e3 * x[np.argmax(gamma), 0]:.4g}, {1e3 * x[np.argmax(gamma), 1]:.4g}) mm")
    print("| dof | node (mm) | reversals in 50 steps | largest around it / mesh's largest | in the band |")
    print("|---|---|---|---|---|")
    for c, nx, ny, steps in named_nodes(os.path.join(RUNS, case, "run.log")):
        near = (np.abs(x[:, 0] - nx) < h_x * (1 - 1e-6)) & (np.abs(x[:, 1] - ny) < h_y * (1 - 1e-6))
        share = gamma[near].max() / gamma.max()
        print(f"| u_{c} | ({1e3 * nx:.4g}, {1e3 * ny:.4g}) | {steps} | {share:.2f} | "
              f"{'yes' if share > 0.5 else 'no'} |")
    band, m = gamma > 0.5 * gamma.max(), membrane[-20:].mean(axis=0)
    print(f"membrane contacts per row, last 20 rows: {band.sum()} IPs in the band {m[band].mean():.1f} "
          f"(median {np.median(m[band]):.3g}), {(~band).sum()} others {m[~band].mean():.1f} "
          f"(median {np.median(m[~band]):.3g}); 35 or more: "
          + ", ".join(f"IP {i} ({1e3 * x[i, 0]:.4g}, {1e3 * x[i, 1]:.4g}) mm {m[i]:.0f}"
                      f"{' in the band' if band[i] else ''}" for i in np.where(m >= 35)[0]))


if __name__ == "__main__":
    main()
