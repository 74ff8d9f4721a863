# Shared helpers of the benchmark scripts (source it).
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print (NR%2) ? a[(NR+1)/2] : 0.5*(a[NR/2]+a[NR/2+1])}'; }
minimum() { printf '%s\n' "$@" | sort -g | head -1; }
# lower quartile (nearest rank): robust to the one-sided noise of a shared machine
quartile1() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print a[int((NR + 3) / 4)]}'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.4f", a / b}'; }
# append_result CSV HEADER VALUES: one row "date,commit,machine,VALUES".
append_result() {
  local csv="$1" header="$2" values="$3" root
  root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
  [[ -f "$csv" ]] || echo "date,commit,machine,$header" > "$csv"
  local machine
  machine="$(nproc)cores-$(awk -F: '/model name/ {gsub(/^ +/, "", $2); print $2; exit}' /proc/cpuinfo | tr ', ' '__')"
  echo "$(date -u +%FT%TZ),$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo none),$machine,$values" >> "$csv"
}
# prm_content < FILE: a parameter file without its comments and blank lines,
# as deal.II's ParameterHandler reads it ('#' starts a comment)
prm_content() { sed -e 's/#.*$//' -e 's/[[:space:]]*$//' -e '/^$/d'; }
# needs_run CASE RESULT < <(commands writing a run's input): false when
# RESULT exists and CASE holds the same parameters (comments aside: the
# stored run is current and keeps the file it ran with), else writes the
# text to CASE, removes a stale RESULT and returns true. Keeps a rerun from
# reusing results made with an older parameter file. Run it in the calling
# shell (input by process substitution, not a pipe) so that an empty input,
# e.g. a missing template, stops the script.
needs_run() {
  local case=$1 result=$2 text
  text="$(cat)"
  [[ -n "$text" ]] || { echo "needs_run: no input text for '$case' (is its template missing?)" >&2; exit 1; }
  if [[ -f "$result" && -f "$case" && "$(prm_content < "$case")" == "$(prm_content <<< "$text")" ]]; then
    return 1
  fi
  mkdir -p "$(dirname "$case")"
  printf '%s\n' "$text" > "$case"
  rm -f "$result"
}
