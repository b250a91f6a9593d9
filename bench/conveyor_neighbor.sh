#!/usr/bin/env bash
# A user's deck with crushing, neighbour lists by style bin against style multi: LIGGGHTS' conveyor
# tutorial (Tutorials_public/conveyor, from the source the build unpacks: grains streamed onto a moving
# belt, a shrink-wrapped box) with doc/own_deck.md's fix crush line (sigma_lim0 3e5, cv 0.5,
# weibull_m 10, d0 0.05, dmin 0.005), its VTK dumps off, run to step 25,000 on RANKS ranks (default
# 2), alternated in ROUNDS rounds (default 2). Prints each round's times and multi / bin, then the
# median of the in-round ratios. Fix crush's advice to a deck on 'bin' (doc/fix_crush.txt) quotes it.
#   bash bench/conveyor_neighbor.sh [ROUNDS] [OUT_DIR (default runs/conveyor_neighbor)]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
rounds=${1:-2}
out=$(mkdir -p "${2:-$here/runs/conveyor_neighbor}" && cd "${2:-$here/runs/conveyor_neighbor}" && pwd)
ranks=${RANKS:-2}
liggghts=${LIGGGHTS:-$here/build/liggghts}
source "$here/scripts/mpi_env.sh"
source "$here/bench/rounds.sh"
source "$here/bench/conveyor_deck.sh"

ratios=()
for round in $(seq "$rounds"); do
  conveyor_deck bin "$out/bin" && conveyor_deck multi "$out/multi"
  if [ $((round % 2)) -eq 1 ]; then t_bin=$(timed "$out/bin"); t_multi=$(timed "$out/multi")
  else t_multi=$(timed "$out/multi"); t_bin=$(timed "$out/bin"); fi
  events_bin=$(($(wc -l < "$out/bin/crush_events.csv") - 1)); events_multi=$(($(wc -l < "$out/multi/crush_events.csv") - 1))
  r=$(ratio "$t_multi" "$t_bin")
  ratios+=("$r")
  echo "round $round: bin $t_bin s ($events_bin events), multi $t_multi s ($events_multi events): multi / bin $r"
done
summary "conveyor with crushing, $ranks ranks: multi / bin" "${ratios[@]}"
