"""Single-particle crushing tests (calibrate.py single-particle): the tests read, the size effect and
the scatter fitted (normal and Weibull) with bootstrap intervals and goodness of fit, the fix crush
line, its figures and report; and tests drawn from known parameters (calibrate.py synthetic)."""
import json
import math
import os

import numpy as np
from scipy import optimize, special, stats

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from post.calibration.data import DataError, data_rows, positive_number  # noqa: E402
from post.calibration.strength import (  # noqa: E402
    CONFIDENCE, DEFAULT_GRAIN, DEFAULT_PLATEN, MIN_CLASSES, MIN_GRAINS, MIN_PER_CLASS, TABLE1, contact_radius_ratio,
    effective_modulus, force_from_strength, size_factor, strength_from_force, survival)


# ---------------------------------------------------------------------------------------------
# reading the tests

def read_tests(path, grain=DEFAULT_GRAIN, platen=DEFAULT_PLATEN):
    """The crushing tests: arrays d, F_f, E_eff and the size-class labels."""
    header, rows = data_rows(path)
    for column in ("d", "F_f"):
        if column not in header:
            raise DataError("%s: no column '%s' in the header (%s); required: d (m), F_f (N)"
                            % (path, column, ",".join(header)))
    d, F, E_eff, labels = [], [], [], []
    for n, row in rows:
        d.append(positive_number(path, n, row, "d"))
        F.append(positive_number(path, n, row, "F_f"))
        moduli = []
        for column, default in (("E_grain", grain[0]), ("nu_grain", grain[1]),
                                ("E_platen", platen[0]), ("nu_platen", platen[1])):
            moduli.append(positive_number(path, n, row, column) if column in header else default)
        for column, nu in (("nu_grain", moduli[1]), ("nu_platen", moduli[3])):
            if nu >= 0.5:
                raise DataError("%s, line %d: %s = %g must be below 0.5" % (path, n, column, nu))
        E_eff.append(effective_modulus(*moduli))
        labels.append(row["size_class"] if "size_class" in header else "%.4g" % d[-1])
    tests = {"d": np.array(d), "F_f": np.array(F), "E_eff": np.array(E_eff), "class": np.array(labels),
             "rows": np.array([n for n, _ in rows])}
    check_amount(path, tests)
    return tests


def size_classes(tests):
    """Class labels ordered by their mean diameter."""
    labels = list(dict.fromkeys(tests["class"]))
    return sorted(labels, key=lambda c: tests["d"][tests["class"] == c].mean())


def check_amount(path, tests):
    n = len(tests["d"])
    classes = size_classes(tests)
    if len(classes) < MIN_CLASSES:
        raise DataError("%s: all %d grains are of one size class (%s m): a size effect needs grains of at "
                        "least %d sizes" % (path, n, classes[0] if classes else "-", MIN_CLASSES))
    for c in classes:
        k = int((tests["class"] == c).sum())
        if k < MIN_PER_CLASS:
            first = tests["rows"][tests["class"] == c][0]
            raise DataError("%s: size class %s (first at line %d) has %d grains: too few for a fit, at "
                            "least %d per class" % (path, c, first, k, MIN_PER_CLASS))
    if n < MIN_GRAINS:
        raise DataError("%s: %d grains: too few for a fit, at least %d" % (path, n, MIN_GRAINS))


# ---------------------------------------------------------------------------------------------
# the fits

def fit_size_effect(d, sigma, d0):
    """log sigma = log A - (3/m) log(d/d0): slope, its standard error and degrees of freedom."""
    r = stats.linregress(np.log(d / d0), np.log(sigma))
    return r.slope, r.stderr, len(d) - 2


def truncated_normal(mu, sd):
    """fix crush's 'normal': N(mu, sd^2) truncated to s > 0."""
    return stats.truncnorm(-mu / sd, np.inf, loc=mu, scale=sd)


