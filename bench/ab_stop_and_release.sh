#!/bin/bash
# A/B of two particlelab-cli builds, interleaved, 3 rounds: a 1e7-molecule tunnel run of 12 steps (set-up
# included; its steps are long enough that a stop may undo them, so the step start is kept) and the
# fluid-obstacle bench (seconds for 400 steps, median of 3). Usage: OLD_CLI NEW_CLI.
OLD=${1:?usage: bench/ab_stop_and_release.sh OLD_CLI NEW_CLI}
NEW=${2:?usage: bench/ab_stop_and_release.sh OLD_CLI NEW_CLI}
for round in 1 2 3; do
  for b in old new; do
    C=$OLD; [ $b = new ] && C=$NEW
    s=$(date +%s.%N); $C run tunnel-cylinder --set fn=2.4e12 --steps 12 --every 1000 --threads 2 --quiet >/dev/null 2>&1; e=$(date +%s.%N)
    echo "tunnel1e7 $b $(echo "$e - $s" | bc)"
    r=$($C bench fluid-obstacle --steps 400 --repeats 3 --threads 2 2>/dev/null | python3 -c 'import json,sys; print(json.load(sys.stdin)["seconds"])')
    echo "fluid-obstacle $b $r"
  done
done
