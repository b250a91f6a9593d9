#!/usr/bin/env python3
"""Shearing with crushing (examples/fontainebleau/in.triaxial, studies/critical_state/README.md) and the
critical-state fit (post/critical_state.py).

    test_critical_state.py LIGGGHTS WORKDIR CASE [ARGS]

Cases: shear_crushing (on 1 and 2 ranks: the isotropic compression and the shearing with grains
that break; exact books through both stages, q/p rising, the cell pressure held), constant_p (the
lateral walls of fix wall/servo's mode mean keep p' while q rises) and fit_fixture (the fit on
histories with a known critical state plane)."""
import csv
import math
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liggghts_run import check, each_rank_count, edited_deck, read_dump, run_deck, variants  # noqa: E402
from liggghts_run import main as test_main  # noqa: E402
from liggghts_run import read_events  # noqa: E402
from test_fontainebleau import read_history  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TRIAXIAL = os.path.join(ROOT, "examples", "fontainebleau", "in.triaxial")
FIT = os.path.join(ROOT, "post", "critical_state.py")
CELL = 2e6
# Grains five times weaker than Table 1's (F_lim / 125), so that some break within 3% of shearing
# at 2 MPa; a faster shear (inertial number about 2e-3) for a short test.
SHORT = {"crushing": 1, "cell": CELL, "sigma_lim0": 1e9, "settle": 5000, "strain_rate": 100,
         "axial_max": 0.03, "checkpoint_every": 0, "vtk": 0}


def sphere_volume(d):
    return math.pi * d ** 3 / 6.0


@variants(["1"], ["2"], timeout=300)
def case_shear_crushing(liggghts, work, ranks):
    """Isotropic compression to 2 MPa and 3% of drained shearing, grains breaking in both stages:
    every history row keeps particles = sample + 13 x events; the particles after shearing are those
    after the compression less the grains broken while shearing plus their 14 fragments each, tags
    unique; the solid volume changes by exactly the broken grains' removed share; q/p rises while
    the lateral walls hold 2 MPa."""
    ranks = int(ranks)
    out = run_deck(liggghts, TRIAXIAL, work, SHORT, ranks=ranks)
    sample = int(re.search(r"^SAMPLE N = 2: (\d+) particles", out, re.M).group(1))
    rows = read_history(os.path.join(work, "history_Tdense2.csv"))
    check(all(r["particles"] == sample + 13 * r["events"] for r in rows),
          "%d history rows: particles = %d + 13 x events" % (len(rows), sample))
    compressed = [r for r in rows if r["stage"] == 0]
    shear = [r for r in rows if r["stage"] == 1]
    check(len(compressed) >= 3 and len(shear) >= 10, "%d rows of compression, %d of shearing"
          % (len(compressed), len(shear)))
    # (grains five times weaker than the sand's break in bursts that unload the walls for a while)
    check(abs(compressed[-1]["p"] / CELL - 1) < 0.08, "compressed to p' = %.4g Pa" % compressed[-1]["p"])

    before = read_dump(os.path.join(work, "dump_Tdense2_2MPa.liggghts"))[-1]
    after = read_dump(os.path.join(work, "dump_Tdense2_sheared.liggghts"))[-1]
    events = read_events(os.path.join(work, "events_Tdense2.csv"))
    broken = [e for e in events if int(e["step"]) > before[0]]
    check(len(broken) >= 5, "%d grains broke while shearing (steps %d - %d)" % (len(broken), before[0], after[0]))
    tags_before = {int(r["id"]) for r in before[2]}
    tags_after = [int(r["id"]) for r in after[2]]
    mothers = {int(e["tag"]) for e in broken}
    fragments = {int(e["fragment_%d" % k]) for e in broken for k in range(1, 15)}
    check(len(tags_after) == len(set(tags_after)) == len(tags_before) + 13 * len(broken),
          "%d particles after shearing, every tag unique: %d + 13 x %d" % (len(tags_after), len(tags_before), len(broken)))
    check(set(tags_after) == (tags_before | fragments) - mothers,
          "the particles after shearing are those before, less the %d broken, plus their fragments" % len(broken))
    # The fourteen fragments keep the same share of every mother's volume: find it on an event whose
    # fragments all survived, then the solid volume must change by exactly (1 - share) x the mothers'.
    radius = {int(r["id"]): r["radius"] for r in after[2]}
    intact = [e for e in broken if all(int(e["fragment_%d" % k]) in radius for k in range(1, 15))]
    share = sum(sphere_volume(2 * radius[int(intact[0]["fragment_%d" % k])]) for k in range(1, 15)) / \
        sphere_volume(float(intact[0]["diameter"]))
    check(0.5 < share < 0.56, "the fourteen fragments keep %.4f of their mother's volume" % share)
    v_before = sum(sphere_volume(2 * r["radius"]) for r in before[2])
    v_after = sum(sphere_volume(2 * r["radius"]) for r in after[2])
    removed = (1 - share) * sum(sphere_volume(float(e["diameter"])) for e in broken)
    # the dumps give radii to 6 digits (a lost fragment of an original grain is 3e-5 of the volume;
    # the tags above catch any lost or doubled particle exactly)
    check(abs(v_before - removed - v_after) < 1e-6 * v_before,
          "solid volume after = before - removed share of the broken grains (%.2e of it)"
          % ((v_before - removed - v_after) / v_before))

    first, last = shear[0], shear[-1]
    check(last["axial_strain"] >= 0.03 and last["q_over_p"] > first["q_over_p"] + 0.4 and last["q_over_p"] > 0.5,
          "q/p rises from %.3f to %.3f over %.1f%% axial strain" % (first["q_over_p"], last["q_over_p"],
                                                                    100 * last["axial_strain"]))
    check(last["I_G"] > first["I_G"], "I_G grows while shearing: %.4f -> %.4f" % (first["I_G"], last["I_G"]))
    held = [r for r in shear if r["axial_strain"] > 0.005]
    worst = max(abs(r[c] / CELL - 1) for r in held for c in ("sigma_x", "sigma_y"))
    check(worst < 0.03, "lateral stresses within %.1f%% of 2 MPa beyond 0.5%% axial strain" % (100 * worst))


