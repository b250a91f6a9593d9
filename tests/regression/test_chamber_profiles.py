#!/usr/bin/env python3
"""post/chamber_profiles.py on packings of known solid fraction, coordination and stress (the radial
profiles of the refined penetration chamber, examples/penetration, across its zones' interfaces).

  python3 test_chamber_profiles.py LIGGGHTS WORKDIR CASE    (--list: the cases; LIGGGHTS is not run)

Simple cubic lattices of spheres (spacing a, radius 0.999 a/2) fill a quarter chamber 4 D_c wide
from the axis: any region made of whole cells holds the solid fraction pi/6 0.999^3, and an annulus of
many cells nearly so (within 0.6 of the Monte Carlo's standard error, 20000 points, at these sizes).
Each case writes a dump custom file and runs the script's command line on it.
"""
import contextlib
import csv
import io
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(HERE)), "post"))
from liggghts_run import check, main  # noqa: E402

DC = 0.02  # the cone's diameter (m)
SHRINK = 0.999  # radius = SHRINK a/2: neighbours do not touch, so no sphere overlaps another
FRACTION = math.pi / 6 * SHRINK ** 3


def run_profiles(work, name, snapshots, options):
    """Writes snapshots [(step, columns, rows)] to WORK/NAME.dump (ids from 1) and runs
    chamber_profiles on it with options; returns (OUT.csv's rows as dicts of floats or None, the
    jumps' rows, the printed text). chamber_profiles (numpy, scipy) is imported here, so that --list
    needs neither."""
    import chamber_profiles
    dump = os.path.join(work, name + ".dump")
    with open(dump, "w") as f:
        for step, columns, rows in snapshots:
            f.write("ITEM: TIMESTEP\n%d\nITEM: NUMBER OF ATOMS\n%d\nITEM: BOX BOUNDS ff ff ff\n0 0.08\n0 0.08\n0 0.05\n"
                    "ITEM: ATOMS id %s\n" % (step, len(rows), " ".join(columns)))
            for n, row in enumerate(rows):
                f.write("%d %s\n" % (n + 1, " ".join("%.17g" % v for v in row)))
    out = os.path.join(work, name)
    text = io.StringIO()
    with contextlib.redirect_stdout(text):
        chamber_profiles.main([dump, "--Dc", str(DC), "--out", out] + options)
    print(text.getvalue(), end="")
    with open(out + ".csv") as f:
        rows = [{k: (float(v) if v != "" else None) for k, v in r.items()} for r in csv.DictReader(f)]
    with open(out + "_jumps.csv") as f:
        jumps = list(csv.DictReader(f))
    return rows, jumps, text.getvalue()


def sites(cells, layers, a):
    """(i, j, k) of a simple cubic lattice of cells x cells x layers, spacing a, from the origin, with
    the site's centre."""
    return [(i, j, k, ((i + 0.5) * a, (j + 0.5) * a, (k + 0.5) * a))
            for i in range(cells) for j in range(cells) for k in range(layers)]


