#!/usr/bin/env bash
# What the decks' physics costs against the engines a user already has, on the dense assembly of
# bench/in.dense_assembly (10,976 spheres, one core), every run a separate process, the runs
# alternated in rounds and the ratios taken inside each round (the machine's speed drifts by up to
# 1.6x within minutes: only ratios measured side by side mean anything). Prints, per comparison, the
# median of the in-round ratios and their lowest and highest.
#   bash bench/stack_cost.sh [rounds=5] [steps=1500] [lammps_steps=600]
# 1. Debian's liggghts (hertz + tangential history, nve/sphere, nothing else) against this build on
#    the same bare deck, and against this build with the decks' stack (bench/in.decks_stack:
#    hertz/scaled + mindlin/scaled, fix crush under which nothing breaks, fix dt/stiffness every step,
#    fix damp/local 0.05). Goals: both at most 1.0.
# 2. Debian's LAMMPS, gran/hertz/history with the same material (bench/in.dense_assembly.lammps),
#    against this build's bare hertz/scaled + mindlin/scaled, with its dedicated pair loop (the
#    default) and with 'dedicated_loop off' (LIGGGHTS' generic loop). Goal: at most 1.1 (aim 1.0).
# Debian's liggghts and lammps packages are installed when missing (as root, or via sudo).
# LIGGGHTS=<binary> times another build of this project.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
rounds=${1:-5}
steps=${2:-1500}
lammps_steps=${3:-600}
source "$here/dense_assembly.sh"
cp "$here/in.decks_stack" "$here/in.dense_assembly.lammps" "$work/"

need=()
[ -x /usr/bin/liggghts ] || need+=(liggghts)
[ -x /usr/bin/lmp ] || need+=(lammps)
if [ ${#need[@]} -gt 0 ]; then
  echo "stack_cost: installing Debian's ${need[*]} (the engines compared against)"
  if [ "$(id -u)" -eq 0 ]; then sudo=(); elif command -v sudo >/dev/null; then sudo=(sudo); else
    echo "stack_cost: needs root to install ${need[*]}: apt-get install ${need[*]}" >&2; exit 1; fi
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null
fi

# debian_time MODEL TMODEL EXTRA: loop time of Debian's liggghts on the same deck (called in $(...):
# the binary changes in that subshell only).
debian_time() { liggghts=/usr/bin/liggghts; loop_time "$@"; }
# lammps_time: loop time of Debian's LAMMPS on the same assembly.
lammps_time() {
  (cd "$work" && /usr/bin/lmp -in in.dense_assembly.lammps -var steps "$lammps_steps" -log none \
     -screen lammps.txt >/dev/null 2>&1 || { tail -5 lammps.txt; exit 1; })
  awk '/^Loop time of/ {print $4}' "$work/lammps.txt"
}

echo "10976 spheres, one core; $rounds rounds; liggghts $steps steps, LAMMPS $lammps_steps steps"
echo "binary: $liggghts"
bare=(); stack=(); vs_lammps=(); generic_vs_lammps=(); dedicated_vs_generic=()
for r in $(seq "$rounds"); do
  d=$(debian_time hertz history in.none)
  o=$(loop_time hertz history in.none)
  s=$(loop_time hertz/scaled mindlin/scaled in.decks_stack)
  bare+=("$(ratio "$o" "$d")")
  stack+=("$(ratio "$s" "$d")")
  echo "round $r: Debian's liggghts $d s, this build bare $o s, this build with the decks' stack $s s"
done
steps=$lammps_steps
for r in $(seq "$rounds"); do
  l=$(lammps_time)
  o=$(loop_time hertz/scaled mindlin/scaled in.none)
  g=$(loop_time hertz/scaled "mindlin/scaled dedicated_loop off" in.none)
  vs_lammps+=("$(ratio "$o" "$l")")
  generic_vs_lammps+=("$(ratio "$g" "$l")")
  dedicated_vs_generic+=("$(ratio "$o" "$g")")
  echo "round $r: Debian's LAMMPS gran/hertz/history $l s, this build hertz/scaled + mindlin/scaled $o s" \
       "(LIGGGHTS' generic loop: $g s)"
done
echo
summary "this build, bare deck / Debian's liggghts (goal <= 1.0)" "${bare[@]}"
summary "this build, the decks' stack / Debian's liggghts (goal <= 1.0)" "${stack[@]}"
summary "this build, hertz/scaled + mindlin/scaled / Debian's LAMMPS (goal <= 1.1)" "${vs_lammps[@]}"
summary "  the same with 'dedicated_loop off' (LIGGGHTS' generic loop) / Debian's LAMMPS" "${generic_vs_lammps[@]}"
summary "  dedicated loop / generic loop" "${dedicated_vs_generic[@]}"
