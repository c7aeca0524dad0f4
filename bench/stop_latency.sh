#!/usr/bin/env bash
# How fast a big wind-tunnel run honours a stop: tunnel-cylinder scaled to N molecules (F_N shrunk and the
# cell grid refined by √ of the ratio along each side, as particlelab-bench scales it), started with
# a row every step, with --snapshot and without, and SIGINT sent once it has written four rows. Prints, per size: the
# molecules, the wall time of a step (between the second and the fourth row), the seconds from the signal
# to the exit, the exit code, the snapshot's size and whether it continues (`run SNAPSHOT --steps 1`).
#
#   bench/stop_latency.sh [BUILD_DIR] [SIZES...]      (default sizes 1e6 1e7 4e7)
set -uo pipefail
build=$(realpath "${1:-build}")
shift || true
sizes=("$@")
[ $# -eq 0 ] && sizes=(1000000 10000000 40000000)
cli="$build/app/particlelab-cli"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
base_molecules=48000 # the preset's at the start (its description)
printf '%-10s %-10s %10s %12s %4s %12s %s\n' molecules cells "step [s]" "stop [s]" rc snapshot continues
for n in "${sizes[@]}"; do
    ratio=$(echo "$n / $base_molecules" | bc -l)
    fn=$(echo "5e14 / $ratio" | sed 's/e/*10^/' | bc -l)
    side=$(echo "sqrt($ratio)" | bc -l)
    # The grid stops refining at the tunnel's cell limit (4194304 cells), as particlelab-bench's scale does.
    side=$(echo "s = $side; m = sqrt(4194304 / 6000); if (s > m) s = m; s" | bc -l)
    cx=$(printf '%.0f' "$(echo "100 * $side" | bc -l)")
    cy=$(printf '%.0f' "$(echo "60 * $side - 0.5" | bc -l)")
    for keep in snapshot none; do
        rm -f "$work"/*
        outputs=(--out "$work/t.csv")
        [ "$keep" = snapshot ] && outputs+=(--snapshot "$work/t.plsnap")
        "$cli" run tunnel-cylinder --set fn="$fn" --set cells_x="$cx" --set cells_y="$cy" --steps 1000000000 \
            --every 1 "${outputs[@]}" --quiet 2>"$work/err" &
        pid=$!
        rows() { { wc -l <"$work/t.csv"; } 2>/dev/null || echo 0; }
        while [ "$(rows)" -lt 3 ] && kill -0 "$pid" 2>/dev/null; do sleep 0.02; done # header + 2 rows
        second=$(date +%s.%N)
        while [ "$(rows)" -lt 5 ] && kill -0 "$pid" 2>/dev/null; do sleep 0.02; done
        step=$(echo "($(date +%s.%N) - $second) / 2" | bc -l)
        sent=$(date +%s.%N)
        kill -INT "$pid"
        wait "$pid"
        rc=$?
        took=$(echo "$(date +%s.%N) - $sent" | bc)
        molecules=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "particles" || $i == "molecules") c = i }
                             NR > 1 && c { last = $c } END { print last }' "$work/t.csv")
        snap=$(stat -c %s "$work/t.plsnap" 2>/dev/null || echo 0)
        cont=-
        if [ "$keep" = snapshot ]; then
            if "$cli" run "$work/t.plsnap" --steps 1 --quiet >/dev/null 2>&1; then cont=yes; else cont=no; fi
        fi
        printf '%-10s %-10s %10.2f %12.2f %4s %12s %s  (%s)\n' "${molecules:-$n}" "${cx}x${cy}" "$step" "$took" \
            "$rc" "$snap" "$cont" "$(grep -v ': warning: ' "$work/err" | tail -n 1 | head -c 160)"
    done
done
