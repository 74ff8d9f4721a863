#!/usr/bin/env bash
# The parameter files of the dynamic one-element triaxial test and of its
# replay by fe2dem-rve (issue 35), written to standard output with the
# templates' paths made absolute; shared by the ctests
# rve_prepared_state_is_fe2dems and rve_table_replays_continuous_triaxial
# and by benchmarks/rve_continuous/replay_dynamic.sh.
#   cases.sh dynamic END_TIME LOAD_STEPS
#       tests/dynamics_rve/triaxial_3d.prm (small_3d prepared at 100 kPa)
#       at its slowest rate, 2e-4 m over 0.3072 s (0.065 /s), run to
#       END_TIME with LOAD_STEPS rows
#   cases.sh replay TABLE ROW_TIME CONTROL_INTERVAL [CHECK_INTERVAL]
#       tests/dynamics_rve/triaxial_continuous_rve.prm as Type = table:
#       TABLE's rows driven continuously, ROW_TIME s each, from the prepared
#       state ('Table start' = isotropic stage), 'Inner start' = affine
set -euo pipefail
tests="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
root="$(cd "$tests/.." && pwd)"
rebase() { sed "s#\.\./\.\./rve_templates#$root/rve_templates#" "$@"; }
case "${1:-}" in
  dynamic)
    [[ $# -eq 3 ]] || { sed -n '2,16p' "$0"; exit 2; }
    rebase "$tests/dynamics_rve/triaxial_3d.prm" \
      | sed "s#-2e-4 \* t / END_TIME#-2e-4 * t / 0.3072#; s#END_TIME#$2#g; s/set Load steps = 8/set Load steps = $3/" ;;
  replay)
    [[ $# -eq 4 || $# -eq 5 ]] || { sed -n '2,16p' "$0"; exit 2; }
    rebase "$tests/dynamics_rve/triaxial_continuous_rve.prm" \
      | sed -e 's/^\( *set Type *=\).*/\1 table/' -e '/^ *set Drive *=/d' -e "s/^\( *set Control interval *=\).*/\1 $4/" \
            -e "s#^\( *set Strain rate *=.*\)#  set Table file        = $2\n  set Table start       = isotropic stage\n  set Table row time    = $3#" \
      | sed "0,/^subsection RVE/s//subsection RVE\n  set Inner start = affine${5:+\n  set Check interval = $5}/" ;;
  *) sed -n '2,16p' "$0"; exit 2 ;;
esac
