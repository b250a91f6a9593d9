#!/usr/bin/python3
"""Radial profiles of a refined penetration chamber across its zones' interfaces: solid fraction,
mean stress, coordination number, particle count, scale factor N and diameter in annuli about the
cone's axis, and the jump of each across the interfaces between the zones (fine grains near the
axis, coarser beyond R1, coarser still beyond R2).

    post/chamber_profiles.py DUMP [DUMP ...] [--snapshot STEP] [--Dc 0.0357] [--dr 0.5] [--rmax R]
                             [--wall-x WX] [--wall-y WY] [--zmin Z1] [--zmax Z2] [--margin 1]
                             [--interfaces R1,R2] [--points 20000] [--seed 1] [--out profiles] [--plot]

The chamber (examples/penetration) is a quarter cylinder about the z axis (the cone's): the sand
fills 0 < x < wall_x, 0 < y < wall_y; or the whole chamber (in.geometry's sector 360, told by sand
on both sides of the axis), -wall < x < wall_x and the same in y, whose annuli are whole. DUMP is a LIGGGHTS 'dump custom' file (its last snapshot, or
the one of timestep --snapshot) with the columns x y z radius and, optionally,
  c_stress[1] c_stress[2] c_stress[3] (compute stress/atom: s_xx s_yy s_zz, pressure x volume,
      negative in compression) and c_stress[4] (s_xy) for the radial and hoop stresses;
  c_coord (compute contact/atom: each particle's contacts);
  f_grain_scale (each particle's scale factor N).
The annuli r_k <= r < r_k+1 (r = sqrt(x^2 + y^2), --dr D_c wide, whole ones up to --rmax, by default
min(wall_x, wall_y)) are cut to the height window zmin <= z < zmax, by default the particles' height
less --margin D_c at each end (the bottom wall and the top). In each annulus:
  solid fraction and porosity: the spheres' volume inside it, from --points Monte Carlo points
      (seeded), with its binomial standard error;
  p = -(1/3V) sum_i (s_xx + s_yy + s_zz), sigma_zz and, with s_xy, sigma_rr and sigma_tt (each
      particle's tensor turned to its own angle, as post/ring_stress.py), summed over the particles
      whose centres lie in the annulus, V its volume (pi/4 (r_k+1^2 - r_k^2) (zmax - zmin) in the
      quarter, four times that in the whole chamber);
      compression positive (Pa);
  the mean coordination number of those particles, and that of those with 2 contacts or more (the
      rattlers left out), with their standard errors;
  their count, mean N and mean diameter (m).
Prints a table (the interfaces, --interfaces in D_c, marked: a line where one falls on an annulus'
edge, 'R1 inside' on the row of an annulus it crosses), writes OUT.csv (a row an annulus, r in m and
in D_c) and OUT_jumps.csv, and with --plot OUT.png (porosity, p and coordination against r/D_c).
The jump across an interface is the mean of the two annuli just outside it less that of the two just
inside (an annulus that the interface crosses is neither), with its standard error: porosity's from
the Monte Carlo, p's from the spread of the two annuli's values, the coordination's from the
particles' values; it is resolved when it is more than 3 standard errors.
Several DUMPs are chambers of one setting with other seeds (their own samples): each is written as
OUT_<k>, on one set of annuli (within the narrowest chamber), and OUT_seeds.csv gathers the annuli's
mean and standard error over the chambers, OUT_seed_jumps.csv each interface's jump (each chamber's,
then their mean and standard error), resolved where the 95% t interval excludes zero.
"""
import argparse
import csv
import itertools
import math
import os
import sys

if not __package__:  # run as a file (python3 post/chamber_profiles.py): the folder above post/ holds the package
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from post import requires  # noqa: E402
from post.ring_stress import chamber_sector  # noqa: E402
from post.seeds import resolved  # noqa: E402

requires("chamber_profiles", "numpy", "scipy")

import numpy as np
from scipy.spatial import cKDTree

RESOLVED = 3.0  # standard errors a jump must exceed to be told from the sampling's scatter
RATTLER = 2  # fewer contacts than this: a rattler, which carries no stress