@variants(timeout=300)
def case_constant_p(liggghts, work):
    """Drained shearing at constant p' = 2 MPa (path p: the lateral walls share 3 p' - sigma_z): p'
    stays within 3% (its mean within 1%) while q grows and the lateral stress falls below p'."""
    out = run_deck(liggghts, TRIAXIAL, work, dict(SHORT, path="p", axial_max=0.02))
    check("ERROR" not in out, "ran")
    shear = [r for r in read_history(os.path.join(work, "history_Tdense2.csv")) if r["stage"] == 1]
    held = [r for r in shear if r["axial_strain"] > 0.005]
    worst = max(abs(r["p"] / CELL - 1) for r in held)
    mean = sum(r["p"] for r in held) / len(held)
    # the axial stress jumps as the top wall meets grains; the lateral walls follow it within a few
    # hundred steps (at this test's fast shear; 1% at the deck's default rate)
    check(len(held) >= 5 and worst < 0.03 and abs(mean / CELL - 1) < 0.01,
          "p' within %.2f%% of 2 MPa over %d rows, their mean within %.2f%%"
          % (100 * worst, len(held), 100 * abs(mean / CELL - 1)))
    last = shear[-1]
    check(last["q_over_p"] > 0.5 and last["sigma_x"] < 0.85 * CELL and last["sigma_z"] > 1.3 * CELL,
          "q/p %.3f: sigma_x %.3g Pa, sigma_z %.3g Pa, mean %.4g Pa"
          % (last["q_over_p"], last["sigma_x"], last["sigma_z"], last["p"]))


