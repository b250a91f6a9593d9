#!/usr/bin/env bash
# What accuracy costs in time: the oedometric test O-N with the paper's crushing (the decks' default,
# the Table 3 reading of studies/fontainebleau/README.md), run at settings that trade accuracy for time, each on RANKS
# MPI ranks (default 2), compared with the finest setting that stays quasi-static (N = 1, L_R = 0.05,
# dmin = 0.025 mm: without a comminution limit fragments of fragments reach nanometres and the time
# step 1e-12 s, see studies/accuracy/README.md). One command:
#   bash bench/accuracy_vs_cost.sh [OUT_DIR (default runs/accuracy)] [setting ...]
# A setting already run (OUT_DIR/<name>/done) is not run again; delete the folder to redo it.
# A run stopped after LIMIT seconds (default 1800, 0 = none) is reported with the stress it reached.
# 'bash bench/accuracy_vs_cost.sh runs/accuracy nodmin_N1' adds the reference without a comminution
# limit (studies/accuracy/README.md: why it is not the reference).
# SEEDS="S1 S2 ..." runs every setting once per seed (its sample and strength draw) into
# OUT_DIR/<name>_s<seed>; without it, once with the decks' seed into OUT_DIR/<name>.
# bench/accuracy_seeds.sh runs the study with seeds (5 at N = 2, 3 for the reference).
# Then bench/accuracy_vs_cost.py writes OUT_DIR/accuracy_vs_cost.csv and the figures
# (studies/accuracy/README.md explains them). Takes about an hour on a 2-core machine (one seed).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out=$(mkdir -p "${1:-$here/runs/accuracy}" && cd "${1:-$here/runs/accuracy}" && pwd)
shift || true
ranks=${RANKS:-2}
liggghts=${LIGGGHTS:-$here/build/liggghts}
limit=${LIMIT:-1800}
source "$here/scripts/mpi_env.sh"

# name: N  L_R  dmin (mm, before scaling; 0 = none)  dt_fraction  dt_every  crush_every  layout
#       fragment_density (true, or scaled: fragments keep their mother's time step)
settings="
N2              2   0.1  0.05  0.5 1  1        fourteen   true
N2_LR0.05       2   0.05 0.05  0.5 1  1        fourteen   true
N2_LR0.2        2   0.2  0.05  0.5 1  1        fourteen   true
N2_dmin0.025    2   0.1  0.025 0.5 1  1        fourteen   true
N2_dmin0.1      2   0.1  0.1   0.5 1  1        fourteen   true
N2_dt0.3        2   0.1  0.05  0.3 1  1        fourteen   true
N2_dt0.8        2   0.1  0.05  0.8 1  1        fourteen   true
N2_dtevery10    2   0.1  0.05  0.5 10 1        fourteen   true
N2_every10      2   0.1  0.05  0.5 1  10       fourteen   true
N2_adaptive     2   0.1  0.05  0.5 1  adaptive fourteen   true
N2_tetrahedral  2   0.1  0.05  0.5 1  1        tetrahedral true
N2_fragscaled   2   0.1  0.05  0.5 1  1        fourteen   scaled
reference       1   0.05 0.025 0.5 1  1        fourteen   true
N1              1   0.1  0.05  0.5 1  1        fourteen   true
N1.5            1.5 0.1  0.05  0.5 1  1        fourteen   true
N1_tetrahedral  1   0.1  0.05  0.5 1  1        tetrahedral true
N2_dmin_none    2   0.1  0     0.5 1  1        fourteen   true
nodmin_N1       1   0.05 0     0.5 1  1        fourteen   true
"
wanted=" ${*:-all} "
# One round a seed: every setting once, in turn, so that the machine's drift in speed falls on all of
# them alike (the cost ratios are taken within a round).
for seed in ${SEEDS:-deck}; do
echo "$settings" | while read -r name n lr dmin frac dt_every every layout fdens; do
  [ -n "$name" ] || continue
  # nodmin_N1 (the reference without a comminution limit: a cascade to nanometres) only when named
  [[ ( "$wanted" == " all " && "$name" != nodmin_N1 ) || "$wanted" == *" $name "* ]] || continue
  dir=$out/$name
  seed_vars=()
  if [ "$seed" != deck ]; then dir=${dir}_s$seed; seed_vars=(-var seed "$seed"); fi
  if [ -f "$dir/done" ]; then echo "== $(basename "$dir"): done before"; continue; fi
  rm -rf "$dir" && mkdir -p "$dir" && cp "$here"/examples/fontainebleau/in.* "$dir"/
  echo "== $(basename "$dir"): N $n, L_R $lr, dmin $dmin mm, dt_fraction $frac, dt_every $dt_every, crush_every $every," \
       "layout $layout, fragment_density $fdens ($ranks ranks)"
  start=$(date +%s%N)
  status=0
  (cd "$dir" && /usr/bin/time -v timeout "$limit" mpirun -np "$ranks" "$liggghts" -in in.oedometer -var N "$n" \
     -var LR "$lr" -var dmin "${dmin}e-3" -var dt_fraction "$frac" -var dt_every "$dt_every" \
     -var crush_every "$every" -var layout "$layout" -var fragment_density "$fdens" "${seed_vars[@]}" -log log.liggghts < /dev/null > screen.txt 2> time.txt) || status=$?
  # 124: stopped by timeout (LIMIT); any other failure is an error, not a row
  if [ "$status" != 0 ] && [ "$status" != 124 ]; then
    tail -5 "$dir/screen.txt"; echo "$name failed with exit status $status"; exit 1
  fi
  finished=$([ "$status" = 0 ] && echo 1 || echo 0)
  seconds=$(awk -v a="$start" -v b="$(date +%s%N)" 'BEGIN {printf "%.1f", (b - a) / 1e9}')
  printf "name,N,L_R,dmin_mm,dt_fraction,dt_every,crush_every,layout,fragment_density,ranks,seconds,finished,seed\n%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s\n" \
    "$name" "$n" "$lr" "$dmin" "$frac" "$dt_every" "$every" "$layout" "$fdens" "$ranks" "$seconds" "$finished" \
    "$([ "$seed" = deck ] && echo 15485863 || echo "$seed")" > "$dir/setting.csv"
  [ "$finished" = 1 ] || echo "   stopped after $limit s (LIMIT)"
  grep -E '^wall/servo: ramp 100' "$dir/screen.txt" || true
  echo "   $seconds s"
  touch "$dir/done"
done
done
[ -n "${NO_ANALYSIS:-}" ] || /usr/bin/python3 "$here/bench/accuracy_vs_cost.py" "$out"
