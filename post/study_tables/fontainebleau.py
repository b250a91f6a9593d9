"""The Fontainebleau element tests (studies/fontainebleau/README.md): Table 3 of Ciantia et al. (2014)
from seeds, the isotropic against the oedometric tests paired by seed, the readings of the strength
draw, and the upscaling. add_run() adds a finished run of scripts/fontainebleau_runs.sh to
table3_runs.csv."""
import csv
import math
import os
import statistics as py_statistics
import sys

from post.paper import TABLE3
from post.seeds import compare, holm, interval, statistics, t_tail, welch_df
from post.study_tables.common import cell, change_cell, conclusions, interval_cell, read_rows, seed_values

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


def paper_change(values, paper):
    """(n, mean, low, high): the runs over the paper's value, in percent, with the 95% t interval of
    the mean (nans for fewer than two runs)."""
    n, mean, _, se = statistics([100.0 * (v / paper - 1.0) for v in values])
    low, high, _ = interval(mean, se, n - 1) if n > 1 else (float("nan"),) * 3
    return n, mean, low, high


def against_paper(values, paper):
    """paper_change() as a cell, signed: 'mean (low .. high)'."""
    n, mean, low, high = paper_change(values, paper)
    if n < 2:
        return "%+.0f" % mean if n else ""
    return "%+.0f (%+.0f .. %+.0f)" % (mean, low, high)


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


IO_WHERE = (("events", "the tests' ends"), ("events_first_load", "the first load"),
            ("events_p10MPa", "p' = 10 MPa"), ("events_p50MPa", "p' = 50 MPa"))


def per_grain(row, column="events"):
    """A run's count in column (events by default) per initial grain."""
    return float(row[column]) / float(row["initial_particles"])


def paper_per_grain(test, n):
    return PAPER[(test, n)][2] / float(PAPER[(test, n)][0])


def paper_io(n):
    """The paper's I - O events per initial grain at scale n (its one run each)."""
    return (PAPER[("I", n)][2] - PAPER[("O", n)][2]) / float(PAPER[("O", n)][0])


def io_change(o, i, value=per_grain):
    """I - O of value(row) over {seed: row} of each test, by the one rule (paired by seed where it
    pairs)."""
    return compare(dict((s, value(r)) for s, r in o.items()), dict((s, value(r)) for s, r in i.items()))


def table3_io(folder):
    runs = runs_by_test(read_rows(os.path.join(folder, "table3_runs.csv")))
    found = []
    for n in ("2", "1.5", "1"):
        o, i = runs.get(("O", n), {}), runs.get(("I", n), {})
        for column, where in IO_WHERE if any(s in i for s in o) else ():
            found.append((n, column, where, io_change(dict((s, r) for s, r in o.items() if r.get(column)),
                                                      dict((s, r) for s, r in i.items() if r.get(column)),
                                                      lambda r, c=column: per_grain(r, c))))
    adjusted = holm([c["p"] for *_, c in found])
    lines = ["| N | where | seeds paired | I - O events per initial grain (95%% interval) | p | resolved | Holm (%d) "
             "| design | paper |" % len(found), "|---|---|---|---|---|---|---|---|---|"]
    for (n, column, where, c), p_holm in zip(found, adjusted):
        lines.append("| %s | %s | %d | %s | %s | %s | %s | %s | %s |"
                     % (n, where, c["pairs"], interval_cell(c, 4), "%.2g" % c["p"] if c["p"] == c["p"] else "",
                        c["resolved"], ("yes" if p_holm < 0.05 else "no") if p_holm == p_holm else "", c["design"],
                        "%+.4f" % paper_io(n) if column == "events" else ""))
    return "\n".join(lines)


