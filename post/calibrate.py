#!/usr/bin/env python3
"""Calibrating fix crush for another sand (doc/calibration.md): from single-particle crushing tests
to the fix crush line, checked by the DEM, and against an oedometric compression curve.

  calibrate.py single-particle DATA.csv [--d0 D0] [--grain-E E --grain-nu NU] [--platen-E E
                                        --platen-nu NU] [--scale N] [--seed S] [--out DIR]
  calibrate.py synthetic OUT.csv --sigma_lim0 S --cv C --weibull_m M --d0 D0 --sizes D1,D2,...
                                 --per-size N --seed SEED [--distribution normal|weibull]
  calibrate.py summary SUMMARY.csv [--d0 D0] [--grain-E E ...] [--scale N] [--out DIR]
                                 (published summary statistics: per size class d, n, m_t and F_0 or sigma_0)
  calibrate.py moduli MODULI.csv [--out DIR]  (published moduli without strengths, against Table 1)
  calibrate.py population FIT_DIR --per-size N --out DIR      (the grains of the DEM check)
  calibrate.py compare DATA.csv FIT_DIR RUN_DIR [--out DIR]   (DEM failure forces against the data)
  calibrate.py oedometer LAB.csv [--sigma_lim0 S1,S2,..] [--cv C1,C2,..] [--from FIT_DIR]
                                 [--liggghts PATH] [--ranks R] [--sigma_max P] [--out DIR]

Data (single-particle): a CSV with a header and one row per crushed grain; lines starting with '#'
are comments. Columns: d (grain diameter, m) and F_f (force at failure, N), required; E_grain,
nu_grain, E_platen, nu_platen (Pa, -), optional, per row (otherwise --grain-E ... or their defaults);
size_class, optional (a label: grains of one sieve fraction; otherwise grains of equal d form a class).

Data (summary): one row per size class, for papers that give only summary statistics: d (the class's
diameter, m), n (grains tested), m_t (the Weibull modulus of the class's failure forces, or of F/d^2:
the same at one size) and F_0 (the characteristic failure force, 37% survival, N) or sigma_0 (the
characteristic F/d^2, Pa); the moduli columns as above, optional.

Data (moduli): published statistics without strengths, one a row: source, material, quantity (m_t:
the Weibull modulus of the failure forces of one size; strength_ratio: the characteristic F/d^2 of
d_small over that of d_large), low and high (the stated range), d_small and d_large (m, for a ratio).

The model's limit (Ciantia et al. 2014, eq. 5) is a contact stress:
    F_lim = [sigma_lim pi (3 r'/(4 E'))^(2/3)]^3
A grain squeezed between platens touches each as a sphere on a plane (r' = R = d/2), with
E' = ((1 - nu_g^2)/E_g + (1 - nu_p^2)/E_p)^-1 (eq. 4). Hence each failure force gives the strength
    sigma_lim = F_f^(1/3) (4 E'/(3 r'))^(2/3) / pi
and the size effect of fix crush (eq. 6/10: sigma_lim = s (d/(N d0))^(-3/m), s drawn with mean
sigma_lim0) is a straight line of log sigma_lim against log d with slope -3/m. E_g is the modulus of
the grains in the deck (the DEM checks F against F_lim with the deck's E'), not the mineral's."""
import argparse
import csv
import json
import math
import os
import shutil
import subprocess
import sys
import time

import numpy as np
from scipy import optimize, special, stats

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# Table 1 of Ciantia et al. (2014): G = 3 GPa, nu = 0.3 (E = 2 G (1 + nu)); a steel platen.
DEFAULT_GRAIN = (7.8e9, 0.3)
DEFAULT_PLATEN = (210e9, 0.29)
TABLE1 = {"sigma_lim0": 5e9, "cv": 1.0, "weibull_m": 10.0, "d0": 2e-3}
# The least data that a fit is made from: 2 size classes (a size effect), 5 grains in each (a
# survival curve), 15 grains in all (a scatter and its interval).
MIN_CLASSES, MIN_PER_CLASS, MIN_GRAINS = 2, 5, 15
CONFIDENCE = 0.95


class DataError(Exception):
    """Bad input: the message names the file, the row and what is wrong."""


# ---------------------------------------------------------------------------------------------
# eq. 4-5: strength <-> failure force for a grain on a plane

