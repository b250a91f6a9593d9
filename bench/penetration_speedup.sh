#!/usr/bin/env bash
# MPI speed-up and load balance of the penetration scene (examples/penetration): one chamber
# (in.chamber, N and width as given), then ROUNDS rounds of the same cone test (in.cone, crushing in
# the zone that follows the tip, DEPTH D_c) on 1 rank and on 2 ranks (or each count of RANKS),
# alternated so that the machine's drift falls on all; prints each round's wall-clock times and ratio, then the median
# of the in-round ratios with their range, for the whole test and per step (the two runs follow
# different trajectories: their time steps, and so their steps to the same depth, differ). Each run
# prints where its time goes per step (LIGGGHTS' breakdown of every stretch, summed: pair, neighbour
# lists, communication, the rest; on several ranks each part's smallest and largest time over the
# ranks, patches/0010), its neighbour builds, event steps and those replaced without a rebuild. With
# LISTS=1 each round adds a run at the largest rank count with 'event_lists rebuild' (a rebuild at
# every event step), and the medians of the neighbour time per step and of its share, insert against
# rebuild. At the end of the last test on the most ranks, each rank's share of the particles and of the contacts (the pair
# work) for the decks' grids on 2 and 4 ranks (2 x 1 x 1 and 2 x 2 x 1, "* * 1"), from the final
# dump (bench/penetration_balance.py).
#   bash bench/penetration_speedup.sh [ROUNDS=3] [N=80] [DEPTH=8] [WIDTH=10]
#   V=0.5882 SCENE="refine=1,distribution=normal,grid=1 1 *,balance=1,balance_dims=z" LISTS=1 \
#     bash bench/penetration_speedup.sh 3 34 2 40
#     (the default scene's refined pristine chamber, 40 D_c wide, at its velocity, on the grid
#     doc/running.md advises for 2 - 16 ranks; tests of 2 D_c)
#   RANKS="1 2 4 8 16" bash bench/penetration_speedup.sh 3 34 1.5 40   (strong scaling on a larger machine)
# Environment: LIGGGHTS (build/liggghts), V (m/s, 2), SCENE (in.chamber's and in.cone's further
# variables, name=value,name=value), LISTS (0 or 1: the rebuild run at the largest rank count),
# RANKS (1 and the rank counts compared with it, default "1 2"; each run is mpirun --oversubscribe
# where the machine has fewer cores, which times nothing useful).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
rounds=${1:-3} n=${2:-80} depth=${3:-8} width=${4:-10}
liggghts=${LIGGGHTS:-$here/build/liggghts}
lists=${LISTS:-0}
source "$here/scripts/mpi_env.sh"
source "$here/bench/rounds.sh"
source "$here/bench/penetration_work.sh"
vars=(-var N "$n" -var width "$width" -var depth "$depth" -var v "${V:-2}" -var vtk 0 -var checkpoint_every 0)
add_scene_vars
mpirun -np 2 "$liggghts" -in in.chamber "${vars[@]}" -log chamber.log > chamber.txt 2>&1 || { tail -5 chamber.txt; exit 1; }
grep '^CHAMBER .* N = ' chamber.txt