def read_snapshot(path, step=None):
    """(step, columns, rows) of a dump custom file's snapshot of timestep STEP (default the last), rows
    a float array (one particle a row). Only the chosen snapshot's rows are converted."""
    with open(path) as f:
        lines = f.read().splitlines()
    heads, k = [], 0
    while k < len(lines):
        if lines[k].startswith("ITEM: TIMESTEP"):
            natoms = int(lines[k + 3])
            heads.append((int(lines[k + 1]), lines[k + 8].split()[2:], k + 9, natoms))
            k += 9 + natoms
        else:
            k += 1
    if not heads:
        raise SystemExit("chamber_profiles: %s holds no dump snapshot" % path)
    if step is None:
        head = heads[-1]
    else:
        found = [h for h in heads if h[0] == step]
        if not found:
            raise SystemExit("chamber_profiles: %s has no snapshot of timestep %d (it has %s)"
                             % (path, step, " ".join(str(h[0]) for h in heads)))
        head = found[-1]
    step, columns, first, natoms = head
    rows = np.array([lines[first + n].split() for n in range(natoms)], dtype=float).reshape(natoms, len(columns))
    return step, columns, rows


def particles_of(columns, rows, where, stress="c_stress", coord="c_coord", scale="f_grain_scale"):
    """{name: array} of a snapshot: x y z radius (required), stress (n x 3, or n x 4 with xy), coord
    and scale where the dump has them."""
    missing = [c for c in ("x", "y", "z", "radius") if c not in columns]
    if missing:
        raise SystemExit("chamber_profiles: %s has no column %s (columns: %s)" % (where, ", ".join(missing), " ".join(columns)))
    col = {c: rows[:, columns.index(c)] for c in columns}
    p = {c: col[c] for c in ("x", "y", "z", "radius")}
    names = ["%s[%d]" % (stress, m) for m in range(1, 5)]
    present = [n in columns for n in names[:3]]
    if any(present) and not all(present):
        raise SystemExit("chamber_profiles: %s has only some of %s (p needs all three)"
                         % (where, " ".join(names[:3])))
    if all(present):
        p["stress"] = np.column_stack([col[n] for n in names if n in columns])
    for key, name in (("coord", coord), ("scale", scale)):
        if name in columns:
            p[key] = col[name]
    return p


def window(p, Dc, dr, rmax, wall_x, wall_y, zmin, zmax, margin):
    """(edges, zmin, zmax): the annuli's edges (m) and the height window; walls and heights not given
    are the particles' extents (centre + radius), the window less margin D_c at each end; in the
    whole chamber the lo walls' distances from the axis bound the annuli too."""
    wall_x = np.max(p["x"] + p["radius"]) if wall_x is None else wall_x
    wall_y = np.max(p["y"] + p["radius"]) if wall_y is None else wall_y
    extent = min(wall_x, wall_y)
    if chamber_sector(p["x"], p["y"]) == 360.0:
        extent = min(extent, -np.min(p["x"] - p["radius"]), -np.min(p["y"] - p["radius"]))
    if rmax is None:
        rmax = extent
    elif rmax > extent * (1 + 1e-12):
        # beyond a wall, part of the annulus holds no sand: its porosity would be wrong
        raise SystemExit("chamber_profiles: --rmax %g m is beyond the chamber's extent min(wall_x, wall_y) = %g m" % (rmax, extent))
    zmin = np.min(p["z"] - p["radius"]) + margin * Dc if zmin is None else zmin
    zmax = np.max(p["z"] + p["radius"]) - margin * Dc if zmax is None else zmax
    if not zmax > zmin:
        raise SystemExit("chamber_profiles: the height window %g - %g m is empty (--zmin, --zmax, --margin)" % (zmin, zmax))
    # whole annuli only (a sliver at rmax would be noise), one short of rmax by a 1000th of its width
    # kept: the particles' extent falls short of the wall by the spheres' gaps
    n = int(math.floor(rmax / (dr * Dc) + 1e-3))
    if n < 1:
        raise SystemExit("chamber_profiles: --rmax %g m holds no annulus of --dr %g D_c" % (rmax, dr))
    return np.arange(n + 1) * dr * Dc, zmin, zmax


