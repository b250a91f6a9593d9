#!/usr/bin/env bash
# MPI speed-up on this machine and a communication projection for a cluster (issue 7):
# the O-1.5 deck (examples/fontainebleau, 2961 particles, full ramp to 100 MPa unless SIGMA_MAX) on
# 1 and on 2 ranks, wall-clock time of the whole deck (preparation included): speed-up (target >= 1.7
# on 2 cores). From the 2-rank run's neighbour statistics (ghost particles per rank across the one
# cut plane) it projects the ghost count and forward-communication volume per step of a cubic
# decomposition for larger samples: a projection from the measured ghost density, not a measurement.
#   bash bench/mpi_speedup.sh [N=1.5]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
n=${1:-1.5}
sigma_max=${SIGMA_MAX:-1e8}
liggghts=${LIGGGHTS:-$here/build/liggghts}
source "$here/scripts/mpi_env.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
declare -A seconds
for ranks in 1 2; do
  mkdir -p "$work/$ranks" && cp "$here"/examples/fontainebleau/in.* "$work/$ranks"/
  start=$(date +%s%N)
  (cd "$work/$ranks" && mpirun -np "$ranks" "$liggghts" -in in.oedometer -var N "$n" -var sigma_max "$sigma_max" \
     -log log.liggghts > screen.txt 2>&1) || { tail -5 "$work/$ranks/screen.txt"; exit 1; }
  seconds[$ranks]=$(awk -v a="$start" -v b="$(date +%s%N)" 'BEGIN {printf "%.1f", (b - a) / 1e9}')
  events=$(($(wc -l < "$work/$ranks/events_O${n}.csv") - 1))
  echo "O-$n on $ranks rank(s): ${seconds[$ranks]} s, $events events"
done
awk -v a="${seconds[1]}" -v b="${seconds[2]}" 'BEGIN {printf "speed-up 1 -> 2 ranks = %.2f (target >= 1.7)\n", a / b}'
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
}' "$work/2/screen.txt"