def effective_modulus(E_grain, nu_grain, E_platen, nu_platen):
    """E' of eq. 4 for grain on platen (Pa)."""
    return 1.0 / ((1.0 - nu_grain ** 2) / E_grain + (1.0 - nu_platen ** 2) / E_platen)


def strength_from_force(F_f, d, E_eff):
    """eq. 5 solved for sigma_lim, r' = R = d/2 (Pa)."""
    r = 0.5 * np.asarray(d)
    return np.cbrt(F_f) * (4.0 * E_eff / (3.0 * r)) ** (2.0 / 3.0) / math.pi


def force_from_strength(sigma_lim, d, E_eff):
    """eq. 5, F_lim = [sigma_lim pi (3 r'/(4 E'))^(2/3)]^3 with r' = d/2 (N)."""
    r = 0.5 * np.asarray(d)
    return (np.asarray(sigma_lim) * math.pi) ** 3 * (3.0 * r / (4.0 * E_eff)) ** 2


def contact_radius_ratio(sigma_lim, E_eff):
    """r_H / r' at failure (eq. 2 with F = F_lim): 3 pi sigma_lim / (4 E'). Hertz assumes << 1."""
    return 3.0 * math.pi * np.asarray(sigma_lim) / (4.0 * E_eff)


def size_factor(d, d0, weibull_m, scale_factor=1.0):
    """eq. 6/10: (d/(N d0))^(-3/m)."""
    return (np.asarray(d) / (scale_factor * d0)) ** (-3.0 / weibull_m)


# ---------------------------------------------------------------------------------------------
# reading the tests

def data_rows(path):
    """(line number, row dict) of a CSV with '#' comment lines."""
    try:
        lines = open(path).read().splitlines()
    except OSError as e:
        raise DataError("%s: cannot read (%s)" % (path, e.strerror))
    numbered = [(n + 1, line) for n, line in enumerate(lines) if line.strip() and not line.lstrip().startswith("#")]
    if not numbered:
        raise DataError("%s: no header and no rows" % path)
    header = [h.strip() for h in next(csv.reader([numbered[0][1]]))]
    rows = []
    for n, line in numbered[1:]:
        values = [v.strip() for v in next(csv.reader([line]))]
        if len(values) != len(header):
            raise DataError("%s, line %d: %d values for the %d columns of the header (%s)"
                            % (path, n, len(values), len(header), ",".join(header)))
        rows.append((n, dict(zip(header, values))))
    return header, rows


def number(path, n, row, column):
    try:
        return float(row[column])
    except ValueError:
        raise DataError("%s, line %d: %s = '%s' is not a number" % (path, n, column, row[column]))


def positive_number(path, n, row, column):
    value = number(path, n, row, column)
    if not math.isfinite(value) or value <= 0.0:
        raise DataError("%s, line %d: %s = %s must be positive and finite" % (path, n, column, row[column]))
    return value


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

def survival(values):
    """Sorted values and their empirical survival probabilities (1 - i/(n+1))."""
    v = np.sort(values)
    return v, 1.0 - np.arange(1, len(v) + 1) / (len(v) + 1.0)


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
# summary statistics: a Weibull law of the failure force per size class

def read_summary(path, grain=DEFAULT_GRAIN, platen=DEFAULT_PLATEN):
    """Per size class: arrays d, n, m_t, F_0 and E_eff."""
    header, rows = data_rows(path)
    for column in ("d", "n", "m_t"):
        if column not in header:
            raise DataError("%s: no column '%s' in the header (%s); required: d (m), n, m_t, and F_0 (N) or sigma_0 (Pa)"
                            % (path, column, ",".join(header)))
    if ("F_0" in header) == ("sigma_0" in header):
        raise DataError("%s: give one of the columns F_0 (N) and sigma_0 (Pa, F/d^2), not %s"
                        % (path, "both" if "F_0" in header else "neither"))
    d, n, m_t, F_0, E_eff = [], [], [], [], []
    for line, row in rows:
        d.append(positive_number(path, line, row, "d"))
        k = positive_number(path, line, row, "n")
        if k != int(k) or k < MIN_PER_CLASS:
            raise DataError("%s, line %d: n = %s: too few grains for a fit, at least %d per class"
                            % (path, line, row["n"], MIN_PER_CLASS))
        n.append(int(k))
        m_t.append(positive_number(path, line, row, "m_t"))
        F_0.append(positive_number(path, line, row, "F_0") if "F_0" in header
                   else positive_number(path, line, row, "sigma_0") * d[-1] ** 2)
        moduli = [positive_number(path, line, row, c) if c in header else v
                  for c, v in (("E_grain", grain[0]), ("nu_grain", grain[1]), ("E_platen", platen[0]), ("nu_platen", platen[1]))]
        E_eff.append(effective_modulus(*moduli))
    if len(set(d)) < MIN_CLASSES:
        raise DataError("%s: %d size class(es): a size effect needs at least %d sizes" % (path, len(set(d)), MIN_CLASSES))
    if sum(n) < MIN_GRAINS:
        raise DataError("%s: %d grains in all: too few for a fit, at least %d" % (path, sum(n), MIN_GRAINS))
    return dict((k, np.array(v)) for k, v in (("d", d), ("n", n), ("m_t", m_t), ("F_0", F_0), ("E_eff", E_eff)))


