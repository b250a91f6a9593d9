#!/usr/bin/env python3
"""Tests of the calibration tools (doc/calibration.md): post/calibrate.py's fit of fix crush's
parameters to single-particle crushing tests, its errors on bad data, and the DEM check of
scripts/calibration_check.sh on a small population.

  test_calibration.py LIGGGHTS WORKDIR CASE     (cases: the case_* functions below)"""
import json
import math
import os
import subprocess
import sys

from liggghts_run import check, main

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
CALIBRATE = os.path.join(REPO, "post", "calibrate.py")
SYNTHETIC = os.path.join(REPO, "examples", "calibration", "synthetic.csv")
# the parameters that examples/calibration/synthetic.csv was drawn from (its header)
TRUE = {"sigma_lim0": 1e9, "cv": 0.25, "weibull_m": 10.0, "d0": 1.4e-3}
PYTHON = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable

sys.path.insert(0, REPO)
from post.calibration import moduli, oedometer, strength, summary  # noqa: E402


def calibrate_cli(*args, cwd=None):
    """post/calibrate.py ARGS: (exit status, stdout, stderr)."""
    p = subprocess.run([PYTHON, CALIBRATE] + [str(a) for a in args], cwd=cwd, stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE, universal_newlines=True)
    return p.returncode, p.stdout, p.stderr


def fitted(work, data, *options):
    out = os.path.join(work, "fit")
    rc, stdout, stderr = calibrate_cli("single-particle", data, "--out", out, "--bootstrap", 200, *options)
    check(rc == 0, "single-particle fits %s (exit %d) %s" % (os.path.basename(data), rc, stderr[-500:]))
    print(stdout)
    return json.load(open(os.path.join(out, "parameters.json"))), stdout


def within(name, value, interval):
    check(interval[0] <= value <= interval[1], "%s = %g lies in the fit's interval [%g, %g]"
          % (name, value, interval[0], interval[1]))


def case_strength_conversion(liggghts, work):
    """eq. 5 inverted, against the single-grain deck's F_lim (examples/single_grain/in.single_grain:
    d = 0.2 mm, E = 7.8 GPa, nu = 0.3 on 210 GPa, 0.29, sigma = 1e8 Pa)."""
    E_eff = 1.0 / ((1.0 - 0.3 ** 2) / 7.8e9 + (1.0 - 0.29 ** 2) / 210e9)
    F_deck = (1e8 * math.pi) ** 3 * (3.0 * 0.0001 / (4.0 * E_eff)) ** 2
    check(abs(strength.effective_modulus(7.8e9, 0.3, 210e9, 0.29) / E_eff - 1) < 1e-14, "E' is eq. 4's")
    check(abs(strength.force_from_strength(1e8, 2e-4, E_eff) / F_deck - 1) < 1e-12,
          "F_lim(sigma_lim = 1e8 Pa) = the deck's %.6g N" % F_deck)
    check(abs(strength.strength_from_force(F_deck, 2e-4, E_eff) / 1e8 - 1) < 1e-12,
          "that force gives back sigma_lim = 1e8 Pa")
    # the strength grows as F^(1/3) and as r'^(-2/3) (a wrong r', e.g. d instead of d/2, is off by 2^(2/3))
    s1 = strength.strength_from_force(8.0, 1e-3, E_eff)
    check(abs(strength.strength_from_force(64.0, 1e-3, E_eff) / s1 - 2.0) < 1e-12, "sigma_lim ~ F^(1/3)")
    check(abs(s1 / strength.strength_from_force(8.0, 8e-3, E_eff) - 4.0) < 1e-12, "sigma_lim ~ d^(-2/3)")


def case_round_trip(liggghts, work):
    """The synthetic set (drawn from TRUE) gives back TRUE within the fit's 95% intervals, and those
    intervals are narrow enough to mean something."""
    p, stdout = fitted(work, SYNTHETIC, "--d0", TRUE["d0"])
    within("weibull_m", TRUE["weibull_m"], p["weibull_m_ci"])
    within("sigma_lim0", TRUE["sigma_lim0"], p["sigma_lim0_ci"])
    within("cv", TRUE["cv"], p["cv_ci"])
    width = (p["sigma_lim0_ci"][1] - p["sigma_lim0_ci"][0]) / p["sigma_lim0"]
    check(width < 0.15, "the sigma_lim0 interval is %.1f%% wide (< 15%%)" % (100 * width))
    check(p["cv_ci"][1] - p["cv_ci"][0] < 0.15, "the cv interval is narrower than 0.15")
    check(p["distribution"] == "normal", "the line takes the normal (the data's law): %s" % p["distribution"])
    check(p["fix_crush"] in stdout and p["fix_crush"].startswith("fix crush all crush sigma_lim0 "),
          "the fix crush line is printed: " + p["fix_crush"])
    for name in ("survival.png", "size_effect.png", "strengths.csv"):
        check(os.path.getsize(os.path.join(work, "fit", name)) > 1000, "wrote " + name)


