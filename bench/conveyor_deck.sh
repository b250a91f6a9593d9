# Shared by the conveyor benchmarks (sourced, after liggghts and ranks are set): LIGGGHTS' conveyor
# tutorial (Tutorials_public/conveyor, from the source the build unpacks) as doc/own_deck.md edits it,
# and its timed run.
tutorial=$(dirname "$liggghts")/liggghts-3.8.0/examples/LIGGGHTS/Tutorials_public/conveyor
[ -f "$tutorial/in.conveyor" ] || { echo "no conveyor tutorial in $tutorial (build first)"; exit 1; }

# conveyor_deck STYLE FOLDER: the tutorial in FOLDER with own_deck.md's fix crush line (sigma_lim0
# 3e5, cv 0.5, weibull_m 10, d0 0.05, dmin 0.005), neighbour style STYLE, run to step 25,000, no dumps
conveyor_deck() {
  rm -rf "$2" && cp -r "$tutorial" "$2"
  sed -i -e "s/^neighbor\t0.01 bin/neighbor\t0.01 $1/" -e 's/^run\t\t\t140000 upto/run\t\t\t25000 upto/' \
         -e 's/^dump/#dump/' "$2/in.conveyor"
  grep -q "^neighbor	0.01 $1" "$2/in.conveyor" && grep -q "^run			25000 upto" "$2/in.conveyor" \
    || { echo "the conveyor tutorial changed: its neighbor or run line is not the one edited here"; exit 1; }
  sed -i '/^pair_coeff/a fix crush all crush sigma_lim0 3e5 cv 0.5 weibull_m 10 d0 0.05 seed 1234567 dmin 0.005 log crush_events.csv' \
      "$2/in.conveyor"
}

# timed FOLDER: seconds of the run on $ranks ranks
timed() {
  local start; start=$(date +%s%N)
  (cd "$1" && mpirun -np "$ranks" "$liggghts" -in in.conveyor -log log.liggghts > screen.txt 2>&1) \
    || { tail -5 "$1/screen.txt"; exit 1; }
  awk -v a="$start" -v b="$(date +%s%N)" 'BEGIN {printf "%.1f", (b - a) / 1e9}'
}
