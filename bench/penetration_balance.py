#!/usr/bin/python3
"""Each rank's share of a penetration test's particles and contacts for the decks' grids.

    bench/penetration_balance.py DUMP [CHAMBER_IN]

DUMP is a 'dump custom' snapshot (id type x y z radius ...) of examples/penetration/in.cone; its box
is the simulation box, which LIGGGHTS 3.8.0 cuts in equal slabs (no balance command). For the grid
"* * 1" on 2 ranks (2 x 1 x 1: one cut across x) and on 4 ranks (2 x 2 x 1) it prints each
subdomain's particles and contacts (overlapping pairs, each counted by the ranks of both particles,
as with 'newton off': the pair work) and the fuller rank's share. CHAMBER_IN (chamber_*.in) is
only echoed, for the record of which chamber it was."""
import sys

import numpy as np


def read_dump(path):
    lines = open(path).read().splitlines()
    k = next(i for i, line in enumerate(lines) if line.startswith("ITEM: BOX BOUNDS"))
    box = [tuple(map(float, lines[k + 1 + d].split()[:2])) for d in range(3)]
    k = next(i for i, line in enumerate(lines) if line.startswith("ITEM: ATOMS"))
    columns = lines[k].split()[2:]
    data = np.array([list(map(float, line.split())) for line in lines[k + 1:] if line.strip()])
    return box, {c: data[:, j] for j, c in enumerate(columns)}


def contacts_per_particle(x, r):
    """Overlapping neighbours of each particle (brute force in blocks: some 10^4 particles)."""
    count = np.zeros(len(r), dtype=int)
    for start in range(0, len(r), 512):
        block = slice(start, min(start + 512, len(r)))
        d = np.linalg.norm(x[block, None, :] - x[None, :, :], axis=2)
        touching = d < (r[block, None] + r[None, :])
        touching[np.arange(block.stop - block.start), np.arange(block.start, block.stop)] = False
        count[block] = touching.sum(axis=1)
    return count


def main():
    box, atoms = read_dump(sys.argv[1])
    if len(sys.argv) > 2:
        print("chamber: " + " ".join(line.split()[1] + " = " + line.split()[3] for line in open(sys.argv[2])
                                     if line.startswith("variable")))
    x = np.stack([atoms["x"], atoms["y"], atoms["z"]], axis=1)
    contacts = contacts_per_particle(x, atoms["radius"])
    mid = [(lo + hi) / 2 for lo, hi in box]
    for name, cells in (("2 ranks (2 x 1 x 1)", (x[:, 0] >= mid[0]).astype(int)),
                        ("4 ranks (2 x 2 x 1)", (x[:, 0] >= mid[0]).astype(int) + 2 * (x[:, 1] >= mid[1]).astype(int))):
        ranks = cells.max() + 1
        particles = [int((cells == k).sum()) for k in range(ranks)]
        work = [int(contacts[cells == k].sum()) for k in range(ranks)]
        print("%s: particles %s, fuller rank %.1f%% (even %.1f%%); contacts %s, fuller rank %.1f%%"
              % (name, particles, 100.0 * max(particles) / sum(particles), 100.0 / ranks, work,
                 100.0 * max(work) / max(sum(work), 1)))


if __name__ == "__main__":
    main()
