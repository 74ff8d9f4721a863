#!/usr/bin/env python3
"""Checks the prints of tests/dynamics_rve/timed_segments.liggghts run twice
on the same path of F: LONG with N solves of two checks, SHORT with 2N
solves of one check. Every solve must have finished (status 1), and solve k
of LONG must report, in sigma12 and sigma22, the mean of solves 2k-1 and 2k
of SHORT (with --last, LONG run with timed_stress last: solve 2k, the state
at its last check) within TOL, relative to the largest |sigma22| (the two runs differ
only by round-off in F at the cut, which the packing amplifies about
threefold per solve: keep N small). A frame move that runs to the end of its
solve carries out a correction made at a solve's start only half by the
next check, one made in its middle wholly: before session 34 this differed
by 1.6e-2 over 8 solves.
Usage: check_timed_segments.py [--last] LONG_LOG SHORT_LOG [TOL]"""
import re
import sys


def solves(log):
    rows = []
    for line in open(log):
        m = re.match(r"^SOLVE (\d+) st (\S+) s12 (\S+) s22 (\S+)$", line.strip())
        if m:
            rows.append([float(x) for x in m.groups()[1:]])
    return rows


args = sys.argv[1:]
last = args[:1] == ["--last"]
if last:
    args = args[1:]
long_log, short_log = args[0], args[1]
tol = float(args[2]) if len(args) > 2 else 1e-6
a, b = solves(long_log), solves(short_log)
if not a or len(b) != 2 * len(a):
    sys.exit(f"FAIL: {len(a)} solves in {long_log} and {len(b)} in {short_log} (want N > 0 and 2N)")
if any(r[0] != 1 for r in a + b):
    sys.exit("FAIL: a timed solve did not finish (status != 1)")
scale = max(abs(r[2]) for r in a)
worst = 0.0
for k, r in enumerate(a):
    for c in (1, 2):
        expected = b[2 * k + 1][c] if last else 0.5 * (b[2 * k][c] + b[2 * k + 1][c])
        worst = max(worst, abs(r[c] - expected) / scale)
what = "the second of each pair (timed_stress last)" if last else "the mean of each pair"
print(f"{'ok' if worst <= tol else 'FAIL'}: {len(a)} solves of two checks against {what} of {len(b)} of one: "
      f"largest difference in sigma12, sigma22 {worst:.2e} of max |sigma22| {scale:.4g} (tolerance {tol})")
sys.exit(0 if worst <= tol else 1)
