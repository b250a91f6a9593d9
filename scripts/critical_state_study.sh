#!/usr/bin/env bash
# The critical-state study of studies/critical_state/README.md: drained triaxial tests with crushing
# (examples/fontainebleau/in.triaxial -var crushing 1), each an isotropic compression to p'_0 followed
# by shearing to 30% axial strain, over pressures, densities and grain rotation; then
# post/critical_state.py's critical states, fitted line and plane, tables and figures.
#   bash scripts/critical_state_study.sh [OUT_DIR (default runs/critical_state)] [cases...]
# A case is variant:sample:p0[:path[:seed]]: variant rotation0 (grains do not rotate, the decks'
# default), rolling (free rotation against LIGGGHTS' rolling resistance epsd2, mu_r 0.7,
# studies/fontainebleau/README.md), normal (as rotation0, with the strength draw 'normal' of fix crush: no grain of
# zero strength, studies/fontainebleau/README.md), weak (as normal, sigma_lim0 = 1 GPa: the reading whose O-2 yield
# stress nears the decks', studies/fontainebleau/README.md "The strength reading side by side") or none (as rotation0,
# no grain breaks: the uncrushable control), each
# with an optional suffix _pre<P> (the sample pre-crushed: compressed isotropically to P MPa, unloaded
# to p0 and sheared there, in.triaxial's precrush; e.g. normal_pre50), sample dense or loose (in.prepare with friction 0.5), p0 the cell pressure in MPa,
# path sigma3 (constant cell pressure, default) or p (constant p'), seed (the sample's and the
# strengths', default the decks' 15485863). Default: the cases of studies/critical_state/README.md: rotation0 at
# p0 = 0.1 0.5 2 5 10 20 50 MPa, normal at the same, rolling at 2 10 50 MPa, each dense and loose,
# path sigma3;
# constant p' (path p) for rotation0 at 10 MPa. The case "fit" only refits and redraws from the
# cases already run; "seeds", "precrushed" and "lab" are the groups named below. Environment MAX_DILATANCY:
# post/critical_state.py's --max-dilatancy (tests still changing volume left out of the fits).
# Environment: JOBS (tests run at once, one rank each; default 2), LIGGGHTS (build/liggghts),
# AXIAL_MAX (0.3).
# Writes OUT_DIR/<variant>/<sample>_<p0>MPa[_<path>][_s<seed>]/ (the deck's outputs, screen.txt,
# log.liggghts, seconds.txt and cpu_seconds.txt: wall-clock and CPU time), OUT_DIR/runtimes.csv and, from post/critical_state.py,
# OUT_DIR/critical_states.csv, OUT_DIR/fit.md and OUT_DIR/figures/*.png.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out=$(mkdir -p "${1:-$here/runs/critical_state}" && cd "${1:-$here/runs/critical_state}" && pwd)
shift || true
liggghts=${LIGGGHTS:-$here/build/liggghts}
jobs=${JOBS:-2}
axial_max=${AXIAL_MAX:-0.3}
source "$here/scripts/mpi_env.sh"

pascals() { awk -v p="$1" 'BEGIN {printf "%.6g", p * 1e6}'; }   # MPa -> Pa, as in.triaxial takes it

