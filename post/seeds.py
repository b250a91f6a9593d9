#!/usr/bin/python3
"""The seeds of a study gathered: for any CSV with one row a run, the runs grouped into settings by
the columns that define a case, the mean and standard error of every measure over each setting's
seeds, and each setting's change against a reference setting, paired by seed where both ran the
same seeds (the seed fixes the sample and the strengths, so each seed's own difference is free of
their scatter), unpaired otherwise (Welch). One rule for every study and page: a change is resolved
when its 95% Student-t interval excludes zero (paired: df = pairs - 1; unpaired: Welch's df). With
3 seeds that is 4.30 standard errors, with 5 seeds 2.78; "2 standard errors" would be about 82%
confidence with 3 seeds. One implementation for the studies' tables (post/penetration_stats.py,
post/compression_seeds.py and post/critical_state.py use it).

    post/seeds.py STUDY.csv [more.csv ...] --setting COL[,COL...] --measure COL[,COL...]
                  [--seed seed] [--reference COL=VALUE[,COL=VALUE...]] [--markdown] [--csv OUT]

--setting: the columns that define a case (the others are measures, names or bookkeeping); --measure:
the columns to gather; --seed: the column of the seed (default seed); --reference: the setting the
others are compared with (every --setting column it names must match; default the first setting in
the file). A row whose measure is empty or not a number is left out of that measure. Two rows of
one setting and one seed are one run counted twice: the first is kept, and a warning names them.

Output, per setting: its seeds, and per measure the mean, sd and standard error; then per setting
and measure the change against the reference with its standard error, degrees of freedom, 95%
interval and two-sided p (unpaired: Welch, the two standard errors in quadrature; paired: the sd of
the seeds' own differences over sqrt(pairs)), "resolved" where the interval excludes zero, and the
correlation of the two settings over their common seeds (pairing narrows the interval only where it
is positive). One seed has no standard error: "one seed", never resolved; a measure the reference
lacks is "no reference value". Holm's step-down correction (holm()) gives a page's many comparisons
one family-wise 95%.
"""
import argparse
import csv
import math
import sys


def statistics(values):
    """(n, mean, sd, standard error) of values; sd and se are nan for fewer than two."""
    n = len(values)
    if n == 0:
        return 0, float("nan"), float("nan"), float("nan")
    mean = sum(values) / n
    sd = math.sqrt(sum((x - mean) ** 2 for x in values) / (n - 1)) if n > 1 else float("nan")
    return n, mean, sd, sd / math.sqrt(n) if n > 1 else float("nan")


def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return float("nan")


LEVEL = 0.95  # the one confidence level of every interval and "resolved"


def _incomplete_beta(a, b, x):
    """The regularised incomplete beta function I_x(a, b) (continued fraction, Numerical Recipes'
    betacf; converges to 1e-15 within 200 terms for the df of a study)."""
    if x <= 0.0:
        return 0.0
    if x >= 1.0:
        return 1.0
    front = math.exp(math.lgamma(a + b) - math.lgamma(a) - math.lgamma(b) + a * math.log(x) + b * math.log(1.0 - x))
    if x > (a + 1.0) / (a + b + 2.0):
        return 1.0 - _incomplete_beta(b, a, 1.0 - x)
    tiny = 1e-300
    c, d = 1.0, 1.0 - (a + b) * x / (a + 1.0)
    d = 1.0 / (d if abs(d) > tiny else tiny)
    f = d
    for m in range(1, 300):
        for numerator in (m * (b - m) * x / ((a + 2 * m - 1) * (a + 2 * m)),
                          -(a + m) * (a + b + m) * x / ((a + 2 * m) * (a + 2 * m + 1))):
            d = 1.0 + numerator * d
            d = 1.0 / (d if abs(d) > tiny else tiny)
            c = 1.0 + numerator / c
            c = c if abs(c) > tiny else tiny
            f *= c * d
        if abs(c * d - 1.0) < 1e-15:
            break
    return front * f / a


def t_tail(t, df):
    """P(|T| > |t|) for Student's t with df degrees of freedom (df may be fractional: Welch)."""
    return _incomplete_beta(df / 2.0, 0.5, df / (df + t * t))


def t_quantile(df, level=LEVEL):
    """The two-sided critical value: P(|T| > q) = 1 - level (bisection on t_tail)."""
    lo, hi = 0.0, 1.0
    while t_tail(hi, df) > 1.0 - level:
        hi *= 2.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if t_tail(mid, df) > 1.0 - level else (lo, mid)
    return 0.5 * (lo + hi)


def interval(change, se, df):
    """(low, high, p) of a change with its standard error and df; nans where se or df is unknown."""
    if not (math.isfinite(se) and math.isfinite(df) and df > 0):
        return float("nan"), float("nan"), float("nan")
    q = t_quantile(df)
    p = t_tail(change / se, df) if se > 0 else (0.0 if change else 1.0)
    return change - q * se, change + q * se, p


