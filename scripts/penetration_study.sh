#!/usr/bin/env bash
# The penetration study of studies/penetration/README.md: cone penetration tests (examples/penetration/in.cone)
# in chambers prepared by in.chamber, one per case, each timed, then post/penetration.py's plateau
# q_c, sleeve friction and gradings gathered in OUT_DIR/study.csv.
#   bash scripts/penetration_study.sh [--dry-run] [OUT_DIR (default runs/penetration)] [cases...]
#   bash scripts/penetration_study.sh runs/refined pristine_wider pristine_base   # the default chamber's width and base
# The cases are the rows of studies/penetration/cases.csv (PENETRATION_CASES names another table),
# one row a case: its groups and settings in named columns (density, N, crushing, v, width, ranks,
# distribution, sigma_v, seed, fragment_density, depth; test_vars, in.cone's further variables, and
# chamber_vars, in.chamber's, which in.cone receives too, each name=value;name=value, e.g.
# tip_shape=flat;stress_every=0.5 and sigma_lim0=5e8), and a note. post/penetration_cases.py reads
# it and refuses a row with a bad value before anything runs. A case on the command line is a case,
# a group (its cases seed by seed; `post/penetration_cases.py --groups` lists them) or a spec
# density:N:crushing:v:width:ranks[:distribution[:sigma_v[:seed[:fragment_density[:depth[:test_vars
# [:chamber_vars]]]]]]] (the name=value lists joined by commas; defaults normal_clipped_originals,
# 1e5 Pa, the decks' seed 15485863, true, 8 D_c with q_c averaged over its second half). Default: the
# group before_protocol (the earlier study's cases). --dry-run prints each case's chamber and test
# commands and runs nothing. A case already in OUT_DIR/study.csv is skipped. Chambers are prepared
# (in.chamber: consolidated with crushing, the element tests' protocol) once per (density, N,
# width, depth, sigma_v, seed, fragment density, chamber_vars) in OUT_DIR/chambers and copied.
# The case "summarise" runs post/penetration.py again in every case's folder that remains and writes
# its crushing about the tip's path into the case's row. The case "figures" draws the earlier study's figures (studies/penetration/history.md) from the cases already run
# (OUT_DIR/figures: q_c, events and gradings of dense_region, dense_off, loose_region, loose_off; the
# events of dense_region_1MPa and of N80_region, N80_everywhere).
# Environment: LIGGGHTS (build/liggghts), PENETRATION_CASES (studies/penetration/cases.csv).
# Writes OUT_DIR/<case>/ (the test's outputs, screen.txt, log.liggghts, the figures of
# post/penetration.py), OUT_DIR/chambers/ and OUT_DIR/study.csv (one row a case: every setting that
# tells it from another case, the name=value ones too (tip_shape, sigma_lim0, neighbor_style, extra), grains,
# particles and events at the end, steps, wall-clock seconds of the test alone, q_c and f_s over
# the second half of the depth with their spread, I_G near the tip and far from it and near the tip
# before the test, the chamber's consolidation events, the velocity, inertial numbers at the tip and
# in the chamber, and the grains' kinetic energy over the penetrometer's work; post/penetration_stats.py
# gathers the seeds of each setting).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
dry=0
[ "${1:-}" != --dry-run ] || { dry=1; shift; }
out=${1:-$here/runs/penetration}
[ "$dry" = 1 ] || out=$(mkdir -p "$out" && cd "$out" && pwd)
shift || true
liggghts=${LIGGGHTS:-$here/build/liggghts}
source "$here/scripts/mpi_env.sh"
# each case to run as NAME<tab>SPEC, the table checked first (exit 2 and its message on a bad row)
plan=$(python3 "$here/post/penetration_cases.py" --cases "${PENETRATION_CASES:-$here/studies/penetration/cases.csv}" \
       -- "${@:-before_protocol}") || exit 2
