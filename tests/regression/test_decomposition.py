#!/usr/bin/env python3
"""post/decomposition.py, the domain decomposition simulated from a state, on lattices whose pairs,
work per rank and ghosts are known by counting (no liggghts needed).

  python3 test_decomposition.py LIGGGHTS WORKDIR CASE"""
import csv
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liggghts_run import check  # noqa: E402
from liggghts_run import main as test_main  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TOOL = os.path.join(ROOT, "post", "decomposition.py")


def lattice_dump(path, layers, n=8, box_top=7.5):
    """A dump of a simple cubic lattice of spheres of radius 0.5 at spacing 1: n x n x layers sites
    in the box [-0.5, n - 0.5]^2 x [-0.5, box_top]."""
    sites = [(x, y, z) for z in range(layers) for y in range(n) for x in range(n)]
    with open(path, "w") as f:
        f.write("ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n%d\nITEM: BOX BOUNDS ff ff ff\n" % len(sites))
        f.write("-0.5 %g\n-0.5 %g\n-0.5 %g\nITEM: ATOMS id type x y z radius\n" % (n - 0.5, n - 0.5, box_top))
        for k, (x, y, z) in enumerate(sites):
            f.write("%d 1 %g %g %g 0.5\n" % (k + 1, x, y, z))
    return path


def run(work, states, ranks):
    out = os.path.join(work, "rows.csv")
    proc = subprocess.run(["/usr/bin/python3", TOOL] + states + ["--skin", "0.1", "--csv", out, "--ranks"] + [str(r) for r in ranks],
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True)
    check(proc.returncode == 0, "post/decomposition.py ran: %s" % proc.stderr[-500:])
    with open(out) as f:
        return proc.stdout, dict(((r["state"], int(r["ranks"]), r["processors"], r["cuts"]), r) for r in csv.DictReader(f))


def case_lattice_cube(liggghts, work):
    """An 8 x 8 x 8 lattice filling its box: the pairs are the face neighbours alone (spacing 1 <
    r_i + r_j + skin = 1.1 < sqrt 2), 3 x 64 x 7 = 1344; on 8 ranks the 3-D grid is 2 x 2 x 2 (the
    least surface), "1 1 *" is 1 x 1 x 8 and "* * 1" 2 x 4 x 1 (the first of two equal surfaces, in
    the order LIGGGHTS' procmap.cpp tries them). A rank computes its own pairs and those across its
    faces (newton off): on 2 x 2 x 2 every rank has three such faces, balanced (1) with any cuts; on
    1 x 1 x 8 uniform slabs of one layer compute 112 pairs inside and 64 across each face, 176 at
    the ends and 240 within: 240 / 224 = 1.0714; on 2 x 4 x 1 columns of 4 x 2 x 8 compute 136
    inside, 16 across x and 32 across each y face: 216 / 200 = 1.08."""
    del liggghts
    text, rows = run(work, ["cube=" + lattice_dump(os.path.join(work, "cube.dump"), 8, box_top=7.5)], [8])
    check("cube: 512 particles, 1344 neighbour pairs" in text, "1344 pairs: %s" % text.splitlines()[0])
    grids = dict((proc, rows[("cube", 8, proc, "uniform")]["grid"]) for proc in ("* * *", "1 1 *", "* * 1"))
    check(grids == {"* * *": "2x2x2", "1 1 *": "1x1x8", "* * 1": "2x4x1"}, "grids %s" % grids)
    cubes = [float(rows[("cube", 8, "* * *", c)]["fullest_over_mean"]) for c in ("uniform", "count", "work")]
    check(cubes == [1.0, 1.0, 1.0], "2 x 2 x 2 balanced with any cuts: %s" % cubes)
    slabs, columns = (float(rows[("cube", 8, p, "uniform")]["fullest_over_mean"]) for p in ("1 1 *", "* * 1"))
    check(abs(slabs - 240 / 224) < 1e-4 and abs(columns - 1.08) < 1e-4, "uniform slabs %.4f (1.0714), columns %.4f (1.08)"
          % (slabs, columns))


def case_lattice_half(liggghts, work):
    """Four layers of the lattice in the box's lower half, on 2 ranks of "1 1 *": uniform cuts (the
    box split at z = 3.5) leave the upper rank empty (fullest over mean 2), though it receives the
    layer z = 3 within 1.1 of its side as ghosts (64: a mean of 32), which a cutoff by size would not
    send to a rank that owns nothing; cuts by count
    or by work split between the second and third layers (z = 1.5), two layers each: each rank
    computes its 2 x 112 in-layer and 64 between-layer pairs and the 64 across, 352, balanced; each
    rank's ghosts are the other's layer next to the cut (within 2 r_max + skin = 1.1 of z = 1.5),
    64, as a cutoff by size sends (r_j + r_own + skin = 1.1 too)."""
    del liggghts
    _, rows = run(work, ["half=" + lattice_dump(os.path.join(work, "half.dump"), 4, box_top=7.5)], [2])
    uniform, count, weighted = (rows[("half", 2, "1 1 *", c)] for c in ("uniform", "count", "work"))
    check(float(uniform["fullest_over_mean"]) == 2.0 and float(uniform["ghosts_mean"]) == 32.0
          and float(uniform["ghosts_by_size_mean"]) == 0.0,
          "uniform: fullest %s, ghosts %s, by size %s" % (uniform["fullest_over_mean"], uniform["ghosts_mean"],
                                                         uniform["ghosts_by_size_mean"]))
    for name, row in (("count", count), ("work", weighted)):
        check(float(row["fullest_over_mean"]) == 1.0 and float(row["ghosts_mean"]) == 64.0 and int(row["ghosts_max"]) == 64
              and float(row["ghosts_by_size_mean"]) == 64.0,
              "by %s: fullest %s, ghosts %s (most %s, by size %s)" % (name, row["fullest_over_mean"], row["ghosts_mean"],
                                                                     row["ghosts_max"], row["ghosts_by_size_mean"]))


if __name__ == "__main__":
    test_main(globals(), sys.argv[1:])
