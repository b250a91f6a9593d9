"""Published moduli without strengths (calibrate.py moduli): what a Weibull modulus of the failure
forces or a strength ratio of two sizes says of fix crush's cv and weibull_m, against Table 1."""
import json
import math
import os

from scipy import optimize

from post.calibration.data import DataError, data_rows, positive_number
from post.calibration.strength import TABLE1, strength_cv


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
