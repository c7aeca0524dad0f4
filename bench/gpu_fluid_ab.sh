#!/usr/bin/env bash
# Builds of the GPU fluid side by side: the fluid points of bench/gpu_goals.sh (40 000 particles, where the
# dependent dispatches set the step, and the 1M goal), the builds taking turns for ROUNDS rounds so that
# the device's drift falls on all alike. One JSON file per build and round in OUT_DIR.
# Usage: bench/gpu_fluid_ab.sh OUT_DIR ROUNDS NAME=BENCH [NAME=BENCH …]  (particlelab-bench binaries)
# On the device, with the binaries and GL loaders carried in .gl/ (bench/gpu_sweep.sh):
#   for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig; export LD_LIBRARY_PATH=$PWD/.gl/lib
#   bench/gpu_fluid_ab.sh "$OUT" 3 base=.gl/bin/particlelab-bench-base new=.gl/bin/particlelab-bench
set -euo pipefail
out="$1" rounds="$2"
shift 2
mkdir -p "$out"
command -v nvidia-smi >/dev/null && nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader |
  tee "$out/gpu.txt"
for round in $(seq 1 "$rounds"); do
  for build in "$@"; do
    name="${build%%=*}" bench="${build#*=}"
    echo "round $round, $name"
    "$bench" --scenes fluid --fluid 40000 1048576 --cpu-max 0 --settle 2 --out "$out/fluid-$name-$round.jsonl" |
      grep '^fluid'
  done
done
