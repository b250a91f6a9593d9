#!/usr/bin/env bash
# The strength reading side by side (studies/fontainebleau/README.md, "The strength reading side by side"): O-2 and I-2
# to 100 MPa under four readings of the grains' strengths, each with the seeds of SEEDS, one round a
# seed (every reading once in turn), each reading's runs in a folder of its own:
#   clipped    the decks' normal_clipped_originals (the Table 3 reading: an original grain's negative
#              draw clipped to zero, so about a sixth of the grains break at the first load)
#   normal     the normal truncated by redrawing (no zero-strength grain), sigma_lim0 5e9 Pa
#   matched    the same normal with sigma_lim0 SIGMA_LIM0_MATCHED (Pa), in the folder
#              matched_<sigma_lim0 in GPa>GPa (matched_0.88GPa): the value that brings O-2's
#              yield stress back to the clipped reading's, found by trials with this script
#              (TESTS=O2 SEEDS=... SIGMA_LIM0_MATCHED=... ... matched) and post/compression_seeds.py's
#              yield_MPa; run only when SIGMA_LIM0_MATCHED is given
#   none       no crushing at all: the grains' elastic compression alone
# then post/compression_seeds.py compares each reading with clipped.
#   bash scripts/strength_readings.sh [OUT_DIR (default runs/readings)] [readings (default clipped,
#   normal and none, and matched where SIGMA_LIM0_MATCHED is given)]
# Environment: SEEDS (default the decks' 15485863 and the primes 179424673 275604541 373587883 1299709,
# none of the grading's template seeds), TESTS (O2 I2), SIGMA_LIM0_MATCHED, RANKS (2), LIGGGHTS.
# A run already done (OUT_DIR/<reading>/<test>_s<seed>/done) is kept. About 50 minutes on a 2-core
# machine. Writes OUT_DIR/<reading>/<test>_s<seed>/ and OUT_DIR/readings_{runs,seeds}.csv,
# readings_seeds.png and readings_curves.png.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out=$(mkdir -p "${1:-$here/runs/readings}" && cd "${1:-$here/runs/readings}" && pwd)
shift || true
matched=${SIGMA_LIM0_MATCHED:-}
readings=${*:-clipped normal ${matched:+matched} none}
for seed in ${SEEDS:-15485863 179424673 275604541 373587883 1299709}; do
  for reading in $readings; do
    case $reading in
      clipped) vars="" ;;
      normal)  vars="-var distribution normal" ;;
      matched) [ -n "$matched" ] || { echo "strength_readings.sh: the reading matched needs SIGMA_LIM0_MATCHED (Pa)" >&2; exit 2; }
               vars="-var distribution normal -var sigma_lim0 $matched" ;;
      none)    vars="-var crushing 0" ;;
      *) echo "strength_readings.sh: unknown reading $reading (clipped normal matched none)" >&2; exit 2 ;;
    esac
    specs=()
    for t in ${TESTS:-O2 I2}; do specs+=("$t:$seed"); done
    folder=$reading
    [ "$reading" != matched ] || folder=matched_$(awk -v s="$matched" 'BEGIN {printf "%g", s / 1e9}')GPa
    EXTRA_VARS="$vars" PLOT=true bash "$here/scripts/fontainebleau_runs.sh" "$out/$folder" "${specs[@]}"
  done
done
/usr/bin/python3 "$here/post/compression_seeds.py" --by-folder --reference folder=clipped --name readings \
  --out "$out" "$out"/*/[OI]*_s*/
