#!/usr/bin/env bash
# The app's frame rate as a user sees it: each preset runs SECONDS under Xvfb (Mesa llvmpipe where there
# is no GPU) with a fresh home, and prints its --measure-fps line (fps, and the frame split into step,
# sample, replot, viewport and other; see BENCHMARKS.md, "App frame rate"). Several builds are run
# alternately, preset by preset, so a before/after comparison on a shared machine sees the same load.
# Usage: bench/app_fps.sh ROUNDS SECONDS "PRESET..." [BINARY...]   (default binary: build/app/particlelab)
# Ends with each preset's and binary's median fps over the rounds.
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=${1:-3}
seconds=${2:-6}
presets=${3:-gas-write-up gas-classroom fluid-obstacle fluid-dam-break}
shift $(($# < 3 ? $# : 3))
binaries=("$@")
[ ${#binaries[@]} -gt 0 ] || binaries=(build/app/particlelab)
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}
chmod 700 "$XDG_RUNTIME_DIR"
log=$(mktemp)
for round in $(seq 1 "$rounds"); do
  for preset in $presets; do
    for binary in "${binaries[@]}"; do
      home=$(mktemp -d)
      line=$(HOME=$home timeout $((seconds + 60)) xvfb-run -a -s "-screen 0 1280x800x24" "$binary" "$preset" \
        --measure-fps "$seconds" 2>/dev/null | grep '"fps"' || echo '{"fps": 0, "failed": true}')
      rm -rf "$home"
      echo "round $round, $binary, load $(cut -d' ' -f1 /proc/loadavg): $line" | tee -a "$log"
    done
  done
done
echo "median fps over $rounds rounds:"
for preset in $presets; do
  for binary in "${binaries[@]}"; do
    grep -F ", $binary, " "$log" | grep -F "\"preset\": \"$preset\"" |
      sed 's/.*"fps": \([0-9.]*\).*/\1/' | sort -n |
      awk -v p="$preset" -v b="$binary" '{ v[NR] = $1 } END {
        m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2; printf "  %-16s %s: %.1f\n", p, b, m }'
  done
done
rm -f "$log"
