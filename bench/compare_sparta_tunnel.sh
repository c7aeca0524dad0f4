#!/usr/bin/env bash
# The wind tunnel against SPARTA on one case: a preset (default tunnel-cylinder: Mach 10 argon past a half
# cylinder, ~48 000 molecules, collisions on) exported with `export sparta` and run in SPARTA serial and
# in ParticleLab's CPU model (1 and 2 threads), repeats interleaved; prints the particle-moves per second
# of each and the ratios (medians of REPEATS), then the physics of one longer run in both codes: drag
# per unit depth, collisions per particle and step, and the stagnation-line density and temperature.
# Usage: bench/compare_sparta_tunnel.sh [REPEATS] [STEPS]   (from a built tree)
# SPARTA=path/to/spa_serial (default: spa_serial on PATH; build it from github.com/sparta/sparta with
# `cd src && make serial`), CLI=path picks another particlelab-cli, PRESET=name another tunnel preset,
# PHYSICS_STEPS=N the length of the physics run (default 3000; the fields window opens at sample_start).
# REPEATS=0 skips the speed part, PHYSICS_STEPS=0 the physics part; SEED=N seeds both codes' physics run.
set -euo pipefail
cd "$(dirname "$0")/.."
repeats=${1:-3}
steps=${2:-1000}
cli=${CLI:-./build/app/particlelab-cli}
sparta=${SPARTA:-$(command -v spa_serial || true)}
preset=${PRESET:-tunnel-cylinder}
physics_steps=${PHYSICS_STEPS:-3000}
seed=(${SEED:+--seed "$SEED"})
[ -x "$cli" ] || { echo "build first: cmake --build build --target particlelab-cli" >&2; exit 1; }
[ -n "$sparta" ] && [ -x "$sparta" ] || { echo "no SPARTA: set SPARTA=path/to/spa_serial" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
param() { sed -n "s/.*\"$1\": *\([-0-9.e+]*\).*/\1/p" "$work/physics/particlelab.json" | head -1; }
median() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
echo "machine: $(nproc) cores, load before: $(cut -d' ' -f1-3 /proc/loadavg); $(date -u +%FT%TZ)"

if [ "$repeats" -gt 0 ]; then
# --- Speed. `bench` warms up for min(STEPS/10 + 1, 200) steps and then times STEPS; SPARTA gets the
# same two runs (the second one's "Loop time" and "Particle moves" count). Both sample the grid fields
# during the timed steps (sample_start = the warm-up) and both collide.
warm=$((steps / 10 + 1 < 200 ? steps / 10 + 1 : 200))
sets=(--set sample_start=$warm)
"$cli" export sparta "$preset" "${sets[@]}" --steps $((warm + steps)) --every $((warm + steps)) \
  --out "$work/timing" --quiet
# The force stays sampled but out of the stats rows: the end of the warm-up run is no force interval.
sed -i -e "s/^run .*/run             $warm\nrun             $steps/" -e 's/ c_force\[1\] c_force\[2\]//' \
  "$work/timing/in.sparta"
sparta_rate() {
  (cd "$work/timing" && "$sparta" -in in.sparta -echo none -screen none >/dev/null)
  awk '/^Loop time of/ { t = $4 } /^Particle moves/ { m = $4 } /^Collide occurs/ { c = $4 }
       END { printf "%.6g %.6g\n", m / t, c / m }' "$work/timing/log.sparta"
}
ours_rate() { "$cli" bench "$preset" "${sets[@]}" --steps "$steps" --repeats 1 --threads "$1" 2>/dev/null |
  sed 's/.*"particles":\([0-9]*\).*"p_steps_per_s":\([0-9.e+]*\).*/\2 \1/'; }
theirs=() ours1=() ours2=() sparta_coll=""
for r in $(seq "$repeats"); do
  read -r rate coll < <(sparta_rate)
  theirs+=("$rate")
  sparta_coll=$coll
  read -r rate particles < <(ours_rate 1)
  ours1+=("$rate")
  read -r rate particles < <(ours_rate 2)
  ours2+=("$rate")
done
ms=$(printf '%s\n' "${theirs[@]}" | median)
m1=$(printf '%s\n' "${ours1[@]}" | median)
m2=$(printf '%s\n' "${ours2[@]}" | median)
echo "raw particle-moves/s: SPARTA ${theirs[*]}; ParticleLab 1 thread ${ours1[*]}; 2 threads ${ours2[*]}"
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg); SPARTA collisions per particle-move $sparta_coll;" \
  "ParticleLab ends with $particles particles"
