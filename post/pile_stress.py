#!/usr/bin/python3
"""Stresses around a jacked pile or cone (examples/penetration/in.cone -var stress_every D): the
radial, hoop and vertical stresses averaged in rings (r, h) about the axis, in the frame of the tip
(h = z - z_tip), over the stress dump's snapshots from --from D_c of depth on (a steady penetration
is stationary in that frame); the radial stress on the shaft, sigma_r', against the height above the
tip h / R, from the rings next to the shaft; and maps of the three stresses.

    post/pile_stress.py --label pile_region --N 80 --Dc 0.0357 [--dir .] [--from 1.5] [--dr 0.25]
                        [--dh 0.25] [--out OUT]

--label may list tests (seeds of one setting, comma-separated, with --dir one folder or one per
label): their snapshots are averaged together, each in its own tip's frame. Reads, for each,
stress_LABEL_N<N>.liggghts (x y z and compute stress/atom, post/ring_stress.py's convention)
and penetration_LABEL_N<N>.csv (the tip's height at each step, interpolated). --dr and --dh are in
D_c. The rings are quarter rings in the quarter chamber and whole ones in the whole chamber (sand on
both sides of the axis). Writes, in the first folder, OUT_rings.csv (r/R, h/R, particles, sigma_rr, sigma_tt, sigma_zz, sigma_rz in Pa, the
snapshots' mean, over those whose ring holds particles and lies wholly below the sand's surface: the
surface is the history's first tip height plus its depth), OUT_shaft.csv (h/R and sigma_r' in the first ring outside the shaft), OUT_maps.png
and OUT_shaft.png, and prints the shaft's profile.
"""
import argparse
import csv
import math
import os
import sys

if not __package__:  # run as a file (python3 post/pile_stress.py): the folder above post/ holds the package
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from post import requires  # noqa: E402

requires("pile_stress", "matplotlib")

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from post.penetration import tip_at  # noqa: E402
from post.ring_stress import chamber_sector, read_snapshots, ring_stresses, stress_particles  # noqa: E402


