#!/usr/bin/env bash
# Reproduces the [LBS] study of physics.md §3.1 (the paper's §4) with FE2DEM.
#
# Usage: benchmarks/lbs2018/run.sh [--build DIR] [--np N] [--mts20] [--checkpoint N] CASE... | all
#   mesh_1x1 mesh_1x2 mesh_2x4 mesh_4x8   mesh convergence (mesh_2x4 is also
#                                         the reference of every study:
#                                         friction 0.4, free rotation, lbs_ref)
#   mesh_8x16                             the finest local mesh (512 RVEs; more
#                                         than 40 min on 2 cores; not in 'all')
#   nonlocal_1x1 ... nonlocal_4x8,        the meshes with the nonlocal operator,
#   nonlocal_8x16                         R = 2.5 mm (README, "Local against
#                                         nonlocal"; 8x16 not in 'all')
#   nonlocal_MESH[_op][_RN][_aA][_le[E]][_half|_quarter|_eighth|_sixteenth]  R = N mm (Staggering = A), e.g.
#                                         nonlocal_4x8_R5; _op (also mesh_MESH_op):
#                                         one point per element; _le: Formulation =
#                                         local elastic, C_e of E = 6e6 N/m, or E;
#                                         _half, _quarter, _eighth, _sixteenth (also mesh_MESH_half...):
#                                         stage 2 in 0.25 / 0.125 / 0.0625 / 0.03125 % steps (not in 'all'; README,
#                                         "Local against nonlocal")
#   ..._slRATE (before _pK, e.g.          slow loading at the nominal strain rate RATE /s
#   mesh_2x4_quarter_sl0.25)              (fe2dem's default with RVEs) instead of relaxed steps
#   ..._smM (after _slRATE, e.g.          'Stability modulus' = M N/m instead of 1e7 (slow
#   mesh_8x16_op_quarter_sl0.25_sm2e7)    loading's numerical mass, the one-point hourglass
#                                         stiffness; README, session 58)
#   ..._pK (after every other part, e.g.  the lateral pressure 1.5e5 (1 + K 1e-6) N/m:
#   nonlocal_4x8_le_quarter_p1)           an ensemble member that differs from the
#                                         case in the sixth digit of one load
#                                         (ensemble_study.py; not in 'all')
#   mesh_4x8_steps22                      4x8 with stage 2 in 0.25 % steps to
#                                         5.5 % (load-step check of the peak)
#   dns_A dns_B                           direct numerical simulations
#   dns_B_tol1e-3 dns_B_tol1e-4           DNS B with looser relaxation
#                                         tolerances (dns.prm: 1e-5)
#   mu0.2 mu0.6                           friction study (2x4)
#   locked                                inner-particle rotation locked (2x4)
#   a005 a008                             initial anisotropy 0.05 / 0.08 (2x4)
#   all                                   every case above, then analyse.py
#                                         (the DNS cases run on one core
#                                         each, side by side)
# Options: --build DIR (default: build/ of the repository), --np N MPI ranks
# of the multiscale runs (default 2; the DNS runs on one core), --mts20 the
# multiscale cases with the study's settings before issue 19 (at most 20 DEM
# steps per iteration, secant frequency estimate, no predictor, Inner start =
# keep) into mts20/ instead (the DNS cases are the same in both),
# --checkpoint N a checkpoint of the multiscale cases every N load steps
# (lbs2018.prm: none; not result-defining: fe2dem --resume runs/CASE/case.prm
# continues a stopped case).
#
# Raw output goes to runs/CASE/ (not committed); the wall time, core count,
# date, commit and machine of each case go to results/runs.csv. analyse.py
# turns runs/ into the committed results/*.csv and results/*.png. With
# --mts20: mts20/runs/ and mts20/results/.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
source "$root/benchmarks/common.sh"
build="$root/build" np=2 mts20=0 checkpoint=0
all_cases=(mesh_1x1 mesh_1x2 mesh_2x4 mesh_4x8 mesh_4x8_steps22 dns_A dns_B dns_B_tol1e-3 dns_B_tol1e-4
           mu0.2 mu0.6 locked a005 a008 nonlocal_1x1 nonlocal_1x2 nonlocal_2x4 nonlocal_4x8)