def fit_normal(s):
    """Maximum-likelihood (sigma_lim0, cv) of the truncated normal of fix crush."""
    mu0, sd0 = s.mean(), s.std(ddof=0)
    if mu0 > 6.0 * sd0:  # the truncation at 0 holds < 1e-9 of the law: the plain normal's estimates
        return mu0, sd0 / mu0

    def nll(p):  # -log L of N(mu, sd^2) truncated to s > 0: the normal's, over Phi(mu/sd)
        mu, sd = math.exp(p[0]), math.exp(p[1])
        z = (s - mu) / sd
        return 0.5 * np.dot(z, z) + len(s) * (math.log(sd) + special.log_ndtr(mu / sd))
    p = optimize.minimize(nll, [math.log(mu0), math.log(sd0)], method="Nelder-Mead",
                          options={"xatol": 1e-8, "fatol": 1e-8}).x
    mu, sd = math.exp(p[0]), math.exp(p[1])
    return mu, sd / mu


def fit_weibull(s):
    """Weibull shape and scale of the normalised strengths, and its mean."""
    shape, _, scale = stats.weibull_min.fit(s, floc=0.0)
    return shape, scale, scale * math.gamma(1.0 + 1.0 / shape)


def point_estimates(d, sigma, d0):
    slope = fit_size_effect(d, sigma, d0)[0]
    weibull_m = -3.0 / slope if slope < 0 else math.inf
    s = sigma * (d / d0) ** (-slope)  # strengths brought to d0 by the fitted size effect
    mu, cv = fit_normal(s)
    shape, scale, mean = fit_weibull(s)
    return {"slope": slope, "weibull_m": weibull_m, "s": s, "sigma_lim0": mu, "cv": cv,
            "weibull_shape": shape, "weibull_scale": scale, "weibull_mean": mean}


def bootstrap(d, sigma, d0, classes, n_resamples, seed):
    """Percentile intervals of sigma_lim0, cv and the Weibull fit over resampled grains (within each
    size class, so that every resample has the classes of the data)."""
    rng = np.random.default_rng(seed)
    keys = ("sigma_lim0", "cv", "weibull_shape", "weibull_mean")
    draws = {k: [] for k in keys}
    groups = [np.flatnonzero(classes == c) for c in np.unique(classes)]
    for _ in range(n_resamples):
        idx = np.concatenate([rng.choice(g, len(g)) for g in groups])
        e = point_estimates(d[idx], sigma[idx], d0)
        for k in keys:
            draws[k].append(e[k])
    q = [(1 - CONFIDENCE) / 2 * 100, (1 + CONFIDENCE) / 2 * 100]
    return {k: tuple(np.percentile(v, q)) for k, v in draws.items()}


def goodness_of_fit(s, mu, cv, shape, scale, weibull_m):
    """KS and Anderson-Darling statistics (and the log-likelihood) of the fitted laws: the normal,
    the free Weibull, and the Weibull that fix crush draws (shape weibull_m, the fitted mean)."""
    mean = scale * math.gamma(1.0 + 1.0 / shape)
    laws = {"normal": truncated_normal(mu, cv * mu), "weibull": stats.weibull_min(shape, scale=scale),
            "weibull_fix": stats.weibull_min(weibull_m, scale=mean / math.gamma(1.0 + 1.0 / weibull_m))}
    out = {}
    for name, law in laws.items():
        ks = stats.kstest(s, law.cdf)
        u = np.sort(law.cdf(s))
        u = np.clip(u, 1e-300, 1 - 1e-16)
        n = len(u)
        k = np.arange(1, n + 1)
        ad = -n - np.mean((2 * k - 1) * (np.log(u) + np.log(1 - u[::-1])))
        out[name] = {"ks": ks.statistic, "ks_p": ks.pvalue, "ad": ad, "loglik": float(law.logpdf(s).sum())}
    return out


