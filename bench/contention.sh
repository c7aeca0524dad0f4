#!/usr/bin/env bash
# Speed on a shared machine: every built-in preset at 1 thread and at the default thread count (each
# step on the team the run measures fastest, core/common/ThreadGovernor.h), on a quiet machine and
# beside a busy loop that holds one core, as another program would. Repeats are interleaved (1 thread,
# default, 1 thread, …), so a change of load hits both alike. Each repeat times about SECONDS of steps
# after the bench's warm-up; the step count per preset is calibrated once at 1 thread.
# Usage: bench/contention.sh [REPEATS] [SECONDS] ["PRESET…"]   (CLI=path for another build; FIXED=2
# compares the default with 2 fixed threads instead of 1, LOADS=quiet runs only the quiet half)
# Prints each repeat as it goes, then a Markdown table of median steps/s (BENCHMARKS.md, "Shared
# machines").
set -euo pipefail
cd "$(dirname "$0")/.."
cli=${CLI:-build/app/particlelab-cli}
repeats=${1:-5}
seconds=${2:-0.5}
presets=${3:-$("$cli" list | cut -f1)}
fixed=${FIXED:-1}
loads=${LOADS:-quiet busy}
log=$(mktemp)
busy=""
stop_busy() { [ -z "$busy" ] || kill "$busy" 2>/dev/null || true; busy=""; }
trap 'stop_busy; rm -f "$log"' EXIT

# Seconds of one timed repeat: the bench's JSON "seconds" field.
seconds_of() { sed 's/.*"seconds":\([0-9.eE+-]*\).*/\1/'; }

declare -A steps
for preset in $presets; do
  probe=$("$cli" bench "$preset" --steps 20 --repeats 1 --threads 1 2>/dev/null | seconds_of)
  steps[$preset]=$(awk -v s="$probe" -v want="$seconds" 'BEGIN {
    n = int(want / (s / 20) + 0.5); if (n < 20) n = 20; if (n > 200000) n = 200000; print n }')
done

for load in $loads; do
  [ "$load" = busy ] && { sh -c 'while :; do :; done' & busy=$!; }
  for preset in $presets; do
    for r in $(seq 1 "$repeats"); do
      for threads in "$fixed" default; do
        option=()
        [ "$threads" = default ] || option=(--threads "$threads")
        line=$("$cli" bench "$preset" --steps "${steps[$preset]}" --repeats 1 "${option[@]}" 2>/dev/null)
        rate=$(echo "$line" | seconds_of | awk -v n="${steps[$preset]}" '{ printf "%.1f", n / $1 }')
        used=$(echo "$line" | sed -n 's/.*"steps_at_threads":\(\[[0-9,]*\]\).*/ steps at 0,1,2… threads \1/p')
        echo "$load $preset $threads $rate" >>"$log"
        echo "$load, $preset, $threads thread(s), repeat $r: $rate steps/s$used"
      done
    done
  done
  stop_busy
done

median() { sort -n | awk '{ v[NR] = $1 } END { print NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
rate_of() { awk -v l="$1" -v p="$2" -v t="$3" '$1 == l && $2 == p && $3 == t { print $4 }' "$log" | median; }
echo
echo "Median steps/s over $repeats interleaved repeats of ~${seconds} s; 'busy': beside sh -c 'while :; do :; done'."
echo
echo "| preset | steps | quiet, $fixed | quiet, default | default / $fixed | busy, $fixed | busy, default | default / $fixed |"
echo "|---|---|---|---|---|---|---|---|"
for preset in $presets; do
  q1=$(rate_of quiet "$preset" "$fixed") qd=$(rate_of quiet "$preset" default)
  b1=$(rate_of busy "$preset" "$fixed") bd=$(rate_of busy "$preset" default)
  awk -v p="$preset" -v n="${steps[$preset]}" -v q1="$q1" -v qd="$qd" -v b1="$b1" -v bd="$bd" 'BEGIN {
    # A load that was not run (LOADS) shows as a dash.
    q = q1 > 0 ? sprintf("%.0f | %.0f | %.2f", q1, qd, qd / q1) : "— | — | —"
    b = b1 > 0 ? sprintf("%.0f | %.0f | %.2f", b1, bd, bd / b1) : "— | — | —"
    printf "| %s | %d | %s | %s |\n", p, n, q, b }'
done
