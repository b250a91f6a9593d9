#!/usr/bin/python3
"""The results tables written from their CSVs into the study pages, never typed. Each study keeps its
page, CSVs and figures in studies/<name>/; its module in post/study_tables/ builds its tables from the
CSVs beside the page, and each table stands in the page between two markers,

    <!-- table NAME: written by crush-tables from CSV; do not edit -->
    ...
    <!-- end table NAME -->

    post/tables.py [--check] [--root DIR] [NAME ...]
    post/tables.py --add-run RUNTIMES.csv TEST:SEED [--root DIR]

Without --check it rewrites every named table (default: all) in its page. With --check it writes
nothing and exits 1 naming each table whose page differs from what its CSVs give (the test suite
runs it on the repository). --list prints each table with its page. Statistics by post/seeds.py's
one rule: means with their 95% Student-t interval over the seeds, changes resolved where that
interval excludes zero, and Holm's correction where a table makes many comparisons.

--add-run adds the row of one finished run of scripts/fontainebleau_runs.sh (its line of the runner's
runtimes.csv, and its history beside it in <TEST>_s<SEED>/) to studies/fontainebleau/table3_runs.csv,
once (scripts/table3_runs.sh calls it as each run lands); with --variant NAME (a row of
studies/fontainebleau/io_variants.csv) to io_mechanisms_runs.csv instead (scripts/io_mechanisms.sh).
"""
import argparse
import importlib
import os
import pkgutil
import re
import sys

if not __package__:  # run as a file (python3 post/tables.py): the folder above post/ holds the package
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
import post.study_tables  # noqa: E402
from post.study_tables import fontainebleau  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def registry():
    """{table name: (page from the root, builder)} over every module of post/study_tables/."""
    tables = {}
    for info in pkgutil.iter_modules(post.study_tables.__path__):
        module = importlib.import_module("post.study_tables." + info.name)
        for name, build in getattr(module, "TABLES", {}).items():
            tables[name] = (module.PAGE, build)
    return tables


def markers(name):
    return ("<!-- table %s: written by crush-tables from CSV; do not edit -->" % name, "<!-- end table %s -->" % name)


def placed(text, name, table):
    """The page's text with the table between its markers; None where the page has no markers."""
    begin, end = markers(name)
    pattern = re.compile(re.escape(begin) + r"\n.*?" + re.escape(end), re.S)
    if not pattern.search(text):
        return None
    return pattern.sub(lambda _: begin + "\n" + table + "\n" + end, text, count=1)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("names", nargs="*", help="tables to write (default: all)")
    parser.add_argument("--check", action="store_true", help="write nothing; exit 1 if a page differs from its CSVs")
    parser.add_argument("--list", action="store_true", help="print each table and its page")
    parser.add_argument("--root", default=ROOT, help="the repository root that holds studies/ (default: this one)")
    parser.add_argument("--add-run", nargs=2, metavar=("RUNTIMES", "TEST:SEED"),
                        help="add a finished run's row to studies/fontainebleau/table3_runs.csv")
    parser.add_argument("--variant", help="with --add-run: the row of io_variants.csv the run belongs to (its row goes "
                        "to io_mechanisms_runs.csv)")
    a = parser.parse_args(argv)
    if a.add_run:
        fontainebleau.add_run(a.add_run[0], a.add_run[1], os.path.dirname(os.path.join(a.root, fontainebleau.PAGE)),
                              a.variant)
        return
    tables = registry()
    if a.list:
        for name, (page, _) in sorted(tables.items(), key=lambda t: (t[1][0], t[0])):
            print("%-24s %s" % (name, page))
        return
    unknown = [n for n in a.names if n not in tables]
    if unknown:
        sys.exit("tables.py: no table %s (tables: %s)" % (", ".join(unknown), ", ".join(sorted(tables))))
    stale = []
    for name in a.names or list(tables):
        page, build = tables[name]
        path = os.path.join(a.root, page)
        text = open(path).read()
        new = placed(text, name, build(os.path.dirname(path)))
        if new is None:
            sys.exit("tables.py: %s has no markers of table %s (%s)" % (path, name, " ... ".join(markers(name))))
        if new != text:
            stale.append("%s in %s" % (name, page))
            if not a.check:
                with open(path, "w") as f:
                    f.write(new)
    if a.check and stale:
        sys.exit("tables.py: written by hand or stale (run post/tables.py): %s" % "; ".join(stale))
    print("%s: %s" % ("stale" if stale else "up to date", ", ".join(stale) if stale else ", ".join(a.names or tables)))


if __name__ == "__main__":
    main()
