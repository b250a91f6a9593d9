#!/usr/bin/env bash
# The paper's upscaling claim with seeds (studies/fontainebleau/README.md, "Upscaling"): the oedometric and
# isotropic tests at N = 1, 1.5 and 2, each with the seeds of SEEDS, run by scripts/fontainebleau_runs.sh
# one round a seed, then compared with N = 1 by post/compression_seeds.py.
#   bash scripts/upscaling_seeds.sh [OUT_DIR (default runs/upscaling)] [tests (default O1 O1.5 O2 I1 I1.5 I2)]
# Environment: SEEDS (default the decks' 15485863 and the primes 179424673 275604541: none of the
# grading's template seeds), RANKS (2), LIGGGHTS (build/liggghts).
# A run already done (OUT_DIR/<test>_s<seed>/done) is kept, so that a stopped study goes on where it
# stopped and runs of the same deck from elsewhere (bench/accuracy_seeds.sh's N1_s* and N2_s* are
# O-1 and O-2 at the decks' defaults) can be copied in. About 1.5 hours on a 2-core machine.
# Writes OUT_DIR/<test>_s<seed>/, OUT_DIR/runtimes.csv and OUT_DIR/upscaling_{runs,seeds}.csv and
# upscaling_seeds.png.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out=$(mkdir -p "${1:-$here/runs/upscaling}" && cd "${1:-$here/runs/upscaling}" && pwd)
shift || true
tests=${*:-O1 O1.5 O2 I1 I1.5 I2}
for seed in ${SEEDS:-15485863 179424673 275604541}; do
  specs=()
  for t in $tests; do specs+=("$t:$seed"); done
  PLOT=true bash "$here/scripts/fontainebleau_runs.sh" "$out" "${specs[@]}"
done
/usr/bin/python3 "$here/post/compression_seeds.py" --name upscaling --out "$out" "$out"/[OI]*_s*/