def io_scatter(folder):
    """Could one run of each test give the paper's I - O by chance? The standard deviation of a single
    run's events per initial grain over the seeds, O and I, that of a single unpaired difference, the
    paper's difference in its units, and the chance that one O run and one I run of this model differ
    by the paper's difference or more (one-sided, Student's t of the prediction: the runs' mean
    difference, the sd's own uncertainty, Welch's df)."""
    runs = runs_by_test(read_rows(os.path.join(folder, "table3_runs.csv")))
    lines = ["| N | seeds | sd of one O-N run | sd of one I-N run | sd of one unpaired I - O | paper's I - O | "
             "paper's I - O / that sd | P(one pair of runs reaches it) | after Holm (3) |", "|---|---|---|---|---|---|---|---|---|"]
    found = []
    for n in ("2", "1.5", "1"):
        shares = [[per_grain(r) for r in runs.get((test, n), {}).values()] for test in ("O", "I")]
        if min(len(v) for v in shares) < 2:
            continue
        sd_o, sd_i = (py_statistics.stdev(v) for v in shares)
        sd = math.hypot(sd_o, sd_i)
        paper = paper_io(n)
        n_o, n_i = len(shares[0]), len(shares[1])
        mean = py_statistics.mean(shares[1]) - py_statistics.mean(shares[0])
        spread = math.sqrt(sd_o ** 2 * (1 + 1.0 / n_o) + sd_i ** 2 * (1 + 1.0 / n_i))
        df = welch_df(sd_o * math.sqrt(1 + 1.0 / n_o), n_o, sd_i * math.sqrt(1 + 1.0 / n_i), n_i)
        chance = t_tail((paper - mean) / spread, df) / 2.0
        found.append((n, n_o, n_i, sd_o, sd_i, sd, paper, paper / sd, chance))
    for row, adjusted in zip(found, holm([f[-1] for f in found])):
        lines.append("| %s | %d, %d | %.4f | %.4f | %.4f | %+.4f | %.1f | %.2g | %.2g |" % (row + (adjusted,)))
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
    lines = ["| reading | test | measure | change from clipped (95%% interval) | p | resolved | Holm (%d) | design |"
             % len(found), "|---|---|---|---|---|---|---|---|"]
    for (name, test, label, digits, c), p_holm in zip(found, adjusted):
        survives = ("yes" if p_holm < 0.05 else "no") if p_holm == p_holm else ""
        lines.append("| %s | %s-2 | %s | %s | %s | %s | %s | %s |"
                     % (name, test, label, interval_cell(c, digits + 1), "%.2g" % c["p"] if c["p"] == c["p"] else "",
                        c["resolved"], survives, c["design"]))
    return "\n".join(lines)


UPSCALING_MEASURES = [("n_1MPa", "n at 1 MPa", 4), ("n_10MPa", "n at 10 MPa", 4), ("n_100MPa", "n at 100 MPa", 4),
                      ("K0_mean", "K0 (mean over 1 - 100 MPa)", 3), ("I_G_first_load", "I_G after the first load", 3),
                      ("I_G_10MPa", "I_G at 10 MPa", 3), ("I_G_100MPa", "I_G at 100 MPa", 3),
                      ("events_per_grain", "events per initial grain", 3), ("yield_MPa", "yield stress (MPa)", 1)]


def upscaling_changes(folder):
    """The runs by (test, N) and every change against N = 1 by the one rule, with Holm's p over them."""
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
    return runs, dict(found), adjusted


def upscaling(folder):
    runs, changes, adjusted = upscaling_changes(folder)
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
        "Welch; the others paired on the seeds both ran)" % len(changes)


def io_verdict(folder):
    """The candidate variants of io_mechanisms (the decks' own left out) whose I - O at the tests' ends is
    resolved above zero, every candidate run on three or more seeds whose runs all carried 100 MPa, and
    those whose walls ended below it."""
    rows = read_rows(os.path.join(folder, "io_mechanisms_runs.csv"))
    above, run, short = [], [], []
    for variant in [v for v in io_variants(folder) if v != "decks"]:
        runs = variant_runs(rows, variant)
        if len(runs["O"]) < 3 or len(runs["I"]) < 3:
            continue
        if any(stress_reached(r) < LOADED_MPA for test in runs.values() for r in test.values()):
            short.append(variant)
            continue
        c = io_change(runs["O"], runs["I"])
        run.append((variant, c))
        if c["low"] > 0:
            above.append(variant)
    return above, run, short