def strength_cv(shape):
    """The cv of a Weibull law of modulus shape."""
    g1, g2 = special.gamma(1 + 1 / shape), special.gamma(1 + 2 / shape)
    return np.sqrt(g2 / g1 ** 2 - 1.0)


def class_strengths(c):
    """The exact law of each class's strengths: F ~ Weibull(m_t, F_0) makes sigma_lim = k(d) F^(1/3)
    (eq. 5 inverted) a Weibull of modulus 3 m_t and scale k F_0^(1/3). Returns its means and cvs."""
    shape = 3.0 * c["m_t"]
    scale = strength_from_force(c["F_0"], c["d"], c["E_eff"])
    return scale * special.gamma(1 + 1 / shape), strength_cv(shape)


def summary_estimates(c, d0):
    """weibull_m from the size effect of the classes' mean strengths (least squares on log mean
    against log d, weighted by n), sigma_lim0 its mean at d0, cv the classes' mean cv (weighted)."""
    mean, cv = class_strengths(c)
    slope, intercept = np.polyfit(np.log(c["d"] / d0), np.log(mean), 1, w=np.sqrt(c["n"]))
    return {"slope": slope, "weibull_m": -3.0 / slope if slope < 0 else math.inf,
            "sigma_lim0": math.exp(intercept), "cv": float(np.average(cv, weights=c["n"])),
            "class_mean": mean, "class_cv": cv}


def summary_calibrate(c, d0=None, scale_factor=1.0, n_resamples=400, seed=2):
    """The parameters from the summary, with intervals from the classes' sizes: each resample draws
    n grains per class from its Weibull law and fits them as single-particle does."""
    d0 = float(np.exp(np.average(np.log(c["d"]), weights=c["n"]))) if d0 is None else d0
    est = summary_estimates(c, d0)
    rng = np.random.default_rng(seed)
    draws = {"sigma_lim0": [], "cv": [], "weibull_m": []}
    for _ in range(n_resamples):
        d = np.repeat(c["d"], c["n"])
        F = np.concatenate([stats.weibull_min(m, scale=F0).rvs(k, random_state=rng)
                            for m, F0, k in zip(c["m_t"], c["F_0"], c["n"])])
        e = point_estimates(d, strength_from_force(F, d, np.repeat(c["E_eff"], c["n"])), d0)
        for k in draws:
            draws[k].append(e[k])
    q = [(1 - CONFIDENCE) / 2 * 100, (1 + CONFIDENCE) / 2 * 100]
    ci = dict((k + "_ci", tuple(np.percentile(v, q))) for k, v in draws.items())
    # fix crush's weibull draws the scatter and the size effect with one modulus: the law a class's
    # strengths follow (modulus 3 m_t) is that one where 3 m_t falls in the size effect's interval
    shape = float(np.average(3.0 * c["m_t"], weights=c["n"]))
    distribution = "weibull" if ci["weibull_m_ci"][0] <= shape <= ci["weibull_m_ci"][1] else "normal"
    p = {"classes": int(len(c["d"])), "grains": int(c["n"].sum()), "d0": d0, "scale": scale_factor,
         "weibull_m": est["weibull_m"], "sigma_lim0": est["sigma_lim0"], "cv": est["cv"],
         "weibull_mean": est["sigma_lim0"], "strength_modulus": shape, "distribution": distribution,
         "class_mean": est["class_mean"].tolist(), "class_cv": est["class_cv"].tolist(),
         "bootstrap_resamples": n_resamples}
    p.update(ci)
    return p


