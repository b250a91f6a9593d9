#!/usr/bin/env bash
# The full Fontainebleau runs of studies/fontainebleau/README.md: O-N and I-N to 100 MPa for N = 2, 1.5, 1, and the
# dense and loose triaxial tests at 100 kPa, each on RANKS MPI ranks (default 2), then the figures.
#   bash scripts/fontainebleau_runs.sh [OUT_DIR (default runs/fontainebleau)] [tests...]
#   tests: O2 O1.5 O1 I2 I1.5 I1 Tdense Tloose (default: all); TEST:SEED runs it with another seed
#   (sample and strengths), e.g. O2:179424673 (a prime that differs from the decks' template seeds), into OUT_DIR/TEST_sSEED
# Environment: RANKS (2), LIGGGHTS (build/liggghts), EXTRA_VARS (further -var pairs for every test,
# e.g. "-var neighbor_style multi"), PLOT (the figures' command: default /usr/bin/python3 post/plot.py;
# setup.sh gives the installed crush-plot).
# A test whose folder holds 'done' (a finished run) is kept, not run again: delete the folder to redo it.
# Writes OUT_DIR/<test>/ (the deck's outputs and log), OUT_DIR/runtimes.csv (test, ranks, initial and
# final particles, events, wall-clock seconds) and OUT_DIR/figures/*.png (post/plot.py).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out=$(mkdir -p "${1:-$here/runs/fontainebleau}" && cd "${1:-$here/runs/fontainebleau}" && pwd)
shift || true
tests=${*:-O2 O1.5 O1 I2 I1.5 I1 Tdense Tloose}
ranks=${RANKS:-2}
liggghts=${LIGGGHTS:-$here/build/liggghts}
source "$here/scripts/mpi_env.sh"
[ -f "$out/runtimes.csv" ] || echo "test,ranks,initial_particles,final_particles,events,seconds" > "$out/runtimes.csv"
for spec in $tests; do
  t=${spec%%:*}
  seed_vars=()
  dir=$out/$t
  if [ "$spec" != "$t" ]; then seed_vars=(-var seed "${spec#*:}"); dir=$out/${t}_s${spec#*:}; fi
  case $t in
    O*) deck=in.oedometer; vars=(-var N "${t#O}") ;;
    I*) deck=in.isotropic; vars=(-var N "${t#I}") ;;
    Tdense) deck=in.triaxial; vars=() ;;
    Tloose) deck=in.triaxial; vars=(-var sample loose -var mu_prep 0.5) ;;
    *) echo "unknown test $t (O2 O1.5 O1 I2 I1.5 I1 Tdense Tloose)" >&2; exit 2 ;;
  esac
  vars+=(${seed_vars[@]+"${seed_vars[@]}"})
  # EXTRA_VARS: further -var pairs for every test (for example '-var neighbor_style multi')
  read -r -a extra <<< "${EXTRA_VARS:-}"
  vars+=(${extra[@]+"${extra[@]}"})
  if [ -f "$dir/done" ]; then echo "== $spec: done before ($dir/done)"; continue; fi
  rm -rf "$dir" && mkdir -p "$dir" && cp "$here"/examples/fontainebleau/in.* "$dir"/
  echo "== $spec: mpirun -np $ranks liggghts -in $deck ${vars[*]}"
  start=$(date +%s%N)
  (cd "$dir" && mpirun -np "$ranks" "$liggghts" -in "$deck" "${vars[@]}" -log log.liggghts > screen.txt 2>&1) \
    || { tail -n 5 "$dir/screen.txt" >&2; echo "$spec failed: $dir/screen.txt" >&2; exit 1; }
  seconds=$(awk -v a="$start" -v b="$(date +%s%N)" 'BEGIN {printf "%.1f", (b - a) / 1e9}')
  grep -E '^(SAMPLE|wall/servo: ramp +(25|50|75|100)\.0)' "$dir/screen.txt" || true
  initial=$(sed -n 's/^SAMPLE N = [^:]*: \([0-9]*\) particles.*/\1/p' "$dir/screen.txt")
  events=$(($(cat "$dir"/events_*.csv | wc -l) - 1))
  final=$((initial + 13 * events))
  echo "$spec,$ranks,$initial,$final,$events,$seconds" >> "$out/runtimes.csv"
  touch "$dir/done"
  echo "   $seconds s"
done
read -r -a plot <<< "${PLOT:-/usr/bin/python3 $here/post/plot.py}"
"${plot[@]}" --out "$out/figures" "$out"/*/ || echo "the figures were not drawn (above): the runs are in $out" >&2
