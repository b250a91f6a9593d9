#!/usr/bin/python3
"""The results tables written from their CSVs into the pages, never typed: each table of TABLES is
built from the CSVs beside it in doc/ and stands in its page between two markers,

    <!-- table NAME: written by crush-tables from CSV; do not edit -->
    ...
    <!-- end table NAME -->

    post/tables.py [--check] [--doc DIR] [NAME ...]
    post/tables.py --add-run RUNTIMES.csv TEST:SEED [--doc DIR]

--add-run adds the row of one finished run of scripts/fontainebleau_runs.sh (its line of the runner's
runtimes.csv, and its history beside it in <TEST>_s<SEED>/) to doc/table3_runs.csv, once.

Without --check it rewrites every named table (default: all) in its page. With --check it writes
nothing and exits 1 naming each table whose page differs from what its CSVs give (the test suite
runs it on doc/). Statistics by post/seeds.py's one rule: means with their 95% Student-t interval
over the seeds, changes resolved where that interval excludes zero.

Tables:
  table3   doc/results.md, from doc/table3_runs.csv (a row a run: test, N, seed, ranks, initial and
           final particles, events, seconds, and from its history the events at the first load and
           where the mean stress p' first reaches 10 and 50 MPa; scripts/table3_runs.sh adds them):
           Table 3 of Ciantia et al. (2014) side by side with the runs, every row over its seeds.
  readings  doc/results.md, from doc/readings_runs.csv (post/compression_seeds.py's runs of
           scripts/strength_readings.sh): each reading of the strength draw and test, its measures'
           means over the seeds with their 95% t intervals.
  readings_changes  doc/results.md, from the same CSV: each reading against the decks' (clipped),
           measure by measure, by post/seeds.py's rule, and Holm's correction over the table.
  accuracy_errors  doc/accuracy_vs_cost.md, from doc/accuracy_seeds_runs.csv (bench/accuracy_seeds.sh):
           each setting's errors against the reference's mean curves, with its cost against N2 in the
           same round.
  accuracy_changes  doc/accuracy_vs_cost.md, from the same CSV: each setting's measures against the
           base N2 by the one rule, and Holm's correction over the table.
  upscaling  doc/results.md, from doc/upscaling_runs.csv (scripts/upscaling_seeds.sh): O-N and I-N at
           N = 1.5 and 2 against N = 1, measure by measure, by the one rule, and Holm over the table.
  table3_io  doc/results.md, from the same CSV: isotropic minus oedometric events per initial grain,
           paired by seed at each N, at the tests' ends (the paper's comparison), at the first load
           and at equal mean stress p' (10 and 50 MPa: the oedometer reaches p' of about 56 MPa).
"""
import argparse
import csv
import os
import re
import statistics as py_statistics
import sys

if not __package__:  # run as a file (python3 post/tables.py): the folder above post/ holds the package
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from post.paper import TABLE3  # noqa: E402
from post.seeds import compare, holm, interval, statistics, welch  # noqa: E402

DOC = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "doc")

# Table 3 of Ciantia et al. (2014) (post/paper.py): N_i, N_e, crushing events, model run (min) by
# (test, N); the paper's E-N are the oedometric tests, O-N here.
PAPER = dict(((name[0], name[1:]), row) for name, row in TABLE3.items())
ORDER = [("O", "2"), ("O", "1.5"), ("O", "1"), ("I", "2"), ("I", "1.5"), ("I", "1")]


def read_rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def runs_by_test(rows):
    """{(test, N): {seed: row}} of Table 3's runs (the first row of a seed kept)."""
    out = {}
    for r in rows:
        out.setdefault((r["test"], r["N"]), {}).setdefault(r["seed"], r)
    return out


def cell(values, digits=0):
    """'mean (low .. high)' over the seeds with the 95% t interval of the mean; the value alone for one
    run, nothing for none."""
    n, mean, _, se = statistics(list(values))
    if n < 2:
        return "%.*f" % (digits, mean) if n else ""
    low, high, _ = interval(mean, se, n - 1)
    return "%.*f (%.*f .. %.*f)" % (digits, mean, digits, low, digits, high)


