"""What accuracy costs in time (studies/accuracy/README.md): the opening table of conclusions (each knob's
price against N2 in the same round and its error against the N = 1 reference, with Holm's correction over
the table), each setting's errors against the reference and its cost, and its measures against N2, all by
the one rule (bench/accuracy_seeds.sh writes accuracy_seeds_runs.csv)."""
import os
import statistics as py_statistics

from post.seeds import compare, holm, interval, resolved, statistics, welch
from post.study_tables.common import by_setting, cell, change_cell, conclusions, read_rows, seed_values

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


# The opening table: each knob the CSV varies, its price (the cost against N2 in the same round) and
# its error against the N = 1 reference, by the one rule, with Holm's correction over the table.
KNOBS = [("N", "N", ""), ("L_R", "L_R", ""), ("dmin_mm", "dmin", " mm"), ("layout", "layout", ""),
         ("dt_fraction", "dt fraction", ""), ("fragment_density", "fragment density", ""),
         ("crush_every", "crush_every", ""), ("dt_every", "dt_every", "")]
ERROR_NAMES = {"err_porosity": "n", "err_K0": "K0", "err_gsd_percent": "GSD", "err_I_G": "I_G",
               "err_events_relative": "events", "err_yield_relative": "yield"}
COMMAND = "bash bench/accuracy_seeds.sh"


def knob_of(seeds, base):
    """(order, label, value, base value, unit) of the knob in which a setting differs from the base."""
    row, ref = next(iter(seeds.values())), next(iter(base.values()))
    for order, (column, label, unit) in enumerate(KNOBS):
        if row[column] != ref[column]:
            return order, label, row[column], ref[column], unit
    return len(KNOBS), "?", "", "", ""


def cost_test(seeds, base):
    """The runtime over the base's in the same round: (median, mean, low, high, p against 1, rounds)."""
    ratios = [float(r["seconds"]) / float(base[k]["seconds"]) for k, r in seeds.items() if k in base]
    n, mean, _, se = statistics(ratios)
    low, high, p = interval(mean - 1.0, se, n - 1) if n > 1 else (float("nan"),) * 3
    return py_statistics.median(ratios), mean, 1.0 + low, 1.0 + high, p, n


def error_test(name, seeds, reference, base, column, scale):
    """A setting's error against the reference, by compare(): at N = 2 paired against N2's error (what
    the knob adds); for the reference's own setting, N2's error against the reference's own scatter
    (each of its seeds against the others' mean; Welch, the two share no sample)."""
    if name != ACCURACY_REFERENCE:
        return compare(seed_values(base, column, scale), seed_values(seeds, column, scale))
    change, se, df = welch(seed_values(reference, column, scale).values(), seed_values(base, column, scale).values())
    low, high, p = interval(change, se, df)
    return dict(change=change, low=low, high=high, p=p, design="unpaired (Welch)", resolved=resolved(change, se, df))


def knob_findings(folder):
    """Each setting against the base, in KNOBS' order: its knob, its price (cost_test) and its errors
    (error_test), each with its adjusted p after Holm's correction over the opening table's comparisons."""
    settings = by_setting(read_rows(os.path.join(folder, "accuracy_seeds_runs.csv")))
    reference, base = settings[ACCURACY_REFERENCE], settings[ACCURACY_BASE]
    found = []
    for name, seeds in settings.items():
        if name != ACCURACY_BASE:
            errors = [(ERROR_NAMES[column], error_test(name, seeds, reference, base, column, scale), digits)
                      for column, _, scale, digits in ACCURACY_ERRORS]
            found.append((knob_of(seeds, base), name, cost_test(seeds, base), errors, len(seeds)))
    found.sort(key=lambda f: f[0][0])  # the knobs in KNOBS' order, each knob's settings as the CSV has them
    adjusted = iter(holm([p for f in found for p in [f[2][4]] + [c["p"] for _, c, _ in f[3]]]))
    out = []
    for knob, name, cost, errors, seeds in found:
        median, mean, low, high, p, rounds = cost
        cost_holm = next(adjusted)
        out.append(dict(knob=knob, name=name, median=median, mean=mean, low=low, high=high, rounds=rounds,
                        seeds=seeds, cheaper=high < 1, dearer=low > 1, cost_holm=cost_holm,
                        errors=[(measure, c, digits, next(adjusted)) for measure, c, digits in errors]))
    return out


