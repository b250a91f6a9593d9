#!/usr/bin/env bash
# The penetration study of studies/penetration/README.md: cone penetration tests (examples/penetration/in.cone)
# in chambers prepared by in.chamber, one per case, each timed, then post/penetration.py's plateau
# q_c, sleeve friction and gradings gathered in OUT_DIR/study.csv.
#   bash scripts/penetration_study.sh [OUT_DIR (default runs/penetration)] [cases...]
#   bash scripts/penetration_study.sh runs/evidence rate seeds more pile knob weak   # studies/penetration/README.md's evidence
# A case is NAME (one of the table below) or a spec density:N:crushing:v:width:ranks[:distribution
# [:sigma_v[:seed[:fragment_density[:depth]]]]] (the strength distribution of in.grains, default
# normal_clipped_originals; the vertical stress, Pa, default 1e5; the seed of the chamber's grains and
# of their strengths, default the decks' 15485863; the fragments' density, true or scaled, default
# true; the penetration in D_c, default 8, q_c averaged over its second half; then in.cone's and
# in.chamber's further variables as name=value,name=value, e.g. tip_shape=flat,stress_every=0.5 and
# mu_prep=0.1). Default: every named case (the earlier study's; the groups below are named
# explicitly). A case already in OUT_DIR/study.csv is skipped. Chambers are prepared (in.chamber: consolidated with crushing, the element tests' protocol)
# once per (density, N, width, depth, sigma_v, seed, fragment density) in OUT_DIR/chambers and copied.
# The case "summarise" runs post/penetration.py again in every case's folder that remains and writes
# its crushing about the tip's path into the case's row. The case "figures" draws studies/penetration/README.md's figures from the cases already run
# (OUT_DIR/figures: q_c, events and gradings of dense_region, dense_off, loose_region, loose_off; the
# events of dense_region_1MPa and of N80_region, N80_everywhere).
# Environment: LIGGGHTS (build/liggghts).
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
out=$(mkdir -p "${1:-$here/runs/penetration}" && cd "${1:-$here/runs/penetration}" && pwd)
shift || true
liggghts=${LIGGGHTS:-$here/build/liggghts}
source "$here/scripts/mpi_env.sh"
declare -A spec=(
  [dense_region]=dense:60:region:2:10:2     # the default scene: crushing near the tip
  [dense_off]=dense:60:0:2:10:2             # its uncrushable reference
  [loose_region]=loose:60:region:2:10:2
  [loose_off]=loose:60:0:2:10:2
  [N80_region]=dense:80:region:2:10:2       # coarser grains: D_c / d50 = 2.1
  [N80_off]=dense:80:0:2:10:2
  [N80_everywhere]=dense:80:1:2:10:2        # crushing everywhere, against the zone
  [N80_v1]=dense:80:region:1:10:2           # half the velocity
  [N80_v4]=dense:80:region:4:10:2           # twice the velocity
  [N80_w15]=dense:80:region:2:15:2          # a chamber 15 D_c wide
  [N80_off_np1]=dense:80:0:2:10:1           # one rank, for the speed-up
  [N80_region_np1]=dense:80:region:2:10:1
  [dense_region_normal]=dense:60:region:2:10:2:normal     # strengths without the zero draws
  [dense_region_1MPa]=dense:60:region:2:10:2:normal_clipped_originals:1e6
  [dense_off_1MPa]=dense:60:0:2:10:2:normal_clipped_originals:1e6
  [N80_region_s2]=dense:80:region:2:10:2:normal_clipped_originals:1e5:179424673   # other seeds: the scatter
  [N80_region_s3]=dense:80:region:2:10:2:normal_clipped_originals:1e5:373587883
  [N80_off_s2]=dense:80:0:2:10:2:normal_clipped_originals:1e5:179424673
  [N80_off_s3]=dense:80:0:2:10:2:normal_clipped_originals:1e5:373587883
  [dense_region_s2]=dense:60:region:2:10:2:normal_clipped_originals:1e5:179424673
  [dense_region_s3]=dense:60:region:2:10:2:normal_clipped_originals:1e5:373587883
  [dense_region_scaled]=dense:60:region:2:10:2:normal_clipped_originals:1e5:15485863:scaled   # the fragments' time step knob
  [dense_region_scaled_s2]=dense:60:region:2:10:2:normal_clipped_originals:1e5:179424673:scaled
  [dense_region_scaled_s3]=dense:60:region:2:10:2:normal_clipped_originals:1e5:373587883:scaled
)
order="dense_region dense_off loose_region loose_off N80_region N80_off N80_everywhere N80_v1 N80_v4 N80_w15"
order="$order N80_off_np1 N80_region_np1 dense_region_normal dense_region_1MPa dense_off_1MPa"
order="$order N80_region_s2 N80_region_s3 N80_off_s2 N80_off_s3"
order="$order dense_region_s2 dense_region_s3 dense_region_scaled dense_region_scaled_s2 dense_region_scaled_s3"
# The evidence of studies/penetration/README.md (the element tests' protocol: chambers consolidated with
# crushing): N = 80, 10 D_c wide, 4 D_c of penetration (q_c over 2 - 4 D_c), fragment_density
# scaled. Groups: rate (v = 2, 1, 0.5, 0.25, 0.125 m/s, dense, crushing in the
# zone, 100 kPa), seeds (at the chosen velocity V: dense and loose at 100 kPa, dense at 1 MPa, each
# with crushing in the zone and without; at 1 MPa crushing everywhere too), pile (the closed-ended
# pile at V in the dense chamber, whose prepared porosity 0.385 is the INPG tests' e0 = 0.62
# (0.626), with crushing in the zone and without, with stress dumps every 0.5 D_c), knob
# (dense_region_s* at V with the fragments' true density, chamber and test, and with neighbour
# lists by bin instead of by size class), weak (as seeds at 100 kPa, of
# grains ten times weaker: sigma_lim0 = 0.5 GPa, chamber and test; the cone, and the pile with
# crushing everywhere too). The rate study has six seeds, crushing everywhere or none at 1 MPa six
# too (group more: seeds 4 - 6), the other groups three. V (PENETRATION_V) is 0.5 m/s, the velocity
# the groups ran at; the six-seed rate study then chose 0.25 m/s for in.cone (studies/penetration/README.md).
V=${PENETRATION_V:-0.5}
seeds=(15485863 179424673 373587883 573259391 776531419 982451653)
declare -A group=()
for k in 1 2 3 4 5 6; do
  seed=${seeds[k-1]}
  for v in 2 1 0.5 0.25 0.125; do
    spec[rate_v${v}_s$k]=dense:80:region:$v:10:2:normal_clipped_originals:1e5:$seed:scaled:4
    group[rate]+=" rate_v${v}_s$k"
  done
  if [ "$k" -gt 3 ]; then   # seeds 4 - 6: the rate study, and crushing everywhere or none at 1 MPa
    for c in 0 1; do
      spec[dense_1MPa_${c}_s$k]=dense:80:$c:$V:10:2:normal_clipped_originals:1e6:$seed:scaled:4
      group[more]+=" dense_1MPa_${c}_s$k"
    done
    continue
  fi
  for d in dense loose; do
    for c in region 0; do
      spec[weak_${d}_${c}_s$k]=$d:80:$c:$V:10:2:normal_clipped_originals:1e5:$seed:scaled:4::sigma_lim0=5e8
      group[weak]+=" weak_${d}_${c}_s$k"
    done
  done
  for c in region 0 1; do
    spec[weak_pile_${c}_s$k]=dense:80:$c:$V:10:2:normal_clipped_originals:1e5:$seed:scaled:4:tip_shape=flat,stress_every=0.5:sigma_lim0=5e8
    group[weak]+=" weak_pile_${c}_s$k"
  done
  for d in dense loose; do
    for c in region 0; do
      spec[${d}_${c}_s$k]=$d:80:$c:$V:10:2:normal_clipped_originals:1e5:$seed:scaled:4
      group[seeds]+=" ${d}_${c}_s$k"
    done
  done
  for c in region 0 1; do
    spec[dense_1MPa_${c}_s$k]=dense:80:$c:$V:10:2:normal_clipped_originals:1e6:$seed:scaled:4
    group[seeds]+=" dense_1MPa_${c}_s$k"
  done
  spec[knob_true_s$k]=dense:80:region:$V:10:2:normal_clipped_originals:1e5:$seed:true:4
  spec[knob_bin_s$k]=dense:80:region:$V:10:2:normal_clipped_originals:1e5:$seed:scaled:4:neighbor_style=bin
  group[knob]+=" knob_true_s$k knob_bin_s$k"
  for c in region 0; do
    spec[pile_${c}_s$k]=dense:80:$c:$V:10:2:normal_clipped_originals:1e5:$seed:scaled:4:tip_shape=flat,stress_every=0.5
    group[pile]+=" pile_${c}_s$k"
  done
