#!/usr/bin/env bash
# Bit-identity of the CPU reference across a change: runs two builds of particlelab-cli on the same
# cases (gas: every integrator, thermal walls, the mixture, obstacles, a large gas; fluid: the filled tank
# with and without XSPH and vorticity, an odd count, the dam break, the obstacle pool; the DSMC cell; the
# wind tunnel's cylinder and shock tube) at 1 and 2 threads,
# and compares the series, the final dumps and the snapshots byte for byte. Prints one line per case and
# exits 1 if any output differs. Usage: bench/bit_identity.sh OLD_CLI NEW_CLI [work dir]
set -uo pipefail
old=${1:?usage: bench/bit_identity.sh OLD_CLI NEW_CLI [work dir]}
new=${2:?usage: bench/bit_identity.sh OLD_CLI NEW_CLI [work dir]}
work=${3:-$(mktemp -d)}
mkdir -p "$work"
here=$(cd "$(dirname "$0")/.." && pwd)

# Presets with obstacles, written next to the outputs in schema 2, which builds before and after preset
# schema 3 both read (gas-write-up has no key that schema 3 renamed).
sed -e 's/"obstacles": \[\]/"obstacles": [{"shape": "disc", "x": 0.2, "y": 0.1, "radius": 0.15}, {"shape": "box", "x": -0.5, "y": -0.4, "width": 0.3, "height": 0.2}]/' \
  -e 's/"schema": 3,/"schema": 2,/' "$here/resources/presets/gas/gas-write-up.json" >"$work/gas-obstacles.json"

failures=0
renamed='s/"name": *"dsmc-\(cylinder\|free-molecular-cylinder\|shock-tube\|couette\)"/"name":"tunnel-\1"/; s/"name": *"\(gas\|fluid\|dsmc\)-seed"/"name":"\1-write-up"/'
# A snapshot embeds its preset in its build's newest schema: schema 2 reads in the words of schema 3
# (docs/presets.md, "Schema 3"), so a build before it and one after compare.
schema3='s/"schema":2,/"schema":3,/; /"model":"\(gas\|fluid\)"/s/"tool_speed":/"tool_speed_factor":/;
/"model":"gas"/s/"piston_speed":/"piston_speed_factor":/; s/"cross_section":"seed"/"cross_section":"inverse-root"/;
s/"kernel":"seed-3d"/"kernel":"3d"/'
check() { # name, then the run arguments
  local name=$1
  shift
  for threads in 1 2; do
    for build in old new; do
      local cli=$old
      [ "$build" = new ] && cli=$new
      local dir="$work/$name-$threads-$build"
      mkdir -p "$dir"
      if ! "$cli" run "$@" --threads "$threads" --quiet --out "$dir/series.csv" --dump-final "$dir/final.csv" \
        --snapshot "$dir/snapshot.json" >"$dir/log" 2>&1; then
        echo "$name, $threads thread(s): the $build build failed (see $dir/log)"
        failures=$((failures + 1))
        continue 2
      fi
    done
    local differ=""
    for f in series.csv final.csv snapshot.json; do
      # A snapshot names its preset: the tunnel's old names read as the new ones (docs/architecture.md).
      cmp -s <(sed -e "$renamed" -e "$schema3" "$work/$name-$threads-old/$f") \
        <(sed -e "$renamed" -e "$schema3" "$work/$name-$threads-new/$f") || differ="$differ $f"
    done
    if [ -z "$differ" ]; then
      echo "$name, $threads thread(s): identical"
    else
      echo "$name, $threads thread(s): DIFFERENT:$differ"
      failures=$((failures + 1))
    fi
  done
}

# Presets by their names since preset schema 3 (both builds must know them; the snapshots of a build
# from before the renames are read through the names' sed above).
for integrator in velocity-verlet symplectic-euler explicit-euler forest-ruth rk4; do
  check "gas-write-up-$integrator" gas-write-up --steps 2000 --every 50 --set integrator=$integrator
done
check gas-write-up-thermal gas-write-up --steps 2000 --every 50 --set wall_mode=thermal
check gas-classroom gas-classroom --steps 2000 --every 50
check gas-mixture gas-mixture --steps 2000 --every 50
check gas-obstacles "$work/gas-obstacles.json" --steps 2000 --every 50
check gas-65536 gas-write-up --steps 200 --every 20 --set count_a=65536 --set box_width=8 --set box_height=8
check fluid-write-up-filled fluid-write-up --steps 600 --every 20 --set fill_x1=79.2 --set fill_y1=29.5
check fluid-write-up-xsph-vorticity fluid-write-up --steps 600 --every 20 --set fill_x1=79.2 --set fill_y1=29.5 \
  --set xsph=0.01 --set vorticity=0.5
check fluid-write-up-odd-2449 fluid-write-up --steps 300 --every 20 --set fill_x1=70.1 --set fill_y1=27.5 --set xsph=0.02 --set vorticity=0.2
check fluid-dam-break fluid-dam-break --steps 300 --every 10
check fluid-obstacle fluid-obstacle --steps 300 --every 10
check dsmc-write-up dsmc-write-up --steps 200 --every 20
check dsmc-bkw dsmc-bkw --steps 200 --every 20
check dsmc-planar-beams dsmc-planar-beams --steps 200 --every 20
check tunnel-cylinder tunnel-cylinder --steps 60 --every 10
check tunnel-shock-tube tunnel-shock-tube --steps 150 --every 15

echo "outputs in $work"
[ "$failures" -eq 0 ]
