#!/usr/bin/env bash
# CPU time of two builds' bench runs, interleaved: on a loaded machine the wall time is mostly other
# processes' time slices, while the CPU time a one-thread run takes (perf stat's task-clock, the whole
# process) still compares builds. Prints one line per run; take the medians and the pairwise ratios.
# Usage: bench/cpu_time_pairs.sh PAIRS THREADS OLD_CLI NEW_CLI -- BENCH ARGUMENTS
#   e.g. bench/cpu_time_pairs.sh 6 1 old/particlelab-cli build/app/particlelab-cli -- fluid-write-up \
#        --set fill_x1=79.2 --set fill_y1=29.5 --steps 1000
set -euo pipefail
pairs=${1:?usage: see the header} threads=${2:?} old=${3:?} new=${4:?}
shift 4
[ "${1:-}" = "--" ] && shift
command -v perf >/dev/null || { echo "needs perf (Debian: linux-perf)" >&2; exit 1; }
stat=$(mktemp)
trap 'rm -f "$stat"' EXIT
for r in $(seq "$pairs"); do
  for build in old new; do
    cli=$old
    [ "$build" = new ] && cli=$new
    line=$(perf stat -x, -e task-clock "$cli" bench "$@" --repeats 1 --threads "$threads" 2>"$stat")
    echo "$r $build threads=$threads cpu_ms=$(awk -F, '/task-clock/ { print $1 }' "$stat")" \
      "wall_s=$(echo "$line" | sed 's/.*"seconds":\([0-9.e+-]*\).*/\1/')"
  done
done
