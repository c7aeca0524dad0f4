#!/usr/bin/env bash
# Throughput of an exported gas: `particlelab-cli export lammps` writes a 262 144-disk gas at gas-write-up's
# area fraction (box [−8, 8]²), LAMMPS runs the deck on 1 and 2 MPI ranks, and ParticleLab's CPU model
# runs the same gas on 1 and 2 threads. Prints particle-steps per second (medians of REPEATS runs) as
# a Markdown table row. Usage: bench/lammps_export_throughput.sh [REPEATS] [STEPS]  (after .ci/build.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
repeats=${1:-3}
steps=${2:-200}
cli=./build/app/particlelab-cli
[ -x "$cli" ] || { echo "build first: ./.ci/build.sh" >&2; exit 1; }
command -v lmp >/dev/null || { echo "needs lmp and mpirun: apt install lammps openmpi-bin" >&2; exit 1; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
n=262144
sets=(--set count_a=$n --set box_width=16 --set box_height=16)
# Thermo and dumps only at the start: the timed loop is the dynamics alone, as in `bench`.
"$cli" export lammps gas-write-up "${sets[@]}" --steps "$steps" --every 1000000000 --out "$work" --quiet

median() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
lammps_rate() { # ranks
  (cd "$work" && mpirun --oversubscribe -np "$1" lmp -screen none -in in.lammps -log timing.log >/dev/null)
  awk -v n=$n -v s="$steps" '/^Loop time/ { printf "%.6g\n", n * s / $4 }' "$work/timing.log"
}
ours_rate() { # threads
  "$cli" bench gas-write-up "${sets[@]}" --steps "$steps" --repeats 1 --threads "$1" --backend cpu |
    sed 's/.*"p_steps_per_s":\([0-9.e+]*\).*/\1/'
}
l1=() l2=() o1=() o2=()
for r in $(seq "$repeats"); do
  l1+=("$(lammps_rate 1)"); l2+=("$(lammps_rate 2)"); o1+=("$(ours_rate 1)"); o2+=("$(ours_rate 2)")
done
echo "| disks | steps | LAMMPS -np 1 | LAMMPS -np 2 | ParticleLab 1 thread | ParticleLab 2 threads |"
echo "|---|---|---|---|---|---|"
printf '| %d | %d | %.3g | %.3g | %.3g | %.3g |\n' $n "$steps" "$(printf '%s\n' "${l1[@]}" | median)" \
  "$(printf '%s\n' "${l2[@]}" | median)" "$(printf '%s\n' "${o1[@]}" | median)" "$(printf '%s\n' "${o2[@]}" | median)"
