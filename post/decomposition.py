#!/usr/bin/python3
"""The domain decomposition a chamber needs, simulated from its real states: for each state (a dump
of in.chamber or in.cone, or a VTK .vtu of the particles), each rank count and each processor grid,
the work of the fullest rank over the mean and the ghosts per rank, with the grid's cuts uniform and
at the work's quantiles (what a balancer by work would set).

    post/decomposition.py STATE [STATE ...] --skin 0.00068 [--box xlo xhi ylo yhi zlo zhi]
                          [--ranks 2 4 8 ... 256] [--csv OUT.csv] [--plot OUT.png]
    post/decomposition.py --rows OUT.csv [...] --plot OUT.png      (draw earlier rows again)

A STATE is LABEL=PATH (a dump custom with id x y z radius, or a .vtu with a radius array). The box
is the dump's (fixed boundaries: every state of a chamber has its box); a .vtu takes --box or the
box of a dump given before it. Each particle's work is its neighbours: the particles j within
r_i + r_j + skin (the granular neighbour list's cutoff; skin is the deck's neighbor distance,
in.cone's 0.00002 N). A rank computes each of its own pairs once and each pair with a ghost too
(newton off, as the decks run), so its work is its pairs inside plus its pairs across; its ghosts
are the other ranks' particles within the ghost cutoff (2 r_max + skin: communicate single) of its
subdomain. Grids, as LIGGGHTS' processors command makes them: "* * 1" and "1 1 *" and the 3-D "* * *",
each the factorisation of the rank count that minimises the subdomains' surface (LAMMPS' procs2box).
Cuts: uniform (equal slabs of the box, LIGGGHTS 3.8.0's layout without balance), by count (each
dimension cut at the quantiles of the particles projected on it: LIGGGHTS 3.8.0's balance, the
decks' -var balance 1) and by work (at the quantiles of the work: a balancer by work, one pass).
Writes one row per state, rank count, grid and cut: the fullest rank's work over the mean, the
emptiest's, the mean and largest ghosts per rank, the ghosts over the owned particles, and the mean
and largest ghosts that a ghost cutoff by size would send (a particle j only where a pair with the
rank's own largest grain can reach it: r_j + r_own + skin from the subdomain).
"""
import argparse
import csv
import os
import sys

if not __package__:  # run as a file (python3 post/decomposition.py): the folder above post/ holds the package
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from post import requires  # noqa: E402

requires("decomposition", "numpy", "scipy")

import numpy as np
from scipy.spatial import cKDTree

GRIDS = {"* * 1": (None, None, 1), "1 1 *": (1, 1, None), "* * *": (None, None, None)}
CUTS = ("uniform", "count", "work")
COLUMNS = ["state", "particles", "ranks", "processors", "grid", "cuts", "fullest_over_mean", "emptiest_over_mean",
           "ghosts_mean", "ghosts_max", "ghosts_over_owned", "ghosts_by_size_mean", "ghosts_by_size_max"]


def read_state(path, box=None):
    """(positions (n, 3), radii (n,), box ((lo, hi) x 3)) of a dump custom or a .vtu."""
    if path.endswith(".vtu"):
        requires("decomposition", "vtk")
        import vtk
        from vtk.util.numpy_support import vtk_to_numpy
        reader = vtk.vtkXMLUnstructuredGridReader()
        reader.SetFileName(path)
        reader.Update()
        grid = reader.GetOutput()
        if grid.GetNumberOfPoints() == 0:
            sys.exit("decomposition.py: no particles in %s" % path)
        x = vtk_to_numpy(grid.GetPoints().GetData()).astype(float)
        r = vtk_to_numpy(grid.GetPointData().GetArray("radius")).astype(float)
        if box is None:
            sys.exit("decomposition.py: %s: a .vtu has no box: give --box or a dump before it" % path)
        return x, r, box
    with open(path) as f:
        lines = f.read().split("\n")
    at = next(i for i, line in enumerate(lines) if line.startswith("ITEM: BOX BOUNDS"))
    box = tuple(tuple(float(v) for v in lines[at + 1 + k].split()[:2]) for k in range(3))
    head = next(i for i, line in enumerate(lines) if line.startswith("ITEM: ATOMS"))
    names = lines[head].split()[2:]
    col = [names.index(c) for c in ("x", "y", "z", "radius")]
    data = np.array([[float(w[c]) for c in col] for w in (line.split() for line in lines[head + 1:]) if len(w) == len(names)])
    return data[:, :3], data[:, 3], box


