#!/usr/bin/python3
"""The seeds of a study gathered: for any CSV with one row a run, the runs grouped into settings by
the columns that define a case, the mean and standard error of every measure over each setting's
seeds, and each setting's change against a reference setting with its standard error, paired by
seed where both ran the same seeds (the seed fixes the sample and the strengths, so each seed's own
difference is free of their scatter), marked resolved or not at 2 standard errors. One
implementation for the studies' tables (post/penetration_stats.py uses its statistics).

    post/seeds.py STUDY.csv [more.csv ...] --setting COL[,COL...] --measure COL[,COL...]
                  [--seed seed] [--reference COL=VALUE[,COL=VALUE...]] [--markdown] [--csv OUT]

--setting: the columns that define a case (the others are measures, names or bookkeeping); --measure:
the columns to gather; --seed: the column of the seed (default seed); --reference: the setting the
others are compared with (every --setting column it names must match; default the first setting in
the file). A row whose measure is empty or not a number is left out of that measure. Two rows of
one setting and one seed are one run counted twice: the first is kept, and a warning names them.

Output, per setting: its seeds, and per measure the mean, sd and standard error; then per setting
and measure the change against the reference, its standard error (unpaired: the two standard
errors in quadrature; paired: the sd of the seeds' own differences over sqrt(seeds)), and
"resolved" where |change| > 2 se. One seed has no standard error: "one seed", never resolved; a
measure the reference lacks is "no reference value".
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


def resolved(change, se):
    """'yes' where |change| > 2 se, 'no' where not, 'one seed' where se is unknown."""
    if not math.isfinite(se):
        return "one seed"
    return "yes" if abs(change) > 2 * se else "no"


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
    change and se; the paired (n, mean change, se) over the common seeds, or None under two)."""
    a, b = statistics(list(reference.values())), statistics(list(other.values()))
    unpaired = (b[1] - a[1], math.sqrt(a[3] ** 2 + b[3] ** 2))
    common = [s for s in reference if s in other]
    paired = None
    if len(common) > 1:
        n, mean, _, se = statistics([other[s] - reference[s] for s in common])
        paired = (n, mean, se)
    return a, b, unpaired, paired


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
    print("reference: %s (%d seeds)" % (label(setting, ref), len(groups[ref])))
    head = ["setting", "measure", "seeds", "mean", "sd", "se", "change", "se", "resolved", "paired change", "se",
            "resolved (seeds)"]
    print(("| " if a.markdown else "") + sep.join(head) + (" |" if a.markdown else ""))
    if a.markdown:
        print("|" + "---|" * len(head))
    out = []
    for key, by_seed in groups.items():
        for m in measures:
            reference, other = values_of(groups[ref], m), values_of(by_seed, m)
            if not other:
                continue
            if reference:
                _, stats, (dx, se), paired = change(reference, other)
            else:  # the reference has no value of this measure
                stats, dx, se, paired = statistics(list(other.values())), float("nan"), float("nan"), None
            is_ref = key == ref
            cells = [label(setting, key), m, "%d" % stats[0], "%.4g" % stats[1], "%.3g" % stats[2], "%.3g" % stats[3]]
            if is_ref:
                cells += ["", "", ""]
            elif not reference:
                cells += ["", "", "no reference value"]
            else:
                cells += ["%+.4g" % dx, "%.3g" % se, resolved(dx, se)]
            cells += ["", "", ""] if is_ref or paired is None else ["%+.4g" % paired[1], "%.3g" % paired[2],
                                                                  "%s (%d)" % (resolved(paired[1], paired[2]), paired[0])]
            print(("| " if a.markdown else "") + sep.join(cells) + (" |" if a.markdown else ""))
            out.append(cells)
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            writer = csv.writer(f, lineterminator="\n")
            writer.writerow(["setting", "measure", "seeds", "mean", "sd", "se", "change", "change_se", "resolved",
                             "paired_change", "paired_se", "paired_resolved"])
            writer.writerows(out)


if __name__ == "__main__":
    main()
