#!/usr/bin/env bash
# What the contact-load hook (patches/0009: every contact model hands its contacts to fix crush)
# costs. Two binaries from the same build: the build itself, and its hot units (hot_variant.sh)
# recompiled with the build's own flags and -DLIGGGHTS_CRUSH_NO_CONTACT_LOAD_HOOK (the hook compiled
# out, as in LIGGGHTS without the patch). bench/in.dense_assembly with each LIGGGHTS normal model:
#   instructions (valgrind's callgrind, exact and repeatable): per step, from the difference of a
#   run of 60 and one of 20 steps on 2,048 spheres; hook / no hook without fix crush (the goal: at
#   most 1.01), and the hook build with a fix crush that records every step and breaks nothing
#   (in.crush_idle) against without it (recording costs the same whatever the law);
#   time: 10,976 spheres, the two binaries run at once, one on each core, then with the cores
#   swapped, in rounds; the median of the in-round ratios and their range. This machine's speed
#   drifts by up to 1.6x within minutes: the times resolve a few percent, the instructions 0.1%.
#   bash bench/contact_load_hook.sh [rounds=3] [steps=800]     (rounds 0: the instructions alone)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=$(cd "${LIGGGHTS_CRUSH_BUILD_DIR:-$here/../build}" && pwd)
rounds=${1:-3}
steps=${2:-800}
flags="$(sed -n 's/^CXX_FLAGS = //p' "$build/CMakeFiles/liggghts.dir/flags.make")"
flags+=" $(sed -n 's/^LIGGGHTS_CRUSH_HOT_FLAGS:STRING=//p' "$build/CMakeCache.txt")"
source "$here/hot_variant.sh"
out=$build/hook_cost
wanted="$flags -DLIGGGHTS_CRUSH_NO_CONTACT_LOAD_HOOK"
if [ ! -x "$out/no_hook/liggghts" ] || [ "$(cat "$out/no_hook/flags" 2>/dev/null)" != "$wanted" ] \
   || [ "$out/no_hook/liggghts" -ot "$build/liggghts" ]; then
  echo "compiling the hot units without the hook: $wanted"
  hot_variant "$out/no_hook" "$wanted"
  echo "$wanted" > "$out/no_hook/flags"
fi
hook=$build/liggghts no_hook=$out/no_hook/liggghts

source "$here/dense_assembly.sh"
# paired LIGGGHTS run of A and B at once, one on each core (the machine's drift falls on both alike),
# then again with the cores swapped; prints A's and B's loop times, each the sum of its two runs.
mkdir -p "$work/a" "$work/b"
cp "$work"/in.* "$work/a/"; cp "$work"/in.* "$work/b/"
paired() {
  local a=$1 b=$2 extra_a=$3 extra_b=$4 ta=0 tb=0 swap args_a args_b
  shift 4
  dense_args "$model" "$tmodel" "$extra_a" "$steps" "$@"; args_a=("${dense_argv[@]}")
  dense_args "$model" "$tmodel" "$extra_b" "$steps" "$@"; args_b=("${dense_argv[@]}")
  for swap in 0 1; do
    (cd "$work/a" && taskset -c $swap "$a" "${args_a[@]}" -log none -screen screen.txt >/dev/null 2>&1) &
    (cd "$work/b" && taskset -c $((1 - swap)) "$b" "${args_b[@]}" -log none -screen screen.txt >/dev/null 2>&1) &
    wait
    ta=$(awk -v t="$ta" '/^Loop time of/ {print t + $4}' "$work/a/screen.txt")
    tb=$(awk -v t="$tb" '/^Loop time of/ {print t + $4}' "$work/b/screen.txt")
  done
  echo "$ta $tb"
}
# law: normal model, tangential model, kn (hooke/stiffness: N/m; hertz/stiffness: N/m^2; the others
# read none)
laws=("hertz/scaled mindlin/scaled 5.7e9" "hertz history 5.7e9" "hertz/stiffness history 5.7e9"
      "hooke history 5.7e9" "hooke/stiffness history 7.8e5")
# instructions BINARY EXTRA KN: callgrind's count per step (60 steps less 20, 2,048 spheres).
instructions() {
  local st
  declare -A at=()
  for st in 20 60; do
    dense_args "$model" "$tmodel" "$2" $st cells 8 kn "$3"
    at[$st]=$(cd "$work/a" && valgrind --tool=callgrind --callgrind-out-file=/dev/null "$1" "${dense_argv[@]}" \
       -log none -screen none 2>&1 | awk '/Collected/ {print $4}')
  done
  awk -v a="${at[20]}" -v b="${at[60]}" 'BEGIN {printf "%.0f", (b - a) / 40}'
}
command -v valgrind >/dev/null || { echo "contact_load_hook: needs valgrind (apt-get install valgrind)" >&2; exit 1; }
echo "instructions per step on 2,048 spheres (callgrind); hot units: $flags"
for law in "${laws[@]}"; do
  read -r model tmodel kn <<< "$law"
  h=$(instructions "$hook" in.none "$kn"); n=$(instructions "$no_hook" in.none "$kn")
  c=$(instructions "$hook" in.crush_idle "$kn")
  printf "%-16s no hook %d, hook %d (%.4f), hook with fix crush %d (%.4f of without)\n" "$model" "$n" "$h" \
         "$(ratio "$h" "$n")" "$c" "$(ratio "$c" "$h")"
done

[ "$rounds" -gt 0 ] || exit 0
declare -A bare crush
echo "10976 spheres, $steps steps, $rounds rounds of pairs run at once on the two cores"
for r in $(seq "$rounds"); do
  line="round $r:"
  for law in "${laws[@]}"; do
    read -r model tmodel kn <<< "$law"
    read -r h n <<< "$(paired "$hook" "$no_hook" in.none in.none kn "$kn")"
    read -r c h2 <<< "$(paired "$hook" "$hook" in.crush_idle in.none kn "$kn")"
    bare[$model]+="$(ratio "$h" "$n") "
    crush[$model]+="$(ratio "$c" "$h2") "
    line+=" $model $n/$h $h2/$c s"
  done
  echo "$line  (no hook/hook, then hook without/with fix crush)"
done
for law in "${laws[@]}"; do
  read -r model _ <<< "$law"
  # shellcheck disable=SC2086  # the ratios are one word each
  summary "$model: hook / no hook, no fix crush" ${bare[$model]}
done
for law in "${laws[@]}"; do
  read -r model _ <<< "$law"
  # shellcheck disable=SC2086
  summary "$model: with fix crush / without" ${crush[$model]}
done
