#!/usr/bin/env bash
# Contact-model cost: hertz/scaled + mindlin/scaled against LIGGGHTS' built-in hertz + tangential
# history on the same dense assembly of 10,976 spheres, same steps, alternating runs; prints the best
# loop time of each and their ratio (target: at most 1.05).
#   bash bench/contact_model.sh [steps=2000] [repeats=3]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
liggghts=${LIGGGHTS:-$here/../build/liggghts}
steps=${1:-2000}
repeats=${2:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$here"/in.dense_assembly "$here"/in.none "$work"/

loop_time() {  # model tmodel -> seconds of the run loop
  (cd "$work" && "$liggghts" -in in.dense_assembly -var model "$1" -var tmodel "$2" -var steps "$steps" \
     -var extra in.none -log none -screen none.txt >/dev/null 2>&1 || { tail -5 none.txt; exit 1; })
  awk '/^Loop time of/ {print $4}' "$work/none.txt"
}

best_builtin=1e30; best_scaled=1e30
for r in $(seq "$repeats"); do
  b=$(loop_time hertz history); s=$(loop_time hertz/scaled mindlin/scaled)
  echo "repeat $r: hertz + history ${b} s, hertz/scaled + mindlin/scaled ${s} s"
  best_builtin=$(awk -v a="$best_builtin" -v b="$b" 'BEGIN{print (b<a)?b:a}')
  best_scaled=$(awk -v a="$best_scaled" -v b="$s" 'BEGIN{print (b<a)?b:a}')
done
awk -v b="$best_builtin" -v s="$best_scaled" -v n="$steps" 'BEGIN{
  printf "10976 particles, %d steps, best of runs: built-in %.3f s, scaled %.3f s\n", n, b, s;
  printf "ratio hertz/scaled+mindlin/scaled / hertz+history = %.3f (target <= 1.05)\n", s/b }'
