# Shared by the benchmarks (sourced): runs bench/in.dense_assembly (10,976 dense spheres) in a scratch
# folder and reports the LIGGGHTS loop time. Needs: here (the bench folder), steps.
liggghts=${LIGGGHTS:-$here/../build/liggghts}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$here"/in.dense_assembly "$here"/in.none "$here"/in.crush_idle "$here"/in.crush_all "$work"/

# dense_args MODEL TMODEL EXTRA STEPS [VAR VALUE ...]: sets the array dense_argv to the command line
# of one run after the binary (with further -var pairs).
dense_args() {
  dense_argv=(-in in.dense_assembly -var model "$1" -var tmodel "$2" -var extra "$3" -var steps "$4")
  shift 4
  while [ $# -ge 2 ]; do dense_argv+=(-var "$1" "$2"); shift 2; done
}

# dense_run MODEL TMODEL EXTRA STEPS [VAR VALUE ...]: one run; its screen output is in $work/screen.txt.
dense_run() {
  dense_args "$@"
  (cd "$work" && "$liggghts" "${dense_argv[@]}" -log none -screen screen.txt >/dev/null 2>&1 \
     || { tail -5 screen.txt; exit 1; })
}

# loop_time MODEL TMODEL EXTRA [VAR VALUE ...]: seconds of the run loop of $steps steps.
loop_time() {
  dense_run "$1" "$2" "$3" "$steps" "${@:4}"
  awk '/^Loop time of/ {print $4}' "$work/screen.txt"
}

# smaller, ratio and summary: the arithmetic of alternated rounds
source "$here/rounds.sh"