done
# The refined chambers (in.chamber refine 1, in.zones: grains of N within fine_radius D_c of the axis,
# N coarsen out to mid_radius, N coarsen^2 beyond; fix crush scale_atom), dense, crushing in the zone,
# 100 kPa, 4 D_c, at the velocity that keeps the rate study's inertial number at the tip (0.25 m/s at
# D_c / d50 = 2.125, raised in proportion to D_c / d50: in.cone's default). Groups: resolution
# (D_c / d50 = 5 and 10 at the cone, 10 D_c wide; 2.1 is the rate study's 0.25 m/s; at 10 the fine
# zone is 1.5 D_c wide, coarsen 3), width (D_c / d50 =
# 5, 20 and 30 D_c wide), fine (D_c / d50 = 5, fine zone of 1 D_c against 2), halving (D_c / d50 = 5 at
# half the velocity), below (D_c / d50 = 5, 5 D_c of sand below the final tip against 2.5), whole (the
# whole chamber, in.geometry's sector 360, against the quarter: the rate study's uniform chamber at
# D_c / d50 = 2.1 and 0.25 m/s, where the symmetry planes cut the fewest grains across the cone, with
# the quarter's rate_v0.25_s1 run again beside it), whole_refined (the same at D_c / d50 = 5, the
# default refined chamber).
v_at_I() { awk -v n="$1" -v f="${2:-1}" 'BEGIN {printf "%.4g", f * 0.25 * 0.0357 / (0.21e-3 * n) / 2.125}'; }
for k in 1 2 3; do
  seed=${seeds[k-1]}
  refined=normal_clipped_originals:1e5:$seed:scaled:4
  # D_c / d50 = 10: the fine zone 1.5 D_c wide and the grains three times coarser beyond it, the
  # chamber that a test of 30 minutes on 2 ranks holds (76,000 particles)
  spec[refined_N34_w10_s$k]=dense:34:region:$(v_at_I 34):10:2:$refined::refine=1
  spec[refined_N17_w10_s$k]=dense:17:region:$(v_at_I 17):10:2:$refined::refine=1,fine_radius=1.5,coarsen=3
  group[resolution]+=" refined_N34_w10_s$k refined_N17_w10_s$k"
  for w in 10 20 30; do
    spec[refined_N34_w${w}_s$k]=dense:34:region:$(v_at_I 34):$w:2:$refined::refine=1
    group[width]+=" refined_N34_w${w}_s$k"
  done
  spec[refined_N34_fine1_s$k]=dense:34:region:$(v_at_I 34):10:2:$refined::refine=1,fine_radius=1
  group[fine]+=" refined_N34_w10_s$k refined_N34_fine1_s$k"
  spec[refined_N34_half_s$k]=dense:34:region:$(v_at_I 34 0.5):10:2:$refined::refine=1
  group[halving]+=" refined_N34_w10_s$k refined_N34_half_s$k"
  spec[refined_N34_below5_s$k]=dense:34:region:$(v_at_I 34):10:2:$refined::refine=1,below=5
  group[below]+=" refined_N34_w10_s$k refined_N34_below5_s$k"
  spec[whole_N80_s$k]=dense:80:region:0.25:10:2:$refined::sector=360
  group[whole]+=" whole_N80_s$k"
  spec[refined_N34_whole_s$k]=dense:34:region:$(v_at_I 34):10:2:$refined::refine=1,sector=360
  group[whole_refined]+=" refined_N34_w10_s$k refined_N34_whole_s$k"
