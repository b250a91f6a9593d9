#!/usr/bin/env bash
# The processor grid of the refined chamber (examples/penetration, refine 1) on RANKS ranks: the
# decks' "* * 1" with equal slabs against "1 1 *" with the balancer moving the planes along z
# (balance 1, balance_dims z: doc/running.md's choice from post/decomposition.py). One chamber,
# then ROUNDS rounds of the same cone test (crushing in the zone that follows the tip, DEPTH D_c),
# the two grids alternated so that the machine's drift falls on both; prints each round's
# wall-clock times and their ratio, per step too (the two runs sum their forces in another order and
# follow different trajectories), and the median of the in-round ratios with their range.
#   bash bench/penetration_grid.sh [ROUNDS=3] [N=34] [DEPTH=1] [RANKS=2]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
rounds=${1:-3} n=${2:-34} depth=${3:-1} ranks=${4:-2}
liggghts=${LIGGGHTS:-$here/build/liggghts}
source "$here/scripts/mpi_env.sh"
source "$here/bench/rounds.sh"
source "$here/bench/penetration_work.sh"
vars=(-var N "$n" -var refine 1 -var depth "$depth" -var vtk 0 -var checkpoint_every 0)
mpirun -np "$ranks" "$liggghts" -in in.chamber "${vars[@]}" -log chamber.log > chamber.txt 2>&1 || { tail -5 chamber.txt; exit 1; }
grep '^CHAMBER .* N = ' chamber.txt
declare -A grid=([slabs_xy]="* * 1" [slabs_z]="1 1 *") balance=([slabs_xy]=0 [slabs_z]=1)
ratios=() step_ratios=()
for round in $(seq "$rounds"); do
  declare -A seconds=() steps=()
  for layout in slabs_xy slabs_z; do
    start=$(date +%s%N)
    mpirun -np "$ranks" "$liggghts" -in in.cone "${vars[@]}" -var crushing region -var label "$layout" -var grid "${grid[$layout]}" \
      -var balance "${balance[$layout]}" -var balance_dims z -log "$layout.log" > "$layout.txt" 2>&1 || { tail -5 "$layout.txt"; exit 1; }
    seconds[$layout]=$(awk -v a="$start" -v b="$(date +%s%N)" 'BEGIN {printf "%.2f", (b - a) / 1e9}')
    steps[$layout]=$(grep -oE 'CHECKED STEPS [0-9.e+]+ OF [0-9]+' "$layout.txt" | awk '{print $5}')
  done
  ratio=$(ratio "${seconds[slabs_xy]}" "${seconds[slabs_z]}")
  step_ratio=$(awk -v a="${seconds[slabs_xy]}" -v b="${seconds[slabs_z]}" -v m="${steps[slabs_xy]}" -v n="${steps[slabs_z]}" \
                   'BEGIN {printf "%.3f", (a / m) / (b / n)}')
  ratios+=("$ratio") step_ratios+=("$step_ratio")
  echo "round $round: \"* * 1\" ${seconds[slabs_xy]} s (${steps[slabs_xy]} steps), \"1 1 *\" balanced along z" \
       "${seconds[slabs_z]} s (${steps[slabs_z]} steps): time ratio $ratio, per step $step_ratio"
  grep '^BALANCE:' slabs_z.txt | tail -1 | sed 's/^/  last balance call: /'
done
summary '"* * 1" over "1 1 *" balanced, the whole test' "${ratios[@]}"
summary '"* * 1" over "1 1 *" balanced, per step' "${step_ratios[@]}"
