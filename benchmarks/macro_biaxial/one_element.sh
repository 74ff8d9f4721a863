#!/usr/bin/env bash
# One-element verification over the full curve ([LSYF] §3.2): fe2dem-rve on
# the reference packing along the path of biaxial_1x1.prm (4 isotropic
# steps to 150 kN/m, then 20 steps to 10 % axial strain, sigma12 free),
# compared with results/1x1/summary.csv of run.sh. Writes
# results/one_element_rve/rve.csv and results/one_element.png and prints the
# relative difference of the stress ratio per step up to the peak.
# Usage: benchmarks/macro_biaxial/one_element.sh [BUILD_DIR]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="$(realpath -m "${1:-$root/build}")"
prm="$(mktemp --suffix=.prm)"
sed "s#\.\./\.\./rve_templates#$root/rve_templates#; s#Loading steps   = 3#Loading steps   = 20#; s#Axial strain    = 0.015#Axial strain    = 0.10#" \
  "$root/tests/one_element/rve.prm" > "$prm"
"$build/dealii_app/rve_driver/fe2dem-rve" "$prm" --output-directory "$here/results/one_element_rve" > /dev/null
rm -f "$prm"
/usr/bin/python3 - "$here/results/1x1/summary.csv" "$here/results/one_element_rve/rve.csv" "$here/results/one_element.png" <<'PY'
import csv, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
macro = [r for r in csv.DictReader(open(sys.argv[1])) if r["stage"] == "2"]
rve = list(csv.DictReader(open(sys.argv[2])))[5:]
ratio = lambda r: abs((float(r["sigma11"]) - float(r["sigma22"])) / (float(r["sigma11"]) + float(r["sigma22"])))
ea = [float(m["axial_strain"]) for m in macro]
rm, rr = [float(m["stress_ratio_mean"]) for m in macro], [ratio(r) for r in rve]
peak = max(range(len(rm)), key=lambda i: rm[i])
for i in range(peak + 1):
    print(f"axial_strain {ea[i]:.3f}: macro {rm[i]:.4f} RVE {rr[i]:.4f} relative difference {abs(rm[i] - rr[i]) / rr[i]:.4f}")
print(f"largest_relative_difference_to_peak {max(abs(rm[i] - rr[i]) / rr[i] for i in range(peak + 1)):.4f} 1")
plt.plot(ea, rm, "o-", label="fe2dem, 1x1 mesh (4 RVEs)")
plt.plot(ea, rr, "s--", label="fe2dem-rve, one RVE")
plt.xlabel("axial strain"); plt.ylabel("stress ratio"); plt.grid(alpha=0.3); plt.legend()
plt.title("One-element verification, lbs_ref, 150 kN/m")
plt.savefig(sys.argv[3], dpi=120, bbox_inches="tight")
PY