def annulus_points(rng, r1, r2, zmin, zmax, n, sector):
    """n points uniform in the volume of the annulus r1 <= r < r2, 0 <= theta < sector degrees."""
    r = np.sqrt(r1 * r1 + rng.random(n) * (r2 * r2 - r1 * r1))
    t = rng.random(n) * math.radians(sector)
    return np.column_stack([r * np.cos(t), r * np.sin(t), zmin + rng.random(n) * (zmax - zmin)])


def solid(points, tree, centres, radius, reach):
    """Whether each point lies inside a sphere: the centres within reach (the largest radius that can
    get there) from the tree, then the exact test of each."""
    near = tree.query_ball_point(points, reach)
    counts = np.fromiter(map(len, near), dtype=np.int64, count=len(near))
    flat = np.fromiter(itertools.chain.from_iterable(near), dtype=np.int64, count=int(counts.sum()))
    owner = np.repeat(np.arange(len(points)), counts)
    d2 = np.sum((points[owner] - centres[flat]) ** 2, axis=1)
    inside = np.zeros(len(points), dtype=bool)
    inside[owner[d2 < radius[flat] ** 2]] = True
    return inside


def cylindrical(stress, theta):
    """(sigma_rr, sigma_tt) parts of each row's (xx, yy, zz, xy) at its angle theta."""
    c, s = np.cos(theta), np.sin(theta)
    xx, yy, xy = stress[:, 0], stress[:, 1], stress[:, 3]
    return c * c * xx + s * s * yy + 2 * c * s * xy, s * s * xx + c * c * yy - 2 * c * s * xy


def mean_se(values):
    """(mean, standard error) of values; None where there are too few."""
    n = len(values)
    if n == 0:
        return None, None
    return float(np.mean(values)), (float(np.std(values, ddof=1) / math.sqrt(n)) if n > 1 else None)


def profiles(p, edges, zmin, zmax, points, seed):
    """One dict an annulus: r_lo, r_hi, particles, mean_N, mean_d, solid_fraction, porosity(_se),
    p, sigma_zz, sigma_rr, sigma_tt, coordination(_se), coordination_nr(_se) (None where the dump
    lacks the data or the annulus has no particle) and the coordinations of its particles (coord)."""
    centres = np.column_stack([p["x"], p["y"], p["z"]])
    radius = p["radius"]
    r = np.hypot(p["x"], p["y"])
    tree = cKDTree(centres)
    big = float(np.max(radius))
    rng = np.random.default_rng(seed)
    in_z = (p["z"] >= zmin) & (p["z"] < zmax)
    sector = chamber_sector(p["x"], p["y"])
    rows = []
    for r1, r2 in zip(edges[:-1], edges[1:]):
        row = {"r_lo": float(r1), "r_hi": float(r2)}
        # the largest sphere that can reach the annulus: fine zones need not search as far as coarse ones
        near = (r >= r1 - big) & (r < r2 + big) & (p["z"] >= zmin - big) & (p["z"] < zmax + big)
        pts = annulus_points(rng, r1, r2, zmin, zmax, points, sector)
        frac = float(np.mean(solid(pts, tree, centres, radius, float(np.max(radius[near]))))) if near.any() else 0.0
        row.update(solid_fraction=frac, porosity=1 - frac, porosity_se=math.sqrt(frac * (1 - frac) / points))
        sel = in_z & (r >= r1) & (r < r2)
        row["particles"] = int(sel.sum())
        row["mean_d"] = float(np.mean(2 * radius[sel])) if sel.any() else None
        row["mean_N"] = float(np.mean(p["scale"][sel])) if "scale" in p and sel.any() else None
        if "stress" in p:
            volume = math.radians(sector) / 2 * (r2 * r2 - r1 * r1) * (zmax - zmin)
            s = p["stress"][sel]
            # stress/atom is minus the virial (negative in compression): compression positive here
            row["p"] = -float(np.sum(s[:, :3])) / (3 * volume)
            row["sigma_zz"] = -float(np.sum(s[:, 2])) / volume
            if s.shape[1] > 3:
                rr, tt = cylindrical(s, np.arctan2(p["y"][sel], p["x"][sel]))
                row["sigma_rr"], row["sigma_tt"] = -float(np.sum(rr)) / volume, -float(np.sum(tt)) / volume
        if "coord" in p:
            row["coord"] = p["coord"][sel]
            row["coordination"], row["coordination_se"] = mean_se(row["coord"])
            row["coordination_nr"], row["coordination_nr_se"] = mean_se(row["coord"][row["coord"] >= RATTLER])
        rows.append(row)
    return rows


