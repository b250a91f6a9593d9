#!/usr/bin/env python3
"""post/ring_stress.py on analytic stress states (the stress maps of penetration and pile scenes).

  python3 test_ring_stress.py LIGGGHTS WORKDIR CASE    (--list: the cases)

A quarter cylinder (sector 90 degrees, radius R, height H) is filled with a fine grid of points,
each carrying the stress/atom of its cell (pressure x volume, LIGGGHTS' sign) for a known state;
the ring averages must give that state in the cylindrical frame, everywhere the grid fills the ring.
"""
import csv
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(HERE)), "post"))
from liggghts_run import check, main  # noqa: E402
import ring_stress  # noqa: E402

R, H, CELLS, LAYERS = 1.0, 0.2, 90, 6
DR, DZ = 0.1, 0.1


def quarter_grid(tensor):
    """(x, y, z, s) at the cell centres of the quarter cylinder, s = -cell volume x tensor(theta)."""
    h = R / CELLS
    volume = h * h * (H / LAYERS)
    points = []
    for a in range(CELLS):
        for b in range(CELLS):
            x, y = (a + 0.5) * h, (b + 0.5) * h
            if math.hypot(x, y) >= R:
                continue
            s = tuple(-volume * v for v in tensor(math.atan2(y, x)))
            for k in range(LAYERS):
                points.append((x, y, (k + 0.5) * H / LAYERS, s))
    return points


def inner_rings(rings):
    """The rings that the grid fills (not the outermost, cut by the cylinder)."""
    return {key: v for key, v in rings.items() if (key[0] + 1) * DR <= R - DR}


def case_hydrostatic(liggghts, work):
    """p in every direction: every ring gives sigma_rr = sigma_tt = sigma_zz = p (to the grid's 2%),
    no shear, with the sector's volume (90 degrees)."""
    p = 1e5
    rings = inner_rings(ring_stress.ring_stresses(quarter_grid(lambda t: (p, p, p, 0, 0, 0)), DR, DZ, sector=90))
    worst = max(abs(v[m] / p - 1) for v in rings.values() for m in (1, 2, 3))
    check(len(rings) == 9 * 2 and worst < 0.02, "%d rings give p to %.2g%% in rr, tt and zz" % (len(rings), 100 * worst))
    check(max(abs(v[4]) for v in rings.values()) < 1e-9 * p, "no r-z shear")


def case_radial(liggghts, work):
    """A radial stress q e_r e_r given in Cartesian components: sigma_rr = q (2%), sigma_tt and
    sigma_zz zero to round-off (a wrong sign of the xy term gives q cos^2(2 theta) instead)."""
    q = 3e6
    tensor = lambda t: (q * math.cos(t) ** 2, q * math.sin(t) ** 2, 0, q * math.cos(t) * math.sin(t), 0, 0)  # noqa: E731
    rings = inner_rings(ring_stress.ring_stresses(quarter_grid(tensor), DR, DZ, sector=90))
    check(max(abs(v[1] / q - 1) for v in rings.values()) < 0.02, "sigma_rr = q in every ring")
    check(max(max(abs(v[2]), abs(v[3])) for v in rings.values()) < 1e-9 * q, "sigma_tt = sigma_zz = 0")


def case_uniaxial_cli(liggghts, work):
    """sigma_xx = q alone, through the command line on a dump file: over a quarter ring sigma_rr and
    sigma_tt average q/2 each (cos^2 and sin^2 over 0 - 90 degrees), sigma_zz 0; a missing column
    stops with its name."""
    q = 2e6
    points = quarter_grid(lambda t: (q, 0, 0, 0, 0, 0))
    dump = os.path.join(work, "stress.dump")
    with open(dump, "w") as f:
        f.write("ITEM: TIMESTEP\n100\nITEM: NUMBER OF ATOMS\n%d\nITEM: BOX BOUNDS ff ff ff\n0 1\n0 1\n0 0.2\n"
                "ITEM: ATOMS id x y z c_s[1] c_s[2] c_s[3] c_s[4] c_s[5] c_s[6]\n" % len(points))
        for n, (x, y, z, s) in enumerate(points):
            f.write("%d %.17g %.17g %.17g %s\n" % (n + 1, x, y, z, " ".join("%.17g" % v for v in s)))
    out = os.path.join(work, "rings.csv")
    ring_stress.main([dump, "--dr", str(DR), "--dz", str(DZ), "--sector", "90", "--column", "c_s", "--out", out])
    rows = [r for r in csv.DictReader(open(out)) if float(r["r_mid"]) + DR / 2 <= R - DR + 1e-12]
    check(len(rows) == 18 and all(abs(float(r[c]) / (q / 2) - 1) < 0.03 for r in rows for c in ("sigma_rr", "sigma_tt"))
          and all(abs(float(r["sigma_zz"])) < 1e-9 * q for r in rows),
          "%d rings read back: sigma_rr = sigma_tt = q/2 (3%%), sigma_zz = 0" % len(rows))
    try:
        ring_stress.main([dump, "--dr", "0.1", "--dz", "0.1", "--out", out])
        check(False, "a dump without c_stress columns is refused")
    except SystemExit as e:
        check("no column c_stress[1]" in str(e), "a dump without c_stress columns is refused naming the column")