echo
echo "| case | timed steps | SPARTA serial | ParticleLab 1 thread | ParticleLab 2 threads | 1 thread / SPARTA | 2 threads / SPARTA |"
echo "|---|---|---|---|---|---|---|"
awk -v p="$preset" -v s="$steps" -v a="$ms" -v b="$m1" -v c="$m2" \
  'BEGIN { printf "| %s | %d | %.3g | %.3g | %.3g | %.2f | %.2f |\n", p, s, a, b, c, b / a, c / a }'
fi

[ "$physics_steps" -gt 0 ] || exit 0
# --- Physics: one run of PHYSICS_STEPS in each code, the fields averaged from the preset's sample_start
# to the end, the forces every 50 steps.
every=50
"$cli" export sparta "$preset" "${seed[@]}" --steps "$physics_steps" --every $every --out "$work/physics" --quiet
(cd "$work/physics" && "$sparta" -in in.sparta -echo none -screen none >/dev/null)
"$cli" run "$preset" "${seed[@]}" --steps "$physics_steps" --every $every --quiet --out "$work/series.csv" \
  --fields "$work/fields.csv" --surface "$work/surface.csv"
start=$(param sample_start)
echo
echo "physics ($preset, $physics_steps steps, window from step $start${SEED:+, seed $SEED}):"
awk -F, -v s="$start" 'NR == 1 { for (k = 1; k <= NF; k++) col[$k] = k; next }
  $col["step"] > s { d += $col["drag"]; q += $col["drag"] ^ 2; l += $col["lift"]; n++ }
  END { printf "%.6g %.6g %.3g\n", d / n, l / n, sqrt((q / n - (d / n) ^ 2) / (n - 1)) }' \
  "$work/surface.csv" >"$work/ours_force"
awk -v s="$start" '/^Step/ { for (k = 1; k <= NF; k++) col[$k] = k; on = 1; next } /^Loop/ { on = 0 }
  on && $1 > s { d += $col["c_force[1]"]; q += $col["c_force[1]"] ^ 2; l += $col["c_force[2]"]
    c += $col["Ncoll"] / $col["Np"]; n++ }
  END { printf "%.6g %.6g %.6g %.3g\n", d / n, l / n, c / n, sqrt((q / n - (d / n) ^ 2) / (n - 1)) }' \
  "$work/physics/log.sparta" >"$work/sparta_force"
# (the series has time, not step: step = time / dt)
awk -F, -v s="$start" -v dt="$(param dt)" 'NR == 1 { for (k = 1; k <= NF; k++) col[$k] = k; next }
  $col["time"] / dt > s + 0.5 { c += $col["collisions"] / $col["particles"]; n++ } END { printf "%.6g\n", c / n }' \
  "$work/series.csv" >"$work/ours_coll"
read -r od ol oe <"$work/ours_force"
read -r sd sl sc se <"$work/sparta_force"
oc=$(cat "$work/ours_coll")
# The drag's standard error from the spread of its every-50-step means (about one flow time past the
# body each, so nearly independent).
echo "| quantity (window mean) | ParticleLab | SPARTA | ParticleLab / SPARTA |"
echo "|---|---|---|---|"
awk -v a="$od" -v b="$sd" -v ea="$oe" -v eb="$se" \
  'BEGIN { printf "| drag per unit depth [N/m] | %.4g ± %.2g | %.4g ± %.2g | %.3f |\n", a, ea, b, eb, a / b }'
