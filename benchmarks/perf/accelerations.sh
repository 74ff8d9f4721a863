#!/usr/bin/env bash
# Speed-up and accuracy cost of each acceleration on the multiscale [LBS]
# biaxial test: runs dealii_app/examples/biaxial_MESH.prm (2x4: benchmarks/perf/biaxial_2x4_strict.prm) on 2 ranks with
# each setting below, keeps results/accel_MESH_SETTING/summary.csv and
# prints `name value unit` lines (wall time, DEM steps, RVE solves, macro
# iterations, peak stress ratio, axial strain at peak, largest difference of
# the stress-ratio curve from the strict scheme relative to its peak).
# Usage: benchmarks/perf/accelerations.sh [BUILD_DIR] MESH [SETTING...]
#   settings: strict (committed history: every trial from the last
#   converged state, [LBS]), warm (continuous history: warm starts, [LSYF]),
#   skip1e-5, skip1e-4 (warm + skip tolerance), check10 (warm + RVE
#   convergence checks every 10 DEM steps instead of 50), fast (check10 +
#   skip1e-5), mtsN (check10 + multiple time stepping: at most N DEM steps
#   per RVE and DR iteration until (M9) first holds, e.g. mts50); a suffix
#   +incremental on any of them adds 'Frequency estimate = incremental' of
#   dynamic relaxation (e.g. mts20+incremental), +dtT the RVE's 'Time
#   step' T (e.g. mts20+incremental+dt2e-6), +sfG dynamic relaxation's
#   'Safety factor' G, +xiX its 'Damping ratio' X, +tolE its 'Kinetic
#   energy tolerance' E, +rampN its 'Ramp iterations' N (e.g.
#   mts50+incremental+sf0.9), +extrap its 'Predictor = extrapolate',
#   +affine the RVE's 'Inner start = affine' (e.g.
#   mts50+incremental+extrap+affine), +ext 'Boundary extension = elastic',
#   and +early ends the run after the first two
#   axial steps (1 %: the start of the curve, where the DR transients show).
#   Default: the first six.
# ACCEL_WORKDIR=DIR keeps each run in DIR/MESH_SETTING with a checkpoint
# after every load step, and a later call with the same DIR resumes it
# (`fe2dem --resume`): for runs longer than one sitting, such as strict on
# 2x4. Stop one with `kill -TERM` on its fe2dem processes (status
# "stopped"); the wall time printed is that of the last sitting.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="$(realpath -m "${1:-$root/build}")"
mesh="${2:-1x1}"
shift 2 || true
settings=("${@:-strict warm skip1e-5 skip1e-4 check10 fast}")
read -r -a settings <<<"${settings[*]}"
source "$root/benchmarks/common.sh"
overrides() {
  case $1 in
    *+*) overrides "${1%+*}"  # the last suffix
      case ${1##*+} in
        incremental) printf 'subsection Dynamic relaxation\n  set Frequency estimate = incremental\nend\n' ;;
        dt*) printf 'subsection RVE\n  set Time step = %s\nend\n' "${1##*+dt}" ;;
        sf*) printf 'subsection Dynamic relaxation\n  set Safety factor = %s\nend\n' "${1##*+sf}" ;;
        xi*) printf 'subsection Dynamic relaxation\n  set Damping ratio = %s\nend\n' "${1##*+xi}" ;;
        tol*) printf 'subsection Dynamic relaxation\n  set Kinetic energy tolerance = %s\nend\n' "${1##*+tol}" ;;
        ramp*) printf 'subsection Dynamic relaxation\n  set Ramp iterations = %s\nend\n' "${1##*+ramp}" ;;
        extrap) printf 'subsection Dynamic relaxation\n  set Predictor = extrapolate\nend\n' ;;
        affine) printf 'subsection RVE\n  set Inner start = affine\nend\n' ;;
        ext) printf 'subsection Dynamic relaxation\n  set Boundary extension = elastic\nend\n' ;;
        early) printf 'subsection Loading\n  set Load steps = 2\n  set Axial strain = 0.01\nend\n' ;;
        *) echo "unknown suffix '+${1##*+}' of setting '$1'" >&2; exit 2 ;;
      esac ;;
    strict) printf 'subsection Material\n  set History = committed\n  set Skip tolerance = 0\nend\n' ;;
    warm) printf 'subsection Material\n  set History = continuous\n  set Skip tolerance = 0\nend\n' ;;
    skip*) printf 'subsection Material\n  set History = continuous\n  set Skip tolerance = %s\nend\n' "${1#skip}" ;;
    check10) printf 'subsection Material\n  set History = continuous\nend\nsubsection RVE\n  set Check interval = 10\nend\n' ;;
    fast) overrides check10; printf 'subsection Material\n  set Skip tolerance = 1e-5\nend\n' ;;
    mts[0-9]*) overrides check10; printf 'subsection Material\n  set DEM steps per iteration = %s\nend\n' "${1#mts}" ;;
    *) echo "unknown setting '$1'" >&2; exit 2 ;;
  esac
}
# 1x1: the example (all defaults); 2x4: the strict copy of the 2x4 example
# (the shipped one has the recommended settings); any other mesh (e.g.
# 4x8): the strict 2x4 with its cells.
prm="$root/dealii_app/examples/biaxial_$mesh.prm"
[[ $mesh == 2x4 ]] && prm="$root/benchmarks/perf/biaxial_2x4_strict.prm"
if [[ ! -f $prm ]]; then
  [[ $mesh =~ ^([0-9]+)x([0-9]+)$ ]] || { echo "accelerations.sh: MESH must be CxR, e.g. 4x8 (got '$mesh')" >&2; exit 2; }
  prm="$(mktemp)"
  trap 'rm -f "$prm"' EXIT
  { cat "$root/benchmarks/perf/biaxial_2x4_strict.prm"
    printf 'subsection Geometry\n  set Cells x = %s\n  set Cells y = %s\nend\n' "${BASH_REMATCH[1]}" "${BASH_REMATCH[2]}"; } > "$prm"
