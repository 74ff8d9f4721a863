# Sourced by sigterm_stuck_solve.sh and second_signal.sh: starts fe2dem on
# a run whose RVE solves never converge (relaxation and servo tolerances
# unreachable, an endless step budget) in WORKDIR, on NP ranks, output in
# WORKDIR/stopped.log, and returns once fe2dem starts building its RVEs, so
# that its signal handlers are installed and it is in the template check (a
# child fe2dem-liggghts) or in a solve. TMPDIR is WORKDIR/tmp, for the
# callers to check that nothing is left there. Sets pid (the process
# started: fe2dem or mpiexec).
# Usage: start_stuck_run FE2DEM PRM WORKDIR NP   (the caller is then in WORKDIR)
start_stuck_run() {
  local exe=$1 prm=$2 work=$3 np=$4
  rm -rf "$work"; mkdir -p "$work"
  { sed 's#^set Output directory.*#set Output directory = out#' "$prm"
    printf '\nsubsection RVE\n  set Relaxation tolerance = 1e-30\n  set Servo tolerance = 1e-30\n'
    printf '  set Step budget = 1000000000\nend\n'; } > "$work/case.prm"
  cd "$work" || exit 1
  mkdir tmp; export TMPDIR=$work/tmp
  if [[ $np -eq 1 ]]; then "$exe" case.prm > stopped.log 2>&1 &
  else mpiexec --allow-run-as-root --oversubscribe -np "$np" "$exe" case.prm > stopped.log 2>&1 &
  fi
  pid=$!
  # No fixed delay: the first line fe2dem prints after installing the handlers.
  until grep -q "^creating [0-9]* RVEs" stopped.log 2>/dev/null; do
    kill -0 $pid 2>/dev/null || { echo "FAIL: fe2dem ended before building its RVEs"; cat stopped.log; exit 1; }
    sleep 0.1
  done
}
