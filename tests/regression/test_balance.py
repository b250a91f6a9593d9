#!/usr/bin/env python3
"""balance (doc/balance.txt) by count and by work ('weight neighbors') on 2 ranks, on a box whose
work is known: a dense lattice of touching grains and a sparse one of grains that touch nothing
(balance/in.work). The test counts each grain's neighbour pairs itself, from the positions and
radii the run dumped (pairs closer than r_i + r_j + skin, as the granular lists hold them), and finds
the lattice plane where the weights below reach half of all: the cut must sit on it.

  python3 test_balance.py LIGGGHTS WORKDIR CASE"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liggghts_run import check, read_dump, run_deck, variants  # noqa: E402
from liggghts_run import main as test_main  # noqa: E402

DECK = os.path.join(os.path.dirname(os.path.abspath(__file__)), "balance", "in.work")
SKIN = 0.001
BOX = (-0.05, 1.05)


def weights(rows, by_work):
    """Each grain's weight: 1, plus its neighbour pairs (each pair counts for both grains)."""
    w = [1.0] * len(rows)
    if by_work:
        for a in range(len(rows)):
            for b in range(a + 1, len(rows)):
                ra, rb = rows[a], rows[b]
                d2 = sum((ra[k] - rb[k]) ** 2 for k in "xyz")
                if d2 < (ra["radius"] + rb["radius"] + SKIN) ** 2:
                    w[a] += 1.0
                    w[b] += 1.0
    return w


def expected_cut(rows, w):
    """The x (fraction of the box) of the lattice plane at which the weights at or below it first
    reach half of all."""
    planes = sorted({round(r["x"], 9) for r in rows})
    total, below = sum(w), 0.0
    for x in planes:
        below += sum(wi for r, wi in zip(rows, w) if round(r["x"], 9) == x)
        if below >= 0.5 * total:
            return (x - BOX[0]) / (BOX[1] - BOX[0])
    raise AssertionError("no plane reaches half of the weights")


@variants(ranks=2)
def case_work(liggghts, work):
    """By count the cut sits on the plane that halves the grains (250 dense, 25 a plane, and 175
    sparse: x = 0.40); by work on the plane that halves 1 + the pairs (a dense plane weighs 25 + 80
    in-plane + 25 or 50 across, 1500 in all, a sparse grain 1: x = 0.25), nearer the dense side.
    Before any run, without ghosts, the same: no pair crosses the uniform plane at x = 0.5."""
    cuts = {}
    for name, by_work in (("count", 0), ("work", 1)):
        folder = os.path.join(work, name)
        out = run_deck(liggghts, DECK, folder, {"by_work": by_work}, ranks=2)
        line = [l for l in out.splitlines() if l.startswith("BALANCE:")][-1]
        cut = float(re.search(r"x cuts ([0-9.eE+-]+)", line).group(1))
        rows = read_dump(os.path.join(folder, "atoms.dump"))[-1][2]
        check(len(rows) == 425, "%s: 250 dense and 175 sparse grains (%d)" % (name, len(rows)))
        expected = expected_cut(rows, weights(rows, name == "work"))
        check(abs(cut - expected) < 1e-6, "%s: the cut at %.7f of the box, on the plane the test finds, %.7f (%s)"
              % (name, cut, expected, line))
        check(("work, particles + neighbour pairs," in line) == (name == "work"), "%s: the line names its measure" % name)
        cuts[name] = cut
    box = BOX[1] - BOX[0]
    check(abs(cuts["count"] - (0.40 - BOX[0]) / box) < 1e-6 and abs(cuts["work"] - (0.25 - BOX[0]) / box) < 1e-6,
          "by count at x = 0.40, by work at x = 0.25 (%.4f, %.4f of the box)" % (cuts["count"], cuts["work"]))
    out = run_deck(liggghts, DECK, os.path.join(work, "first"), {"by_work": 1, "first": 1}, ranks=2)
    first = [l for l in out.splitlines() if l.startswith("BALANCE:")][0]
    check(abs(float(re.search(r"x cuts ([0-9.eE+-]+)", first).group(1)) - cuts["work"]) < 1e-6,
          "before any run (no ghosts yet; no pair crosses the first plane, x = 0.5) the same cut: %s" % first)


if __name__ == "__main__":
    test_main(globals(), sys.argv[1:])
