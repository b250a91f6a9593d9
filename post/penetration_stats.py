#!/usr/bin/python3
"""The seeds of a penetration study gathered: per setting (every column of scripts/penetration_study.sh's
study.csv that defines a case: all but the case's name, its seed and what the run measured; tip_shape,
sigma_lim0, neighbor_style and extra, the case's other in.cone / in.chamber variables, tell the pile
from the cone and the weak sand from Table 1's), the number of seeds, the mean of q_c with its sd and
standard error, and the means of the events, the inertial numbers, the kinetic energy's share, the
steps and the time; then, for --vary FIELD, the change of q_c between settings that differ in FIELD
alone (a numeric field's values in turn; a named field's every pair: crushing 0 -> 1, 0 -> region,
1 -> region), with its standard error, Welch's df, its 95% Student-t interval and p, and whether it
is resolved (the interval excludes zero: post/seeds.py's one rule); where both
ran the same seeds, the change paired by seed too (each seed's own difference, free of the chambers'
scatter); for --fit-log2 FIELD, the slope of q_c against log2 FIELD over all the runs of the
settings that differ in FIELD alone, one intercept per seed (ordinary least squares), with its
standard error; --members lists the cases of each setting; --versus A B compares two sets of cases
named by patterns (fnmatch: 'refined_N34_w10_s*' against 'rate_v0.25_s*'), settings that differ in
more than one field (D_c / d50 with the velocity that keeps the inertial number, a refined chamber
against a uniform one): the means, their difference with the unpaired standard error (Welch), its
interval and whether it is resolved, and a field of the study (--field, default q_c_MPa);
--ratio A B gives B's mean over A's with its standard error, and each seed's own ratio where both ran
it (the density effect: dense over loose); --fit-power FIELD the exponent of q_c against a numeric
field (the stress exponent: log q_c against log sigma_v, a factor per seed) and, over three levels or
more, each seed's exponent between neighbouring levels and its change from one step to the next.

    post/penetration_stats.py study.csv [more.csv ...] [--vary v] [--vary crushing] [--fit-log2 v]
                              [--fit-power sigma_v] [--members] [--markdown] [--versus A B]
                              [--ratio A B] [--field q_c_MPa]

--versus and --ratio stop, naming the columns that vary, where one side's pattern matches cases of
more than one setting (each side must be one setting; the two sides may differ as the comparison
intends). The output-only variables of extra (OUTPUT_ONLY: stress_every, vtk, ...) define no setting.
Rows without a defining column (an older study.csv) take in.cone's default for it (DEFAULTS). Two
rows of one setting and one seed are one run (a case run under two names): the first is kept, and
a warning names them where their q_c differ, the sign of a column that should tell them apart.
"""
import argparse
import csv
import fnmatch
import math
import os
import sys

if not __package__:  # run as a file (python3 post/penetration_stats.py): the folder above post/ holds the package
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from post.seeds import interval, number, statistics, welch_df  # noqa: E402,F401
from post.seeds import resolved as is_resolved  # noqa: E402  (the studies' one rule: the 95% t interval)

SETTING = ["density", "N", "crushing", "v", "width", "ranks", "distribution", "sigma_v", "fragment_density", "depth",
           "tip_shape", "sigma_lim0", "neighbor_style", "extra"]
# in.cone's defaults (sigma_lim0: in.grains', Table 1), for rows of CSVs written before these columns
DEFAULTS = {"tip_shape": "cone", "sigma_lim0": "5e9", "neighbor_style": "multi", "extra": ""}
# in.cone's variables that change what a test writes, not what it measures: they never split a setting
OUTPUT_ONLY = ("stress_every", "vtk", "vtk_every", "output_every", "progress_every", "checkpoint_every", "label")
MEANS = ["q_c_MPa", "events", "events_loaded", "I_tip", "I_chamber", "ke_share", "steps", "seconds", "particles", "grains",
         "I_G_near", "I_G_near0", "chamber_events"]


def defining_extra(extra):
    """The name=value pairs of a row's extra (',' or ';' between them) that define the test: the
    output-only ones dropped, the rest in order of name."""
    pairs = [p for p in extra.replace(";", ",").split(",") if p.strip()]
    return ",".join(sorted(p.strip() for p in pairs if p.split("=", 1)[0].strip() not in OUTPUT_ONLY))


