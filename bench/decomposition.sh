#!/usr/bin/env bash
# The decomposition a refined chamber needs, simulated from its real states (doc/running.md, "Many
# ranks"): one refined chamber (examples/penetration/in.chamber, refine 1, N and width as given,
# 2 ranks), one cone test of DEPTH D_c in it (crushing in the zone), then post/decomposition.py on
# the consolidated chamber and the test's last state: for 2 - 256 ranks, the grids "* * 1", "1 1 *"
# and 3-D, uniform cuts and cuts at the particles' and at the work's quantiles, the fullest rank's
# work over the mean and the ghosts per rank. Prints the table; keeps the rows and the figure in
# OUT_DIR.
#   bash bench/decomposition.sh [OUT_DIR (runs/decomposition)] [N=34] [DEPTH=4] [WIDTH=10]
# Environment: LIGGGHTS (build/liggghts), SCENE (in.chamber's and in.cone's further variables,
# name=value,name=value, e.g. distribution=normal for the default scene's pristine grains).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out=$(mkdir -p "${1:-$here/runs/decomposition}" && cd "${1:-$here/runs/decomposition}" && pwd)
n=${2:-34} depth=${3:-4} width=${4:-10}
liggghts=${LIGGGHTS:-$here/build/liggghts}
source "$here/scripts/mpi_env.sh"
source "$here/bench/penetration_work.sh"
vars=(-var N "$n" -var refine 1 -var width "$width" -var depth "$depth" -var v 2 -var vtk 0 -var checkpoint_every 0)
add_scene_vars
mpirun -np 2 "$liggghts" -in in.chamber "${vars[@]}" -log chamber.log > chamber.txt 2>&1 || { tail -5 chamber.txt; exit 1; }
grep '^CHAMBER .* N = ' chamber.txt
mpirun -np 2 "$liggghts" -in in.cone "${vars[@]}" -var crushing region -var label bench -log cone.log > cone.txt 2>&1 \
  || { tail -5 cone.txt; exit 1; }
grep '^PENETRATED' cone.txt
# the granular lists' skin of in.cone (0.00002 N m), as post/decomposition.py counts the work
skin=$(awk -v n="$n" 'BEGIN {printf "%.6g", 0.00002 * n}')
/usr/bin/python3 "$here/post/decomposition.py" "consolidated=chamber_dense_N${n}.liggghts" \
  "tip at $depth D_c=particles_bench_N${n}.liggghts" --skin "$skin" \
  --csv "$out/decomposition_N${n}.csv" --plot "$out/decomposition_N${n}.png"