def conclusions_fontainebleau(folder):
    """The study's answers, each from its CSV."""
    runs = runs_by_test(read_rows(os.path.join(folder, "table3_runs.csv")))
    events = lambda key: [float(r["events"]) for r in runs.get(key, {}).values()]  # noqa: E731
    seeds = lambda *keys: "%s seeds" % "/".join(str(len(runs.get(k, {}))) for k in keys)  # noqa: E731
    vs_paper = lambda key: "%s-%s %s%%" % (key[0], key[1], against_paper(events(key), PAPER[key][2]))  # noqa: E731
    first = [100.0 * float(r["events_first_load"]) / float(r["events"]) for k in ORDER for r in runs.get(k, {}).values()]
    io = [(n, io_change(runs.get(("O", n), {}), runs.get(("I", n), {}))) for n in ("2", "1.5", "1")]
    above, tried, short = io_verdict(folder)
    if above:
        mechanisms = "%s reverses the I - O order" % ", ".join(above)
    else:
        mechanisms = ("none of the %d candidate mechanisms run reverses the I - O order" % len(tried)) if tried \
            else "no candidate mechanism has run"
    if short:
        mechanisms += " (%s left out: a run's walls end below %.0f MPa)" % (" and ".join(short), LOADED_MPA)
    _, ups, ups_holm = upscaling_changes(folder)
    readings_rows = read_rows(os.path.join(folder, "readings_runs.csv"))
    reading = lambda f: reading_values(readings_rows, f, "O", "events_per_grain").values()  # noqa: E731
    bounds = []
    for key in (("O", "1"), ("I", "1")):
        n, mean, low, high = paper_change(events(key), PAPER[key][2])
        bounds += [low, high] if n > 1 else [mean]
    within = math.ceil(max(abs(b) for b in bounds))
    rows = [
        ("At N = 1 the events lie within %d%% of Table 3's." % within,
         "events vs the paper: %s; %s" % (vs_paper(("O", "1")), vs_paper(("I", "1"))), seeds(("O", "1"), ("I", "1")),
         "bash scripts/table3_runs.sh runs/table3 O1 I1"),
        ("The coarser oedometric samples (N = 2, 1.5) break more than Table 3's.",
         "%s; %s" % (vs_paper(("O", "2")), vs_paper(("O", "1.5"))), seeds(("O", "2"), ("O", "1.5")),
         "bash scripts/table3_runs.sh runs/table3 O2 O1.5"),
        ("Most events are the zero-strength sixth of the grains breaking at the first load.",
         "share of a run's events at the first load: %s%%" % cell(first), "%d runs" % len(first),
         "bash scripts/table3_runs.sh"),
        ("The paper's isotropic tests break more per grain than its oedometric ones; ours do not.",
         "; ".join("N %s: I - O %s (paper %+.3f)" % (n, interval_cell(c, 4), paper_io(n)) for n, c in io),
         "5 seeds, paired", "bash scripts/table3_runs.sh"),
        ("At N = 2, %s." % mechanisms,
         "; ".join("%s %s" % (v, interval_cell(c, 4)) for v, c in tried), "5 seeds each, paired",
         "bash scripts/io_mechanisms.sh runs/io"),
        ("Upscaling (N = 1.5 and 2 against N = 1) resolves no change in porosity, K0, I_G, events or yield; the "
         "intervals are wide.",
         "%d of %d changes resolved, %d after Holm" % (sum(c["resolved"] == "yes" for c in ups.values()), len(ups),
                                                       sum(p < 0.05 for p in ups_holm.values())),
         "3 - 5 seeds", "bash scripts/upscaling_seeds.sh runs/upscaling && SEEDS=\"373587883 1299709\" bash "
         "scripts/upscaling_seeds.sh runs/upscaling O2 && cp runs/upscaling/upscaling_runs.csv studies/fontainebleau/"),
        ("At the paper's sigma_lim0 (5 GPa) the truncated normal breaks a fifth of Table 3's grains; the zero-strength "
         "reading comes near them.",
         "O-2 events / N_i at 100 MPa: clipped %s, normal %s, paper %.3f" % (cell(reading("clipped"), 3),
                                                                             cell(reading("normal"), 3), paper_per_grain("O", "2")),
         "5 seeds", "bash scripts/strength_readings.sh runs/readings && cp runs/readings/readings_runs.csv studies/fontainebleau/"),
        ("Matching the yield stress with the truncated normal breaks several times Table 3's grains.",
         "O-2 events / N_i at 100 MPa, sigma_lim0 0.88 GPa: %s" % cell(reading("matched_0.88GPa"), 3), "5 seeds",
         "SIGMA_LIM0_MATCHED=8.8e8 bash scripts/strength_readings.sh runs/readings matched && cp runs/readings/readings_runs.csv "
         "studies/fontainebleau/"),
    ]
    return conclusions(rows)


def history_events(path):
    """From a run's history: the events at its first row (the first load) and where the mean stress
    p' first reaches 10 and 50 MPa ('' where it never does)."""
    rows = list(csv.DictReader(open(path)))
    first_at = lambda target: next((r["events"] for r in rows if float(r["p"]) >= target), "")  # noqa: E731
    return {"events_first_load": rows[0]["events"], "events_p10MPa": first_at(1e7), "events_p50MPa": first_at(5e7)}


def history_end(path):
    """From a run's history: K0 and the mean stress p' (MPa) at its last row."""
    last = list(csv.DictReader(open(path)))[-1]
    return {"K0_end": "%.4f" % float(last["K0"]), "p_end_MPa": "%.2f" % (float(last["p"]) / 1e6)}


def append_once(table, new, key):
    """Appends the row to the CSV unless a row with the same key columns is there."""
    rows = read_rows(table) if os.path.exists(table) else []
    if any(tuple(r.get(k) for k in key) == tuple(new[k] for k in key) for r in rows):
        return
    with open(table, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(new), lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows + [new])


