#!/usr/bin/env bash
# MPI speed-up on this machine and a communication projection for a cluster:
# the O-N deck (examples/fontainebleau, N = 1.5 unless given, with the paper's crushing; full ramp to
# 100 MPa unless SIGMA_MAX) on 1 rank, on 2 ranks with the decks' decomposition (grid "* * 1": the
# ranks split x and y, never the loading axis z) and on 2 ranks with LAMMPS' default for the cubic box
# (grid "* * *": 1 x 1 x 2, a cut across z, under which the hi wall pushes the grains), all in one
# call: wall-clock time of the whole deck (preparation included), speed-ups and the particles per
# rank at the end. LIGGGHTS 3.8.0 has no balance command; the grid is its load balancing. From the
# 2-rank run's neighbour statistics (ghost particles per rank across the one cut plane) it projects
# the ghost count and forward-communication volume per step of a cubic decomposition for larger
# samples: a projection from the measured ghost density, not a measurement.
#   bash bench/mpi_speedup.sh [N=1.5]     (N = 1: about 40 minutes on 2 cores)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
n=${1:-1.5}
sigma_max=${SIGMA_MAX:-1e8}
liggghts=${LIGGGHTS:-$here/build/liggghts}
source "$here/scripts/mpi_env.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
declare -A seconds
for run in "1 * * 1" "2 * * 1" "2 * * *"; do
  ranks=${run%% *} grid=${run#* }
  name="$ranks ranks, grid $grid" dir="$work/$ranks${grid//[ *]/}"
  mkdir -p "$dir" && cp "$here"/examples/fontainebleau/in.* "$dir"/
  start=$(date +%s%N)
  (cd "$dir" && mpirun -np "$ranks" "$liggghts" -in in.oedometer -var N "$n" -var sigma_max "$sigma_max" \
     -var grid "$grid" -log log.liggghts > screen.txt 2>&1) || { tail -5 "$dir/screen.txt"; exit 1; }
  seconds[$run]=$(awk -v a="$start" -v b="$(date +%s%N)" 'BEGIN {printf "%.1f", (b - a) / 1e9}')
  events=$(($(wc -l < "$dir/events_O${n}.csv") - 1))
  echo "O-$n on $name: ${seconds[$run]} s, $events events, $(grep -m1 'MPI processor grid' "$dir/screen.txt" | xargs)"
  # particles per rank at 100 MPa, from the dump: either side of the one cut, at the middle of the
  # box (-1 to 5 mm, in.prepare) along x (2 x 1 x 1) or z (1 x 1 x 2)
  dump="$dir/dump_O${n}_100MPa.liggghts"
  if [ "$ranks" = 2 ] && [ -f "$dump" ]; then
    axis=$([ "$grid" = "* * 1" ] && echo 3 || echo 5)  # x or z column of 'id type x y z ...'
    awk -v c="$axis" 'f && NF > 4 {n++; if ($c < 0.002) low++} /^ITEM: ATOMS/ {f = 1}
      END {printf "   at 100 MPa: %d and %d particles either side of the cut (%.0f%% on the fuller rank)\n", low, n - low,
           100 * (low > n - low ? low : n - low) / n}' "$dump"
  fi
done
awk -v a="${seconds[1 * * 1]}" -v b="${seconds[2 * * 1]}" -v c="${seconds[2 * * *]}" 'BEGIN {
  printf "speed-up 1 -> 2 ranks = %.2f with the decks grid (* * 1), %.2f with LAMMPS default (* * *)\n", a / b, a / c }'
# Ghosts per rank in the last statistics LIGGGHTS printed on 2 ranks (the end of the preparation: the
# chunked ramp runs print none), one cut plane across the 4 mm sample.
awk '/^Nlocal:/ {local = $2} /^Nghost:/ {ghost = $2} END {
  doubles = 10  # forward communication per ghost per step: x, v, omega (3 each) and radius
  printf "2 ranks, prepared sample: %.0f particles and %.0f ghosts per rank (one cut plane: %.0f ghosts per face)\n", local, ghost, ghost
  printf "projection, cubic decomposition (6 faces per rank, ghosts per face scaling with the face area), %d doubles per ghost per step:\n", doubles
  printf "  %12s %6s %14s %14s %18s %14s\n", "particles", "ranks", "local/rank", "ghosts/rank", "bytes/step/rank", "ghost/local"
  total = 2 * local
  split("1000000 1000000 1000000 10000000 10000000", sizes, " ")
  split("16 64 256 256 1024", counts, " ")
  for (k = 1; k <= 5; k++) {
    nloc = sizes[k] / counts[k]
    g = 6 * ghost * (nloc / total) ^ (2.0 / 3.0)
    printf "  %12d %6d %14.0f %14.0f %18.0f %14.3f\n", sizes[k], counts[k], nloc, g, g * doubles * 8, g / nloc
  }
}' "$work/21/screen.txt"