def setting_of(row):
    values = dict((k, row.get(k) or DEFAULTS.get(k, "")) for k in SETTING)
    values["extra"] = defining_extra(values["extra"])
    return tuple(values[k] for k in SETTING)


def all_groups(rows):
    """{setting tuple: [every row of it]} in the order the settings first appear."""
    out = {}
    for row in rows:
        out.setdefault(setting_of(row), []).append(row)
    return out


def one_per_seed(members):
    """The first row of each seed (a case run twice under two names, e.g. rate_v0.5_s1 and
    dense_region_s1, is one run); warns where the rows of a seed differ in q_c: not one run."""
    kept = {}
    for row in members:
        first = kept.setdefault(row["seed"], row)
        if first is not row and first["q_c_MPa"] != row["q_c_MPa"]:
            sys.stderr.write("penetration_stats.py: warning: %s and %s share every setting and seed %s but not q_c"
                             " (%s against %s MPa): %s is kept; is a column that tells them apart missing?\n"
                             % (first["case"], row["case"], row["seed"], first["q_c_MPa"], row["q_c_MPa"], first["case"]))
    return list(kept.values())


def groups(rows):
    """{setting tuple: [rows]}, one row per seed."""
    return dict((setting, one_per_seed(members)) for setting, members in all_groups(rows).items())


def summarise(rows):
    stats = {}
    for field in MEANS:
        values = [number(r.get(field, "nan")) for r in rows]
        values = [x for x in values if math.isfinite(x)]
        stats[field] = statistics(values) if values else (0, float("nan"), float("nan"), float("nan"))
    stats["seeds"] = ",".join(r["seed"] for r in rows)
    return stats


def verdict(change, se, df):
    """A comparison's words: its 95% interval, p and whether it is resolved (post/seeds.py's rule)."""
    low, high, p = interval(change, se, df)
    if not math.isfinite(low):
        return "resolved: one seed"
    return "95%% interval %+.3g .. %+.3g, p %.2g, resolved: %s" % (low, high, p, is_resolved(change, se, df))


def paired_change(first, second):
    """(n, mean, sd, se) of q_c(second) - q_c(first) over the seeds both ran, or None: the seed fixes
    the chamber and the strengths, so the pair's difference is free of their scatter."""
    a = dict((r["seed"], number(r["q_c_MPa"])) for r in first)
    b = dict((r["seed"], number(r["q_c_MPa"])) for r in second)
    common = [seed for seed in a if seed in b]
    return statistics([b[seed] - a[seed] for seed in common]) if len(common) > 1 else None


def fit_log2(points):
    """(runs, seeds, slope, se) of y = a_seed + slope log2 x over (seed, x, y) points, ordinary least
    squares with one intercept per seed: within each seed x and y less their means, the slope their
    regression through the origin; the residuals' variance over runs - seeds - 1 degrees of freedom.
    None where no seed ran two values of x."""
    by_seed = {}
    for seed, x, y in points:
        by_seed.setdefault(seed, []).append((math.log2(x), y))
    centred = []
    for values in by_seed.values():
        mx, my = (sum(v[k] for v in values) / len(values) for k in (0, 1))
        centred += [(x - mx, y - my) for x, y in values]
    sxx = sum(x * x for x, _ in centred)
    if sxx == 0:
        return None
    slope = sum(x * y for x, y in centred) / sxx
    dof = len(centred) - len(by_seed) - 1
    rss = sum((y - slope * x) ** 2 for x, y in centred)
    return len(centred), len(by_seed), slope, math.sqrt(rss / dof / sxx) if dof > 0 else float("nan")


def ratio(first, second):
    """The ratio of second's mean to first's, each (n, mean, sd, se), with its standard error to first
    order (the relative errors added in quadrature)."""
    (_, m1, _, se1), (_, m2, _, se2) = first, second
    r = m2 / m1
    return r, abs(r) * math.sqrt((se1 / m1) ** 2 + (se2 / m2) ** 2)


def label(setting, skip=()):
    return " ".join("%s=%s" % (k, v) for k, v in zip(SETTING, setting) if k not in skip and (k != "extra" or v))


def families(table, field):
    """[(settings)] of the table that differ in field alone, two or more of them, field's value sorted:
    numbers in order, names after them in alphabetical order."""
    at = SETTING.index(field)
    others = {}
    for setting in table:
        others.setdefault(setting[:at] + setting[at + 1:], []).append(setting)
    key = lambda m: (0, number(m[at]), "") if math.isfinite(number(m[at])) else (1, 0.0, m[at])  # noqa: E731
    return [sorted(members, key=key) for members in others.values() if len(members) > 1]