def resolved(change, se, df):
    """'yes' where the 95% t interval of change excludes zero, 'no' where not, 'one seed' where se
    or df is unknown."""
    low, high, _ = interval(change, se, df)
    if not math.isfinite(low):
        return "one seed"
    return "yes" if low > 0 or high < 0 else "no"


def welch(a, b):
    """The unpaired change mean(b) - mean(a) of two value lists: (change, se, Welch's df)."""
    (na, ma, _, ea), (nb, mb, _, eb) = statistics(list(a)), statistics(list(b))
    return mb - ma, math.sqrt(ea ** 2 + eb ** 2), welch_df(ea, na, eb, nb)


def one_sample(values):
    """(mean, se, df) of values against zero: paired differences, each seed's slope."""
    n, mean, _, se = statistics(list(values))
    return mean, se, float(n - 1) if n > 1 else float("nan")


def correlation(x, y):
    """Pearson's r of two equal-length lists (nan under three or without spread)."""
    n = len(x)
    if n < 3:
        return float("nan")
    mx, my = sum(x) / n, sum(y) / n
    sxy = sum((a - mx) * (b - my) for a, b in zip(x, y))
    sxx, syy = sum((a - mx) ** 2 for a in x), sum((b - my) ** 2 for b in y)
    return sxy / math.sqrt(sxx * syy) if sxx > 0 and syy > 0 else float("nan")


def holm(pvalues):
    """Holm's step-down adjusted p-values (same order): a comparison is resolved within its family
    at 95% where its adjusted p < 0.05. Unknown p (nan) stay nan and do not count."""
    known = sorted((p, k) for k, p in enumerate(pvalues) if math.isfinite(p))
    adjusted, running = [float("nan")] * len(pvalues), 0.0
    for rank, (p, k) in enumerate(known):
        running = max(running, min(1.0, (len(known) - rank) * p))
        adjusted[k] = running
    return adjusted


def group(rows, setting, seed="seed", warn=sys.stderr):
    """{setting tuple: {seed: row}} in the order the settings first appear; the first row of a seed
    is kept."""
    out = {}
    for row in rows:
        key = tuple(row.get(c, "") for c in setting)
        seeds = out.setdefault(key, {})
        if row[seed] in seeds:
            if warn:
                warn.write("seeds.py: warning: two rows of setting %s and seed %s: the first is kept\n"
                           % (dict(zip(setting, key)), row[seed]))
            continue
        seeds[row[seed]] = row
    return out


def values_of(by_seed, measure):
    """{seed: value} of one measure, the non-numbers left out."""
    out = dict((s, number(r.get(measure))) for s, r in by_seed.items())
    return dict((s, x) for s, x in out.items() if math.isfinite(x))


def change(reference, other):
    """The change other - reference of two {seed: value}: ((n, mean, sd, se) of each; the unpaired
    change (change, se, Welch's df); the paired one over the common seeds (pairs, mean change, se,
    df, r: the two sides' correlation over them), or None under two common seeds)."""
    a, b = statistics(list(reference.values())), statistics(list(other.values()))
    unpaired = welch(reference.values(), other.values())
    common = [s for s in reference if s in other]
    paired = None
    if len(common) > 1:
        mean, se, df = one_sample([other[s] - reference[s] for s in common])
        paired = (len(common), mean, se, df, correlation([reference[s] for s in common], [other[s] for s in common]))
    return a, b, unpaired, paired


def welch_df(se_a, n_a, se_b, n_b):
    """Welch-Satterthwaite degrees of freedom of two means' difference from their standard errors and
    counts (nan where either has under two values)."""
    if n_a < 2 or n_b < 2 or not (math.isfinite(se_a) and math.isfinite(se_b)):
        return float("nan")
    total = se_a ** 2 + se_b ** 2
    if total == 0:
        return float(n_a + n_b - 2)
    return total ** 2 / (se_a ** 4 / (n_a - 1) + se_b ** 4 / (n_b - 1))


def compare(reference, other):
    """other - reference of two {seed: value}, by the one rule: paired on the common seeds where three
    or more are common and the two sides correlate positively over them (the seed fixes the sample,
    and pairing then removes the scatter they share), else unpaired over every seed (Welch). A dict:
    change, se, df, low, high, p, resolved, pairs, r, design (its words for a page)."""
    _, _, unpaired, paired = change(reference, other)
    if paired and paired[0] >= 3 and math.isfinite(paired[4]) and paired[4] > 0:
        pairs, dx, se, df, r = paired
        design = "paired (%d seeds, r %.2f)" % (pairs, r)
    else:
        (dx, se, df), pairs = unpaired, (paired[0] if paired else len([s for s in reference if s in other]))
        r = paired[4] if paired else float("nan")
        design = "unpaired (Welch" + (", r %.2f over %d common seeds)" % (r, pairs) if math.isfinite(r) else ")")
    low, high, p = interval(dx, se, df)
    return dict(change=dx, se=se, df=df, low=low, high=high, p=p, resolved=resolved(dx, se, df), pairs=pairs, r=r,
                design=design)


