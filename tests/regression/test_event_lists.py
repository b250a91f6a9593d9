#!/usr/bin/env python3
"""Event steps without a rebuild (fix crush 'event_lists insert'): a burst of grains away from every
processor and periodic boundary is replaced in place, its fragments added to the neighbour lists,
on 1 - 4 ranks (tests/regression/burst/in.event_lists).

  python3 test_event_lists.py LIGGGHTS WORKDIR CASE RANKS     CASE: interior, mixed, inherit or mesh
  python3 test_event_lists.py --list

Each case runs the deck twice, with 'event_lists insert check_lists yes' and with 'event_lists
rebuild', and asserts: the same events and fragment tags, particles = initial + 13 x events, the books
to 1e-12, every tag unique; with insert, every touching pair in the neighbour list at every step
until the next build (check_lists stops the run otherwise); and the same particles at the end, within
1e-9 m, as the run that rebuilt. Case inherit (in.event_lists_inherit) checks that the fragments made
in place hold their mother's fix property/atom values.
"""
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liggghts_run import check, each_rank_count, read_dump, read_thermo, run_deck, variants  # noqa: E402
from liggghts_run import FRAGMENTS, inheritance_errors, read_events  # noqa: E402
from liggghts_run import main as test_main  # noqa: E402

BURST = os.path.join(os.path.dirname(os.path.abspath(__file__)), "burst")
CELLS = (24, 8, 8)       # grains along x, y, z
SPACING = 0.21e-3        # m, lattice spacing; the box is CELLS x SPACING
DIAMETER = 0.2121e-3     # m: 1% overlap with each neighbour
# Slabs along x on 1 - 4 ranks cut at these cells (the periodic faces at 0 and 24); the ghost cutoff is
# a diameter plus the skin (0.232 mm), so a grain two cells from every plane is sent in no swap.
PLANES_X = (0, 6, 8, 12, 16, 18, 24)
PLANES_YZ = (0, 8)


def interior(i, j, k):
    return (min(abs(i - p) for p in PLANES_X) >= 2 and min(abs(j - p) for p in PLANES_YZ) >= 2
            and min(abs(k - p) for p in PLANES_YZ) >= 2)


def breaks(case, i, j, k):
    """Type 2: the interior grains; in case 'mixed' also the grains on the periodic face x = 0 (sent on
    every rank count); in case 'mesh' (z not periodic, one processor along it) the grains of the
    lowest three layers two cells from every plane along x and y, those resting on the floor among them."""
    if case == "mesh":
        return interior(i, j, 2) and k <= 2
    return interior(i, j, k) or (case == "mixed" and i == 0)


def write_data(path, case):
    """The lattice, tagged x fastest, and its breakable grains' tags. In case 'mesh' it stands one cell
    up in a box one cell taller, and floor.stl beside the data file is the floor under its bottom layer."""
    nx, ny, nz = CELLS
    lift = SPACING if case == "mesh" else 0.0
    lines = ["LIGGGHTS data file: event_lists lattice", "", "%d atoms" % (nx * ny * nz), "2 atom types", ""]
    for d, n in zip("xyz", CELLS):
        lines.append("0 %.17g %slo %shi" % ((n + 1 if lift and d == "z" else n) * SPACING, d, d))
    lines += ["", "Atoms", ""]
    tag, breakable = 0, []
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                tag += 1
                breakable_here = breaks(case, i, j, k)
                if breakable_here:
                    breakable.append(tag)
                lines.append("%d %d %.17g 2650 %.17g %.17g %.17g" % (tag, 2 if breakable_here else 1, DIAMETER,
                                                                      i * SPACING, j * SPACING, lift + k * SPACING))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    if lift:
        write_floor(os.path.join(os.path.dirname(path), "floor.stl"), lift - 0.99 * DIAMETER / 2)
    return breakable


def write_floor(path, z):
    """A plane at height z under the lattice, two triangles a cell (small beside the sub-domains)."""
    nx, ny, _ = CELLS
    facets = []
    for i in range(nx):
        for j in range(ny):
            a, b, c, d = [((i + di) * SPACING, (j + dj) * SPACING, z) for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1))]
            for tri in ((a, b, c), (a, c, d)):
                facets.append("facet normal 0 0 1\n outer loop\n%s endloop\nendfacet" % "".join(
                    "  vertex %.17g %.17g %.17g\n" % v for v in tri))
    with open(path, "w") as f:
        f.write("solid floor\n%s\nendsolid floor\n" % "\n".join(facets))


def run(liggghts, work, case, ranks, lists, deck=None):
    deck = deck or ("in.event_lists_mesh" if case == "mesh" else "in.event_lists")
    os.makedirs(work, exist_ok=True)
    breakable = write_data(os.path.join(work, "event_lists.data"), case)
    extra = "event_lists insert check_lists yes" if lists == "insert" else "event_lists rebuild"
    run_deck(liggghts, os.path.join(BURST, deck), work,
             {"log": "events.csv", "out": "final.dump", "crush_extra": extra}, ranks=ranks, keep=True)
    return breakable