done
# What a geotechnical engineer would check, at D_c / d50 = 5 and 10 D_c wide (the refined chamber the
# resolution and width studies afford): groups stress (dense, the INPG e0 = 0.62, and loose chambers
# at 100, 200 and 400 kPa, crushing in the zone; dense at 100 kPa is the resolution group's),
# reference (the uncrushable chambers' tests, dense at 100 and 400 kPa), pristine (chambers drawn with
# distribution normal: no zero-strength grains, no consolidation crushing; crushing in the zone and
# none), pile_refined (the closed-ended pile, crushing in the zone), weak_refined (grains ten times
# weaker, sigma_lim0 = 0.5 GPa, chamber and test: crushing in the zone and none), pristine_stress
# (the pristine chambers, dense and loose at 100 and 400 kPa, crushing in the zone and, dense at 100
# and 400 kPa, none: the density effect and the stress exponent without the zero-strength grains),
# pristine_resolution, pristine_width and pristine_whole (the pristine chamber at D_c / d50 = 10, 20
# and 30 D_c wide, and whole, each beside the pristine chamber at 5, 10 D_c wide, quarter),
# pristine_wider (the width study's next steps, 40 and 50 D_c), pristine_base and pristine_deep (at
# 40 D_c: the rigid base 5 D_c below the final tip, and tests of 8 D_c, each beside the 40 D_c tests),
# pristine_stress_w40 (pristine_stress's chambers 40 D_c wide: loose at 100 kPa, dense and loose at
# 200 and 400, crushing in the zone, beside the 40 D_c tests), pristine_pile (the closed-ended pile in the
# pristine chamber at 5, crushing in the zone), pristine_w40_400kPa (the dense 400 kPa chambers 40 D_c
# wide: the cone's tests, the uncrushable reference and the pile, each paired by chamber),
# pristine_pile_w40 (the pile in the dense 100 kPa chambers 40 D_c wide), pristine_reference_w40
# (the uncrushable reference at 100 kPa in pristine_base's chambers 5 D_c below the tip),
# pristine_weak_w40 (grains ten times weaker, sigma_lim0 = 0.5 GPa, in the pristine chamber 40 D_c
# wide at 100 kPa: crushing in the zone and none, paired by chamber; pristine_weak_w40_everywhere:
# crushing everywhere in the same chambers). Seeds 1 - 3
# each;
# everywhere_refined, crushing everywhere in the dense chamber at 100 kPa (the coarse zones' events
# too), seed 1 (refined_N34_everywhere_s2 and _s3 run by name).
for k in 1 2 3; do
  seed=${seeds[k-1]}
  v=$(v_at_I 34)
  for p in 1 2 4; do
    for d in dense loose; do
      name=refined_N34_${d}_${p}00kPa_s$k
      [ "$d$p" = dense1 ] && { group[stress]+=" refined_N34_w10_s$k"; continue; }
      spec[$name]=$d:34:region:$v:10:2:normal_clipped_originals:${p}e5:$seed:scaled:4::refine=1
      group[stress]+=" $name"
    done
  done
  for p in 1 4; do
    spec[refined_N34_off_${p}00kPa_s$k]=dense:34:0:$v:10:2:normal_clipped_originals:${p}e5:$seed:scaled:4::refine=1
    group[reference]+=" refined_N34_off_${p}00kPa_s$k"
  done
  for c in region 0; do
    spec[refined_N34_pristine_${c}_s$k]=dense:34:$c:$v:10:2:normal:1e5:$seed:scaled:4::refine=1,distribution=normal
    group[pristine]+=" refined_N34_pristine_${c}_s$k"
    group[pristine_stress]+=" refined_N34_pristine_${c}_s$k"
    spec[refined_N34_weak_${c}_s$k]=dense:34:$c:$v:10:2:normal_clipped_originals:1e5:$seed:scaled:4::refine=1,sigma_lim0=5e8
    group[weak_refined]+=" refined_N34_weak_${c}_s$k"
  done
  for p in 1 4; do
    for d in dense loose; do
      [ "$d$p" = dense1 ] && continue
      spec[refined_N34_pristine_${d}_${p}00kPa_s$k]=$d:34:region:$v:10:2:normal:${p}e5:$seed:scaled:4::refine=1,distribution=normal
      group[pristine_stress]+=" refined_N34_pristine_${d}_${p}00kPa_s$k"
    done
  done
  spec[refined_N34_pristine_0_400kPa_s$k]=dense:34:0:$v:10:2:normal:4e5:$seed:scaled:4::refine=1,distribution=normal
  group[pristine_stress]+=" refined_N34_pristine_0_400kPa_s$k"
  # the pristine chamber's own studies, against refined_N34_pristine_region_s$k: D_c / d50 = 10 (the
  # resolution group's zones), 20 and 30 D_c wide, and whole
  pristine=normal:1e5:$seed:scaled:4::refine=1,distribution=normal
  spec[refined_N17_pristine_s$k]=dense:17:region:$(v_at_I 17):10:2:$pristine,fine_radius=1.5,coarsen=3
  group[pristine_resolution]+=" refined_N34_pristine_region_s$k refined_N17_pristine_s$k"
  group[pristine_width]+=" refined_N34_pristine_region_s$k"
  for w in 20 30 40 50; do
    spec[refined_N34_pristine_w${w}_s$k]=dense:34:region:$v:$w:2:$pristine
    if [ "$w" -le 30 ]; then group[pristine_width]+=" refined_N34_pristine_w${w}_s$k"
    else group[pristine_wider]+=" refined_N34_pristine_w${w}_s$k"; fi
  done
  # what the rise of q_c over the last D_c at 40 D_c is: the rigid base 5 D_c below the final tip
  # instead of 2.5, and a test of 8 D_c (its chamber 10.5 D_c high)
  spec[refined_N34_pristine_w40_below5_s$k]=dense:34:region:$v:40:2:$pristine,below=5
  group[pristine_base]+=" refined_N34_pristine_w40_s$k refined_N34_pristine_w40_below5_s$k"
  spec[refined_N34_pristine_w40_d8_s$k]=dense:34:region:$v:40:2:normal:1e5:$seed:scaled:8::refine=1,distribution=normal
  group[pristine_deep]+=" refined_N34_pristine_w40_s$k refined_N34_pristine_w40_d8_s$k"
  # the engineer's set at the width the width study ends on (40 D_c): loose at 100 kPa, dense and
  # loose at 200 and 400, crushing in the zone, beside the 40 D_c tests (dense, 100 kPa)
  for p in 1 2 4; do
    for d in dense loose; do
      [ "$d$p" = dense1 ] && { group[pristine_stress_w40]+=" refined_N34_pristine_w40_s$k"; continue; }
      spec[refined_N34_pristine_w40_${d}_${p}00kPa_s$k]=$d:34:region:$v:40:2:normal:${p}e5:$seed:scaled:4::refine=1,distribution=normal
      group[pristine_stress_w40]+=" refined_N34_pristine_w40_${d}_${p}00kPa_s$k"
    done
  done
  # at 400 kPa in the same chambers 40 D_c wide (paired by chamber with the cone's tests above): the
  # uncrushable reference and the closed-ended pile, crushing in the zone
  spec[refined_N34_pristine_w40_0_400kPa_s$k]=dense:34:0:$v:40:2:normal:4e5:$seed:scaled:4::refine=1,distribution=normal
  spec[refined_N34_pristine_w40_pile_400kPa_s$k]=dense:34:region:$v:40:2:normal:4e5:$seed:scaled:4:tip_shape=flat,stress_every=0.5:refine=1,distribution=normal
  group[pristine_w40_400kPa]+=" refined_N34_pristine_w40_dense_400kPa_s$k refined_N34_pristine_w40_0_400kPa_s$k refined_N34_pristine_w40_pile_400kPa_s$k"
  # the uncrushable reference at 100 kPa in the base study's chambers (5 D_c below the final tip),
  # paired by chamber with their cone's tests
  spec[refined_N34_pristine_w40_below5_0_s$k]=dense:34:0:$v:40:2:$pristine,below=5
  group[pristine_reference_w40]+=" refined_N34_pristine_w40_below5_s$k refined_N34_pristine_w40_below5_0_s$k"
  # the weak sand (sigma_lim0 = 0.5 GPa, chamber and test) in the pristine chamber 40 D_c wide at
  # 100 kPa: crushing in the zone and none, paired by chamber
  for c in region 0; do
    spec[refined_N34_pristine_w40_weak_${c}_s$k]=dense:34:$c:$v:40:2:$pristine,sigma_lim0=5e8
    group[pristine_weak_w40]+=" refined_N34_pristine_w40_weak_${c}_s$k"
  done
  # and crushing everywhere in the same chambers (what the zone leaves out)
  spec[refined_N34_pristine_w40_weak_1_s$k]=dense:34:1:$v:40:2:$pristine,sigma_lim0=5e8
  group[pristine_weak_w40_everywhere]+=" refined_N34_pristine_w40_weak_1_s$k"
  spec[refined_N34_pristine_w40_pile_s$k]=dense:34:region:$v:40:2:normal:1e5:$seed:scaled:4:tip_shape=flat,stress_every=0.5:refine=1,distribution=normal
  group[pristine_pile_w40]+=" refined_N34_pristine_w40_pile_s$k"
  spec[refined_N34_pristine_whole_s$k]=dense:34:region:$v:10:2:$pristine,sector=360
  group[pristine_whole]+=" refined_N34_pristine_region_s$k refined_N34_pristine_whole_s$k"
  spec[refined_N34_pristine_pile_s$k]=dense:34:region:$v:10:2:normal:1e5:$seed:scaled:4:tip_shape=flat,stress_every=0.5:refine=1,distribution=normal
  group[pristine_pile]+=" refined_N34_pristine_pile_s$k"
  spec[refined_N34_everywhere_s$k]=dense:34:1:$v:10:2:normal_clipped_originals:1e5:$seed:scaled:4::refine=1
  [ "$k" -gt 1 ] || group[everywhere_refined]+=" refined_N34_everywhere_s$k"
  spec[refined_N34_pile_s$k]=dense:34:region:$v:10:2:normal_clipped_originals:1e5:$seed:scaled:4:tip_shape=flat,stress_every=0.5:refine=1
  group[pile_refined]+=" refined_N34_pile_s$k"
