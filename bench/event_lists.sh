#!/usr/bin/env bash
# Event steps without a rebuild (fix crush 'event_lists insert') against a rebuild at every event step
# ('event_lists rebuild'), on the oedometric test O-N (examples/fontainebleau/in.oedometer, N = 1 unless
# given, the ramp to SIGMA_MAX (1e8 Pa)) on RANKS (2) ranks: the sample prepared once, then the
# compression alternated in rounds (insert, then rebuild, in each round). Per run: the compression's
# wall-clock seconds, its loop time, the neighbour builds and LIGGGHTS' neighbour time with its share of
# the loop (summed over the compression's runs), the event steps and those replaced without a rebuild
# (f_crush[10]); then the median of the in-round ratios insert / rebuild with their range.
#   bash bench/event_lists.sh [N (1)] [ROUNDS (2)]
# Environment: LIGGGHTS (build/liggghts), RANKS (2), SIGMA_MAX (1e8).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(dirname "$here")
n=${1:-1}
rounds=${2:-2}
ranks=${RANKS:-2}
sigma_max=${SIGMA_MAX:-1e8}
liggghts=${LIGGGHTS:-$root/build/liggghts}
source "$root/scripts/mpi_env.sh"
source "$here/rounds.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$root"/examples/fontainebleau/in.* "$work"/

deck() {  # deck LABEL MODE: the compression from the prepared sample (reuse 1)
  mkdir -p "$work/$1" && cp "$work"/in.* "$work"/sample_N*.restart "$work/$1"/
  local start
  start=$(date +%s%N)
  (cd "$work/$1" && mpirun -np "$ranks" "$liggghts" -in in.oedometer -var N "$n" -var sigma_max "$sigma_max" \
     -var reuse 1 -var crush_where "event_lists $2" -var timing yes -log log.liggghts > screen.txt 2>&1) \
    || { tail -5 "$work/$1/screen.txt"; exit 1; }
  local seconds events
  seconds=$(awk -v a="$start" -v b="$(date +%s%N)" 'BEGIN {printf "%.1f", (b - a) / 1e9}')
  events=$(cut -d, -f1 "$work/$1"/events_O"$n".csv | tail -n +2 | sort -u | wc -l)
  # loop time and neighbour time (the first number of 'Neigh time (%) = s (p)') of the ramp's
  # stretches, builds, and the deck's count of event steps replaced without a rebuild (f_crush[10])
  awk -v s="$seconds" -v e="$events" '/^Loop time of/ {loop += $4} /^Neigh time/ {neigh += $5}
       /^Neighbor list builds/ {builds += $NF} /^EVENT STEPS WITHOUT A REBUILD/ {inserted = $NF}
       END {printf "%s %.1f %.1f %.1f %d %d %d\n", s, loop, neigh, 100 * neigh / loop, builds, e, inserted}' \
      "$work/$1/screen.txt"
}

echo "preparing the sample (N = $n) ..."
(cd "$work" && mpirun -np "$ranks" "$liggghts" -in in.prepare -var N "$n" -log log.prepare > screen.prepare 2>&1) || { tail -5 "$work/screen.prepare"; exit 1; }
printf '%-8s %-6s %9s %9s %9s %7s %7s %12s %9s\n' round lists "deck (s)" "loop (s)" "neigh (s)" "neigh %" builds "event steps" inserted
time_ratios=() neigh_ratios=() build_ratios=()
for r in $(seq "$rounds"); do
  declare -A row=()
  for mode in insert rebuild; do
    row[$mode]=$(deck "r${r}_$mode" "$mode")
    read -r s loop neigh share builds events inserted <<< "${row[$mode]}"
    printf '%-8s %-6s %9s %9s %9s %7s %7s %12s %9s\n' "$r" "$mode" "$s" "$loop" "$neigh" "$share" "$builds" "$events" "$inserted"
  done
  read -r s1 _ n1 _ b1 _ _ <<< "${row[insert]}"
  read -r s2 _ n2 _ b2 _ _ <<< "${row[rebuild]}"
  time_ratios+=("$(ratio "$s1" "$s2")") neigh_ratios+=("$(ratio "$n1" "$n2")") build_ratios+=("$(ratio "$b1" "$b2")")
done
summary "O-$n on $ranks ranks, compression time, insert / rebuild" "${time_ratios[@]}"
summary "neighbour time, insert / rebuild" "${neigh_ratios[@]}"
summary "neighbour builds, insert / rebuild" "${build_ratios[@]}"
