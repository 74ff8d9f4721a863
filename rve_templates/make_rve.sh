#!/usr/bin/env bash
# make_rve.sh NAME [-var KEY VALUE ...] [KEY=VALUE ...]
#
# Makes one FE2DEM RVE packing in two steps:
#   1. liggghts -in make_packing_2d.liggghts ... -var out OUTDIR/NAME.periodic.data
#   2. build_frame.py OUTDIR/NAME.periodic.data NAME --outdir OUTDIR
# (RVE_DIM=3: make_packing_3d.liggghts and build_frame_3d.py)
# giving OUTDIR/NAME.periodic.data, NAME.rve.data, NAME.vars, NAME.stats.txt,
# NAME.frame.txt.  Arguments after NAME go to liggghts; "KEY=VALUE" is a shorthand
# for "-var KEY VALUE".  Do not pass "out" (it is set here).
#
# Environment: RVE_DIM (2 or 3, default 2),
#              RVE_OUTDIR (default: packings/ next to this script),
#              LIGGGHTS (default: liggghts), PYTHON (default: python3),
#              BUILD_FRAME_ARGS (extra options for build_frame.py),
#              KEEP_LOG=1 keeps the LIGGGHTS log as OUTDIR/NAME.liggghts.log.
# Example (the reference RVE, see packings/README.md):
#   ./make_rve.sh lbs_ref seed=10007
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
if [[ $# -lt 1 || "$1" == -* ]]; then
  sed -n '2,18p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
  exit 2
fi
name="$1"
shift
case "${RVE_DIM:-2}" in
  2) packing_script=make_packing_2d.liggghts builder=build_frame.py ;;
  3) packing_script=make_packing_3d.liggghts builder=build_frame_3d.py ;;
  *) echo "make_rve.sh: RVE_DIM=${RVE_DIM} must be 2 or 3" >&2; exit 2 ;;
esac
outdir="${RVE_OUTDIR:-$here/packings}"
liggghts="${LIGGGHTS:-liggghts}"
python="${PYTHON:-python3}"

vars=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    -var|-v)
      [[ $# -ge 3 ]] || { echo "make_rve.sh: '$1' needs KEY VALUE" >&2; exit 2; }
      vars+=(-var "$2" "$3"); shift 3 ;;
    *=*)
      vars+=(-var "${1%%=*}" "${1#*=}"); shift ;;
    *)
      echo "make_rve.sh: unexpected argument '$1' (use -var KEY VALUE or KEY=VALUE)" >&2
      exit 2 ;;
  esac
done
for ((i = 0; i < ${#vars[@]}; i += 3)); do
  if [[ "${vars[i+1]}" == "out" ]]; then
    echo "make_rve.sh: do not pass 'out'; the output is $outdir/$name.periodic.data" >&2
    exit 2
  fi
done

command -v "$liggghts" >/dev/null || { echo "make_rve.sh: '$liggghts' not found (set LIGGGHTS)" >&2; exit 1; }
mkdir -p "$outdir"
outdir="$(cd "$outdir" && pwd)"
periodic="$outdir/$name.periodic.data"
work="$(mktemp -d "${TMPDIR:-/tmp}/make_rve.XXXXXX")"
trap 'rm -rf "$work"' EXIT
log="$work/liggghts.log"
rm -f "$periodic"

echo "make_rve.sh: $name: liggghts ${vars[*]:-}"
start=$(date +%s)
screen="$work/screen.txt"
# stdbuf: LIGGGHTS exits through MPI_Abort on errors; unbuffered output keeps the message
unbuf=()
if command -v stdbuf >/dev/null; then unbuf=(stdbuf -o0 -e0); fi
if ! (cd "$work" && "${unbuf[@]}" "$liggghts" -nocite -echo none -log "$log" \
        -in "$here/$packing_script" "${vars[@]}" -var out "$periodic" \
        >"$screen" 2>&1); then
  echo "make_rve.sh: LIGGGHTS failed for $name; its messages:" >&2
  grep -v '^ *[0-9]' "$screen" | grep -iv 'mpi_abort\|^--\|^NOTE\|^You may\|^exactly\|^$' | tail -n 15 >&2 || true
  exit 1
fi
if [[ ! -s "$periodic" ]]; then
  echo "make_rve.sh: LIGGGHTS wrote no $periodic; end of its output:" >&2
  tail -n 25 "$screen" >&2 || true
  exit 1
fi
grep '^PACKING:' "$log" || true
if [[ "${KEEP_LOG:-0}" == 1 ]]; then cp "$log" "$outdir/$name.liggghts.log"; fi
echo "make_rve.sh: LIGGGHTS took $(( $(date +%s) - start )) s"

# shellcheck disable=SC2086
"$python" "$here/$builder" "$periodic" "$name" --outdir "$outdir" ${BUILD_FRAME_ARGS:-}