run_case() {
  local spec=$1 variant sample p0 path seed wall cpu
  IFS=: read -r variant sample p0 path seed <<< "$spec"
  path=${path:-sigma3}
  local crushing=1 pre=""
  case $variant in
    *_pre*) pre=${variant##*_pre}; variant=${variant%_pre*} ;;
  esac
  [ "$variant" = none ] && crushing=0
  local vars=(-var crushing $crushing -var cell "$(pascals "$p0")" -var axial_max "$axial_max"
              -var path "$path" -var sample "$sample" -var checkpoint_every 0)
  case $sample in
    dense) ;;
    loose) vars+=(-var mu_prep 0.5) ;;
    *) echo "unknown sample $sample (dense, loose)" >&2; return 2 ;;
  esac
  case $variant in
    rotation0) ;;
    rolling) vars+=(-var rotation 1 -var rolling epsd2 -var mu_r 0.7) ;;
    normal) vars+=(-var distribution normal) ;;
    weak) vars+=(-var distribution normal -var sigma_lim0 1e9) ;;
    none) ;;
    *) echo "unknown variant $variant (rotation0, rolling, normal, weak, none; each with _pre<P>)" >&2; return 2 ;;
  esac
  if [ -n "$pre" ]; then
    awk -v p="$pre" -v c="$p0" 'BEGIN {exit !(p + 0 > c + 0)}' \
      || { echo "variant _pre$pre: the pre-crushing stress (MPa) must exceed p0 = $p0" >&2; return 2; }
    vars+=(-var precrush "$(pascals "$pre")")
    variant=${variant}_pre$pre
  fi
  local dir=$out/$variant/${sample}_${p0}MPa
  [ "$path" = sigma3 ] || dir=${dir}_$path
  if [ -n "${seed:-}" ]; then vars+=(-var seed "$seed"); dir=${dir}_s$seed; fi
  rm -rf "$dir" && mkdir -p "$dir" && cp "$here"/examples/fontainebleau/in.* "$dir"/
  echo "== $spec: liggghts -in in.triaxial ${vars[*]}"
  # wall-clock and CPU seconds (the CPU time does not grow when JOBS exceeds the free cores)
  local TIMEFORMAT="%R %U"
  { time (cd "$dir" && "$liggghts" -in in.triaxial "${vars[@]}" -log log.liggghts > screen.txt 2>&1) ; } 2> "$dir/time.txt" \
    || { tail -n 5 "$dir/screen.txt" >&2; echo "$spec failed: $dir/screen.txt" >&2; return 1; }
  read -r wall cpu < "$dir/time.txt"
  echo "$wall" > "$dir/seconds.txt"
  echo "$cpu" > "$dir/cpu_seconds.txt"
  echo "$spec,$wall,$cpu" >> "$out/runtimes.csv"
  echo "   $spec: $wall s ($cpu s CPU)"
}

# the named groups of studies/critical_state/README.md: seeds (normal at 2, 10 and 50 MPa with a second seed),
# precrushed (weak and weak_pre50 dense at 2 and 10 MPa, three seeds each; the uncrushable control
# none dense at 0.5 - 50 MPa and loose at 10 - 50 MPa, three seeds at 10 and 50 MPa), lab (the
# decks' reading, rotation0, loose at a cell pressure of 0.2 MPa, its critical state near p' = 0.4 MPa:
# inside the 50 - 400 kPa where the laboratory measured NE34's phi_cs; five seeds; run it with
# AXIAL_MAX=0.4 to come nearer the critical state. The samples start at 100 kPa, the lowest cell.)
seeds=(15485863 179424673 373587883)
more_seeds=(275604541 1299709)
expand() {
  local sample p0 seed
  case $1 in
    seeds) for sample in dense loose; do for p0 in 2 10 50; do echo "normal:$sample:$p0::${seeds[1]}"; done; done ;;
    precrushed)
      for p0 in 2 10; do for seed in "${seeds[@]}"; do echo "weak:dense:$p0:sigma3:$seed weak_pre50:dense:$p0:sigma3:$seed"; done; done
      for p0 in 0.5 2 5 10 20 50; do echo "none:dense:$p0"; done
      for p0 in 10 20 50; do echo "none:loose:$p0"; done
      for p0 in 10 50; do for seed in "${seeds[@]:1}"; do echo "none:dense:$p0:sigma3:$seed"; done; done ;;
    lab) for seed in "${seeds[@]}" "${more_seeds[@]}"; do echo "rotation0:loose:0.2:sigma3:$seed"; done ;;
    *) echo "$1" ;;
  esac
}
if [ "${1:-}" = --one ]; then run_case "$2"; exit; fi
cases=""
for c in "$@"; do cases+=" $(expand "$c")"; done
cases=${cases# }
if [ -z "$cases" ]; then
  for sample in dense loose; do
    for p0 in 0.1 0.5 2 5 10 20 50; do cases+=" rotation0:$sample:$p0 normal:$sample:$p0"; done
    for p0 in 2 10 50; do cases+=" rolling:$sample:$p0"; done
    cases+=" rotation0:$sample:10:p"
  done
fi
if [ "$cases" != fit ]; then
  [ -f "$out/runtimes.csv" ] || echo "case,seconds,cpu_seconds" > "$out/runtimes.csv"
  printf '%s\n' $cases | xargs -P "$jobs" -I{} bash "${BASH_SOURCE[0]}" "$out" --one {}
fi
/usr/bin/python3 "$here/post/critical_state.py" --out "$out" ${MAX_DILATANCY:+--max-dilatancy "$MAX_DILATANCY"} "$out"
