#!/usr/bin/env python3
"""Granular neighbour lists in style multi (patches/0012, neighbor_classes/): the same pairs as style
bin, found by size class, on crushed samples.

- burst: the burst lattice (periodic on every face, or shrink-wrapped) after its breakable half broke,
  grains and fragments, on 1-4 ranks: bin and multi hold the same number of pairs ('Total # of neighbors'),
  log the same events, keep the burst's books, and end with the same forces and torques up to the
  order of summation;
- cone: a cone pushed into the chamber (the penetrometer is a mesh: fix neighlist/mesh reads the main
  bins): the same q_c, row by row, down to 1 D_c.

  python3 test_neighbor_multi.py LIGGGHTS WORKDIR CASE [ARG ...]"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liggghts_run import check, edited_deck, each_rank_count, read_dump, run_deck, variants  # noqa: E402
from liggghts_run import main as test_main  # noqa: E402
from test_burst import BURST, check_run, write_data  # noqa: E402
from test_penetration import push, prepare_chamber, read_rows  # noqa: E402

# largest difference of a force or torque component between bin and multi, relative to the largest
# component: round-off in the order of summation, grown over the run's 100 steps after the burst
# (2e-13 to 1e-9 measured on 1-4 ranks); a pair lost or a history not carried over costs 1e-3 or more
FORCE_TOLERANCE = 1e-7


def run_summary(output, label):
    """The value of LIGGGHTS' last 'LABEL = value' line after a run ('Total # of neighbors', 'Ave
    neighs/atom', 'Neighbor list builds': the last neighbour list's)."""
    found = re.findall(r"^%s = (\S+)" % re.escape(label), output, re.M)
    check(found, "the run printed '%s'" % label)
    return float(found[-1])


def neighbors_per_atom(out_bin, out_multi):
    return "Ave neighs/atom: %.2f (bin) %.2f (multi)" % tuple(run_summary(o, "Ave neighs/atom") for o in (out_bin, out_multi))


def burst_run(liggghts, work, style, ranks, boundary="p p p"):
    """The burst deck in work, in a periodic box or (boundary 'm m m') a shrink-wrapped one."""
    deck = edited_deck(os.path.join(BURST, "in.burst_neighbor"), work + "_deck",
                       [("boundary        p p p", "boundary        " + boundary)], includes=("in.burst_setup",))
    os.makedirs(work, exist_ok=True)
    types = write_data(os.path.join(work, "burst.data"))
    out = run_deck(liggghts, deck, work,
                   {"case": "half", "log": "events.csv", "out": "final.dump", "neighbor_style": style},
                   ranks=ranks, keep=True)
    check_run(work, "half", ranks, types)
    return out, read_dump(os.path.join(work, "final.dump"))[-1][2]


def largest_difference(rows_a, rows_b, keys):
    scale = max(abs(r[k]) for r in rows_a for k in keys)
    worst = max(abs(a[k] - b[k]) for a, b in zip(rows_a, rows_b) for k in keys)
    return worst / scale


@variants(*[(ranks, boundary) for boundary in ("periodic", "shrink") for ranks in (1, 2, 3, 4)], timeout=600)
def case_burst(liggghts, work, ranks, boundary):
    """bin and multi on the crushed burst lattice, periodic on every face or in a shrink-wrapped box
    (the lattice's faces then free): same pairs, events and books, forces and torques within
    round-off."""
    ranks = int(ranks)
    box = "p p p" if boundary == "periodic" else "m m m"
    out_bin, bin_rows = burst_run(liggghts, os.path.join(work, "bin"), "bin", ranks, box)
    out_multi, multi_rows = burst_run(liggghts, os.path.join(work, "multi"), "multi", ranks, box)
    pairs = run_summary(out_bin, "Total # of neighbors")
    check(run_summary(out_multi, "Total # of neighbors") == pairs > 0, "the same %d pairs in the last lists" % pairs)
    builds = [run_summary(o, "Neighbor list builds") for o in (out_bin, out_multi)]
    check(builds[0] == builds[1] >= 20, "%d neighbour builds in the run, each carrying the contact history" % builds[1])
    radii = sorted(set(round(r["radius"], 12) for r in bin_rows))
    check(radii[-1] / radii[0] > 4, "radii from %.3g to %.3g m" % (radii[0], radii[-1]))
    check([r["id"] for r in bin_rows] == [r["id"] for r in multi_rows], "the same %d particles" % len(bin_rows))
    force = largest_difference(bin_rows, multi_rows, ("fx", "fy", "fz"))
    torque = largest_difference(bin_rows, multi_rows, ("tqx", "tqy", "tqz"))
    check(force <= FORCE_TOLERANCE and torque <= FORCE_TOLERANCE,
          "forces agree to %.2g and torques to %.2g of the largest (tolerance %.0g)" % (force, torque, FORCE_TOLERANCE))
    print(neighbors_per_atom(out_bin, out_multi))


@variants(*each_rank_count(1, 2), timeout=600)
def case_cone(liggghts, work, ranks):
    """A cone pushed into the chamber (graded grains, no crushing: a crushing burst would make the two
    runs' round-off diverge within a few hundred steps), with bin and with multi lists. The
    penetrometer is a mesh, whose neighbour lists read the main bins (kept at style bin's size):
    q_c, every 200 steps down to 1 D_c, the same to 1e-5 (round-off, growing about 100 times per
    0.2 D_c: 1e-9 on one rank, 2e-7 on two)."""
    ranks = int(ranks)
    # the chamber as prepared (chamber_crushing 0): the consolidation's fragments make the round-off
    # grow faster than the comparison allows (1e-4 by 1 D_c on two ranks)
    folder = prepare_chamber(liggghts, work, ranks, chamber_crushing=0)
    runs = {}
    for style in ("bin", "multi"):
        out = push(liggghts, folder, ranks, crushing=0, vtk=0, label=style, neighbor_style=style, output_every=200)
        runs[style] = (out, read_rows(os.path.join(folder, "penetration_%s_N80.csv" % style)))
    (out_bin, rows_bin), (out_multi, rows_multi) = runs["bin"], runs["multi"]
    pairs = [(a["q_c"], b["q_c"]) for a, b in zip(rows_bin, rows_multi) if a["depth_Dc"] <= 1.0]
    touching = [p for p in pairs if p[0] > 0]
    scale = max(p[0] for p in pairs)
    worst = max(abs(a - b) for a, b in pairs) / scale
    check(len(touching) >= 10 and worst < 1e-5,
          "q_c over %d rows down to 1 D_c (%d with the cone in the sand, up to %.3g MPa) agrees to %.2g"
          % (len(pairs), len(touching), scale / 1e6, worst))
    print(neighbors_per_atom(out_bin, out_multi))

if __name__ == "__main__":
    test_main(globals(), sys.argv[1:])
