#!/usr/bin/python3
"""Stresses around an axis from per-particle stresses: radial, vertical and hoop stresses averaged in
rings (r, z) about a vertical axis, for penetrometers and piles (a chamber sector of --sector degrees
about the axis at (--x0, --y0)).

    post/ring_stress.py DUMP --dr DR --dz DZ [--x0 0 --y0 0] [--sector 90] [--column c_stress]
                        [--out rings.csv]

DUMP: a LIGGGHTS 'dump custom' file (its last snapshot) with the columns x y z and the six components
of 'compute stress/atom' (COLUMN[1] ... COLUMN[6]: xx yy zz xy xz yz). LIGGGHTS gives a particle's
stress as minus its virial, in pressure x volume units: the mean stress of a region V is
sigma = -(1/V) sum_i s_i, here with compression positive. Each particle's tensor is turned into the
cylindrical frame at its own angle theta about the axis,
    sigma_rr = c^2 s_xx + s^2 s_yy + 2 c s s_xy,   sigma_tt = s^2 s_xx + c^2 s_yy - 2 c s s_xy,
    sigma_rz = c s_xz + s s_yz,                    (c = cos theta, s = sin theta)
and summed over the ring r1 <= r < r2, z1 <= z < z2, whose volume is (sector/360) pi (r2^2 - r1^2) dz.
Writes one row a ring: r_mid, z_mid, particles, sigma_rr, sigma_tt, sigma_zz, sigma_rz (Pa).
"""
import argparse
import csv
import math
import sys


def read_snapshots(path):
    """[(timestep, columns, rows)] of every snapshot of a dump custom file, rows as lists of floats."""
    with open(path) as f:
        lines = f.read().splitlines()
    starts = [k for k, line in enumerate(lines) if line.startswith("ITEM: TIMESTEP")]
    if not starts:
        raise SystemExit("ring_stress: %s holds no dump snapshot" % path)
    snapshots = []
    for k in starts:
        natoms = int(lines[k + 3])
        columns = lines[k + 8].split()[2:]
        snapshots.append((int(lines[k + 1]), columns, [list(map(float, lines[k + 9 + n].split())) for n in range(natoms)]))
    return snapshots


def read_last_snapshot(path):
    """(columns, rows) of the last snapshot of a dump custom file, rows as lists of floats."""
    _, columns, rows = read_snapshots(path)[-1]
    return columns, rows


def stress_particles(columns, rows, column="c_stress", where="dump"):
    """(x, y, z, (s_xx, ..., s_yz)) of a snapshot's rows, from its x y z and COLUMN[1] ... COLUMN[6]."""
    wanted = ["x", "y", "z"] + ["%s[%d]" % (column, m) for m in range(1, 7)]
    missing = [c for c in wanted if c not in columns]
    if missing:
        raise SystemExit("ring_stress: %s has no column %s (columns: %s)" % (where, ", ".join(missing), " ".join(columns)))
    at = [columns.index(c) for c in wanted]
    return [(r[at[0]], r[at[1]], r[at[2]], tuple(r[a] for a in at[3:])) for r in rows]


def chamber_sector(xs, ys):
    """The penetration chamber's angle about the axis (degrees), told from its particles' centres:
    360 where they lie on both sides of the axis in x and in y (in.geometry's sector 360, the whole
    chamber), else 90 (the quarter, whose symmetry walls keep every centre at x, y > 0)."""
    return 360.0 if min(xs) < 0 and min(ys) < 0 else 90.0


def cylindrical(s, theta):
    """(rr, tt, zz, rz) of a symmetric tensor given as (xx, yy, zz, xy, xz, yz) at angle theta."""
    c, n = math.cos(theta), math.sin(theta)
    xx, yy, zz, xy, xz, yz = s
    return (c * c * xx + n * n * yy + 2 * c * n * xy, n * n * xx + c * c * yy - 2 * c * n * xy, zz,
            c * xz + n * yz)


def ring_stresses(particles, dr, dz, x0=0.0, y0=0.0, sector=360.0):
    """particles: (x, y, z, (s_xx, s_yy, s_zz, s_xy, s_xz, s_yz)) with s in pressure x volume (LIGGGHTS'
    sign). Returns {(i, k): [count, rr, tt, zz, rz]} with the ring-averaged stresses, compression
    positive, for rings i dr <= r < (i+1) dr, k dz <= z < (k+1) dz."""
    sums = {}
    for x, y, z, s in particles:
        r = math.hypot(x - x0, y - y0)
        key = (int(r // dr), int(math.floor(z / dz)))
        entry = sums.setdefault(key, [0, 0.0, 0.0, 0.0, 0.0])
        entry[0] += 1
        for m, value in enumerate(cylindrical(s, math.atan2(y - y0, x - x0))):
            entry[m + 1] += value
    rings = {}
    for (i, k), (count, *parts) in sums.items():
        volume = sector / 360.0 * math.pi * ((i + 1) ** 2 - i ** 2) * dr * dr * dz
        rings[(i, k)] = [count] + [-p / volume for p in parts]
    return rings


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("dump")
    ap.add_argument("--dr", type=float, required=True, help="ring width (m)")
    ap.add_argument("--dz", type=float, required=True, help="ring height (m)")
    ap.add_argument("--x0", type=float, default=0.0)
    ap.add_argument("--y0", type=float, default=0.0)
    ap.add_argument("--sector", type=float, default=360.0, help="the chamber's angle about the axis (degrees)")
    ap.add_argument("--column", default="c_stress", help="the dump's stress/atom columns, NAME[1] ... NAME[6]")
    ap.add_argument("--out", default="rings.csv")
    args = ap.parse_args(argv)
    if not (args.dr > 0 and args.dz > 0 and 0 < args.sector <= 360):
        raise SystemExit("ring_stress: --dr and --dz must be > 0 and --sector in (0, 360]")
    columns, rows = read_last_snapshot(args.dump)
    particles = stress_particles(columns, rows, args.column, args.dump)
    rings = ring_stresses(particles, args.dr, args.dz, args.x0, args.y0, args.sector)
    with open(args.out, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["r_mid", "z_mid", "particles", "sigma_rr", "sigma_tt", "sigma_zz", "sigma_rz"])
        for (i, k) in sorted(rings):
            count, rr, tt, zz, rz = rings[(i, k)]
            w.writerow(["%.6g" % ((i + 0.5) * args.dr), "%.6g" % ((k + 0.5) * args.dz), count,
                        "%.6g" % rr, "%.6g" % tt, "%.6g" % zz, "%.6g" % rz])
    print("ring_stress: %d particles in %d rings -> %s" % (len(particles), len(rings), args.out))


if __name__ == "__main__":
    main(sys.argv[1:])
