#!/usr/bin/env bash
# The GPU gas's force pass with and without shared-memory tiles (gas_forces.comp), side by side in one
# binary: the goal sizes (4096 and 4 194 304 disks), tiles on and off in turn within each of ROUNDS
# rounds, then one round profiled pass by pass with the share of work groups that used a tile.
# Usage: bench/gpu_gas_tiles.sh OUT_DIR ROUNDS  (BENCH=path picks the particlelab-bench binary)
# On the device, with the binary and GL loaders carried in .gl/ (bench/gpu_sweep.sh):
#   for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig; export LD_LIBRARY_PATH=$PWD/.gl/lib
#   BENCH=.gl/bin/particlelab-bench bench/gpu_gas_tiles.sh "$OUT" 3
set -euo pipefail
bench="${BENCH:-build/app/particlelab-bench}"
out="$1" rounds="$2"
mkdir -p "$out"
command -v nvidia-smi >/dev/null && nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader |
  tee "$out/gpu.txt"
for round in $(seq 1 "$rounds"); do
  echo "round $round"
  "$bench" --scenes gas --gas 4096 4194304 --force-tiles on off --cpu-max 0 --settle 2 \
    --out "$out/gas-$round.jsonl" | grep '^gas'
done
"$bench" --scenes gas --gas 4096 4194304 --force-tiles on off --cpu-max 0 --settle 1 --profile-each \
  --out "$out/gas-profile.jsonl" | grep '^gas'