def sides(rows, R):
    """The two annuli just inside R (r_hi <= R) and the two just outside (r_lo >= R); None if either
    side has fewer than two."""
    tol = 1e-9 * R
    inside = [row for row in rows if row["r_hi"] <= R + tol][-2:]
    outside = [row for row in rows if row["r_lo"] >= R - tol][:2]
    return (inside, outside) if len(inside) == 2 and len(outside) == 2 else None


def side_values(pair, quantity):
    """(mean, standard error) of a quantity over two annuli, as the jump table takes it."""
    if quantity == "porosity":
        return (pair[0]["porosity"] + pair[1]["porosity"]) / 2, math.hypot(pair[0]["porosity_se"], pair[1]["porosity_se"]) / 2
    if quantity == "p":
        values = [row["p"] for row in pair]
        return float(np.mean(values)), abs(values[0] - values[1]) / 2  # std/sqrt(2) of two values
    values = np.concatenate([row["coord"] for row in pair])  # coordination: the particles' values
    if quantity == "coordination_nr":
        values = values[values >= RATTLER]
    mean, se = mean_se(values)
    return mean, se


def interface_jumps(rows, Dc, interfaces):
    """One dict an interface and quantity: interface (label), R_over_Dc, quantity, inside, inside_se,
    outside, outside_se, jump, jump_se, resolved; [] for an interface without two annuli each side."""
    quantities = ["porosity"] + (["p"] if "p" in rows[0] else []) + (["coordination", "coordination_nr"] if "coord" in rows[0] else [])
    jumps = []
    for label, R in interfaces:
        pairs = sides(rows, R * Dc)
        if pairs is None:
            print("chamber_profiles: %s = %g D_c has not two whole annuli on each side: no jump" % (label, R))
            continue
        for q in quantities:
            (a, a_se), (b, b_se) = side_values(pairs[0], q), side_values(pairs[1], q)
            if a is None or b is None:
                continue
            se = math.hypot(a_se, b_se) if a_se is not None and b_se is not None else None
            jumps.append({"interface": label, "R_over_Dc": R, "quantity": q, "inside": a, "inside_se": a_se,
                          "outside": b, "outside_se": b_se, "jump": b - a, "jump_se": se,
                          "resolved": se is not None and abs(b - a) > RESOLVED * se})
    return jumps


def fmt(value, spec="%.6g"):
    return "" if value is None else spec % value


# full precision but for the standard errors: the stresses are checked to round-off
COLUMNS = [("particles", "%d")] + [(c, "%.12g") for c in ("mean_N", "mean_d", "solid_fraction", "porosity")] + [
    ("porosity_se", "%.3g")] + [(c, "%.12g") for c in ("p", "sigma_zz", "sigma_rr", "sigma_tt")] + [
    ("coordination", "%.12g"), ("coordination_se", "%.3g"), ("coordination_nr", "%.12g"), ("coordination_nr_se", "%.3g")]


def present_columns(rows, p):
    """The CSV's columns that this dump gives (mean_N needs the scale column, p the stresses, ...)."""
    keys = set(rows[0]) - (set() if "scale" in p else {"mean_N"})
    return [(c, spec) for c, spec in COLUMNS if c in keys]


def write_csv(path, rows, columns, Dc):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["r_lo", "r_hi", "r_mid", "r_over_Dc"] + [c for c, _ in columns])
        for row in rows:
            mid = (row["r_lo"] + row["r_hi"]) / 2
            w.writerow(["%.12g" % row["r_lo"], "%.12g" % row["r_hi"], "%.12g" % mid, "%.12g" % (mid / Dc)]
                       + [fmt(row.get(c), spec) for c, spec in columns])


