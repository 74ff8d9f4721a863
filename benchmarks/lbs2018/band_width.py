#!/usr/bin/python3
"""Shear-band width of a 2D strain-increment field, for the IPs of a
multiscale run (history.h5) and for the particles of a DNS (particle dumps).

The measure, the same for both: the shear strain increment
gamma = sqrt((e11 - e22)^2 + (2 e12)^2) of the symmetric part of the
displacement-increment gradient between two load steps; its band is
averaged in bins of the distance d along a normal (bin width `bin`,
default 0.5 mm or half the points' spacing); the band's normal is the one
of 180 directions whose bin means explain the largest share of the
variance of gamma (the bins then run along the band), and the width is the
full width at half maximum of that profile, the two crossings of half its
peak found by linear interpolation between bins. Distances are in the configuration at the first of the two
steps for particles, and in the reference configuration for IPs (history.h5
holds reference positions; at 10 % axial strain the two differ by at most
10 %, a bias the same for every mesh).

Usage (a module for nonlocal_study.py; as a script, one field):
  band_width.py ips HISTORY_H5 STEP0 STEP1
  band_width.py particles DUMP0 DUMP1 [GRID_SPACING FIT_RADIUS]
Debian's python3 with numpy and h5py.
"""
import sys

import numpy as np


def shear_strain(grad):
    """gamma of the symmetric part of displacement-increment gradients [n, 2, 2]."""
    e = 0.5 * (grad + np.transpose(grad, (0, 2, 1)))
    return np.sqrt((e[:, 0, 0] - e[:, 1, 1]) ** 2 + (2.0 * e[:, 0, 1]) ** 2)


def ip_field(history, step0, step1, dataset="F"):
    """(reference positions [n, 2], gamma [n]) of the IPs between two rows of history.h5:
    the increment of `dataset` (F, or F_nonlocal: the F the RVEs saw) over the steps in the
    configuration of step0, dF F0^-1."""
    import h5py
    with h5py.File(history, "r") as h:
        x = h["ip_position"][()]
        F = h[dataset][()].reshape(len(h["step"]), -1, 2, 2)
    grad = np.einsum("nij,njk->nik", F[step1] - F[step0], np.linalg.inv(F[step0]))
    return x, shear_strain(grad)


