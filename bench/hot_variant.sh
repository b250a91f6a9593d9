# Shared by the benchmarks (sourced): the hot units (cmake/hot_path_units.txt: the contact models and
# the granular pair loop, all instantiated in lammps.cpp; the integrator; neighbour lists;
# communication) recompiled with other flags and linked with the build's other objects.
# Needs: here (the bench folder), build (the build folder).

# hot_variant OUT FLAGS: the hot units compiled with FLAGS (in place of the build's own for them),
# linked as OUT/liggghts.
hot_variant() {
  local out=$1 flags=$2 cmd unit
  cmd=$(cat "$build/CMakeFiles/liggghts.dir/link.txt")
  mkdir -p "$out"
  while read -r unit; do
    local object target defines includes
    object=$(cd "$build" && ls CMakeFiles/*/liggghts-3.8.0/src/$unit.cpp.o | head -n 1)
    target=${object%%/liggghts-3.8.0/*}
    defines=$(sed -n 's/^CXX_DEFINES = //p' "$build/$target/flags.make")
    includes=$(sed -n 's/^CXX_INCLUDES = //p' "$build/$target/flags.make")
    (cd "$build" && eval c++ $defines $includes $flags -std=c++14 -w \
       -c liggghts-3.8.0/src/$unit.cpp -o "$out/$unit.o")
    cmd=${cmd/$object/$out\/$unit.o}
  done < <(grep -E '^[a-z_]+$' "$here/../cmake/hot_path_units.txt")
  (cd "$build" && eval "${cmd/-o liggghts/-o $out/liggghts}")
}