def case_round_trip_weibull(liggghts, work):
    """Tests drawn from fix crush's weibull (one modulus m = 8 for scatter and size effect, sizes
    0.5 - 2 mm): the fit gives back m and the mean, and takes the weibull."""
    data = os.path.join(work, "weibull.csv")
    rc, _, err = calibrate_cli("synthetic", data, "--sigma_lim0", 2e9, "--cv", 0, "--weibull_m", 8, "--d0", 1e-3,
                               "--sizes", "0.5e-3,1e-3,2e-3", "--per-size", 40, "--seed", 7,
                               "--distribution", "weibull")
    check(rc == 0, "synthetic draws a Weibull set " + err)
    p, _ = fitted(work, data, "--d0", 1e-3)
    within("weibull_m", 8.0, p["weibull_m_ci"])
    within("Weibull shape of the scatter", 8.0, p["weibull_shape_ci"])
    within("mean strength at d0", 2e9, p["weibull_mean_ci"])
    check(p["distribution"] == "weibull", "the line takes the weibull: %s" % p["distribution"])


def case_summary_exact(liggghts, work):
    """A class's failure forces Weibull(m_t, F_0) give strengths k(d) F^(1/3): a Weibull of modulus
    3 m_t, whose mean is k F_0^(1/3) Gamma(1 + 1/(3 m_t)) and cv sqrt(G2/G1^2 - 1), checked against
    eq. 5's inversion of a million drawn forces; sigma_0 = F_0/d^2 reads as F_0."""
    import numpy as np
    E_eff = strength.effective_modulus(*strength.DEFAULT_GRAIN, *strength.DEFAULT_PLATEN)
    c = {"d": np.array([1e-3]), "n": np.array([30]), "m_t": np.array([2.5]), "F_0": np.array([40.0]),
         "E_eff": np.array([E_eff])}
    mean, cv = summary.class_strengths(c)
    F = np.random.default_rng(3).weibull(2.5, 1000000) * 40.0
    s = strength.strength_from_force(F, 1e-3, E_eff)
    check(abs(mean[0] / s.mean() - 1) < 1e-3 and abs(cv[0] / (s.std() / s.mean()) - 1) < 5e-3,
          "mean %.5g Pa and cv %.4f against the draws' %.5g and %.4f" % (mean[0], cv[0], s.mean(), s.std() / s.mean()))
    path = os.path.join(work, "sigma0.csv")
    open(path, "w").write("d,n,m_t,sigma_0\n1e-3,30,2.5,4e7\n2e-3,30,2.5,2e7\n")
    read = summary.read_summary(path)
    check(np.allclose(read["F_0"], [40.0, 80.0]), "sigma_0 = F_0 / d^2: F_0 %s N" % read["F_0"])


