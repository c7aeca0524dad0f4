#!/usr/bin/env bash
# The signal matrix: each terminating signal a user can send from a terminal or a session manager (INT,
# TERM, HUP, QUIT, USR1, USR2), sent to each long-running subcommand of particlelab-cli and to
# particlelab-bench while it works. One line per case: the exit code (128 + N expected), the one line the
# program said, and which outputs are on disk and read back whole.
#
#   bench/signal_matrix.sh [BUILD_DIR] > matrix.txt
#
# "said" is the program's last line on stderr (the preset's own warnings left out). A case waits until the
# program has started its work (its first output row, or a fixed settle time for
# the subcommands that write nothing before the end), then sends the signal.
set -uo pipefail
build=$(realpath "${1:-build}")
cli="$build/app/particlelab-cli" bench="$build/app/particlelab-bench"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
signals=(INT TERM HUP QUIT USR1 USR2)

# Waits until FILE has at least LINES lines or SECONDS have passed.
wait_for_lines() {
    local file=$1 lines=$2 seconds=$3 waited=0
    while [ "$({ wc -l <"$file"; } 2>/dev/null || echo 0)" -lt "$lines" ] && [ "$waited" -lt $((seconds * 10)) ]; do
        sleep 0.1
        waited=$((waited + 1))
    done
}

# A file's state after the signal: missing, empty, or its line count (and, for a CSV, whether every row has
# the header's number of columns).
describe() {
    local file=$1
    [ -e "$file" ] || { echo "missing"; return; }
    [ -s "$file" ] || { echo "empty"; return; }
    case "$file" in
    *.csv)
        awk -F, 'NR == 1 { n = NF } NF != n && !/^#/ { bad++ } END { printf "%d rows%s", NR, bad ? ", " bad " ragged" : ", whole" }' "$file" ;;
    *.plsnap)
        if "$cli" run "$file" --steps 1 --quiet >/dev/null 2>&1; then echo "continues"; else echo "unreadable"; fi ;;
    *.pdf)
        if pdftotext "$file" - >/dev/null 2>&1; then echo "reads"; else echo "unreadable"; fi ;;
    *.mp4 | *.webm | *.gif)
        if ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 "$file" >"$work/frames" 2>"$work/probe" && [ ! -s "$work/probe" ]; then
            echo "$(cat "$work/frames") frames, decodes"
        else echo "decode errors"; fi ;;
    *) echo "$(wc -l <"$file") lines" ;;
    esac
}

# case NAME SIGNAL WAIT_FILE WAIT_LINES SETTLE OUTPUTS... -- COMMAND...
run_case() {
    local name=$1 signal=$2 wait_file=$3 wait_lines=$4 settle=$5
    shift 5
    local outputs=()
    while [ "$1" != "--" ]; do outputs+=("$1"); shift; done
    shift
    rm -f "${outputs[@]}" "$work/err"
    "$@" >"$work/stdout" 2>"$work/err" &
    local pid=$!
    if [ -n "$wait_file" ]; then wait_for_lines "$wait_file" "$wait_lines" 60; fi
    sleep "$settle"
    local sent
    sent=$(date +%s.%N)
    kill -s "$signal" "$pid"
    wait "$pid"
    local rc=$?
    local took
    took=$(echo "$(date +%s.%N) - $sent" | bc)
    local kept=""
    for o in "${outputs[@]}"; do kept+=" $(basename "$o"): $(describe "$o");"; done
    printf '%-8s SIG%-4s rc %3s  %5.2f s  said: %s |%s\n' "$name" "$signal" "$rc" "$took" \
        "$(grep -v ': warning: ' "$work/err" | tail -n 1 | head -c 160)" "$kept"
}

for s in "${signals[@]}"; do
    run_case run "$s" "$work/s.csv" 4 0 "$work/s.csv" "$work/h.csv" "$work/final.csv" "$work/end.plsnap" -- \
        "$cli" run gas-classroom --steps 1000000000 --every 5 --out "$work/s.csv" --histogram "$work/h.csv" \
        --dump-final "$work/final.csv" --snapshot "$work/end.plsnap" --quiet --threads 1
    run_case tunnel "$s" "$work/t.csv" 3 0 "$work/t.csv" "$work/fields.csv" "$work/surf.csv" "$work/t.plsnap" -- \
        "$cli" run tunnel-cylinder --steps 1000000000 --every 20 --out "$work/t.csv" --fields "$work/fields.csv" \
        --surface "$work/surf.csv" --snapshot "$work/t.plsnap" --quiet --threads 1
    run_case report "$s" "" 0 3 "$work/r.pdf" -- \
        "$cli" report gas-classroom --steps 1000000000 --out "$work/r.pdf" --threads 1
    run_case record "$s" "" 0 4 "$work/c.mp4" -- \
        "$cli" record gas-classroom --seconds 600 --size 320x240 --out "$work/c.mp4" --quiet --threads 1
    run_case bench "$s" "" 0 3 -- \
        "$cli" bench gas-write-up --steps 200 --repeats 1000 --threads 1
    run_case gpubench "$s" "$work/b.jsonl" 1 0.5 "$work/b.jsonl" -- \
        "$bench" --scenes gas --gas 1024 4096 --cpu-max 0 --seconds 60 --out "$work/b.jsonl"
done