usage() { sed -n '4,/^set -euo/{/^#/p}' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 2; }
cases=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build) [[ $# -ge 2 ]] || usage; build="$(realpath -m "$2")"; shift 2 ;;
    --np) [[ $# -ge 2 && "$2" =~ ^[1-9][0-9]*$ ]] || { echo "run.sh: --np needs a positive integer" >&2; exit 2; }
          np=$2; shift 2 ;;
    --mts20) mts20=1; shift ;;
    --checkpoint) [[ $# -ge 2 && "$2" =~ ^[1-9][0-9]*$ ]] ||
                    { echo "run.sh: --checkpoint needs a positive number of load steps" >&2; exit 2; }
                  checkpoint=$2; shift 2 ;;
    all) cases+=("${all_cases[@]}"); shift ;;
    -h|--help) usage ;;
    *) [[ " ${all_cases[*]} " == *" $1 "* || $1 =~ ^(mesh|nonlocal)_(1x1|1x2|2x4|4x8|8x16)(_op)?(_R[0-9.]+)?(_a[0-9.]+)?(_le[0-9.e]*)?(_half|_quarter|_eighth|_sixteenth)?(_sl[0-9.]+)?(_sm[0-9.e]+)?(_p[1-9][0-9]*)?$ ]] ||
         { echo "run.sh: unknown case '$1' (cases: ${all_cases[*]}, mesh_MESH[_op], nonlocal_MESH[_op][_RN][_aA][_le[E]][_half|_quarter|_eighth|_sixteenth][_slRATE][_smM][_pK], all)" >&2; exit 2; }
       cases+=("$1"); shift ;;
  esac
