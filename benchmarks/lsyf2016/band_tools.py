"""What problem3.py and problem4.py share: the in-plane band of a 3D run on
one layer of one-point elements, and the curves' PNG (Debian's python3 with
numpy, h5py, matplotlib)."""
import os
import sys

import h5py
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lbs2018"))
import band_width as bw  # noqa: E402


def inplane_band(history, rows, band_angles=range(180), field="F", end=-1):
    """(reference positions [n, 2], gamma [n], width, angle, middle) of the band in the increment of
    the in-plane (x, y) block of `field` (F, or F_nonlocal: what the RVEs saw) over the `rows` rows
    of history.h5 up to row index `end` (the last by default) (benchmarks/lbs2018/
    band_width.py: width the full width at half maximum of the profile across the band, angle
    from x in degrees among `band_angles`, middle the profile's peak position along the band's
    normal)."""
    with h5py.File(history, "r") as h:
        x = h["ip_position"][()][:, :2]
        F = h[field if field in h else "F"][()].reshape(len(h["step"]), -1, 3, 3)[:, :, :2, :2]
    end = end % len(F)
    grad = np.einsum("nij,njk->nik", F[end] - F[end - rows], np.linalg.inv(F[end - rows]))
    gamma = bw.shear_strain(grad)
    width, angle, (centres, means) = bw.band_width(x, gamma, band_angles=band_angles)
    return x, gamma, width, angle, centres[int(np.argmax(means))]


def row_means(x, gamma):
    """(y of each row of IPs, the mean of @p gamma over the row): a structured mesh's profile across
    a band along x."""
    y, row = np.unique(np.round(x[:, 1], 6), return_inverse=True)
    return y, np.bincount(row, weights=gamma) / np.bincount(row)


def shear_modulus(E, nu):
    """The shear modulus of an isotropic law of Young's modulus E and Poisson ratio nu."""
    return E / (2 * (1 + nu))


def print_ce_ratios(moduli, nu, softening):
    """One line per Young's modulus E in `moduli` (Pa): C_e's shear modulus (Poisson ratio `nu`)
    and its ratio to the smallest and largest H_s in `softening` (nothing if that is empty)."""
    if not softening:
        return
    print()
    for E in moduli:
        mu = shear_modulus(E, nu)
        print(f"- C_e of E = {E / 1e6:g} MPa: shear modulus {mu / 1e6:.3g} MPa, "
              f"{mu / max(softening):.1f}-{mu / min(softening):.1f} times H_s")


def band_softening(history, tau):
    """(peak row, gamma_band, H_s): the band's softening modulus in shear H_s = (tau_peak - tau_end) /
    gamma_band of the run in `history`, tau a shear stress per row of history.h5 and gamma_band the
    largest IP shear strain increment from the peak row to the last (inplane_band). Against C_e's
    shear modulus it predicts the band's width in R on the softening bar (ctest
    macro_nonlocal_softening_bar: 1.1 R at C_e / H = 2.7, 2.1 R at 9)."""
    peak = int(np.argmax(tau))
    _, gamma, _, _, _ = inplane_band(history, len(tau) - 1 - peak)
    return peak, gamma.max(), (tau[peak] - tau[-1]) / gamma.max()


def plot_curves(curves, xlabel, ylabel, path, dashed=lambda label: False):
    """One line per {label: (strain, value)}, strain in per cent on the axis; lines past the
    tenth colour dotted (the colour cycle repeats)."""
    plt.figure(figsize=(6, 4))
    for k, (label, (x, y)) in enumerate(curves.items()):
        style = "--" if dashed(label) else ":" if k >= 10 else "-"
        plt.plot(100 * np.asarray(x), y, style, label=label)
    plt.xlabel(xlabel)
    plt.ylabel(ylabel)
    plt.legend(fontsize=6)
    plt.tight_layout()
    plt.savefig(path, dpi=120)