def print_table(table, markdown):
    sep = " | " if markdown else "  "
    head = ["setting", "seeds", "q_c (MPa)", "sd", "se", "events", "loaded", "I tip", "I chamber", "KE / work",
            "steps", "time (s)"]
    print(("| " if markdown else "") + sep.join(head) + (" |" if markdown else ""))
    if markdown:
        print("|" + "---|" * len(head))
    for setting, s in table.items():
        cells = [label(setting), "%d" % s["q_c_MPa"][0], "%.2f" % s["q_c_MPa"][1], "%.2f" % s["q_c_MPa"][2],
                 "%.2f" % s["q_c_MPa"][3], "%.0f" % s["events"][1], "%.0f" % s["events_loaded"][1],
                 "%.2g" % s["I_tip"][1], "%.2g" % s["I_chamber"][1], "%.2g" % s["ke_share"][1],
                 "%.0f" % s["steps"][1], "%.0f" % s["seconds"][1]]
        print(("| " if markdown else "") + sep.join(cells) + (" |" if markdown else ""))


def print_changes(table, seeded, field):
    at = SETTING.index(field)
    print("\nq_c against %s (the others fixed): change, its standard error, 95%% t interval, p, resolved" % field)
    for members in families(table, field):
        numeric = all(math.isfinite(number(m[at])) for m in members)
        # a numeric field (v, sigma_v): each value against the next; a named one (crushing,
        # density, tip_shape): every pair, in the order of the values (crushing 0, 1, region)
        pairs = zip(members, members[1:]) if numeric else \
            ((x, y) for k, x in enumerate(members) for y in members[k + 1:])
        for x, y in pairs:
            (nx, mx, _, ex), (ny, my, _, ey) = table[x]["q_c_MPa"], table[y]["q_c_MPa"]
            se = math.sqrt(ex ** 2 + ey ** 2)
            print("%s: %s %s -> %s: %.2f -> %.2f MPa, change %+.2f +- %.2f (%+.0f%%), %s (Welch, %d and %d seeds)"
                  % (label(x, (field,)), field, x[at], y[at], mx, my, my - mx, se, 100 * (my / mx - 1),
                     verdict(my - mx, se, welch_df(ex, nx, ey, ny)), nx, ny))
            paired = paired_change(seeded[x], seeded[y])
            if paired:
                n, mean, _, se = paired
                print("    paired by seed (the same chamber and strengths): change %+.2f +- %.2f, %s (%d seeds)"
                      % (mean, se, verdict(mean, se, n - 1), n))


def fits(table, seeded, field, power=False):
    """(members, runs, seeds, slope, se) of each family of settings that differ in the numeric field x
    alone: q_c (or, with power, log2 q_c) against log2 x, one intercept per seed."""
    at = SETTING.index(field)
    y = (lambda q: math.log2(q)) if power else (lambda q: q)  # noqa: E731
    for members in families(table, field):
        points = [(r["seed"], number(m[at]), y(number(r["q_c_MPa"]))) for m in members for r in seeded[m]]
        if not all(x > 0 for _, x, _ in points):
            continue
        fit = fit_log2(points)
        if fit is not None:
            yield (members,) + fit


def print_fit(table, seeded, field):
    at = SETTING.index(field)
    print("\nq_c against log2 %s (the others fixed), one intercept per seed: slope, its standard error" % field)
    for members, runs, seeds, slope, se in fits(table, seeded, field):
        print("%s: %s = %s: %+.3f +- %.3f MPa per doubling of %s (%+.3f +- %.3f per halving), %s"
              " (%d runs, %d seeds), df %d" % (label(members[0], (field,)), field, ", ".join(m[at] for m in members),
                                               slope, se, field, -slope, se, verdict(slope, se, runs - seeds - 1),
                                               runs, seeds, runs - seeds - 1))


def print_power(table, seeded, field):
    """The exponent b of q_c = a_seed x^b over the settings that differ in the numeric field x alone:
    log2 q_c against log2 x, one intercept per seed."""
    at = SETTING.index(field)
    print("\nq_c against %s (the others fixed) as a power, one factor per seed: exponent, its standard error" % field)
    for members, runs, seeds, slope, se in fits(table, seeded, field, power=True):
        low, high, _ = interval(slope, se, runs - seeds - 1)
        print("%s: %s = %s: exponent %.3f +- %.3f, 95%% interval %.3f .. %.3f (%d runs, %d seeds)"
              % (label(members[0], (field,)), field, ", ".join(m[at] for m in members), slope, se, low, high, runs, seeds))
        if len(members) > 2:
            print_local_powers(seeded, members, at)


