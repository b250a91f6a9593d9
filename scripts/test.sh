#!/usr/bin/env bash
# The default test suite: set up and build if needed (idempotent), then every test not labelled slow.
#   bash scripts/test.sh              # unit + regression + mpi
#   bash scripts/test.sh -L slow      # extra ctest arguments select other sets (here: the slow ones)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${LIGGGHTS_CRUSH_BUILD_DIR:-$here/build}
bash "$here/scripts/setup.sh" --no-run
cd "$build_dir"
if [ $# -eq 0 ]; then set -- -LE slow; fi
ctest --output-on-failure -j "$(nproc)" "$@"