def summary(args):
    c = read_summary(args.data, (args.grain_E, args.grain_nu), (args.platen_E, args.platen_nu))
    p = summary_calibrate(c, args.d0, args.scale, args.bootstrap, args.seed)
    line = fix_crush_line(p, args.crush_seed)
    lines = ["calibrate.py summary: %d size classes, %d grains (%s)" % (p["classes"], p["grains"], args.data)]
    for d, k, m, mean, cv in zip(c["d"], c["n"], c["m_t"], p["class_mean"], p["class_cv"]):
        lines.append("  d = %.4g m, %d grains, m_t %.3g: mean sigma_lim %.4g Pa, cv %.3f (a Weibull of modulus %.3g)"
                     % (d, k, m, mean, cv, 3 * m))
    lines.append("weibull_m %.3g (%.3g - %.3g), sigma_lim0 %.4g Pa at d0 = %.4g m (%.4g - %.4g), cv %.3f (%.3f - %.3f),"
                 " %d%% intervals from %d resamples of the classes' sizes"
                 % (p["weibull_m"], p["weibull_m_ci"][0], p["weibull_m_ci"][1], p["sigma_lim0"], p["d0"],
                    p["sigma_lim0_ci"][0], p["sigma_lim0_ci"][1], p["cv"], p["cv_ci"][0], p["cv_ci"][1],
                    100 * CONFIDENCE, p["bootstrap_resamples"]))
    lines.append("against Table 1 (sigma_lim0 %.3g Pa, cv %g, weibull_m %g, d0 %g m): sigma_lim0 at Table 1's d0 %.4g Pa"
                 % (TABLE1["sigma_lim0"], TABLE1["cv"], TABLE1["weibull_m"], TABLE1["d0"],
                    p["sigma_lim0"] * (TABLE1["d0"] / p["d0"]) ** (-3.0 / p["weibull_m"])))
    lines.append(line)
    print("\n".join(lines))
    os.makedirs(args.out, exist_ok=True)
    p["fix_crush"] = line
    json.dump(p, open(os.path.join(args.out, "parameters.json"), "w"), indent=1)
    print("wrote %s/parameters.json" % args.out)


# ---------------------------------------------------------------------------------------------
# published moduli without strengths: the scatter and the size effect, against Table 1

def m_t_of_cv(cv):
    """The Weibull modulus of the failure forces whose strengths (modulus 3 m_t) have this cv."""
    return optimize.brentq(lambda k: strength_cv(k) - cv, 0.05, 1e3) / 3.0


def weibull_m_of_ratio(ratio, d_small, d_large):
    """weibull_m from the ratio of the characteristic F/d^2 of d_small to that of d_large: F/d^2 ~
    d^-b makes sigma_lim ~ (F/d^2)^(1/3) ~ d^(-b/3) (eq. 5 inverted) = d^(-3/m)."""
    return 9.0 * math.log(d_large / d_small) / math.log(ratio)


def ratio_of_weibull_m(weibull_m, d_small, d_large):
    return (d_large / d_small) ** (9.0 / weibull_m)


def read_moduli(path):
    """Rows of published statistics: source, material, quantity (m_t or strength_ratio), low, high,
    and for strength_ratio the sizes d_small, d_large (m)."""
    header, rows = data_rows(path)
    for column in ("source", "material", "quantity", "low", "high", "d_small", "d_large"):
        if column not in header:
            raise DataError("%s: no column '%s' in the header (%s)" % (path, column, ",".join(header)))
    out = []
    for line, row in rows:
        q = row["quantity"]
        if q not in ("m_t", "strength_ratio"):
            raise DataError("%s, line %d: quantity = '%s': expected m_t (Weibull modulus of the failure forces at one "
                            "size) or strength_ratio (characteristic F/d^2 of d_small over that of d_large)" % (path, line, q))
        low, high = positive_number(path, line, row, "low"), positive_number(path, line, row, "high")
        if high < low:
            raise DataError("%s, line %d: high = %s is below low = %s" % (path, line, row["high"], row["low"]))
        r = {"source": row["source"], "material": row["material"], "quantity": q, "low": low, "high": high}
        if q == "strength_ratio":
            r["d_small"] = positive_number(path, line, row, "d_small")
            r["d_large"] = positive_number(path, line, row, "d_large")
            if r["d_large"] <= r["d_small"]:
                raise DataError("%s, line %d: d_large = %s must exceed d_small = %s" % (path, line, row["d_large"], row["d_small"]))
            if low <= 1.0:
                raise DataError("%s, line %d: low = %s: a strength ratio of the smaller size over the larger is above 1"
                                % (path, line, row["low"]))
        out.append(r)
    return out


