#!/usr/bin/env bash
# fix crush overhead and event cost on 10,976 dense spheres (hertz/scaled + mindlin/scaled):
# 1. blocks of steps with and without a fix crush under which nothing breaks, alternated in one
#    process (bench/in.crush_alternate, ABBA order): ratio of the summed loop times (target <= 1.03),
#    and the spread of the ratio over the rounds;
# 2. a run where every grain breaks once: microseconds per event and per fragment created.
#   bash bench/crush_overhead.sh [quads=10] [block=400]
#   CRUSH_EVERY=adaptive bash bench/crush_overhead.sh    # the same with 'every adaptive' (or every N)
# Why one process: separate runs differ by up to 5% from one invocation to the next on a shared
# machine (memory layout, neighbours' load), more than the overhead measured; paired blocks of one
# run see the same atoms, the same memory and the same machine state.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
quads=${1:-10}
block=${2:-400}
steps=0
source "$here/dense_assembly.sh"
cp "$here/in.crush_alternate" "$work/"

(cd "$work" && "$liggghts" -in in.dense_assembly -var model hertz/scaled -var tmodel mindlin/scaled \
   -var extra in.crush_alternate -var quads "$quads" -var block "$block" -var steps 0 -var crush_every "${CRUSH_EVERY:-1}" \
   -log none -screen screen.txt >/dev/null 2>&1 || { tail -5 screen.txt; exit 1; })
# Loop-time lines: the warm-up, then none, crush, crush, none per round, then the deck's final 'run 0'.
awk -v quads="$quads" -v block="$block" -v every="${CRUSH_EVERY:-1}" '/^Loop time of/ {t[n++] = $4} END {
  if (n < 4 * quads + 1) { print "crush_overhead: expected " 4 * quads + 1 " runs, got " n; exit 1 }
  for (q = 0; q < quads; q++) {
    a = t[1 + 4 * q] + t[4 + 4 * q]; b = t[2 + 4 * q] + t[3 + 4 * q]
    none += a; crush += b; r[q] = b / a
  }
  for (p = 0; p < quads; p++) for (q = p + 1; q < quads; q++) if (r[q] < r[p]) { s = r[p]; r[p] = r[q]; r[q] = s }
  printf "10976 particles, %d rounds of 2 x %d steps each: without fix %.3f s, with fix crush %.3f s\n",
         quads, block, none, crush
  printf "per round: lowest %.3f, median %.3f, highest %.3f\n", r[0], (r[int((quads - 1) / 2)] + r[int(quads / 2)]) / 2, r[quads - 1]
  printf "ratio with / without fix crush (every %s) = %.3f (target <= 1.03; adaptive: <= 1.01)\n", every, crush / none }' "$work/screen.txt"

sed -i 's/^run             \${steps}$/run             ${steps}\nprint           "EVENTS ${events} SECONDS ${seconds}"/' "$work/in.dense_assembly"
dense_run hertz/scaled mindlin/scaled in.crush_all 3
awk '/^EVENTS [0-9]/ {e=$2; s=$4} END {
  printf "every grain breaks once: %d events replaced in %.4f s: %.2f us per event, %.3f us per fragment\n",
         e, s, 1e6*s/e, 1e6*s/(14*e) }' "$work/screen.txt"