@variants(*each_rank_count(1, 2, 3, 4), timeout=300)
def case_box_grows(liggghts, work, ranks):
    """The box follows the lateral walls: a box cut 0.06 mm beyond the sample before shearing grows
    as the walls move out (in.triaxial_box), the grains migrating to the processors of the new box,
    and none is lost: 1340 grains, unique tags, the walls past the old edge."""
    ranks = int(ranks)
    deck = edited_deck(TRIAXIAL, os.path.join(work, "deck"), [(
        "include         in.triaxial_state\n",
        "change_box      all x final -0.001 $(f_walls[2]+6e-5) y final -0.001 $(f_walls[4]+6e-5) units box\n"
        "include         in.triaxial_state\n")], includes=("in.shear_stage",))
    # the sample prepared on one rank (the preparation's 90000 steps are slow on 4 oversubscribed ranks)
    folder = os.path.dirname(deck)
    run_deck(liggghts, os.path.join(folder, "in.prepare"), os.path.join(work, "sample"))
    shutil.copy(os.path.join(work, "sample", "sample_N2.restart"), folder)
    out = run_deck(liggghts, deck, os.path.join(work, "run"),
                   {"reuse": 1, "axial_max": 0.01, "checkpoint_every": 0, "vtk": 0}, ranks=ranks)
    grown = re.findall(r"^BOX grown to x \S+ (\S+) y \S+ (\S+) m: the lateral walls at (\S+) (\S+) m", out, re.M)
    check(len(grown) >= 1, "the box grew %d time(s) on %d rank(s)" % (len(grown), ranks))
    xhi, yhi, wx, wy = map(float, grown[0])
    check(abs(xhi - wx - 1e-3) < 1e-9 or abs(yhi - wy - 1e-3) < 1e-9, "to 1 mm beyond the wall that came near it")
    rows = read_dump(os.path.join(work, "run", "dump_Tdense2_sheared.liggghts"))[-1][2]
    tags = [int(r["id"]) for r in rows]
    check(len(tags) == len(set(tags)) == 1340, "%d grains, every tag unique" % len(tags))
    history = read_history(os.path.join(work, "run", "history_Tdense2.csv"))
    check(history[-1]["axial_strain"] >= 0.01, "sheared to %.2f%%" % (100 * history[-1]["axial_strain"]))


# The fixture's critical state plane and stress ratio.
GAMMA0, LAMBDA, BETA, M_CS = 1.50, 0.06, 0.8, 1.2   # M = 1.2: phi_cs = 30 degrees exactly
HEADER = ("step,axial_strain,volumetric_strain,sigma_x,sigma_y,sigma_z,p,q,q_over_p,porosity,events,void_ratio,"
          "I_G,particles,stage")


def write_fixture(folder, cell_mpa, ig0, e_shift=0.0):
    """A history of in.triaxial's columns at cell pressure cell_mpa: 5 rows of isotropic compression,
    then shearing to 30%, q/p rising to a peak of 1.5 at 5% and settling at M_CS from 20% (p' =
    cell / (1 - M_CS / 3) there), I_G reaching ig0 + 0.01 ln(p'/MPa) and e the plane's value (plus
    e_shift, a residual) at 25%, both staying there."""
    os.makedirs(folder, exist_ok=True)
    cell = cell_mpa * 1e6
    p_cs = cell / (1 - M_CS / 3)
    ig_cs = ig0 + 0.01 * math.log(p_cs / 1e6)
    e_cs = GAMMA0 - LAMBDA * math.log(p_cs / 1e3) - BETA * ig_cs + e_shift
    rows = [HEADER]
    for k in range(5):
        rows.append("%d,%g,%g,%g,%g,%g,%g,0,0,%g,%d,%g,%g,%d,0" % (1000 * k, 0.002 * k, 0.004 * k, cell, cell, cell,
                                                                  cell, 0.4, k, 0.7 - 0.01 * k, ig_cs - 0.05,
                                                                  1340 + 13 * k))
    for k in range(301):
        eps = k / 1000.0
        eta = 1.5 * eps / 0.05 if eps <= 0.05 else (1.5 - 0.3 * (eps - 0.05) / 0.15 if eps < 0.2 else M_CS)
        p = cell / (1 - eta / 3)
        approach = min(1.0, eps / 0.25)
        e = 0.66 + (e_cs - 0.66) * approach
        events = 4 + k // 10
        rows.append("%d,%g,%.12g,%g,%g,%.12g,%.12g,%.12g,%.12g,%.12g,%d,%.12g,%.12g,%d,1"
                    % (5000 + 1000 * k, eps, (0.66 - e) / 1.66, cell, cell, cell + eta * p, p, eta * p, eta,
                       e / (1 + e), events, e, ig_cs - 0.05 * (1 - approach), 1340 + 13 * events))
    sample = os.path.basename(folder).split("_")[0]
    with open(os.path.join(folder, "history_T%s2.csv" % sample), "w") as f:
        f.write("\n".join(rows) + "\n")
    with open(os.path.join(folder, "seconds.txt"), "w") as f:
        f.write("12.5\n")
    with open(os.path.join(folder, "cpu_seconds.txt"), "w") as f:
        f.write("11.0\n")


