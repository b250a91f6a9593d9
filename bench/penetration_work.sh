# Shared by the penetration benchmarks (sourced after `here` is set): a temporary copy of
# examples/penetration and of the Fontainebleau decks it includes, removed on exit; the shell is
# left in its penetration folder.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -r "$here/examples/fontainebleau" "$here/examples/penetration" "$work/"
cd "$work/penetration"
