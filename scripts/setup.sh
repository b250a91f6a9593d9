#!/usr/bin/env bash
# One-time setup on Debian 12 / Ubuntu: install the Debian packages liggghts-crush needs, fetch the
# LIGGGHTS 3.8.0 source package (enabling apt source entries derived from this machine's own apt
# configuration when needed), then configure and build. Idempotent: every step checks before acting.
#
#   bash scripts/setup.sh            # packages + source + build, install (to ~/.local), then the main
#                                    # job: O-2 to 100 MPa, its summary and figures
#   bash scripts/setup.sh --no-run   # packages + source + build
#   bash scripts/setup.sh --no-build # packages + source only
# Environment: LIGGGHTS_CRUSH_BUILD_DIR (default ./build), LIGGGHTS_CRUSH_DOWNLOAD_DIR (./.downloads),
# LIGGGHTS_CRUSH_PREFIX (install prefix, default ~/.local).
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${LIGGGHTS_CRUSH_BUILD_DIR:-$here/build}
download_dir=${LIGGGHTS_CRUSH_DOWNLOAD_DIR:-$here/.downloads}
do_build=1
do_run=1
case "${1:-}" in
  --no-build) do_build=0; do_run=0 ;;
  --no-run) do_run=0 ;;
  "") ;;
  *) echo "usage: bash scripts/setup.sh [--no-run|--no-build]" >&2; exit 2 ;;
esac

say() { printf '[setup] %s\n' "$*"; }

packages=(g++ make cmake ccache patch libopenmpi-dev openmpi-bin libeigen3-dev libgtest-dev
          xz-utils dpkg-dev python3 python3-numpy python3-matplotlib gcovr
          python3-scipy  # post/calibrate.py: fits and goodness-of-fit statistics
          time   # GNU time: peak memory in bench/memory.sh and bench/accuracy_vs_cost.sh
          procps # pkill/pgrep: the checkpoint tests kill a whole MPI run
          libvtk9-dev python3-vtk9)  # VTK dumps for ParaView (dump custom/vtk, patch 0005); the test reads them

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

as_root() { if [ "$(id -u)" -eq 0 ]; then "$@"; elif command -v sudo >/dev/null; then sudo "$@"; else return 1; fi; }
can_root() { [ "$(id -u)" -eq 0 ] || { command -v sudo >/dev/null && sudo -n true 2>/dev/null; }; }

if [ ${#missing[@]} -gt 0 ]; then
  if ! can_root; then
    say "missing Debian packages: ${missing[*]}"
    say "install them as root (apt-get install ${missing[*]}) and run this script again"
    exit 1
  fi
  say "installing Debian packages: ${missing[*]}"
  as_root apt-get update -qq
  DEBIAN_FRONTEND=noninteractive as_root apt-get install -y -qq --no-install-recommends "${missing[@]}"
else
  say "all Debian packages present"
fi

# --- LIGGGHTS source: the upstream tarball inside Debian's source package 'liggghts' ---------------
mkdir -p "$download_dir"
tarball=$(ls "$download_dir"/liggghts_3.8.0*.orig.tar.* 2>/dev/null | head -n 1 || true)
if [ -n "$tarball" ]; then
  say "LIGGGHTS source present: $tarball"
else
  if ! apt-get source --print-uris liggghts >/dev/null 2>&1; then
    # No deb-src entries: derive them from the machine's own 'deb' entries (no mirror is hard-coded).
    can_root || { say "apt-get source needs deb-src entries; as root, enable them for the entries in /etc/apt/sources.list*"; exit 1; }
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
  [ -n "$tarball" ] || { say "apt-get source liggghts did not deliver liggghts_3.8.0+repack1.orig.tar.xz"; exit 1; }
fi

[ $do_build -eq 1 ] || exit 0

if [ ! -f "$build_dir/CMakeCache.txt" ]; then
  say "configuring in $build_dir"
  cmake -S "$here" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DLIGGGHTS_TARBALL="$tarball"
fi
say "building with $(nproc) jobs (incremental after the first time)"
cmake --build "$build_dir" -j "$(nproc)"
say "built: $build_dir/liggghts"

[ $do_run -eq 1 ] || exit 0

# --- install: bin/liggghts-crush and a bin/liggghts link, doc pages and examples (cmake/Install.cmake)
prefix=${LIGGGHTS_CRUSH_PREFIX:-$HOME/.local}
say "installing into $prefix (cmake --install $build_dir --prefix $prefix)"
cmake --install "$build_dir" --prefix "$prefix" > "$build_dir/install_manifest.log"
say "installed $prefix/bin/liggghts-crush and the link $prefix/bin/liggghts; examples in" \
    "$prefix/share/liggghts-crush/examples, doc pages in $prefix/share/doc/liggghts-crush"
case ":$PATH:" in
  *":$prefix/bin:"*) ;;
  *) say "to type 'liggghts -in in.oedometer': export PATH=\"$prefix/bin:\$PATH\" (add it to ~/.bashrc)" ;;
esac

# --- the main job: the paper's oedometric test O-2 to 100 MPa, its summary and figures -------------
ranks=$(( $(nproc) >= 2 ? 2 : 1 ))
say "running the main job: oedometric test O-2 to 100 MPa on $ranks rank(s), about 2 minutes" \
    "(scripts/fontainebleau_runs.sh, output in $build_dir/run/O2)"
RANKS=$ranks LIGGGHTS=$build_dir/liggghts bash "$here/scripts/fontainebleau_runs.sh" "$build_dir/run" O2 \
  || { say "the O-2 run failed: see $build_dir/run/O2/screen.txt"; exit 1; }
seconds=$(tail -n 1 "$build_dir/run/runtimes.csv" | cut -d, -f6)
/usr/bin/python3 "$here/post/summary.py" "$build_dir/run/O2" --figures "$build_dir/run/figures" \
  --seconds "$seconds" --ranks "$ranks"
say "done: every deck, its variables and the paper's other tests are in doc/running.md"
