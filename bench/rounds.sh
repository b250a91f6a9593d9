# Shared by the benchmarks (sourced): the arithmetic of runs alternated in rounds.

# smaller A B: the smaller of two numbers.
smaller() { awk -v a="$1" -v b="$2" 'BEGIN{print (b<a)?b:a}'; }

# ratio A B: A / B.
ratio() { awk -v a="$1" -v b="$2" 'BEGIN{print a/b}'; }

# summary NAME RATIO...: the median of in-round ratios and their range, on one line.
summary() {
  local name=$1; shift
  printf '%s\n' "$@" | sort -g | awk -v name="$name" '{r[NR] = $1} END {
    m = (NR % 2) ? r[(NR + 1) / 2] : (r[NR / 2] + r[NR / 2 + 1]) / 2
    printf "%-62s median %.3f   (rounds: %.3f - %.3f)\n", name, m, r[1], r[NR] }'
}