def local_powers(seeded, x, y, at):
    """{seed: log(q_c(y) / q_c(x)) / log(field(y) / field(x))} over the seeds both settings ran."""
    a = dict((r["seed"], number(r["q_c_MPa"])) for r in seeded[x])
    b = dict((r["seed"], number(r["q_c_MPa"])) for r in seeded[y])
    step = math.log(number(y[at]) / number(x[at]))
    return dict((seed, math.log(b[seed] / a[seed]) / step) for seed in a if seed in b)


def print_local_powers(seeded, members, at):
    """Whether one power holds over three or more levels: each seed's exponent between neighbouring
    levels, and the change of that exponent from one step to the next, paired by seed."""
    steps = [local_powers(seeded, x, y, at) for x, y in zip(members, members[1:])]
    for (x, y), local in zip(zip(members, members[1:]), steps):
        n, mean, _, se = statistics(list(local.values()))
        print("    %s -> %s: exponent %.3f +- %.3f (%d seeds)" % (x[at], y[at], mean, se, n))
    for k in range(len(steps) - 1):
        common = [seed for seed in steps[k] if seed in steps[k + 1]]
        if len(common) < 2:
            continue
        n, mean, _, se = statistics([steps[k + 1][seed] - steps[k][seed] for seed in common])
        print("    change from the step to %s to the next: %+.3f +- %.3f (paired, %d seeds), %s"
              % (members[k + 1][at], mean, se, n, verdict(mean, se, n - 1)))


def one_setting(matched, pattern):
    """Stops, naming the columns that vary, where the rows a pattern matches are not of one setting:
    a comparison of two sides must not mix cases within a side (the 400 kPa pile with the 100 kPa cone)."""
    settings = {setting_of(r) for r in matched}
    if len(settings) > 1:
        varying = [k for i, k in enumerate(SETTING) if len({s[i] for s in settings}) > 1]
        sys.exit("penetration_stats.py: the cases of %s are of %d settings; they differ in %s (%s): name one setting"
                 % (pattern, len(settings), ", ".join(varying), ", ".join(sorted(r["case"] for r in matched))))


def picked(rows, pattern, field):
    """{seed: value of field} of the cases named by pattern, all of one setting (the first row of a
    seed kept)."""
    kept = dict()
    matched = [r for r in rows if fnmatch.fnmatch(r["case"], pattern)]
    one_setting(matched, pattern)
    for r in matched:
        kept.setdefault(r["seed"], r)
    values = dict((seed, number(r.get(field, "nan"))) for seed, r in kept.items())
    values = dict((seed, x) for seed, x in values.items() if math.isfinite(x))
    if not values:
        sys.exit("penetration_stats.py: no case matches %s with a value of %s" % (pattern, field))
    return values


def print_ratio(rows, first, second, field):
    """second's field over first's: the ratio of the means (unpaired, Welch's df of the two means) and
    the mean of each seed's own ratio (paired, over the seeds both ran), each with its standard error
    and its 95% interval, resolved from 1 where that interval excludes 1."""
    a, b = picked(rows, first, field), picked(rows, second, field)
    sa, sb = statistics(list(a.values())), statistics(list(b.values()))
    r, se = ratio(sa, sb)
    print("\n%s: %s over %s" % (field, second, first))
    print("  ratio of the means %.3f +- %.3f (unpaired, %d and %d seeds), from 1: %s"
          % (r, se, len(a), len(b), verdict(r - 1, se, welch_df(sa[3], sa[0], sb[3], sb[0]))))
    common = [seed for seed in a if seed in b]
    if len(common) > 1:
        n, mean, _, se = statistics([b[seed] / a[seed] for seed in common])
        print("  paired by seed: %.3f +- %.3f (%d seeds), from 1: %s" % (mean, se, n, verdict(mean - 1, se, n - 1)))


def versus(rows, first, second, field):
    """The cases named by the patterns first and second (one row per seed in each: the first of a
    seed's rows kept): (n, mean, sd, se) of field in each, and (difference second - first, its
    unpaired standard error)."""
    (n1, m1, s1, se1), (n2, m2, s2, se2) = (statistics(list(picked(rows, p, field).values())) for p in (first, second))
    se = math.sqrt(se1 ** 2 + se2 ** 2) if n1 > 1 and n2 > 1 else float("nan")
    return [(n1, m1, s1, se1), (n2, m2, s2, se2)], (m2 - m1, se)