def calibrate(tests, d0=None, scale_factor=1.0, n_resamples=400, seed=2):
    """Every parameter of the fix crush line, with intervals and the fits' statistics."""
    d, sigma = tests["d"], strength_from_force(tests["F_f"], tests["d"], tests["E_eff"])
    d0 = float(np.median(d)) if d0 is None else d0
    est = point_estimates(d, sigma, d0)
    slope, stderr, dof = fit_size_effect(d, sigma, d0)
    t = stats.t.ppf((1 + CONFIDENCE) / 2, dof)
    slope_ci = (slope - t * stderr, slope + t * stderr)
    m_ci = tuple(sorted(-3.0 / b if b < 0 else math.inf for b in slope_ci))
    if slope_ci[1] >= 0:
        m_ci = (-3.0 / slope_ci[0], math.inf)
    boot = bootstrap(d, sigma, d0, tests["class"], n_resamples, seed)
    gof = goodness_of_fit(est["s"], est["sigma_lim0"], est["cv"], est["weibull_shape"], est["weibull_scale"],
                          est["weibull_m"])
    better = "normal" if gof["normal"]["ad"] <= gof["weibull"]["ad"] else "weibull"
    # fix crush's weibull has one modulus for the scatter and the size effect: the line takes the law
    # that fix crush would draw closer to the data (the smaller Anderson-Darling statistic)
    shape_ci = boot["weibull_shape"]
    consistent = bool(shape_ci[0] <= m_ci[1] and m_ci[0] <= shape_ci[1])
    distribution = "weibull" if gof["weibull_fix"]["ad"] < gof["normal"]["ad"] else "normal"
    E_eff = float(np.median(tests["E_eff"]))
    return {
        "grains": int(len(d)), "classes": size_classes(tests), "d0": d0, "scale": scale_factor,
        "weibull_m": est["weibull_m"], "weibull_m_ci": m_ci, "slope": slope, "slope_ci": slope_ci,
        "sigma_lim0": est["sigma_lim0"], "sigma_lim0_ci": boot["sigma_lim0"],
        "cv": est["cv"], "cv_ci": boot["cv"],
        "weibull_shape": est["weibull_shape"], "weibull_shape_ci": boot["weibull_shape"],
        "weibull_mean": est["weibull_mean"], "weibull_mean_ci": boot["weibull_mean"],
        "weibull_scale": est["weibull_scale"], "gof": gof, "better_fit": better,
        "weibull_consistent": consistent, "better_fit_note": "free laws, smaller Anderson-Darling", "distribution": distribution,
        "E_eff": E_eff, "contact_radius_ratio": float(contact_radius_ratio(est["sigma_lim0"], E_eff)),
        "bootstrap_resamples": n_resamples,
    }


def fix_crush_line(p, seed):
    """The fix crush line of the better-fitting law. weibull: one modulus for the scatter and the
    size effect (doc/fix_crush.txt), the size effect's; its mean is sigma_lim0."""
    if p["distribution"] == "weibull":
        s0, cv = p["weibull_mean"], p["cv"]
    else:
        s0, cv = p["sigma_lim0"], p["cv"]
    return ("fix crush all crush sigma_lim0 %.4g cv %.3g weibull_m %.3g d0 %.4g seed %d scale %g distribution %s"
            % (s0, cv, p["weibull_m"], p["d0"], seed, p["scale"], p["distribution"]))


# ---------------------------------------------------------------------------------------------
# figures

