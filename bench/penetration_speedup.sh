#!/usr/bin/env bash
# MPI speed-up and load balance of the penetration scene (examples/penetration): one chamber
# (in.chamber, N and width as given), then ROUNDS rounds of the same cone test (in.cone, crushing in
# the zone that follows the tip, DEPTH D_c) on 1 rank and on 2 ranks, alternated so that the
# machine's drift falls on both; prints each round's wall-clock times and ratio, then the median
# of the in-round ratios with their range, for the whole test and per step (the two runs follow
# different trajectories: their time steps, and so their steps to the same depth, differ). At the end of the last 2-rank test, each rank's share of
# the particles and of the contacts (the pair work) for the decks' grids on 2 and 4 ranks
# (2 x 1 x 1 and 2 x 2 x 1, "* * 1"), from the final dump (bench/penetration_balance.py).
#   bash bench/penetration_speedup.sh [ROUNDS=3] [N=80] [DEPTH=8] [WIDTH=10]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
rounds=${1:-3} n=${2:-80} depth=${3:-8} width=${4:-10}
liggghts=${LIGGGHTS:-$here/build/liggghts}
source "$here/scripts/mpi_env.sh"
source "$here/bench/penetration_work.sh"
vars=(-var N "$n" -var width "$width" -var depth "$depth" -var v 2 -var vtk 0 -var checkpoint_every 0)
mpirun -np 2 "$liggghts" -in in.chamber "${vars[@]}" -log chamber.log > chamber.txt 2>&1 || { tail -5 chamber.txt; exit 1; }
grep '^CHAMBER .* N = ' chamber.txt
ratios=() step_ratios=()
for round in $(seq "$rounds"); do
  declare -A seconds=() steps=()
  for ranks in 1 2; do
    start=$(date +%s%N)
    mpirun -np "$ranks" "$liggghts" -in in.cone "${vars[@]}" -var crushing region -var label "np$ranks" -log "cone$ranks.log" > "cone$ranks.txt" 2>&1 \
      || { tail -5 "cone$ranks.txt"; exit 1; }
    seconds[$ranks]=$(awk -v a="$start" -v b="$(date +%s%N)" 'BEGIN {printf "%.2f", (b - a) / 1e9}')
    steps[$ranks]=$(grep -oE 'CHECKED STEPS [0-9.e+]+ OF [0-9]+' "cone$ranks.txt" | awk '{print $5}')
  done
  ratio=$(awk -v a="${seconds[1]}" -v b="${seconds[2]}" 'BEGIN {printf "%.3f", a / b}')
  step_ratio=$(awk -v a="${seconds[1]}" -v b="${seconds[2]}" -v m="${steps[1]}" -v n="${steps[2]}" \
                   'BEGIN {printf "%.3f", (a / m) / (b / n)}')
  ratios+=("$ratio") step_ratios+=("$step_ratio")
  echo "round $round: 1 rank ${seconds[1]} s (${steps[1]} steps), 2 ranks ${seconds[2]} s (${steps[2]} steps)," \
       "speed-up $ratio, per step $step_ratio ($(grep '^PENETRATED' cone2.txt))"
done
median() { sort -g | awk -v what="$1" '{r[NR] = $1} END {
  m = (NR % 2) ? r[(NR + 1) / 2] : (r[NR / 2] + r[NR / 2 + 1]) / 2
  printf "speed-up 1 -> 2 ranks, %s: median %.3f of %d rounds (range %.3f - %.3f)\n", what, m, NR, r[1], r[NR] }'; }
printf '%s\n' "${ratios[@]}" | median "whole test"
printf '%s\n' "${step_ratios[@]}" | median "per step"
grep -E '^(Nlocal|Nghost|Neighs):' cone2.txt | tail -3 | sed 's/^/2 ranks at the end: /' || true
/usr/bin/python3 "$here/bench/penetration_balance.py" "particles_np2_N${n}.liggghts" chamber_dense_N${n}.in
