#!/usr/bin/env bash
# Contact-model cost: hertz/scaled + mindlin/scaled against LIGGGHTS' built-in hertz + tangential
# history on the same dense assembly of 10,976 spheres, same steps, alternating runs; prints the best
# loop time of each and their ratio (target: at most 1.05).
#   bash bench/contact_model.sh [steps=2000] [repeats=3]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
steps=${1:-2000}
repeats=${2:-3}
source "$here/dense_assembly.sh"

best_builtin=1e30; best_scaled=1e30
for r in $(seq "$repeats"); do
  b=$(loop_time hertz history in.none); s=$(loop_time hertz/scaled mindlin/scaled in.none)
  echo "repeat $r: hertz + history ${b} s, hertz/scaled + mindlin/scaled ${s} s"
  best_builtin=$(smaller "$best_builtin" "$b")
  best_scaled=$(smaller "$best_scaled" "$s")
done
awk -v b="$best_builtin" -v s="$best_scaled" -v n="$steps" 'BEGIN{
  printf "10976 particles, %d steps, best of runs: built-in %.3f s, scaled %.3f s\n", n, b, s;
  printf "ratio hertz/scaled+mindlin/scaled / hertz+history = %.3f (target <= 1.05)\n", s/b }'