def write_jumps(path, jumps):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        keys = ["interface", "R_over_Dc", "quantity", "inside", "inside_se", "outside", "outside_se", "jump", "jump_se", "resolved"]
        w.writerow(keys)
        for j in jumps:
            w.writerow([j["interface"], "%g" % j["R_over_Dc"], j["quantity"]]
                       + [fmt(j[k], "%.6g" if k.endswith("_se") else "%.12g") for k in keys[3:9]] + [int(j["resolved"])])


def print_table(rows, Dc, interfaces, jumps):
    """The profiles (a line where an interface falls on an edge, a mark on an annulus it crosses) and
    the jumps."""
    head = "%-13s %7s %6s %9s %8s %7s %10s %10s %10s %6s %6s" % (
        "r/Dc", "n", "N", "d (m)", "porosity", "+-", "p (Pa)", "s_rr", "s_tt", "Z", "Z_nr")
    print(head)
    tol = 1e-9 * Dc
    for row in rows:
        for label, R in interfaces:
            if abs(R * Dc - row["r_lo"]) < tol:
                print("-" * 30 + " %s = %g D_c " % (label, R) + "-" * 30)
        marks = [label for label, R in interfaces if row["r_lo"] + tol < R * Dc < row["r_hi"] - tol]
        print("%-13s %7d %6s %9s %8.4f %7.4f %10s %10s %10s %6s %6s%s" % (
            "%.3g-%.3g" % (row["r_lo"] / Dc, row["r_hi"] / Dc), row["particles"], fmt(row.get("mean_N"), "%.4g"),
            fmt(row["mean_d"], "%.3g"), row["porosity"], row["porosity_se"], fmt(row.get("p"), "%.4g"),
            fmt(row.get("sigma_rr"), "%.4g"), fmt(row.get("sigma_tt"), "%.4g"), fmt(row.get("coordination"), "%.3f"),
            fmt(row.get("coordination_nr"), "%.3f"), "".join("  %s inside" % m for m in marks)))
    for j in jumps:
        print("jump at %s = %g D_c: %-15s %.5g +- %s (inside) -> %.5g +- %s (outside): %+.4g +- %s%s" % (
            j["interface"], j["R_over_Dc"], j["quantity"], j["inside"], fmt(j["inside_se"], "%.2g"), j["outside"],
            fmt(j["outside_se"], "%.2g"), j["jump"], fmt(j["jump_se"], "%.2g"),
            ", resolved" if j["resolved"] else ", not resolved"))


def plot(path, rows, Dc, interfaces):
    requires("chamber_profiles", "matplotlib")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    x = np.array([(row["r_lo"] + row["r_hi"]) / 2 / Dc for row in rows])
    panels = [("porosity", "porosity_se", "porosity")]
    if "p" in rows[0]:
        panels.append(("p", "p_se" if "p_se" in rows[0] else None, "p (Pa)"))
    if "coordination" in rows[0]:
        panels.append(("coordination", "coordination_se", "coordination"))
    fig, axes = plt.subplots(len(panels), 1, sharex=True, figsize=(6, 2.4 * len(panels)), squeeze=False)
    for ax, (key, se_key, label) in zip(axes[:, 0], panels):
        y = np.array([np.nan if row.get(key) is None else row[key] for row in rows])
        err = None if se_key is None else np.array([0.0 if row.get(se_key) is None else row[se_key] for row in rows])
        ax.errorbar(x, y, yerr=err, fmt="o-", ms=3, lw=1, capsize=2)
        if key == "coordination" and "coordination_nr" in rows[0]:
            ax.plot(x, [np.nan if row.get("coordination_nr") is None else row["coordination_nr"] for row in rows], "s--",
                    ms=3, lw=1, label="without rattlers")
            ax.legend(fontsize=8)
        for name, R in interfaces:
            ax.axvline(R, color="grey", ls=":", lw=1)
        ax.set_ylabel(label)
    for name, R in interfaces:
        axes[0, 0].annotate(name, (R, 1), xycoords=("data", "axes fraction"), ha="center", va="bottom", fontsize=8)
    axes[-1, 0].set_xlabel("r / D_c")
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def parse_interfaces(text):
    """[(label, R in D_c)] of 'R1,R2,...'."""
    if not text:
        return []
    try:
        values = [float(v) for v in text.split(",")]
    except ValueError:
        raise SystemExit("chamber_profiles: --interfaces takes radii in D_c, comma-separated (got %s)" % text)
    if any(not v > 0 for v in values):
        raise SystemExit("chamber_profiles: --interfaces must be > 0 (got %s)" % text)
    return [("R%d" % (k + 1), v) for k, v in enumerate(values)]


