"""The model every step of the calibration shares (doc/calibration.md): eq. 4-5 (E' of a grain on a
platen, strength <-> failure force), eq. 6/10 (the size effect), the deck's defaults and Table 1,
the least data of a fit, the cv of a Weibull law of the strengths, and survival curves."""
import math

import numpy as np
from scipy import special


# Table 1 of Ciantia et al. (2014): G = 3 GPa, nu = 0.3 (E = 2 G (1 + nu)); a steel platen.
DEFAULT_GRAIN = (7.8e9, 0.3)
DEFAULT_PLATEN = (210e9, 0.29)
TABLE1 = {"sigma_lim0": 5e9, "cv": 1.0, "weibull_m": 10.0, "d0": 2e-3}
# The least data that a fit is made from: 2 size classes (a size effect), 5 grains in each (a
# survival curve), 15 grains in all (a scatter and its interval).
MIN_CLASSES, MIN_PER_CLASS, MIN_GRAINS = 2, 5, 15
CONFIDENCE = 0.95


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
# the laws of the strengths: shared by several steps

def strength_cv(shape):
    """The cv of a Weibull law of modulus shape."""
    g1, g2 = special.gamma(1 + 1 / shape), special.gamma(1 + 2 / shape)
    return np.sqrt(g2 / g1 ** 2 - 1.0)


def survival(values):
    """Sorted values and their empirical survival probabilities (1 - i/(n+1))."""
    v = np.sort(values)
    return v, 1.0 - np.arange(1, len(v) + 1) / (len(v) + 1.0)
