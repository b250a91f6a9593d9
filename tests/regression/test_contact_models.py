#!/usr/bin/env python3
"""Deck tests of the hertz/scaled + mindlin/scaled contact models and fix damp/local, run by the built
liggghts. Each case asserts a value that would be wrong if the physics were wrong.

  python3 test_contact_models.py LIGGGHTS WORKDIR CASE
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liggghts_run import check, edited_deck, printed, read_dump, read_thermo, run_deck  # noqa: E402
from liggghts_run import main as test_main  # noqa: E402

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "contact")
G, NU = 3e9, 0.3                                    # in.materials: E = 7.8e9, nu = 0.3
C_NORMAL = 2 * math.sqrt(2) * G / (3 * (1 - NU))   # eq. 8: k_N = C_NORMAL sqrt(Dt U)
C_SHEAR = 2 * math.sqrt(2) * G / (2 - NU)          # eq. 9 with |F| = k_N U: k_S = C_SHEAR sqrt(Dt U)


def deck(name):
    return os.path.join(HERE, name)


def normal_forces(liggghts, work, model, tmodel):
    out = os.path.join(work, "normal.dump")
    run_deck(liggghts, deck("in.normal"), work, {"model": model, "tmodel": tmodel, "out": "normal.dump"})
    result = []
    for step, _, rows in read_dump(out):
        a, b = rows
        gap = math.dist((a["x"], a["y"], a["z"]), (b["x"], b["y"], b["z"]))
        result.append((step, a["radius"] + b["radius"] - gap, a["radius"], b["radius"], -a["fx"]))
    return result


def case_normal_hertz(liggghts, work):
    """Two spheres, pure normal loading: F = k_N U of eq. 8 to 1e-10."""
    worst, n = 0.0, 0
    for step, U, r1, r2, F in normal_forces(liggghts, work, "hertz/scaled", "mindlin/scaled"):
        if U <= 0:
            check(F == 0.0, "no force before contact (step %d)" % step)
            continue
        Dt = 2 * r1 * r2 / (r1 + r2)
        expected = C_NORMAL * math.sqrt(Dt * U) * U
        worst = max(worst, abs(F - expected) / expected)
        n += 1
    check(n >= 10, "%d loaded snapshots" % n)
    check(worst < 1e-10, "normal force matches eq. 8 (worst relative error %.2e)" % worst)


def case_normal_vs_builtin(liggghts, work):
    """Equal materials, no damping: hertz/scaled gives LIGGGHTS' built-in hertz forces."""
    scaled = normal_forces(liggghts, os.path.join(work, "scaled"), "hertz/scaled", "mindlin/scaled")
    builtin = normal_forces(liggghts, os.path.join(work, "builtin"), "hertz", "no_history")
    worst = max(abs(a[4] - b[4]) / max(abs(b[4]), 1e-300) for a, b in zip(scaled, builtin) if b[4] > 0)
    check(len(scaled) == len(builtin), "same snapshots")
    check(worst < 1e-12, "hertz/scaled equals built-in hertz (worst relative difference %.2e)" % worst)


def assembly_contacts(liggghts, work, model, tmodel, mu):
    """Normal force magnitude per contact (keyed by the two tags) after 300 steps."""
    run_deck(liggghts, deck("in.assembly"), work, {"model": model, "tmodel": tmodel, "mu": mu,
                                                   "out": "final.dump", "contacts": "contacts.dump"})
    rows = read_dump(os.path.join(work, "contacts.dump"))[-1][2]
    keys = sorted(rows[0].keys())
    return {(int(r[keys[0]]), int(r[keys[1]])):
            math.sqrt(r[keys[3]] ** 2 + r[keys[4]] ** 2 + r[keys[5]] ** 2) for r in rows}


def normal_force_difference(a, b):
    """Largest per-contact difference of normal force magnitudes, relative to the mean one."""
    check(set(a) == set(b), "the same %d contacts in both runs" % len(a))
    mean = sum(b.values()) / len(b)
    return max(abs(a[k] - b[k]) for k in b) / mean