def plot_survival(tests, p, path):
    sigma = strength_from_force(tests["F_f"], tests["d"], tests["E_eff"])
    fig, ax = plt.subplots(figsize=(6, 4.2))
    for k, c in enumerate(size_classes(tests)):
        sel = tests["class"] == c
        d = tests["d"][sel].mean()
        v, ps = survival(sigma[sel])
        colour = "C%d" % k
        ax.plot(v / 1e6, ps, "o", color=colour, ms=4, label="d = %.3g mm (%d)" % (d * 1e3, sel.sum()))
        x = np.linspace(0.3 * v.min(), 1.3 * v.max(), 200)
        f = size_factor(d, p["d0"], p["weibull_m"])
        ax.plot(x / 1e6, truncated_normal(p["sigma_lim0"], p["cv"] * p["sigma_lim0"]).sf(x / f), "-", color=colour, lw=1)
        ax.plot(x / 1e6, stats.weibull_min(p["weibull_shape"], scale=p["weibull_scale"]).sf(x / f), "--",
                color=colour, lw=1)
    ax.set_xlabel("strength sigma_lim (MPa), eq. 5 with r' = d/2")
    ax.set_ylabel("survival probability")
    ax.set_title("points: tests; lines: normal (solid), Weibull (dashed)", fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def plot_size_effect(tests, p, path):
    sigma = strength_from_force(tests["F_f"], tests["d"], tests["E_eff"])
    fig, ax = plt.subplots(figsize=(5, 4))
    ax.loglog(tests["d"] * 1e3, sigma / 1e6, "o", ms=3, alpha=0.5, label="grains")
    for c in size_classes(tests):
        sel = tests["class"] == c
        ax.loglog(tests["d"][sel].mean() * 1e3, sigma[sel].mean() / 1e6, "ks", ms=6)
    d = np.geomspace(tests["d"].min() * 0.9, tests["d"].max() * 1.1, 50)
    mean0 = np.exp(np.log(sigma).mean() - p["slope"] * np.log(tests["d"] / p["d0"]).mean())
    for b, style in ((p["slope"], "-"), (p["slope_ci"][0], ":"), (p["slope_ci"][1], ":")):
        ax.loglog(d * 1e3, mean0 * (d / p["d0"]) ** b / 1e6, "k" + style, lw=1)
    ax.set_xlabel("d (mm)")
    ax.set_ylabel("sigma_lim (MPa)")
    ax.set_title("m = %.3g [%.3g, %.3g] (slope -3/m; squares: class means)"
                 % (p["weibull_m"], p["weibull_m_ci"][0], p["weibull_m_ci"][1]), fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


# ---------------------------------------------------------------------------------------------
# single-particle

def report(p, line):
    def ci(k):
        lo, hi = p[k + "_ci"]
        return "[%.4g, %.4g]" % (lo, hi)
    g = p["gof"]
    lines = [
        "grains: %d in %d size classes (%s); d0 = %.4g m; E' (grain on platen) = %.4g Pa"
        % (p["grains"], len(p["classes"]), ", ".join(p["classes"]), p["d0"], p["E_eff"]),
        "size effect: slope of log sigma_lim on log d = %.4g %s -> weibull_m = %.4g %s"
        % (p["slope"], ci("slope"), p["weibull_m"], ci("weibull_m")),
        "normal (fix crush 'normal', truncated to s > 0): sigma_lim0 = %.4g Pa %s, cv = %.4g %s"
        % (p["sigma_lim0"], ci("sigma_lim0"), p["cv"], ci("cv")),
        "Weibull of the strengths at d0: shape %.4g %s, mean %.4g Pa %s"
        % (p["weibull_shape"], ci("weibull_shape"), p["weibull_mean"], ci("weibull_mean")),
        "goodness of fit (strengths at d0): normal KS D = %.3f (p = %.2f), AD = %.3f; weibull KS D = %.3f "
        "(p = %.2f), AD = %.3f -> %s fits better (smaller Anderson-Darling)"
        % (g["normal"]["ks"], g["normal"]["ks_p"], g["normal"]["ad"], g["weibull"]["ks"], g["weibull"]["ks_p"],
           g["weibull"]["ad"], p["better_fit"]),
        "(intervals: %d%%; weibull_m from the regression's t interval, the others from %d bootstrap "
        "resamples; KS p-values are optimistic, the laws being fitted to the same data)"
        % (round(CONFIDENCE * 100), p["bootstrap_resamples"]),
        "contact radius at failure at d0 (eq. 2): r_H/r' = %.2f%s"
        % (p["contact_radius_ratio"], "" if p["contact_radius_ratio"] < 0.5 else
           " (> 0.5: far outside Hertz's small-contact range; eq. 5 is then a formal criterion)"),
        "Table 1 (Fontainebleau NE34): sigma_lim0 = %.3g Pa, cv = %g, weibull_m = %g, d0 = %g m"
        % (TABLE1["sigma_lim0"], TABLE1["cv"], TABLE1["weibull_m"], TABLE1["d0"]),
    ]
    lines.append("fix crush's weibull draws one modulus for the scatter and the size effect: shape %.3g vs "
                 "weibull_m %.3g (intervals %s); that law's AD = %.3f against the normal's %.3f -> the line uses %s"
                 % (p["weibull_shape"], p["weibull_m"], "overlap" if p["weibull_consistent"] else "apart",
                    g["weibull_fix"]["ad"], g["normal"]["ad"], p["distribution"]))
    lines.append(line)
    return "\n".join(lines)


def single_particle(args):
    tests = read_tests(args.data, (args.grain_E, args.grain_nu), (args.platen_E, args.platen_nu))
    p = calibrate(tests, args.d0, args.scale, args.bootstrap, args.seed)
    line = fix_crush_line(p, args.crush_seed)
    print(report(p, line))
    os.makedirs(args.out, exist_ok=True)
    p["fix_crush"] = line
    p["data"] = os.path.abspath(args.data)
    p["grain"] = [args.grain_E, args.grain_nu]
    p["platen"] = [args.platen_E, args.platen_nu]
    json.dump(p, open(os.path.join(args.out, "parameters.json"), "w"), indent=1)
    with open(os.path.join(args.out, "strengths.csv"), "w") as f:
        f.write("line,size_class,d,F_f,E_eff,sigma_lim\n")
        sigma = strength_from_force(tests["F_f"], tests["d"], tests["E_eff"])
        for k in range(len(sigma)):
            f.write("%d,%s,%.6g,%.6g,%.6g,%.6g\n" % (tests["rows"][k], tests["class"][k], tests["d"][k],
                                                     tests["F_f"][k], tests["E_eff"][k], sigma[k]))
    plot_survival(tests, p, os.path.join(args.out, "survival.png"))
    plot_size_effect(tests, p, os.path.join(args.out, "size_effect.png"))
    print("wrote %s/: parameters.json, strengths.csv, survival.png, size_effect.png" % args.out)


# ---------------------------------------------------------------------------------------------
# synthetic

def draw_strengths(rng, n, sigma_lim0, cv, weibull_m, distribution):
    """Strengths s with fix crush's laws: truncated normal (mean parameter sigma_lim0, cv), or
    Weibull of modulus weibull_m and mean sigma_lim0."""
    if distribution == "weibull":
        scale = sigma_lim0 / math.gamma(1.0 + 1.0 / weibull_m)
        return stats.weibull_min(weibull_m, scale=scale).rvs(n, random_state=rng)
    return truncated_normal(sigma_lim0, cv * sigma_lim0).rvs(n, random_state=rng)


def synthetic(args):
    rng = np.random.default_rng(args.seed)
    sizes = [float(v) for v in args.sizes.split(",")]
    E_eff = effective_modulus(args.grain_E, args.grain_nu, args.platen_E, args.platen_nu)
    with open(args.out_csv, "w") as f:
        f.write("# synthetic single-particle crushing tests (post/calibrate.py synthetic): strengths drawn from\n"
                "# distribution %s, sigma_lim0 = %g Pa, cv = %g, weibull_m = %g, d0 = %g m, seed %d, and\n"
                "# F_f from eq. 5 (r' = d/2) for E_grain = %g Pa, nu_grain = %g on E_platen = %g Pa, nu_platen = %g\n"
                % (args.distribution, args.sigma_lim0, args.cv, args.weibull_m, args.d0, args.seed,
                   args.grain_E, args.grain_nu, args.platen_E, args.platen_nu))
        f.write("d,F_f\n")
        for d in sizes:
            s = draw_strengths(rng, args.per_size, args.sigma_lim0, args.cv, args.weibull_m, args.distribution)
            F = force_from_strength(s * size_factor(d, args.d0, args.weibull_m), d, E_eff)
            for v in F:
                f.write("%.6g,%.6g\n" % (d, v))
    print("wrote %s: %d grains at d = %s m" % (args.out_csv, args.per_size * len(sizes), args.sizes))
