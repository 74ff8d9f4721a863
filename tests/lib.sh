# Shell helpers of the test scripts (sourced: . "$tests/lib.sh").

# wait_for_rows FILE N: wait until FILE exists with at least N lines (a
# header and N - 1 rows), polling every 0.05 s for at most 60 s. Returns 1
# on time-out; the callers' own checks then say what is missing.
wait_for_rows() {
  local file=$1 lines=$2
  for _ in $(seq 1200); do
    [[ -f $file && $(wc -l < "$file") -ge $lines ]] && return 0
    sleep 0.05
  done
  return 1
}
