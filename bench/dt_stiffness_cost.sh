#!/usr/bin/env bash
# Cost of fix dt/stiffness (PFC's automatic time step) on 10,976 dense spheres: the same steps with
# it (recomputing every step, and every 10 steps) against without it; the step is capped at the
# deck's own, so only the fix's work differs.
#   bash bench/dt_stiffness_cost.sh [steps=2000] [repeats=3]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
steps=${1:-2000}
repeats=${2:-3}
source "$here/dense_assembly.sh"
cp "$here"/in.dt_stiffness "$work"/
best_none=1e30; best_1=1e30; best_10=1e30
for r in $(seq "$repeats"); do
  a=$(loop_time hertz/scaled mindlin/scaled in.none)
  sed -i 's/every [0-9]* max/every 1 max/' "$work/in.dt_stiffness"
  b=$(loop_time hertz/scaled mindlin/scaled in.dt_stiffness)
  sed -i 's/every 1 max/every 10 max/' "$work/in.dt_stiffness"
  c=$(loop_time hertz/scaled mindlin/scaled in.dt_stiffness)
  echo "repeat $r: without ${a} s, every step ${b} s, every 10 steps ${c} s"
  best_none=$(smaller "$best_none" "$a"); best_1=$(smaller "$best_1" "$b"); best_10=$(smaller "$best_10" "$c")
done
awk -v a="$best_none" -v b="$best_1" -v c="$best_10" -v n="$steps" 'BEGIN{
  printf "10976 particles, %d steps: without %.3f s, fix dt/stiffness every step %.3f s, every 10 steps %.3f s\n", n, a, b, c;
  printf "ratio with / without: every step %.3f, every 10 steps %.3f\n", b/a, c/a }'