done
group[whole]="rate_v0.25_s1${group[whole]}"
cases=""
for c in ${*:-$order}; do cases+=" ${group[$c]:-$c}"; done
# The last four columns, with the spec's, tell every case apart (post/penetration_stats.py groups by
# all of them): tip_shape, sigma_lim0, neighbor_style (a name=value of the case, or the decks'
# default) and extra (the case's other name=value settings, sorted, joined by ';'). The rows of
# studies/penetration/penetration_study.csv, run before these columns, had them added from the case names and the
# groups above: pile_* flat with stress_every=0.5, weak_* sigma_lim0 5e8, knob_bin_* bin, the rest
# in.cone's defaults (cone, 5e9, multi: the runs postdate multi as in.cone's default).
header0="case,density,N,D_c_over_d50,crushing,v,width,ranks,distribution,sigma_v,seed,grains,particles,events,events_loaded,steps,seconds,q_c_MPa,q_c_sd_MPa,f_s_kPa,I_G_near,I_G_far,fragment_density,depth,I_G_near0,chamber_events,v_measured,I_tip,I_chamber,ke_share,tip_shape,sigma_lim0,neighbor_style,extra"
# the crushing about the tip's path (post/penetration.py): a study.csv with header0 alone gains these
# columns, its rows empty there until the case "summarise" fills them
path_columns="events_path1,events_path2,events_far,I_G_path,I_G_path0,I_G_far0"
header="$header0,$path_columns"
[ -f "$out/study.csv" ] || echo "$header" > "$out/study.csv"
[ "$(head -n 1 "$out/study.csv")" != "$header0" ] || sed -i "1s/.*/$header/" "$out/study.csv"
[ "$(head -n 1 "$out/study.csv")" = "$header" ] || { echo "$out/study.csv: not this script's columns (an older study's, without those that tell the cases apart?): another OUT_DIR, or add them as studies/penetration/penetration_study.csv's were" >&2; exit 2; }
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
for name in $cases; do
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
  if grep -q "^$name," "$out/study.csv"; then echo "== $name: in $out/study.csv already, skipped"; continue; fi
  s=${spec[$name]:-$name}
  IFS=: read -r density N crushing v width ranks distribution sigma_v seed fragment_density depth cone_vars chamber_vars <<< "$s"
  distribution=${distribution:-normal_clipped_originals} sigma_v=${sigma_v:-1e5} seed=${seed:-15485863}
  fragment_density=${fragment_density:-true} depth=${depth:-8}
  plateau=$(awk -v d="$depth" 'BEGIN {print d / 2}')
  extra_cone=() extra_chamber=()
  for kv in ${cone_vars//,/ }; do extra_cone+=(-var "${kv%%=*}" "${kv#*=}"); done
  for kv in ${chamber_vars//,/ }; do extra_chamber+=(-var "${kv%%=*}" "${kv#*=}"); done
  [ -n "${ranks:-}" ] || { echo "unknown case $name (named: $order; or density:N:crushing:v:width:ranks)" >&2; exit 2; }
  chamber=$out/chambers/${density}_N${N}_w${width}_d${depth}_s${sigma_v}_seed${seed}_${fragment_density}${chamber_vars:+_${chamber_vars//[=,]/_}}
  if [ ! -f "$chamber/penetration/chamber_${density}_N${N}.restart" ]; then
    rm -rf "$chamber" && mkdir -p "$chamber/penetration" && cp -r "$here/examples/fontainebleau" "$chamber/"
    cp "$here"/examples/penetration/in.* "$here"/examples/penetration/*.py "$chamber/penetration/"
    echo "== chamber $density N = $N, width $width D_c, sigma_v $sigma_v Pa"
    start=$(date +%s%N)
    (cd "$chamber/penetration" && mpirun -np 2 "$liggghts" -in in.chamber -var density "$density" -var N "$N" \
       -var width "$width" -var depth "$depth" -var sigma_v "$sigma_v" -var seed "$seed" -var fragment_density "$fragment_density" "${extra_chamber[@]}" -log log.liggghts > screen.txt 2>&1) || { tail -n 5 "$chamber/penetration/screen.txt" >&2; exit 1; }
    awk -v a="$start" -v b="$(date +%s%N)" 'BEGIN {printf "   prepared in %.1f s\n", (b - a) / 1e9}'
    grep '^CHAMBER .* N = ' "$chamber/penetration/screen.txt"
  fi
  dir=$out/$name
  rm -rf "$dir" && mkdir -p "$dir/penetration" && cp -r "$here/examples/fontainebleau" "$dir/"
  cp "$here"/examples/penetration/in.* "$here"/examples/penetration/*.py "$chamber"/penetration/*chamber_* "$dir/penetration/"
  vars=(-var density "$density" -var N "$N" -var crushing "$crushing" -var v "$v" -var width "$width"
        -var distribution "$distribution" -var sigma_v "$sigma_v" -var seed "$seed" -var label "$name"
        -var fragment_density "$fragment_density" -var depth "$depth" "${extra_cone[@]}" "${extra_chamber[@]}")
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
  columns=$(case_columns "$cone_vars" "$chamber_vars")
  python3 - "$history" "$dir/penetration/penetration_${name}_summary.csv" "$dir/penetration/chamber_${density}_N${N}.in" \
    "$dir/penetration/screen.txt" <<EOF >> "$out/study.csv"
import csv, re, sys
rows = list(csv.DictReader(open(sys.argv[1])))
summary = next(csv.DictReader(open(sys.argv[2])))
grains = int(float(open(sys.argv[3]).read().split("grains0 equal")[1].split()[0]))
steps = int(float(re.search(r"CHECKED STEPS \\S+ OF (\\S+)", open(sys.argv[4]).read()).group(1)))
print("$name,$density,$N,%.3f,$crushing,$v,$width,$ranks,$distribution,$sigma_v,$seed,%d,%d,%d,%s,%d,$seconds,%s,%s,%s,%s,%s,$fragment_density,$depth,%s,%s,%s,%s,%s,%s,$columns,%s" % (
    0.0357 / (0.21e-3 * $N), grains, int(float(rows[-1]["particles"])), int(float(rows[-1]["events"])),
    summary["events_loaded"], steps,
    summary["q_c_MPa"], summary["q_c_sd_MPa"], summary["f_s_kPa"], summary["I_G_near"], summary["I_G_far"],
    summary["I_G_near0"], summary["chamber_events"], summary["v"], summary["I_tip"], summary["I_chamber"], summary["ke_share"],
    ",".join(summary[c] for c in "$path_columns".split(","))))
EOF
  tail -n 1 "$out/study.csv"
done
