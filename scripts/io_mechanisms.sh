#!/usr/bin/env bash
# The isotropic against the oedometric tests at N = 2 under each candidate mechanism of the paper's
# ordering (studies/fontainebleau/README.md): every variant of studies/fontainebleau/io_variants.csv
# (a row a variant: its name, the deck variables, what it tests) runs O-2 and I-2 to 100 MPa with five
# seeds through scripts/fontainebleau_runs.sh, each run's row added to
# studies/fontainebleau/io_mechanisms_runs.csv as it lands, then the table io_mechanisms rewritten.
#   bash scripts/io_mechanisms.sh [OUT_DIR (default runs/io)] [VARIANTS (default: every row)]
# SEEDS overrides the five seeds; RANKS the ranks (2). A pair of runs takes about 1.5 minutes on 2 ranks.
# The variant 'decks' runs the decks as they are (Table 3's runs of scripts/table3_runs.sh are the same).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out=${1:-$here/runs/io}
shift || true
table=$here/studies/fontainebleau/io_variants.csv
variants=${*:-$(tail -n +2 "$table" | cut -d, -f1)}
seeds=${SEEDS:-15485863 179424673 275604541 1299709 373587883}
for v in $variants; do
  line=$(awk -F, -v v="$v" 'NR > 1 && $1 == v {print; exit}' "$table")
  [ -n "$line" ] || { echo "io_mechanisms.sh: no variant $v in $table" >&2; exit 2; }
  vars=$(echo "$line" | cut -d, -f2)
  for s in $seeds; do
    for t in O2 I2; do
      EXTRA_VARS="$vars" PLOT=true bash "$here/scripts/fontainebleau_runs.sh" "$out/$v" "$t:$s"
      /usr/bin/python3 "$here/post/tables.py" --add-run "$out/$v/runtimes.csv" "$t:$s" --variant "$v"
    done
  done
done
/usr/bin/python3 "$here/post/tables.py" io_mechanisms