def case_summary_round_trip(liggghts, work):
    """Summary statistics made from a set of known parameters (fix crush's weibull, m = 9, mean
    1.5 GPa at d0 = 1 mm; sizes 0.5 - 2 mm, 40 grains each): each class's failure forces fitted by
    a Weibull (scipy), written as d, n, m_t, F_0; calibrate.py summary gives back m and sigma_lim0
    within its intervals, and takes the weibull (the classes' modulus 3 m_t within the size
    effect's interval)."""
    import numpy as np
    from scipy import stats
    data = os.path.join(work, "grains.csv")
    rc, _, err = calibrate_cli("synthetic", data, "--sigma_lim0", 1.5e9, "--cv", 0, "--weibull_m", 9, "--d0", 1e-3,
                               "--sizes", "0.5e-3,1e-3,2e-3", "--per-size", 40, "--seed", 11, "--distribution", "weibull")
    check(rc == 0, "synthetic draws the grains " + err)
    grains = np.loadtxt(data, delimiter=",", comments="#", skiprows=4)
    table = os.path.join(work, "summary.csv")
    with open(table, "w") as f:
        f.write("# per-class Weibull fits of the failure forces of %s\nd,n,m_t,F_0\n" % os.path.basename(data))
        for d in np.unique(grains[:, 0]):
            F = grains[grains[:, 0] == d, 1]
            m_t, _, F_0 = stats.weibull_min.fit(F, floc=0.0)
            f.write("%g,%d,%.6g,%.6g\n" % (d, len(F), m_t, F_0))
    out = os.path.join(work, "fit_summary")
    rc, stdout, err = calibrate_cli("summary", table, "--d0", 1e-3, "--bootstrap", 200, "--out", out)
    check(rc == 0, "summary fits the table (exit %d) %s" % (rc, err[-300:]))
    print(stdout)
    p = json.load(open(os.path.join(out, "parameters.json")))
    within("weibull_m", 9.0, p["weibull_m_ci"])
    within("sigma_lim0", 1.5e9, p["sigma_lim0_ci"])
    check(p["distribution"] == "weibull" and p["fix_crush"] in stdout and "against Table 1" in stdout,
          "the line takes the weibull and is printed, with Table 1 beside it: " + p["fix_crush"])
    bad = os.path.join(work, "one_class.csv")
    open(bad, "w").write("d,n,m_t,F_0\n1e-3,30,3,40\n")
    rc, _, err = calibrate_cli("summary", bad, "--out", os.path.join(work, "bad"))
    check(rc != 0 and "1 size class" in err, "one size class is refused: " + err.strip())
    open(bad, "w").write("d,n,m_t,F_0\n1e-3,30,3,40\n2e-3,3,3,60\n")
    rc, _, err = calibrate_cli("summary", bad, "--out", os.path.join(work, "bad"))
    check(rc != 0 and "line 3" in err and "n = 3" in err, "a class of 3 grains is named with its line: " + err.strip())


def case_moduli(liggghts, work):
    """Published moduli without strengths (calibrate.py moduli): the cv of a class's strengths from
    the failure forces' Weibull modulus, against eq. 5's inversion of drawn forces; the size effect
    of a strength ratio, against F_lim of fix crush's own size effect at two sizes; Table 1 in the
    same terms (cv 1 is the exponential: m_t = 1/3); the published file's numbers; bad rows named."""
    import numpy as np
    E_eff = strength.effective_modulus(*strength.DEFAULT_GRAIN, *strength.DEFAULT_PLATEN)
    s = strength.strength_from_force(np.random.default_rng(5).weibull(2.0, 1000000) * 30.0, 1e-3, E_eff)
    cv = float(strength.strength_cv(6.0))
    check(abs(cv / (s.std() / s.mean()) - 1) < 5e-3, "m_t = 2: cv %.4f against the draws' %.4f" % (cv, s.std() / s.mean()))
    check(abs(strength.strength_cv(1.0) - 1.0) < 1e-12 and abs(moduli.m_t_of_cv(1.0) - 1.0 / 3.0) < 1e-9,
          "cv 1 is a Weibull of modulus 1 (the exponential): m_t = 1/3")
    # fix crush's size effect with weibull_m = 10: F_lim at two sizes, then F/d^2's ratio read back
    d_small, d_large = 0.05e-3, 20e-3
    F = [strength.force_from_strength(5e9 * (d / 2e-3) ** (-0.3), d, E_eff) for d in (d_small, d_large)]
    ratio = (F[0] / d_small ** 2) / (F[1] / d_large ** 2)
    check(abs(moduli.weibull_m_of_ratio(ratio, d_small, d_large) - 10.0) < 1e-9
          and abs(moduli.ratio_of_weibull_m(10.0, d_small, d_large) / ratio - 1) < 1e-12,
          "the F/d^2 ratio %.4g of weibull_m = 10 over %g - %g m reads back as 10" % (ratio, d_small, d_large))
    published = os.path.join(REPO, "examples", "calibration", "published_moduli.csv")
    out = os.path.join(work, "moduli")
    rc, stdout, err = calibrate_cli("moduli", published, "--out", out)
    check(rc == 0, "moduli reads %s (exit %d) %s" % (published, rc, err))
    print(stdout)
    placed = json.load(open(os.path.join(out, "moduli.json")))
    sato, minerals = placed
    check(abs(sato["cv"][0] - 0.1938) < 5e-4 and sato["weibull_m"] == [6.0, 6.0],
          "Sato et al.'s m_t = 2: cv %.4f, weibull_m 6 by Weibull's size effect" % sato["cv"][0])
    check(abs(minerals["weibull_m"][0] - 13.78) < 0.01 and abs(minerals["weibull_m"][1] - 19.03) < 0.01
          and abs(minerals["table1"]["strength_ratio"] - 219.7) < 0.1,
          "strength ratio 17 - 50 over 0.05 - 20 mm: weibull_m %.2f - %.2f; Table 1's m = 10 a ratio of %.1f"
          % (minerals["weibull_m"][0], minerals["weibull_m"][1], minerals["table1"]["strength_ratio"]))
    header = "source,material,quantity,low,high,d_small,d_large\n"
    for name, row, expected in (("quantity", "a,b,m_w,2,2,,", "line 2: quantity = 'm_w'"),
                                ("sizes", "a,b,strength_ratio,17,50,2e-2,5e-5", "line 2: d_large = 5e-5 must exceed"),
                                ("ratio", "a,b,strength_ratio,0.5,2,5e-5,2e-2", "line 2: low = 0.5"),
                                ("range", "a,b,m_t,3,2,,", "line 2: high = 2 is below low = 3")):
        path = os.path.join(work, "bad_%s.csv" % name)
        open(path, "w").write(header + row + "\n")
        rc, _, err = calibrate_cli("moduli", path, "--out", os.path.join(work, "bad"))
        check(rc != 0 and expected in err, "bad %s refused: %s" % (name, err.strip()))


