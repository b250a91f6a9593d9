#!/usr/bin/env bash
# AddressSanitizer + UndefinedBehaviorSanitizer build of the plugin (and LIGGGHTS) in build-asan/:
# runs the unit tests and the crushing decks (single grain, compression with restart) under the
# sanitizers. LIGGGHTS' own leaks at exit are not ours: leak detection is off.
#   bash scripts/sanitize.sh          (first build about 15 minutes on 2 cores)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
dir=$here/build-asan
tarball=$(ls "$here"/.downloads/liggghts_3.8.0*.orig.tar.* 2>/dev/null | head -n 1 || true)
cmake -S "$here" -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLIGGGHTS_CRUSH_SANITIZE=ON \
      ${tarball:+-DLIGGGHTS_TARBALL="$tarball"} > /dev/null
cmake --build "$dir" -j "$(nproc)"
# verify_asan_link_order=0: the deck tests run liggghts under stdbuf, which preloads a library.
export ASAN_OPTIONS=detect_leaks=0:abort_on_error=1:verify_asan_link_order=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
"$dir/tests/unit/crush_unit_tests"
for case in single_grain restart compression; do
  python3 "$here/tests/regression/test_crush.py" "$dir/liggghts" "$dir/sanitize_$case" "$case"
done
echo "sanitizers: clean"
