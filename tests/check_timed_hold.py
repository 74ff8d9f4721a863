#!/usr/bin/env python3
"""Checks the prints of tests/dynamics_rve/timed_hold.liggghts: the held timed
state and the quasi-static solve from it (status 1, converged) differ by at
most TOL in sigma12 and sigma22 (relative), so the timed state is an
equilibrium the quasi-static solver accepts.
Usage: check_timed_hold.py LOG [TOL]"""
import re
import sys

log, tol = sys.argv[1], float(sys.argv[2]) if len(sys.argv) > 2 else 0.005
values = {}
for line in open(log):
    m = re.match(r"^(TIMED_END|HELD|QUASI_STATIC) st (\S+) s12 (\S+) s22 (\S+) res (\S+)$", line.strip())
    if m:
        values[m[1]] = [float(x) for x in m.groups()[1:]]
if set(values) != {"TIMED_END", "HELD", "QUASI_STATIC"}:
    sys.exit(f"FAIL: {log} lacks lines: {sorted({'TIMED_END', 'HELD', 'QUASI_STATIC'} - set(values))}")
for k, (st, s12, s22, res) in values.items():
    print(f"{k:13s} status {st:.0f} sigma12 {s12:.6g} sigma22 {s22:.6g} servo residual {res:.3g}")
held, qs = values["HELD"], values["QUASI_STATIC"]
d12, d22 = abs(qs[1] - held[1]) / abs(held[1]), abs(qs[2] - held[2]) / abs(held[2])
ok = qs[0] == 1 and d12 <= tol and d22 <= tol
print(f"{'ok' if ok else 'FAIL'}: the quasi-static solve from the held state "
      f"{'converged' if qs[0] == 1 else 'did not converge'} and moved sigma12 by {d12:.2e}, "
      f"sigma22 by {d22:.2e} (tolerance {tol})")
sys.exit(0 if ok else 1)
