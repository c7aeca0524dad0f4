#!/usr/bin/env bash
# Headless recording speed: gas-classroom at 1280x720, 30 frames/s, 10 s (300 frames) in each format,
# median frames per wall second of three runs side by side in one invocation, and the clip sizes.
# Usage: bench/record_throughput.sh [build/app/particlelab-cli]
set -euo pipefail
cli="${1:-build/app/particlelab-cli}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
echo "format  fps_run1  fps_run2  fps_run3  median_fps  clip_bytes"
for format in mp4 webm gif; do
  rates=()
  for run in 1 2 3; do
    line=$("$cli" record gas-classroom --out "$out/clip.$format" --seconds 10 --fps 30 --size 1280x720 2>&1 |
      grep -o '[0-9.]* frames per wall second' | cut -d' ' -f1)
    rates+=("$line")
  done
  median=$(printf '%s\n' "${rates[@]}" | sort -g | sed -n 2p)
  echo "$format  ${rates[*]}  $median  $(stat -c %s "$out/clip.$format")"
done