SEED_QUANTITIES = ("porosity", "p", "sigma_rr", "sigma_tt", "coordination", "coordination_nr", "mean_N")


def over_seeds(per_seed, interfaces, Dc):
    """Each chamber's profile (one per seed: their own samples) gathered: per annulus, the mean and the
    standard error over the chambers of each quantity; per interface, each chamber's jump (the mean
    of the two annuli outside less the two inside) and their mean and standard error, resolved where
    the 95% t interval (df = chambers - 1) excludes zero."""
    annuli = []
    for k in range(len(per_seed[0])):
        row = {"r_lo": per_seed[0][k]["r_lo"], "r_hi": per_seed[0][k]["r_hi"]}
        for q in SEED_QUANTITIES:
            values = [rows[k].get(q) for rows in per_seed]
            if all(v is not None for v in values):
                row[q], row[q + "_se"] = mean_se(values)
        annuli.append(row)
    jumps = []
    for label, R in interfaces:
        for q in SEED_QUANTITIES[:-1]:
            values = []
            for rows in per_seed:
                pairs = sides(rows, R * Dc)
                if pairs and all(row.get(q) is not None for row in pairs[0] + pairs[1]):
                    values.append(np.mean([row[q] for row in pairs[1]]) - np.mean([row[q] for row in pairs[0]]))
            if len(values) == len(per_seed) > 1:
                mean, se = mean_se(values)
                jumps.append({"interface": label, "R_over_Dc": R, "quantity": q, "jump": mean, "jump_se": se,
                              "seeds": len(values), "resolved": resolved(mean, se, len(values) - 1) == "yes"})
    return annuli, jumps