def change_cell(c, digits, p_holm):
    """A change of compare() as 'change (low .. high)': '*' resolved, '**' also after Holm (p_holm),
    ' u' where unpaired (Welch)."""
    if c["low"] != c["low"]:
        return "%+.*f" % (digits, c["change"])
    mark = "" if c["resolved"] != "yes" else ("**" if p_holm < 0.05 else "*")
    return "%+.*f (%+.*f .. %+.*f)%s%s" % (digits, c["change"], digits, c["low"], digits, c["high"], mark,
                                           "" if c["design"].startswith("paired") else " u")


def against_paper(values, paper):
    """The runs' mean over the paper's value, in percent, with its 95% t interval."""
    return cell([100.0 * (v / paper - 1.0) for v in values])


def table3(doc):
    runs = runs_by_test(read_rows(os.path.join(doc, "table3_runs.csv")))
    lines = ["| test | seeds | N_i | N_e | events | events / N_i (%) | paper N_i, N_e, events | N_e vs paper (%) | "
             "events vs paper (%) | runtime (s, median; ranks) | paper (min) |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for key in ORDER:
        p_ni, p_ne, p_events, p_minutes = PAPER[key]
        seeds = runs.get(key, {})
        name = "%s-%s" % key
        if not seeds:
            lines.append("| %s | 0 | not run | | | | %d, %d, %d | | | | %d |" % (name, p_ni, p_ne, p_events, p_minutes))
            continue
        rows = list(seeds.values())
        ni = [float(r["initial_particles"]) for r in rows]
        ne = [float(r["final_particles"]) for r in rows]
        events = [float(r["events"]) for r in rows]
        share = [100.0 * e / n for e, n in zip(events, ni)]
        seconds = py_statistics.median(float(r["seconds"]) for r in rows)
        ranks = "/".join(sorted({r["ranks"] for r in rows}))
        lines.append("| %s | %d | %s | %s | %s | %s | %d, %d, %d | %s | %s | %.0f; %s | %d |" % (
            name, len(rows), cell(ni), cell(ne), cell(events), cell(share, 1),
            p_ni, p_ne, p_events, against_paper(ne, p_ne), against_paper(events, p_events), seconds, ranks, p_minutes))
    return "\n".join(lines)


def table3_io(doc):
    runs = runs_by_test(read_rows(os.path.join(doc, "table3_runs.csv")))
    lines = ["| N | where | seeds paired | I - O events per initial grain | 95% interval | p | resolved | design | "
             "paper |", "|---|---|---|---|---|---|---|---|---|"]
    for n in ("2", "1.5", "1"):
        o, i = runs.get(("O", n), {}), runs.get(("I", n), {})
        paper = (PAPER[("I", n)][2] - PAPER[("O", n)][2]) / float(PAPER[("O", n)][0])
        common = [s for s in o if s in i]
        if not common:
            lines.append("| %s | the tests' ends | 0 | not run | | | | | %+.4f |" % (n, paper))
            continue
        for column, where in (("events", "the tests' ends"), ("events_first_load", "the first load"),
                              ("events_p10MPa", "p' = 10 MPa"), ("events_p50MPa", "p' = 50 MPa")):
            per_grain = lambda r: float(r[column]) / float(r["initial_particles"])  # noqa: E731
            c = compare(dict((s, per_grain(o[s])) for s in o if o[s].get(column)),
                        dict((s, per_grain(i[s])) for s in i if i[s].get(column)))
            span = "%+.4f .. %+.4f" % (c["low"], c["high"]) if c["low"] == c["low"] else ""
            p = "%.2g" % c["p"] if c["p"] == c["p"] else ""
            lines.append("| %s | %s | %d | %+.4f +- %.4f | %s | %s | %s | %s | %s |"
                         % (n, where, c["pairs"], c["change"], c["se"], span, p, c["resolved"], c["design"],
                            "%+.4f" % paper if column == "events" else ""))
    return "\n".join(lines)


# The readings of the strength draw (scripts/strength_readings.sh), the decks' first; their measures.
READINGS = [("clipped", "clipped (the decks')"), ("normal", "normal"), ("none", "none"),
            ("matched_0.88GPa", "matched (`normal`, sigma_lim0 0.88 GPa)")]
READING_MEASURES = [("events_per_grain_1MPa", "events / N_i by 1 MPa", 3), ("events_per_grain", "events / N_i at 100 MPa", 3),
                    ("I_G_first_load", "I_G after the first load", 3), ("I_G_100MPa", "I_G at 100 MPa", 3),
                    ("n_1MPa", "n at 1 MPa", 4), ("n_10MPa", "n at 10 MPa", 3), ("n_100MPa", "n at 100 MPa", 3),
                    ("yield_MPa", "yield stress (MPa)", 1), ("pass_0.1", "passing 0.1 mm at 100 MPa (%)", 1)]


def reading_values(rows, folder, test, column):
    """{seed: value} of one reading, test and measure (empty cells left out)."""
    return dict((r["seed"], float(r[column])) for r in rows
                if r["folder_name"] == folder and r["test"] == test and r.get(column, "") not in ("", "nan"))


def readings(doc):
    rows = read_rows(os.path.join(doc, "readings_runs.csv"))
    lines = ["| reading | test | seeds | " + " | ".join(label for _, label, _ in READING_MEASURES) + " |",
             "|" + "---|" * (3 + len(READING_MEASURES))]
    for test in ("O", "I"):
        for folder, name in READINGS:
            seeds = {r["seed"] for r in rows if r["folder_name"] == folder and r["test"] == test}
            cells = []
            for column, _, digits in READING_MEASURES:
                values = reading_values(rows, folder, test, column)
                cells.append(cell(values.values(), digits) + (" [%d]" % len(values) if len(values) < len(seeds) else ""))
            lines.append("| %s | %s-2 | %d | %s |" % (name, test, len(seeds), " | ".join(cells)))
    return "\n".join(lines)


def readings_changes(doc):
    rows = read_rows(os.path.join(doc, "readings_runs.csv"))
    found = []
    for test in ("O", "I"):
        for folder, name in READINGS[1:]:
            for column, label, digits in READING_MEASURES:
                ref, other = reading_values(rows, "clipped", test, column), reading_values(rows, folder, test, column)
                if len(ref) > 1 and len(other) > 1:
                    found.append((name, test, label, digits, compare(ref, other)))
    adjusted = holm([c["p"] for *_, c in found])
    lines = ["| reading | test | measure | change from clipped | 95%% interval | p | resolved | Holm (%d) | design |"
             % len(found), "|---|---|---|---|---|---|---|---|---|"]
    for (name, test, label, digits, c), p_holm in zip(found, adjusted):
        d = digits + 1
        span = "%+.*f .. %+.*f" % (d, c["low"], d, c["high"]) if c["low"] == c["low"] else ""
        survives = ("yes" if p_holm < 0.05 else "no") if p_holm == p_holm else ""
        lines.append("| %s | %s-2 | %s | %+.*f +- %.*f | %s | %s | %s | %s | %s |"
                     % (name, test, label, d, c["change"], d, c["se"], span, "%.2g" % c["p"] if c["p"] == c["p"] else "",
                        c["resolved"], survives, c["design"]))
    return "\n".join(lines)


# The accuracy-versus-cost study with seeds (bench/accuracy_seeds.sh): its errors (scale), measures.
ACCURACY_ERRORS = [("err_porosity", "dn", 1, 4), ("err_K0", "dK0", 1, 3), ("err_gsd_percent", "dGSD (%)", 1, 2),
                   ("err_I_G", "dI_G", 1, 4), ("err_events_relative", "d events (%)", 100, 1),
                   ("err_yield_relative", "d yield (%)", 100, 1)]
ACCURACY_MEASURES = [("n_1MPa", "n at 1 MPa", 4), ("n_10MPa", "n at 10 MPa", 4), ("n_100MPa", "n at 100 MPa", 4),
                     ("K0_mean", "K0", 3), ("I_G_100MPa", "I_G at 100 MPa", 4),
                     ("events_per_grain", "events per grain", 4), ("yield_MPa", "yield (MPa)", 2)]
ACCURACY_BASE, ACCURACY_REFERENCE = "N2", "N1"


def by_setting(rows):
    """{setting: {seed: row}} in the order the settings first appear."""
    out = {}
    for r in rows:
        out.setdefault(r["setting"], {}).setdefault(r["seed"], r)
    return out


def seed_values(seeds, column, scale=1.0):
    return dict((k, scale * float(r[column])) for k, r in seeds.items() if r.get(column, "") not in ("", "nan"))


def accuracy_errors(doc):
    settings = by_setting(read_rows(os.path.join(doc, "accuracy_seeds_runs.csv")))
    reference, base = settings[ACCURACY_REFERENCE], settings[ACCURACY_BASE]
    lines = ["| setting | seeds | cost vs N2 (median, range) | cost vs N2 (mean, 95% interval) | "
             + " | ".join(label for _, label, _, _ in ACCURACY_ERRORS) + " |", "|" + "---|" * (4 + len(ACCURACY_ERRORS))]
    for name, seeds in settings.items():
        ratios = [float(r["seconds"]) / float(base[k]["seconds"]) for k, r in seeds.items() if k in base]
        cost = ("%.2f (%.2f .. %.2f)" % (py_statistics.median(ratios), min(ratios), max(ratios))) if ratios else ""
        n, mean, _, se = statistics(ratios)
        low, high, _ = interval(mean, se, n - 1) if n > 1 else (float("nan"),) * 3
        mark = "*" if low == low and (low > 1 or high < 1) else ""
        cost_mean = "%.2f (%.2f .. %.2f)%s" % (mean, low, high, mark) if low == low else ""
        cells = []
        for column, _, scale, digits in ACCURACY_ERRORS:
            values = seed_values(seeds, column, scale)
            # beyond the reference's own spread (each of its seeds against the others' mean): unpaired,
            # for a setting's error and the reference's self-error do not share a sample
            beyond = ""
            if name != ACCURACY_REFERENCE:
                low, _, _ = interval(*welch(seed_values(reference, column, scale).values(), values.values()))
                beyond = "*" if low == low and low > 0 else ""
            cells.append(cell(values.values(), digits) + beyond)
        lines.append("| %s | %d | %s | %s | %s |" % (name, len(seeds), cost, cost_mean, " | ".join(cells)))
    return "\n".join(lines)


def accuracy_changes(doc):
    settings = by_setting(read_rows(os.path.join(doc, "accuracy_seeds_runs.csv")))
    base = settings[ACCURACY_BASE]
    found = []
    for name, seeds in settings.items():
        if name == ACCURACY_BASE:
            continue
        for column, _, digits in ACCURACY_MEASURES:
            found.append((name, column, digits, compare(seed_values(base, column), seed_values(seeds, column))))
    adjusted = dict(zip(((f[0], f[1]) for f in found), holm([f[3]["p"] for f in found])))
    lines = ["| setting | " + " | ".join(label for _, label, _ in ACCURACY_MEASURES) + " |",
             "|" + "---|" * (1 + len(ACCURACY_MEASURES))]
    for name in [n for n in settings if n != ACCURACY_BASE]:
        cells = []
        for setting, column, digits, c in found:
            if setting != name:
                continue
            cells.append(change_cell(c, digits, adjusted[(name, column)]))
        lines.append("| %s | %s |" % (name, " | ".join(cells)))
    return "\n".join(lines) + "\n\n(%d changes; '*' resolved, '**' also after Holm's correction over them; 'u': unpaired, " \
        "Welch)" % len(found)


UPSCALING_MEASURES = [("n_1MPa", "n at 1 MPa", 4), ("n_10MPa", "n at 10 MPa", 4), ("n_100MPa", "n at 100 MPa", 4),
                      ("K0_mean", "K0 (mean over 1 - 100 MPa)", 3), ("I_G_first_load", "I_G after the first load", 3),
                      ("I_G_10MPa", "I_G at 10 MPa", 3), ("I_G_100MPa", "I_G at 100 MPa", 3),
                      ("events_per_grain", "events per initial grain", 3), ("yield_MPa", "yield stress (MPa)", 1)]


def upscaling(doc):
    rows = read_rows(os.path.join(doc, "upscaling_runs.csv"))
    runs = dict(((r["test"], r["N"]), {}) for r in rows)
    for r in rows:
        runs[(r["test"], r["N"])].setdefault(r["seed"], r)
    found = []
    for test in ("O", "I"):
        for n in ("1.5", "2"):
            for column, _, digits in UPSCALING_MEASURES:
                one, other = seed_values(runs.get((test, "1"), {}), column), seed_values(runs.get((test, n), {}), column)
                if len(one) > 1 and len(other) > 1:
                    found.append(((test, n, column), compare(one, other)))
    adjusted = dict(zip((k for k, _ in found), holm([c["p"] for _, c in found])))
    changes = dict(found)
    lines = ["| measure | O-1 | O-1.5 - O-1 | O-2 - O-1 | I-1 | I-1.5 - I-1 | I-2 - I-1 |", "|---|---|---|---|---|---|---|"]
    for column, label, digits in UPSCALING_MEASURES:
        cells = []
        for test in ("O", "I"):
            cells.append(cell(seed_values(runs.get((test, "1"), {}), column).values(), digits))
            for n in ("1.5", "2"):
                c = changes.get((test, n, column))
                if c is None:
                    cells.append("")
                    continue
                cells.append(change_cell(c, digits, adjusted[(test, n, column)]))
        lines.append("| %s | %s |" % (label, " | ".join(cells)))
    return "\n".join(lines) + "\n\n(%d changes; '*' resolved, '**' also after Holm's correction over them; 'u': unpaired, " \
        "Welch; the others paired on the seeds both ran)" % len(found)


def history_events(path):
    """From a run's history: the events at its first row (the first load) and where the mean stress
    p' first reaches 10 and 50 MPa ('' where it never does)."""
    rows = list(csv.DictReader(open(path)))
    first_at = lambda target: next((r["events"] for r in rows if float(r["p"]) >= target), "")  # noqa: E731
    return {"events_first_load": rows[0]["events"], "events_p10MPa": first_at(1e7), "events_p50MPa": first_at(5e7)}


def add_run(runtimes, spec, doc):
    """Adds one run's row to doc/table3_runs.csv (once): its line of the runner's runtimes.csv and the
    events of its history (the run's folder beside runtimes.csv, as fontainebleau_runs.sh names it)."""
    test, seed = spec.split(":")
    row = next((r for r in read_rows(runtimes) if r["test"] == spec), None)
    if row is None:
        sys.exit("tables.py: %s has no row %s" % (runtimes, spec))
    history = os.path.join(os.path.dirname(runtimes), "%s_s%s" % (test, seed), "history_%s.csv" % test)
    new = {"test": test[0], "N": test[1:], "seed": seed, "ranks": row["ranks"],
           "initial_particles": row["initial_particles"], "final_particles": row["final_particles"],
           "events": row["events"], "seconds": row["seconds"]}
    new.update(history_events(history))
    table = os.path.join(doc, "table3_runs.csv")
    rows = read_rows(table) if os.path.exists(table) else []
    if any((r["test"], r["N"], r["seed"]) == (new["test"], new["N"], new["seed"]) for r in rows):
        return
    with open(table, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(new), lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows + [new])


TABLES = {"table3": ("results.md", table3), "table3_io": ("results.md", table3_io),
          "readings": ("results.md", readings), "readings_changes": ("results.md", readings_changes),
          "upscaling": ("results.md", upscaling),
          "accuracy_errors": ("accuracy_vs_cost.md", accuracy_errors),
          "accuracy_changes": ("accuracy_vs_cost.md", accuracy_changes)}


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
    parser.add_argument("--doc", default=DOC, help="the folder of the pages and their CSVs (default doc/)")
    parser.add_argument("--add-run", nargs=2, metavar=("RUNTIMES", "TEST:SEED"),
                        help="add a finished run's row to table3_runs.csv")
    a = parser.parse_args(argv)
    if a.add_run:
        add_run(a.add_run[0], a.add_run[1], a.doc)
        return
    unknown = [n for n in a.names if n not in TABLES]
    if unknown:
        sys.exit("tables.py: no table %s (tables: %s)" % (", ".join(unknown), ", ".join(TABLES)))
    stale = []
    for name in a.names or list(TABLES):
        page, build = TABLES[name]
        path = os.path.join(a.doc, page)
        text = open(path).read()
        new = placed(text, name, build(a.doc))
        if new is None:
            sys.exit("tables.py: %s has no markers of table %s (%s)" % (path, name, " ... ".join(markers(name))))
        if new != text:
            stale.append("%s in %s" % (name, page))
            if not a.check:
                with open(path, "w") as f:
                    f.write(new)
    if a.check and stale:
        sys.exit("tables.py: written by hand or stale (run post/tables.py): %s" % "; ".join(stale))
    print("%s: %s" % ("stale" if stale else "up to date", ", ".join(stale) if stale else ", ".join(a.names or TABLES)))


if __name__ == "__main__":
    main()