def check_run(work, breakable, label):
    n0 = CELLS[0] * CELLS[1] * CELLS[2]
    v0 = n0 * math.pi / 6 * DIAMETER ** 3
    thermo = [row for row in read_thermo(os.path.join(work, "log.liggghts")) if "crush[1]" in row]
    bad = [row["Step"] for row in thermo if row["Atoms"] != n0 + 13 * row["crush[1]"]
           or abs(row["gsd"] - v0) > 1e-12 * v0 or row["KinEng"] != row["KinEng"]]
    check(not bad, "%s: at every thermo row (%d) particles = %d + 13 x events, books to 1e-12, no NaN"
          % (label, len(thermo), n0))
    log = read_events(os.path.join(work, "events.csv"))
    check([int(e["tag"]) for e in log] == breakable and all(e["step"] == "1" for e in log),
          "%s: the burst step breaks exactly the %d breakable grains, in tag order" % (label, len(breakable)))
    expected = [[str(n0 + 1 + FRAGMENTS * k + f) for f in range(FRAGMENTS)] for k in range(len(breakable))]
    check([[e["fragment_%d" % (f + 1)] for f in range(FRAGMENTS)] for e in log] == expected,
          "%s: fragment tags %d + 14 k + (0..13)" % (label, n0 + 1))
    final = read_dump(os.path.join(work, "final.dump"))[-1][2]
    tags = [int(r["id"]) for r in final]
    check(len(tags) == len(set(tags)) == thermo[-1]["Atoms"], "%s: %d particles, every tag unique" % (label, len(tags)))
    builds = sum(int(m) for m in re.findall(r"Neighbor list builds = (\d+)",
                                            open(os.path.join(work, "log.liggghts")).read()))
    return thermo[-1]["crush[10"], builds, final  # (LIGGGHTS cuts the header at 8 characters)


def compare(liggghts, work, case, ranks):
    ranks = int(ranks)
    runs = {}
    for lists in ("insert", "rebuild"):
        folder = os.path.join(work, lists)
        breakable = run(liggghts, folder, case, ranks, lists)
        runs[lists] = check_run(folder, breakable, "%s, %s, %d rank(s)" % (case, lists, ranks))
    (inserted, builds_insert, final_insert), (rebuilt, builds_rebuild, final_rebuild) = runs["insert"], runs["rebuild"]
    if case in ("interior", "mesh"):
        check(inserted == 1 and rebuilt == 0, "the burst of %d interior grains was replaced without a rebuild "
              "(event steps inserted: %d with insert, %d with rebuild)" % (len(breakable), inserted, rebuilt))
        check(builds_insert < builds_rebuild, "neighbour builds: %d with insert, %d with rebuild"
              % (builds_insert, builds_rebuild))
    else:
        check(inserted == 0 and rebuilt == 0, "a burst with grains on the periodic face takes the rebuild "
              "(event steps inserted: %d)" % inserted)
    moved = max(max(abs(a[c] - b[c]) for c in "xyz") for a, b in zip(final_insert, final_rebuild))
    check([r["id"] for r in final_insert] == [r["id"] for r in final_rebuild] and moved < 1e-9,
          "the same %d particles after 100 steps, positions within %.1e m (limit 1e-9)" % (len(final_insert), moved))


@variants(*each_rank_count(1, 2, 3, 4), timeout=600)
def case_interior(liggghts, work, ranks):
    """A burst of 175 grains, each two cells from every processor and periodic boundary."""
    compare(liggghts, work, "interior", ranks)


@variants(*each_rank_count(1, 2, 3, 4), timeout=600)
def case_inherit(liggghts, work, ranks):
    """The interior burst with a user's fix property/atom, scalar and vector, set from each grain's tag
    (in.event_lists_inherit): every fragment made in place, the one copied into its mother's slot
    among them, holds its mother's values (tag, 2 tag, -tag), every other grain its own."""
    ranks = int(ranks)
    breakable = run(liggghts, work, "interior", ranks, "insert", "in.event_lists_inherit")
    inserted, _, final = check_run(work, breakable, "inherit, insert, %d rank(s)" % ranks)
    check(inserted == 1, "the burst was replaced without a rebuild (event steps inserted: %d)" % inserted)
    mother, wrong = inheritance_errors(final, read_events(os.path.join(work, "events.csv")))
    check(not wrong, "on %d rank(s) all %d fragments hold their mother's scalar and vector, the %d grains their "
          "own (%d wrong)" % (ranks, len(mother), len(final) - len(mother), len(wrong)))


@variants(*each_rank_count(1, 2, 3, 4), timeout=600)
def case_mesh(liggghts, work, ranks):
    """The lattice on a mesh floor (in.event_lists_mesh): 120 grains of the lowest layers, those
    touching the floor among them, burst in one step; with check_lists every particle touching a
    triangle is in its list at every step until the next build."""
    compare(liggghts, work, "mesh", ranks)


@variants(*each_rank_count(1, 2, 3, 4), timeout=600)
def case_mixed(liggghts, work, ranks):
    """The same burst with the grains of a periodic face: the step rebuilds, on every rank count."""
    compare(liggghts, work, "mixed", ranks)


if __name__ == "__main__":
    test_main(globals(), sys.argv[1:])
