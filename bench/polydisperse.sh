#!/usr/bin/env bash
# Neighbour lists by size class against style bin, per particle-step, on crushed samples, in
# alternated rounds (bin, then multi, in each round; the median of the in-round ratios multi / bin
# and their range):
#   1. the O-1 oedometer's particles at 100 MPa (about 40,000, radii 8:1) between plane walls
#      (bench/in.polydisperse, servo walls at the state's stresses, no crushing, STEPS steps on one rank): from the dump of an earlier
#      `scripts/fontainebleau_runs.sh DIR O1` (O1_DIR=DIR/O1), else the script runs O-1 first
#      (about 7 minutes on 2 ranks);
#   2. the cone penetration with crushing everywhere (examples/penetration, in.cone -var crushing 1)
#      in a chamber of CONE_N (default 40: about 5,000 grains) 6 D_c wide, prepared once, on 2 ranks:
#      every stretch's loop time over its particle-steps.
# Each line also gives the neighbour build's share of the loop (LIGGGHTS' 'Neigh time (%)', case 1)
# and the lists' 'Ave neighs/atom' (pairs per particle).
#   bash bench/polydisperse.sh [ROUNDS (3)]
# Environment: O1_DIR, STEPS (2000), CONE_N (40), CASES ("o1 cone": either alone skips the other).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(dirname "$here")
rounds=${1:-3}
steps=${STEPS:-2000}
cone_n=${CONE_N:-40}
cases=${CASES:-o1 cone}
liggghts=${LIGGGHTS:-$root/build/liggghts}
source "$root/scripts/mpi_env.sh"
source "$here/rounds.sh"   # ratio, summary
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# --- 1. the O-1 state -------------------------------------------------------------------------
if [[ " $cases " == *" o1 "* ]]; then
  o1=${O1_DIR:-}
  if [ -z "$o1" ]; then
    echo "running O-1 for its 100 MPa state (scripts/fontainebleau_runs.sh $work/runs O1) ..."
    RANKS=2 bash "$root/scripts/fontainebleau_runs.sh" "$work/runs" O1 > "$work/o1.txt" 2>&1 \
      || { tail -5 "$work/o1.txt"; exit 1; }
    o1=$work/runs/O1
  fi
  dump=$o1/dump_O1_100MPa.liggghts
  [ -f "$dump" ] || { echo "no $dump: run 'scripts/fontainebleau_runs.sh DIR O1' and give O1_DIR=DIR/O1" >&2; exit 1; }
  mkdir -p "$work/o1state" && cp "$here/in.polydisperse" "$work/o1state/"
  # the data file, the walls' first positions at the particles' extents and a time step of 0.2 Rayleigh steps of the
  # smallest particle (G = 3 GPa, nu = 0.3, rho = 2650 kg/m^3)
  walls=$(/usr/bin/python3 - "$dump" "$work/o1state/polydisperse.data" <<'EOF'
import math, sys
lines = open(sys.argv[1]).read().splitlines()
start = next(k for k, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
header = lines[start].split()[2:]
rows = [dict(zip(header, map(float, l.split()))) for l in lines[start + 1:]]
lo = [min(r[k] - r["radius"] for r in rows) for k in "xyz"]
hi = [max(r[k] + r["radius"] for r in rows) for k in "xyz"]
pad = [0.05 * (h - l) for l, h in zip(lo, hi)]
out = ["crushed sample: %d particles" % len(rows), "", "%d atoms" % len(rows), "2 atom types", ""]
out += ["%.17g %.17g %slo %shi" % (l - p, h + p, k, k) for l, h, p, k in zip(lo, hi, pad, "xyz")]
out += ["", "Atoms", ""]
out += ["%d 1 %.17g 2650 %.17g %.17g %.17g" % (r["id"], 2 * r["radius"], r["x"], r["y"], r["z"]) for r in rows]
open(sys.argv[2], "w").write("\n".join(out) + "\n")
radii = [r["radius"] for r in rows]
dt = 0.2 * math.pi * min(radii) * math.sqrt(2650 / 3e9) / (0.1631 * 0.3 + 0.8766)
print(" ".join("-var %s %.17g" % (n, v) for n, v in zip(("xlo", "ylo", "zlo"), lo)),
      " ".join("-var %s %.17g" % (n, v) for n, v in zip(("xhi", "yhi", "zhi"), hi)),
      "-var dt %.6g" % dt, "# %d %.4g" % (len(rows), max(radii) / min(radii)))
EOF
  )
  read -r -a wall_args <<< "${walls%%#*}"
  info=${walls##*# }
  echo "O-1 at 100 MPa: ${info% *} particles, largest / smallest radius ${info#* }"
fi

# o1_run STYLE: seconds per particle-step, neighbour share (%), neighbours per particle, builds
o1_run() {
  (cd "$work/o1state" && "$liggghts" -in in.polydisperse -var neighbor_style "$1" -var steps "$steps" \
     -var skin 0.00002 "${wall_args[@]}" -log none -screen screen_$1.txt > /dev/null 2>&1) \
    || { tail -5 "$work/o1state/screen_$1.txt"; exit 1; }
  awk '/^Loop time of/ {t = $4; w = $9 * $12} /^Neigh time/ {n = $NF; gsub(/[()]/, "", n)} /^Ave neighs\/atom/ {a = $NF}
       /^Neighbor list builds/ {b = $NF} END {printf "%.6g %.1f %.2f %d\n", t / w, n, a, b}' "$work/o1state/screen_$1.txt"
}

# --- 2. the penetration chamber -------------------------------------------------------------------
cone=$work/cone
chamber=(-var N "$cone_n" -var width 6 -var depth 3 -var below 2)
if [[ " $cases " == *" cone "* ]]; then
  mkdir -p "$cone"
  cp -r "$root/examples/penetration" "$root/examples/fontainebleau" "$cone/"
  echo "preparing the chamber (N = $cone_n) ..."
  (cd "$cone/penetration" && mpirun -np 2 "$liggghts" -in in.chamber "${chamber[@]}" -log log.chamber \
     > chamber.txt 2>&1) || { tail -5 "$cone/penetration/chamber.txt"; exit 1; }
fi

# cone_run STYLE: seconds per particle-step over the test's stretches, neighbours per particle
cone_run() {
  (cd "$cone/penetration" && mpirun -np 2 "$liggghts" -in in.cone "${chamber[@]}" -var crushing 1 -var v 2 -var vtk 0 \
     -var label "$1" -var neighbor_style "$1" -log log.$1 > cone_$1.txt 2>&1) \
    || { tail -5 "$cone/penetration/cone_$1.txt"; exit 1; }
  awk '/^Loop time of/ {t += $4; w += $9 * $12} /^Ave neighs\/atom/ {a = $NF}
       END {printf "%.6g %.2f\n", t / w, a}' "$cone/penetration/log.$1"
}


o1_ratios=() cone_ratios=()
for round in $(seq "$rounds"); do
  line="round $round:"
  if [[ " $cases " == *" o1 "* ]]; then
    read -r o1_bin o1_bin_neigh o1_bin_pairs o1_builds <<< "$(o1_run bin)"
    read -r o1_multi o1_multi_neigh o1_multi_pairs o1_builds <<< "$(o1_run multi)"
    o1_ratios+=("$(ratio "$o1_multi" "$o1_bin")")
    line+=" O-1 bin $o1_bin s (neigh $o1_bin_neigh%), multi $o1_multi s (neigh $o1_multi_neigh%);"
  fi
  if [[ " $cases " == *" cone "* ]]; then
    read -r cone_bin cone_bin_pairs <<< "$(cone_run bin)"
    read -r cone_multi cone_multi_pairs <<< "$(cone_run multi)"
    cone_ratios+=("$(ratio "$cone_multi" "$cone_bin")")
    line+=" cone bin $cone_bin s, multi $cone_multi s;"
  fi
  echo "$line per particle-step"
done
if [ ${#o1_ratios[@]} -gt 0 ]; then
  echo "pairs per particle, O-1: $o1_bin_pairs (bin) $o1_multi_pairs (multi); $o1_builds neighbour builds in $steps steps"
  summary "O-1 at 100 MPa, multi / bin per particle-step" "${o1_ratios[@]}"
fi
if [ ${#cone_ratios[@]} -gt 0 ]; then
  echo "pairs per particle, cone: $cone_bin_pairs (bin) $cone_multi_pairs (multi)"
  summary "cone penetration, crushing everywhere, multi / bin" "${cone_ratios[@]}"
fi
