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
tutorial=$(dirname "$liggghts")/liggghts-3.8.0/examples/LIGGGHTS/Tutorials_public/conveyor
source "$here/scripts/mpi_env.sh"
source "$here/bench/rounds.sh"
[ -f "$tutorial/in.conveyor" ] || { echo "no conveyor tutorial in $tutorial (build first)"; exit 1; }

deck() {  # deck STYLE FOLDER: the tutorial with crushing, its neighbour style STYLE
  rm -rf "$2" && cp -r "$tutorial" "$2"
  sed -i -e "s/^neighbor\t0.01 bin/neighbor\t0.01 $1/" -e 's/^run\t\t\t140000 upto/run\t\t\t25000 upto/' \
         -e 's/^dump/#dump/' "$2/in.conveyor"
  grep -q "^neighbor	0.01 $1" "$2/in.conveyor" && grep -q "^run			25000 upto" "$2/in.conveyor" \
    || { echo "the conveyor tutorial changed: its neighbor or run line is not the one edited here"; exit 1; }
  sed -i '/^pair_coeff/a fix crush all crush sigma_lim0 3e5 cv 0.5 weibull_m 10 d0 0.05 seed 1234567 dmin 0.005 log crush_events.csv' \
      "$2/in.conveyor"
}

timed() {  # timed FOLDER: seconds of the run
  local start; start=$(date +%s%N)
  (cd "$1" && mpirun -np "$ranks" "$liggghts" -in in.conveyor -log log.liggghts > screen.txt 2>&1) \
    || { tail -5 "$1/screen.txt"; exit 1; }
  awk -v a="$start" -v b="$(date +%s%N)" 'BEGIN {printf "%.1f", (b - a) / 1e9}'
}

ratios=()
for round in $(seq "$rounds"); do
  deck bin "$out/bin" && deck multi "$out/multi"
  if [ $((round % 2)) -eq 1 ]; then t_bin=$(timed "$out/bin"); t_multi=$(timed "$out/multi")
  else t_multi=$(timed "$out/multi"); t_bin=$(timed "$out/bin"); fi
  events_bin=$(($(wc -l < "$out/bin/crush_events.csv") - 1)); events_multi=$(($(wc -l < "$out/multi/crush_events.csv") - 1))
  r=$(ratio "$t_multi" "$t_bin")
  ratios+=("$r")
  echo "round $round: bin $t_bin s ($events_bin events), multi $t_multi s ($events_multi events): multi / bin $r"
done
summary "conveyor with crushing, $ranks ranks: multi / bin" "${ratios[@]}"
