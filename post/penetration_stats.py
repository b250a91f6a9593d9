#!/usr/bin/python3
"""The seeds of a penetration study gathered: per setting (every column of scripts/penetration_study.sh's
study.csv but the case's name and its seed), the number of seeds, the mean of q_c with its sd and
standard error, and the means of the events, the inertial numbers, the kinetic energy's share, the
steps and the time; then, for --vary FIELD, the change of q_c between settings that differ in FIELD
alone (a numeric field's values in turn; a named field's against its first value: crushing 0,
dense), with its standard error, and whether it is resolved at 2 standard errors; where both ran
the same seeds, the change paired by seed too (each seed's own difference, free of the chambers'
scatter).

    post/penetration_stats.py study.csv [more.csv ...] [--vary v] [--vary crushing] [--markdown]
"""
import argparse
import csv
import math
import sys

SETTING = ["density", "N", "crushing", "v", "width", "ranks", "distribution", "sigma_v", "fragment_density", "depth"]
MEANS = ["q_c_MPa", "events", "events_loaded", "I_tip", "I_chamber", "ke_share", "steps", "seconds", "particles", "grains",
         "I_G_near", "I_G_near0", "chamber_events"]


def statistics(values):
    """(n, mean, sd, standard error) of values; sd and se are nan for one value."""
    n = len(values)
    mean = sum(values) / n
    sd = math.sqrt(sum((x - mean) ** 2 for x in values) / (n - 1)) if n > 1 else float("nan")
    return n, mean, sd, sd / math.sqrt(n) if n > 1 else float("nan")


def number(text):
    try:
        return float(text)
    except ValueError:
        return float("nan")


def groups(rows):
    """{setting tuple: [rows]} in the order the settings first appear, one row per seed (a case run
    twice under two names, e.g. rate_v0.5_s1 and dense_region_s1, is one run: the first is kept)."""
    out = {}
    for row in rows:
        members = out.setdefault(tuple(row.get(k, "") for k in SETTING), [])
        if all(r["seed"] != row["seed"] for r in members):
            members.append(row)
    return out


def summarise(rows):
    stats = {}
    for field in MEANS:
        values = [number(r.get(field, "nan")) for r in rows]
        values = [x for x in values if math.isfinite(x)]
        stats[field] = statistics(values) if values else (0, float("nan"), float("nan"), float("nan"))
    stats["seeds"] = ",".join(r["seed"] for r in rows)
    return stats


def paired_change(first, second):
    """(n, mean, sd, se) of q_c(second) - q_c(first) over the seeds both ran, or None: the seed fixes
    the chamber and the strengths, so the pair's difference is free of their scatter."""
    a = dict((r["seed"], number(r["q_c_MPa"])) for r in first)
    b = dict((r["seed"], number(r["q_c_MPa"])) for r in second)
    common = [seed for seed in a if seed in b]
    return statistics([b[seed] - a[seed] for seed in common]) if len(common) > 1 else None


def label(setting, skip=()):
    return " ".join("%s=%s" % (k, v) for k, v in zip(SETTING, setting) if k not in skip)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("studies", nargs="+", help="study.csv files of scripts/penetration_study.sh")
    parser.add_argument("--vary", action="append", default=[], choices=SETTING,
                        help="compare the settings that differ in this field alone")
    parser.add_argument("--markdown", action="store_true", help="tables in markdown")
    a = parser.parse_args()
    rows = []
    for path in a.studies:
        with open(path) as f:
            rows += list(csv.DictReader(f))
    if not rows:
        sys.exit("penetration_stats.py: no rows in %s" % " ".join(a.studies))
    table = dict((setting, summarise(members)) for setting, members in groups(rows).items())
    sep = " | " if a.markdown else "  "
    head = ["setting", "seeds", "q_c (MPa)", "sd", "se", "events", "loaded", "I tip", "I chamber", "KE / work",
            "steps", "time (s)"]
    print(("| " if a.markdown else "") + sep.join(head) + (" |" if a.markdown else ""))
    if a.markdown:
        print("|" + "---|" * len(head))
    for setting, s in table.items():
        cells = [label(setting), "%d" % s["q_c_MPa"][0], "%.2f" % s["q_c_MPa"][1], "%.2f" % s["q_c_MPa"][2],
                 "%.2f" % s["q_c_MPa"][3], "%.0f" % s["events"][1], "%.0f" % s["events_loaded"][1],
                 "%.2g" % s["I_tip"][1], "%.2g" % s["I_chamber"][1], "%.2g" % s["ke_share"][1],
                 "%.0f" % s["steps"][1], "%.0f" % s["seconds"][1]]
        print(("| " if a.markdown else "") + sep.join(cells) + (" |" if a.markdown else ""))
    for field in a.vary:
        at = SETTING.index(field)
        others = {}
        for setting in table:
            others.setdefault(setting[:at] + setting[at + 1:], []).append(setting)
        print("\nq_c against %s (the others fixed): change, its standard error, resolved at 2 se" % field)
        for rest, members in others.items():
            if len(members) < 2:
                continue
            numeric = all(math.isfinite(number(m[at])) for m in members)
            members.sort(key=lambda m: (0, number(m[at]), "") if math.isfinite(number(m[at])) else (1, 0.0, m[at]))
            # a numeric field (v, sigma_v): each value against the next; a named one (crushing,
            # density): each against the first (crushing 0, dense)
            for x, y in (zip(members, members[1:]) if numeric else ((members[0], m) for m in members[1:])):
                (nx, mx, _, ex), (ny, my, _, ey) = table[x]["q_c_MPa"], table[y]["q_c_MPa"]
                se = math.sqrt(ex ** 2 + ey ** 2)
                resolved = "yes" if math.isfinite(se) and abs(my - mx) > 2 * se else "no"
                print("%s: %s %s -> %s: %.2f -> %.2f MPa, change %+.2f +- %.2f (%+.0f%%), resolved: %s (%d and %d seeds)"
                      % (label(x, (field,)), field, x[at], y[at], mx, my, my - mx, se, 100 * (my / mx - 1), resolved, nx, ny))
                paired = paired_change(groups(rows)[x], groups(rows)[y])
                if paired:
                    n, mean, _, se = paired
                    print("    paired by seed (the same chamber and strengths): change %+.2f +- %.2f, resolved: %s (%d seeds)"
                          % (mean, se, "yes" if math.isfinite(se) and abs(mean) > 2 * se else "no", n))


if __name__ == "__main__":
    main()
