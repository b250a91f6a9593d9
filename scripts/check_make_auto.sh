#!/usr/bin/env bash
# Proves the "copy the plugin into LIGGGHTS' src/ and run make auto" path: unpacks the LIGGGHTS
# tarball into a scratch folder, applies patches/, copies the plugin folders' files into src/, builds
# with LIGGGHTS' own 'make auto', and runs the smoke deck with the resulting binary.
#   bash scripts/check_make_auto.sh [scratch-dir]      (about 10 minutes on 2 cores; ctest label: slow)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
scratch=${1:-$here/build-make-auto}
tarball=${LIGGGHTS_TARBALL:-$here/.downloads/liggghts_3.8.0+repack1.orig.tar.xz}
[ -f "$tarball" ] || { echo "no LIGGGHTS tarball at $tarball: run 'bash scripts/setup.sh --no-build'"; exit 1; }

rm -rf "$scratch" && mkdir -p "$scratch"
tar xJf "$tarball" -C "$scratch"
tree=$(echo "$scratch"/LIGGGHTS-PUBLIC-*)
for p in "$here"/patches/*.patch; do patch -s -p1 -d "$tree" < "$p"; done
cp "$here"/fix_crush/* "$here"/pair_hertz_scaled/* "$tree/src/"

# LIGGGHTS' user options: no VTK (LIGGGHTS 3.8.0 predates Debian's VTK 9), Eigen for the plugin.
cat > "$tree/src/MAKE/Makefile.user" <<MAKEUSER
USE_MPI = "ON"
USE_VTK = "OFF"
USE_SUPERQUADRICS = "OFF"
USE_JPG = "OFF"
USE_FPIC = "ON"
USE_DEBUG = "OFF"
USE_PROFILE = "OFF"
USE_CONVEX = "OFF"
USE_GZIP = "OFF"
USE_XDR = "OFF"
USE_MFEM = "OFF"
BUILD_LIBRARIES = "NONE"
MAKEFILE_USER_VERSION = "1.4"
MPI_CCFLAGS_USR = -funroll-loops -fstrict-aliasing -Wno-unused-result -I/usr/include/eigen3
MAKEUSER
command -v ccache >/dev/null && export CCACHE_BASEDIR="$scratch"
(cd "$tree/src" && make -j "$(nproc)" auto > "$scratch/make_auto.log" 2>&1) || {
  tail -30 "$scratch/make_auto.log"; echo "make auto FAILED (log: $scratch/make_auto.log)"; exit 1; }
exe="$tree/src/lmp_auto"
[ -x "$exe" ] || { echo "make auto produced no $exe"; exit 1; }
mkdir -p "$scratch/run" && cd "$scratch/run"
"$exe" -in "$here/examples/smoke/in.smoke" | tee run.log | tail -3
grep -q "SMOKE_DONE atoms=100" run.log && echo "make auto build: OK ($exe)"
