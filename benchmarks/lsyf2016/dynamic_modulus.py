#!/usr/bin/python3
"""The RVE's constrained modulus under a sinusoidal strain (issue 35, item 7):
one one-point element (constrained_modulus.prm, lateral faces fixed) whose
top is driven by -A sin(2 pi f t); the RVE's sigma_yy is fitted over the
last periods as c + a sin + b cos, and M(f) = amplitude / (A / height).

Usage: dynamic_modulus.py OUT_DIR FREQ T_FIT [AMPLITUDE HEIGHT]
  OUT_DIR  fe2dem's output directory (summary.csv, history.h5)
  FREQ     the driving frequency [Hz]; T_FIT: fit over t > T_FIT [s]
  AMPLITUDE, HEIGHT: 1e-6 m and 0.01 m by default
Prints 'M_dyn VALUE MPa', the mean stress and the phase of the stress
behind the strain (degrees). tests/check_dynamic_modulus.py imports fit()."""
import csv
import sys

import h5py
import numpy as np


def fit(out, f0, t_fit, amplitude=1e-6, height=0.01):
    """(M [Pa], mean sigma_yy [Pa], phase lag [deg], rows fitted) of OUT_DIR."""
    t = np.array([float(r["time"]) for r in csv.DictReader(open(out + "/summary.csv"))])
    with h5py.File(out + "/history.h5", "r") as f:
        s22 = f["sigma"][:, 0, 4]
    m = t > t_fit
    w = 2 * np.pi * f0
    X = np.stack([np.ones(m.sum()), np.sin(w * t[m]), np.cos(w * t[m])], axis=1)
    c, a, b = np.linalg.lstsq(X, s22[m], rcond=None)[0]
    # compressive strain eps = (A/h) sin(w t) raises the compression: s22 = c - M eps
    M = np.hypot(a, b) / (amplitude / height)
    return M, c, np.degrees(np.arctan2(b, -a)), int(m.sum())


if __name__ == "__main__":
    if len(sys.argv) not in (4, 6):
        sys.exit(__doc__)
    extra = [float(v) for v in sys.argv[4:6]]
    M, c, lag, rows = fit(sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), *extra)
    print(f"M_dyn {M / 1e6:.1f} MPa")
    print(f"mean_sigma_yy {c:.0f} Pa")
    print(f"phase_lag {lag:.1f} deg")
    print(f"rows_fitted {rows}")
