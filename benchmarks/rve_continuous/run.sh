#!/usr/bin/env bash
# The continuous (constant-rate) RVE paths of issue 35 and the stepped ones
# against them. Each case writes results/CASE/rve.csv (+ run.log); a case
# whose rve.csv exists is skipped unless --force.
#
#   run.sh BUILD rates     triaxial and simple shear, small_3d and lsyf_1000,
#                          at 0.25 and 0.125 /s (and timed_servo proportional
#                          at both rates on small_3d triaxial), lsyf_4096
#                          triaxial at 0.25 and 0.125 /s to 3 %
#   run.sh BUILD slow_small_3d  small_3d triaxial and shear at 0.0625 and 0.03125 /s as
#                          well: the rate ensemble beside YADE's (rate_ensemble.py)
#   run.sh BUILD ensemble_small_3d  small_3d triaxial and shear at 0.25 /s x F for the
#                          eight F in 0.96 ... 1.04, and YADE's periodic cell at the
#                          same rates (yade_periodic/run_3d.sh): twelve members
#                          with the four rates, for rate_ensemble.py
#   run.sh BUILD rates_keep  rates and slow_small_3d with 'Inner start' = keep (the
#                          continuous drive's default before session 24) into
#                          results/inner_keep/; the held diagnostics start from them
#   run.sh BUILD stepped   small_3d triaxial, stepped: 0.5 % and 0.25 % steps to 5 %, 0.1 % to 2.5 %
#   run.sh BUILD held      the 0.25 /s paths of small_3d (to 3 %) and lsyf_1000 (to 2 %)
#                          held at rest: their F every 0.5 % and 0.25 % as table
#                          paths, 'Solve drive' = continuous and servo iterations
#                          (also with the frame moved at ~0.25 /s)
#   run.sh BUILD holds     the 0.25 /s paths to 3 % held at rest every 0.5 % ('Hold rows' = 2)
#   run.sh BUILD one_element  the continuous reference of benchmarks/one_element_3d
#                          (lsyf_1000, axial y, Inner start affine) at 0.25 and
#                          0.125 /s and keep at 0.25 /s
#   run.sh BUILD biaxial_2d  2D: lbs_ref biaxial (benchmarks/frame_vs_periodic/biaxial.prm)
#                          continuous at 0.1 /s, the rate of the 2D YADE reference
#   run.sh BUILD tables    curves.py comparisons into results/*.txt
#   run.sh BUILD all       all of them in order
#
# BUILD: the build directory (e.g. build). Runs one case at a time.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
[[ $# -ge 2 ]] || { sed -n '2,33p' "$0"; exit 2; }
build="$(cd "$1" && pwd)"; what="$2"; force="${3:-}"
rve="$build/dealii_app/rve_driver/fe2dem-rve"
[[ -x "$rve" ]] || { echo "run.sh: no fe2dem-rve in $build (build it first)"; exit 2; }
results="$here/results"
mkdir -p "$results"

# case NAME BASE_PRM SED_EXPRESSION: BASE_PRM with the substitutions, run into results/NAME.
case_run() {
  local name="$1" base="$2" edit="$3" out="$results/$1"
  if [[ -f "$out/rve.csv" && "$force" != "--force" ]]; then
    echo "$name: exists (--force to run again)"; return
  fi
  mkdir -p "$out"
  # relative paths of the parameter file are resolved against its folder: make them absolute
  sed -e "s|\.\./\.\./|$root/|g" -e "$edit" "$here/$base" > "$out/case.prm"
  local t0=$SECONDS
  "$rve" "$out/case.prm" --output-directory "$out" > "$out/run.log" 2>&1 ||
    { echo "$name: FAILED (see $out/run.log)"; return 1; }
  echo "$name: $((SECONDS - t0)) s"
}

rate() { echo "s/^\( *set Strain rate *=\).*/\1 $1/"; }
keep='s/^\( *set Inner start *=\).*/\1 keep/'

rates() {
  for packing in small_3d lsyf_1000; do
    for path in triaxial shear; do
      for r in 0.25 0.125; do
        case_run "${path}_${packing}_${r}" "${path}_${packing}.prm" "$(rate $r)"
      done
    done
  done
  for r in 0.25 0.125; do
    case_run "triaxial_lsyf_4096_${r}" triaxial_lsyf_4096.prm "$(rate $r)"
  done
  for r in 0.25 0.125; do # measured with keep (before session 24), kept so
    case_run "triaxial_small_3d_${r}_proportional" triaxial_small_3d.prm \
      "$(rate $r); $keep; s/^\( *set Frame membrane .*\)/\1\n  set Template variables = timed_servo proportional/"
  done
}

# the continuous paths with 'Inner start' = keep, into results/inner_keep/
rates_keep() {
  local packing path r
  for packing in small_3d lsyf_1000 lsyf_4096; do
    for path in triaxial shear; do
      [[ -f "$here/${path}_${packing}.prm" ]] || continue
      for r in 0.25 0.125 0.0625 0.03125; do
        [[ $packing != small_3d && $r != 0.25 && $r != 0.125 ]] && continue
        case_run "inner_keep/${path}_${packing}_${r}" "${path}_${packing}.prm" "$(rate $r); $keep"
      done
    done
  done
}

slow_small_3d() {
  for path in triaxial shear; do
    for r in 0.0625 0.03125; do
      case_run "${path}_small_3d_${r}" "${path}_small_3d.prm" "$(rate $r)"
    done
  done
}

ensemble_factors=(0.96 0.97 0.98 0.99 1.01 1.02 1.03 1.04)
ensemble_small_3d() {
  local path f r
  for path in triaxial shear; do
    for f in "${ensemble_factors[@]}"; do
      r=$(awk -v f="$f" 'BEGIN {printf "%.6g", 0.25 * f}')
      case_run "${path}_small_3d_$r" "${path}_small_3d.prm" "$(rate "$r")"
      "$root/benchmarks/yade_periodic/run_3d.sh" "small_3d:$path:$f" | grep -v '^small_3d_\|^lsyf_' || true
    done
  done
}

stepped() {
  # steps of 0.5 % and 0.25 % to 5 %, of 0.1 % to 2.5 %, with the continuous runs' RVE
  # settings (Inner start keep, as the stepped default)
  for case in "10 0.05" "20 0.05" "25 0.025"; do
    read -r n strain <<<"$case"
    case_run "triaxial_small_3d_stepped_${n}" triaxial_small_3d.prm \
      "$keep; s/^\( *set Drive *=\).*/\1 stepped/; s/^\( *set Loading steps *=\).*/\1 $n/; s/^\( *set Axial strain *=\).*/\1 $strain/"
  done
}

held() {
  # the continuous path (0.25 /s, Inner start keep: results/inner_keep) held at rest: its F at every 0.5 % (and
  # 0.25 %) as table paths, each row one quasi-static solve, with each solve
  # drive; small_3d to 3 %, lsyf_1000 to 2 %. 'iterations_slow': the servo
  # iterations with the frame moved at about 0.25 /s (move_rate).
  local packing every rows drive name move
  for run in "small_3d 2 12" "small_3d 1 12" "lsyf_1000 2 8" "lsyf_1000 1 8"; do
    read -r packing every rows <<<"$run"
    for drive in continuous iterations iterations_slow; do
      [[ $packing == lsyf_1000 && $every == 1 && $drive == iterations_slow ]] && continue
      name="held_${packing}_${every}_${drive}"
      mkdir -p "$results/$name"
      /usr/bin/python3 "$root/tests/held_path.py" table "$results/inner_keep/triaxial_${packing}_0.25/rve.csv" "$every" \
        "$results/$name/table.txt" "$rows"
      move=""; [[ $drive == iterations_slow ]] && move="s/^\( *set Step budget.*\)/\1\n  set Template variables = move_rate $([[ $packing == small_3d ]] && echo 5e-6 || echo 2e-6)/;"
      case_run "$name" "triaxial_${packing}.prm" \
        "$keep; s|^\( *set Type *=\).*|\1 table\n  set Table file = $results/$name/table.txt|; $move s/^\( *set Servo tolerance .*\)/\1\n  set Solve drive = $([[ $drive == continuous ]] && echo continuous || echo servo iterations)/"
    done
  done
}

holds() {
  # the continuous drive (0.25 /s) held at rest at every 0.5 % ('Hold rows' =
  # 2) to 3 %, against YADE's held cell (../yade_periodic, RELAX_EVERY=2);
  # measured with Inner start keep, as the runs they are compared with
  local packing
  for packing in small_3d lsyf_1000; do
    case_run "hold_rows_${packing}" "triaxial_${packing}.prm" \
      "$keep; s/^\( *set Loading steps *=\).*/\1 12/; s/^\( *set Axial strain *=\).*/\1 0.03/; s/^\( *set Drive .*\)/\1\n  set Hold rows = 2/"
  done
}

one_element() {
  for r in 0.25 0.125; do
    case_run "one_element_lsyf_1000_${r}" one_element_lsyf_1000.prm "$(rate $r)"
  done
  case_run "one_element_lsyf_1000_0.25_keep" one_element_lsyf_1000.prm "$keep"
}

biaxial_2d() {
  local name=biaxial_2d_lbs_ref_0.1 out="$results/biaxial_2d_lbs_ref_0.1"
  if [[ -f "$out/rve.csv" && "$force" != "--force" ]]; then echo "$name: exists"; return; fi
  mkdir -p "$out"
  sed -e "s|\.\./\.\./|$root/|g" -e "s|^set Output directory.*|set Output directory = $out|" \
    -e 's/^\( *set Isotropic control.*\)/\1\n  set Drive = continuous\n  set Strain rate = 0.1\n  set Max stress iterations = 50/' \
    "$root/benchmarks/frame_vs_periodic/biaxial.prm" > "$out/case.prm"
  local t0=$SECONDS
  "$rve" "$out/case.prm" > "$out/run.log" 2>&1 || { echo "$name: FAILED"; return 1; }
  echo "$name: $((SECONDS - t0)) s"
}

# 2D rve.csv against the YADE biaxial CSV: sigma22 and the stress ratio at YADE's 0.5 % rows.
compare_2d() {
  /usr/bin/python3 - "$1" "$2" <<'PY'
import csv, sys
rve = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(open(sys.argv[1]))]
ic = next(k for k, r in enumerate(rve) if r["drive_time_s"] > 0) - 1
yade = [r for r in csv.DictReader(l for l in open(sys.argv[2]) if not l.startswith("#")) if r["stage"] == "biaxial"]
print("strain  yade_ratio  rve_ratio  d_ratio  yade_s22  rve_s22  d_s22")
for y in yade:
    e = float(y["axial_strain"])
    for a, b in zip(rve[ic:], rve[ic + 1:]):
        ea, eb = 1 - a["F22"] / rve[ic]["F22"], 1 - b["F22"] / rve[ic]["F22"]
        if ea - 1e-9 <= e <= eb + 1e-9 and e > 1e-6:
            t = (e - ea) / (eb - ea)
            s11 = a["sigma11"] + t * (b["sigma11"] - a["sigma11"])
            s22 = a["sigma22"] + t * (b["sigma22"] - a["sigma22"])
            ratio = abs((s11 - s22) / (s11 + s22))
            yr, ys = float(y["stress_ratio"]), float(y["sigma22_Npm"])
            print(f"{e:.4f}  {yr:.4f}  {ratio:.4f}  {ratio / yr - 1:+.2%}  {ys:.0f}  {s22:.0f}  {s22 / ys - 1:+.2%}")
            break
PY
}

# rate_tables DIR: the continuous paths of DIR (results or results/inner_keep):
# their two rates, against YADE's periodic cell and small_3d as an ensemble
rate_tables() {
  local dir="$1" c="$here/curves.py" packing path r
  for packing in small_3d lsyf_1000 lsyf_4096; do
    for path in triaxial shear; do
      local a="$dir/${path}_${packing}_0.125/rve.csv" b="$dir/${path}_${packing}_0.25/rve.csv"
      [[ -f "$a" && -f "$b" ]] && "$c" compare "$a" "$b" > "$dir/rates_${path}_${packing}.txt"
    done
  done
  # against YADE's periodic cell (benchmarks/yade_periodic/run_3d.sh makes its results_3d):
  # one call per RVE rate (the plot holds one RVE curve per packing and path)
  for r in 0.125 0.25; do
    local yade=() suffix=""; [[ $r == 0.25 ]] && suffix="_0.25"
    for packing in small_3d lsyf_1000 lsyf_4096; do for path in triaxial shear; do
      [[ -f "$dir/${path}_${packing}_${r}/rve.csv" ]] && yade+=(--rve "${packing}_${path}=$dir/${path}_${packing}_${r}/rve.csv")
    done; done
    [[ ${#yade[@]} -gt 0 ]] && /usr/bin/python3 "$root/benchmarks/yade_periodic/compare_3d.py" "${yade[@]}" \
      --plot "$dir/vs_yade$suffix.png" --tables "$dir/vs_yade$suffix.md" > "$dir/vs_yade$suffix.txt"
  done
  # small_3d as an ensemble: the RVE's mean over the four rates (and the eight of
  # ensemble_small_3d where both codes ran them) against YADE's (rate_ensemble.py)
  local y3="$root/benchmarks/yade_periodic/results_3d" f
  for path in triaxial shear; do
    local ens=() yades=()
    for f in 1 0.5 0.25 0.125 "${ensemble_factors[@]}"; do
      r=$(awk -v f="$f" 'BEGIN {printf "%.6g", 0.25 * f}')
      [[ -f "$dir/${path}_small_3d_$r/rve.csv" && -f "$y3/small_3d_${path}_rate$f.csv" ]] || continue
      ens+=("$dir/${path}_small_3d_$r/rve.csv")
      yades+=("$y3/small_3d_${path}_rate$f.csv")
    done
    [[ ${#ens[@]} -ge 4 ]] && "$here/rate_ensemble.py" "$path" --yade "${yades[@]}" --rve "${ens[@]}" \
      > "$dir/ensemble_small_3d_${path}.txt"
  done
  return 0
}

tables() {
  local c="$here/curves.py"
  rate_tables "$results"
  rate_tables "$results/inner_keep"
  # the stepped paths and the proportional servo were measured with Inner start keep: against keep
  local ref="$results/inner_keep/triaxial_small_3d_0.125/rve.csv" others=()
  for n in 10 20 25; do
    [[ -f "$results/triaxial_small_3d_stepped_${n}/rve.csv" ]] && others+=("$results/triaxial_small_3d_stepped_${n}/rve.csv")
  done
  [[ -f "$ref" && ${#others[@]} -gt 0 ]] && "$c" --iso 2 compare "$ref" "${others[@]}" > "$results/stepped_vs_continuous_small_3d.txt"
  local p="$results/triaxial_small_3d_0.125_proportional/rve.csv"
  [[ -f "$ref" && -f "$p" ]] && "$c" compare "$ref" "$p" "$results/triaxial_small_3d_0.25_proportional/rve.csv" \
    > "$results/servo_integral_vs_proportional_small_3d.txt"
  local one="$root/benchmarks/one_element_3d/results/lsyf_1000" oref="$results/one_element_lsyf_1000_0.125/rve.csv"
  [[ -f "$oref" ]] && "$c" compare "$oref" "$results/one_element_lsyf_1000_0.25/rve.csv" \
    "$results/one_element_lsyf_1000_0.25_keep/rve.csv" "$one/macro_summary.csv" "$one/macro_10_steps_summary.csv" \
    > "$results/one_element_stepped_vs_continuous.txt"
  [[ -f "$oref" ]] && "$c" --iso 2 compare "$oref" "$one/rve_100_steps.csv" >> "$results/one_element_stepped_vs_continuous.txt"
  local p25="$results/triaxial_small_3d_0.25_proportional/rve.csv"
  [[ -f "$p25" ]] && /usr/bin/python3 "$root/benchmarks/yade_periodic/compare_3d.py" --rve "small_3d_triaxial=$p25" \
    --plot "$results/vs_yade_proportional.png" --tables "$results/vs_yade_proportional.md" > "$results/vs_yade_proportional.txt"
  local b2="$results/biaxial_2d_lbs_ref_0.1/rve.csv"
  [[ -f "$b2" ]] && compare_2d "$b2" "$root/benchmarks/yade_periodic/results/lbs_ref_rate1.csv" > "$results/biaxial_2d_vs_yade.txt"
  local y="$root/benchmarks/yade_periodic/results_3d" packing_h
  for packing_h in small_3d lsyf_1000; do
    local held_y="$y/${packing_h}_triaxial_rate1_RELAX_EVERY2_EPS_END0.03.csv"
    [[ -f "$held_y" ]] && "$here/holds.py" yade "$y/${packing_h}_triaxial_rate1.csv" "$held_y" \
      > "$results/holds_yade_${packing_h}.txt"
    [[ -f "$results/hold_rows_${packing_h}/rve.csv" ]] && "$here/holds.py" rve \
      "$results/inner_keep/triaxial_${packing_h}_0.25/rve.csv" "$results/hold_rows_${packing_h}/rve.csv" 2 \
      > "$results/holds_rve_${packing_h}.txt"
  done
  local h
  for h in "$results"/held_*/rve.csv; do
    [[ -f "$h" ]] || continue
    local case_dir; case_dir="$(dirname "$h")"; local packing
    packing="$(basename "$case_dir" | sed 's/^held_\(small_3d\|lsyf_1000\)_.*/\1/')"
    /usr/bin/python3 "$root/tests/held_path.py" check "$results/inner_keep/triaxial_${packing}_0.25/rve.csv" "$h" 0.02 0.05 \
      > "$case_dir/vs_continuous.txt" || true
  done
  ls "$results"/*.txt
}

case "$what" in
  rates) rates ;;
  rates_keep) rates_keep ;;
  slow_small_3d) slow_small_3d ;;
  ensemble_small_3d) ensemble_small_3d ;;
  stepped) stepped ;;
  held) held ;;
  holds) holds ;;
  tables) tables ;;
  one_element) one_element ;;
  biaxial_2d) biaxial_2d ;;
  all) rates; slow_small_3d; ensemble_small_3d; rates_keep; stepped; held; holds; one_element; biaxial_2d; tables ;;
  *) sed -n '2,33p' "$0"; exit 2 ;;
esac
