#!/usr/bin/env python3
"""The cases of the penetration study (studies/penetration/cases.csv), read for
scripts/penetration_study.sh: one row a case, its settings in named columns,

    case, groups, density, N, crushing, v, width, ranks, distribution, sigma_v, seed,
    fragment_density, depth, test_vars, chamber_vars, note

groups: the groups the case belongs to, separated by spaces; test_vars: in.cone's further
variables (name=value;name=value); chamber_vars: those of in.chamber, which in.cone receives too
(they also name the chamber's folder, so their order is kept). Every row is checked before anything
runs: a value that is not one the decks take stops the runner with the row, the column and the
value.

    post/penetration_cases.py [--cases CASES.csv] NAME ...
    post/penetration_cases.py [--cases CASES.csv] --groups

Each NAME is a case, a group (its cases seed by seed, in the table's order within a seed) or a spec
density:N:crushing:v:width:ranks[:distribution[:sigma_v[:seed[:fragment_density[:depth[:test_vars[:chamber_vars]]]]]]]
(its name=value lists joined by commas), checked as a row is; summarise and figures pass through.
Prints one line a case, its name and its spec (the thirteen fields, the name=value lists joined by
commas) separated by a tab; a case named twice runs once. --groups prints each group and its cases.
Exit status 2, with a message, on a bad row or an unknown name.
"""
import argparse
import csv
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CASES = os.path.join(ROOT, "studies", "penetration", "cases.csv")
FIELDS = ["density", "N", "crushing", "v", "width", "ranks", "distribution", "sigma_v", "seed", "fragment_density",
          "depth", "test_vars", "chamber_vars"]
COLUMNS = ["case", "groups"] + FIELDS + ["note"]
# what a short spec leaves out: the values the runner has always filled in
DEFAULTS = {"distribution": "normal_clipped_originals", "sigma_v": "1e5", "seed": "15485863",
            "fragment_density": "true", "depth": "8", "test_vars": "", "chamber_vars": ""}
CHOICES = {"density": ("dense", "loose"), "crushing": ("region", "0", "1"), "fragment_density": ("true", "scaled"),
           # fix crush's strength draws (doc/fix_crush.txt)
           "distribution": ("normal_clipped_originals", "normal", "normal_clipped", "weibull", "constant")}
POSITIVE = ("N", "v", "width", "sigma_v", "depth")
COUNTS = ("ranks", "seed")
WORDS = ("summarise", "figures")  # the runner's own steps
NAME = re.compile(r"^[A-Za-z0-9_.]+$")
VARIABLE = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*=[^\s,:;=]+$")


class Refused(Exception):
    pass


def positive(text):
    try:
        return float(text) > 0
    except ValueError:
        return False


def check_settings(settings, where):
    """Refuses (Refused, naming where, the column and the value) a setting the decks do not take."""
    for column in FIELDS:
        value = settings[column]
        if column in CHOICES and value not in CHOICES[column]:
            raise Refused("%s: %s '%s' is not one of %s" % (where, column, value, ", ".join(CHOICES[column])))
        if column in POSITIVE and not positive(value):
            raise Refused("%s: %s '%s' is not a positive number" % (where, column, value))
        if column in COUNTS and not (value.isdigit() and int(value) > 0):
            raise Refused("%s: %s '%s' is not a positive integer" % (where, column, value))
        if column.endswith("_vars") and value and not all(VARIABLE.match(kv) for kv in value.split(";")):
            raise Refused("%s: %s '%s' is not a list name=value;name=value" % (where, column, value))


def read_cases(path):
    """(cases {name: settings} in the table's order, groups {name: [cases]}); Refused on a bad row."""
    with open(path) as f:
        reader = csv.DictReader(f)
        missing = [c for c in COLUMNS if c not in (reader.fieldnames or [])]
        if missing:
            raise Refused("%s has no column %s (its columns: %s)" % (path, ", ".join(missing), ", ".join(COLUMNS)))
        cases, groups = {}, {}
        for line, row in enumerate(reader, 2):
            name = row["case"] or ""
            where = "%s line %d, case %s" % (path, line, name or "(no name)")
            if not NAME.match(name) or name in WORDS:
                raise Refused("%s: the case's name '%s' is empty, holds other than letters, digits, '_' and '.', or"
                              " is one of the runner's words (%s)" % (where, name, ", ".join(WORDS)))
            if name in cases:
                raise Refused("%s: a second row of case %s" % (where, name))
            settings = dict((c, (row[c] or "").strip()) for c in FIELDS)
            check_settings(settings, where)
            cases[name] = settings
            for group in (row["groups"] or "").split():
                if not NAME.match(group):
                    raise Refused("%s: group '%s' holds other than letters, digits, '_' and '.'" % (where, group))
                groups.setdefault(group, []).append(name)
    both = [g for g in groups if g in cases or g in WORDS]
    if both:
        raise Refused("%s: %s both a case and a group, or a word of the runner" % (path, ", ".join(both)))
    return cases, groups


def spec_of(settings):
    """The runner's colon spec of a case: the name=value lists joined by commas."""
    return ":".join(settings[c].replace(";", ",") if c.endswith("_vars") else settings[c] for c in FIELDS)


def parse_spec(text):
    """A spec on the command line as settings (its name=value lists as the table writes them);
    Refused where it is not one."""
    fields = text.split(":")
    if len(fields) < 6 or len(fields) > len(FIELDS):
        raise Refused("'%s' is no case, group or spec density:N:crushing:v:width:ranks[:distribution[:sigma_v[:seed"
                      "[:fragment_density[:depth[:test_vars[:chamber_vars]]]]]]]" % text)
    settings = dict(DEFAULTS)
    settings.update((c, v.replace(",", ";")) for c, v in zip(FIELDS, fields) if v or c not in DEFAULTS)
    check_settings(settings, "spec %s" % text)
    return settings


def plan(names, cases, groups):
    """[(name, spec)] to run, in order, each case once; summarise and figures with an empty spec."""
    out, seen = [], set()
    for name in names:
        if name in WORDS:
            out.append((name, ""))
            continue
        if name in groups:
            # seed by seed, in the table's order within a seed: a run cut short leaves whole seeds to pair
            first = {}
            for c in groups[name]:
                first.setdefault(cases[c]["seed"], len(first))
            members = [(c, cases[c]) for c in sorted(groups[name], key=lambda c: first[cases[c]["seed"]])]
        elif name in cases:
            members = [(name, cases[name])]
        elif ":" in name:
            members = [(name, parse_spec(name))]
        else:
            raise Refused("unknown case or group %s (groups: %s; or a spec density:N:crushing:v:width:ranks[:...])"
                          % (name, " ".join(sorted(groups))))
        for case, settings in members:
            if case not in seen:
                seen.add(case)
                out.append((case, spec_of(settings)))
    return out


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("names", nargs="*", help="cases, groups or specs")
    parser.add_argument("--cases", default=CASES, help="the table of cases (default studies/penetration/cases.csv)")
    parser.add_argument("--groups", action="store_true", help="print each group and its cases")
    a = parser.parse_args(argv)
    try:
        cases, groups = read_cases(a.cases)
        if a.groups:
            for group in sorted(groups):
                print("%s: %s" % (group, " ".join(groups[group])))
            return
        for name, spec in plan(a.names, cases, groups):
            print("%s\t%s" % (name, spec))
    except (Refused, OSError) as e:
        sys.stderr.write("penetration_cases.py: %s\n" % e)
        raise SystemExit(2)


if __name__ == "__main__":
    main()
