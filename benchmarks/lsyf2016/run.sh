#!/usr/bin/env bash
# [LSYF] problems 1 and 2 at full size (issue 35, items 6 and 7): lsyf_4096
# RVEs with the [LSYF] Hertz grains prepared at 416 kPa ('Initial pressure').
#   wave       problem 2: the wave column (wave_column.prm, 2 ranks), the
#              constrained modulus M of its RVE (constrained_modulus.prm; and
#              its sigma(eps) to 1 % for the nonlinear front), an
#              elastic column with that M (the same mesh and loading), and
#              wave.py's table and PNG
#   problem1   problem 1: one element in triaxial compression and in simple
#              shear in explicit dynamics against fe2dem-rve on the same
#              packing and path (problem1_*_{dynamic,rve}.prm), and the
#              triaxial one quasi-static: by slow loading, the default
#              (problem1_triaxial_slow_loading.prm), and by dynamic
#              relaxation in 8 steps against the single RVE in the same
#              relaxed steps and continuously
#              (problem1_triaxial_{quasi_static,rve_stepped}.prm)
#   modulus    the RVE's constrained modulus under a sinusoidal strain of
#              amplitude 1e-4 at 2.5 and 10 kHz (constrained_modulus.prm
#              driven by a sine; lsyf_4096 and lsyf_1000, each with the
#              default 'Inner start' (affine in dynamics) and with keep, and
#              with keep also with the proportional frame servo and without
#              Cundall damping at 10 kHz): results/dynamic_modulus.txt
#   problem1_ensemble  the triaxial dynamic element and its single RVE at
#              0.5 /s x 0.98, 1.02, 1.04 as well: the means of four runs each
#              (results/problem1_ensemble.txt)
#   problem4   problem 4 (issue 37): plane-strain biaxial compression of
#              40 x 80 x 5 mm with lsyf_300 RVEs (problem4.prm) on the meshes
#              4x8, 6x12, 8x16 and 10x20 (one-point elements), local, and
#              nonlocal (Wendland's weight, R = 11.8 mm: the half-value width
#              of [LSYF]'s bell with 2R = 13.5 mm), the local elastic
#              formulation on 6x12-10x20 and two single runs, 2 ranks each;
#              also 2x4 local at 4 and 1 /s (the rate's effect); a run
#              that stops (an RVE fails) keeps its converged rows and the
#              others go on; problem4.py's tables and PNGs
#   problem3   problem 3 (issue 37): simple shear of 118 x 50.6 x 12.7 mm on
#              12x5x1 one-point elements with lsyf_300 RVEs, one of them
#              lsyf_300_weak (problem3.prm), local and nonlocal with R = 15
#              and 25 mm, the local elastic formulation with R = 15-25 mm;
#              local on 12x5 at two more macro steps; the problem3_band
#              and problem3_scaled cases too; 2 ranks each; problem3.py's tables and PNGs
#   problem3_band  problem 3 on 12x10x1 (local, local elastic R = 10-20 mm, E = 0.5 and
#              2 MPa) and on 12x5 with E = 2 MPa: the band against R and the mesh
#   problem3_scaled  problem 3 with E = 2 MPa at R = 2 element heights: R = 20, 6.75
#              and 5 mm on 12x5, 12x15, 12x20 (the band against R, mesh and seed scaled with R),
#              and R = 15 mm on 12x10 with the seed a region of one 12x5 element
#   problem3_fixed_r  problem 3 at a fixed R = 10 mm (E = 2 MPa) on 12x10 and 12x20, the seed
#              a region of one 12x5 element: the band over meshes at a fixed R
#   problem3_own_volume  the two problem3_fixed_r cases with 'Volume change' = own (each RVE's
#              volume its element's), R = 15 mm on 12x20 with it, and session 36's one-IP seed at
#              R = 15 mm on 12x10 with it, and R = 5 mm on 12x20: about 150 min alone
#   problem3_converged  the 12x10 own-volume case at half and a quarter of the macro step (1 and
#              0.5 us), at 1 us with servo checks of 5 DEM steps, and at half the rate (2 /s): is
#              the banded answer converged in both? About 105 min alone
#   problem3_perturbed  the same 12x10 case at the default step and rate with the top's
#              pressure 1-4 parts per million higher, and at the quarter step with 1-3: how far
#              the band's width scatters at one step (session 42). About 140 min alone
#   problem3_fine_step  the same ensemble (unperturbed, +1-3 ppm) at 0.2 us, 2 DEM steps per macro
#              step with servo checks of 2: does the band's mean width settle in the step? (session
#              43). About 33 min per run alone, 130 min in all
#   problem3_against_r  the 12x10 own-volume ensemble (unperturbed, +1-3 ppm) at the default step
#              with R = 15 and 20 mm beside the R = 10 mm one: the band's width against R as the
#              means of ensembles (session 44; those radii turned out hourglass-dominated with
#              own volume, README). About 11 min per run alone, 90 min in all
#   problem3_against_r_averaged  the same with 'Volume change' = averaged at R = 10, 15, 20 mm
#              (unperturbed, +1, +2 ppm; session 44). About 11 min per run alone
#   problem3_own_half_step  the own-volume runs at R = 20 and 15 mm on 12x10 at half the default
#              step (1 us), and R = 20 mm +1 ppm: is their hourglass-dominated state the step's?
#              (session 44; 22 min each)
#   problem3_against_r_half_step  the own-volume ensembles at R = 15 and 20 mm at 1 us (+1-3 ppm,
#              beside problem3_own_half_step's runs): the width against R as ensemble means at
#              a step where they are equilibria (session 45). About 17 min per run alone, 85 min in all
#   problem3_last_check  the own-volume runs at R = 20 and 15 mm on 12x10 at the default 2 us with
#              session 45's build (the last check's stress): 18-19 min each alone (measured)
#   problem3_half_rate  the same two runs at half the rate (2 /s): is the width at 4 /s the
#              quasi-static one at these radii? (session 46; 35-37 min each alone)
#   problem3_hourglass_probe  the R = 20 mm own-volume case for its first 1 % of shear (two load
#              steps) without the seed, without C_e, with the averaged volume and at 1 us: which of
#              them makes the hourglass forces do the work (session 44; 1.5-3 min each)
#   problem4_rates  problem4.prm's RVE alone in plane strain
#              (problem4_element.prm) at 4, 2, 1 and 0.5 /s to 8 %
#   cv_shear   problem 3's packings (lsyf_300, lsyf_300_weak) sheared at constant volume, fe2dem-rve
#              against YADE's periodic cell with the same Hertz grains (benchmarks/yade_periodic/
#              run_3d.sh shear_cv), and the weak RVE replayed along its averaged F (cv_shear.py)
#   macro_step one element at 4 /s with the macro step and the RVE's
#              'Check interval' varied (problems 3 and 4's RVEs), and problem
#              1's shear element with lsyf_300 at three macro steps against
#              fe2dem-rve's continuous drive (macro_step.py)
#   problem3 --full, problem4 --full, all --full   the same cases at the
#              paper's size, lsyf_4096 RVEs (problem 3's weak one made by
#              weaken_packing.py into results/full/), as SLURM jobs through
#              scripts/slurm/fe2dem.sbatch (16 ranks each) if a SLURM
#              controller answers, else the sbatch commands are printed;
#              results/full/CASE/
#   tables     the comparison tables from what exists
# Each case in results/CASE/ (the parameter file, log, outputs); a case whose
# result exists and whose parameter file is unchanged is not run again.
#
#   run.sh BUILD wave|problem1|problem1_ensemble|modulus|problem3|problem3_band|problem3_scaled|problem3_fixed_r|problem3_own_volume|problem3_converged|problem3_perturbed|problem3_fine_step|problem3_against_r|problem3_against_r_averaged|problem3_own_half_step|problem3_against_r_half_step|problem3_last_check|problem3_half_rate|problem3_hourglass_probe|problem4|problem4_rates|macro_step|cv_shear|tables|all [--full]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
[[ $# -eq 2 || ( $# -eq 3 && $3 == --full ) ]] || { sed -n '2,/^#   run.sh BUILD/p' "$0"; exit 2; }
build="$(cd "$1" && pwd)"
what=$2
full=${3:-}
results="$here/results"
py=/usr/bin/python3
source "$here/../common.sh"
rebase() { sed "s#\.\./\.\./rve_templates#$root/rve_templates#" "$@"; }
# time_step_edit DT: the sed expression that sets the macro step of a parameter file with
# 'Analysis = dynamic' (subsection Dynamics) to DT s; check_interval_edit N: the RVE's 'Check
# interval' from 10 to N DEM steps (a macro step must be whole checks)
time_step_edit() { echo "s#^  set Analysis = dynamic#  set Analysis = dynamic\n  set Time step = $1#"; }
check_interval_edit() { echo "s#set Check interval        = 10#set Check interval        = $1#"; }
mpirun_np() {
  local n=$1; shift
  if [[ $n -eq 1 ]]; then "$@"; else mpirun --allow-run-as-root --oversubscribe -np "$n" "$@"; fi
}

# clear_run DIR FILE: remove an earlier run's outputs from DIR but its input FILE
clear_run() { find "$1" -mindepth 1 -maxdepth 1 ! -name "$2" -exec rm -rf {} +; }
# run_macro NAME PRM NP [sed expression]: fe2dem into results/NAME/out; a
# stored run is reused only if its macro.prm is the one generated now
# (needs_run, ../common.sh), else it is run again
run_macro() {
  local dir="$results/$1" prm=$2 np=$3 edit=${4:-}
  needs_run "$dir/macro.prm" "$dir/wall_s" < <(rebase "$prm" | sed "$edit") || return 0
  clear_run "$dir" macro.prm
  local t0=$SECONDS
  (cd "$dir" && mpirun_np "$np" "$build/dealii_app/solver/fe2dem" macro.prm > log 2>&1)
  echo $((SECONDS - t0)) > "$dir/wall_s"
  rm -rf "$dir/out/checkpoints" "$dir"/out/*.vtu "$dir"/out/*.pvd
  echo "$1: $(cat "$dir/wall_s") s on $np rank(s)"
}
# run_rve NAME PRM [sed expression]: fe2dem-rve into results/NAME (reused as run_macro's)
run_rve() {
  local dir="$results/$1" prm=$2 edit=${3:-}
  needs_run "$dir/case.prm" "$dir/wall_s" < <(rebase "$prm" | sed "$edit") || return 0
  clear_run "$dir" case.prm
  local t0=$SECONDS
  "$build/dealii_app/rve_driver/fe2dem-rve" "$dir/case.prm" --output-directory "$dir" > "$dir/run.log"
  echo $((SECONDS - t0)) > "$dir/wall_s"
  echo "$1: $(cat "$dir/wall_s") s"
}

wave() {
  run_macro constrained_modulus "$here/constrained_modulus.prm" 1
  local M
  M=$($py "$here/wave.py" modulus "$results/constrained_modulus/out")
  # the elastic column: the same mesh, density and loading, neo-Hookean with
  # lambda + 2 mu = M and nu = 0.2 (only M matters in uniaxial strain)
  local mu lambda
  mu=$(awk -v M="$M" 'BEGIN {printf "%.6g", M / (2 + 2 * 0.2 / 0.6)}')
  lambda=$(awk -v M="$M" -v mu="$mu" 'BEGIN {printf "%.6g", M - 2 * mu}')
  local elastic="s/^  set Type              = RVE/  set Type              = neo-Hookean\n  set Shear modulus     = $mu\n  set Lame lambda       = $lambda/; s/^  set Initial pressure .*//"
  local small="s#-1e-4 \* sin#-1e-6 * sin#"
  # the same RVE's sigma_yy(eps_yy) to 1 % at 0.5 /s: the speeds of a nonlinear front
  local ramp="s#-1e-6 \* t / 0.004#-1e-4 * t / 0.02#; s#set End time   = 0.004#set End time   = 0.02#; s#set Load steps = 20#set Load steps = 80#; s#^  set Analysis     = dynamic#  set Analysis     = dynamic\n  set Time step    = 1e-6#"
  run_macro constrained_modulus_1_percent "$here/constrained_modulus.prm" 1 "$ramp"
  run_macro wave_column "$here/wave_column.prm" 2
  run_macro wave_column_elastic "$here/wave_column.prm" 1 "$elastic"
  # the same column driven at 1 um: a linear wave (strain amplitude 1e-4)
  run_macro wave_column_1um "$here/wave_column.prm" 2 "$small"
  run_macro wave_column_1um_elastic "$here/wave_column.prm" 1 "$elastic; $small"
  # the 0.1 mm column at half the macro step (5 DEM steps of 1e-7 s, a check each)
  local half="s#^  set Time step = 1e-6#  set Time step = 5e-7#; s#set Check interval        = 10#set Check interval        = 5#"
  run_macro wave_column_half_step "$here/wave_column.prm" 2 "$half"
  wave_table
}
wave_table() {
  local r=$results
  {
    echo "## driven at 0.1 mm ([LSYF])"
    $py "$here/wave.py" column "$r/constrained_modulus/out" "$r/wave_column/out" "$r/wave_column_elastic/out" \
      "$r/wave_column.png" 1e-4 "$r/constrained_modulus_1_percent/out"
    echo "## driven at 0.1 mm: against a 1D bar of the same discretisation with the RVE's own sigma(eps) (column_1d.py)"
    $py "$here/column_1d.py" table "$r/constrained_modulus/out" "$r/wave_column/out" "$r/wave_column_elastic/out" \
      "$r/constrained_modulus_1_percent/out" 1e-4
    echo "## driven at 0.1 mm, half the macro step (5e-7 s)"
    [[ -f "$r/wave_column_half_step/out/history.h5" ]] &&
      $py "$here/wave.py" column "$r/constrained_modulus/out" "$r/wave_column_half_step/out" "$r/wave_column_elastic/out" \
        "$r/wave_column_half_step.png" 1e-4 "$r/constrained_modulus_1_percent/out"
    echo "## driven at 1 um (linear)"
    $py "$here/wave.py" column "$r/constrained_modulus/out" "$r/wave_column_1um/out" "$r/wave_column_1um_elastic/out" \
      "$r/wave_column_1um.png" 1e-6
    echo "## driven at 1 um: against the 1D bars"
    $py "$here/column_1d.py" table "$r/constrained_modulus/out" "$r/wave_column_1um/out" "$r/wave_column_1um_elastic/out" \
      "$r/constrained_modulus_1_percent/out" 1e-6
  } 2>&1 | tee "$r/wave_column.txt"
}

# the sine instead of constrained_modulus.prm's ramp: FREQ Hz over PERIODS periods, a row every 5 us
sine() {
  local f=$1 periods=$2
  local end; end=$(awk -v f="$f" -v n="$periods" 'BEGIN {printf "%.6g", n / f}')
  local rows; rows=$(awk -v e="$end" 'BEGIN {printf "%d", e / 5e-6 + 0.5}')
  echo "s#-1e-6 \* t / 0.004#-1e-6 * sin(2 * pi * $f * t)#; s#set End time   = 0.004#set End time   = $end#; s#set Load steps = 20#set Load steps = $rows#; s#^  set Analysis     = dynamic#  set Analysis     = dynamic\n  set Time step    = 1e-6#"
}
modulus() {
  local prm="$here/constrained_modulus.prm"
  local prop="s#hertz 1, youngs#timed_servo proportional, hertz 1, youngs#"
  local nodamp="s#^\(  set Friction .*\)#\1\n  set Local damping force  = 0\n  set Local damping moment = 0#"
  local small="s#packings/lsyf_4096#packings/lsyf_1000#"
  local keep="s#^\(  set Friction .*\)#\1\n  set Inner start = keep#"
  local c
  # the default ('Inner start' = auto: affine in dynamics) and keep
  for c in "lsyf_4096;" "lsyf_4096_keep;$keep" "lsyf_1000;$small" "lsyf_1000_keep;$small; $keep"; do
    run_macro "modulus_${c%%;*}_2.5kHz" "$prm" 1 "$(sine 2.5e3 2); ${c#*;}"
    run_macro "modulus_${c%%;*}_10kHz" "$prm" 1 "$(sine 1e4 3); ${c#*;}"
  done
  run_macro modulus_lsyf_4096_keep_10kHz_proportional "$prm" 1 "$(sine 1e4 3); $keep; $prop"
  run_macro modulus_lsyf_4096_keep_10kHz_no_damping "$prm" 1 "$(sine 1e4 3); $keep; $nodamp"
  modulus_table
}
modulus_table() {
  local c
  {
    echo "# case M_dyn[MPa] mean_sigma_yy[Pa] phase_lag[deg] (fit over the last period(s))"
    for c in lsyf_4096_2.5kHz lsyf_4096_10kHz lsyf_4096_keep_2.5kHz lsyf_4096_keep_10kHz \
      lsyf_4096_keep_10kHz_proportional lsyf_4096_keep_10kHz_no_damping \
      lsyf_1000_2.5kHz lsyf_1000_10kHz lsyf_1000_keep_2.5kHz lsyf_1000_keep_10kHz; do
      local d="$results/modulus_$c/out" f=1e4 t=1e-4
      [[ $c == *2.5kHz* ]] && { f=2.5e3; t=4e-4; }
      [[ -f "$d/history.h5" ]] || continue
      echo "$c $($py "$here/dynamic_modulus.py" "$d" $f $t | awk '{print $2}' | head -3 | tr '\n' ' ')"
    done
  } | tee "$results/dynamic_modulus.txt"
}

problem1() {
  run_rve problem1_triaxial_rve "$here/problem1_triaxial_rve.prm" &
  run_macro problem1_triaxial_dynamic "$here/problem1_triaxial_dynamic.prm" 1
  wait
  run_rve problem1_shear_rve "$here/problem1_shear_rve.prm" &
  run_macro problem1_shear_dynamic "$here/problem1_shear_dynamic.prm" 1
  wait
  run_rve problem1_triaxial_rve_stepped "$here/problem1_triaxial_rve_stepped.prm" &
  run_macro problem1_triaxial_quasi_static "$here/problem1_triaxial_quasi_static.prm" 1
  run_macro problem1_triaxial_slow_loading "$here/problem1_triaxial_slow_loading.prm" 1
  wait
  problem1_tables
}
# problem 1, triaxial, as an ensemble of four rates 2-4 % apart: after the
# plateau single runs drop at different strains
problem1_ensemble() {
  local f end rate
  for f in 0.98 1.02 1.04; do
    end=$(awk -v f="$f" 'BEGIN {printf "%.6g", 0.04 / f}')
    rate=$(awk -v f="$f" 'BEGIN {printf "%.6g", 0.5 * f}')
    run_rve "problem1_triaxial_rve_$rate" "$here/problem1_triaxial_rve.prm" "s#^\(  set Strain rate *=\).*#\1 $rate#" &
    run_macro "problem1_triaxial_dynamic_$end" "$here/problem1_triaxial_dynamic.prm" 1 \
      "s#set End time   = 0.04#set End time   = $end#; s#-2e-4 \* t / 0.04#-2e-4 * t / $end#"
    wait
  done
  problem1_ensemble_table
}
problem1_ensemble_table() {
  local f dyn=("$results/problem1_triaxial_dynamic/out/history.h5") ref=("$results/problem1_triaxial_rve/rve.csv") IFS=,
  for f in 0.98 1.02 1.04; do # the runs of problem1_ensemble
    dyn+=("$results/problem1_triaxial_dynamic_$(awk -v f="$f" 'BEGIN {printf "%.6g", 0.04 / f}')/out/history.h5")
    ref+=("$results/problem1_triaxial_rve_$(awk -v f="$f" 'BEGIN {printf "%.6g", 0.5 * f}')/rve.csv")
  done
  [[ -f "${dyn[3]}" && -f "${ref[3]}" ]] || return 0
  {
    echo "# [LSYF] problem 1, triaxial: the mean of four dynamic elements against the mean of four single RVEs (0.5 /s x 1, 0.98, 1.02, 1.04)"
    $py "$root/tests/compare_triaxial.py" "${dyn[*]}" "${ref[*]}" 3 0.02 || true
    echo "## each single RVE against the single RVEs' mean"
    local r d
    for r in "${ref[@]}"; do $py "$root/tests/compare_triaxial.py" "$r" "${ref[*]}" 3 0.02 | tail -1 || true; done
    echo "## each dynamic element against the single RVEs' mean"
    for d in "${dyn[@]}"; do $py "$root/tests/compare_triaxial.py" "$d" "${ref[*]}" 3 0.02 | tail -1 || true; done
  } | tee "$results/problem1_ensemble.txt"
}
problem1_tables() {
  {
    echo "# [LSYF] problem 1, triaxial: dynamic one element against fe2dem-rve (rows every 0.25 %)"
    $py "$root/tests/compare_triaxial.py" "$results/problem1_triaxial_dynamic/out/history.h5" \
      "$results/problem1_triaxial_rve/rve.csv" 3 0.02 || true
    echo "# [LSYF] problem 1, simple shear: dynamic one element against fe2dem-rve"
    $py "$root/tests/compare_rve_stress.py" "$results/problem1_shear_dynamic/out/history.h5" \
      "$results/problem1_shear_rve/rve.csv" 3 0.02 0.02 || true
    echo "# [LSYF] problem 1, triaxial, quasi-static one element against fe2dem-rve stepped (the same 0.25 % steps)"
    $py "$root/tests/compare_triaxial.py" "$results/problem1_triaxial_quasi_static/out/history.h5" \
      "$results/problem1_triaxial_rve_stepped/rve.csv" 3 0.02 || true
    echo "# [LSYF] problem 1, triaxial, quasi-static one element against fe2dem-rve continuous"
    $py "$root/tests/compare_triaxial.py" "$results/problem1_triaxial_quasi_static/out/history.h5" \
      "$results/problem1_triaxial_rve/rve.csv" 3 0.02 || true
    echo "# triaxial, slow loading (fe2dem's default quasi-static scheme) vs the continuous single RVE"
    $py "$root/tests/compare_triaxial.py" "$results/problem1_triaxial_slow_loading/out/history.h5" \
      "$results/problem1_triaxial_rve/rve.csv" 3 0.02 || true
    # before session 24 fe2dem-rve's continuous drive and slow loading ran 'Inner
    # start' = keep (results/inner_keep); the dynamic element has always run affine
    local k="$results/inner_keep"
    echo "# with keep: triaxial, dynamic one element against fe2dem-rve (keep)"
    $py "$root/tests/compare_triaxial.py" "$results/problem1_triaxial_dynamic/out/history.h5" \
      "$k/problem1_triaxial_rve/rve.csv" 3 0.02 || true
    echo "# with keep: simple shear, dynamic one element against fe2dem-rve (keep)"
    $py "$root/tests/compare_rve_stress.py" "$results/problem1_shear_dynamic/out/history.h5" \
      "$k/problem1_shear_rve/rve.csv" 3 0.02 0.02 || true
    echo "# with keep: triaxial, slow loading (keep) vs the continuous single RVE (keep)"
    $py "$root/tests/compare_triaxial.py" "$k/problem1_triaxial_slow_loading/out/history.h5" \
      "$k/problem1_triaxial_rve/rve.csv" 3 0.02 || true
  } | tee "$results/problem1.txt"
}

mkdir -p "$results"
# Problem 4's cases: NAME CELLS_X CELLS_Y RADIUS (the same here and with --full)
problem4_cases=("problem4_local_4x8 4 8 0" "problem4_R11.8_4x8 4 8 0.0118" "problem4_local_6x12 6 12 0"
                "problem4_R11.8_6x12 6 12 0.0118" "problem4_local_8x16 8 16 0" "problem4_R11.8_8x16 8 16 0.0118"
                "problem4_local_10x20 10 20 0" "problem4_R11.8_10x20 10 20 0.0118")
# ... and in the local elastic formulation (user guide, 'Nonlocal operator'), NAME CELLS_X CELLS_Y
# RADIUS E: with C_e's E = 50 MPa at [LSYF]'s radius on 8x16 and with R = 20 mm on 4x8 both rose
# far above the RVE's strength (README, 'Problem 4'), so the other meshes were not run; E = 5 MPa
# is the tenth, run on the three meshes whose IPs R reaches (6x12, 8x16, 10x20; on 4x8 the
# neighbours weigh 0.002), with the local and total-strain 10x20 beside it (session 30); E = 1 MPa
# (C_e's shear modulus about twice the band's softening in shear of the local runs) on the same
# meshes and with R = 8 and 16 mm on 10x20, for the band against R, and E = 2 and 0.5 MPa on 10x20
# for the band against C_e (session 31)
problem4_le_cases=("problem4_R11.8_le50_8x16 8 16 0.0118 5e7" "problem4_R20_le50_4x8 4 8 0.02 5e7"
                   "problem4_R11.8_le5_8x16 8 16 0.0118 5e6" "problem4_R11.8_le5_6x12 6 12 0.0118 5e6"
                   "problem4_R11.8_le5_10x20 10 20 0.0118 5e6" "problem4_R11.8_le1_8x16 8 16 0.0118 1e6"
                   "problem4_R11.8_le1_6x12 6 12 0.0118 1e6" "problem4_R11.8_le1_10x20 10 20 0.0118 1e6"
                   "problem4_R8_le1_10x20 10 20 0.008 1e6" "problem4_R16_le1_10x20 10 20 0.016 1e6"
                   "problem4_R11.8_le2_10x20 10 20 0.0118 2e6" "problem4_R11.8_le0.5_10x20 10 20 0.0118 5e5")
# local_elastic E: the sed expression, after the radius is set, of the local elastic formulation with
# C_e of Young's modulus E (Pa) and nu = 0.2 (README, problems 3 and 4): E = 5.84e8 is
# [LSYF]'s effective elastic modulus (physics.md 3.2; P-wave modulus 649 MPa against the measured
# 668-703 MPa of dynamic_modulus.txt), E = 5e7 the order of the RVE's secant loading stiffness to
# its peak (problem 4's local 4x8 specimen: 98 MPa to 1 %; problem 3: G = 9-18 MPa to 1-2 % of shear)
local_elastic() {
  echo "s/^\(  set Interaction radius = .*\)\$/\1\n  set Formulation = local elastic\n  set Local elastic modulus = $1\n  set Local Poisson ratio = 0.2/"
}
# problem4_edit CELLS_X CELLS_Y RADIUS PACKING: problem4.prm's substitutions
problem4_edit() { echo "s/CELLS_X/$1/; s/CELLS_Y/$2/; s/RADIUS/$3/; s#packings/PACKING#packings/$4#"; }
# band_case NAME PRM [sed expression]: run_macro on 2 ranks; a run that stops (an RVE in a band
# failed: a lost particle, an overlap beyond max_overlap) keeps its rows and the next case runs
band_case() {
  run_macro "$1" "$2" 2 "${3:-}" || true
  if grep -q "the run stopped after writing" "$results/$1/log"; then
    echo "$1: stopped before the end (results/$1/log); its converged rows are kept"
  fi
}
# problem4_case NAME CELLS_X CELLS_Y RADIUS [sed expression]
problem4_case() { band_case "$1" "$here/problem4.prm" "$(problem4_edit "$2" "$3" "$4" lsyf_300); ${5:-}"; }
problem4() {
  problem4_case problem4_2x4_rate4 2 4 0
  # 1 /s with the macro step of 4 /s, 1 us = 10 DEM steps (one check): the default picks 2 us here,
  # at which the RVEs' stress jumps from row to row (README, 'The rate, and the macro step')
  problem4_case problem4_2x4_rate1 2 4 0 "s#set End time   = 0.015#set End time   = 0.06#; s#-4.8e-3 \* t / 0.015#-4.8e-3 * t / 0.06#; $(time_step_edit 1e-6)"
  local c
  for c in "${problem4_cases[@]}"; do problem4_case $c; done
  local name x y radius modulus
  for c in "${problem4_le_cases[@]}"; do
    read -r name x y radius modulus <<< "$c"
    problem4_case "$name" "$x" "$y" "$radius" "$(local_elastic "$modulus")"
  done
  problem4_table
}
# Problem 3's cases: NAME CELLS_X CELLS_Y RADIUS [E]; with E, the local elastic formulation with C_e
# of Young's modulus E (local_elastic). On [LSYF]'s 12x5 mesh: local, R = 15 and 25 mm (total
# strain), and E = 5.84e8 and 5e7 Pa (session 29), which held every element to one strain, no band;
# E = 5e5 Pa (session 33): C_e's shear modulus 2.6-3.1 times the band's softening in shear of the
# local and R = 15 mm runs (H_s = 0.068-0.081 MPa, problem3.py), the ratio of problem 4's band about
# R wide, with R = 15, 20, 25 mm
problem3_cases=("problem3_R0 12 5 0" "problem3_R0.015 12 5 0.015" "problem3_R0.025 12 5 0.025"
                "problem3_R0.025_le584 12 5 0.025 5.84e8" "problem3_R0.025_le50 12 5 0.025 5e7"
                "problem3_R0.015_le0.5 12 5 0.015 5e5" "problem3_R0.02_le0.5 12 5 0.02 5e5"
                "problem3_R0.025_le0.5 12 5 0.025 5e5")
# ... and the local runs of the macro step (README, 'The rate, and the macro step'), NAME CELLS_X
# CELLS_Y TIME_STEP: 12x5 at 2 us (at which the RVEs' stress jumped before session 34) and at 1 us
# (its default is 5 us = 50 DEM steps); not in --full
problem3_step_cases=("problem3_R0_dt2us 12 5 2e-6" "problem3_R0_dt1us 12 5 1e-6")
# ... and on 12x10 (elements 9.8 x 5.1 mm: the band runs along x, so its width across y is what the
# mesh must resolve; 24x10 costs twice as much for the same rows) at the default step (2 us = 20 DEM
# steps): local, the local elastic formulation of E = 0.5 MPa at R = 20 and 10 mm, and, as at
# R = 20 mm the elements took an element-scale pattern that C_e of 1.5 H_s hardly resisted, of
# E = 2 MPa (6 H_s) at R = 10 and 15 mm, and that at R = 15 mm on 12x5 too, for the band against R
# and the mesh (session 35; session 33's local 24x10 run stopped on an overlap at load step 10 with
# the old frame motion)
problem3_band_cases=("problem3_R0_12x10 12 10 0" "problem3_R0.02_le0.5_12x10 12 10 0.02 5e5"
                     "problem3_R0.01_le0.5_12x10 12 10 0.01 5e5" "problem3_R0.01_le2_12x10 12 10 0.01 2e6"
                     "problem3_R0.015_le2_12x10 12 10 0.015 2e6" "problem3_R0.015_le2 12 5 0.015 2e6")
# ... and the band against R with the mesh and the seed scaled with R (session 36): E = 2 MPa at
# R = 2 element heights (the window where the 12x10 elements followed their RVEs), R = 20 mm on
# 12x5 and 6.75 mm ([LSYF]'s 2R = 13.5 mm) on 12x15 (the weak RVE is one element, so the seed's
# height scales with R too; the specimen does not), 5 mm on 12x20 (its 2.5 mm elements bring the
# default step to 1 us: about 70 min here); R = 10 mm on 12x10 is problem3_band's
problem3_scaled_cases=("problem3_R0.02_le2 12 5 0.02 2e6" "problem3_R0.00675_le2_12x15 12 15 0.00675 2e6"
                       "problem3_R0.005_le2_12x20 12 20 0.005 2e6")
# ... and the seed as a region of a fixed size (subsection Imperfection, 'Size'): the one 12x5
# element around 'Point' (two IPs on 12x10), at R = 15 mm with E = 2 MPa on 12x10, where one weak IP
# (a share 0.46 of its own average, Wendland's weights) lost its pressure (session 36)
seed_box='s#^  set Point   = .*#&\n  set Size    = 0.0098, 0.0101, 0.0127#'
problem3_seed_box_cases=("problem3_R0.015_le2_12x10_box 12 10 0.015 2e6")
# ... and the band at a fixed R over meshes (session 38): R = 10 mm, E = 2 MPa, the seed box, on
# 12x10 (R = 2 element heights, the seed two IPs; 30 min here) and 12x20 (4 heights, four IPs; the
# default step is 1 us there: 50 min here)
problem3_fixed_r_cases=("problem3_R0.01_le2_12x10_box 12 10 0.01 2e6" "problem3_R0.01_le2_12x20_box 12 20 0.01 2e6")
# ... and the same two with each RVE's volume change its own element's ('Volume change' = own,
# session 39): only the isochoric part of the motion averaged; and R = 15 mm on 12x20 (the band
# against R on one mesh; R reaches the next column of IPs, 9.83 mm away, there), and R = 5 mm on
# 12x20 (session 41: the third radius on that mesh; R reaches only the rows above and below)
problem3_own_volume_cases=("problem3_R0.01_le2_12x20_box_own 12 20 0.01 2e6" "problem3_R0.01_le2_12x10_box_own 12 10 0.01 2e6"
                           "problem3_R0.015_le2_12x20_box_own 12 20 0.015 2e6" "problem3_R0.005_le2_12x20_box_own 12 20 0.005 2e6")
# ... and session 36's one-IP seed at R = 15 mm on 12x10 (its weak RVE lost its pressure, 330 -> 47 kPa)
# with it: no seed box
problem3_own_volume_one_ip_cases=("problem3_R0.015_le2_12x10_own 12 10 0.015 2e6")
own_volume='s/^\(  set Interaction radius = .*\)$/\1\n  set Volume change = own/'
# ... and problem3_own_volume's 12x10 case (R = 10 mm, the seed box) at half its macro step (1 us =
# 10 DEM steps; the default picks 2 us) and at half the rate (2 /s, to 8 % in 40 ms, the default
# step): the banded answer's convergence in the two numerical parameters (session 41)
half_step=$(time_step_edit 1e-6)
half_rate='s#set End time   = 0.02#set End time   = 0.04#; s#t / 0.02#t / 0.04#g'
# ... and at a quarter of the macro step (0.5 us = 5 DEM steps; a macro step is whole servo checks, so
# the check is 5 DEM steps here, not 10: problem 3's element alone gave mean ratios 0.535 and 0.540
# with checks of 5 and 10 at 2 us, results/macro_step.txt): does the width's change from 2 to 1 us settle?
quarter_step="$(time_step_edit 5e-7); $(check_interval_edit 5)"
# ... and half the step with checks of 5 (session 41, after the quarter step widened the band): is
# that the step's or the check's?
check5=$(check_interval_edit 5)
# own_12x10 [R]: the edits of that case (problem3_own_volume's 12x10 case) at interaction radius R
# (default 0.01 m), the base of problem3_converged, problem3_perturbed and the R studies below
own_12x10() { echo "$(problem3_edit 12 10 "${1:-0.01}" 2e6); $seed_box; $own_volume"; }
problem3_converged() {
  local own
  own=$(own_12x10)
  band_case problem3_R0.01_le2_12x10_box_own_dt1us "$here/problem3.prm" "$own; $half_step"
  band_case problem3_R0.01_le2_12x10_box_own_rate2 "$here/problem3.prm" "$own; $half_rate"
  band_case problem3_R0.01_le2_12x10_box_own_dt0.5us "$here/problem3.prm" "$own; $quarter_step"
  band_case problem3_R0.01_le2_12x10_box_own_dt1us_ci5 "$here/problem3.prm" "$own; $half_step; $check5"
}
# ... and the same case at the default step and rate with the top's pressure (Boundary condition 3)
# 416 kPa times 1 + k 1e-6, k = 1..4 (session 42): the runs differ from the reference in the sixth
# digit of one load, so what they scatter by is what the DEM's sensitivity to its start makes of
# it, the floor under any width difference between runs at one step; and the quarter-step case
# (0.5 us, checks of 5) with k = 1..3: is the step's widening more than that scatter?
top_pressure_edit() { echo "s#set Function   = 4.16e5#set Function   = $(awk -v k="$1" 'BEGIN { printf "%.3f", 4.16e5 * (1 + k * 1e-6) }')#"; }
problem3_perturbed() {
  local own k
  own=$(own_12x10)
  for k in 1 2 3 4; do
    band_case "problem3_R0.01_le2_12x10_box_own_p$k" "$here/problem3.prm" "$own; $(top_pressure_edit $k)"
  done
  for k in 1 2 3; do
    band_case "problem3_R0.01_le2_12x10_box_own_dt0.5us_p$k" "$here/problem3.prm" "$own; $quarter_step; $(top_pressure_edit $k)"
  done
}
# ... and the same ensemble at a tenth of the default step (0.2 us = 2 DEM steps, servo checks of 2;
# session 43): after 2 -> 0.5 us widened the band by 4.6 +- 2.1 mm, does the mean width settle? The
# unperturbed run first, then k = 1..3
tenth_step="$(time_step_edit 2e-7); $(check_interval_edit 2)"
problem3_fine_step() {
  local own k
  own=$(own_12x10)
  band_case problem3_R0.01_le2_12x10_box_own_dt0.2us "$here/problem3.prm" "$own; $tenth_step"
  for k in 1 2 3; do
    band_case "problem3_R0.01_le2_12x10_box_own_dt0.2us_p$k" "$here/problem3.prm" "$own; $tenth_step; $(top_pressure_edit $k)"
  done
}
# ... and the default-step ensemble (unperturbed, +1-3 ppm) at R = 15 and 20 mm (session 44): the width
# against R from ensemble means, since one run's width is one draw (sd 1.4-2.3 mm at R = 10 mm). The
# two radii alternate so that, stopped early, both ensembles have the same number of runs
problem3_against_r() {
  local k r edit
  for k in 0 1 2 3; do
    for r in 0.015 0.02; do
      edit=$(own_12x10 "$r")
      if [[ $k -eq 0 ]]; then
        band_case "problem3_R${r}_le2_12x10_box_own" "$here/problem3.prm" "$edit"
      else
        band_case "problem3_R${r}_le2_12x10_box_own_p$k" "$here/problem3.prm" "$edit; $(top_pressure_edit $k)"
      fi
    done
  done
}
# ... and with the averaged volume ([LSYF]'s rule, the default), after the own-volume runs at R = 15
# and 20 mm on 12x10 were hourglass-dominated (the hourglass forces did more work than the
# stresses; README, problem 3, session 44): R = 20 mm unperturbed, then +1 and +2 ppm at each R
problem3_against_r_averaged() {
  local k r edit
  band_case problem3_R0.02_le2_12x10_box "$here/problem3.prm" "$(problem3_edit 12 10 0.02 2e6); $seed_box"
  for k in 1 2; do
    for r in 0.01 0.015 0.02; do
      edit="$(problem3_edit 12 10 $r 2e6); $seed_box; $(top_pressure_edit $k)"
      band_case "problem3_R${r}_le2_12x10_box_p$k" "$here/problem3.prm" "$edit"
    done
  done
}
# ... and the own-volume runs at R = 20 and 15 mm at half the default step: two load steps of the R =
# 20 mm case at 1 us stayed at 1.6 % of hourglass work where 2 us had 54 % (session 44); then R = 20 mm
# with the top's pressure 1 ppm higher
problem3_own_half_step() {
  local r
  for r in 0.02 0.015; do
    band_case "problem3_R${r}_le2_12x10_box_own_dt1us" "$here/problem3.prm" \
      "$(own_12x10 "$r"); $half_step"
  done
  band_case problem3_R0.02_le2_12x10_box_own_dt1us_p1 "$here/problem3.prm" \
    "$(own_12x10 0.02); $half_step; $(top_pressure_edit 1)"
}
# ... and their ensembles at that step (session 45): R = 15 mm +1-3 ppm and R = 20 mm +2, +3 ppm beside
# the unperturbed runs and R = 20 mm +1 ppm above, alternating so that, stopped early, both have as
# many runs
problem3_against_r_half_step() {
  local k r edit
  for k in 1 2 3; do
    for r in 0.015 0.02; do
      [[ $r == 0.02 && $k -eq 1 ]] && continue
      edit="$(own_12x10 "$r"); $half_step; $(top_pressure_edit $k)"
      band_case "problem3_R${r}_le2_12x10_box_own_dt1us_p$k" "$here/problem3.prm" "$edit"
    done
  done
}
# ... and the unperturbed runs at the default step again with session 45's build, which returns each
# RVE's stress at its step's last check (the runs of problem3_against_r had the mean of two checks)
problem3_last_check() {
  local r
  for r in 0.02 0.015; do
    band_case "problem3_R${r}_le2_12x10_box_own_last" "$here/problem3.prm" "$(own_12x10 "$r")"
  done
}
# ... and at half the rate (2 /s, to 8 % in 40 ms, twice the DEM steps) with that build (session 46)
problem3_half_rate() {
  local r
  for r in 0.02 0.015; do
    band_case "problem3_R${r}_le2_12x10_box_own_last_rate2" "$here/problem3.prm" "$(own_12x10 "$r"); $half_rate"
  done
}
# ... and that case's first 1 % of shear (two load steps at the same rate), one ingredient changed at a
# time: the seed removed, C_e removed (total strain), the averaged volume, half the step
problem3_hourglass_probe() {
  local short='s#set End time   = 0.02#set End time   = 0.0025#; s#set Load steps = 16#set Load steps = 2#'
  local r20 no_seed='/^subsection Imperfection/,/^end/d'
  r20=$(problem3_edit 12 10 0.02 2e6)
  band_case probe_R0.02_own_box "$here/problem3.prm" "$r20; $seed_box; $own_volume; $short"
  band_case probe_R0.02_own_no_seed "$here/problem3.prm" "$r20; $no_seed; $own_volume; $short"
  band_case probe_R0.02_averaged_box "$here/problem3.prm" "$r20; $seed_box; $short"
  band_case probe_R0.02_own_box_total_strain "$here/problem3.prm" "$(problem3_edit 12 10 0.02); $seed_box; $own_volume; $short"
  band_case probe_R0.02_own_box_dt1us "$here/problem3.prm" "$r20; $seed_box; $own_volume; $(time_step_edit 1e-6); $short"
  # the first case again with session 45's build, which returns each RVE's stress at its step's last
  # check, not the mean of the step's two checks (same input; the runs above predate it)
  band_case probe_R0.02_own_box_last "$here/problem3.prm" "$r20; $seed_box; $own_volume; $short"
}
# problem3_edit CELLS_X CELLS_Y RADIUS [E]: problem3.prm's substitutions
problem3_edit() { echo "s/CELLS_X/$1/; s/CELLS_Y/$2/; s/RADIUS/$3/; ${4:+$(local_elastic "$4")}"; }
# submit_full NAME PRM [sed expression]: the case at the paper's size (lsyf_4096) in
# results/full/NAME/ as a SLURM job of 16 ranks, or its sbatch command printed
submit_full() {
  local dir="$results/full/$1" prm=$2 edit=${3:-}
  mkdir -p "$dir"
  rebase "$prm" | sed "s#packings/lsyf_300_weak#packings/lsyf_4096_weak#; s#packings/lsyf_300\$#packings/lsyf_4096#; $edit" |
    sed "s#$root/rve_templates/packings/lsyf_4096_weak#$results/full/lsyf_4096_weak#" > "$dir/macro.prm"
  local cmd=(env FE2DEM="$build/dealii_app/solver/fe2dem" sbatch --ntasks=16 --chdir="$dir" --job-name="lsyf_$1"
             "$root/scripts/slurm/fe2dem.sbatch" "$dir/macro.prm")
  if scontrol ping 2> /dev/null | grep -q UP; then "${cmd[@]}"; else echo "no SLURM controller answers; submit with: ${cmd[*]}"; fi
}
problem3_full() {
  [[ -f "$results/full/lsyf_4096_weak.rve.data" ]] || { mkdir -p "$results/full"
    $py "$root/rve_templates/weaken_packing.py" "$root/rve_templates/packings/lsyf_4096" "$results/full/lsyf_4096_weak" 25; }
  local c name x y radius modulus
  for c in "${problem3_cases[@]}"; do
    read -r name x y radius modulus <<< "$c"
    submit_full "$name" "$here/problem3.prm" "$(problem3_edit "$x" "$y" "$radius" "$modulus")"
  done
  # ... and the width against R as this machine measures it (session 46): 12x10, the seed box, own
  # volume, C_e of E = 2 MPa, R = 10, 15, 20 mm, each unperturbed and with the top's pressure +1-3 ppm,
  # at fe2dem's default step (the last check's stress since session 45)
  local k r
  for r in 0.01 0.015 0.02; do
    submit_full "problem3_R${r}_le2_12x10_box_own" "$here/problem3.prm" "$(own_12x10 "$r")"
    for k in 1 2 3; do
      submit_full "problem3_R${r}_le2_12x10_box_own_p$k" "$here/problem3.prm" "$(own_12x10 "$r"); $(top_pressure_edit $k)"
    done
  done
}
problem4_full() {
  local c name x y radius
  for c in "${problem4_cases[@]}"; do
    read -r name x y radius <<< "$c"
    submit_full "$name" "$here/problem4.prm" "$(problem4_edit "$x" "$y" "$radius" lsyf_4096)"
  done
  for c in "${problem4_le_cases[@]}"; do
    read -r name x y radius modulus <<< "$c"
    submit_full "$name" "$here/problem4.prm" "$(problem4_edit "$x" "$y" "$radius" lsyf_4096); $(local_elastic "$modulus")"
  done
}
# problem3_run [--box] [--own] CASE...: band_case for each NAME CELLS_X CELLS_Y RADIUS [E]; with
# --box the seed is the region of one 12x5 element (seed_box), with --own 'Volume change' = own
problem3_run() {
  local c name x y radius modulus box=""
  [[ ${1:-} == --box ]] && { box="; $seed_box"; shift; }
  [[ ${1:-} == --own ]] && { box="$box; $own_volume"; shift; }
  for c in "$@"; do
    read -r name x y radius modulus <<< "$c"
    band_case "$name" "$here/problem3.prm" "$(problem3_edit "$x" "$y" "$radius" "$modulus")$box"
  done
}
problem3() {
  problem3_run "${problem3_cases[@]}"
  local c name x y dt
  for c in "${problem3_step_cases[@]}"; do
    read -r name x y dt <<< "$c"
    band_case "$name" "$here/problem3.prm" "$(problem3_edit "$x" "$y" 0); $(time_step_edit "$dt")"
  done
  problem3_run "${problem3_band_cases[@]}" "${problem3_scaled_cases[@]}"
  problem3_run --box "${problem3_seed_box_cases[@]}" "${problem3_fixed_r_cases[@]}"
  problem3_run --box --own "${problem3_own_volume_cases[@]}"
  problem3_run --own "${problem3_own_volume_one_ip_cases[@]}"
  problem3_converged
  problem3_perturbed
  problem3_fine_step
  problem3_against_r
  problem3_against_r_averaged
  problem3_own_half_step
  problem3_against_r_half_step
  problem3_last_check
  problem3_half_rate
  problem3_hourglass_probe
  problem3_table
}
problem3_table() {
  $py "$here/problem3.py" "$results" | tee "$results/problem3.txt"
}
problem4_rates() {
  local r
  for r in 4 2 1 0.5; do
    run_macro "problem4_element_rate$r" "$here/problem4_element.prm" 1 "s#ENDT#$(awk -v r="$r" 'BEGIN {print 0.08 / r}')#g"
  done
}
# The macro step against the RVE servo's checks (session 33; README, 'The rate, and the macro
# step'): one element at 4 /s, NAME PRM TIME_STEP CHECK_INTERVAL; problem3.prm as one element without the
# weak RVE, problem4_element.prm at 4 /s
macro_step_cases=("step_p3_5us_ci10 problem3 5e-6 10" "step_p3_2us_ci10 problem3 2e-6 10"
                  "step_p3_1us_ci10 problem3 1e-6 10" "step_p3_2us_ci5 problem3 2e-6 5"
                  "step_p3_5us_ci25 problem3 5e-6 25" "step_p4_2us_ci10 problem4_element 2e-6 10"
                  "step_p4_1us_ci10 problem4_element 1e-6 10" "step_p4_2us_ci5 problem4_element 2e-6 5")
macro_step() {
  local c name prm dt ci edit
  for c in "${macro_step_cases[@]}"; do
    read -r name prm dt ci <<< "$c"
    if [[ $prm == problem3 ]]; then
      edit="$(problem3_edit 1 1 0); /^subsection Imperfection/,/^end/d; $(time_step_edit "$dt")"
    else
      edit="s#ENDT#0.02#g; s#^  set Time step    = 1e-6#  set Time step    = $dt#"
    fi
    run_macro "$name" "$here/$prm.prm" 1 "$edit; $(check_interval_edit "$ci")"
  done
  # against the single RVE driven continuously (fe2dem-rve, Check interval 10 as the element's RVE; before
  # session 34 it stopped on an overlap at 1.5 % and the reference ran at 50): problem 1's shear
  # element (every node prescribed: F12 = gamma, the other F fixed) with lsyf_300 to 8 % at 4 /s,
  # Check interval 10, at three macro steps
  local small="s#packings/lsyf_4096#packings/lsyf_300#"
  shear_rve step_shear_rve lsyf_300 4
  for dt in 1e-6 2e-6 5e-6; do
    run_macro "step_shear_${dt%e-6}us" "$here/problem1_shear_dynamic.prm" 1 "$small; s#End time   = 0.04#End time   = 0.02#
      s#Load steps = 8#Load steps = 16#; s#0.02 \* t / 0.04 \* y#0.08 * t / 0.02 * y#g
      0,/^subsection RVE/s//subsection RVE\n  set Check interval        = 10/
      s#^  set Analysis     = dynamic#  set Analysis     = dynamic\n  set Time step    = $dt#"
  done
  $py "$here/macro_step.py" "$results" | tee "$results/macro_step.txt"
}
# shear_rve NAME PACKING RATE: problem 1's shear element's single RVE (fe2dem-rve, every F but F12
# held: constant volume) of PACKING to 8 % at RATE (1/s), 'Check interval' 10 as the elements' RVEs
shear_rve() {
  run_rve "$1" "$here/problem1_shear_rve.prm" "s#packings/lsyf_4096#packings/$2#
    s#Shear strain      = 0.02#Shear strain      = 0.08#; s#Strain rate       = 0.5#Strain rate       = $3#
    s#Loading steps     = 8#Loading steps     = 16#; 0,/^subsection RVE/s//subsection RVE\n  set Check interval        = 10/"
}
# Constant-volume simple shear of problem 3's two packings, fe2dem-rve (lsyf_300 at 4 /s: macro_step's
# step_shear_rve) against a periodic YADE cell with the same Hertz grains (session 38; README,
# problem 3), to 8 % at 4 /s (YADE's factor 16 of 0.25 /s), the weak packing at 1 /s too; and the
# weak RVE of two problem-3 runs replayed alone along the averaged F its IP saw (weak_replay.prm)
yade_cv="YOUNG=6.67e10+DT=1e-7+P=4.16e5+EPS_END=0.08"
cv_shear() {
  shear_rve step_shear_rve lsyf_300 4
  shear_rve cv_shear_rve_lsyf_300_weak lsyf_300_weak 4
  shear_rve cv_shear_rve_lsyf_300_weak_rate1 lsyf_300_weak 1
  bash "$root/benchmarks/yade_periodic/run_3d.sh" "lsyf_300:shear_cv:16:$yade_cv" "lsyf_300_weak:shear_cv:16:$yade_cv" \
    "lsyf_300_weak:shear_cv:4:$yade_cv"
  local c weak
  mkdir -p "$results/weak_replay_tables"
  for c in problem3_R0.015_le2_12x10 problem3_R0_12x10; do
    weak=$($py -c "import sys; sys.path.insert(0, '$here'); import problem3; print(problem3.weak_ip(problem3.read('$results/$c')))")
    $py "$root/tests/history_to_table.py" "$results/$c/out/history.h5" "$weak" "$results/weak_replay_tables/$c.txt" \
      F_nonlocal > /dev/null
    run_rve "weak_replay_$c" "$here/weak_replay.prm" "s#TABLE#$results/weak_replay_tables/$c.txt#"
  done
  $py "$here/cv_shear.py" "$results" "$root/benchmarks/yade_periodic/results_3d" | tee "$results/cv_shear.txt"
}
problem4_table() {
  $py "$here/problem4.py" "$results" | tee "$results/problem4.txt"
}

case "$what" in
  wave) wave ;;
  problem1) problem1 ;;
  problem1_ensemble) problem1_ensemble ;;
  modulus) modulus ;;
  problem3) if [[ -n $full ]]; then problem3_full; else problem3; fi ;;
  problem3_band) problem3_run "${problem3_band_cases[@]}"; problem3_table ;;
  problem3_scaled) problem3_run "${problem3_scaled_cases[@]}"; problem3_run --box "${problem3_seed_box_cases[@]}"; problem3_table ;;
  problem3_fixed_r) problem3_run --box "${problem3_fixed_r_cases[@]}"; problem3_table ;;
  problem3_own_volume) problem3_run --box --own "${problem3_own_volume_cases[@]}"
                       problem3_run --own "${problem3_own_volume_one_ip_cases[@]}"; problem3_table ;;
  problem3_converged) problem3_converged; problem3_table ;;
  problem3_perturbed) problem3_perturbed; problem3_table ;;
  problem3_fine_step) problem3_fine_step; problem3_table ;;
  problem3_against_r) problem3_against_r; problem3_table ;;
  problem3_against_r_averaged) problem3_against_r_averaged; problem3_table ;;
  problem3_own_half_step) problem3_own_half_step; problem3_table ;;
  problem3_against_r_half_step) problem3_against_r_half_step; problem3_table ;;
  problem3_last_check) problem3_last_check; problem3_table ;;
  problem3_half_rate) problem3_half_rate; problem3_table ;;
  problem3_hourglass_probe) problem3_hourglass_probe; problem3_table ;;
  problem4) if [[ -n $full ]]; then problem4_full; else problem4; fi ;;
  problem4_rates) problem4_rates ;;
  macro_step) macro_step ;;
  cv_shear) cv_shear ;;
  tables) wave_table; problem1_tables; problem1_ensemble_table; modulus_table; problem3_table; problem4_table
          $py "$here/macro_step.py" "$results" | tee "$results/macro_step.txt"
          $py "$here/cv_shear.py" "$results" "$root/benchmarks/yade_periodic/results_3d" | tee "$results/cv_shear.txt" ;;
  all) if [[ -n $full ]]; then problem3_full; problem4_full; else wave; problem1; modulus; problem3; problem4; problem4_rates; macro_step; cv_shear; fi ;;
  *) sed -n '2,/^#   run.sh BUILD/p' "$0"; exit 2 ;;
esac
