"""The Fontainebleau element tests (studies/fontainebleau/README.md): Table 3 of Ciantia et al. (2014)
from seeds, the isotropic against the oedometric tests paired by seed, the readings of the strength
draw, and the upscaling. add_run() adds a finished run of scripts/fontainebleau_runs.sh to
table3_runs.csv."""
import csv
import os
import statistics as py_statistics
import sys

from post.paper import TABLE3
from post.seeds import compare, holm
from post.study_tables.common import cell, change_cell, read_rows, seed_values

PAGE = "studies/fontainebleau/README.md"

# Table 3 of Ciantia et al. (2014) (post/paper.py): N_i, N_e, crushing events, model run (min) by
# (test, N); the paper's E-N are the oedometric tests, O-N here.
PAPER = dict(((name[0], name[1:]), row) for name, row in TABLE3.items())
ORDER = [("O", "2"), ("O", "1.5"), ("O", "1"), ("I", "2"), ("I", "1.5"), ("I", "1")]


def runs_by_test(rows):
    """{(test, N): {seed: row}} of Table 3's runs (the first row of a seed kept)."""
    out = {}
    for r in rows:
        out.setdefault((r["test"], r["N"]), {}).setdefault(r["seed"], r)
    return out


def against_paper(values, paper):
    """The runs' mean over the paper's value, in percent, with its 95% t interval."""
    return cell([100.0 * (v / paper - 1.0) for v in values])


def table3(folder):
    runs = runs_by_test(read_rows(os.path.join(folder, "table3_runs.csv")))
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


def table3_io(folder):
    runs = runs_by_test(read_rows(os.path.join(folder, "table3_runs.csv")))
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


def readings(folder):
    rows = read_rows(os.path.join(folder, "readings_runs.csv"))
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


def readings_changes(folder):
    rows = read_rows(os.path.join(folder, "readings_runs.csv"))
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


UPSCALING_MEASURES = [("n_1MPa", "n at 1 MPa", 4), ("n_10MPa", "n at 10 MPa", 4), ("n_100MPa", "n at 100 MPa", 4),
                      ("K0_mean", "K0 (mean over 1 - 100 MPa)", 3), ("I_G_first_load", "I_G after the first load", 3),
                      ("I_G_10MPa", "I_G at 10 MPa", 3), ("I_G_100MPa", "I_G at 100 MPa", 3),
                      ("events_per_grain", "events per initial grain", 3), ("yield_MPa", "yield stress (MPa)", 1)]


def upscaling(folder):
    rows = read_rows(os.path.join(folder, "upscaling_runs.csv"))
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


def add_run(runtimes, spec, folder):
    """Adds one run's row to studies/fontainebleau/table3_runs.csv (once): its line of the runner's runtimes.csv and the
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
    table = os.path.join(folder, "table3_runs.csv")
    rows = read_rows(table) if os.path.exists(table) else []
    if any((r["test"], r["N"], r["seed"]) == (new["test"], new["N"], new["seed"]) for r in rows):
        return
    with open(table, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(new), lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows + [new])


TABLES = {"table3": table3, "table3_io": table3_io, "readings": readings, "readings_changes": readings_changes,
          "upscaling": upscaling}
