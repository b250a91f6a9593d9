#!/usr/bin/env bash
# Rewrites the regression references (tests/regression/reference/*.json) from the current build, on
# purpose: after a change of the physics or of the toolchain. Records the git commit and the build
# options next to the data. Never run by the tests.
#   bash scripts/regen_references.sh [build-dir]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-$here/build}
for case in $(python3 -c "import sys; sys.path.insert(0, '$here/tests/regression'); from reference_cases import CASES; print(' '.join(CASES))"); do
  python3 "$here/tests/regression/compare_reference.py" "$build/liggghts" "$build/regen_$case" "$case" --regenerate
done
# fix dt/stiffness's step sequence along O-2 (test_fontainebleau.py, case time_step_sequence)
LIGGGHTS_CRUSH_REGENERATE=1 python3 "$here/tests/regression/test_fontainebleau.py" "$build/liggghts" \
  "$build/regen_time_step_sequence" time_step_sequence
