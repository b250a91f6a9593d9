#!/usr/bin/env bash
# The largest runs this machine holds (issue 16): bench/in.dense_assembly (hertz/scaled + mindlin/scaled,
# friction 0.5, a fix crush under which nothing breaks) at 4 x cells^3 spheres, serial: the loop time
# per particle-step and the peak resident memory per particle, and the ratio of the time per
# particle-step at each size to that at the first. Steps per size shrink with the size, so that each
# run takes about as long.
#   bash bench/large_run.sh [cells ...]     (default 14 29 63: 10,976, 97,556 and 1,000,188 spheres)
# A projection to 100 MPa multiplies the time per particle-step by the particles and the ramp's steps
# (studies/accuracy/README.md).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/dense_assembly.sh"   # liggghts, the scratch folder work with the decks
first=""
for cells in "${@:-14 29 63}"; do
  for c in $cells; do
    n=$((4 * c * c * c))
    steps=$(( 40000000 / n < 40 ? 40 : 40000000 / n ))
    (cd "$work" && /usr/bin/time -v "$liggghts" -in in.dense_assembly -var model hertz/scaled -var tmodel mindlin/scaled \
       -var extra in.crush_idle -var steps "$steps" -var cells "$c" -log none > screen.txt 2> time.txt)
    loop=$(awk '/^Loop time of/ {t = $4} END {print t}' "$work/screen.txt")
    rss=$(awk '/Maximum resident set size/ {print $NF}' "$work/time.txt")
    per=$(awk -v t="$loop" -v n="$n" -v s="$steps" 'BEGIN {printf "%.4g", 1e6 * t / (n * s)}')
    [ -n "$first" ] || first=$per
    awk -v n="$n" -v s="$steps" -v t="$loop" -v p="$per" -v f="$first" -v r="$rss" 'BEGIN {
      printf "%d particles, %d steps: loop %.2f s, %.4f us per particle-step (%.3f x the first size), peak memory %.0f MiB (%.0f bytes per particle)\n",
             n, s, t, p, p / f, r / 1024, r * 1024 / n }'
  done
done
