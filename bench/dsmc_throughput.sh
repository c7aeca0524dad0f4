#!/usr/bin/env bash
# DSMC throughput: the write-up run's wall time, and a 200 000-particle collisional cell in particle-steps
# and collisions per second, one core. Usage: bench/dsmc_throughput.sh [repeats]  (from a built tree)
set -euo pipefail
cd "$(dirname "$0")/.."
cli=build/app/particlelab-cli
repeats=${1:-5}
median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }

# 1. The whole write-up run as a user starts it: process start, preset, initial state, 500 steps sampled
#    every step, CSV written.
times=()
for _ in $(seq "$repeats"); do
  start=$(date +%s.%N)
  "$cli" run dsmc-write-up --quiet --out /tmp/dsmc-write-up-series.csv --histogram /tmp/dsmc-write-up-hist.csv
  times+=("$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN {print b - a}')")
done
echo "dsmc-write-up whole run (500 steps, 2000 particles): median $(printf '%s\n' "${times[@]}" | median) s"
"$cli" bench dsmc-write-up --steps 500 --repeats "$repeats" --threads 1

# 2. 200 000 particles at the write-up's density (F_N scaled down 100×), ν Δt ≈ 0.04.
big=(--set count_a=100000 --set count_b=100000 --set fn=5e6 --set run_steps=0)
line=$("$cli" bench dsmc-write-up "${big[@]}" --steps 500 --repeats "$repeats" --threads 1)
echo "$line"
"$cli" run dsmc-write-up "${big[@]}" --steps 500 --every 500 --quiet --out /tmp/dsmc-big.csv
seconds=$(echo "$line" | sed 's/.*"seconds":\([0-9.e-]*\).*/\1/')
per_particle=$(tail -1 /tmp/dsmc-big.csv | awk -F, '{print $NF}')
echo "200k cell: collisions per particle in 500 steps = $per_particle;" \
  "collisions/s = $(awk -v c="$per_particle" -v s="$seconds" 'BEGIN {printf "%.3g", c * 200000 / 2 / s}')"