def case_assembly_vs_builtin(liggghts, work):
    """864 dense spheres, 300 steps, against hertz + tangential history. Frictionless, the normal
    forces agree to rounding. With friction the trajectories differ through the tangential laws:
    mindlin/scaled adds k_t du each step (PFC), history multiplies the total displacement by the
    current k_t; they differ by (k_t(now) - k_t(then)) du, small when the overlaps change little."""
    frictionless = normal_force_difference(
        assembly_contacts(liggghts, os.path.join(work, "s0"), "hertz/scaled", "mindlin/scaled", 0.0),
        assembly_contacts(liggghts, os.path.join(work, "b0"), "hertz", "history", 0.0))
    check(frictionless < 1e-10, "frictionless: normal forces equal the built-in model's "
                                "(largest difference %.2e of the mean)" % frictionless)
    friction = normal_force_difference(
        assembly_contacts(liggghts, os.path.join(work, "s1"), "hertz/scaled", "mindlin/scaled", 0.5),
        assembly_contacts(liggghts, os.path.join(work, "b1"), "hertz", "history", 0.5))
    # The assembly relaxes: normal forces drop by about a third in 300 steps, k_t by a sixth, so the
    # two shear laws part by a few percent of the shear force and the trajectories follow.
    check(friction < 0.05, "mu = 0.5: normal forces differ by %.2e of the mean (below 5e-2)" % friction)
    check(friction > frictionless, "and the difference comes from the tangential law")


def case_oblique(liggghts, work):
    """Sphere dragged on a plane: slope k_S of eq. 9 (wall convention Dt = D), then Coulomb sliding."""
    run_deck(liggghts, deck("in.oblique"), work, {"out": "oblique.dump"})
    snaps = read_dump(os.path.join(work, "oblique.dump"))
    r = snaps[0][2][0]["radius"]
    U = r - snaps[0][2][0]["z"]
    Dt = 2 * r
    Fn_expected = C_NORMAL * math.sqrt(Dt * U) * U
    k_s = C_SHEAR * math.sqrt(Dt * U)
    v, dt, mu = 0.001, 1e-8, 0.3
    elastic, sliding = [], []
    for step, _, rows in snaps:
        a = rows[0]
        check_fn = abs(a["fz"] - Fn_expected) / Fn_expected
        if check_fn > 1e-10:
            raise AssertionError("normal wall force %.6g at step %d, expected %.6g" % (a["fz"], step, Fn_expected))
        if abs(a["fx"]) < 0.99 * mu * a["fz"]:
            elastic.append((step, a["fx"], a["fz"]))
        elif abs(a["fx"]) > (1 - 1e-6) * mu * a["fz"]:
            sliding.append((step, a["fx"], a["fz"]))
    check(len(elastic) > 5 and len(sliding) > 5, "both regimes sampled (%d elastic, %d sliding)"
          % (len(elastic), len(sliding)))
    (s0, f0, _), (s1, f1, _) = elastic[1], elastic[-1]
    slope = (f1 - f0) / ((s1 - s0) * v * dt)
    check(abs(-slope - k_s) / k_s < 1e-9, "shear stiffness k_S = %.6g N/m (eq. 9: %.6g)" % (-slope, k_s))
    worst = max(abs(abs(fx) - mu * fz) / (mu * fz) for _, fx, fz in sliding)
    check(worst < 1e-12, "sliding at mu |F_n| (worst relative error %.2e)" % worst)


def tangential_in_rotation(liggghts, work, tmodel):
    run_deck(liggghts, deck("in.rotate"), work, {"tmodel": tmodel, "out": "rotate.dump"})
    history = []
    for step, _, rows in read_dump(os.path.join(work, "rotate.dump")):
        a, b = rows
        n = [b[k] - a[k] for k in "xyz"]
        nn = math.sqrt(sum(c * c for c in n))
        n = [c / nn for c in n]
        f = [b["f" + k] for k in "xyz"]
        fn = sum(fc * nc for fc, nc in zip(f, n))
        ft = [fc - fn * nc for fc, nc in zip(f, n)]
        # tangent direction of the rotation: e_z x n
        t = (-n[1], n[0], 0.0)
        history.append((step, math.sqrt(sum(c * c for c in ft)), sum(fc * tc for fc, tc in zip(ft, t)), n))
    return history


def case_rotating_contact(liggghts, work):
    """The stored shear force turns with the contact plane when the pair turns rigidly by 90 deg."""
    hist = tangential_in_rotation(liggghts, os.path.join(work, "scaled"), "mindlin/scaled")
    m0 = hist[0][1]
    check(m0 > 0, "a shear force was stored before turning (%.4g N)" % m0)
    drift = max(abs(h[1] - m0) / m0 for h in hist)
    check(drift < 1e-9, "its magnitude is kept while turning (largest change %.2e)" % drift)
    aligned = min(abs(h[2]) / h[1] for h in hist)
    check(aligned > 1 - 1e-9, "it stays along the turning tangent e_z x n (alignment %.12f)" % aligned)
    check(abs(hist[-1][3][1]) > 0.999999, "the contact normal turned by 90 degrees")
    builtin = tangential_in_rotation(liggghts, os.path.join(work, "history"), "history")
    loss = (builtin[0][1] - builtin[-1][1]) / builtin[0][1]
    print("note: LIGGGHTS' tangential history (projection only) loses %.2e of the shear force in "
          "the same rotation" % loss)