def place_modulus(r):
    """What one published statistic says of fix crush's cv and weibull_m, and Table 1 in its terms."""
    if r["quantity"] == "m_t":
        # a class's strengths are a Weibull of modulus 3 m_t (class_strengths); Weibull's own size
        # effect (characteristic F/d^2 ~ d^(-3/m_t), McDowell & Amon 2000) is weibull_m = 3 m_t
        return {"cv": (float(strength_cv(3 * r["high"])), float(strength_cv(3 * r["low"]))),
                "weibull_m": (3 * r["low"], 3 * r["high"]),
                "table1": {"m_t": m_t_of_cv(TABLE1["cv"])}}
    m = (weibull_m_of_ratio(r["high"], r["d_small"], r["d_large"]),
         weibull_m_of_ratio(r["low"], r["d_small"], r["d_large"]))
    return {"weibull_m": m,
            "table1": {"strength_ratio": ratio_of_weibull_m(TABLE1["weibull_m"], r["d_small"], r["d_large"])}}


def published_moduli(args):
    placed = []
    print("calibrate.py moduli: published statistics against Table 1 (cv %g, weibull_m %g) (%s)"
          % (TABLE1["cv"], TABLE1["weibull_m"], args.data))
    for r in read_moduli(args.data):
        p = place_modulus(r)
        p.update(r)
        placed.append(p)
        span = "%g" % r["low"] if r["low"] == r["high"] else "%g - %g" % (r["low"], r["high"])
        print("%s (%s): %s %s" % (r["source"], r["material"], r["quantity"], span))
        if r["quantity"] == "m_t":
            print("  scatter: strengths a Weibull of modulus %s, cv %.3f - %.3f; Table 1's cv %g is m_t %.3g"
                  % ("%g" % (3 * r["low"]) if r["low"] == r["high"] else "%g - %g" % (3 * r["low"], 3 * r["high"]),
                     p["cv"][0], p["cv"][1], TABLE1["cv"], p["table1"]["m_t"]))
            print("  size effect if Weibull's (F/d^2 ~ d^(-3/m_t)): weibull_m %.3g - %.3g (Table 1: %g)"
                  % (p["weibull_m"][0], p["weibull_m"][1], TABLE1["weibull_m"]))
        else:
            print("  size effect over %.3g - %.3g m: weibull_m %.3g - %.3g; Table 1's weibull_m %g is a ratio of %.3g"
                  % (r["d_small"], r["d_large"], p["weibull_m"][0], p["weibull_m"][1], TABLE1["weibull_m"],
                     p["table1"]["strength_ratio"]))
    print("sigma_lim0 is not placed: a modulus carries no strength; find it from a compression curve (oedometer)")
    os.makedirs(args.out, exist_ok=True)
    json.dump(placed, open(os.path.join(args.out, "moduli.json"), "w"), indent=1)
    print("wrote %s/moduli.json" % args.out)


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


# ---------------------------------------------------------------------------------------------
# oedometer: O-2 (examples/fontainebleau/in.oedometer) for a grid of (sigma_lim0, cv)

def finite_number(path, n, row, column):
    value = number(path, n, row, column)
    if not math.isfinite(value):
        raise DataError("%s, line %d: %s = %s must be finite" % (path, n, column, row[column]))
    return value


def read_curve(path, stress="sigma_v", ratio="e", booked=False):
    """sigma and e of a compression curve. A lab's e is positive; a run's booked e (booked=True) may
    not be: its removed volume, counted as solid, can outgrow the void space (doc/design.md, 8)."""
    header, rows = data_rows(path)
    for column in (stress, ratio):
        if column not in header:
            raise DataError("%s: no column '%s' in the header (%s)" % (path, column, ",".join(header)))
    s = np.array([positive_number(path, n, r, stress) for n, r in rows])
    e = np.array([(finite_number if booked else positive_number)(path, n, r, ratio) for n, r in rows])
    return s, e


def overbooked_at(s, e):
    """The first stress at which a run's booked void ratio is no longer positive (None if never)."""
    gone = np.nonzero(e <= 0.0)[0]
    return float(s[gone[0]]) if len(gone) else None


