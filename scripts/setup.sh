#!/usr/bin/env bash
# Setup: what liggghts-crush needs, the LIGGGHTS 3.8.0 source, configure and build, then install and
# the main job. Idempotent: every step checks before acting. Two paths:
#  - Debian 12 / Ubuntu as root (or with sudo): installs the Debian packages it lacks and fetches
#    LIGGGHTS' source package with apt-get source (enabling apt source entries derived from this
#    machine's own apt configuration when needed).
#  - Anywhere else (a cluster with environment modules, a machine without dpkg, Debian without root):
#    nothing is installed. It checks what the build needs (an MPI compiler wrapper, CMake >= 3.21,
#    make, patch), says what is missing, and builds with what is there: Eigen 3 through CMake;
#    GoogleTest, VTK, ccache and numpy/scipy/matplotlib are optional. The compiler is the MPI
#    wrapper (MPICXX, default mpicxx). LIGGGHTS' source is the tarball the user gives (--tarball or
#    LIGGGHTS_TARBALL; CMake checks its SHA256), or Debian's source package where apt-get source works.
#
#   bash scripts/setup.sh [--tarball FILE]            # source + build, install (to ~/.local), then the
#                                                     # main job: O-2 to 100 MPa, its summary and figures
#   bash scripts/setup.sh --no-run [--tarball FILE]   # source + build
#   bash scripts/setup.sh --no-build [--tarball FILE] # source only
# Environment: LIGGGHTS_CRUSH_BUILD_DIR (default ./build), LIGGGHTS_CRUSH_DOWNLOAD_DIR (./.downloads),
# LIGGGHTS_CRUSH_PREFIX (install prefix, default ~/.local), LIGGGHTS_TARBALL, MPICXX and MPICC (the
# second path's compilers), LIGGGHTS_CRUSH_NO_APT=1 (the second path on a Debian machine),
# LIGGGHTS_CRUSH_CMAKE_ARGS (further configure options, e.g. "-DLIGGGHTS_CRUSH_VTK=OFF").
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${LIGGGHTS_CRUSH_BUILD_DIR:-$here/build}
download_dir=${LIGGGHTS_CRUSH_DOWNLOAD_DIR:-$here/.downloads}
tarball=${LIGGGHTS_TARBALL:-}
do_build=1
do_run=1
usage() { echo "usage: bash scripts/setup.sh [--no-run|--no-build] [--tarball LIGGGHTS_TARBALL]" >&2; exit 2; }
while [ $# -gt 0 ]; do
  case "$1" in
    --no-build) do_build=0; do_run=0 ;;
    --no-run) do_run=0 ;;
    --tarball) [ $# -ge 2 ] || usage; tarball=$2; shift ;;
    *) usage ;;
  esac
  shift
done

say() { printf '[setup] %s\n' "$*"; }
tarball_name=liggghts_3.8.0+repack1.orig.tar.xz
tarball_sha256=$(sed -n 's/^set(LIGGGHTS_TARBALL_SHA256 "\([0-9a-f]*\)".*/\1/p' "$here/cmake/LiggghtsSource.cmake")

as_root() { if [ "$(id -u)" -eq 0 ]; then "$@"; elif command -v sudo >/dev/null; then sudo "$@"; else return 1; fi; }
can_root() { [ "$(id -u)" -eq 0 ] || { command -v sudo >/dev/null && sudo -n true 2>/dev/null; }; }
no_apt() { [ -n "${LIGGGHTS_CRUSH_NO_APT:-}" ] && [ "${LIGGGHTS_CRUSH_NO_APT}" != 0 ]; }
have_apt() { ! no_apt && command -v dpkg-query >/dev/null && command -v apt-get >/dev/null; }

# --- path 1: Debian packages ------------------------------------------------------------------------
packages=(g++ make cmake ccache patch libopenmpi-dev openmpi-bin libeigen3-dev libgtest-dev
          xz-utils dpkg-dev python3 python3-numpy python3-matplotlib gcovr
          python3-scipy  # post/calibrate.py: fits and goodness-of-fit statistics
          time   # GNU time: peak memory in bench/memory.sh and bench/accuracy_vs_cost.sh
          procps # pkill/pgrep: the checkpoint tests kill a whole MPI run
          libvtk9-dev python3-vtk9)  # VTK dumps for ParaView (dump custom/vtk, patch 0005); the test reads them

