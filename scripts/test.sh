#!/usr/bin/env bash
# The default test suite: set up and build if needed (idempotent), then every test not labelled slow
# or long (tests/long.txt).
#   bash scripts/test.sh              # the default set: unit + regression + mpi, about 10 minutes on 2 cores
#   bash scripts/test.sh -L long      # extra ctest arguments select other sets: the long set
#   bash scripts/test.sh -L slow      # the studies' slow cases
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${LIGGGHTS_CRUSH_BUILD_DIR:-$here/build}
bash "$here/scripts/setup.sh" --no-run
cd "$build_dir"
if [ $# -eq 0 ]; then set -- -LE "slow|long"; fi
ctest --output-on-failure -j "$(nproc)" "$@"
