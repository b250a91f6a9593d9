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
cp "$here"/common/* "$here"/pair_hertz_scaled/* "$here"/quasi_static/* "$here"/fix_crush/* "$here"/checkpoint/* "$here"/balance/* "$here"/neighbor_classes/* "$tree/src/"

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
MPI_LIB_USR = $(mpicxx --showme:libdirs | awk '{print $1}')
MPI_INC_USR = $(mpicxx --showme:incdirs | awk '{print $1}')
MAKEUSER
command -v ccache >/dev/null && export CCACHE_BASEDIR="$scratch"
# Makefile.auto detects the MPI flavour from a test file written with '\#include': GNU make >= 4.3
# keeps that backslash, the test fails and Open MPI is taken for MPICH (-lmpich). Name it instead.
mpi_type=OpenMPI
mpicxx --showme >/dev/null 2>&1 || mpi_type=MPICH
(cd "$tree/src" && make -j "$(nproc)" auto MPI_TYPE=$mpi_type > "$scratch/make_auto.log" 2>&1) || {
  tail -30 "$scratch/make_auto.log"; echo "make auto FAILED (log: $scratch/make_auto.log)"; exit 1; }
exe="$tree/src/lmp_auto"
[ -x "$exe" ] || { echo "make auto produced no $exe"; exit 1; }
mkdir -p "$scratch/run" && cd "$scratch/run"
"$exe" -in "$here/examples/smoke/in.smoke" | tee run.log | tail -3
"$exe" -h > styles.txt 2>&1 || true
for style in crush/gsd hertz/scaled mindlin/scaled damp/local wall/servo; do
  grep -q "$style" styles.txt || { echo "make auto binary lacks the style $style"; exit 1; }
done
grep -q "SMOKE_DONE atoms=100" run.log && echo "make auto build: OK ($exe)"