def rolling_torques(liggghts, work, rmodel, mu_r):
    """(step, torque on sphere 1, torque on sphere 2, normal force, shear force) of contact/in.rolling."""
    out = run_deck(liggghts, deck("in.rolling"), work, {"rmodel": rmodel, "mu_r": mu_r, "out": "rolling.dump"})
    check("not located in any whitelist" not in out, "%s: a compiled combination (no 'unoptimized' warning)" % rmodel)
    return [(step, [a["tqx"], a["tqy"], a["tqz"]], [b["tqx"], b["tqy"], b["tqz"]], -a["fx"],
             math.hypot(a["fy"], a["fz"])) for step, _, (a, b) in read_dump(os.path.join(work, "rolling.dump"))]


def case_rolling_resistance(liggghts, work):
    """LIGGGHTS' rolling_friction with hertz/scaled + mindlin/scaled (compiled as its own instance by
    pair_hertz_scaled/style_contact_model_user.whitelist, not LIGGGHTS' slower generic path): a
    frictionless pair, sphere 1 rolling at 100 rad/s about y and twisting at 30 rad/s about the contact
    normal x. With coefficient 0 (the Fontainebleau decks' preparation) no torque at all. epsd2: an
    elastic rolling spring k_S R_eff^2 (k_S of eq. 9) on the rolling part only, capped at
    mu_r R_eff F_n; cdt: mu_r R_eff F_n at once along the relative spin, its torsion part then removed.
    The two spheres get opposite torques that resist the rolling."""
    r1, r2, U, mu_r, w_roll, w_twist, dt, start = 1e-4, 1.5e-4, 1e-6, 0.1, 100.0, 30.0, 1e-8, 500
    Dt = 2 * r1 * r2 / (r1 + r2)
    r_eff = r1 * r2 / (r1 + r2)
    Fn = C_NORMAL * math.sqrt(Dt * U) * U
    cap = mu_r * r_eff * Fn
    increment = C_SHEAR * math.sqrt(Dt * U) * r_eff ** 2 * w_roll * dt   # epsd2's spring, per step
    for rmodel in ("epsd2", "cdt"):
        snaps = rolling_torques(liggghts, os.path.join(work, rmodel), rmodel, mu_r)
        worst = max(abs(s[3] - Fn) / Fn for s in snaps)
        check(worst < 1e-10 and all(s[4] == 0.0 for s in snaps),
              "%s: F_n = %.6g N of eq. 8 (worst relative %.1e), no shear force" % (rmodel, Fn, worst))
        check(all(s[1] == s[2] == [0.0, 0.0, 0.0] for s in snaps if s[0] <= start),
              "%s: coefficient 0 for the first %d steps: no torque" % (rmodel, start))
        late = [s for s in snaps if s[0] > start]
        check(all(s[1][0] == s[1][2] == 0.0 and s[1][1] < 0.0 and s[2][1] == -s[1][1] for s in late),
              "%s: the torque on sphere 1 is along -y, against the rolling, none about the normal; sphere 2 "
              "gets the opposite" % rmodel)
        if rmodel == "epsd2":
            n_cap = cap / increment
            spring = [s for s in late if s[0] - start < 0.9 * n_cap]
            worst = max(abs(-s[1][1] / ((s[0] - start) * increment) - 1) for s in spring)
            check(len(spring) >= 5 and worst < 1e-10,
                  "epsd2: n steps in, the torque is n k_S R_eff^2 w_roll dt (%d snapshots, worst relative %.1e)"
                  % (len(spring), worst))
            capped, expected, what = [s for s in late if s[0] - start > 1.1 * n_cap], cap, "mu_r R_eff F_n"
        else:
            capped, expected, what = late, cap * w_roll / math.hypot(w_roll, w_twist), "mu_r R_eff F_n w_roll/|w|"
        worst = max(abs(-s[1][1] / expected - 1) for s in capped)
        check(len(capped) >= 5 and worst < 1e-10, "%s: then %.6g N m = %s (%d snapshots, worst relative %.1e)"
              % (rmodel, expected, what, len(capped), worst))