def survivors_of(findings):
    """The comparisons of the opening table resolved and surviving Holm's correction over it."""
    out = []
    for f in findings:
        if (f["cheaper"] or f["dearer"]) and f["cost_holm"] < 0.05:
            out.append("%s's cost" % f["name"])
        out += ["%s's error in %s" % (f["name"], measure) for measure, c, _, p_holm in f["errors"]
                if c["resolved"] == "yes" and p_holm < 0.05]
    return out


def answer_accuracy(folder):
    """The page's answer under its title: which prices are resolved, what N = 1 costs against N2, and
    what survives Holm's correction over the opening table."""
    findings = knob_findings(folder)
    knob_words = lambda f: "%s %s%s" % (f["knob"][1], f["knob"][2], f["knob"][4])  # noqa: E731
    knobs = [f for f in findings if f["name"] != ACCURACY_REFERENCE]
    priced = ["%s (%s)" % (knob_words(f), "dearer" if f["dearer"] else "cheaper") for f in knobs
              if f["dearer"] or f["cheaper"]]
    n1 = next(f for f in findings if f["name"] == ACCURACY_REFERENCE)
    total = sum(1 + len(f["errors"]) for f in findings)
    survivors = survivors_of(findings)
    return ("**The answer**: among the N = 2 knobs, %s. One N = 1 run costs %.2f (%.2f .. %.2f) N2 runs in its "
            "round (the mean over %d rounds%s). %s of the %d comparisons of the table below %s Holm's correction%s." % (
                ("only the prices of %s are resolved" % " and ".join(priced)) if priced else "no price is resolved",
                n1["mean"], n1["low"], n1["high"], n1["rounds"],
                "" if n1["dearer"] or n1["cheaper"] else ", not resolved from 1",
                "None" if not survivors else "%d" % len(survivors), total,
                "survive" if len(survivors) > 1 else "survives",
                (": " + ", ".join(survivors)) if survivors else ""))


def conclusions_accuracy(folder):
    findings = knob_findings(folder)
    rows, total, n_resolved = [], 0, 0
    for f in findings:
        (_, label, value, base_value, unit), name = f["knob"], f["name"]
        total += 1 + len(f["errors"])
        cheaper, dearer = f["cheaper"], f["dearer"]
        n_resolved += cheaper or dearer
        price = "cost: median %.2f, mean %.2f (%.2f .. %.2f)%s" % (
            f["median"], f["mean"], f["low"], f["high"],
            "" if not (cheaper or dearer) else ("**" if f["cost_holm"] < 0.05 else "*"))
        more, less, cells = [], [], []
        for measure, c, digits, p_holm in f["errors"]:
            if c["resolved"] == "yes":
                n_resolved += 1
                (more if c["change"] > 0 else less).append(measure)
                cells.append("%s %s" % (measure, change_cell(c, digits, p_holm)))
        cost_words = "costs more" if dearer else "costs less" if cheaper else "cost not resolved"
        if name == ACCURACY_REFERENCE:
            finding = "%s = %s instead of %s = %s: %s; one N = %s run's error exceeds N = %s's own scatter in %s" % (
                label, value, label, base_value, cost_words, base_value, value, ", ".join(more) if more else "no measure")
        else:
            error_words = "; ".join(w for w in ("more error than N2 in " + ", ".join(more) if more else "",
                                                "less error than N2 in " + ", ".join(less) if less else "") if w)
            finding = "%s %s%s instead of %s%s: %s; %s" % (label, value, unit, base_value, unit, cost_words,
                                                         error_words or "no error resolved beyond N2's")
        error = ("error: " + ", ".join(cells) + ", the rest not resolved") if cells \
            else "error: none of %d resolved" % len(f["errors"])
        runs = "%d seeds, %d rounds" % (f["seeds"], f["rounds"]) if name != ACCURACY_REFERENCE else \
            "%d seeds of %s, %d rounds" % (f["seeds"], name, f["rounds"])
        rows.append(("**%s**: %s" % (name, finding), price + "; " + error, runs, COMMAND))
    survivors = survivors_of(findings)
    return conclusions(rows) + "\n\n(%d comparisons, a cost and %d errors a row: %d resolved ('*'); %s after Holm's " \
        "correction over the %d ('**'). 'u': unpaired, Welch.)" % (
            total, len(ACCURACY_ERRORS), n_resolved, ("these survive: " + ", ".join(survivors)) if survivors else "none",
            total)


TABLES = {"answer_accuracy": answer_accuracy, "conclusions_accuracy": conclusions_accuracy,
          "accuracy_errors": accuracy_errors, "accuracy_changes": accuracy_changes}
