#!/usr/bin/env bash
# The fragments' time-step knob (fix crush 'fragment_density scaled', doc/fix_crush.txt) as an
# accuracy-versus-cost row: O-2 to 100 MPa and the penetration test dense_region, each over three
# seeds with the true density and with the scaled one, then bench/fragment_density.py's tables
# (studies/accuracy/history.md, "The fragments' time step"). About 25 minutes on 2 cores.
#   bash bench/fragment_density.sh [OUT_DIR (default runs/fragment_density)]
# Environment: LIGGGHTS (build/liggghts), RANKS (2).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out=$(mkdir -p "${1:-$here/runs/fragment_density}" && cd "${1:-$here/runs/fragment_density}" && pwd)
seeds="O2 O2:179424673 O2:275604541"
# shellcheck disable=SC2086
EXTRA_VARS="-var fragment_density scaled" bash "$here/scripts/fontainebleau_runs.sh" "$out/o2_scaled" $seeds
# shellcheck disable=SC2086
bash "$here/scripts/fontainebleau_runs.sh" "$out/o2_true" $seeds
bash "$here/scripts/penetration_study.sh" "$out/penetration" dense_region_scaled dense_region \
  dense_region_scaled_s2 dense_region_N60_s2 dense_region_scaled_s3 dense_region_N60_s3
/usr/bin/python3 "$here/bench/fragment_density.py" "$out/o2_true" "$out/o2_scaled" "$out/penetration/study.csv" \
  | tee "$out/fragment_density.md"
