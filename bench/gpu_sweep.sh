#!/usr/bin/env bash
# The GPU benchmark sweep of BENCHMARKS.md ("GPU backends"): gas 4 096 … 4 194 304 disks, fluid
# 10 000 … 1 048 576 particles (5 iterations), CPU reference up to 65 536, GL copy bandwidth and a
# per-pass profile of the largest gas, one JSON line per measurement.
#
# On a machine with a GL driver but no Debian packages (the H100 device), bring the binary and the
# GL loader libraries along, e.g. in .gl/: particlelab-bench from build/app, libgomp.so.1, and the
# .debs of libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2 libepoxy0, then run there:
#   for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig; export LD_LIBRARY_PATH=$PWD/.gl/lib
#   BENCH=.gl/bin/particlelab-bench bench/gpu_sweep.sh results.jsonl
set -euo pipefail
bench="${BENCH:-build/app/particlelab-bench}"
out="${1:-gpu-sweep.jsonl}"
shift $(($# > 0 ? 1 : 0)) # further arguments go to particlelab-bench (e.g. --force-lanes 0 1 8)
command -v nvidia-smi >/dev/null && nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader
"$bench" --out "$out" "$@"
