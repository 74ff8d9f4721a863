#!/usr/bin/env bash
# One Hertz contact in Debian's LIGGGHTS (`model hertz tangential history`)
# along a path that separates the total-displacement law it implements,
# F_t = k_t(delta) s, from Mindlin's incremental law dF_t = k_t(delta) ds:
# shift s0 at overlap delta1, then load to delta2 = 4 delta1 at fixed s.
# Prints each stage's tangential force and the ratio to k_t(delta) s.
# Usage: benchmarks/hertz_mindlin/run.sh [E_Pa]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
E="${1:-5e8}"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
(cd "$tmp" && liggghts -in "$here/two_spheres.liggghts" -var E "$E" -log none > out.txt)
grep -a '^S[0-9]' "$tmp/out.txt" | awk -v E="$E" '
  BEGIN { nu = 0.15; G = E / (2 * (1 + nu)); Gs = G / (2 * (2 - nu)); Rs = 0.25e-3
          print "stage what fn_N ft_N kt(delta)*s_N ft/(kt*s) incremental_Mindlin_ft_N" }
  { d = $3; ft = $5; fn = -$7
    if ($1 == "S1") { delta = 5e-7; s = 0 } else if ($1 == "S2") { s = 1e-8 }
    else if ($1 == "S3") { delta = 2e-6 } else if ($1 == "S4") { delta = 5e-7 } else { s = 0 }
    kt = 8 * Gs * sqrt(Rs * delta)
    if ($1 == "S2") mindlin = kt * s   # shift at delta1
    if ($1 == "S5") mindlin = 0
    printf "%s %s=%s %.6g %.6g %.6g %s %.6g\n", $1, $2, $3, fn, ft, kt * s, (s > 0 ? sprintf("%.6f", ft / (kt * s)) : "-"), mindlin }'