mapfile -t plan <<< "$plan"
# The last four columns, with the spec's, tell every case apart (post/penetration_stats.py groups by
# all of them): tip_shape, sigma_lim0, neighbor_style (a name=value of the case, or the decks'
# default) and extra (the case's other name=value settings, sorted, joined by ';'). The rows of
# studies/penetration/penetration_study.csv, run before these columns, had them added from the case names and the
# groups of cases.csv: pile_* flat with stress_every=0.5, weak_* sigma_lim0 5e8, knob_bin_* bin, the rest
# in.cone's defaults (cone, 5e9, multi: the runs postdate multi as in.cone's default).
header0="case,density,N,D_c_over_d50,crushing,v,width,ranks,distribution,sigma_v,seed,grains,particles,events,events_loaded,steps,seconds,q_c_MPa,q_c_sd_MPa,f_s_kPa,I_G_near,I_G_far,fragment_density,depth,I_G_near0,chamber_events,v_measured,I_tip,I_chamber,ke_share,tip_shape,sigma_lim0,neighbor_style,extra"
# the crushing about the tip's path (post/penetration.py): a study.csv with header0 alone gains these
# columns, its rows empty there until the case "summarise" fills them
path_columns="events_path1,events_path2,events_far,I_G_path,I_G_path0,I_G_far0"
# sleeve_in: the sleeve's mean share in the sand over the read depths; f_s_kPa is over that length (a
# row without it, run before in.cone divided by the embedded length: f_s over the whole sleeve);
# q_c_slope_last2: q_c's slope over the last 2 D_c (MPa per D_c, post/penetration.py): levelled off
# where the seeds' interval holds zero (post/penetration_stats.py --levelling)
# sigma_v_axis: the vertical stress of the column about the axis (r < 2 D_c, Pa) before the test,
# from in.cone's first stress dump (post/chamber_profiles.py; empty without stress_every), the stress
# the cone meets, which post/cpt_interpretation.py normalises by
steady_columns="sleeve_in,q_c_slope_last2,sigma_v_axis"
header="$header0,$path_columns,$steady_columns"

# sigma_zz (Pa) of the column r < 2 D_c in a test's first stress dump (the chamber at rest before the
# push); nothing without the dump
axis_stress() {
  [ -f "$1" ] || return 0
  local first folder
  first=$(awk '/ITEM: TIMESTEP/ {getline; print; exit}' "$1")
  folder=$(dirname "$1")
  (cd "$folder" && /usr/bin/python3 "$here/post/chamber_profiles.py" "$1" --snapshot "$first" --dr 2 --rmax 0.0714 \
     --out axis_stress > /dev/null) || return 0
  /usr/bin/python3 -c 'import csv, sys; print(next(csv.DictReader(open(sys.argv[1])))["sigma_zz"])' "$folder/axis_stress.csv"
}
if [ "$dry" = 0 ]; then
  [ -f "$out/study.csv" ] || echo "$header" > "$out/study.csv"
  # a study.csv of this script's columns less the last ones (written before they were added): its
  # header gains them, its rows stay empty there
  old=$(head -n 1 "$out/study.csv")
  [ "${old#"$header0"}" = "$old" ] || [ "${header#"$old",}" = "$header" ] || sed -i "1s/.*/$header/" "$out/study.csv"
  [ "$(head -n 1 "$out/study.csv")" = "$header" ] || { echo "$out/study.csv: not this script's columns (an older study's, without those that tell the cases apart?): another OUT_DIR, or add them as studies/penetration/penetration_study.csv's were" >&2; exit 2; }
