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

The half-share width (band_width.half_share_width, the [LBS] study's measure where the profile
leaves the specimen before falling to half): on the [LBS] specimen, 10 x 20 mm,
- a uniform field holds half its sum in half of the points;
- uniform bands 4 and 6 mm wide at 50 deg, through three centres, read 4 and 6 mm within 0.2 mm
  on a 0.1 mm grid and within 0.5 mm on the IPs of the study's meshes (2x4 and 4x8 with 2x2
  Gauss points, 8x16 with one point);
- a Gaussian band of FWHM 4 mm reads 2 x 2 x 0.674 sigma = 1.146 FWHM within 3 %;
- the Coulomb angle of stress ratio 0.5 (phi = 30 deg) is 60 deg.

Usage: check_band_width.py SOURCE_DIR (Debian's python3 with numpy)."""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(sys.argv[1], "benchmarks", "lbs2018"))
import band_width as bw  # noqa: E402

INCLINED = bw.INCLINED
FWHM_PER_SIGMA = 2 * math.sqrt(2 * math.log(2))


def distance(points, centre, angle_deg):
    """The signed distance of `points` from the line through `centre` at `angle_deg` from x."""
    a = math.radians(angle_deg)
    return (points - centre) @ np.array([-math.sin(a), math.cos(a)])


def gaussian_band(points, centre, angle_deg, fwhm):
    """gamma of a band through `centre` at `angle_deg` from x, Gaussian across it."""
    return np.exp(-0.5 * (distance(points, centre, angle_deg) / (fwhm / FWHM_PER_SIGMA)) ** 2)


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
    return 0 if (ok and check_half_share_width()) else 1


def ip_grid(nx, ny, gauss):
    """The IPs of an nx x ny mesh of the 10 x 20 mm [LBS] specimen: 2x2 Gauss points or one point."""
    offsets = [0.5 - 0.5 / math.sqrt(3), 0.5 + 0.5 / math.sqrt(3)] if gauss else [0.5]
    h = 10e-3 / nx
    xs = [(i + o) * h for i in range(nx) for o in offsets]
    ys = [(j + o) * h for j in range(ny) for o in offsets]
    x, y = np.meshgrid(xs, ys)
    return np.column_stack([x.ravel(), y.ravel()])


def check_half_share_width():
    height, angle = 20e-3, 50
    fine = ip_grid(100, 200, False)
    ok = check("uniform field: half share", bw.half_share(np.ones(len(fine))), 0.5, 1e-12)
    for label, points, tol in (("0.1 mm grid", fine, 0.2e-3), ("2x4, 2x2 Gauss", ip_grid(2, 4, True), 0.5e-3),
                               ("4x8, 2x2 Gauss", ip_grid(4, 8, True), 0.5e-3),
                               ("8x16, one point", ip_grid(8, 16, False), 0.5e-3)):
        for width in (4e-3, 6e-3):
            for y in (8e-3, 10e-3, 11.3e-3):
                band = (np.abs(distance(points, np.array([5e-3, y]), angle)) <= width / 2).astype(float)
                ok &= check(f"uniform band {1e3 * width:g} mm through y = {1e3 * y:g} mm, {label}: width (m)",
                            bw.half_share_width(band, height, angle), width, tol)
    gauss = gaussian_band(fine, np.array([5e-3, 10e-3]), angle, 4e-3)
    ok &= check("Gaussian band of FWHM 4 mm: width / FWHM", bw.half_share_width(gauss, height, angle) / 4e-3,
                4 * 0.6745 / FWHM_PER_SIGMA, 0.03 * 4 * 0.6745 / FWHM_PER_SIGMA)
    ok &= check("Coulomb angle of stress ratio 0.5 (deg)", bw.coulomb_angle(0.5), 60, 1e-9)
    return ok


if __name__ == "__main__":
    sys.exit(main())
