#!/usr/bin/env bash
# What accuracy costs, resolved by seeds (studies/accuracy/README.md): the knobs
# of bench/accuracy_vs_cost.sh at N = 2 with five seeds (each its own sample and strength draw): the
# base N2 (L_R 0.1, dmin 0.05 mm, dt fraction 0.5, every step, fourteen fragments of true density),
# L_R 0.05 and 0.2, dmin 0.025 mm, dt fraction 0.8, the step every 10 steps, breakage checked every
# 10 steps and adaptively, the tetrahedral layout, scaled fragment density; and the reference, N = 1
# at the base's knobs, with three. One round a seed: every setting once in turn, so that the cost
# ratios are taken within a round. Then bench/accuracy_seeds.py: each error against the reference
# seeds' mean, each knob's change against the base paired by seed, resolved or not by its 95% t
# interval (post/seeds.py), and the cost as the median of the rounds' ratios; copy its
# accuracy_seeds_runs.csv into studies/accuracy/ and post/tables.py writes the page's tables.
#   bash bench/accuracy_seeds.sh [OUT_DIR (default runs/accuracy_seeds)]
# Runs already done are kept (OUT_DIR/<name>_s<seed>/done). About 1.5 hours on a 2-core machine.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out=${1:-$here/runs/accuracy_seeds}
knobs="N2 N2_LR0.05 N2_LR0.2 N2_dmin0.025 N2_dt0.8 N2_dtevery10 N2_every10 N2_adaptive N2_tetrahedral N2_fragscaled"
# the decks' seed and four more primes (insert/pack takes a prime above 10,000, none of the grading's
# template seeds: 32452843, 49979687, ... are theirs)
SEEDS="15485863 179424673 275604541" NO_ANALYSIS=1 bash "$here/bench/accuracy_vs_cost.sh" "$out" $knobs N1
SEEDS="373587883 1299709" NO_ANALYSIS=1 bash "$here/bench/accuracy_vs_cost.sh" "$out" $knobs
/usr/bin/python3 "$here/bench/accuracy_seeds.py" --reference N1 "$out"