def case_impact_energy(liggghts, work):
    """Elastic head-on impact without damping conserves kinetic energy to 1e-4."""
    out = run_deck(liggghts, deck("in.impact"), work)
    before, after = printed(out, "KE_BEFORE"), printed(out, "KE_AFTER")
    check(abs(after - before) / before < 1e-4, "kinetic energy after/before = %.8f" % (after / before))
    check(printed(out, "VX_AFTER") > 0.0999, "the spheres rebounded")


def case_impact_restitution(liggghts, work):
    """'viscous_damping on' adds LIGGGHTS' restitution damping: a head-on impact with
    coefficientRestitution 0.5 rebounds at about half its speed (the damping formula is exact for a
    linear spring, close for Hertz)."""
    src = edited_deck(deck("in.impact"), os.path.join(work, "deck"),
                      [("tangential mindlin/scaled\n", "tangential mindlin/scaled viscous_damping on\n"),
                       ("peratomtypepair 2 1.0 1.0 1.0 1.0", "peratomtypepair 2 0.5 0.5 0.5 0.5")],
                      includes=("in.materials",))
    out = run_deck(liggghts, src, os.path.join(work, "run"))
    e = printed(out, "VX_AFTER") / 0.1
    check(abs(e - 0.5) < 0.05, "coefficient of restitution %.4f (asked 0.5)" % e)


def case_local_damping(liggghts, work):
    """Constant force m g, local damping alpha: with velocity Verlet, v_n = g dt [n (1-alpha) + alpha/2]
    (the first half step is undamped, v = 0); PFC's continuous form is v = (1-alpha) g t."""
    for alpha in (0.05, 0.3):
        out = run_deck(liggghts, deck("in.damping"), os.path.join(work, str(alpha)), {"alpha": alpha})
        vz = printed(out, "VZ_AFTER")
        expected = -9.81 * 1e-6 * (1000 * (1 - alpha) + alpha / 2)
        check(abs(vz - expected) / abs(expected) < 1e-12,
              "alpha = %g: v_z = %.12g m/s (closed form %.12g)" % (alpha, vz, expected))


def case_servo_wall(liggghts, work):
    """fix wall/servo: the top wall settles where both wall contacts carry F = sigma A, with the
    overlap of eq. 8 (plane convention Dt = D)."""
    out = run_deck(liggghts, deck("in.servo"), work)
    sigma, area, r = 1e4, 1e-6, 1e-4
    F = sigma * area
    # F = C_NORMAL sqrt(2 r U) U  ->  U = (F / (C_NORMAL sqrt(2 r)))^(2/3)
    U = (F / (C_NORMAL * math.sqrt(2 * r))) ** (2.0 / 3.0)
    check(abs(printed(out, "SIGMA_Z") / sigma - 1) < 1e-6, "wall stress %.9g Pa (target 1e4)" % printed(out, "SIGMA_Z"))
    gap = printed(out, "ZHI") - printed(out, "ZLO")
    check(abs(gap - (2 * r - 2 * U)) / U < 1e-4, "wall gap = 2r - 2U with U = %.6g m from eq. 8 (error %.1e U)"
          % (U, abs(gap - (2 * r - 2 * U)) / U))
    check(abs(printed(out, "Z_GRAIN") - (r - U)) / U < 1e-4, "the grain sits at r - U above the bottom wall")


def case_dt_stiffness(liggghts, work):
    """fix dt/stiffness: 0.5 x the critical step of the sphere touching both the other sphere and the
    wall, by hand from eq. 8-9: translational sqrt(m / sum(1.5 k_N + k_S)), rotational
    sqrt(0.4 m / sum k_S)."""
    out = run_deck(liggghts, deck("in.dt_stiffness"), work)
    d, U, Uw = 2e-4, 1e-7, 4e-8
    m = 2650 * math.pi / 6 * d ** 3
    pair, wall = math.sqrt(d / 2 * U), math.sqrt(d * Uw)
    translational = 1.5 * C_NORMAL * (pair + wall) + C_SHEAR * pair
    rotational = C_SHEAR * pair
    expected = 0.5 * min(math.sqrt(m / translational), math.sqrt(0.4 * m / rotational))
    dt = printed(out, "DT")
    check(abs(dt / expected - 1) < 1e-6, "dt %.9g s = 0.5 x critical %.9g s by hand" % (dt, 2 * expected))
    check(printed(out, "F_DT") == dt, "the fix's scalar is the time step")


