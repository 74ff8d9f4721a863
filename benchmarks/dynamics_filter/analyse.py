#!/usr/bin/env python3
"""Noise of the samples of timed RVE solves (noise.liggghts) and what the box
filter of fe2dem (the mean of the m checks of a macro step) leaves of it:
noise = standard deviation of the samples about a centred moving average
over WINDOW samples (the trend), for single samples and for means of m.
Usage: analyse.py LOG WINDOW"""
import sys

import numpy as np

log, window = sys.argv[1], int(sys.argv[2])
d = np.array([[float(x) for x in l.split()[1:]] for l in open(log) if l.startswith("SAMPLE")])
edge = window
for name, x in (("sigma12", d[:, 1]), ("sigma22", d[:, 2])):
    trend = np.convolve(x, np.ones(window) / window, mode="same")
    single = np.std((x - trend)[edge:-edge])
    residual = (x - trend)[edge:-edge]
    lag1 = np.corrcoef(residual[:-1], residual[1:])[0, 1]
    line = (f"{name}: {len(x)} samples, noise {single:.0f} Pa = {100 * single / np.mean(np.abs(x[edge:-edge])):.3f} % "
            f"of the stress, lag-1 autocorrelation {lag1:.2f}")
    for m in (3, 15):
        n = len(x) // m * m
        means = x[:n].reshape(-1, m).mean(axis=1)
        centres = np.arange(len(means)) * m + (m - 1) / 2
        keep = (centres > edge) & (centres < len(x) - edge)
        left = np.std((means - np.interp(centres, np.arange(len(x)), trend))[keep])
        line += f"; mean of {m}: {left / single:.2f} of it (white noise: {1 / np.sqrt(m):.2f})"
    print(line)