awk -v a="$ol" -v b="$sl" 'BEGIN { printf "| lift per unit depth [N/m] | %.4g | %.4g | |\n", a, b }'
awk -v a="$oc" -v b="$sc" 'BEGIN { printf "| collisions per particle and step | %.4g | %.4g | %.3f |\n", a, b, a / b }'

# The stagnation line: the cells along the lowest row (the symmetry plane), from the inflow to the body's
# front, every other cell; n / n_inf and T [K] in both codes. SPARTA's T from its averaged moments:
# T = m / (3k) (<vx²> + <vy²> + <vz²> − u² − v² − w²).
n_inf=$(param stream_density)
mass_over_k=$(awk -v u="$(param mass_amu)" 'BEGIN { printf "%.10g", u * 1.66053906660e-27 / 1.380649e-23 }')
# The first body's front: its centre x minus its radius (particlelab.json lists "x" before "radius").
front=$(awk -F': *' '/"obstacles"/ { b = 1 } b && /"x"/ { x = $2 + 0 } b && /"radius"/ { print x - $2; exit }' \
  "$work/physics/particlelab.json")
# grid.sparta holds the step-0 snapshot and the last one: the last one's cells win.
awk -v mk="$mass_over_k" '/^ITEM: CELLS/ { f = 1; next } /^ITEM:/ { f = 0 } f && NF == 14 && $3 == 0 {
    line[$1] = sprintf("%.6f %.6g %.6g", ($2 + $4) / 2, $8, mk / 3 * ($12 + $13 + $14 - $9 * $9 - $10 * $10 - $11 * $11)) }
  END { for (c in line) print line[c] }' "$work/physics/grid.sparta" | LC_ALL=C sort >"$work/sparta_line"
awk -F, 'NR > 1 && $2 == 0 { printf "%.6f %.6g %.6g\n", $3, $5, $8 }' "$work/fields.csv" | LC_ALL=C sort >"$work/ours_line"
# The sampling noise of one cell's n: the spread of n / n_inf over the cells ahead of x = front / 2,
# where both codes hold the free stream.
noise_ours=$(awk -F, -v f="$front" -v n="$n_inf" 'NR > 1 && $3 < f / 2 { v = $5 / n; m += v; q += v * v; c++ }
  END { m /= c; printf "%.3f", sqrt(q / c - m * m) }' "$work/fields.csv")
noise_sparta=$(awk -v f="$front" -v n="$n_inf" '/^ITEM: TIMESTEP/ { getline; last = $1 } { print last, $0 }' \
  "$work/physics/grid.sparta" | awk -v s="$physics_steps" -v f="$front" -v n="$n_inf" '$1 == s && NF == 15 &&
  ($3 + $5) / 2 < f / 2 { v = $9 / n; m += v; q += v * v; c++ } END { m /= c; printf "%.3f", sqrt(q / c - m * m) }')
echo
echo "stagnation line (lowest row of cells), n_inf = $n_inf m^-3, body front at x = $front m; one cell's"
echo "n / n_inf scatters by $noise_ours (ParticleLab) and $noise_sparta (SPARTA) in the free stream ahead of x = front / 2:"
echo "| x [m] | n/n_inf ParticleLab | n/n_inf SPARTA | T [K] ParticleLab | T [K] SPARTA |"
echo "|---|---|---|---|---|"
LC_ALL=C join "$work/ours_line" "$work/sparta_line" | sort -g |
  awk -v n="$n_inf" -v f="$front" '$1 < f { if (k++ % 2 == 0) printf "| %.4f | %.3f | %.3f | %.0f | %.0f |\n", $1, $2 / n, $4 / n, $3, $5 }'
