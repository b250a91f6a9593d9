#!/usr/bin/env bash
# Table 3 from seeds (studies/fontainebleau/README.md): the oedometric and isotropic tests O-N and I-N to 100 MPa at
# N = 2, 1.5, 1, each with five seeds (the decks' own and four primes), on RANKS ranks (default 2)
# through scripts/fontainebleau_runs.sh (a finished run is kept), each run's row added to
# studies/fontainebleau/table3_runs.csv as it lands, then the tables rewritten from the CSV (post/tables.py).
#   bash scripts/table3_runs.sh [OUT_DIR (default runs/table3)] [TESTS (default O2 I2 O1.5 I1.5 O1 I1)]
# SEEDS overrides the five seeds. A run of N = 2 takes about a minute on 2 ranks, N = 1.5 about 2 - 5,
# N = 1 about 20: split the study by TESTS to fit a sitting.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out=${1:-$here/runs/table3}
shift || true
tests=${*:-O2 I2 O1.5 I1.5 O1 I1}
seeds=${SEEDS:-15485863 179424673 275604541 1299709 373587883}
for t in $tests; do
  for s in $seeds; do
    PLOT=true bash "$here/scripts/fontainebleau_runs.sh" "$out" "$t:$s"
    /usr/bin/python3 "$here/post/tables.py" --add-run "$out/runtimes.csv" "$t:$s"
  done
done
/usr/bin/python3 "$here/post/tables.py" table3 table3_io