def read_dump(path):
    """{id: (x, y)} of the inner particles (frame = 0) of a particle dump."""
    with open(path) as f:
        lines = f.read().splitlines()
    start = next(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS")) + 1
    cols = lines[start - 1].split()[2:]
    data = np.array([l.split() for l in lines[start:] if l.strip()], dtype=float)
    inner = data[:, cols.index("frame")] == 0
    return {int(i): (x, y) for i, x, y in data[inner][:, [cols.index("id"), cols.index("x"), cols.index("y")]]}


def particle_field(dump0, dump1, spacing=0.5e-3, radius=1.0e-3):
    """(grid points [n, 2], gamma [n]) of the particles' displacement increment
    between two dumps: an affine least-squares fit of the displacements of the
    inner particles within `radius` of each grid point (at least 6 of them)."""
    p0, p1 = read_dump(dump0), read_dump(dump1)
    ids = sorted(set(p0) & set(p1))
    x = np.array([p0[i] for i in ids])
    u = np.array([p1[i] for i in ids]) - x
    lo, hi = x.min(axis=0) + radius, x.max(axis=0) - radius
    gx, gy = np.meshgrid(np.arange(lo[0], hi[0] + 1e-12, spacing), np.arange(lo[1], hi[1] + 1e-12, spacing))
    points, grads = [], []
    for g in np.column_stack([gx.ravel(), gy.ravel()]):
        near = np.linalg.norm(x - g, axis=1) <= radius
        if near.sum() < 6:
            continue
        A = np.column_stack([np.ones(near.sum()), x[near] - g])
        coef, *_ = np.linalg.lstsq(A, u[near], rcond=None)
        points.append(g)
        grads.append(coef[1:].T)  # du_i/dx_j
    return np.array(points), shear_strain(np.array(grads))


# band directions of biaxial compression, degrees from x (the minor stress): a shear band is
# inclined (45 deg + half the friction angle for Coulomb); a near-horizontal "band" is the crossing
# of a conjugate pair or a platen's dead zone, a near-vertical one the barrel. A band found on an
# edge of this range (20 or 160 deg) is a feature outside it, not a band (tests/check_band_width.py).
INCLINED = [a for a in range(180) if 20 <= a <= 70 or 110 <= a <= 160]


def profile(points, gamma, normal, bin):
    """(bin centres d, mean gamma, share of the variance of gamma the bin means explain) of the
    points binned by d = normal . x (bins with >= 2 points)."""
    d = points @ normal
    edges = np.arange(d.min() - bin / 2, d.max() + bin, bin)
    which = np.digitize(d, edges) - 1
    counts = np.bincount(which, minlength=len(edges))[:-1]
    sums = np.bincount(which, weights=gamma, minlength=len(edges))[:-1]
    means = sums / np.maximum(counts, 1)
    explained = (counts * (means - gamma.mean()) ** 2).sum() / max(((gamma - gamma.mean()) ** 2).sum(), 1e-300)
    keep = counts >= 2
    return (0.5 * (edges[:-1] + edges[1:]))[keep], means[keep], explained


def band_width(points, gamma, bin=None, band_angles=range(180)):
    """(width, band direction in degrees from x, profile (d, mean gamma)) of the
    band of `gamma`: over the band directions `band_angles` (degrees from x;
    default 0, 1, ... 179), the one whose normal's profile explains the
    largest share of the variance of gamma is the band's (the bins then run
    along the band); the width is that profile's full width at half maximum
    (NaN without two crossings). `bin` defaults to max(0.5 mm, half the
    median nearest-neighbour spacing of the points)."""
    if bin is None:
        gaps = np.linalg.norm(points[:, None, :] - points[None, :, :], axis=2)
        np.fill_diagonal(gaps, np.inf)
        bin = max(0.5e-3, 0.5 * np.median(gaps.min(axis=1)))
    best = None
    for deg in sorted((angle + 90) % 180 for angle in band_angles):  # the band's normals
        normal = np.array([np.cos(np.radians(deg)), np.sin(np.radians(deg))])
        centres, means, explained = profile(points, gamma, normal, bin)
        if best is None or explained > best[0]:
            best = (explained, deg, centres, means)
    _, deg, centres, means = best
    return half_maximum_width(centres, means), (deg + 90) % 180, (centres, means)


def half_maximum_width(centres, means):
    """The full width at half maximum of the profile `means` over `centres`: the distance between
    the first crossings of half its peak on either side of the peak, interpolated linearly (NaN
    without two crossings)."""
    k = int(np.argmax(means))
    half = 0.5 * means[k]

    def crossing(step):
        j = k
        while 0 <= j + step < len(means):
            if means[j + step] < half:
                a, b = means[j], means[j + step]
                return centres[j] + (centres[j + step] - centres[j]) * (a - half) / (a - b)
            j += step
        return np.nan

    return crossing(+1) - crossing(-1)


def half_share(gamma):
    """The smallest share of the points that holds half of the summed gamma (points of equal area:
    the IPs of a structured mesh, one point or 2x2 Gauss). 0.5 for a uniform field; for a uniform
    band over zero, half the band's share of the specimen."""
    g = np.sort(np.asarray(gamma, dtype=float))[::-1]
    return (np.searchsorted(np.cumsum(g) / g.sum(), 0.5) + 1) / len(g)


def half_share_width(gamma, height, angle_deg):
    """The width of the uniform band, crossing the whole width of a specimen `height` tall at
    `angle_deg` from x (its area: width x width of specimen / cos angle), that holds what the
    half_share of gamma holds: 2 half_share height cos(angle). Exact for a uniform band over
    zero that crosses both lateral edges; 1.146 FWHM for a Gaussian profile (its half lies
    within +-0.674 standard deviations); a background adds to it, a band cut by a corner or at
    another angle is misread by its shorter length or by the ratio of the cosines. It needs no
    profile falling to half its peak on both sides inside the specimen, which band_width does."""
    return 2.0 * half_share(gamma) * height * np.cos(np.radians(angle_deg))


def coulomb_angle(stress_ratio):
    """45 deg + phi / 2 from x (the minor stress) of a Coulomb band at the mobilised friction
    angle phi = asin(stress_ratio), stress_ratio = |(s11 - s22) / (s11 + s22)|."""
    return 45.0 + 0.5 * np.degrees(np.arcsin(stress_ratio))


if __name__ == "__main__":
    if len(sys.argv) >= 5 and sys.argv[1] == "ips":
        pts, g = ip_field(sys.argv[2], int(sys.argv[3]), int(sys.argv[4]))
    elif len(sys.argv) >= 4 and sys.argv[1] == "particles":
        extra = [float(v) for v in sys.argv[4:6]]
        pts, g = particle_field(sys.argv[2], sys.argv[3], *extra)
    else:
        sys.exit(__doc__)
    width, angle, _ = band_width(pts, g)
    print(f"{len(pts)} points, gamma max {g.max():.4g}: band width {width * 1e3:.2f} mm at {angle:.0f} deg")