# cone RANKS LABEL [LISTS]: one test, timed; prints "seconds steps neighbour-us-per-step share" and
# its breakdown to stderr
cone() {
  local start seconds
  start=$(date +%s%N)
  mpirun -np "$1" "$liggghts" -in in.cone "${vars[@]}" -var crushing region -var label "$2" -var timing yes \
    ${3:+-var crush_lists "event_lists $3"} -log "$2.log" > "$2.txt" 2>&1 || { tail -5 "$2.txt" >&2; exit 1; }
  seconds=$(awk -v a="$start" -v b="$(date +%s%N)" 'BEGIN {printf "%.2f", (b - a) / 1e9}')
  awk -v s="$seconds" -v label="$2" '
    /^Loop time of/ {loop += $4} /^Pair  time \(%\)/ {pair += $5} /^Neigh time \(%\)/ {neigh += $5}
    /^Comm  time \(%\)/ {comm += $5} /^Neighbor list builds/ {builds += $NF}
    / time per processor:/ {lo[$1] += $(NF - 2); hi[$1] += $NF}
    /^CHECKED STEPS/ {steps = $NF} /^EVENT STEPS WITHOUT A REBUILD/ {inserted = $NF}
    /^PENETRATED/ {for (i = 1; i <= NF; i++) if ($i ~ /^events/) events = $(i - 1)}
    END {
      u = 1e6 / steps
      printf "%s %d %.3f %.2f\n", s, steps, neigh * u, 100 * neigh / loop
      printf "  %s: %.1f s, %d steps, per step %.1f us: pair %.1f, neighbour %.2f (%.1f%%), communication %.1f, the rest %.1f;" \
             " %d builds, %d events, %d event steps without a rebuild\n",
             label, s, steps, loop * u, pair * u, neigh * u, 100 * neigh / loop, comm * u, (loop - pair - neigh - comm) * u,
             builds, events, inserted > "/dev/stderr"
      if ("Pair" in lo)
        printf "    per rank (min - max, us per step): pair %.1f - %.1f, neighbour %.2f - %.2f, communication %.1f - %.1f, the rest %.1f - %.1f\n",
               lo["Pair"] * u, hi["Pair"] * u, lo["Neigh"] * u, hi["Neigh"] * u, lo["Comm"] * u, hi["Comm"] * u,
               lo["Other"] * u, hi["Other"] * u > "/dev/stderr"
    }' "$2.txt"
}

# each rank count of RANKS after the first against the first (1 rank): its speed-up in each round
read -ra counts <<< "${RANKS:-1 2}"
[ "${#counts[@]}" -ge 2 ] && [ "${counts[0]}" = 1 ] || { echo "RANKS: 1 and then the rank counts to compare (\"1 2 4 8 16\")" >&2; exit 2; }
last=${counts[-1]}
declare -A ratios=() step_ratios=()
neigh_ratios=() share_ratios=()
for round in $(seq "$rounds"); do
  row=$(cone 1 np1); read -r s1 m1 _ _ <<< "$row"
  for r in "${counts[@]:1}"; do
    row=$(cone "$r" "np$r"); read -r sr mr nur shr <<< "$row"
    ratio=$(ratio "$s1" "$sr")
    step_ratio=$(awk -v a="$s1" -v b="$sr" -v m="$m1" -v n="$mr" 'BEGIN {print (a / m) / (b / n)}')
    ratios[$r]+=" $ratio" step_ratios[$r]+=" $step_ratio"
    echo "round $round: 1 rank $s1 s ($m1 steps), $r ranks $sr s ($mr steps), speed-up $ratio, per step $step_ratio ($(grep '^PENETRATED' "np$r.txt"))"
  done
  if [ "$lists" = 1 ]; then
    # the largest rank count again, rebuilding every list at each event step
    row=$(cone "$last" "np${last}_rebuild" rebuild); read -r _ _ nu3 sh3 <<< "$row"
    neigh_ratios+=("$(ratio "$nur" "$nu3")") share_ratios+=("$(ratio "$shr" "$sh3")")
    echo "round $round: $last ranks, neighbour time per step $nur us (share $shr%) with the insertion, $nu3 us ($sh3%) rebuilding at each event step"
  fi
done
for r in "${counts[@]:1}"; do
  # shellcheck disable=SC2086  # the rounds' ratios, one word each
  summary "speed-up 1 -> $r ranks, whole test" ${ratios[$r]}
  # shellcheck disable=SC2086
  summary "speed-up 1 -> $r ranks, per step" ${step_ratios[$r]}
done
if [ "$lists" = 1 ]; then
  summary "$last ranks, neighbour time per step, insert / rebuild" "${neigh_ratios[@]}"
  summary "$last ranks, neighbour share of the loop, insert / rebuild" "${share_ratios[@]}"
fi
grep -E '^(Nlocal|Nghost|Neighs):' "np$last.txt" | tail -3 | sed "s/^/$last ranks at the end: /" || true
/usr/bin/python3 "$here/bench/penetration_balance.py" "particles_np${last}_N${n}.liggghts" chamber_dense_N${n}.in