def case_fit_precrushed(liggghts, work):
    """post/critical_state.py groups a variant with its pre-crushed samples (variant_pre<P>): dense
    samples of normal at 2 MPa (seeds 11 and 12: I_G 0.78 and 0.79 + 0.01 ln p') and 8 MPa (the decks'
    seed) and of normal_pre50 at the same p' with I_G 0.90 and 0.92 + 0.01 ln p', all on the known
    plane: the group "normal + pre-crushed" (6 tests) recovers beta, which normal's own 3 tests cannot
    give; paired by seed, each seed's -de_cs / dI_G at 2 MPa is beta; --max-dilatancy below every
    test's leaves them all out of the fits."""
    del liggghts
    study = os.path.join(work, "study")
    if os.path.isdir(study):
        shutil.rmtree(study)
    for variant, ig0 in (("normal", 0.78), ("normal_pre50", 0.90)):
        write_fixture(os.path.join(study, variant, "dense_2MPa_s11"), 2.0, ig0)
        write_fixture(os.path.join(study, variant, "dense_2MPa_s12"), 2.0, ig0 + (0.01 if variant == "normal" else 0.02))
        write_fixture(os.path.join(study, variant, "dense_8MPa"), 8.0, ig0)

    def fit(*options):
        out = subprocess.run(["/usr/bin/python3", FIT, "--out", os.path.join(work, "fit"), "--no-figures"] + list(options)
                             + [study], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
        check(out.returncode == 0, "post/critical_state.py ran:\n" + out.stdout[-2000:])
        return open(os.path.join(work, "fit", "fit.md")).read()

    text = fit()
    plane = re.search(r"^\| normal \+ pre-crushed \| 6 \| (\S+) \| (\S+) \| (\S+) \|", text, re.M)
    check(plane is not None and abs(float(plane.group(3)) - BETA) < 1e-3 and abs(float(plane.group(2)) - LAMBDA) < 1e-4,
          "the pre-crushed family's plane: lambda %s, beta %s (built with %g, %g)"
          % (plane and plane.group(2), plane and plane.group(3), LAMBDA, BETA))
    check(re.search(r"^\| normal \| 3 \|", text, re.M) is None, "no plane from normal's own three tests")
    paired = re.search(r"^\| normal \| normal_pre50 \| dense \| 2 \| sigma3 \| 2 \| .* \| (\S+) \+- (\S+) \|$", text, re.M)
    check(paired is not None and abs(float(paired.group(1)) - BETA) < 1e-3,
          "beta paired by seed at 2 MPa: %s (built with %g)" % (paired and paired.group(1), BETA))
    with open(os.path.join(work, "fit", "critical_states.csv")) as f:
        seeds = sorted({(r["p0_MPa"], r["seed"]) for r in csv.DictReader(f)})
    check(seeds == [("2", "11"), ("2", "12"), ("8", "15485863")],
          "seeds named by the folders, the decks' where none is: %s" % seeds)
    text = fit("--max-dilatancy", "-1")
    check(re.search(r"^\| normal \+ pre-crushed \|", text, re.M) is None and "Left out of every fit" in text
          and text.count(" seed ") >= 6, "--max-dilatancy -1 leaves every test out of the fits")


def case_fit_fixture(liggghts, work):
    """post/critical_state.py on histories built on a known plane e_cs = 1.5 - 0.06 ln(p'/kPa) -
    0.8 I_G at q/p = 1.2: it recovers the plane exactly, phi_cs = 30 degrees, each sample's line
    through its own points, residuals that are the shifts put in, and writes the tables and figures;
    read back from the critical_states.csv it wrote (--from-csv), the same plane."""
    study = os.path.join(work, "study")
    if os.path.isdir(study):
        shutil.rmtree(study)
    pressures = (0.5, 2.0, 8.0, 20.0)
    for sample, ig0 in (("dense", 0.80), ("loose", 0.85)):
        for p in pressures:
            # I_G grows with p' on each sample, differently for each: the plane separates the samples
            write_fixture(os.path.join(study, "rotation0", "%s_%gMPa" % (sample, p)), p, ig0)
    out = subprocess.run(["/usr/bin/python3", FIT, "--out", os.path.join(work, "fit"), study],
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
    check(out.returncode == 0, "post/critical_state.py ran:\n" + out.stdout[-2000:])
    with open(os.path.join(work, "fit", "critical_states.csv")) as f:
        tests = list(csv.DictReader(f))
    check(len(tests) == 8, "8 tests in critical_states.csv")
    for t in tests:
        p = float(t["p_cs_MPa"]) * 1e6
        check(abs(float(t["phi_cs"]) - 30.0) < 1e-4 and abs(float(t["M_cs"]) - M_CS) < 1e-6,
              "%s %s MPa: q/p = %s at the critical state, phi_cs = %s deg" % (t["sample"], t["p0_MPa"], t["M_cs"], t["phi_cs"]))
        expected = GAMMA0 - LAMBDA * math.log(p / 1e3) - BETA * float(t["IG_cs"])
        check(abs(float(t["e_cs"]) - expected) < 1e-5, "e_cs %s on the plane (%.6f)" % (t["e_cs"], expected))
        check(abs(float(t["dilatancy_end"])) < 1e-9 and abs(float(t["M_peak"]) - 1.5) < 1e-9
              and abs(float(t["eps_peak"]) - 0.05) < 1e-9 and int(float(t["events_shearing"])) == 30,
              "no volume change at the end, peak 1.5 at 5%, 30 events while shearing")
    fit = open(os.path.join(work, "fit", "fit.md")).read()
    check(re.search(r"^\| rotation0 \| dense \| 0.5 \|.* \| 305000 \| 11 \|$", fit, re.M) is not None,
          "fit.md gives each test's steps and its CPU time (not the wall-clock time)")
    plane = re.search(r"^\| rotation0 \| 8 \| (\S+) \| (\S+) \| (\S+) \| (\S+) \| (\S+) \| (\S+) \| (\S+) \| (\S+) "
                      r"\| (\S+) \|", fit, re.M)
    check(plane is not None, "fit.md has the plane's row")
    gamma0, lam, beta, r2, rms, single, *errors = map(float, plane.groups())
    check(max(errors) < 1e-3, "standard errors of an exact plane: %s" % errors)
    check(abs(gamma0 - GAMMA0) < 1e-3 and abs(lam - LAMBDA) < 1e-4 and abs(beta - BETA) < 1e-3 and rms < 1e-5,
          "plane: Gamma_0 %.4f, lambda %.4f, beta %.4f, rms %.1e (built with %g, %g, %g)"
          % (gamma0, lam, beta, rms, GAMMA0, LAMBDA, BETA))
    check(single > 0.005, "a single line through both samples misses by %.4f rms" % single)
    for sample, ig0 in (("dense", 0.80), ("loose", 0.85)):
        line = re.search(r"^\| rotation0 \| %s \| 4 \| (\S+) \| (\S+) \|" % sample, fit, re.M)
        # on one sample I_G = ig0 + 0.01 ln(p'/MPa) = ig0 + 0.01 [ln(p'/kPa) - ln 1000], so its line is
        # e = Gamma0 - beta ig0 + 0.01 beta ln 1000 - (lambda + 0.01 beta) ln(p'/kPa)
        gamma = GAMMA0 - BETA * ig0 + BETA * 0.01 * math.log(1e3)
        check(line is not None and abs(float(line.group(1)) - gamma) < 1e-4
              and abs(float(line.group(2)) - (LAMBDA + 0.01 * BETA)) < 1e-4,
              "%s line: Gamma %s, lambda %s (expected %.4f, %.4f)" % (sample, line and line.group(1),
                                                                      line and line.group(2), gamma, LAMBDA + 0.01 * BETA))
    # --from-csv: the study's tables from its CSV alone give the plane the run folders gave
    subprocess.run(["/usr/bin/python3", FIT, "--from-csv", "--out", os.path.join(work, "fit_csv"),
                    os.path.join(work, "fit", "critical_states.csv")], stdout=subprocess.DEVNULL, check=True)
    again = re.search(r"^\| rotation0 \| 8 \| (\S+) \| (\S+) \| (\S+) \|",
                      open(os.path.join(work, "fit_csv", "fit.md")).read(), re.M)
    check(again is not None and abs(float(again.group(1)) - GAMMA0) < 1e-3 and abs(float(again.group(2)) - LAMBDA) < 1e-4
          and abs(float(again.group(3)) - BETA) < 1e-3,
          "--from-csv recovers the plane from critical_states.csv alone: %s" % (again and again.groups(),))
    # a residual put in comes out as the plane's residual
    write_fixture(os.path.join(study, "rotation0", "dense_5MPa"), 5.0, 0.80, e_shift=0.01)
    subprocess.run(["/usr/bin/python3", FIT, "--out", os.path.join(work, "fit2"), "--no-figures", study],
                   stdout=subprocess.DEVNULL, check=True)
    fit = open(os.path.join(work, "fit2", "fit.md")).read()
    row = re.search(r"^\| rotation0 \| rotation0 \| dense \| 5 \| \S+ \| \S+ \| \S+ \| (\S+) \|", fit, re.M)
    shifted = float(row.group(1)) if row else float("nan")
    check(0.006 < shifted < 0.01, "the shifted test's residual is %+.4f (0.01 shared with the refitted plane)" % shifted)
    # the curved lines recover curves built on their own forms (the fit module, under Debian's numpy)
    probe = ("import sys; sys.path.insert(0, %r); import critical_state as c, numpy as np; p = np.array([0.2, 1, 4, 9, 30]); "
             "a = c.fit_curved(p, 0.9 * (p * 1e3) ** -0.08); b = c.fit_curved(p, 0.6 - 0.006 * (p * 1e6 / 101e3) ** 0.7); "
             "v = c.lens_volume(np.array([[0, 0, 0], [1.5, 0, 0], [10, 0, 0], [10, 1.2, 0.]]), np.array([1, 1, 0.5, 1.])); "
             "ig = np.array([0.74, 0.85, 0.75, 0.86, 0.8]); "
             "cp = c.fit_plane_curved(p, ig, 2.0 - 0.004 * (p * 1e6 / 101e3) ** 0.7 - 1.5 * ig); "
             "print(a['e1'], a['b'], a['rms_power'], b['e_gamma'], b['lambda_c'], b['rms_li_wang'], v, "
             "cp['e_gamma0'], cp['lambda_c'], cp['beta'], cp['rms'])"
             % os.path.dirname(FIT))
    values = [float(v) for v in subprocess.run(["/usr/bin/python3", "-c", probe], stdout=subprocess.PIPE,
                                               universal_newlines=True, check=True).stdout.split()]
    # two unit spheres 1.5 apart: pi (4 r + d)(2 r - d)^2 / 12; a sphere of 0.5 and one of 1 at 1.2:
    # pi (r1 + r2 - d)^2 (d^2 + 2 d (r1 + r2) - 3 (r1 - r2)^2) / (12 d)
    lens = math.pi * 5.5 * 0.25 / 12 + math.pi * 0.09 * (1.44 + 3.6 - 0.75) / 14.4
    expected = [0.9, 0.08, 0.0, 0.6, 0.006, 0.0, lens, 2.0, 0.004, 1.5, 0.0]
    check(all(abs(v - x) < 1e-9 for v, x in zip(values, expected)),
          "curved lines: e_1, b, rms and e_Gamma, lambda_c, rms; the overlaps' lens volume; the curved plane's "
          "e_Gamma0, lambda_c, beta, rms: %s (expected %s)"
          % (values, expected))
    for name in ("critical_state_e_lnp.png", "critical_state_IG_p.png", "critical_state_plane.png",
                 "critical_state_strain.png"):
        path = os.path.join(work, "fit", "figures", name)
        check(os.path.getsize(path) > 10000, "%s drawn" % name)


if __name__ == "__main__":
    test_main(globals(), sys.argv[1:])