def yield_and_slope(s, e, low, high):
    """Bilinear fit of e against log10 sigma_v (doc/accuracy_vs_cost.md): lines fitted to the ranges
    low and high (Pa); returns the yield stress (their intersection) and the slope of the second
    (the normal compression line, de/dlog10 sigma)."""
    lo = (s >= low[0]) & (s <= low[1])
    hi = (s >= high[0]) & (s <= high[1])
    if lo.sum() < 2 or hi.sum() < 2:
        return math.nan, math.nan
    a1, b1 = np.polyfit(np.log10(s[lo]), e[lo], 1)
    a2, b2 = np.polyfit(np.log10(s[hi]), e[hi], 1)
    return 10 ** ((b1 - b2) / (a2 - a1)), a2


def fit_ranges(s_lab):
    """The paper's ranges (0.3-3 MPa, 50-100 MPa), scaled to a lab curve that ends elsewhere: the
    first decade above the lab's start and the top half of its last decade."""
    smax, smin = s_lab.max(), s_lab.min()
    if smax >= 1e8 and smin <= 3e5:
        return (3e5, 3e6), (5e7, 1e8)
    return (smin * 1.01, smin * 10.0), (0.5 * smax, smax)


def run_oedometer(args, sigma_lim0, cv, weibull_m, d0, folder):
    """One O-N run in folder (a copy of examples/fontainebleau with in.grains' cv, weibull_m, d0
    replaced); its history (sigma_z, void_ratio) and wall-clock seconds."""
    source = os.path.join(REPO, "examples", "fontainebleau")
    if os.path.isdir(folder):
        shutil.rmtree(folder)
    shutil.copytree(source, folder)
    grains = os.path.join(folder, "in.grains")
    text = open(grains).read()
    old = "cv 1 weibull_m 10 d0 2e-3"
    if old not in text:
        raise DataError("%s: the fix crush line no longer reads '%s'" % (grains, old))
    open(grains, "w").write(text.replace(old, "cv %g weibull_m %g d0 %g" % (cv, weibull_m, d0)))
    cmd = args.command.format(liggghts=args.liggghts, ranks=args.ranks, N=args.N, sigma_lim0=sigma_lim0,
                              sigma_max=args.sigma_max).split()
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    start = time.time()
    with open(os.path.join(folder, "screen.txt"), "w") as screen:
        rc = subprocess.call(cmd, cwd=folder, stdout=screen, stderr=subprocess.STDOUT, env=env)
    seconds = time.time() - start
    if rc != 0:
        raise DataError("the run in %s failed (exit %d): %s" % (folder, rc, " ".join(cmd)))
    history = os.path.join(folder, "history_O%s.csv" % args.N)
    s, e = read_curve(history, "sigma_z", "void_ratio", booked=True)
    return s, e, seconds


