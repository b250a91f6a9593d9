"""Published summary statistics (calibrate.py summary): per size class d, n, the Weibull modulus m_t of
the failure forces and F_0 or sigma_0; each class's exact law of strengths, and fix crush's
parameters with intervals from resamples of the classes' sizes."""
import json
import math
import os

import numpy as np
from scipy import special, stats

from post.calibration.data import DataError, data_rows, positive_number
from post.calibration.single_particle import fix_crush_line, point_estimates
from post.calibration.strength import (CONFIDENCE, DEFAULT_GRAIN, DEFAULT_PLATEN, MIN_CLASSES, MIN_GRAINS,
                                       MIN_PER_CLASS, TABLE1, effective_modulus, strength_cv, strength_from_force)


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