def case_pile_shaft_profile(liggghts, work):
    """post/pile_stress.py on a known field that moves with the tip: a pile of D = 0.4 (R = 0.2),
    two snapshots with the tip at z = 0.3 and 0.2 (steps 100 and 200 of the history), and in both
    sigma_rr = q (1 + h / R) at the height h = z - z_tip above the tip (any radius), sigma_tt =
    q / 2, sigma_zz = 2 q. Averaged in the tip's frame, the shaft's ring (r 0.2 - 0.3) gives
    sigma_r' = q (1 + h / R) at each ring's mid-height h (the field is linear in h), within the
    grid's 3%, the ring at h/R 1.75, which the first snapshot's field does not reach, too; a field
    read in the box's frame instead would smear it by the tip's travel. With the history's surface
    at 0.55 instead of the field's top (0.6), the rings that reach above it are left out: h/R 1.75
    in both snapshots, 1.25 in the first (a ring half in the sand would read its stress low)."""
    q, Dc, cells, dz = 1e5, 0.4, 60, 0.02
    tips, surface = {100: 0.3, 200: 0.2}, 0.6
    cell = R / cells
    dump = os.path.join(work, "stress_pile_N1.liggghts")
    with open(dump, "w") as f:
        for step, tip in sorted(tips.items()):
            points = []
            for k in range(30):
                z = (k + 0.5) * dz
                h = z - tip
                for a in range(cells):
                    for b in range(cells):
                        x, y = (a + 0.5) * cell, (b + 0.5) * cell
                        if math.hypot(x, y) >= R:
                            continue
                        t = math.atan2(y, x)
                        rr, tt, zz = q * (1 + h / (Dc / 2)), q / 2, 2 * q
                        c, n = math.cos(t), math.sin(t)
                        tensor = (c * c * rr + n * n * tt, n * n * rr + c * c * tt, zz, c * n * (rr - tt), 0, 0)
                        points.append((x, y, z, tuple(-cell * cell * dz * v for v in tensor)))
            f.write("ITEM: TIMESTEP\n%d\nITEM: NUMBER OF ATOMS\n%d\nITEM: BOX BOUNDS ff ff ff\n0 1\n0 1\n0 0.6\n"
                    "ITEM: ATOMS id x y z radius c_stress[1] c_stress[2] c_stress[3] c_stress[4] c_stress[5] c_stress[6]\n"
                    % (step, len(points)))
            for m, (x, y, z, s) in enumerate(points):
                f.write("%d %.12g %.12g %.12g 0.001 %s\n" % (m + 1, x, y, z, " ".join("%.12g" % v for v in s)))
    import pile_stress  # noqa: E402

    def shaft(top):
        """pile_stress's shaft profile with the history's sand surface at top."""
        with open(os.path.join(work, "penetration_pile_N1.csv"), "w") as f:
            f.write("step,tip_z,depth\n")
            for step, tip in sorted(tips.items()):
                f.write("%d,%g,%g\n" % (step, tip, top - tip))
        pile_stress.main(["--label", "pile", "--N", "1", "--Dc", str(Dc), "--dir", work, "--from", "0", "--dr", "0.25",
                          "--dh", "0.25"])
        return list(csv.DictReader(open(os.path.join(work, "pile_shaft.csv"))))

    # h/R 0.25 - 1.25 from both snapshots; 1.75 from the second alone (the field ends at z = 0.6):
    # a ring is averaged over the snapshots that hold it
    full = shaft(surface)
    worst = max(abs(float(r["sigma_r"]) / (q * (1 + float(r["h_over_R"]))) - 1) for r in full)
    check(len(full) == 4 and worst < 0.03 and all(abs(float(r["sigma_theta"]) / (q / 2) - 1) < 0.03 for r in full),
          "sigma_r' = q (1 + h/R) on the shaft at h/R = %s, to %.2g%%; sigma_theta = q/2"
          % (", ".join(r["h_over_R"] for r in full), 100 * worst))
    rows = shaft(0.55)
    worst = max(abs(float(r["sigma_r"]) / (q * (1 + float(r["h_over_R"]))) - 1) for r in rows)
    check([r["h_over_R"] for r in rows] == ["0.25", "0.75", "1.25"] and worst < 0.03,
          "with the surface at 0.55 the rings reaching above it are left out: h/R %s, to %.2g%%"
          % (", ".join(r["h_over_R"] for r in rows), 100 * worst))


if __name__ == "__main__":
    main(globals(), sys.argv[1:])