def parse_reference(text, setting, groups):
    if not text:
        return next(iter(groups))
    wanted = dict(item.split("=", 1) for item in text.split(","))
    unknown = [k for k in wanted if k not in setting]
    if unknown:
        sys.exit("seeds.py: --reference names %s, not a --setting column (%s)" % (",".join(unknown), ",".join(setting)))
    matches = [key for key in groups if all(key[setting.index(k)] == v for k, v in wanted.items())]
    if len(matches) != 1:
        sys.exit("seeds.py: --reference %s matches %d settings, not one" % (text, len(matches)))
    return matches[0]


def write_csv(path, rows):
    """Rows of dicts, the columns in the order they first appear, numbers to 6 digits."""
    columns = []
    for row in rows:
        columns += [k for k in row if k not in columns]
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns, lineterminator="\n")
        w.writeheader()
        for row in rows:
            w.writerow(dict((k, "%.6g" % v if isinstance(v, float) else v) for k, v in row.items()))


def label(setting, key):
    return " ".join("%s=%s" % (c, v) for c, v in zip(setting, key))


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("studies", nargs="+")
    parser.add_argument("--setting", required=True, help="the columns that define a case, comma-separated")
    parser.add_argument("--measure", required=True, help="the columns to gather, comma-separated")
    parser.add_argument("--seed", default="seed", help="the seed's column (default seed)")
    parser.add_argument("--reference", help="COL=VALUE,...: the setting the others are compared with")
    parser.add_argument("--markdown", action="store_true")
    parser.add_argument("--csv", help="write the changes here")
    a = parser.parse_args(argv)
    rows = []
    for path in a.studies:
        with open(path) as f:
            rows += list(csv.DictReader(f))
    setting, measures = a.setting.split(","), a.measure.split(",")
    missing = [c for c in setting + measures + [a.seed] if rows and c not in rows[0]]
    if not rows or missing:
        sys.exit("seeds.py: %s: %s" % (" ".join(a.studies), "no rows" if not rows else "no column " + ",".join(missing)))
    groups = group(rows, setting, a.seed)
    ref = parse_reference(a.reference, setting, groups)
    sep = " | " if a.markdown else "  "
    print("reference: %s (%d seeds); intervals at %d%% (Student's t)" % (label(setting, ref), len(groups[ref]),
                                                                       round(100 * LEVEL)))
    head = ["setting", "measure", "seeds", "mean", "sd", "se", "change", "se", "df", "95% interval", "p", "resolved",
            "paired change", "se", "df", "95% interval", "p", "resolved (pairs)", "r"]
    print(("| " if a.markdown else "") + sep.join(head) + (" |" if a.markdown else ""))
    if a.markdown:
        print("|" + "---|" * len(head))
    out = []
    for key, by_seed in groups.items():
        for m in measures:
            cells = comparison_cells(setting, key, m, values_of(groups[ref], m), values_of(by_seed, m), key == ref)
            if not cells:
                continue
            print(("| " if a.markdown else "") + sep.join(cells) + (" |" if a.markdown else ""))
            out.append(cells)
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            writer = csv.writer(f, lineterminator="\n")
            writer.writerow(["setting", "measure", "seeds", "mean", "sd", "se", "change", "change_se", "change_df",
                             "change_interval", "change_p", "resolved", "paired_change", "paired_se", "paired_df",
                             "paired_interval", "paired_p", "paired_resolved", "paired_r"])
            writer.writerows(out)


def test_cells(change, se, df):
    """change, se, df, 95% interval, p and resolved, as text."""
    low, high, p = interval(change, se, df)
    return ["%+.4g" % change, "%.3g" % se, "%.3g" % df,
            "%+.4g .. %+.4g" % (low, high) if math.isfinite(low) else "", "%.3g" % p if math.isfinite(p) else "",
            resolved(change, se, df)]


def comparison_cells(setting, key, measure, reference, other, is_reference):
    """One output row: the setting's statistics, its unpaired change against the reference and the
    change paired by seed (empty cells where there is none)."""
    if not other:
        return None
    if reference:
        _, stats, unpaired, paired = change(reference, other)
    else:  # the reference has no value of this measure
        stats, unpaired, paired = statistics(list(other.values())), None, None
    cells = [label(setting, key), measure, "%d" % stats[0], "%.4g" % stats[1], "%.3g" % stats[2], "%.3g" % stats[3]]
    if is_reference:
        cells += [""] * 6
    elif not reference:
        cells += [""] * 5 + ["no reference value"]
    else:
        cells += test_cells(*unpaired)
    if is_reference or paired is None:
        return cells + [""] * 7
    pairs, mean, se, df, r = paired
    test = test_cells(mean, se, df)
    return cells + test[:5] + ["%s (%d)" % (test[5], pairs), "%.3g" % r if math.isfinite(r) else ""]

if __name__ == "__main__":
    main()