fi
mkdir -p "$here/results"
for s in "${settings[@]}"; do
  if [[ -n "${ACCEL_WORKDIR:-}" ]]; then
    work="$(realpath -m "$ACCEL_WORKDIR")/${mesh}_$s"
    mkdir -p "$work"
  else
    work="$(mktemp -d)"
  fi
  resume=() log="$here/results/accel_${mesh}_$s.log"
  if compgen -G "$work/out/checkpoints/checkpoint-*.h5" > /dev/null; then
    resume=(--resume)
    echo "accelerations.sh: resuming $work from its newest checkpoint" >> "$log"
  else
    : > "$log"
  fi
  { sed "s#^set Output directory.*#set Output directory = $work/out#; s#\.\./\.\./rve_templates#$root/rve_templates#" \
      "$prm"; overrides "$s"
    [[ -z "${ACCEL_WORKDIR:-}" ]] || printf 'subsection Checkpoint\n  set Every = 1\nend\n'; } > "$work/case.prm"
  start=$(date +%s.%N) from=$(( $(wc -l < "$log") + 1 ))
  status=completed
  mpirun --allow-run-as-root --oversubscribe -np 2 "$build/dealii_app/solver/fe2dem" "$work/case.prm" \
    "${resume[@]}" >> "$log" 2>&1 || status=stopped
  # SIGTERM makes fe2dem write a checkpoint and exit 0
  ! tail -n "+$from" "$log" | grep -q "and stopped\.\$" || status=stopped
  wall=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN {printf "%.1f", e - s}')
  mkdir -p "$here/results/accel_${mesh}_$s"
  cp "$work/out/summary.csv" "$here/results/accel_${mesh}_$s/"
  [[ -n "${ACCEL_WORKDIR:-}" ]] || rm -rf "$work"
  line=$(/usr/bin/python3 "$here/compare_curves.py" "$here/results/accel_${mesh}_$s/summary.csv" \
           "$here/results/accel_${mesh}_strict/summary.csv")
  echo "${mesh}_${s}_status $status -"
  echo "${mesh}_${s}_wall $wall s"
  echo "$line" | sed "s/^/${mesh}_${s}_/"
  append_result "$here/results_accelerations.csv" "benchmark,mesh,setting,status,wall_s,$(echo "$line" | awk '{print $1}' | paste -sd,)" \
    "accelerations,$mesh,$s,$status,$wall,$(echo "$line" | awk '{print $2}' | paste -sd,)"
done
