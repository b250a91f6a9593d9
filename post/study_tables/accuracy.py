"""What accuracy costs in time (studies/accuracy/README.md): each setting's errors against the N = 1
reference and its cost against N2 in the same round, and its measures against N2 by the one rule
(bench/accuracy_seeds.sh writes accuracy_seeds_runs.csv)."""
import os
import statistics as py_statistics

from post.seeds import compare, holm, interval, statistics, welch
from post.study_tables.common import by_setting, cell, change_cell, read_rows, seed_values

PAGE = "studies/accuracy/README.md"

# The accuracy-versus-cost study with seeds (bench/accuracy_seeds.sh): its errors (scale), measures.
ACCURACY_ERRORS = [("err_porosity", "dn", 1, 4), ("err_K0", "dK0", 1, 3), ("err_gsd_percent", "dGSD (%)", 1, 2),
                   ("err_I_G", "dI_G", 1, 4), ("err_events_relative", "d events (%)", 100, 1),
                   ("err_yield_relative", "d yield (%)", 100, 1)]
ACCURACY_MEASURES = [("n_1MPa", "n at 1 MPa", 4), ("n_10MPa", "n at 10 MPa", 4), ("n_100MPa", "n at 100 MPa", 4),
                     ("K0_mean", "K0", 3), ("I_G_100MPa", "I_G at 100 MPa", 4),
                     ("events_per_grain", "events per grain", 4), ("yield_MPa", "yield (MPa)", 2)]
ACCURACY_BASE, ACCURACY_REFERENCE = "N2", "N1"


def accuracy_errors(folder):
    settings = by_setting(read_rows(os.path.join(folder, "accuracy_seeds_runs.csv")))
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


def accuracy_changes(folder):
    settings = by_setting(read_rows(os.path.join(folder, "accuracy_seeds_runs.csv")))
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


TABLES = {"accuracy_errors": accuracy_errors, "accuracy_changes": accuracy_changes}