def print_versus(rows, first, second, field):
    (a, b), (change, se) = versus(rows, first, second, field)
    print("\n%s: %s against %s" % (field, second, first))
    for name, (n, mean, sd, s_e) in ((first, a), (second, b)):
        print("  %-28s %d seeds, mean %.4g, sd %.3g, se %.3g" % (name, n, mean, sd, s_e))
    print("  change %+.4g +- %.3g (unpaired, Welch), %s" % (change, se, verdict(change, se, welch_df(a[3], a[0], b[3], b[0]))))


def print_levelling(seeded):
    """Per setting: q_c's slope over the last 2 D_c (study.csv's q_c_slope_last2, post/penetration.py)
    over the seeds, with its 95% t interval; levelled off where that interval holds zero (and how far
    it reaches: a wide interval levels nothing), still rising where it lies above zero."""
    print("\nq_c's slope over the last 2 D_c (MPa per D_c) over the seeds, 95% t interval")
    for setting, members in seeded.items():
        slopes = [number(r.get("q_c_slope_last2") or "nan") for r in members]
        slopes = [s for s in slopes if math.isfinite(s)]
        if not slopes:
            continue
        n, mean, _, se = statistics(slopes)
        low, high, p = interval(mean, se, n - 1)
        if not math.isfinite(low):
            state = "one seed: not tested"
        else:
            state = "still rising" if low > 0 else ("still falling" if high < 0 else "levelled off (not resolved from zero)")
        print("%s: %+.3f MPa per D_c (%s), %d seeds: %s"
              % (label(setting), mean, "%+.3f .. %+.3f, p %.2g" % (low, high, p) if math.isfinite(low) else "no interval",
                 n, state))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("studies", nargs="+", help="study.csv files of scripts/penetration_study.sh")
    parser.add_argument("--vary", action="append", default=[], choices=SETTING,
                        help="compare the settings that differ in this field alone")
    parser.add_argument("--fit-log2", action="append", default=[], choices=SETTING, metavar="FIELD",
                        help="fit q_c against log2 of this numeric field over the settings that differ in it alone")
    parser.add_argument("--members", action="store_true", help="list the cases of each setting")
    parser.add_argument("--markdown", action="store_true", help="tables in markdown")
    parser.add_argument("--versus", nargs=2, action="append", default=[], metavar=("A", "B"),
                        help="compare the cases named by pattern B against those of pattern A (unpaired)")
    parser.add_argument("--fit-power", action="append", default=[], choices=SETTING, metavar="FIELD",
                        help="fit q_c as a power of this numeric field (log q_c against log FIELD, a factor per seed)")
    parser.add_argument("--ratio", nargs=2, action="append", default=[], metavar=("A", "B"),
                        help="the ratio of pattern B's cases to pattern A's, unpaired and paired by seed")
    parser.add_argument("--levelling", action="store_true", help="per setting, q_c's slope over the last 2 D_c over the"
                        " seeds: levelled off where its 95%% interval holds zero")
    parser.add_argument("--field", default="q_c_MPa", help="the study's column that --versus and --ratio compare"
                        " (default q_c_MPa)")
    a = parser.parse_args()
    rows = []
    for path in a.studies:
        with open(path) as f:
            rows += list(csv.DictReader(f))
    if not rows:
        sys.exit("penetration_stats.py: no rows in %s" % " ".join(a.studies))
    seeded = groups(rows)
    table = dict((setting, summarise(members)) for setting, members in seeded.items())
    print_table(table, a.markdown)
    if a.members:
        print("\ncases of each setting (a case run under two names counts once)")
        for setting, members in all_groups(rows).items():
            print("%s: %s" % (label(setting), ",".join(r["case"] for r in members)))
    for field in a.vary:
        print_changes(table, seeded, field)
    for field in a.fit_log2:
        print_fit(table, seeded, field)
    for field in a.fit_power:
        print_power(table, seeded, field)
    if a.levelling:
        print_levelling(seeded)
    for first, second in a.versus:
        print_versus(rows, first, second, a.field)
    for first, second in a.ratio:
        print_ratio(rows, first, second, a.field)


if __name__ == "__main__":
    main()