def bad_data(work, name, text):
    path = os.path.join(work, name)
    open(path, "w").write(text)
    rc, stdout, stderr = calibrate_cli("single-particle", path, "--out", os.path.join(work, "fit_" + name))
    check(rc != 0, "%s is refused (exit %d)" % (name, rc))
    print(stderr.strip())
    return stderr


def rows(sizes, per_size, force=50.0):
    return "".join("%g,%g\n" % (d, force * (1 + 0.01 * k)) for d in sizes for k in range(per_size))


def case_bad_data(liggghts, work):
    good = rows([1e-3, 2e-3], 10)
    lines = good.splitlines()
    e = bad_data(work, "negative_d.csv", "d,F_f\n" + "\n".join(lines[:4] + ["-1e-3,50"] + lines[5:]) + "\n")
    check("line 6" in e and "d = -1e-3 must be positive" in e, "a negative d is named with its line")
    e = bad_data(work, "zero_force.csv", "# comment\nd,F_f\n" + "\n".join(lines[:2] + ["1e-3,0"] + lines[3:]) + "\n")
    check("line 5" in e and "F_f = 0 must be positive" in e, "a zero F_f is named with its line")
    e = bad_data(work, "nan_force.csv", "d,F_f\n" + "\n".join(lines[:7] + ["1e-3,nan"] + lines[8:]) + "\n")
    check("line 9" in e and "F_f = nan" in e, "a non-finite F_f is named with its line")
    e = bad_data(work, "missing.csv", "d,F\n" + good)
    check("no column 'F_f'" in e, "a missing column is named")
    e = bad_data(work, "one_size.csv", "d,F_f\n" + rows([1e-3], 30))
    check("one size class" in e, "a single size class cannot give a size effect")
    e = bad_data(work, "few.csv", "d,F_f\n" + rows([1e-3, 2e-3], 7))
    check("14 grains: too few" in e and "at least %d" % strength.MIN_GRAINS in e, "too few grains in all")
    e = bad_data(work, "thin_class.csv", "d,F_f\n" + rows([1e-3, 2e-3], 10) + rows([3e-3], 3))
    check("size class 0.003" in e and "3 grains" in e, "a class of too few grains is named")


def case_yield_and_slope(liggghts, work):
    """The bilinear yield of post/calibrate.py oedometer on a curve with a known kink."""
    import numpy as np
    s = np.geomspace(1e5, 1e8, 60)
    e = np.where(s < 1e7, 0.7 - 0.01 * np.log10(s / 1e5), 0.68 - 0.3 * np.log10(s / 1e7))
    y, c = oedometer.yield_and_slope(s, e, (3e5, 3e6), (5e7, 1e8))
    check(abs(y / 1e7 - 1) < 1e-9 and abs(c + 0.3) < 1e-9, "yield 1e7 Pa and slope -0.3: %g, %g" % (y, c))


