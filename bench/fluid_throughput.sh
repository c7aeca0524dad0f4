#!/usr/bin/env bash
# Fluid throughput: the write-up's tank filled to its 3000-particle cap, and the dam break, in steps/s and
# particle-steps/s at 1 and 2 threads (median of the repeats). Usage: bench/fluid_throughput.sh [repeats]
# (from a built tree). CLI=path runs another build (a copy kept from before a change, say) through the
# same script, so before and after can be run alternately in one session on a shared machine.
set -euo pipefail
cd "$(dirname "$0")/.."
cli=${CLI:-build/app/particlelab-cli}
repeats=${1:-5}

report() { # name, then the bench arguments
  local name=$1
  shift
  for threads in 1 2; do
    line=$("$cli" bench "$@" --repeats "$repeats" --threads "$threads")
    echo "$line"
    echo "$line" | awk -v name="$name" -v t="$threads" -F'[:,]' '{
      for (i = 1; i < NF; ++i) { if ($i == "\"steps\"") steps = $(i + 1); if ($i == "\"seconds\"") s = $(i + 1);
                                  if ($i == "\"p_steps_per_s\"") p = $(i + 1) }
      printf "%s, %d thread(s): %.0f steps/s, %.3g particle-steps/s\n", name, t, steps / s, p }'
  done
}

# The write-up as written (5 iterations, Δt = 1/20, ε = 100) with a 79.2 × 29.5 block of 2970 particles at
# 0.8 h: it implodes to the write-up's rest density and settles on the floor within the 2000 steps.
report "fluid-write-up, 2970 particles" fluid-write-up --set fill_x1=79.2 --set fill_y1=29.5 --steps 2000
# The dam break as the preset runs it: 1250 particles, 300 steps.
report "fluid-dam-break, 1250 particles" fluid-dam-break --steps 300
