# Shared by the penetration benchmarks (sourced after `here` is set): a temporary copy of
# examples/penetration and of the Fontainebleau decks it includes, removed on exit; the shell is
# left in its penetration folder. add_scene_vars appends the decks' further variables of SCENE
# (name=value,name=value; a value may hold spaces: grid=1 1 *) to the caller's array vars.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -r "$here/examples/fontainebleau" "$here/examples/penetration" "$work/"
cd "$work/penetration"
add_scene_vars() {
  local scene kv
  IFS=, read -ra scene <<< "${SCENE:-}"
  for kv in ${scene[@]+"${scene[@]}"}; do vars+=(-var "${kv%%=*}" "${kv#*=}"); done
}