def oedometer(args):
    s_lab, e_lab = read_curve(args.lab)
    weibull_m, d0 = args.weibull_m, args.d0
    if args.fit:
        p = json.load(open(os.path.join(args.fit, "parameters.json")))
        weibull_m, d0 = p["weibull_m"], p["d0"]
    low, high = fit_ranges(s_lab)
    y_lab, c_lab = yield_and_slope(s_lab, e_lab, low, high)
    print("lab: yield stress %.4g Pa, NCL slope de/dlog10(sigma_v) = %.4g (lines on %.3g-%.3g and %.3g-%.3g Pa)"
          % (y_lab, c_lab, low[0], low[1], high[0], high[1]))
    grid = [(float(s), float(c)) for s in args.sigma_lim0.split(",") for c in args.cv.split(",")]
    print("search: %d runs (sigma_lim0 in %s Pa x cv in %s), weibull_m = %g, d0 = %g m; command: %s"
          % (len(grid), args.sigma_lim0, args.cv, weibull_m, d0, args.command))
    os.makedirs(args.out, exist_ok=True)
    runs = []
    for k, (s0, cv) in enumerate(grid):
        s, e, seconds = run_oedometer(args, s0, cv, weibull_m, d0, os.path.join(args.out, "run_%d" % k))
        y, c = yield_and_slope(s, e, low, high)
        overbooked = overbooked_at(s, e)
        # a cascade's curve past zero booked porosity is not a result, however well it fits
        err = math.hypot(math.log(y / y_lab), (c - c_lab) / c_lab) if math.isfinite(y) and overbooked is None else math.inf
        runs.append({"sigma_lim0": s0, "cv": cv, "yield": y, "slope": c, "seconds": seconds, "misfit": err,
                     "overbooked_at": overbooked, "s": s, "e": e})
        print("run %d: sigma_lim0 = %.4g Pa, cv = %g: yield %.4g Pa (lab %.4g), slope %.4g (lab %.4g), misfit %.3g, %.1f s"
              % (k, s0, cv, y, y_lab, c, c_lab, err, seconds))
        if overbooked is not None:
            print("run %d: the booked void ratio reaches %.3g (<= 0 from %.4g Pa): the removed volume outgrows "
                  "the void space (a cascade, doc/design.md section 8); not a candidate" % (k, e.min(), overbooked))
    total = sum(r["seconds"] for r in runs)
    print("search: %d runs, %.1f s in all, %.1f s a run" % (len(runs), total, total / len(runs)))
    candidates = [r for r in runs if math.isfinite(r["misfit"])]
    best = min(candidates, key=lambda r: r["misfit"]) if candidates else None
    if best is not None:
        print("best: sigma_lim0 = %.4g Pa, cv = %g (misfit %.3g: |log yield ratio| and relative slope error, "
              "combined)" % (best["sigma_lim0"], best["cv"], best["misfit"]))
    keys = ("sigma_lim0", "cv", "yield", "slope", "seconds", "misfit", "overbooked_at")
    json.dump({"lab_yield": y_lab, "lab_slope": c_lab,
               "best": {k: best[k] for k in ("sigma_lim0", "cv", "yield", "slope")} if best else None,
               "runs": [{k: (r[k] if r[k] != math.inf else None) for k in keys} for r in runs]},
              open(os.path.join(args.out, "oedometer.json"), "w"), indent=1)
    fig, ax = plt.subplots(figsize=(6, 4.2))
    ax.semilogx(s_lab / 1e6, e_lab, "ko", ms=4, label="lab")
    for r in runs:
        ax.semilogx(r["s"] / 1e6, r["e"], "-" if r["overbooked_at"] is None else ":", lw=2 if r is best else 0.8,
                    label="sigma_lim0 %.3g GPa, cv %g%s" % (r["sigma_lim0"] / 1e9, r["cv"],
                                                          "" if r["overbooked_at"] is None else " (booked e <= 0)"))
    ax.set_xlabel("sigma_v (MPa)")
    ax.set_ylabel("void ratio e")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "oedometer.png"), dpi=90)
    plt.close(fig)
    print("wrote %s/oedometer.json, oedometer.png" % args.out)
    if best is None:
        raise DataError("no run of the grid is a candidate (each lacks a yield or books more solid than the "
                        "box holds); widen --sigma_lim0 and --cv")


# ---------------------------------------------------------------------------------------------

