#!/usr/bin/env bash
# Soak: each scene for many steps in one process, reporting its resident memory early and at the end
# (flat means nothing accumulates) and how far its energy moved. Usage (from a built tree):
#   bench/soak.sh [steps] [fluid-steps]     (defaults 1000000 and 100000: the fluid steps at ~700/s)
#   SCENES="dsmc-write-up fluid-dam-break" bench/soak.sh   (a subset of the four scenes)
set -euo pipefail
cd "$(dirname "$0")/.."
cli=${CLI:-build/app/particlelab-cli}
steps=${1:-1000000}
fluid_steps=${2:-100000}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

# Runs the CLI in the background, samples VmRSS every 0.2 s, prints the first sample taken after 2 s and
# the last one before the process ended, then the first and last total energy of the series.
soak() { # name, energy column, CLI arguments…
  local name=$1 column=$2
  shift 2
  "$cli" run "$@" --out "$out/$name.csv" 2>/dev/null &
  local pid=$! start="" last="" t0=$SECONDS
  while kill -0 "$pid" 2>/dev/null; do
    rss=$(awk '/VmRSS/ {print $2}' "/proc/$pid/status" 2>/dev/null || true)
    [ -n "$rss" ] && last=$rss
    [ -z "$start" ] && [ $((SECONDS - t0)) -ge 2 ] && start=$last
    sleep 0.2
  done
  wait "$pid"
  awk -F, -v name="$name" -v col="$column" -v start="${start:-$last}" -v end="$last" -v secs=$((SECONDS - t0)) '
    NR == 1 { for (i = 1; i <= NF; ++i) if ($i == col) c = i; next }
    NR == 2 { first = $c; s0 = $1 }
    { lastE = $c; s1 = $1 }
    END { change = first != 0 ? sprintf("%+.3f %%", 100 * (lastE - first) / first) : "from rest"
          printf "%s: steps %d to %d in %d s, RSS %.1f MB early, %.1f MB at the end, %s %.6g to %.6g (%s)\n",
                 name, s0, s1, secs, start / 1024, end / 1024, col, first, lastE, change }' \
    "$out/$name.csv"
}

every=$((steps / 100))
scenes=${SCENES:-gas-classroom gas-write-up dsmc-write-up fluid-dam-break} # a subset: SCENES="dsmc-write-up" …
for scene in $scenes; do
  case $scene in
  gas-*) soak "$scene" total "$scene" --steps "$steps" --every "$every" --threads 2 ;;
  dsmc-*) soak "$scene" T "$scene" --steps "$steps" --every "$every" ;;
  fluid-*) soak "$scene" kinetic "$scene" --steps "$fluid_steps" --every $((fluid_steps / 100)) --threads 2 ;;
  esac
done
