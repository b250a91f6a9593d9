#!/usr/bin/env bash
# Line coverage of the plain C++ model by its unit tests (gcov via gcovr, from Debian).
#   bash scripts/coverage.sh      # builds build-coverage/ (model + unit tests only) and prints a report
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
dir=$here/build-coverage
cmake -S "$here" -B "$dir" -DCMAKE_BUILD_TYPE=Debug -DLIGGGHTS_CRUSH_BUILD_LIGGGHTS=OFF \
      -DLIGGGHTS_CRUSH_COVERAGE=ON > /dev/null
cmake --build "$dir" -j "$(nproc)" > /dev/null
find "$dir" -name '*.gcda' -delete
(cd "$dir" && ctest -L unit > /dev/null)
gcovr --root "$here" --filter "$here/fix_crush/crush_" --filter "$here/pair_hertz_scaled/hertz_mindlin_" \
      "$dir"
