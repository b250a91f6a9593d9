"""The DEM check of a fit (calibrate.py population and compare; scripts/calibration_check.sh): the
grains and variables of a population run (examples/calibration/in.population), and its failure
forces against the tests."""
import csv
import json
import math
import os

import numpy as np
from scipy import stats

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from post.calibration.data import DataError  # noqa: E402
from post.calibration.single_particle import read_tests, size_classes  # noqa: E402
from post.calibration.strength import size_factor, strength_from_force, survival  # noqa: E402


# ---------------------------------------------------------------------------------------------
# the DEM check: a population of single-grain tests in one run (examples/calibration/in.population)

def rayleigh_time(d, E, nu, density):
    G = E / (2.0 * (1.0 + nu))
    return math.pi * 0.5 * d * math.sqrt(density / G) / (0.1631 * nu + 0.8766)


def population(args):
    p = json.load(open(os.path.join(args.fit, "parameters.json")))
    tests = read_tests(p["data"], tuple(p["grain"]), tuple(p["platen"]))
    diameters = [float(tests["d"][tests["class"] == c].mean()) for c in size_classes(tests)]
    if max(diameters) * (math.sqrt(2.0) - 1.0) >= 0.99 * min(diameters):
        raise DataError("the largest class (%.3g m) is over 2.4 times the smallest (%.3g m): its fragments "
                        "would be large enough to break again in the DEM check" % (max(diameters), min(diameters)))
    os.makedirs(args.out, exist_ok=True)
    n = args.per_size * len(diameters)
    spacing = 12.0 * max(diameters)
    columns = int(math.ceil(math.sqrt(n)))
    with open(os.path.join(args.out, "grains.include"), "w") as f:
        f.write("# %d grains, %d of each size (post/calibrate.py population)\n" % (n, args.per_size))
        tag = 0
        for d in diameters:
            for _ in range(args.per_size):
                x, y = (tag % columns + 0.5) * spacing, (tag // columns + 0.5) * spacing
                tag += 1
                f.write("create_atoms    1 single %.6g %.6g %.6g units box\n" % (x, y, 0.5 * d))
                f.write("set             atom %d diameter %.6g density ${density}\n" % (tag, d))
    F = tests["F_f"]
    grain_E, grain_nu = p["grain"]
    t_r = rayleigh_time(min(diameters), grain_E, grain_nu, args.density)
    dt, tau = 0.2 * t_r, 60.0 * t_r
    F_start, F_end = 0.1 * F.min(), 10.0 * F.max()
    steps = tau * math.log(F_end / F_start) / dt
    chunk = 100
    line = p["fix_crush"].split()
    kw = dict(zip(line[4::2], line[5::2]))
    variables = {
        "grains": "grains.include", "n": n, "E_grain": grain_E, "nu_grain": grain_nu,
        "E_platen": p["platen"][0], "nu_platen": p["platen"][1], "density": args.density,
        "sigma_lim0": kw["sigma_lim0"], "cv": kw["cv"], "weibull_m": kw["weibull_m"], "d0": kw["d0"],
        "scale": kw["scale"], "distribution": args.distribution or kw["distribution"], "seed": args.seed,
        "dmin": 0.99 * min(diameters), "F_start": F_start, "tau": tau, "dt": dt,
        "chunks": int(math.ceil(steps / chunk)), "chunk": chunk,
        "xhi": columns * spacing, "yhi": math.ceil(n / columns) * spacing, "zhi": 3.0 * max(diameters),
    }
    with open(os.path.join(args.out, "variables.txt"), "w") as f:
        f.write(" ".join("-var %s %s" % (k, v) for k, v in variables.items()) + "\n")
    print(" ".join("-var %s %s" % (k, v) for k, v in variables.items()))


def dem_failures(run_dir, variables):
    """(diameter, failure force) of each original grain's event: the push at that step."""
    rows = list(csv.DictReader(open(os.path.join(run_dir, "population_events.csv"))))
    n = int(variables["n"])
    out = [(float(r["diameter"]), float(variables["F_start"]) * math.exp(int(r["step"]) * float(variables["dt"])
                                                                         / float(variables["tau"])))
           for r in rows if int(r["tag"]) <= n]
    return out


def pooled_ks(tests, dem, p):
    """Two-sample KS of the tests' and the DEM's strengths at d0 (eq. 5, then (d/d0)^(3/m))."""
    def at_d0(d, F, E_eff):
        return strength_from_force(F, d, E_eff) / size_factor(d, p["d0"], p["weibull_m"])
    lab = at_d0(tests["d"], tests["F_f"], tests["E_eff"])
    d, F = np.array(dem).T
    return stats.ks_2samp(lab, at_d0(d, F, p["E_eff"]))


def compare(args):
    p = json.load(open(os.path.join(args.fit, "parameters.json")))
    tests = read_tests(args.data, tuple(p["grain"]), tuple(p["platen"]))
    words = open(os.path.join(args.run_dir, "variables.txt")).read().split()
    variables = dict(zip(words[1::3], words[2::3]))
    dem = dem_failures(args.run_dir, variables)
    n = int(variables["n"])
    fig, ax = plt.subplots(figsize=(6, 4.2))
    results = []
    for k, c in enumerate(size_classes(tests)):
        sel = tests["class"] == c
        d = float(tests["d"][sel].mean())
        lab = tests["F_f"][sel]
        model = np.array([F for dd, F in dem if abs(dd - d) < 1e-6 * d])
        if len(model) == 0:
            raise DataError("%s: no grain of d = %.4g m broke in the DEM run" % (args.run_dir, d))
        ks = stats.ks_2samp(lab, model)
        results.append({"size_class": c, "d": d, "lab": len(lab), "dem": len(model),
                        "lab_median_N": float(np.median(lab)), "dem_median_N": float(np.median(model)),
                        "ks": ks.statistic, "ks_p": ks.pvalue})
        for values, style, name in ((lab, "o", "tests"), (model, "-", "DEM")):
            v, ps = survival(values)
            ax.semilogx(v, ps, style, color="C%d" % k, ms=4, drawstyle="steps-post" if style == "-" else None,
                        label="%s, d = %.3g mm" % (name, d * 1e3))
    ax.set_xlabel("failure force F_f (N)")
    ax.set_ylabel("survival probability")
    ax.set_title("DEM (%s) against the tests; KS p: %s" % (
        p["fix_crush"].split("distribution ")[-1], ", ".join("%.2f" % r["ks_p"] for r in results)), fontsize=9)
    ax.legend(fontsize=7)
    fig.tight_layout()
    os.makedirs(args.out, exist_ok=True)
    fig.savefig(os.path.join(args.out, "dem_check.png"), dpi=90)
    plt.close(fig)
    pooled = pooled_ks(tests, dem, p)
    broken = len(dem)
    print("DEM: %d of %d grains broke between F_start = %.3g N and the end of the ramp"
          % (broken, n, float(variables["F_start"])))
    for r in results:
        print("size class %s (d = %.4g m): tests %d, DEM %d; median F_f %.4g N (tests) vs %.4g N (DEM); "
              "KS D = %.3f, p = %.3f" % (r["size_class"], r["d"], r["lab"], r["dem"], r["lab_median_N"],
                                        r["dem_median_N"], r["ks"], r["ks_p"]))
    print("all sizes, strengths brought to d0 by the fitted size effect: KS D = %.3f, p = %.3f"
          % (pooled.statistic, pooled.pvalue))
    json.dump({"broken": broken, "grains": n, "classes": results, "pooled_ks": pooled.statistic,
               "pooled_ks_p": pooled.pvalue}, open(os.path.join(args.out, "dem_check.json"), "w"),
              indent=1)
    print("wrote %s/dem_check.png, dem_check.json" % args.out)