def write_seeds(prefix, annuli, jumps, Dc):
    with open(prefix + "_seeds.csv", "w", newline="") as f:
        w = csv.writer(f)
        names = [q for q in SEED_QUANTITIES if q in annuli[0]]
        w.writerow(["r_lo", "r_hi", "r_over_Dc"] + [c for q in names for c in (q, q + "_se")])
        for row in annuli:
            w.writerow(["%.12g" % row["r_lo"], "%.12g" % row["r_hi"], "%.12g" % ((row["r_lo"] + row["r_hi"]) / 2 / Dc)]
                       + [fmt(row.get(c), "%.12g") for q in names for c in (q, q + "_se")])
    with open(prefix + "_seed_jumps.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["interface", "R_over_Dc", "quantity", "seeds", "jump", "jump_se", "resolved"])
        for j in jumps:
            w.writerow([j["interface"], "%g" % j["R_over_Dc"], j["quantity"], j["seeds"], fmt(j["jump"], "%.12g"),
                        fmt(j["jump_se"], "%.12g"),
                        int(j["resolved"])])
    print("over %s chambers: the jumps across the interfaces (outside less inside, mean +- se over the chambers)"
          % (jumps[0]["seeds"] if jumps else "the"))
    for j in jumps:
        print("  %s = %g D_c: %-16s %+.4g +- %.3g, %s" % (j["interface"], j["R_over_Dc"], j["quantity"], j["jump"], j["jump_se"],
                                                        "resolved" if j["resolved"] else "not resolved"))


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dump", nargs="+", help="LIGGGHTS dump custom files with id x y z radius [c_stress[1..4]] [c_coord] "
                                            "[f_grain_scale]; several: one chamber each (seeds), gathered in OUT_seeds.csv")
    ap.add_argument("--snapshot", type=int, default=None, help="the timestep of the snapshot to read (default: the last)")
    ap.add_argument("--Dc", type=float, default=0.0357, help="the cone's diameter (m), the unit of --dr, --margin and --interfaces")
    ap.add_argument("--dr", type=float, default=0.5, help="annulus width (D_c)")
    ap.add_argument("--rmax", type=float, default=None, help="outer radius of the last annulus (m; default min(wall_x, wall_y))")
    ap.add_argument("--wall-x", type=float, default=None, help="the chamber's x wall (m; default the particles' largest x + radius)")
    ap.add_argument("--wall-y", type=float, default=None, help="the chamber's y wall (m; default the particles' largest y + radius)")
    ap.add_argument("--zmin", type=float, default=None, help="bottom of the height window (m; default the particles' lowest + margin)")
    ap.add_argument("--zmax", type=float, default=None, help="top of the height window (m; default the particles' highest - margin)")
    ap.add_argument("--margin", type=float, default=1.0, help="height left out at each end by default, off the walls (D_c)")
    ap.add_argument("--interfaces", default="", help="the zones' interfaces R1,R2,... (D_c), marked and jumped across")
    ap.add_argument("--points", type=int, default=20000, help="Monte Carlo points an annulus for the solid fraction")
    ap.add_argument("--seed", type=int, default=1, help="seed of the Monte Carlo points")
    ap.add_argument("--column", default="c_stress", help="the stress/atom columns, NAME[1] ... NAME[4] (xx yy zz xy)")
    ap.add_argument("--coord", default="c_coord", help="the contact/atom column (contacts of each particle)")
    ap.add_argument("--scale", default="f_grain_scale", help="the column of each particle's scale factor N")
    ap.add_argument("--out", default="profiles", help="prefix of OUT.csv, OUT_jumps.csv and OUT.png (OUT_<k>... for several dumps)")
    ap.add_argument("--plot", action="store_true", help="write OUT.png: porosity, p and coordination against r/D_c")
    a = ap.parse_args(argv)
    if not (a.Dc > 0 and a.dr > 0 and a.margin >= 0 and a.points > 0):
        raise SystemExit("chamber_profiles: --Dc, --dr and --points must be > 0 and --margin >= 0")
    interfaces = parse_interfaces(a.interfaces)
    chambers = []
    for path in a.dump:
        step, columns, data = read_snapshot(path, a.snapshot)
        p = particles_of(columns, data, path, a.column, a.coord, a.scale)
        if len(p["x"]) == 0:
            raise SystemExit("chamber_profiles: snapshot %d of %s has no particle" % (step, path))
        chambers.append((path, step, p))
    rmax = a.rmax
    if rmax is None and len(chambers) > 1:
        # one set of annuli for every chamber: within the narrowest
        rmax = min(min(np.max(p["x"] + p["radius"]), np.max(p["y"] + p["radius"])) for _, _, p in chambers)
    per_seed = []
    for k, (path, step, p) in enumerate(chambers):
        out = a.out if len(chambers) == 1 else "%s_%d" % (a.out, k + 1)
        edges, zmin, zmax = window(p, a.Dc, a.dr, rmax, a.wall_x, a.wall_y, a.zmin, a.zmax, a.margin)
        rows = profiles(p, edges, zmin, zmax, a.points, a.seed)
        jumps = interface_jumps(rows, a.Dc, interfaces)
        print("chamber_profiles: %s, step %d: %d particles, %d annuli of %g D_c to r = %g m, z %g - %g m"
              % (path, step, len(p["x"]), len(rows), a.dr, edges[-1], zmin, zmax))
        print_table(rows, a.Dc, interfaces, jumps)
        write_csv(out + ".csv", rows, present_columns(rows, p), a.Dc)
        write_jumps(out + "_jumps.csv", jumps)
        written = [out + ".csv", out + "_jumps.csv"]
        if a.plot:
            plot(out + ".png", rows, a.Dc, interfaces)
            written.append(out + ".png")
        print("chamber_profiles: wrote %s" % ", ".join(written))
        per_seed.append(rows)
    if len(per_seed) > 1:
        annuli, jumps = over_seeds(per_seed, interfaces, a.Dc)
        write_seeds(a.out, annuli, jumps, a.Dc)
        written = [a.out + "_seeds.csv", a.out + "_seed_jumps.csv"]
        if a.plot:
            # the mean over the chambers, with its standard error
            plot(a.out + "_seeds.png", annuli, a.Dc, interfaces)
            written.append(a.out + "_seeds.png")
        print("chamber_profiles: wrote %s" % ", ".join(written))


if __name__ == "__main__":
    main(sys.argv[1:])