def add_run(runtimes, spec, folder, variant=None):
    """Adds one run's row (once): its line of the runner's runtimes.csv and the events of its history
    (the run's folder beside runtimes.csv, as fontainebleau_runs.sh names it), to table3_runs.csv, or
    with a variant (a row of io_variants.csv) to io_mechanisms_runs.csv with K0 and p' at the end."""
    test, seed = spec.split(":")
    row = next((r for r in read_rows(runtimes) if r["test"] == spec), None)
    if row is None:
        sys.exit("tables.py: %s has no row %s" % (runtimes, spec))
    history = os.path.join(os.path.dirname(runtimes), "%s_s%s" % (test, seed), "history_%s.csv" % test)
    new = {"variant": variant} if variant else {}
    new.update({"test": test[0], "N": test[1:], "seed": seed, "ranks": row["ranks"],
                "initial_particles": row["initial_particles"], "final_particles": row["final_particles"],
                "events": row["events"], "seconds": row["seconds"]})
    new.update(history_events(history))
    if variant:
        new.update(history_end(history))
        append_once(os.path.join(folder, "io_mechanisms_runs.csv"), new, ("variant", "test", "N", "seed"))
    else:
        append_once(os.path.join(folder, "table3_runs.csv"), new, ("test", "N", "seed"))


def stress_reached(r):
    """The loading stress at a run's end (MPa): sigma_v = 3 p' / (1 + 2 K0) of an oedometric run, p' of
    an isotropic one."""
    p = float(r["p_end_MPa"])
    return 3.0 * p / (1.0 + 2.0 * float(r["K0_end"])) if r["test"] == "O" else p


LOADED_MPA = 95.0  # a run whose walls end below this never carried the paper's 100 MPa


def variant_runs(rows, variant):
    """{test: {seed: row}} of one variant's runs at N = 2 (the first row of a seed kept)."""
    runs = {"O": {}, "I": {}}
    for r in rows:
        if r["variant"] == variant and r["N"] == "2":
            runs[r["test"]].setdefault(r["seed"], r)
    return runs


def io_variants(folder):
    """{variant: (the deck variables, what it tests)} of io_variants.csv, in its order."""
    return dict((r["variant"], (r["vars"], r["tests"])) for r in read_rows(os.path.join(folder, "io_variants.csv")))


def io_mechanisms(folder):
    """Each candidate mechanism of the paper's isotropic-over-oedometric breakage at N = 2: the events
    per initial grain of O-2 and I-2, their paired difference at the tests' ends (with Holm's
    correction over the variants) and after the first load, and the oedometer's K0 and p' at
    sigma_v = 100 MPa."""
    rows = read_rows(os.path.join(folder, "io_mechanisms_runs.csv"))
    found = []
    for variant, (_, tests) in io_variants(folder).items():
        runs = variant_runs(rows, variant)
        if not runs["O"] or not runs["I"]:
            found.append((variant, tests, None, None, None))
            continue
        end = io_change(runs["O"], runs["I"])
        after = io_change(runs["O"], runs["I"], lambda r: per_grain(r) - per_grain(r, "events_first_load"))
        found.append((variant, tests, runs, end, after))
    tested = [f for f in found if f[3] is not None]
    adjusted = dict(zip((f[0] for f in tested), holm([f[3]["p"] for f in tested])))
    lines = ["| variant | what it tests | seeds | O-2 events / N_i | I-2 events / N_i | I - O at the ends (95%%) | p "
             "| resolved | Holm (%d) | I - O after the first load (95%%) | O-2 K0 at the end | O-2 p' at the end (MPa) "
             "| loading stress at the end, O-2 sigma_v and I-2 p' (MPa) |"
             % len(tested), "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for variant, tests, runs, end, after in found:
        if end is None:
            lines.append("| %s | %s | 0 | not run | | | | | | | | | |" % (variant, tests))
            continue
        p_holm = adjusted[variant]
        lines.append("| %s | %s | %d | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            variant, tests, end["pairs"], cell([per_grain(r) for r in runs["O"].values()], 4),
            cell([per_grain(r) for r in runs["I"].values()], 4), interval_cell(end, 4),
            "%.2g" % end["p"] if end["p"] == end["p"] else "", end["resolved"],
            ("yes" if p_holm < 0.05 else "no") if p_holm == p_holm else "", interval_cell(after, 4),
            cell([float(r["K0_end"]) for r in runs["O"].values()], 3),
            cell([float(r["p_end_MPa"]) for r in runs["O"].values()], 1),
            "%s; %s" % tuple(cell([stress_reached(r) for r in runs[test].values()], 1) for test in ("O", "I"))))
    lines.append("| the paper (one run each) | | 1 | %.4f | %.4f | %+.4f | | | | | | | 100; 100 |"
                 % (paper_per_grain("O", "2"), paper_per_grain("I", "2"), paper_io("2")))
    return "\n".join(lines)


TABLES = {"table3": table3, "table3_io": table3_io, "readings": readings, "readings_changes": readings_changes,
          "upscaling": upscaling, "io_mechanisms": io_mechanisms, "io_scatter": io_scatter,
          "conclusions_fontainebleau": conclusions_fontainebleau}