debian=0  # 1: every Debian package is there (installed now or before): the Debian build
if have_apt; then
  missing=()
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ ${#missing[@]} -eq 0 ]; then
    say "all Debian packages present"
    debian=1
  elif can_root; then
    say "installing Debian packages: ${missing[*]}"
    as_root apt-get update -qq
    DEBIAN_FRONTEND=noninteractive as_root apt-get install -y -qq --no-install-recommends "${missing[@]}"
    debian=1
  else
    say "missing Debian packages: ${missing[*]}"
    say "without root, building with what is here (as root: apt-get install ${missing[*]})"
  fi
else
  say "no apt here (or LIGGGHTS_CRUSH_NO_APT): nothing is installed; building with what is here"
fi

# --- path 2: what the build needs, found on the PATH -------------------------------------------------
cmake_args=(-DCMAKE_BUILD_TYPE=Release)
if [ $debian -eq 0 ] && [ $do_build -eq 1 ]; then
  lacking=()
  mpicxx=$(command -v "${MPICXX:-mpicxx}" || true)
  [ -n "$mpicxx" ] || lacking+=("an MPI C++ compiler wrapper (${MPICXX:-mpicxx}; e.g. 'module load openmpi', or set MPICXX)")
  for tool in cmake make patch; do
    command -v "$tool" >/dev/null || lacking+=("$tool")
  done
  if command -v cmake >/dev/null; then
    version=$(cmake --version | sed -n 's/^cmake version \([0-9][0-9.]*\).*/\1/p')
    [ "$(printf '%s\n3.21\n' "$version" | sort -V | head -n 1)" = 3.21 ] \
      || lacking+=("CMake >= 3.21 (found $version; e.g. 'module load cmake')")
  fi
  if [ ${#lacking[@]} -gt 0 ]; then
    say "cannot build: missing"
    for l in "${lacking[@]}"; do say "  - $l"; done
    say "a cluster's lines are in doc/building.md, \"On a cluster\"; then run this script again"
    exit 1
  fi
  mpicc=$(command -v "${MPICC:-mpicc}" || true)
  say "compilers: $mpicxx${mpicc:+ and $mpicc} (MPI wrappers)"
  cmake_args+=(-DCMAKE_CXX_COMPILER="$mpicxx")
  [ -z "$mpicc" ] || cmake_args+=(-DCMAKE_C_COMPILER="$mpicc")
  command -v ccache >/dev/null || say "optional, not found: ccache (rebuilds take longer)"
fi

# --- LIGGGHTS source: a given tarball, one fetched before, or Debian's source package -------------
mkdir -p "$download_dir"
if [ -n "$tarball" ]; then
  [ -f "$tarball" ] || { say "LIGGGHTS tarball $tarball (--tarball or LIGGGHTS_TARBALL): no such file"; exit 1; }
  tarball=$(cd "$(dirname "$tarball")" && pwd)/$(basename "$tarball")
else
  tarball=$(ls "$download_dir"/liggghts_3.8.0*.orig.tar.* 2>/dev/null | head -n 1 || true)
  # a build configured before keeps the tarball it was given (a second run needs no --tarball)
  if [ -z "$tarball" ] && [ -f "$build_dir/CMakeCache.txt" ]; then
    tarball=$(sed -n 's/^LIGGGHTS_TARBALL:FILEPATH=//p' "$build_dir/CMakeCache.txt")
    [ -f "$tarball" ] || tarball=""
  fi
fi
if [ -n "$tarball" ]; then
  say "LIGGGHTS source: $tarball (CMake checks its SHA256)"
elif command -v apt-get >/dev/null && ! no_apt && \
     { apt-get source --print-uris liggghts >/dev/null 2>&1 || can_root; }; then
  if ! apt-get source --print-uris liggghts >/dev/null 2>&1; then
    # No deb-src entries: derive them from the machine's own 'deb' entries (no mirror is hard-coded).
    say "enabling apt source entries derived from this machine's deb entries"
    src_list=/etc/apt/sources.list.d/liggghts-crush-src.list
    src_822=/etc/apt/sources.list.d/liggghts-crush-src.sources
    for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
      [ -f "$f" ] && [ "$f" != "$src_list" ] && grep -E '^\s*deb\s' "$f" | sed -E 's/^\s*deb\s/deb-src /'
    done | sort -u | as_root tee "$src_list" >/dev/null || true
    for f in /etc/apt/sources.list.d/*.sources; do
      [ -f "$f" ] && [ "$f" != "$src_822" ] && sed -E 's/^Types:.*/Types: deb-src/' "$f" && echo
    done | as_root tee "$src_822" >/dev/null || true
    as_root apt-get update -qq
  fi
  say "downloading Debian source package liggghts into $download_dir"
  # Only the upstream tarball is needed: a missing Debian diff is not an error here. CMake verifies
  # the tarball's SHA256.
  (cd "$download_dir" && apt-get source --download-only liggghts) || true
  tarball=$(ls "$download_dir"/liggghts_3.8.0*.orig.tar.* 2>/dev/null | head -n 1 || true)
  [ -n "$tarball" ] || { say "apt-get source liggghts did not deliver $tarball_name"; exit 1; }
else
  say "LIGGGHTS 3.8.0's source is needed: Debian's $tarball_name (SHA256 $tarball_sha256),"
  say "from any Debian mirror (pool/main/l/liggghts/) or 'apt-get source --download-only liggghts' on a"
  say "Debian machine; then: bash scripts/setup.sh --tarball /path/to/$tarball_name"
  exit 1
fi

[ $do_build -eq 1 ] || exit 0

# Configured when the build has no Makefile (a failed configuration leaves a cache, not a Makefile),
# and again when further options are given; the compilers of a configured build stay its own.
read -r -a extra <<< "${LIGGGHTS_CRUSH_CMAKE_ARGS:-}"
if [ ! -f "$build_dir/Makefile" ] || [ ${#extra[@]} -gt 0 ]; then
  say "configuring in $build_dir"
  [ ! -f "$build_dir/CMakeCache.txt" ] || cmake_args=(-DCMAKE_BUILD_TYPE=Release)
  cmake -S "$here" -B "$build_dir" "${cmake_args[@]}" -DLIGGGHTS_TARBALL="$tarball" ${extra[@]+"${extra[@]}"} || {
    say "configuring failed: see the CMake error above. Eigen 3 is found through CMake: 'module load eigen'"
    say "or -DEigen3_DIR=<eigen>/share/eigen3/cmake in LIGGGHTS_CRUSH_CMAKE_ARGS"
    exit 1
  }
fi
jobs=$(nproc 2>/dev/null || getconf _NPROCESSORS_ONLN 2>/dev/null || echo 2)
say "building with $jobs jobs (incremental after the first time)"
cmake --build "$build_dir" -j "$jobs"
say "built: $build_dir/liggghts"

[ $do_run -eq 1 ] || exit 0

# --- install: bin/liggghts-crush, a bin/liggghts link and the post-processing commands bin/crush-*,
# doc pages, examples and post/ (cmake/Install.cmake)
prefix=${LIGGGHTS_CRUSH_PREFIX:-$HOME/.local}
say "installing into $prefix (cmake --install $build_dir --prefix $prefix)"
cmake --install "$build_dir" --prefix "$prefix" > "$build_dir/install_manifest.log"
say "installed $prefix/bin/liggghts-crush, the link $prefix/bin/liggghts and the post-processing commands" \
    "$prefix/bin/crush-* (crush-summary, crush-plot, ...); examples in $prefix/share/liggghts-crush/examples," \
    "doc pages in $prefix/share/doc/liggghts-crush"
case ":$PATH:" in
  *":$prefix/bin:"*) ;;
  *) say "to type 'liggghts -in in.oedometer': export PATH=\"$prefix/bin:\$PATH\" (add it to ~/.bashrc)" ;;
esac

# --- the main job: the paper's oedometric test O-2 to 100 MPa, its summary and figures -------------
ranks=$(( jobs >= 2 ? 2 : 1 ))
say "running the main job: oedometric test O-2 to 100 MPa on $ranks rank(s), about 2 minutes" \
    "(scripts/fontainebleau_runs.sh, output in $build_dir/run/O2)"
RANKS=$ranks LIGGGHTS=$build_dir/liggghts PLOT="$prefix/bin/crush-plot" \
  bash "$here/scripts/fontainebleau_runs.sh" "$build_dir/run" O2 \
  || { say "the O-2 run failed: see $build_dir/run/O2/screen.txt"; exit 1; }
seconds=$(tail -n 1 "$build_dir/run/runtimes.csv" | cut -d, -f6)
"$prefix/bin/crush-summary" "$build_dir/run/O2" --figures "$build_dir/run/figures" --seconds "$seconds" --ranks "$ranks"
say "done: every deck, its variables and the paper's other tests are in doc/running.md"