done
[[ ${#cases[@]} -gt 0 ]] || usage
for exe in dealii_app/solver/fe2dem dealii_app/rve_driver/fe2dem-rve; do
  [[ -x "$build/$exe" ]] || { echo "run.sh: $build/$exe not found: build first (scripts/run-tests.sh) or pass --build DIR" >&2; exit 1; }
done
cd "$here"
base=.  # holds runs/ and results/
[[ $mts20 == 0 ]] || base=mts20
runs=$base/runs results=$base/results
mkdir -p "$runs" "$results"

# The entries a case changes in lbs2018.prm (printed after it: the last value wins).
overrides() {
  local cells
  case "$1" in
    mesh_*|nonlocal_*)
      cells=${1#*_}; cells=${cells%%_*}
      printf 'subsection Geometry\n  set Cells x = %s\n  set Cells y = %s\nend\n' "${cells%x*}" "${cells#*x}"
      [[ $1 != *_steps22 ]] || printf 'subsection Loading\n  set Load steps = 22\n  set Axial strain = 0.055\nend\n'
      # _half, _quarter, _eighth, _sixteenth: stage 2 in 0.25, 0.125, 0.0625 and 0.03125 % steps
      # (the load-step check of a whole curve; _eighth, _sixteenth: of the ensembles' drop, sessions 52-53)
      [[ $1 != *_half* ]] || printf 'subsection Loading\n  set Load steps = 40\nend\n'
      [[ $1 != *_quarter* ]] || printf 'subsection Loading\n  set Load steps = 80\nend\n'
      [[ $1 != *_eighth* ]] || printf 'subsection Loading\n  set Load steps = 160\nend\n'
      [[ $1 != *_sixteenth* ]] || printf 'subsection Loading\n  set Load steps = 320\nend\n'
      # _slRATE: fe2dem's default quasi-static scheme with RVEs, slow loading at the nominal strain
      # rate RATE /s, instead of [LBS]'s relaxed steps (session 54): the load steps then only set the
      # rows (every step lasts its strain over RATE); the DR settings of lbs2018.prm do not apply
      [[ ! $1 =~ _sl([0-9.]+) ]] ||
        printf 'subsection Dynamics\n  set Quasi-static scheme = slow loading\n  set Strain rate = %s\nend\nsubsection Material\n  set DEM steps per iteration = 0\nend\n' "${BASH_REMATCH[1]}"
      # _smM: 'Stability modulus' = M (the macro step's stability with RVEs, session 58)
      [[ ! $1 =~ _sm([0-9.e]+) ]] ||
        printf 'subsection Material\n  set Stability modulus = %s\nend\n' "${BASH_REMATCH[1]}"
      # _pK: the lateral pressure 1 + K ppm higher, an ensemble member (the curves after the peak
      # part by rounding alone: README, "The band width over three meshes, and what rounding does")
      [[ ! $1 =~ _p([0-9]+)$ ]] ||
        printf 'subsection Loading\n  set Pressure = %s\nend\n' "$(awk -v k="${BASH_REMATCH[1]}" 'BEGIN { printf "%.3f", 1.5e5 * (1 + k * 1e-6) }')" ;;
    mu*) printf 'subsection RVE\n  set Friction = %s\nend\n' "${1#mu}" ;;
    locked) printf 'subsection RVE\n  set Rotation = locked\nend\n' ;;
    a005|a008) printf 'subsection RVE\n  set Packing = ../../rve_templates/packings/lbs_%s\nend\n' "$1" ;;
  esac
  [[ $1 != *_op* ]] || printf 'subsection Finite elements\n  set Quadrature = one point\nend\n'
  # 2R = 5 mm, the side of one RVE (README, "Local against nonlocal"); nonlocal_MESH_RN: R = N mm
  # (_aA: Staggering = A); _le: the local elastic formulation with C_e of E = 6e6 N/m (the RVE's
  # secant modulus over the first 0.5 % of stage 2 of mesh_1x1, 5.7e6 N/m, rounded up), nu = 0.2;
  # _leE: with E N/m
  if [[ $1 == nonlocal_* ]]; then
    local radius=0.0025 alpha=1 part modulus=""
    for part in $(tr _ ' ' <<<"${1#nonlocal_*_}"); do
      case "$part" in
        R*) radius=$(awk -v r="${part#R}" 'BEGIN {print r / 1000}') ;;
        a*) alpha=${part#a} ;;
        le*) modulus=${part#le}; modulus=${modulus:-6e6} ;;
      esac
    done
    printf 'subsection Nonlocal\n  set Interaction radius = %s\n  set Staggering = %s\n' "$radius" "$alpha"
    [[ -z $modulus ]] ||
      printf '  set Formulation = local elastic\n  set Local elastic modulus = %s\n  set Local Poisson ratio = 0.2\n' "$modulus"
    printf 'end\n'
  fi
  # Particles and contact forces of every IP at 9 % axial strain (step 10 + 18)
  # for the pictures of the highest- and lowest-stress IPs.
  case "$1" in
    mesh_2x4|mesh_4x8)
      cells=${1#mesh_}
      printf 'subsection Particle dumps\n  set Points = %s\n  set Every = 28\nend\n' \
        "$(seq -s, 0 $(( ${cells%x*} * ${cells#*x} * 4 - 1 )))" ;;
  esac
}

# --mts20: the study's settings before issue 19 (README), after a case's own.
mts20_overrides() {
  printf 'subsection Material\n  set DEM steps per iteration = 20\nend\n'
  printf 'subsection Dynamic relaxation\n  set Frequency estimate = secant\n  set Predictor = none\n'
  printf '  set Boundary extension = none\nend\n'
  printf 'subsection RVE\n  set Inner start = keep\nend\n'
}

# The entries a DNS case changes in dns.prm.
dns_overrides() {
  case "$1" in
    dns_B_tol*) printf 'subsection RVE\n  set Relaxation tolerance = %s\nend\n' "${1#dns_B_tol}" ;;
    dns_B) printf 'set Particle dumps every = 2\n' ;; # the band width (band_width.py)
  esac
}

# The reference packing tiled 1x2 (A) or 2x4 (B), framed like an RVE.
make_dns_packing() {
  local name=$1 nx=$2 ny=$3
  mkdir -p "$runs/packings"
  python3 "$root/rve_templates/tile_packing.py" "$root/rve_templates/packings/lbs_ref.periodic.data" \
    "$nx" "$ny" "$runs/packings/$name.periodic.data"
  python3 "$root/rve_templates/build_frame.py" "$runs/packings/$name.periodic.data" "$name" \
    --outdir "$runs/packings" --allow-rectangular --quiet
}