def two_zones(cells, layers, a, R1):
    """A lattice of coarse cells (2a): one whose centre lies at R1 or beyond holds a sphere of radius
    0.999 a (N 34), any other eight of radius 0.999 a/2 (N 17) on the fine lattice. Space is filled
    as one lattice would, the coarse centres lie beyond R1 and the fine ones within R1 + a/sqrt(2).
    Returns (x, y, z, radius, N) rows."""
    rows = []
    for i, j, k, (x, y, z) in sites(cells // 2, layers // 2, 2 * a):
        if math.hypot(x, y) >= R1:
            rows.append((x, y, z, SHRINK * a, 34.0))
        else:
            rows += [(x + dx, y + dy, z + dz, SHRINK * a / 2, 17.0) for dx in (-a / 2, a / 2)
                     for dy in (-a / 2, a / 2) for dz in (-a / 2, a / 2)]
    return rows


def in_annulus(x, y, z, row, zmin, zmax):
    return row["r_lo"] <= math.hypot(x, y) < row["r_hi"] and zmin <= z < zmax


def check_fraction(rows, what):
    worst = max(abs(r["solid_fraction"] - FRACTION) / r["porosity_se"] for r in rows)
    check(worst < 3, "%s: the solid fraction of each of %d annuli is pi/6 0.999^3 = %.5f within %.2f Monte Carlo "
          "standard errors (< 3)" % (what, len(rows), FRACTION, worst))


def case_lattice(liggghts, work):
    """One lattice (a = D_c/12, 48 x 48 x 24 cells), annuli 1 D_c wide up to the walls (4 D_c), the
    height window 0.5 D_c off each end (--margin): the solid fraction is the lattice's in every
    annulus; the coordination column holds each site's neighbours (6 inside, 5 on a face, ...) but 0
    for one particle in 11 (rattlers): the annuli's mean coordination with and without the rattlers is
    that of the particles whose centres lie in them, and the counts and diameters are right. An
    interface on an annulus' edge (R1 = 2 D_c) is a line of the table, and the coordination's jump
    across it pools the particles of the annuli 0 - 2 D_c against those of 2 - 4 D_c."""
    a, cells, layers = DC / 12, 48, 24
    lattice = []
    for i, j, k, (x, y, z) in sites(cells, layers, a):
        contacts = sum(0 <= i + di < cells and 0 <= j + dj < cells and 0 <= k + dk < layers
                       for di, dj, dk in ((1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)))
        lattice.append((x, y, z, SHRINK * a / 2, 0.0 if (7 * i + 3 * j + k) % 11 == 0 else float(contacts)))
    rows, jumps, text = run_profiles(work, "lattice", [(100, ["x", "y", "z", "radius", "c_coord"], lattice)],
                                  ["--dr", "1", "--wall-x", str(cells * a), "--wall-y", str(cells * a), "--margin", "0.5",
                                   "--interfaces", "2"])
    check(len(rows) == 4 and abs(rows[-1]["r_hi"] - 4 * DC) < 1e-12, "4 annuli of 1 D_c up to the walls at 4 D_c")
    check("p" not in rows[0] and "mean_N" not in rows[0] and "coordination" in rows[0],
          "no stress nor N columns from a dump without them; coordination from c_coord")
    check_fraction(rows, "one lattice")
    zmin, zmax = 0.5 * DC, 1.5 * DC
    for row in rows:
        inside = [c for x, y, z, _, c in lattice if in_annulus(x, y, z, row, zmin, zmax)]
        held = [c for c in inside if c >= 2]
        check(row["particles"] == len(inside) and abs(row["mean_d"] - SHRINK * a) < 1e-12
              and abs(row["coordination"] - sum(inside) / len(inside)) < 1e-9
              and abs(row["coordination_nr"] - sum(held) / len(held)) < 1e-9 and 5 < row["coordination_nr"] < 6,
              "r %.2g - %.2g D_c: %d particles of d = 0.999 a, coordination %.4f, %.4f without the %d rattlers"
              % (row["r_lo"] / DC, row["r_hi"] / DC, len(inside), row["coordination"], row["coordination_nr"],
                 len(inside) - len(held)))
    check(("-- R1 = 2 D_c --" in text) and "inside" not in text.replace("(inside)", ""),
          "an interface on an annulus' edge (R1 = 2 D_c) is a line of the table, not a mark on a row")
    # the coordination's jump: the particles' values of the two annuli on each side, pooled
    for side, (lo, hi) in (("inside", (0, 2)), ("outside", (2, 4))):
        values = [c for x, y, z, _, c in lattice if lo * DC <= math.hypot(x, y) < hi * DC and zmin <= z < zmax]
        mean = sum(values) / len(values)
        se = math.sqrt(sum((v - mean) ** 2 for v in values) / (len(values) - 1) / len(values))
        j = [j for j in jumps if j["quantity"] == "coordination"][0]
        check(abs(float(j[side]) - mean) < 1e-9 and abs(float(j[side + "_se"]) / se - 1) < 1e-5,
              "coordination %s R1: %.4f +- %.2g over the %d particles of r %d - %d D_c" % (side, mean, se, len(values), lo, hi))
    check({j["quantity"] for j in jumps} == {"porosity", "coordination", "coordination_nr"},
          "jumps of porosity and coordination (no stress in the dump)")


def case_two_zones(liggghts, work):
    """Fine spheres (a = D_c/10, N 17) within R1 = 2.5 D_c and coarse ones beyond (spacing and radius
    doubled, N 34) to 5 D_c, annuli 1 D_c wide, the window z 6a - 18a (--zmin, --zmax: whole coarse layers):
    the same solid fraction on both sides; mean N 17 and diameter 0.999 a in every annulus inside R1,
    34 and 0.999 (2a) outside, between in the annulus that R1 crosses (marked on its row, and in
    neither side of the jump); the jump of porosity across R1 is not resolved; --plot writes the
    figure."""
    a, R1 = DC / 10, 2.5 * DC
    packing = two_zones(50, 24, a, R1)
    rows, jumps, text = run_profiles(work, "zones", [(100, ["x", "y", "z", "radius", "f_grain_scale"], packing)],
                                     ["--dr", "1", "--zmin", str(6 * a), "--zmax", str(18 * a),
                                      "--interfaces", "2.5", "--plot"])
    check(len(rows) == 5, "5 annuli of 1 D_c to 5 D_c")
    check_fraction(rows, "two zones")
    inner = [r for r in rows if r["r_hi"] <= R1]
    outer = [r for r in rows if r["r_lo"] >= R1]
    cross = [r for r in rows if r["r_lo"] < R1 < r["r_hi"]]
    check(len(inner) == 2 and all(r["mean_N"] == 17 and abs(r["mean_d"] - SHRINK * a) < 1e-12 for r in inner),
          "N 17 and d 0.999 a in the 2 annuli inside R1")
    check(len(outer) == 2 and all(r["mean_N"] == 34 and abs(r["mean_d"] - 2 * SHRINK * a) < 1e-12 for r in outer),
          "N 34 and d 0.999 (2a) in the 2 annuli outside R1")
    check(len(cross) == 1 and 17 < cross[0]["mean_N"] < 34,
          "N %.3g in the annulus R1 crosses" % cross[0]["mean_N"])
    check(any(line.startswith("2-3 ") and line.rstrip().endswith("R1 inside") for line in text.splitlines()),
          "the table marks the annulus 2 - 3 D_c as holding R1")
    jump = [j for j in jumps if j["quantity"] == "porosity"]
    check(len(jump) == 1 and jump[0]["interface"] == "R1" and jump[0]["resolved"] == "0"
          and abs(float(jump[0]["jump"])) < 3 * float(jump[0]["jump_se"]),
          "porosity's jump across R1, %s +- %s, is not resolved" % (jump[0]["jump"], jump[0]["jump_se"]))
    sides = [(inner, "inside"), (outer, "outside")]
    check(all(abs(float(jump[0][side]) - (pair[0]["porosity"] + pair[1]["porosity"]) / 2) < 1e-9
              and abs(float(jump[0][side + "_se"]) - math.hypot(pair[0]["porosity_se"], pair[1]["porosity_se"]) / 2) < 1e-5
              for pair, side in sides), "its sides are the annuli 0 - 2 and 3 - 5 D_c, with their Monte Carlo errors")
    png = os.path.join(work, "zones.png")
    check(os.path.exists(png) and os.path.getsize(png) > 1000, "--plot wrote zones.png")


def case_stress(liggghts, work):
    """The two zones' packing (particles of two volumes) with two stress snapshots: at step 100 every
    particle holds -p0 V_i delta (hydrostatic), at step 200 -s0 V_i e_r e_r (radial, in xx yy xy by
    its angle). Each annulus's stresses are the virial sum over the centres inside: p0 (or s0) times
    f_c = sum V_i / V_annulus; --snapshot 100 gives p = sigma_rr = sigma_tt = sigma_zz = p0 f_c, the
    last snapshot (default) sigma_rr = s0 f_c, p = s0 f_c / 3 and sigma_tt = sigma_zz = 0, to 1e-9."""
    a, p0, s0 = DC / 10, 2e5, 3e6
    packing = two_zones(40, 24, a, 2.25 * DC)
    columns = ["x", "y", "z", "radius"] + ["c_stress[%d]" % m for m in range(1, 7)]
    hydrostatic, radial = [], []
    for x, y, z, radius, _ in packing:
        v = 4 / 3 * math.pi * radius ** 3
        t = math.atan2(y, x)
        c, s = math.cos(t), math.sin(t)
        hydrostatic.append((x, y, z, radius, -p0 * v, -p0 * v, -p0 * v, 0, 0, 0))
        radial.append((x, y, z, radius, -s0 * v * c * c, -s0 * v * s * s, 0, -s0 * v * c * s, 0, 0))
    zmin, zmax = 6 * a, 18 * a
    options = ["--dr", "0.5", "--zmin", str(zmin), "--zmax", str(zmax), "--points", "2000"]
    snapshots = [(100, columns, hydrostatic), (200, columns, radial)]

    def fractions(rows):
        """sum V_i / V_annulus over the centres in each annulus."""
        return [sum(4 / 3 * math.pi * r ** 3 for x, y, z, r, _ in packing if in_annulus(x, y, z, row, zmin, zmax))
                / (math.pi / 4 * (row["r_hi"] ** 2 - row["r_lo"] ** 2) * (zmax - zmin)) for row in rows]

    rows, jumps, _ = run_profiles(work, "stress", snapshots, options + ["--snapshot", "100", "--interfaces", "2.25"])
    fc = fractions(rows)
    worst = max(abs(row[k] / (p0 * f) - 1) for row, f in zip(rows, fc) for k in ("p", "sigma_rr", "sigma_tt", "sigma_zz"))
    check(len(rows) == 8 and worst < 1e-9, "step 100: p = sigma_rr = sigma_tt = sigma_zz = p0 f_c (f_c %.4f - %.4f) "
          "in 8 annuli, to %.1e" % (min(fc), max(fc), worst))
    # p's jump across 2.25 D_c: the annuli 1 - 2 D_c against 2.5 - 3.5, each side's error the spread of its two
    j = [j for j in jumps if j["quantity"] == "p"][0]
    pairs = {"inside": (p0 * fc[2], p0 * fc[3]), "outside": (p0 * fc[5], p0 * fc[6])}
    check(all(abs(float(j[side]) / ((a + b) / 2) - 1) < 1e-9 and abs(float(j[side + "_se"]) / (abs(a - b) / 2) - 1) < 1e-5
              for side, (a, b) in pairs.items()),
          "p's jump across 2.25 D_c: %s +- %s (the annuli 1 - 2 D_c) to %s +- %s (2.5 - 3.5 D_c)"
          % (j["inside"], j["inside_se"], j["outside"], j["outside_se"]))
    rows, _, _ = run_profiles(work, "stress", snapshots, options)
    worst = max(max(abs(row["sigma_rr"] / (s0 * f) - 1), abs(row["p"] / (s0 * f / 3) - 1)) for row, f in zip(rows, fc))
    zero = max(max(abs(row["sigma_tt"]), abs(row["sigma_zz"])) / s0 for row in rows)
    check(worst < 1e-9 and zero < 1e-9, "the last snapshot (200): sigma_rr = s0 f_c and p = s0 f_c / 3 to %.1e, "
          "sigma_tt and sigma_zz zero to %.1e s0" % (worst, zero))


def case_seeds(liggghts, work):
    """Three chambers (seeds) of the two zones' packing, hydrostatic at p0, 2 p0 and 3 p0 inside 2.25 D_c
    and at 2 p0 beyond: per annulus p's mean over the chambers is 2 p0 f_c on both sides, with standard
    error p0 f_c / sqrt(3) inside and 0 beyond; the jump of p across 2.25 D_c (the two annuli outside
    less the two inside, each chamber's) is 2 p0 (f_out - f_in) on average, with the spread of the
    inner side over the chambers, p0 f_in / sqrt(3), as its standard error."""
    del liggghts
    import chamber_profiles
    a, p0, R1 = DC / 10, 2e5, 2.25 * DC
    packing = two_zones(40, 24, a, R1)
    columns = ["x", "y", "z", "radius", "c_stress[1]", "c_stress[2]", "c_stress[3]", "c_stress[4]"]
    dumps = []
    for k, inner in enumerate((1, 2, 3)):
        rows = []
        for x, y, z, radius, _ in packing:
            v = 4 / 3 * math.pi * radius ** 3 * (inner if math.hypot(x, y) < R1 else 2)
            rows.append((x, y, z, radius, -p0 * v, -p0 * v, -p0 * v, 0))
        dumps.append(os.path.join(work, "chamber_%d.dump" % (k + 1)))
        with open(dumps[-1], "w") as f:
            f.write("ITEM: TIMESTEP\n100\nITEM: NUMBER OF ATOMS\n%d\nITEM: BOX BOUNDS ff ff ff\n0 0.08\n0 0.08\n0 0.05\n"
                    "ITEM: ATOMS id %s\n" % (len(rows), " ".join(columns)))
            for n, row in enumerate(rows):
                f.write("%d %s\n" % (n + 1, " ".join("%.17g" % value for value in row)))
    out = os.path.join(work, "seeds")
    text = io.StringIO()
    zmin, zmax = 6 * a, 18 * a
    with contextlib.redirect_stdout(text):
        chamber_profiles.main(dumps + ["--Dc", str(DC), "--out", out, "--dr", "0.5", "--zmin", str(zmin), "--zmax",
                                       str(zmax), "--points", "500", "--interfaces", "2.25"])
    with open(out + "_seeds.csv") as f:
        annuli = [{k: float(v) for k, v in r.items() if v != ""} for r in csv.DictReader(f)]
    fc = [sum(4 / 3 * math.pi * r ** 3 for x, y, z, r, _ in packing if in_annulus(x, y, z, row, zmin, zmax))
          / (math.pi / 4 * (row["r_hi"] ** 2 - row["r_lo"] ** 2) * (zmax - zmin)) for row in annuli]
    inside = [row["r_hi"] <= R1 for row in annuli]
    worst = max(abs(row["p"] / (2 * p0 * f) - 1) for row, f in zip(annuli, fc))
    spread = max(abs(row["p_se"] - (p0 * f / math.sqrt(3) if inner else 0.0)) / (p0 * f)
                 for row, f, inner in zip(annuli, fc, inside) if inner or row["r_lo"] >= R1)
    check(len(annuli) == 8 and worst < 1e-9 and spread < 1e-9,
          "p over 3 chambers: 2 p0 f_c in each of 8 annuli (to %.1e), se p0 f_c / sqrt(3) inside and 0 beyond (to %.1e)"
          % (worst, spread))
    with open(out + "_seed_jumps.csv") as f:
        jump = [r for r in csv.DictReader(f) if r["quantity"] == "p"][0]
    f_in, f_out = (fc[2] + fc[3]) / 2, (fc[5] + fc[6]) / 2
    mean, se = 2 * p0 * (f_out - f_in), p0 * f_in / math.sqrt(3)
    check(abs(float(jump["jump"]) - mean) < 1e-9 * p0 and abs(float(jump["jump_se"]) / se - 1) < 1e-9
          and jump["seeds"] == "3" and jump["resolved"] == str(int(abs(mean) > 2 * se)),
          "p's jump across 2.25 D_c over 3 chambers: %s +- %s = 2 p0 (f_out - f_in) +- p0 f_in / sqrt(3)"
          % (jump["jump"], jump["jump_se"]))


def case_whole(liggghts, work):
    """The whole chamber (in.geometry's sector 360): the two zones' packing mirrored into the four
    quadrants about the axis, every particle holding -p0 V_i delta. The script tells the whole
    chamber by the sand on both sides of the axis; its annuli are whole, so each annulus's solid
    fraction is the lattice's and p = sigma_rr = sigma_tt = p0 f_c, as in the quarter (a quarter
    annulus's volume would read four times the stress), with four times the quarter's particles."""
    a, p0 = DC / 10, 2e5
    quarter = two_zones(40, 24, a, 2.25 * DC)
    columns = ["x", "y", "z", "radius"] + ["c_stress[%d]" % m for m in range(1, 5)]
    stress = lambda r: [-p0 * 4 / 3 * math.pi * r ** 3] * 3 + [0]  # noqa: E731
    whole = [(sx * x, sy * y, z, r) + tuple(stress(r)) for x, y, z, r, _ in quarter for sx in (1, -1) for sy in (1, -1)]
    zmin, zmax = 6 * a, 18 * a
    options = ["--dr", "0.5", "--zmin", str(zmin), "--zmax", str(zmax)]
    rows, _, _ = run_profiles(work, "quarter", [(100, columns, [(x, y, z, r) + tuple(stress(r)) for x, y, z, r, _ in quarter])], options)
    whole_rows, _, _ = run_profiles(work, "whole", [(100, columns, whole)], options)
    check(len(whole_rows) == len(rows) == 8, "8 annuli of 0.5 D_c to 4 D_c in both chambers")
    check_fraction(whole_rows, "the whole chamber")
    worst = max(abs(w[k] / q[k] - 1) for w, q in zip(whole_rows, rows) for k in ("p", "sigma_rr", "sigma_tt", "sigma_zz"))
    check(worst < 1e-9 and all(w["particles"] == 4 * q["particles"] for w, q in zip(whole_rows, rows)),
          "p, sigma_rr, sigma_tt and sigma_zz of each whole annulus are the quarter's to %.1e (p %.4g - %.4g kPa), "
          "with 4 times its particles" % (worst, min(w["p"] for w in whole_rows) / 1e3, max(w["p"] for w in whole_rows) / 1e3))


def case_missing_column(liggghts, work):
    """A dump without the radius column stops with a message that names it; so does a --snapshot
    that the dump does not hold, naming the ones it does."""
    points = [(0.001 * n, 0.002, 0.003, 4.0) for n in range(1, 5)]
    try:
        run_profiles(work, "no_radius", [(100, ["x", "y", "z", "c_coord"], points)], [])
        check(False, "a dump without radius is refused")
    except SystemExit as e:
        check("no column radius" in str(e), "a dump without radius is refused: %s" % e)
    try:
        run_profiles(work, "one_step", [(100, ["x", "y", "z", "radius"], points)], ["--snapshot", "7"])
        check(False, "a missing snapshot is refused")
    except SystemExit as e:
        check("no snapshot of timestep 7 (it has 100)" in str(e), "a missing snapshot is refused: %s" % e)


if __name__ == "__main__":
    main(globals(), sys.argv[1:])