def neighbour_pairs(x, r, skin):
    """(i, j) arrays of the pairs within r_i + r_j + skin, each pair once: the particles sorted into
    size classes, each pair of classes searched at its own largest cutoff."""
    edges = np.unique(np.quantile(r, np.linspace(0, 1, 7)))
    if len(edges) < 2:  # one size
        edges = np.array([r.min(), r.max() * (1 + 1e-12) + 1e-300])
    cls = np.clip(np.searchsorted(edges, r, side="right") - 1, 0, len(edges) - 2)
    members = [np.flatnonzero(cls == c) for c in range(len(edges) - 1)]
    trees = [cKDTree(x[m]) if len(m) else None for m in members]
    out_i, out_j = [], []
    for a in range(len(members)):
        for b in range(a, len(members)):
            if trees[a] is None or trees[b] is None:
                continue
            reach = r[members[a]].max() + r[members[b]].max() + skin
            if a == b:
                pairs = trees[a].query_pairs(reach, output_type="ndarray")
                i, j = members[a][pairs[:, 0]], members[a][pairs[:, 1]]
            else:
                found = trees[a].query_ball_tree(trees[b], reach)
                i = np.repeat(members[a], [len(f) for f in found])
                j = members[b][np.fromiter((k for f in found for k in f), dtype=int, count=len(i))]
            d = np.linalg.norm(x[i] - x[j], axis=1)
            keep = d < r[i] + r[j] + skin
            out_i.append(i[keep])
            out_j.append(j[keep])
    return np.concatenate(out_i), np.concatenate(out_j)