# Paths in a parameter file are relative to it; the case copy sits in runs/CASE/.
absolute_paths() {
  sed -i "s#\.\./\.\./rve_templates#$root/rve_templates#; s#^set Output directory.*#set Output directory = $here/$out#" "$1"
}

run_case() {
  local c=$1 out="$runs/$1" prm status=1 cores start
  rm -rf "$out"; mkdir -p "$out"
  start=$(date +%s.%N)
  case "$c" in
    dns_*)
      local tiles=dns_B
      [[ $c != dns_A ]] || tiles=dns_A
      prm="$out/case.prm"
      { sed "s#runs/packings/dns_B#$here/$runs/packings/$tiles#" dns.prm; dns_overrides "$c"; } > "$prm"
      absolute_paths "$prm"
      cores=1
      echo "run.sh: $c: fe2dem-rve on $(awk '/rve_natoms/ {print $4}' "$runs/packings/$tiles.vars") particles"
      "$build/dealii_app/rve_driver/fe2dem-rve" "$prm" > "$out/run.log" 2>&1 && status=0 || true ;;
    *)
      prm="$out/case.prm"
      { cat lbs2018.prm; overrides "$c"; [[ $mts20 == 0 ]] || mts20_overrides
        [[ $checkpoint == 0 ]] || printf 'subsection Checkpoint\n  set Every = %s\nend\n' "$checkpoint"; } > "$prm"
      absolute_paths "$prm"
      cores=$np
      echo "run.sh: $c: fe2dem on $np ranks"
      mpirun --allow-run-as-root --oversubscribe -np "$np" "$build/dealii_app/solver/fe2dem" "$prm" \
        > "$out/run.log" 2>&1 && status=0 || true ;;
  esac
  local wall
  wall=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN {printf "%.1f", e - s}')
  echo "${c}_wall $wall s"
  echo "${c}_cores $cores 1"
  echo "${c}_completed $(( 1 - status )) bool"
  [[ $status == 0 ]] || { echo "run.sh: $c did not finish; end of $out/run.log:" >&2; tail -n 5 "$out/run.log" >&2; }
  # results/runs.csv keeps the newest row of each case (locked: DNS cases end concurrently)
  (
    flock 9
    if [[ -f $results/runs.csv ]]; then
      grep -v "^[^,]*,[^,]*,[^,]*,$c," "$results/runs.csv" > "$results/runs.csv.tmp" || true
      mv "$results/runs.csv.tmp" "$results/runs.csv"
    fi
    append_result "$results/runs.csv" "case,cores,wall_s,completed" "$c,$cores,$wall,$(( 1 - status ))"
  ) 9> "$runs/.runs.csv.lock"
}

# The multiscale cases one after the other (each uses --np ranks), then the
# DNS cases, one core each, as many at once as there are cores.
multiscale=() dns=()
for c in "${cases[@]}"; do if [[ $c == dns_* ]]; then dns+=("$c"); else multiscale+=("$c"); fi; done
for c in "${multiscale[@]}"; do run_case "$c"; done
[[ " ${dns[*]} " != *" dns_A "* ]] || make_dns_packing dns_A 1 2
[[ " ${dns[*]} " != *" dns_B"* ]] || make_dns_packing dns_B 2 4
running=0
for c in "${dns[@]}"; do
  run_case "$c" &
  running=$((running + 1))
  if [[ $running -ge $(nproc) ]]; then wait -n; running=$((running - 1)); fi
done
wait
# analyse.py reads the study's own cases (all_cases) and rewrites results/ from what runs/ holds;
# other cases (*_le*, *_op*, *_quarter, ...) have their scripts (nonlocal_study.py, band_study.py)
for c in "${cases[@]}"; do
  if [[ " ${all_cases[*]} " == *" $c "* ]]; then /usr/bin/python3 "$here/analyse.py" "$here/$base"; exit; fi
done
echo "run.sh: none of these cases is analyse.py's: results/ left as it is (nonlocal_study.py, band_study.py read them)"
