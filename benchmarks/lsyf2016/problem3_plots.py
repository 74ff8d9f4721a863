"""problem3.py's figures of the band across y: the row-mean profiles of one run each
(problem3_profiles*.png) and the width against R with the ensembles' mean profiles
(problem3_against_r*.png)."""
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from band_tools import inplane_band, row_means  # noqa: E402
from problem3_cases import ALONG_X, BAND_ROWS, CASES, LOAD_STEPS, SHEAR  # noqa: E402


def plot_profiles(results, cases, path):
    """Two panels, the elements' own F and the averaged F (what the RVEs saw): the row means of the
    shear strain increment over the last BAND_ROWS rows against y, one line per case."""
    if not cases:
        return
    fig, axes = plt.subplots(1, 2, figsize=(9, 3.6), sharey=True)
    for ax, field, title in zip(axes, ("F", "F_nonlocal"), ("the elements' F", "the averaged F (what the RVEs saw)")):
        for k in cases:
            x, gamma, _, _, _ = inplane_band(os.path.join(results, CASES[k], "out", "history.h5"), BAND_ROWS,
                                             ALONG_X, field)
            y, g = row_means(x, gamma)
            ax.plot(g, 1e3 * y, "o-", ms=3, label=k)
        ax.set_title(f"{title}, last {BAND_ROWS // 2} % of shear", fontsize=8)
        ax.set_xlabel("row mean of the shear strain increment")
    axes[0].set_ylabel("y (mm)")
    axes[0].legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def plot_against_r(results, ensembles, widths, invalid, title, path):
    """Two panels into @p path: each run's end width over the last 2 BAND_ROWS rows and the ensemble
    means +- standard error against R (@p widths: {R: [runs, (elements' F, averaged F)]}, mm; the
    radii in @p invalid, whose runs' hourglass share passed 0.1, hollow), the line width = R and 2 R
    beside them; and each ensemble's mean row profile of the elements' F."""
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(9, 3.8))
    for col, (name, marker) in enumerate((("elements' F", "o"), ("averaged F", "s"))):
        for i, (r, w) in enumerate(widths.items()):
            shift = 0.3 * (col - 0.5)
            face = "none" if r in invalid else f"C{col}"
            ax.plot(np.full(len(w), r + shift), w[:, col], marker, color=f"C{col}", mfc=face, ms=3, alpha=0.5)
            ax.errorbar(r + shift, w[:, col].mean(), w[:, col].std(ddof=1) / np.sqrt(len(w)), fmt=marker,
                        color=f"C{col}", mfc=face, ms=7, capsize=3,
                        label=f"{name}, mean +- s.e." if i == 0 else None)
    ax.set_title(title + (f"; hollow: hourglass share > 0.1 at R = {', '.join(f'{r:g}' for r in sorted(invalid))} mm, "
                          "not equilibria" if invalid else ""), fontsize=7)
    r = np.array([0, max(widths) + 2])
    ax.plot(r, r, "k:", lw=0.8, label="width = R")
    ax.plot(r, 2 * r, "k--", lw=0.8, label="width = 2 R")
    ax.set_xlabel("R (mm)")
    ax.set_ylabel(f"band width, last {100 * SHEAR * 2 * BAND_ROWS / LOAD_STEPS:g} % of shear (mm)")
    ax.legend(fontsize=6)
    for r, members in ensembles.items():
        profiles = []
        for k in members:
            x, gamma, _, _, _ = inplane_band(os.path.join(results, CASES[k], "out", "history.h5"), 2 * BAND_ROWS,
                                             ALONG_X, "F")
            y, g = row_means(x, gamma)
            profiles.append(g)
        bx.plot(np.mean(profiles, axis=0), 1e3 * y, "o-", ms=3, label=f"R = {r:g} mm ({len(members)} runs)")
    bx.set_xlabel(f"row-mean shear increment, last {100 * SHEAR * 2 * BAND_ROWS / LOAD_STEPS:g} % (ensemble mean)")
    bx.set_ylabel("y (mm)")
    bx.legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
