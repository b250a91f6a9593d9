#!/usr/bin/env bash
# A user's deck with crushing on 2 ranks, with fix balance and without: LIGGGHTS' conveyor tutorial
# (Tutorials_public/conveyor, from the source the build unpacks: grains streamed onto a moving belt in
# a shrink-wrapped box, whose equal slabs leave the grains to one rank) with doc/own_deck.md's fix
# crush line (sigma_lim0 3e5, cv 0.5, weibull_m 10, d0 0.05, dmin 0.005), neighbour lists by size
# class ('neighbor 0.01 multi', own_deck.md's advice), its VTK dumps off, run to step 25,000 on
# RANKS ranks (default 2), alternated in ROUNDS rounds (default 2). The balanced run adds
#   fix bal all balance 1000 1.05 shift xyz 20 1.0 weight neighbors out balance.txt
# (doc/fix_balance.txt) and prints the fix's imbalance (the fullest rank's work over the mean) at
# every check to imbalance.txt. Prints each round's times, events, each run's particles per rank at
# the end and pair seconds per rank over the run (patches/0010), the balanced run's largest imbalance
# right after a check from step 3,000 on and before a move (the shrink-wrapped box stretches between
# checks, and the planes are fractions of it), then the median of the in-round ratios balanced /
# equal slabs.
#   bash bench/conveyor_balance.sh [ROUNDS] [OUT_DIR (default runs/conveyor_balance)]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
rounds=${1:-2}
out=$(mkdir -p "${2:-$here/runs/conveyor_balance}" && cd "${2:-$here/runs/conveyor_balance}" && pwd)
ranks=${RANKS:-2}
liggghts=${LIGGGHTS:-$here/build/liggghts}
source "$here/scripts/mpi_env.sh"
source "$here/bench/rounds.sh"
source "$here/bench/conveyor_deck.sh"

deck() {  # deck FOLDER BALANCE(0|1): the tutorial with crushing and multi, with fix balance or not
  conveyor_deck multi "$1"
  [ "$2" = 1 ] || return 0
  sed -i -e '/^fix crush all crush/a fix bal all balance 1000 1.05 shift xyz 20 1.0 weight neighbors out balance.txt' \
         -e '/^fix crush all crush/a variable imbalance equal f_bal' \
         -e '/^fix crush all crush/a fix bal_trace all print 1000 "${imbalance}" file imbalance.txt screen no' "$1/in.conveyor"
}

ranks_line() {  # ranks_line FOLDER: the run's particles per rank at the end (min - max) and pair seconds per rank (min - max)
  awk '/^Nlocal:/ {n = $6 " - " $4} /^Pair  time per processor/ {p = $6 " - " $8} END {print "particles per rank " n ", pair s per rank " p}' "$1/log.liggghts"
}

ratios=()
for round in $(seq "$rounds"); do
  deck "$out/equal" 0 && deck "$out/balanced" 1
  if [ $((round % 2)) -eq 1 ]; then t_equal=$(timed "$out/equal"); t_bal=$(timed "$out/balanced")
  else t_bal=$(timed "$out/balanced"); t_equal=$(timed "$out/equal"); fi
  ev_equal=$(($(wc -l < "$out/equal/crush_events.csv") - 1)); ev_bal=$(($(wc -l < "$out/balanced/crush_events.csv") - 1))
  worst=$(awk 'NR > 3 && $1 + 0 > m {m = $1 + 0} END {printf "%.3f", m}' "$out/balanced/imbalance.txt")
  drift=$(awk '/^step/ && $2 + 0 >= 3000 {b = $4 + 0; if (b > m) m = b} END {printf "%.3f", m}' "$out/balanced/balance.txt")
  r=$(ratio "$t_bal" "$t_equal")
  ratios+=("$r")
  echo "round $round: equal slabs $t_equal s ($ev_equal events; $(ranks_line "$out/equal")), fix balance $t_bal s ($ev_bal events; $(ranks_line "$out/balanced")), imbalance by work after each check from step 3000 at most $worst, before a move from step 3000 at most $drift, $(grep -c '^step' "$out/balanced/balance.txt") moves: balanced / equal $r"
done
summary "conveyor with crushing, $ranks ranks: fix balance / equal slabs" "${ratios[@]}"
