#!/usr/bin/env python3
"""Rate independence of fe2dem-rve's continuous drive (issue 35), stdlib only.

Usage: check_continuous_rates.py SLOW_CSV FAST_CSV TOLERANCE [--control-error E]
Reads both rve.csv as triaxial curves (benchmarks/rve_continuous/curves.py)
and asserts that at every row of the loading stage the stress ratio q/p and
the axial stress of FAST are within TOLERANCE (relative) of SLOW's, that
both rows fall on the same strains, and, with --control-error, that every
loading row held its lateral stresses within E of the pressure. Prints the
differences, so that a failure shows where the curves part.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "benchmarks", "rve_continuous"))
import curves  # noqa: E402

slow_path, fast_path, tol = sys.argv[1], sys.argv[2], float(sys.argv[3])
max_error = float(sys.argv[5]) if len(sys.argv) > 5 and sys.argv[4] == "--control-error" else None
_, slow = curves.load(slow_path)
_, fast = curves.load(fast_path)
failures = []
if len(slow) != len(fast) or len(slow) < 2:
    failures.append(f"{len(slow)} and {len(fast)} loading rows")
for a, b in zip(slow[1:], fast[1:]):
    if abs(a["strain"] - b["strain"]) > 1e-9:
        failures.append(f"rows at strains {a['strain']} and {b['strain']}")
    d_ratio = b["ratio"] / a["ratio"] - 1.0
    d_stress = b["stress"] / a["stress"] - 1.0
    print(f"strain {a['strain']:.4f}: q/p {a['ratio']:.4f} / {b['ratio']:.4f} ({d_ratio:+.2%}), "
          f"axial stress {a['stress']:.0f} / {b['stress']:.0f} Pa ({d_stress:+.2%}), "
          f"control errors {a['error']:.1e} / {b['error']:.1e}")
    if abs(d_ratio) > tol or abs(d_stress) > tol:
        failures.append(f"strain {a['strain']:.4f}: q/p {d_ratio:+.2%}, axial stress {d_stress:+.2%} "
                        f"(tolerance {tol:.1%})")
    if max_error is not None and max(a["error"], b["error"]) > max_error:
        failures.append(f"strain {a['strain']:.4f}: lateral stress off by {max(a['error'], b['error']):.2%} "
                        f"of the pressure (> {max_error:.1%})")
if failures:
    print("FAIL:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("PASS")