def averaged_rings(snapshots, Dc, start, dr, dh):
    """{(i, k): [particles, rr, tt, zz, rz]}: each snapshot's rings in the tip's frame (h = z - z_tip),
    averaged over the snapshots whose tip is at least start D_c deep and whose ring lies wholly
    below the sand's surface (a ring that reaches above it holds sand in part of its volume, and
    its stress, averaged over the whole, would read low); and the number of snapshots used.
    snapshots: (step, columns, rows, the test's history, its surface's height)."""
    total, seen, used = {}, {}, 0
    for step, columns, rows, history, surface in snapshots:
        tip = tip_at(history, step)
        if (surface - tip) / Dc < start:
            continue
        used += 1
        particles = [(x, y, z - tip, s) for x, y, z, s in stress_particles(columns, rows)]
        sector = chamber_sector([q[0] for q in particles], [q[1] for q in particles])
        for key, values in ring_stresses(particles, dr, dh, sector=sector).items():
            if tip + (key[1] + 1) * dh > surface + 1e-9 * Dc:
                continue
            entry = total.setdefault(key, [0.0] * 5)
            seen[key] = seen.get(key, 0) + 1
            for m, value in enumerate(values):
                entry[m] += value
    return dict((key, [v / seen[key] for v in values]) for key, values in total.items()), used


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--label", required=True)
    ap.add_argument("--N", type=float, required=True)
    ap.add_argument("--Dc", type=float, required=True, help="the pile's (cone's) diameter (m)")
    ap.add_argument("--dir", default=".")
    ap.add_argument("--from", dest="start", type=float, default=1.5, help="average from this depth of the tip (D_c)")
    ap.add_argument("--dr", type=float, default=0.25, help="ring width (D_c)")
    ap.add_argument("--dh", type=float, default=0.25, help="ring height (D_c)")
    ap.add_argument("--out")
    a = ap.parse_args(argv)
    n_label = "%g" % a.N
    labels, dirs = a.label.split(","), a.dir.split(",")
    if len(dirs) == 1:
        dirs = dirs * len(labels)
    if len(dirs) != len(labels):
        raise SystemExit("pile_stress: --dir gives %d folders for %d labels (one, or one per label)" % (len(dirs), len(labels)))
    out = os.path.join(dirs[0], a.out or labels[0])
    snapshots, used = [], 0
    rings = {}
    for label, folder in zip(labels, dirs):
        dump = os.path.join(folder, "stress_%s_N%s.liggghts" % (label, n_label))
        path = os.path.join(folder, "penetration_%s_N%s.csv" % (label, n_label))
        for f in (dump, path):
            if not os.path.exists(f):
                raise SystemExit("pile_stress: no %s (run in.cone with -var label %s -var stress_every D)" % (f, label))
        with open(path) as f:
            history = [dict((k, float(v)) for k, v in row.items()) for row in csv.DictReader(f)]
        surface = history[0]["tip_z"] + history[0]["depth"]
        # each test's snapshots in its own tip's frame, together (the tests are seeds of one setting)
        snapshots += [(step, columns, rows, history, surface) for step, columns, rows in read_snapshots(dump)]
    rings, used = averaged_rings(snapshots, a.Dc, a.start, a.dr * a.Dc, a.dh * a.Dc)
    if not used:
        raise SystemExit("pile_stress: no snapshot of %s with the tip %.2f D_c deep or more" % (a.label, a.start))
    with open(out + "_rings.csv", "w") as f:
        f.write("r_over_R,h_over_R,particles,sigma_rr,sigma_tt,sigma_zz,sigma_rz\n")
        for (i, k) in sorted(rings):
            count, rr, tt, zz, rz = rings[(i, k)]
            f.write("%.4g,%.4g,%.1f,%.6g,%.6g,%.6g,%.6g\n" % ((i + 0.5) * a.dr * 2, (k + 0.5) * a.dh * 2, count, rr, tt, zz, rz))
    # the shaft's ring: the first whose inner radius is at or beyond R
    first = int(math.ceil(0.5 / a.dr - 1e-9))
    shaft = sorted((k, rings[(i, k)]) for (i, k) in rings if i == first and k >= 0)
    with open(out + "_shaft.csv", "w") as f:
        f.write("h_over_R,particles,sigma_r,sigma_theta,sigma_z\n")
        for k, (count, rr, tt, zz, _) in shaft:
            f.write("%.4g,%.1f,%.6g,%.6g,%.6g\n" % ((k + 0.5) * a.dh * 2, count, rr, tt, zz))
    print("pile_stress %s: %d snapshots from %.1f D_c deep; sigma_r' on the shaft (r %.2f - %.2f R):"
          % (a.label, used, a.start, first * a.dr * 2, (first + 1) * a.dr * 2))
    for k, (count, rr, tt, _, _) in shaft:
        print("  h/R %5.2f: sigma_r' %8.1f kPa, sigma_theta %8.1f kPa (%.1f particles)"
              % ((k + 0.5) * a.dh * 2, rr / 1e3, tt / 1e3, count))

    fig, axes = plt.subplots(1, 3, figsize=(13, 5), sharey=True)
    keys = sorted(rings)
    imax = max(i for i, _ in keys) + 1
    kmin, kmax = min(k for _, k in keys), max(k for _, k in keys) + 1
    for ax, m, name in zip(axes, (1, 2, 3), ("radial", "hoop", "vertical")):
        grid = [[rings.get((i, k), [0] * 5)[m] / 1e3 for i in range(imax)] for k in range(kmin, kmax)]
        image = ax.imshow(grid, origin="lower", aspect="auto", cmap="viridis",
                          extent=(0, imax * a.dr * 2, kmin * a.dh * 2, kmax * a.dh * 2))
        ax.plot([1, 1], [0, kmax * a.dh * 2], color="w", lw=1)
        ax.plot([0, 1], [0, 0], color="w", lw=1)
        ax.set_title("%s stress (kPa)" % name)
        ax.set_xlabel("r / R")
        fig.colorbar(image, ax=ax)
    axes[0].set_ylabel("h / R (height above the tip)")
    fig.suptitle("%s: ring-averaged stresses in the tip's frame, %d snapshots" % (a.label, used))
    fig.tight_layout()
    fig.savefig(out + "_maps.png", dpi=110)
    fig, ax = plt.subplots(figsize=(5, 5))
    ax.plot([rr / 1e3 for _, (_, rr, _, _, _) in shaft], [(k + 0.5) * a.dh * 2 for k, _ in shaft], "o-")
    ax.set_xlabel("sigma_r' on the shaft (kPa)")
    ax.set_ylabel("h / R")
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out + "_shaft.png", dpi=110)


if __name__ == "__main__":
    main(sys.argv[1:])
