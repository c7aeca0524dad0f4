#!/usr/bin/env bash
# The CPU's limits behind BENCHMARKS.md's "Limits": copy bandwidth by working-set size at 1 and 2 threads,
# the cost of an OpenMP parallel region and of a barrier, and the square root and division throughput.
# Usage: bench/machine_limits.sh   (needs g++ with OpenMP; run it in the same window as the benchmarks it
# explains: on a shared VM every one of these figures moves with the load)
set -euo pipefail
cd "$(dirname "$0")"
bin=$(mktemp)
trap 'rm -f "$bin"' EXIT
g++ -O2 -fopenmp -std=c++17 machine_limits.cpp -o "$bin"
grep -m1 'model name' /proc/cpuinfo
uptime
"$bin"