fi
# a deck's default for a variable: its 'variable NAME index VALUE' line
default() { awk -v n="$2" '$1 == "variable" && $2 == n && $3 == "index" {print $4; exit}' "$1"; }
# the case's defining settings of its name=value fields: tip_shape, sigma_lim0, neighbor_style, extra
case_columns() {
  local tip_shape sigma_lim0 neighbor_style extra=() kv
  tip_shape=$(default "$here/examples/penetration/in.cone" tip_shape)
  sigma_lim0=$(default "$here/examples/fontainebleau/in.grains" sigma_lim0)
  neighbor_style=$(default "$here/examples/penetration/in.cone" neighbor_style)
  for kv in ${1//,/ } ${2//,/ }; do
    case ${kv%%=*} in
      tip_shape) tip_shape=${kv#*=} ;;
      sigma_lim0) sigma_lim0=${kv#*=} ;;
      neighbor_style) neighbor_style=${kv#*=} ;;
      *) extra+=("$kv") ;;
    esac
  done
  echo "$tip_shape,$sigma_lim0,$neighbor_style,$(printf '%s\n' "${extra[@]}" | LC_ALL=C sort | paste -sd ';')"
}
# OUT_DIR/figures/<N>/: the named cases' files together, drawn by post/penetration.py
draw() {
  local n=$1 tag=$2; shift 2
  mkdir -p "$out/figures/$tag"
  for c in "$@"; do cp "$out/$c"/penetration/{penetration_,particles_}"${c}"_N"$n".* "$out/$c"/penetration/events_pen_*.csv "$out/$c"/penetration/*chamber_*.{csv,liggghts} "$out/figures/$tag/" 2>/dev/null || true; done
  (cd "$out/figures/$tag" && "$here/post/penetration.py" --N "$n" --Dc 0.0357 --out "$tag" "$@")
}
for line in "${plan[@]}"; do
  name=${line%%$'\t'*} s=${line#*$'\t'}
  if [ "$dry" = 1 ] && [ -z "$s" ]; then echo "== $name: the runner's step, not run (dry run)"; continue; fi
  if [ "$name" = summarise ]; then
    # post/penetration.py again in every case's folder that remains, its crushing about the tip's
    # path written into the case's row (for rows of a study.csv older than those columns)
    python3 - "$out" "$here/post/penetration.py" "$path_columns" <<'EOF'
import csv, os, subprocess, sys
out, script, columns = sys.argv[1], sys.argv[2], sys.argv[3].split(",")
path = os.path.join(out, "study.csv")
with open(path) as f:
    reader = csv.DictReader(f)
    fields, rows = reader.fieldnames, list(reader)
for row in rows:
    folder = os.path.join(out, row["case"], "penetration")
    if not os.path.exists(os.path.join(folder, "particles_%s_N%s.liggghts" % (row["case"], row["N"]))):
        continue
    chamber = "events_chamber_%s_N%s.csv" % (row["density"], row["N"])
    subprocess.run([script, "--N", row["N"], "--Dc", "0.0357", "--plateau", "%g" % (float(row["depth"]) / 2),
                    "--out", row["case"], row["case"]] + (["--chamber", chamber] if os.path.exists(os.path.join(folder, chamber)) else []),
                   cwd=folder, check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(folder, "penetration_%s_summary.csv" % row["case"])) as f:
        summary = next(csv.DictReader(f))
    row.update((c, summary[c]) for c in columns)
    print("== %s: %s" % (row["case"], " ".join("%s %s" % (c, row[c]) for c in columns)))
with open(path + ".new", "w", newline="") as f:
    writer = csv.DictWriter(f, fieldnames=fields, lineterminator="\n")
    writer.writeheader()
    writer.writerows(rows)
os.replace(path + ".new", path)
EOF
    continue
  fi
  if [ "$name" = figures ]; then
    draw 60 N60 dense_region dense_off loose_region loose_off
    draw 60 N60_1MPa dense_region_1MPa dense_off_1MPa
    draw 80 N80 N80_region N80_everywhere N80_off
    continue
  fi
  if [ -f "$out/study.csv" ] && grep -q "^$name," "$out/study.csv"; then echo "== $name: in $out/study.csv already, skipped"; continue; fi
  # the spec's thirteen fields, every one filled by post/penetration_cases.py
  IFS=: read -r density N crushing v width ranks distribution sigma_v seed fragment_density depth cone_vars chamber_vars <<< "$s"
  plateau=$(awk -v d="$depth" 'BEGIN {print d / 2}')
  extra_cone=() extra_chamber=()
  for kv in ${cone_vars//,/ }; do extra_cone+=(-var "${kv%%=*}" "${kv#*=}"); done
  for kv in ${chamber_vars//,/ }; do extra_chamber+=(-var "${kv%%=*}" "${kv#*=}"); done
  chamber=$out/chambers/${density}_N${N}_w${width}_d${depth}_s${sigma_v}_seed${seed}_${fragment_density}${chamber_vars:+_${chamber_vars//[=,]/_}}
  chamber_args=(-var density "$density" -var N "$N" -var width "$width" -var depth "$depth" -var sigma_v "$sigma_v"
                -var seed "$seed" -var fragment_density "$fragment_density" "${extra_chamber[@]}")
  vars=(-var density "$density" -var N "$N" -var crushing "$crushing" -var v "$v" -var width "$width"
        -var distribution "$distribution" -var sigma_v "$sigma_v" -var seed "$seed" -var label "$name"
        -var fragment_density "$fragment_density" -var depth "$depth" "${extra_cone[@]}" "${extra_chamber[@]}")
  if [ "$dry" = 1 ]; then
    echo "== $name: chamber $chamber: mpirun -np 2 liggghts -in in.chamber ${chamber_args[*]}"
    echo "== $name: mpirun -np $ranks liggghts -in in.cone ${vars[*]}"
    continue
  fi
  if [ ! -f "$chamber/penetration/chamber_${density}_N${N}.restart" ]; then
    rm -rf "$chamber" && mkdir -p "$chamber/penetration" && cp -r "$here/examples/fontainebleau" "$chamber/"
    cp "$here"/examples/penetration/in.* "$here"/examples/penetration/*.py "$chamber/penetration/"
    echo "== chamber $density N = $N, width $width D_c, sigma_v $sigma_v Pa"
    start=$(date +%s%N)
    (cd "$chamber/penetration" && mpirun -np 2 "$liggghts" -in in.chamber "${chamber_args[@]}" -log log.liggghts > screen.txt 2>&1) \
      || { tail -n 5 "$chamber/penetration/screen.txt" >&2; exit 1; }
    awk -v a="$start" -v b="$(date +%s%N)" 'BEGIN {printf "   prepared in %.1f s\n", (b - a) / 1e9}'
    grep '^CHAMBER .* N = ' "$chamber/penetration/screen.txt"
  fi
  dir=$out/$name
  rm -rf "$dir" && mkdir -p "$dir/penetration" && cp -r "$here/examples/fontainebleau" "$dir/"
  cp "$here"/examples/penetration/in.* "$here"/examples/penetration/*.py "$chamber"/penetration/*chamber_* "$dir/penetration/"
  echo "== $name: mpirun -np $ranks liggghts -in in.cone ${vars[*]}"
  start=$(date +%s%N)
  (cd "$dir/penetration" && mpirun -np "$ranks" "$liggghts" -in in.cone "${vars[@]}" -log log.liggghts > screen.txt 2>&1) \
    || { tail -n 5 "$dir/penetration/screen.txt" >&2; echo "$name failed: $dir/penetration/screen.txt" >&2; exit 1; }
  seconds=$(awk -v a="$start" -v b="$(date +%s%N)" 'BEGIN {printf "%.1f", (b - a) / 1e9}')
  grep -E '^(PENETRATED|CHECKED)' "$dir/penetration/screen.txt"
  consolidation=()
  [ ! -f "$dir/penetration/events_chamber_${density}_N${N}.csv" ] || consolidation=(--chamber "events_chamber_${density}_N${N}.csv")
  summary=$(cd "$dir/penetration" && "$here/post/penetration.py" --N "$N" --Dc 0.0357 --plateau "$plateau" --out "$name" \
             "${consolidation[@]}" "$name")
  echo "$summary"
  history=$dir/penetration/penetration_${name}_N${N}.csv
  axis_stress=$(axis_stress "$dir/penetration/stress_${name}_N${N}.liggghts")
  columns=$(case_columns "$cone_vars" "$chamber_vars")
  python3 - "$history" "$dir/penetration/penetration_${name}_summary.csv" "$dir/penetration/chamber_${density}_N${N}.in" \
    "$dir/penetration/screen.txt" <<EOF >> "$out/study.csv"
import csv, re, sys
rows = list(csv.DictReader(open(sys.argv[1])))
summary = next(csv.DictReader(open(sys.argv[2])))
grains = int(float(open(sys.argv[3]).read().split("grains0 equal")[1].split()[0]))
steps = int(float(re.search(r"CHECKED STEPS \\S+ OF (\\S+)", open(sys.argv[4]).read()).group(1)))
print("$name,$density,$N,%.3f,$crushing,$v,$width,$ranks,$distribution,$sigma_v,$seed,%d,%d,%d,%s,%d,$seconds,%s,%s,%s,%s,%s,$fragment_density,$depth,%s,%s,%s,%s,%s,%s,$columns,%s,%s" % (
    0.0357 / (0.21e-3 * $N), grains, int(float(rows[-1]["particles"])), int(float(rows[-1]["events"])),
    summary["events_loaded"], steps,
    summary["q_c_MPa"], summary["q_c_sd_MPa"], summary["f_s_kPa"], summary["I_G_near"], summary["I_G_far"],
    summary["I_G_near0"], summary["chamber_events"], summary["v"], summary["I_tip"], summary["I_chamber"], summary["ke_share"],
    ",".join(summary[c] for c in "$path_columns".split(",")),
    ",".join(summary.get(c, "") for c in "$steady_columns".split(",") if c != "sigma_v_axis") + ",$axis_stress"))
EOF
  tail -n 1 "$out/study.csv"
done
