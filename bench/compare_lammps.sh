#!/usr/bin/env bash
# Runs gas-seed (4096 disks) and a 262 144-disk gas at the same area fraction in ParticleLab (1 and 2
# threads) and in Debian's LAMMPS (mpirun -np 2), from the identical initial state, and prints
# particle-steps per second and their ratio (medians of REPEATS runs) as a Markdown table.
# Usage: bench/compare_lammps.sh [REPEATS]   (after .ci/build.sh; installs lammps if missing)
set -euo pipefail
cd "$(dirname "$0")/.."
repeats=${1:-3}
cli=./build/app/particlelab-cli
[ -x "$cli" ] || { echo "build first: ./.ci/build.sh" >&2; exit 1; }
if ! command -v lmp >/dev/null; then
  [ "$(id -u)" -eq 0 ] && as_root=() || as_root=(sudo)
  DEBIAN_FRONTEND=noninteractive "${as_root[@]}" apt-get install -y -q --no-install-recommends lammps openmpi-bin
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

k=1000
d=0.01
# Pair table: F = k (d - r) is linear in r, so linear interpolation reproduces it exactly. The inner
# point is tiny because soft disks pass through each other (r can approach 0).
awk -v k=$k -v d=$d 'BEGIN {
  n = 2000; lo = 1e-9; print "# harmonic repulsion"; print "HARMONIC"; print "N " n " R " lo " " d; print "";
  for (i = 1; i <= n; i++) { r = lo + (d - lo) * (i - 1) / (n - 1); printf "%d %.12g %.12g %.12g\n", i, r, 0.5*k*(d-r)^2, k*(d-r) } }' \
  >"$work/harmonic.table"

median() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

# name, particle count, half box side, timed steps
run_case() {
  local name=$1 n=$2 half=$3 steps=$4
  local sets=(--set count_a=$n --set box_width=$((2 * half)) --set box_height=$((2 * half)))
  "$cli" run gas-seed "${sets[@]}" --steps 0 --quiet --dump-initial "$work/init.csv"
  awk -F, -v n=$n -v h=$half 'NR == 1 { next } { x[NR] = $3; y[NR] = $4; vx[NR] = $5; vy[NR] = $6 }
    END { print "ParticleLab initial state\n"; print n " atoms\n1 atom types\n"; print -h " " h " xlo xhi";
          print -h " " h " ylo yhi"; print "-0.5 0.5 zlo zhi\n\nMasses\n\n1 1.0\n\nAtoms # atomic\n";
          for (i = 2; i <= NR; i++) printf "%d 1 %.17g %.17g 0\n", i - 1, x[i], y[i];
          print "\nVelocities\n"; for (i = 2; i <= NR; i++) printf "%d %.17g %.17g 0\n", i - 1, vx[i], vy[i] }' \
    "$work/init.csv" >"$work/data.lmp"

  local ours1=() ours2=() lammps=()
  for r in $(seq "$repeats"); do
    ours1+=("$("$cli" bench gas-seed "${sets[@]}" --steps "$steps" --repeats 1 --threads 1 | sed 's/.*"p_steps_per_s":\([0-9.e+]*\).*/\1/')")
    ours2+=("$("$cli" bench gas-seed "${sets[@]}" --steps "$steps" --repeats 1 --threads 2 | sed 's/.*"p_steps_per_s":\([0-9.e+]*\).*/\1/')")
    loop=$(cd "$work" && OMP_NUM_THREADS=1 mpirun --allow-run-as-root --oversubscribe -np 2 lmp -log none -screen none \
             -in "$OLDPWD/bench/harmonic.lmp" -var data data.lmp -var table harmonic.table -var d $d \
             -var steps "$steps" -var skin 0.003 -echo none -log lammps.log >/dev/null; \
           awk '/^Loop time/ { print $4 }' lammps.log)
    lammps+=("$(awk -v t="$loop" -v n=$n -v s="$steps" 'BEGIN { printf "%.6g", n * s / t }')")
  done
  local m1 m2 ml
  m1=$(printf '%s\n' "${ours1[@]}" | median)
  m2=$(printf '%s\n' "${ours2[@]}" | median)
  ml=$(printf '%s\n' "${lammps[@]}" | median)
  awk -v name="$name" -v m1="$m1" -v m2="$m2" -v ml="$ml" -v s="$steps" 'BEGIN {
    printf "| %s | %d | %.3g | %.3g | %.3g | %.2f |\n", name, s, m1, m2, ml, m2 / ml }'
}

echo "| system | steps | ParticleLab 1 thread | ParticleLab 2 threads | LAMMPS mpirun -np 2 | ratio (2 threads / LAMMPS) |"
echo "|---|---|---|---|---|---|"
run_case "gas-seed, 4096 disks" 4096 1 2000
run_case "262144 disks, same area fraction" 262144 8 200
