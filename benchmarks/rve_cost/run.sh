#!/usr/bin/env bash
# Cost per DEM step of the reference RVE: through the coupler and fix
# rve/servo (chunked runs; convergence checks every 50 steps, the default,
# and every 1000 steps) versus the same packing and step count under the
# bare Debian `liggghts` binary. Runs interleaved repetitions and reports
# medians and their ratio as `name value unit` lines; appends them to
# results.csv with machine, date and commit.
# Usage: benchmarks/rve_cost/run.sh [BUILD_DIR] [PACKING_PREFIX] [STEPS] [REPEATS]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="$(realpath -m "${1:-$root/build}")"
packing="$(realpath -m "${2:-$root/rve_templates/packings/lbs_ref}")"
steps="${3:-20000}"
repeats="${4:-5}"
# 3D packings (their .vars define rve_Lz): the 3D template, and as the
# reference the periodic packing itself (no frame) under bare liggghts.
if grep -q rve_Lz "$packing.vars"; then
  template="$root/rve_templates/rve_setup_3d.liggghts" bare_in="$here/bare_liggghts_3d.in" bare_data="$packing.periodic.data"
else
  template="$root/rve_templates/rve_setup_2d.liggghts" bare_in="$here/bare_liggghts.in" bare_data="$packing.rve.data"
fi
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
natoms=$(awk '/atoms$/ {print $1; exit}' "$packing.rve.data")
bare_atoms=$(awk '/atoms$/ {print $1; exit}' "$bare_data")

# Each repeat is a pair measured back to back on the same core (taskset, so
# that neither run migrates or shares a core with the other's leftovers),
# in alternating order; the paired ratio cancels most of the drift of a
# shared machine between repeats.
pin=()
if command -v taskset >/dev/null && [[ $(nproc) -ge 2 ]]; then pin=(taskset -c 1); fi
run_coupler() { "${pin[@]}" "$build/benchmarks/rve_cost/bench_rve_steps" "$template" "$packing" "$steps" "$1" | awk '/coupler_us_per_step/ {print $2}'; }
run_bare() {
  (cd "$tmp" && "${pin[@]}" liggghts -in "$bare_in" -var packing "$packing" -var steps "$steps" -log none > bare.out)
  grep -q "steps with $bare_atoms atoms" "$tmp/bare.out" ||
    { echo "bare liggghts run lost atoms; see $tmp/bare.out" >&2; exit 1; }
  awk -v n="$steps" '/Loop time of/ && $9 == n {printf "%.4f", 1e6 * $4 / n}' "$tmp/bare.out" | tail -1
}
coupler=(); coupler_sparse=(); bare=(); pairs=()
for ((k = 0; k < repeats; ++k)); do
  if ((k % 2 == 0)); then c=$(run_coupler 50); b=$(run_bare); else b=$(run_bare); c=$(run_coupler 50); fi
  cs=$(run_coupler 1000)
  [[ -n "$c" && -n "$b" && -n "$cs" ]] || { echo "run.sh: a timing run failed (coupler '$c', bare '$b')" >&2; exit 1; }
  coupler+=("$c"); coupler_sparse+=("$cs"); bare+=("$b"); pairs+=("$(ratio "$c" "$b")")
done
mc=$(median "${coupler[@]}"); mcs=$(median "${coupler_sparse[@]}"); mb=$(median "${bare[@]}")
ratio=$(ratio "$mc" "$mb"); ratio_sparse=$(ratio "$mcs" "$mb")
echo "particles $natoms count"
echo "bare_particles $bare_atoms count"
echo "steps $steps steps"
echo "repeats $repeats runs"
echo "bare_liggghts_us_per_step $mb us"
echo "coupler_us_per_step $mc us"
echo "coupler_over_bare $ratio ratio"
echo "coupler_check1000_us_per_step $mcs us"
echo "coupler_check1000_over_bare $ratio_sparse ratio"
min_ratio=$(ratio "$(minimum "${coupler[@]}")" "$(minimum "${bare[@]}")")
echo "coupler_over_bare_of_minima $min_ratio ratio"
echo "coupler_over_bare_of_lower_quartiles $(ratio "$(quartile1 "${coupler[@]}")" "$(quartile1 "${bare[@]}")") ratio"
paired=$(median "${pairs[@]}")
echo "coupler_over_bare_paired_median $paired ratio"
echo "coupler_over_bare_paired_range $(minimum "${pairs[@]}")-$(printf '%s\n' "${pairs[@]}" | sort -g | tail -1) ratio"
echo "pinned_to_core ${pin[*]:-none} -"
echo "all_coupler_samples ${coupler[*]}"
echo "all_coupler_check1000_samples ${coupler_sparse[*]}"
echo "all_bare_samples ${bare[*]}"
echo "all_paired_ratios ${pairs[*]}"
if [[ "$bare_atoms" != "$natoms" ]]; then # 3D: per particle-step, the RVE counted with its frame images
  echo "bare_us_per_particle_step $(awk -v t="$mb" -v n="$bare_atoms" 'BEGIN {printf "%.5f", t / n}') us"
  echo "coupler_us_per_body_step $(awk -v t="$mc" -v n="$natoms" 'BEGIN {printf "%.5f", t / n}') us"
  echo "coupler_over_bare_per_particle_step $(ratio "$(awk -v t="$mc" -v n="$natoms" 'BEGIN {printf "%.6f", t / n}')" "$(awk -v t="$mb" -v n="$bare_atoms" 'BEGIN {printf "%.6f", t / n}')") ratio"
fi
append_result "$here/results.csv" \
  "particles,steps,repeats,bare_us_per_step,coupler_us_per_step,ratio,coupler_check1000_us_per_step,ratio_check1000,paired_median_ratio" \
  "$natoms,$steps,$repeats,$mb,$mc,$ratio,$mcs,$ratio_sparse,$paired"
