#!/usr/bin/env bash
# Peak resident memory per 10,000 particles (issue 7): bench/in.dense_assembly (hertz/scaled +
# mindlin/scaled, friction 0.5, with a fix crush under which nothing breaks) at 4 x 7^3 = 1372 and
# 4 x 14^3 = 10,976 spheres, 200 steps, serial; the difference of the two peaks per 10,000 particles
# is the per-particle cost, the rest the fixed cost of the executable.
#   bash bench/memory.sh
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
liggghts=${LIGGGHTS:-$here/../build/liggghts}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$here"/in.dense_assembly "$here"/in.crush_idle "$work"/
declare -A rss
for cells in 7 14; do
  (cd "$work" && /usr/bin/time -v "$liggghts" -in in.dense_assembly -var model hertz/scaled -var tmodel mindlin/scaled \
     -var extra in.crush_idle -var steps 200 -var cells "$cells" -log none > screen.txt 2> time.txt)
  rss[$cells]=$(awk '/Maximum resident set size/ {print $NF}' "$work/time.txt")
  echo "$((4 * cells * cells * cells)) particles: peak resident memory $((rss[$cells] / 1024)) MiB"
done
awk -v a="${rss[7]}" -v b="${rss[14]}" 'BEGIN {
  per = (b - a) / (10976 - 1372) * 10000 / 1024
  printf "per 10,000 particles: %.1f MiB (slope); whole process at 10,976 particles: %.1f MiB\n", per, b / 1024 }'
