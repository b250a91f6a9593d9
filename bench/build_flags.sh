#!/usr/bin/env bash
# Which compiler flags make the fastest binary: the translation units that hold the dense benchmark's
# time (cmake/hot_path_units.txt: the contact models and the granular pair loop, all instantiated in
# lammps.cpp; the integrator; neighbour lists and communication) recompiled with each candidate set
# (in place of the build's own flags for them) and linked with
# the build's other objects, then bench/in.dense_assembly timed with each binary and with Debian's
# liggghts, alternated in rounds; prints the median of the in-round ratios to Debian's and their
# spread. The rest of the binary (input parsing, output, setup) is not on the hot path.
#   bash bench/build_flags.sh [rounds=5] [steps=1500] ["name:flags" ...]
# Default candidates: Debian's (-O2: dpkg-buildflags' CXXFLAGS, which override LIGGGHTS' own CMake
# defaults), LIGGGHTS' Makefile default (-O2 -funroll-loops -fstrict-aliasing), -O3 without
# unrolling, and -O2 -fno-math-errno and -march=native variants; this_build is the build as it is.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=$(cd "${LIGGGHTS_CRUSH_BUILD_DIR:-$here/../build}" && pwd)
rounds=${1:-5}
steps=${2:-1500}
shift $(( $# > 2 ? 2 : $# ))
candidates=("$@")
[ ${#candidates[@]} -gt 0 ] || candidates=(
  "o2:-O2 -DNDEBUG"
  "o2_unroll:-O2 -DNDEBUG -funroll-loops -fstrict-aliasing"
  "o3:-O3 -DNDEBUG -fstrict-aliasing"
  "o2_nomatherrno:-O2 -DNDEBUG -fno-math-errno"
  "o2_native:-O2 -DNDEBUG -march=native")
[ -x /usr/bin/liggghts ] || { echo "build_flags: needs Debian's liggghts (apt-get install liggghts)" >&2; exit 1; }

out=$build/flags
mkdir -p "$out"
source "$here/hot_variant.sh"

# variant NAME FLAGS: the hot units compiled with FLAGS, linked as $out/NAME/liggghts.
variant() { hot_variant "$out/$1" "$2"; }

names=(this_build)
for c in "${candidates[@]}"; do
  name=${c%%:*}; flags=${c#*:}
  if [ ! -x "$out/$name/liggghts" ] || [ "$(cat "$out/$name/flags" 2>/dev/null)" != "$flags" ]; then
    echo "compiling the hot units with $flags ($name)"
    variant "$name" "$flags"
    echo "$flags" > "$out/$name/flags"
  fi
  names+=("$name")
done

source "$here/dense_assembly.sh"
declare -A ratios
echo "10976 spheres, hertz + tangential history, $steps steps, one core, $rounds rounds"
echo "this_build: $(sed -n 's/^CXX_FLAGS = //p' "$build/CMakeFiles/liggghts.dir/flags.make"), hot path adds" \
     "$(sed -n 's/^LIGGGHTS_CRUSH_HOT_FLAGS:STRING=//p' "$build/CMakeCache.txt")"
for r in $(seq "$rounds"); do
  d=$(liggghts=/usr/bin/liggghts loop_time hertz history in.none)
  line="round $r: Debian $d s"
  for name in "${names[@]}"; do
    if [ "$name" = this_build ]; then bin=$build/liggghts; else bin=$out/$name/liggghts; fi
    t=$(liggghts=$bin loop_time hertz history in.none)
    ratios[$name]+="$(ratio "$t" "$d") "
    line+=", $name $t s"
  done
  echo "$line"
done
for name in "${names[@]}"; do
  # shellcheck disable=SC2086  # the ratios are one word each
  summary "$name ($(cat "$out/$name/flags" 2>/dev/null || echo 'as built')) / Debian's" ${ratios[$name]}
done
