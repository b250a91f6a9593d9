#!/usr/bin/env bash
# What a step's fewer global reductions buy (patches/0016; fix crush's events agreed at the rebuilds):
# the same cone test run by a liggghts built without the change (BEFORE) and by this build, alternated
# in ROUNDS rounds on RANKS ranks. The scene is test_penetration's small chamber (N = 80, 6 D_c wide,
# 670 grains; 3 D_c at 2 m/s, crushing in the zone): few particles a rank, as on many ranks, where a
# step's waits weigh most. Each run writes its final particles to 17 digits; the bench says whether the
# two builds' trajectories are the same to the bit, then prints each round's times and the median of
# the in-round ratios (this build over BEFORE).
# BEFORE: a liggghts without the change, e.g. a worktree at the commit before it, built by
# scripts/setup.sh --no-run.
#   bash bench/cone_reductions.sh BEFORE [ROUNDS=5] [RANKS=2]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
before=${1:?"usage: bench/cone_reductions.sh BEFORE_LIGGGHTS [ROUNDS] [RANKS]"}
rounds=${2:-5} ranks=${3:-2}
after=${LIGGGHTS:-$here/build/liggghts}
source "$here/scripts/mpi_env.sh"
source "$here/bench/rounds.sh"
source "$here/bench/penetration_work.sh"
vars=(-var N 80 -var width 6 -var depth 3 -var below 2 -var sigma_lim0 5e8)
mpirun -np "$ranks" --oversubscribe "$after" -in in.chamber "${vars[@]}" -var density dense -log chamber.log > chamber.txt 2>&1 \
  || { tail -5 chamber.txt; exit 1; }
grep '^CHAMBER .* N = ' chamber.txt
format='"%d %.17g %.17g %.17g %.17g %.17g %.17g %.17g"'
printf 'include in.cone\nwrite_dump all custom exact_${label}.txt id x y z vx vy vz radius modify sort id format %s\n' "$format" > in.exact
timed_cone() {  # timed_cone BINARY LABEL: the test's wall-clock seconds
  local start=$(date +%s%N)
  mpirun -np "$ranks" --oversubscribe "$1" -in in.exact "${vars[@]}" -var v 2 -var crushing region -var vtk 0 \
    -var label "$2" -log "$2.log" > "$2.txt" 2>&1 || { tail -5 "$2.txt" >&2; exit 1; }
  awk -v a="$start" -v b="$(date +%s%N)" 'BEGIN {printf "%.2f", (b - a) / 1e9}'
}
ratios=()
for round in $(seq "$rounds"); do
  if [ $((round % 2)) -eq 1 ]; then t_before=$(timed_cone "$before" before); t_after=$(timed_cone "$after" after)
  else t_after=$(timed_cone "$after" after); t_before=$(timed_cone "$before" before); fi
  same=$(cmp -s exact_before.txt exact_after.txt && echo "the same to the bit" || echo "DIFFERENT")
  r=$(ratio "$t_after" "$t_before")
  ratios+=("$r")
  echo "round $round: BEFORE $t_before s, this build $t_after s: $r; final particles $same ($(($(wc -l < exact_after.txt) - 9)) particles)"
done
summary "cone test on $ranks ranks: this build / BEFORE" "${ratios[@]}"
