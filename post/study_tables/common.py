"""What every study's tables share: reading a CSV, a mean with its 95% interval over seeds, a change
with its marks, and runs keyed by seed."""
import csv

from post.seeds import interval, statistics


def read_rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def by_setting(rows, key="setting"):
    """{setting: {seed: row}} in the order the settings first appear (the first row of a seed kept)."""
    out = {}
    for r in rows:
        out.setdefault(r[key], {}).setdefault(r["seed"], r)
    return out


def seed_values(seeds, column, scale=1.0):
    return dict((k, scale * float(r[column])) for k, r in seeds.items() if r.get(column, "") not in ("", "nan"))




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


def interval_cell(c, digits):
    """A change of compare() as 'change (low .. high)'; the change alone where it has no interval."""
    if c["low"] != c["low"]:
        return "%+.*f" % (digits, c["change"])
    return "%+.*f (%+.*f .. %+.*f)" % (digits, c["change"], digits, c["low"], digits, c["high"])


def conclusions(rows):
    """A study's opening table: rows of (conclusion, measured, runs, command), the measured cell written
    from the CSVs (a mean or change with its 95% interval, and whether the one rule resolves it)."""
    lines = ["| # | conclusion | measured (95% interval) | runs | the command that makes it |", "|---|---|---|---|---|"]
    for k, (finding, measured, runs, command) in enumerate(rows, 1):
        lines.append("| %d | %s | %s | %s | `%s` |" % (k, finding, measured, runs, command))
    return "\n".join(lines)