def parser():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = ap.add_subparsers(dest="command_name", required=True)

    def command(name, help):
        return sub.add_parser(name, help=help, formatter_class=argparse.ArgumentDefaultsHelpFormatter)

    def moduli(p):
        p.add_argument("--grain-E", type=float, default=DEFAULT_GRAIN[0], help="grain Young's modulus (Pa) of the deck")
        p.add_argument("--grain-nu", type=float, default=DEFAULT_GRAIN[1], help="grain Poisson ratio of the deck")
        p.add_argument("--platen-E", type=float, default=DEFAULT_PLATEN[0], help="platen Young's modulus (Pa)")
        p.add_argument("--platen-nu", type=float, default=DEFAULT_PLATEN[1], help="platen Poisson ratio")

    sp = command("single-particle", "fit fix crush's parameters to crushing tests")
    sp.add_argument("data", help="CSV: one grain a row, columns d (m), F_f (N); optional E_grain, nu_grain, E_platen, nu_platen, size_class")
    sp.add_argument("--d0", type=float, default=None, help="reference diameter (m; default: the median size)")
    sp.add_argument("--scale", type=float, default=1.0, help="the deck's upscaling factor N (scale keyword)")
    sp.add_argument("--bootstrap", type=int, default=400, help="bootstrap resamples for the intervals")
    sp.add_argument("--seed", type=int, default=2, help="seed of the bootstrap")
    sp.add_argument("--crush-seed", type=int, default=15485863, help="seed written in the fix crush line")
    sp.add_argument("--out", default="calibration", help="folder for parameters.json and the figures")
    moduli(sp)
    sp.set_defaults(run=single_particle)

    su = command("summary", "fix crush's parameters from published summary statistics per size")
    su.add_argument("data", help="CSV: one size class a row, columns d (m), n, m_t, and F_0 (N) or sigma_0 (Pa)")
    su.add_argument("--d0", type=float, default=None, help="reference diameter (m; default: the classes' geometric mean)")
    su.add_argument("--scale", type=float, default=1.0, help="the deck's upscaling factor N (scale keyword)")
    su.add_argument("--bootstrap", type=int, default=400, help="resamples for the intervals")
    su.add_argument("--seed", type=int, default=2, help="seed of the resamples")
    su.add_argument("--crush-seed", type=int, default=15485863, help="seed written in the fix crush line")
    su.add_argument("--out", default="calibration", help="folder for parameters.json and the figures")
    moduli(su)
    su.set_defaults(run=summary)

    mo = command("moduli", "published Weibull moduli and size ratios (no strengths) against Table 1")
    mo.add_argument("data", help="CSV: source, material, quantity (m_t or strength_ratio), low, high, d_small, d_large")
    mo.add_argument("--out", default="moduli", help="folder for moduli.json")
    mo.set_defaults(run=published_moduli)

    sy = command("synthetic", "draw tests from known parameters")
    sy.add_argument("out_csv", help="the CSV to write (d, F_f)")
    for name in ("--sigma_lim0", "--cv", "--weibull_m", "--d0"):
        sy.add_argument(name, type=float, required=True)
    sy.add_argument("--sizes", required=True, help="diameters (m), comma-separated")
    sy.add_argument("--per-size", type=int, required=True, help="grains per size class")
    sy.add_argument("--seed", type=int, required=True, help="seed of the draws")
    sy.add_argument("--distribution", choices=("normal", "weibull"), default="normal", help="law of the strengths")
    moduli(sy)
    sy.set_defaults(run=synthetic)

    po = command("population", "grains and variables of the DEM check")
    po.add_argument("fit", help="the --out folder of single-particle")
    po.add_argument("--per-size", type=int, default=30, help="grains per size class")
    po.add_argument("--density", type=float, default=2650.0, help="grain density (kg/m^3)")
    po.add_argument("--seed", type=int, default=15485863, help="fix crush's seed in the run")
    po.add_argument("--distribution", default=None, help="instead of the fitted line's (e.g. constant)")
    po.add_argument("--out", default="population", help="folder for grains.include and variables.txt")
    po.set_defaults(run=population)

    co = command("compare", "DEM failure forces against the tests")
    co.add_argument("data", help="the tests' CSV (as for single-particle)")
    co.add_argument("fit", help="the --out folder of single-particle")
    co.add_argument("run_dir", help="the folder of the DEM run (population's --out)")
    co.add_argument("--out", default=None, help="default: the run's folder")
    co.set_defaults(run=compare)

    oe = command("oedometer", "O-N runs for a grid of (sigma_lim0, cv) against a lab curve")
    oe.add_argument("lab", help="CSV with columns sigma_v (Pa), e")
    oe.add_argument("--sigma_lim0", default="2.5e9,5e9,1e10", help="candidate values (Pa), comma-separated")
    oe.add_argument("--cv", default="0.5,1", help="candidate values, comma-separated")
    oe.add_argument("--weibull_m", type=float, default=10.0, help="size effect modulus of the runs")
    oe.add_argument("--d0", type=float, default=2e-3, help="reference diameter (m) of the runs")
    oe.add_argument("--from", dest="fit", default=None, help="take weibull_m and d0 from a single-particle fit")
    oe.add_argument("--N", default="2", help="the upscaling factor of the run (O-N)")
    oe.add_argument("--sigma_max", type=float, default=1e8, help="largest vertical stress of the runs (Pa)")
    oe.add_argument("--ranks", type=int, default=2, help="MPI ranks of each run")
    oe.add_argument("--liggghts", default=os.path.join(REPO, "build", "liggghts"), help="the executable")
    oe.add_argument("--command", default="mpirun -np {ranks} --oversubscribe {liggghts} -in in.oedometer -var N {N} "
                    "-var sigma_lim0 {sigma_lim0} -var sigma_max {sigma_max} -log log.liggghts",
                    help="the run's command line ({liggghts} {ranks} {N} {sigma_lim0} {sigma_max} filled in)")
    oe.add_argument("--out", default="oedometer", help="folder for the runs, oedometer.json and the figure")
    oe.set_defaults(run=oedometer)
    return ap


def main(argv):
    args = parser().parse_args(argv)
    if getattr(args, "out", "") is None:
        args.out = args.run_dir
    try:
        args.run(args)
    except DataError as e:
        print("calibrate.py: error: %s" % e, file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