# A stand-in for an O-N run: writes the history a run would (sigma_z, void_ratio) for a bilinear
# curve whose yield stress is 2.6e-3 sigma_lim0 and whose slope is -0.3 - 0.01 cv. With a third
# argument, the pair (sigma_lim0, cv) named there books past zero porosity: its curve is shifted
# down by 0.6: the same yield and slope, e > 0 at the start and e < 0 from about 25 MPa.
FAKE_RUN = """import sys
import numpy as np
sigma_lim0, cv, N = float(sys.argv[1]), float(open("in.grains").read().split(" cv ")[1].split()[0]), sys.argv[2]
y = 2.6e-3 * sigma_lim0
s = np.geomspace(1e5, 1e8, 80)
e = np.where(s < y, 0.7 - 0.01 * np.log10(s / 1e5), 0.7 - 0.01 * np.log10(y / 1e5) + (-0.3 - 0.01 * cv) * np.log10(s / y))
if len(sys.argv) > 3 and [float(v) for v in sys.argv[3].split(",")] == [sigma_lim0, cv]:
    e = e - 0.6
with open("history_O%s.csv" % N, "w") as f:
    f.write("step,sigma_z,void_ratio\\n")
    for k, (a, b) in enumerate(zip(s, e)):
        f.write("%d,%.17g,%.17g\\n" % (k, a, b))
"""


def stand_in_search(work):
    """The stand-in run's script and a lab curve of the pair (5e9, 1) in work: (script, lab CSV, the
    lab's yield stress)."""
    import numpy as np
    fake = os.path.join(work, "fake_run.py")
    open(fake, "w").write(FAKE_RUN)
    s = np.geomspace(1e5, 1e8, 80)
    y = 2.6e-3 * 5e9
    e = np.where(s < y, 0.7 - 0.01 * np.log10(s / 1e5), 0.7 - 0.01 * np.log10(y / 1e5) - 0.31 * np.log10(s / y))
    lab = os.path.join(work, "lab.csv")
    with open(lab, "w") as f:
        f.write("sigma_v,e\n" + "".join("%.17g,%.17g\n" % (a, b) for a, b in zip(s, e)))
    return fake, lab, y


def case_oedometer_search(liggghts, work):
    """post/calibrate.py oedometer over a 3 x 2 grid, each run a stand-in that writes a curve of known
    yield (2.6e-3 sigma_lim0) and slope (-0.3 - 0.01 cv), against a lab curve of the pair (5e9, 1):
    every run's yield and slope are read back, the best pair is the lab's, and the cost is reported."""
    fake, lab, y = stand_in_search(work)
    out = os.path.join(work, "search")
    rc, stdout, stderr = calibrate_cli("oedometer", lab, "--sigma_lim0", "2.5e9,5e9,1e10", "--cv", "0.5,1",
                                       "--command", "%s %s {sigma_lim0} {N}" % (PYTHON, fake), "--out", out)
    print(stdout)
    check(rc == 0, "the search ran (exit %d) %s" % (rc, stderr[-500:]))
    result = json.load(open(os.path.join(out, "oedometer.json")))
    runs = result["runs"]
    check(len(runs) == 6, "6 runs: 3 sigma_lim0 x 2 cv")
    check(all(abs(r["yield"] / (2.6e-3 * r["sigma_lim0"]) - 1) < 0.02 and abs(r["slope"] + 0.3 + 0.01 * r["cv"]) < 1e-6
              for r in runs), "each run's yield (2.6e-3 sigma_lim0, 2%) and slope read back from its history")
    check(abs(result["lab_yield"] / y - 1) < 0.02, "the lab's yield %.4g Pa (%.4g)" % (result["lab_yield"], y))
    best = result["best"]
    check(best["sigma_lim0"] == 5e9 and best["cv"] == 1.0, "the best pair is the lab's: %g, %g" % (best["sigma_lim0"], best["cv"]))
    check("search: 6 runs" in stdout and " s a run" in stdout, "the cost of the search is printed")
    check(os.path.exists(os.path.join(out, "oedometer.png")), "the figure is written")