def grid_for(ranks, fixed, box):
    """(px, py, pz) of ranks with the fixed counts (None: free) minimising the subdomains' surface."""
    lx, ly, lz = (hi - lo for lo, hi in box)
    best = None
    for px in range(1, ranks + 1):
        if ranks % px or (fixed[0] and px != fixed[0]):
            continue
        for py in range(1, ranks // px + 1):
            if (ranks // px) % py or (fixed[1] and py != fixed[1]):
                continue
            pz = ranks // px // py
            if fixed[2] and pz != fixed[2]:
                continue
            surface = lx * ly / px / py + lx * lz / px / pz + ly * lz / py / pz
            if best is None or surface < best[0] - 1e-12 * surface:
                best = (surface, (px, py, pz))
    return best[1] if best else None


def cuts(coordinate, weight, lo, hi, parts, mode):
    """The parts + 1 cut positions of one dimension: equal slabs (uniform), or the quantiles of the
    particles (count) or of their work (work)."""
    if mode == "uniform" or parts == 1:
        return np.linspace(lo, hi, parts + 1)
    order = np.argsort(coordinate)
    cumulative = np.cumsum(weight[order] if mode == "work" else np.ones(len(order)))
    targets = cumulative[-1] * np.arange(1, parts) / parts
    ordered = coordinate[order]
    at = np.searchsorted(cumulative, targets)  # the particle that completes each share: the cut just above it
    inner = 0.5 * (ordered[at] + ordered[np.minimum(at + 1, len(ordered) - 1)])
    return np.concatenate(([lo], inner, [hi]))


def assign(x, planes):
    """Each particle's rank index from the cut planes of the three dimensions."""
    idx = [np.clip(np.searchsorted(p, x[:, k], side="right") - 1, 0, len(p) - 2) for k, p in enumerate(planes)]
    shape = [len(p) - 1 for p in planes]
    return (idx[0] * shape[1] + idx[1]) * shape[2] + idx[2]


def ghosts_per_rank(x, r, owner, planes, skin):
    """Per rank, the other ranks' particles within the ghost cutoff of its subdomain (2 r_max + skin
    for all, as LIGGGHTS 3.8.0 communicates), and those that a pair of its own needs: within r_j +
    (its own largest radius) + skin of the subdomain (what a cutoff by size would send)."""
    shape = [len(p) - 1 for p in planes]
    cutoff = 2 * r.max() + skin
    out, needed = [], []
    for a in range(shape[0]):
        for b in range(shape[1]):
            for c in range(shape[2]):
                rank = (a * shape[1] + b) * shape[2] + c
                lo = np.array([planes[0][a], planes[1][b], planes[2][c]])
                hi = np.array([planes[0][a + 1], planes[1][b + 1], planes[2][c + 1]])
                other = owner != rank
                near = np.all((x >= lo - cutoff) & (x < hi + cutoff), axis=1) & other
                out.append(int(np.count_nonzero(near)))
                own = r[~other]
                if len(own) == 0:
                    needed.append(0)
                    continue
                gap = np.linalg.norm(np.maximum(np.maximum(lo - x[near], x[near] - hi), 0.0), axis=1)
                needed.append(int(np.count_nonzero(gap < r[near] + own.max() + skin)))
    return np.array(out), np.array(needed)


def pairs_per_particle(pairs, count):
    """Each particle's neighbour pairs (its work weight)."""
    i, j = pairs
    return (np.bincount(i, minlength=count) + np.bincount(j, minlength=count)).astype(float)


def measure(x, r, box, pairs, weight, skin, ranks, grid, mode):
    """(the fullest rank's work / mean, the emptiest's / mean, mean ghosts, most ghosts, ghosts over
    owned particles, mean and most ghosts a cutoff by size would send) of one decomposition; weight is
    pairs_per_particle(pairs)."""
    i, j = pairs
    planes = [cuts(x[:, k], weight, box[k][0], box[k][1], grid[k], mode) for k in range(3)]
    owner = assign(x, planes)
    inside = owner[i] == owner[j]
    work = np.bincount(owner[i][inside], minlength=ranks).astype(float)
    work += np.bincount(owner[i][~inside], minlength=ranks) + np.bincount(owner[j][~inside], minlength=ranks)
    ghosts, needed = ghosts_per_rank(x, r, owner, planes, skin)
    mean = work.mean()
    return work.max() / mean, work.min() / mean, ghosts.mean(), ghosts.max(), ghosts.sum() / len(r), needed.mean(), needed.max()


def write_rows(path, rows):
    with open(path, "w", newline="") as f:
        writer = csv.writer(f, lineterminator="\n")
        writer.writerow(COLUMNS)
        for row in rows:
            writer.writerow(list(row[:6]) + ["%.4f" % row[6], "%.4f" % row[7], "%.1f" % row[8], "%d" % row[9],
                                             "%.4f" % row[10], "%.1f" % row[11], "%d" % row[12]])


def read_rows(path):
    """The rows of a CSV this tool wrote (--rows: draw again without computing)."""
    with open(path) as f:
        return [(r["state"], int(r["particles"]), int(r["ranks"]), r["processors"], r["grid"], r["cuts"])
                + tuple(float(r[c]) for c in COLUMNS[6:]) for r in csv.DictReader(f)]


def draw(path, rows):
    """Per state, the fullest rank's work over the mean (above) and the ghosts per rank over the
    particles it owns (below: LIGGGHTS' single cutoff, and by size), against the ranks."""
    requires("decomposition", "matplotlib")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    states = list(dict.fromkeys(row[0] for row in rows))
    fig, axes = plt.subplots(2, len(states), figsize=(5 * len(states), 8.5), squeeze=False, sharey="row")
    colours = dict(zip(GRIDS, ("C0", "C1", "C2")))
    for k, state in enumerate(states):
        top, bottom = axes[0][k], axes[1][k]
        for grid_name in GRIDS:
            for cut, style in (("uniform", ":"), ("count", "--"), ("work", "-")):
                chosen = [row for row in rows if row[0] == state and row[3] == grid_name and row[5] == cut]
                top.loglog([row[2] for row in chosen], [row[6] for row in chosen], style, marker="o", ms=3,
                           color=colours[grid_name], label="%s, %s cuts" % (grid_name, cut))
            chosen = [row for row in rows if row[0] == state and row[3] == grid_name and row[5] == "work"]
            owned = [row[1] / row[2] for row in chosen]
            bottom.loglog([row[2] for row in chosen], [row[8] / n for row, n in zip(chosen, owned)], "-", marker="o", ms=3,
                          color=colours[grid_name], label="%s, work cuts: single cutoff" % grid_name)
            bottom.loglog([row[2] for row in chosen], [row[11] / n for row, n in zip(chosen, owned)], "--", marker="s", ms=3,
                          color=colours[grid_name], label="%s, work cuts: cutoff by size" % grid_name)
        top.set_title(state)
        bottom.set_xlabel("ranks")
        for ax in (top, bottom):
            ax.grid(alpha=0.3, which="both")
    axes[0][0].set_ylabel("fullest rank's work / mean")
    axes[1][0].set_ylabel("ghosts per rank / particles per rank")
    axes[0][0].legend(fontsize=7)
    axes[1][0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("states", nargs="*", help="LABEL=PATH: a dump custom (id x y z radius) or a .vtu")
    parser.add_argument("--skin", type=float, help="the deck's neighbor skin (m)")
    parser.add_argument("--box", type=float, nargs=6, help="xlo xhi ylo yhi zlo zhi for .vtu states")
    parser.add_argument("--ranks", type=int, nargs="+", default=[2, 4, 8, 16, 32, 64, 128, 256])
    parser.add_argument("--csv", help="write the rows here")
    parser.add_argument("--rows", nargs="+", help="instead of states, the rows of earlier --csv files (to draw them)")
    parser.add_argument("--plot", help="draw the fullest rank's work over the mean and the ghosts against the ranks")
    a = parser.parse_args()
    if a.rows:
        rows = [row for path in a.rows for row in read_rows(path)]
    elif not a.states or a.skin is None:
        sys.exit("decomposition.py: give states (LABEL=PATH) and --skin, or --rows CSV")
    else:
        rows = decompose(a)
    if a.csv:
        write_rows(a.csv, rows)
    if a.plot:
        draw(a.plot, rows)


def decompose(a):
    """The rows of every state, rank count, grid and cut of the command line."""
    box = tuple(zip(a.box[0::2], a.box[1::2])) if a.box else None
    rows = []
    for state in a.states:
        if "=" not in state:
            sys.exit("decomposition.py: %s: a state is LABEL=PATH" % state)
        name, path = state.split("=", 1)
        x, r, box = read_state(path, box)
        pairs = neighbour_pairs(x, r, a.skin)
        weight = pairs_per_particle(pairs, len(r))
        print("%s: %d particles, %d neighbour pairs (%.1f a particle), ghost cutoff %.4g m"
              % (name, len(r), len(pairs[0]), 2.0 * len(pairs[0]) / len(r), 2 * r.max() + a.skin))
        for ranks in a.ranks:
            for grid_name, fixed in GRIDS.items():
                grid = grid_for(ranks, fixed, box)
                for mode in CUTS:
                    m = measure(x, r, box, pairs, weight, a.skin, ranks, grid, mode)
                    rows.append((name, len(r), ranks, grid_name, "%dx%dx%d" % grid, mode) + m)
                    print("  %4d ranks %-6s %-9s %-8s fullest %.2f emptiest %.2f ghosts %.0f (most %d, %.2f of the owned;"
                          " by size %.0f, most %d)"
                          % ((ranks, grid_name, "%dx%dx%d" % grid, rows[-1][5]) + m))
    return rows


if __name__ == "__main__":
    main()
