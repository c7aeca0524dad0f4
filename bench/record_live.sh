#!/usr/bin/env bash
# The live scene while the app records (issue 30): PRESET runs SECONDS under Xvfb (Mesa llvmpipe where
# there is no GPU) without and with `--record` (a clip at the scene's watchable pace, 1280×720, 30
# frames/s), alternately, for each binary, on a quiet machine and beside a busy loop that holds one core.
# Prints each run's fps, steps/s and clip frames (read back with ffprobe; "taken": the app's own count),
# then per binary and load the medians and the ratio of steps/s with recording to without.
# Usage: bench/record_live.sh [ROUNDS] [SECONDS] [PRESET] [BINARY...]   (default binary:
# build/app/particlelab; LOADS=quiet runs only the quiet half)
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=${1:-3}
seconds=${2:-6}
preset=${3:-gas-classroom}
shift $(($# < 3 ? $# : 3))
binaries=("$@")
[ ${#binaries[@]} -gt 0 ] || binaries=(build/app/particlelab)
loads=${LOADS:-quiet busy}
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}
chmod 700 "$XDG_RUNTIME_DIR"
work=$(mktemp -d)
busy=""
stop_busy() { [ -z "$busy" ] || kill "$busy" 2>/dev/null || true; busy=""; }
trap 'stop_busy; rm -rf "$work"' EXIT

field() { sed -n "s/.*\"$1\": \([0-9.]*\).*/\1/p"; }

for load in $loads; do
  [ "$load" = busy ] && { sh -c 'while :; do :; done' & busy=$!; }
  for round in $(seq 1 "$rounds"); do
    for binary in "${binaries[@]}"; do
      for mode in plain recording; do
        clip=$work/clip.mp4
        rm -f "$clip"
        record=()
        [ "$mode" = recording ] && record=(--record "$clip")
        home=$(mktemp -d)
        line=$(HOME=$home timeout $((seconds + 60)) xvfb-run -a -s "-screen 0 1280x800x24" "$binary" \
          "$preset" --backend cpu --measure-fps "$seconds" "${record[@]}" 2>/dev/null | grep '"fps"' ||
          echo '{"fps": 0, "steps_per_second": 0}')
        rm -rf "$home"
        frames=0
        [ "$mode" = recording ] && [ -s "$clip" ] && frames=$(ffprobe -v error -count_frames \
          -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 "$clip")
        fps=$(echo "$line" | field fps)
        steps=$(echo "$line" | field steps_per_second)
        taken=$(echo "$line" | field clip_frames)
        echo "$load $round $binary $mode fps $fps steps/s $steps clip_frames $frames taken ${taken:-0} load_avg $(cut -d' ' -f1 /proc/loadavg)" |
          tee -a "$work/log"
      done
    done
  done
  stop_busy
done

echo "medians over $rounds rounds ($preset, ${seconds} s a run):"
for load in $loads; do
  for binary in "${binaries[@]}"; do
    awk -v load="$load" -v bin="$binary" '
      function median(a, n,   i, j, t) { for (i = 1; i <= n; ++i) for (j = i + 1; j <= n; ++j)
          if (a[j] < a[i]) { t = a[i]; a[i] = a[j]; a[j] = t }
        return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2 }
      $1 == load && $3 == bin && $4 == "plain" { pf[++np] = $6; ps[np] = $8 }
      $1 == load && $3 == bin && $4 == "recording" { rf[++nr] = $6; rs[nr] = $8; rc[nr] = $10 }
      END { p = median(ps, np); r = median(rs, nr)
        printf "%s, %s: without %.1f fps %.0f steps/s; recording %.1f fps %.0f steps/s, %.0f clip frames; %.2fx\n",
          load, bin, median(pf, np), p, median(rf, nr), r, median(rc, nr), (p > 0 ? r / p : 0) }' "$work/log"
  done
done
