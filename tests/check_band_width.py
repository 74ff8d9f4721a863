#!/usr/bin/python3
"""The band finder of benchmarks/lbs2018/band_width.py on fields whose band is known:
points on a regular 0.5 mm grid over 40 x 80 mm (the [LSYF] problem 4 specimen), gamma a
Gaussian profile across a line at a known angle, FWHM known in closed form (2 sqrt(2 ln 2) s).

- one band at 50 deg: found at 50 deg, width within one bin of the FWHM, with all directions
  and with the inclined ones (band_width.INCLINED: 20-70, 110-160 deg, as problem4.py searches);
- the same band crossed at its centre by a narrow horizontal stripe of twice its peak (the
  crossing of an X, as the last increments of problem 4's local elastic runs show): among all
  directions the stripe is found (0 deg, its own width), among the inclined ones the band (its
  angle within 2 deg, its width within two bins: the stripe adds to its profile);
- a wider, stronger stripe (three times the peak, 4 mm) defeats the inclined search too, and
  shows it: the angle found lies on an edge of the inclined range (20 or 160 deg), which is
  how problem4.py's README reads such a result (no band), not as a width.

Usage: check_band_width.py SOURCE_DIR (Debian's python3 with numpy)."""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(sys.argv[1], "benchmarks", "lbs2018"))
import band_width as bw  # noqa: E402

INCLINED = bw.INCLINED
FWHM_PER_SIGMA = 2 * math.sqrt(2 * math.log(2))


def gaussian_band(points, centre, angle_deg, fwhm):
    """gamma of a band through `centre` at `angle_deg` from x, Gaussian across it."""
    a = math.radians(angle_deg)
    d = (points - centre) @ np.array([-math.sin(a), math.cos(a)])  # distance along the normal
    return np.exp(-0.5 * (d / (fwhm / FWHM_PER_SIGMA)) ** 2)


def check(name, got, want, tol):
    ok = abs(got - want) <= tol
    print(f"{'ok  ' if ok else 'FAIL'} {name}: {got:.4g} (expected {want:.4g} +- {tol:.3g})")
    return ok


def main():
    x, y = np.meshgrid(np.arange(0.25e-3, 40e-3, 0.5e-3), np.arange(0.25e-3, 80e-3, 0.5e-3))
    points = np.column_stack([x.ravel(), y.ravel()])
    centre = np.array([20e-3, 40e-3])
    fwhm, bin = 6e-3, 0.5e-3
    band = gaussian_band(points, centre, 50, fwhm)
    ok = True
    for label, angles in (("all directions", range(180)), ("inclined", INCLINED)):
        width, angle, _ = bw.band_width(points, band, bin, angles)
        ok &= check(f"one band, {label}: angle", angle, 50, 0)
        ok &= check(f"one band, {label}: width (m)", width, fwhm, bin)
    crossed = band + 2 * gaussian_band(points, centre, 0, 3e-3)
    width, angle, _ = bw.band_width(points, crossed, bin)
    ok &= check("band and narrow stripe, all directions: angle (the stripe)", min(angle, 180 - angle), 0, 1)
    ok &= check("band and narrow stripe, all directions: width (m), the stripe's", width, 3e-3, bin)
    width, angle, _ = bw.band_width(points, crossed, bin, INCLINED)
    ok &= check("band and narrow stripe, inclined: angle (the band)", angle, 50, 2)
    ok &= check("band and narrow stripe, inclined: width (m)", width, fwhm, 2 * bin)
    _, angle, _ = bw.band_width(points, band + 3 * gaussian_band(points, centre, 0, 4e-3), bin, INCLINED)
    ok &= check("band and wide stripe, inclined: distance of the angle from the range's edge (deg)",
                min(abs(angle - 20), abs(angle - 160)), 0, 1)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
