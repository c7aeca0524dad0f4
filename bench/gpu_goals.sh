#!/usr/bin/env bash
# Every GPU speed goal of BENCHMARKS.md in one run, so one device session measures them all side by side:
# the GL copy bandwidth the goals are set against, the small gas (4096 disks, µs per step) and the large
# one (4M disks) with the GPU time of each pass, the fluid at 1M particles (5 iterations) and the wind
# tunnel at 10M molecules. One JSON line per measurement in OUT_DIR, the GPU's name and clocks beside them.
# Usage: bench/gpu_goals.sh [OUT_DIR]  (BENCH=path picks the particlelab-bench binary)
# On a device without Debian's GL packages, carry the binary and the loaders in .gl/ (see bench/gpu_sweep.sh):
#   for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig; export LD_LIBRARY_PATH=$PWD/.gl/lib
#   BENCH=.gl/bin/particlelab-bench bench/gpu_goals.sh "$OUT"
set -euo pipefail
bench="${BENCH:-build/app/particlelab-bench}"
out="${1:-gpu-goals}"
mkdir -p "$out"
if command -v nvidia-smi >/dev/null; then
  nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.max.sm,clocks.max.mem --format=csv >"$out/gpu.txt"
  cat "$out/gpu.txt"
fi
# Gas: the 4096-disk goal (µs per step) at the automatic lanes and at 8, and the 4M goal; each point also
# profiled pass by pass (GPU timestamps, a sync each step).
"$bench" --scenes gas --gas 4096 16384 4194304 --force-lanes 0 1 8 --cpu-max 0 --settle 2 --profile-each \
  --out "$out/gas.jsonl"
# Fluid at 1M particles (the goal) and at 40 000 (where the dependent dispatches set the step).
"$bench" --scenes fluid --fluid 40000 1048576 --cpu-max 0 --settle 2 --out "$out/fluid.jsonl"
# The wind tunnel at 10M molecules (the goal that is met must stay met).
"$bench" --scenes tunnel --tunnel 10000000 --cpu-max 0 --out "$out/tunnel.jsonl"
