#!/usr/bin/python3
"""The RVE answers a fast strain as it answers a slow one (issue 35): the
constrained modulus fitted over the last period of sinusoidal runs of
tests/dynamics_rve/modulus_3d.prm (benchmarks/lsyf2016/dynamic_modulus.py).

Usage: check_dynamic_modulus.py SLOW_OUT F_SLOW FAST_OUT F_FAST TOL [KEEP_OUT MAX_KEEP_RATIO]
  M(fast) / M(slow) must be within 1 +- TOL (the default, 'Inner start' =
  auto: affine in dynamics); and, if given, the run with 'Inner start' = keep
  at the fast frequency must be below MAX_KEEP_RATIO times M(slow): the
  inertia of an interior that follows its frame only through contacts, the
  lag the default removes (so the first check could not pass for a reason
  that would also hide it)."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "benchmarks", "lsyf2016"))
from dynamic_modulus import fit  # noqa: E402

if len(sys.argv) not in (6, 8):
    sys.exit(__doc__)
slow, f_slow, fast, f_fast, tol = sys.argv[1], float(sys.argv[2]), sys.argv[3], float(sys.argv[4]), float(sys.argv[5])
M_slow = fit(slow, f_slow, 1.0 / f_slow)[0]
M_fast = fit(fast, f_fast, 1.0 / f_fast)[0]
ratio = M_fast / M_slow
print(f"M({f_slow:g} Hz) = {M_slow / 1e6:.1f} MPa, M({f_fast:g} Hz) = {M_fast / 1e6:.1f} MPa, ratio {ratio:.3f}"
      f" (allowed 1 +- {tol:g})")
ok = abs(ratio - 1.0) <= tol
if len(sys.argv) == 8:
    M_keep = fit(sys.argv[6], f_fast, 1.0 / f_fast)[0]
    keep_ratio = M_keep / M_slow
    limit = float(sys.argv[7])
    print(f"'Inner start' = keep: M({f_fast:g} Hz) = {M_keep / 1e6:.1f} MPa, ratio {keep_ratio:.3f} (must be < {limit:g})")
    ok = ok and keep_ratio < limit
print("PASS" if ok else "FAIL")
sys.exit(0 if ok else 1)