def case_oedometer_cascade(liggghts, work):
    """The search with the lab's own pair (5e9, 1) booking past zero porosity (a cascade): that run is
    named and left out, the best is another, and a grid of such runs alone is refused."""
    fake, lab, y = stand_in_search(work)
    out = os.path.join(work, "search")
    command = "%s %s {sigma_lim0} {N} 5e9,1" % (PYTHON, fake)
    rc, stdout, stderr = calibrate_cli("oedometer", lab, "--sigma_lim0", "2.5e9,5e9", "--cv", "0.5,1",
                                       "--command", command, "--out", out)
    print(stdout)
    check(rc == 0, "the search ran (exit %d) %s" % (rc, stderr[-500:]))
    result = json.load(open(os.path.join(out, "oedometer.json")))
    cascade = [r for r in result["runs"] if r["overbooked_at"] is not None]
    check([(r["sigma_lim0"], r["cv"]) for r in cascade] == [(5e9, 1.0)], "only the pair (5e9, 1) books e <= 0")
    check(2e7 < cascade[0]["overbooked_at"] < 5e7, "e <= 0 from %.4g Pa (about 25 MPa)" % cascade[0]["overbooked_at"])
    check(cascade[0]["misfit"] is None and abs(cascade[0]["slope"] + 0.31) < 1e-6,
          "its curve has the lab's slope but no misfit: it is not a candidate")
    check("run 3: the booked void ratio reaches" in stdout and "not a candidate" in stdout, "the run is named")
    best = result["best"]
    check(best["sigma_lim0"] == 5e9 and best["cv"] == 0.5, "the best is the next pair: %g, %g" % (best["sigma_lim0"], best["cv"]))
    rc, stdout, stderr = calibrate_cli("oedometer", lab, "--sigma_lim0", "5e9", "--cv", "1",
                                       "--command", command, "--out", os.path.join(work, "alone"))
    check(rc != 0 and "no run of the grid is a candidate" in stderr, "a grid of cascades alone is refused: %s" % stderr[-300:])


def dem_check(liggghts, work, per_size, distribution=None):
    env = dict(os.environ, PER_SIZE=str(per_size), LIGGGHTS=liggghts)
    if distribution:
        env["DISTRIBUTION"] = distribution
    out = os.path.join(work, "check_" + (distribution or "fitted"))
    p = subprocess.run(["bash", os.path.join(REPO, "scripts", "calibration_check.sh"), SYNTHETIC, out,
                        "--bootstrap", "100"], env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       universal_newlines=True)
    print(p.stdout[-2000:])
    check(p.returncode == 0, "scripts/calibration_check.sh ran (exit %d)" % p.returncode)
    result = json.load(open(os.path.join(out, "dem", "dem_check.json")))
    fit = json.load(open(os.path.join(out, "fit", "parameters.json")))
    check(result["broken"] == result["grains"] == 3 * per_size, "all %d grains broke" % result["grains"])
    return result, fit, out


def case_dem_constant(liggghts, work):
    """Every grain at the fitted sigma_lim0 (distribution constant): each breaks at eq. 5's F_lim for
    its size, through the size effect (d/d0)^(-3/m), to 1%."""
    result, fit, _ = dem_check(liggghts, work, 3, "constant")
    for c in result["classes"]:
        F = strength.force_from_strength(fit["sigma_lim0"] * strength.size_factor(c["d"], fit["d0"], fit["weibull_m"]),
                                         c["d"], fit["E_eff"])
        check(abs(c["dem_median_N"] / F - 1) < 0.01, "d = %g m: DEM F_f %.4g N = F_lim %.4g N" % (c["d"], c["dem_median_N"], F))


def case_dem_population(liggghts, work):
    """The fitted line over 10 grains a size: the DEM's strengths, all sizes brought to d0, are not
    told apart from the tests' (KS p > 0.05), and at each size the median strength (F_f^(1/3))
    agrees within 25% (10 grains: a per-size KS test has little power)."""
    result, _, out = dem_check(liggghts, work, 10)
    check(result["pooled_ks_p"] > 0.05, "all sizes at d0: KS p = %.3f" % result["pooled_ks_p"])
    for c in result["classes"]:
        ratio = (c["dem_median_N"] / c["lab_median_N"]) ** (1.0 / 3.0)
        check(0.75 < ratio < 1.25, "d = %g m: median strength ratio DEM/tests %.2f (KS p %.3f)"
              % (c["d"], ratio, c["ks_p"]))
    check(os.path.getsize(os.path.join(out, "dem", "dem_check.png")) > 1000, "wrote dem_check.png")


if __name__ == "__main__":
    main(globals(), sys.argv[1:])
