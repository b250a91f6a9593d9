#!/usr/bin/env bash
# The DEM check of a calibration (doc/calibration.md): fits fix crush's parameters to single-particle
# crushing tests (post/calibrate.py single-particle), runs the single-grain test over a population of
# grains with the fitted fix crush line (examples/calibration/in.population: PER_SIZE grains at each
# size class of the data, in one serial run, each grain pushed onto its own spot of a plane) and
# compares the DEM's failure forces with the tests' (Kolmogorov-Smirnov per size, one figure).
#   bash scripts/calibration_check.sh DATA.csv [OUT_DIR (default runs/calibration)] [single-particle options]
# Environment: PER_SIZE (grains per size, 30), LIGGGHTS (build/liggghts), DISTRIBUTION (instead of
# the fitted line's, e.g. constant: every grain at sigma_lim0, the size effect alone).
# Writes OUT_DIR/fit/ (parameters.json, the figures), OUT_DIR/dem/ (the run, dem_check.png, dem_check.json).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
data=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
shift
out=${1:-$here/runs/calibration}
[ $# -gt 0 ] && shift
mkdir -p "$out" && out=$(cd "$out" && pwd)
liggghts=${LIGGGHTS:-$here/build/liggghts}
py=/usr/bin/python3
$py "$here/post/calibrate.py" single-particle "$data" --out "$out/fit" "$@"
rm -rf "$out/dem" && mkdir -p "$out/dem"
$py "$here/post/calibrate.py" population "$out/fit" --per-size "${PER_SIZE:-30}" --out "$out/dem" \
    ${DISTRIBUTION:+--distribution "$DISTRIBUTION"} > /dev/null
cp "$here/examples/calibration/in.population" "$out/dem/"
read -r -a vars < "$out/dem/variables.txt"
start=$(date +%s%N)
(cd "$out/dem" && "$liggghts" -in in.population "${vars[@]}" -log log.liggghts > screen.txt 2>&1) \
  || { tail -n 5 "$out/dem/screen.txt" >&2; echo "the DEM run failed: $out/dem/screen.txt" >&2; exit 1; }
grep -E '^(GRAINS_BROKEN|FORCE_REACHED)' "$out/dem/screen.txt"
awk -v a="$start" -v b="$(date +%s%N)" 'BEGIN {printf "DEM run: %.1f s (serial)\n", (b - a) / 1e9}'
$py "$here/post/calibrate.py" compare "$data" "$out/fit" "$out/dem"
