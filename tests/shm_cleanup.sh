#!/usr/bin/env bash
# RVE images in /dev/shm (issue 16): a normal run leaves none of its own; a
# run killed by SIGKILL, and one aborted (SIGABRT), leave theirs (the test
# checks they exist, so that it can fail) and the next start removes them.
# Runs fe2dem on 1 rank, without mpirun, so that $! is the process.
# Usage: shm_cleanup.sh FE2DEM PRM WORKDIR
set -uo pipefail
exe=$1 prm=$2 work=$3
shm=/dev/shm
[[ -d $shm ]] || { echo "SKIP: no /dev/shm"; exit 77; }
rm -rf "$work"; mkdir -p "$work"; cd "$work"
{ sed 's#^set Output directory.*#set Output directory = out#' "$prm"
  printf '\nsubsection Checkpoint\n  set Every = 1\nend\n'; } > case.prm
fail() { echo "FAIL: $*"; exit 1; }
images() { ls $shm 2> /dev/null | grep -c "^fe2dem-$1-"; }
"$exe" case.prm > normal.log 2>&1 & pid=$!
wait $pid || fail "the normal run failed: $(tail -n 3 normal.log)"
[[ $(images $pid) -eq 0 ]] || fail "the normal run (pid $pid) left $(images $pid) images in $shm"
echo "normal exit: no image of pid $pid left"
for sig in KILL ABRT; do
  "$exe" case.prm > $sig.log 2>&1 & pid=$!
  for _ in $(seq 600); do [[ -f out/checkpoints/checkpoint-000001.h5 ]] && break; sleep 0.1; done
  left=$(images $pid)
  [[ $left -gt 0 ]] || fail "no image of the running pid $pid in $shm to leak: the test cannot see them"
  kill -$sig $pid; wait $pid 2> /dev/null
  [[ $(images $pid) -eq $left ]] || fail "SIG$sig: expected the $left images of pid $pid still there"
  "$exe" case.prm --resume > resume-$sig.log 2>&1 & next=$!
  wait $next || fail "resume after SIG$sig: $(tail -n 3 resume-$sig.log)"
  [[ $(images $pid) -eq 0 ]] || fail "after SIG$sig and the next start, $(images $pid) images of pid $pid remain"
  [[ $(images $next) -eq 0 ]] || fail "the resumed run (pid $next) left $(images $next) images"
  echo "SIG$sig: $left images of pid $pid left behind, removed by the next start (pid $next)"
done
echo "ok"