def case_dt_stiffness_every(liggghts, work):
    """fix dt/stiffness 'every 1000' while a squeezed grain breaks into 14 fragments at step 2: the
    step shrinks at the reneighboring that brings the fragments (the fragment on each wall keeps the
    mother's overlap with 7% of her mass), and is followed step by step while the fragments, pressed
    together, stiffen faster than the growth factor: the same steps as 'every 1'."""
    steps = {}
    for every in (1, 1000):
        run_deck(liggghts, deck("in.dt_stiffness_crush"), os.path.join(work, "every%d" % every), {"every": every})
        steps[every] = [row["Dt"] for row in read_thermo(os.path.join(work, "every%d" % every, "log.liggghts"))]
    dt = steps[1000]
    check(len(dt) == 7, "7 thermo rows (steps 0-6)")
    check(dt[2] < 0.5 * dt[1], "step 2, fragments present: dt %.4g s < half the mother's %.4g s" % (dt[2], dt[1]))
    check(dt == steps[1], "every 1000 gives the steps of every 1 while the fragments stiffen: %s"
          % ", ".join("%.4g" % v for v in dt))


def case_bad_input(liggghts, work):
    """Errors name the keyword or property and what was expected."""
    cases = [
        ("damping fix before gravity", "in.damping", {"alpha": 0.05},
         [("fix             grav all gravity 9.81 vector 0.0 0.0 -1.0\n", ""),
          ("fix             damp all damp/local alpha ${alpha}\n",
           "fix             damp all damp/local alpha ${alpha}\n"
           "fix             grav all gravity 9.81 vector 0.0 0.0 -1.0\n")],
         "fix damp/local must be defined after fix grav"),
        ("alpha out of range", "in.damping", {"alpha": 1.5}, [],
         "keyword 'alpha' expects a value in [0, 1), got '1.5'"),
        ("missing alpha", "in.damping", {"alpha": 0.1},
         [("damp/local alpha ${alpha}", "damp/local")], "keyword 'alpha' is required"),
        ("unknown damping keyword", "in.damping", {"alpha": 0.1},
         [("damp/local alpha ${alpha}", "damp/local alpha ${alpha} speed 3")], "unknown keyword 'speed'"),
        ("servo wall without type", "in.servo", {},
         [("z stress 1e4", "z stress 1e4"), (" type 2 x fixed", " x fixed")], "keyword 'type'"),
        ("servo wall unknown mode", "in.servo", {}, [("z stress 1e4", "z push 1e4")], "expects fixed, ramp"),
        ("ramp without parameters", "in.servo", {}, [("z stress 1e4", "z ramp")], "no 'ramp sigma_start"),
        ("mean stresses that differ", "in.servo", {}, [("x fixed y fixed z stress 1e4", "x mean 1e4 y mean 2e4 z stress 1e4")],
         "axes x and y hold different mean stresses"),
        ("mean stress not positive", "in.servo", {}, [("x fixed y fixed z stress 1e4", "x mean 0 y fixed z stress 1e4")],
         "mean P (Pa, in (0, 1e12])"),
        ("dt without fraction", "in.dt_stiffness", {}, [("dt/stiffness fraction 0.5", "dt/stiffness every 2")],
         "keyword 'fraction' is required"),
        ("dt fraction out of range", "in.dt_stiffness", {}, [("fraction 0.5", "fraction 2")], "'fraction' expects"),
        ("dt unknown keyword", "in.dt_stiffness", {}, [("fraction 0.5", "fraction 0.5 safety 2")],
         "unknown keyword 'safety'"),
        ("two dt fixes", "in.dt_stiffness", {},
         [("dtfix all dt/stiffness fraction 0.5", "dtfix all dt/stiffness fraction 0.5\nfix dt2 all dt/stiffness fraction 0.3")],
         "only one fix dt/stiffness"),
        ("Poisson ratio out of range", "in.impact", {},
         [("poissonsRatio peratomtype 0.3 0.3", "poissonsRatio peratomtype 0.6 0.6")], "poisson"),
        ("missing Poisson ratio", "in.impact", {},
         [("fix             m2 all property/global poissonsRatio peratomtype 0.3 0.3\n", "")],
         "poissonsRatio"),
    ]
    for label, name, variables, edits, expected in cases:
        path = os.path.join(work, label.replace(" ", "_"))
        deck = edited_deck(os.path.join(HERE, name), os.path.join(path, "deck"), edits, includes=("in.materials",))
        out = run_deck(liggghts, deck, os.path.join(path, "run"), variables,
                       expect_fail=True)
        check(expected.lower() in out.lower(), "%s -> error mentions '%s'" % (label, expected))


if __name__ == "__main__":
    test_main(globals(), sys.argv[1:])
