#!/usr/bin/python3
"""What accuracy costs, resolved by seeds: the analysis of bench/accuracy_seeds.sh (runs OUT_DIR/<name>_s<seed>).

    bench/accuracy_seeds.py [--reference NAME] OUT_DIR

Per run (OUT_DIR/accuracy_seeds_runs.csv): its setting and seed, its runtime, and the measures of
the compression curve: n at 1, 10 and 100 MPa, K0 (1 - 100 MPa, the mean), I_G at 10 and 100 MPa,
the percent passing at 100 MPa at each sieve, the events per initial grain, the yield stress (the
two lines of accuracy_vs_cost.py); and its errors against the reference seeds' mean curves, the
measures of accuracy_vs_cost.py (the largest difference in n, K0, GSD, I_G; events and yield
relative). The reference's own errors, each seed against the mean of the others, give the spread
inside which an error is not an error.

Per setting (OUT_DIR/accuracy_seeds_settings.csv, post/seeds.py's statistics and changes):
  - each error's mean and standard error over the seeds, and whether it exceeds the reference's own
    spread by its 95% t interval (Welch);
  - each measure's change against the base N = 2 setting (L_R 0.1, dmin 0.05 mm, ...) and against
    the reference, by post/seeds.py's one rule (compare()): paired by seed on three or more common
    seeds where the two sides correlate positively, else unpaired (Welch); across N too, for the seed
    draws the sample at each N and the correlation decides; resolved or not by its 95% t interval
    (<measure>_vs_base_design and _vs_reference_design: paired or Welch; vs_base_paired: yes where
    every measure paired, no where none, partly else);
  - the cost: the runtime over the base's in the same round (seed), median and range of the rounds.
Writes also accuracy_seeds_table.md and pareto_seeds.png (each error against the cost ratio, with
its error bars, the reference's spread shaded)."""
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.dirname(HERE))
import accuracy_vs_cost as avc  # noqa: E402
from post import compression_seeds  # noqa: E402
from post.seeds import compare, resolved, statistics, t_quantile, welch_df, write_csv  # noqa: E402

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

KNOBS = ["N", "L_R", "dmin_mm", "dt_fraction", "dt_every", "crush_every", "layout", "fragment_density"]
ERRORS = ["err_porosity", "err_K0", "err_gsd_percent", "err_I_G", "err_events_relative", "err_yield_relative"]
MEASURES = ["n_1MPa", "n_10MPa", "n_100MPa", "K0_mean", "I_G_10MPa", "I_G_100MPa", "events_per_grain", "yield_MPa"]
BASE = "N2"
REFERENCE = "N1"  # N = 1 at the base's knobs; --reference NAME: another setting in its place


def at(history, column, stress):
    """The column at a vertical stress (Pa): post/compression_seeds.py's at()."""
    return compression_seeds.at(history["sigma_z"], history[column], stress)


def measures(run):
    h = run["history"]
    out = {"n_1MPa": at(h, "porosity", 1e6), "n_10MPa": at(h, "porosity", 1e7), "n_100MPa": at(h, "porosity", 1e8),
           "K0_mean": float(np.nanmean(avc.on_grid(h, "K0", lo=1e6))), "I_G_10MPa": at(h, "I_G", 1e7),
           "I_G_100MPa": at(h, "I_G", 1e8), "events_per_grain": run["events"] / run["initial"],
           "yield_MPa": run["yield"] / 1e6}
    if run["gsd"] is not None:
        size = sieve_column(run["gsd"])
        for d, p in zip(run["gsd"][size], run["gsd"]["percent_passing"]):
            out["pass_%g" % d] = float(p)
    return out


def sieve_column(gsd):
    return next(k for k in gsd if k != "percent_passing")


def curves(run):
    """The run's curves on accuracy_vs_cost's grid, as that study compares them: n from 0.2 MPa, K0
    (a 5-row running mean) and I_G from 1 MPa; NaN outside the run."""
    h = run["history"]
    return {"porosity": avc.on_grid(h, "porosity"), "K0": avc.on_grid(h, "K0", lo=1e6, smooth=True),
            "I_G": avc.on_grid(h, "I_G", lo=1e6)}


def mean_of(runs):
    """The runs' mean: curves on the grid, passing at 100 MPa, events per grain and yield stress."""
    return {"curves": {c: np.nanmean([r["curves"][c] for r in runs], axis=0) for c in ("porosity", "K0", "I_G")},
            "passing": np.mean([r["gsd"]["percent_passing"] for r in runs], axis=0),
            "events_per_grain": float(np.mean([r["events"] / r["initial"] for r in runs])),
            "yield": float(np.mean([r["yield"] for r in runs]))}


def errors(run, ref):
    """accuracy_vs_cost's errors of a run against a mean: the largest differences of the curves and
    of the passing at 100 MPa, the events per grain and the yield stress relative."""
    def largest(column):
        d = np.abs(run["curves"][column] - ref["curves"][column])
        return float(np.nanmax(d)) if np.any(np.isfinite(d)) else float("nan")
    return {"err_porosity": largest("porosity"), "err_K0": largest("K0"), "err_I_G": largest("I_G"),
            "err_gsd_percent": float(np.max(np.abs(run["gsd"]["percent_passing"] - ref["passing"]))),
            "err_events_relative": abs(run["events"] / run["initial"] / ref["events_per_grain"] - 1.0),
            "err_yield_relative": abs(run["yield"] / ref["yield"] - 1.0)}


def main(out):
    runs = [avc.load(f) for f in sorted(d for d in (os.path.join(out, n) for n in os.listdir(out))
                                          if os.path.exists(os.path.join(d, "done")))]
    runs = [r for r in runs if r["finished"] and r["gsd"] is not None]
    for r in runs:
        r["setting"] = r["name"].rsplit("_s", 1)[0]
        r["curves"] = curves(r)
    refs = [r for r in runs if r["setting"] == REFERENCE]
    if len(refs) < 2:
        sys.exit("accuracy_seeds.py: %d finished reference runs in %s; the reference needs 2 or more seeds" % (len(refs), out))
    ref_mean = mean_of(refs)
    rows = []
    for r in runs:
        row = {k: r[k] for k in ["setting", "seed", "ranks", "seconds", "initial", "final", "events"] + KNOBS}
        row.update(measures(r))
        # the reference's own spread: each seed against the mean of the others
        row.update(errors(r, mean_of([o for o in refs if o is not r]) if r["setting"] == REFERENCE else ref_mean))
        rows.append(row)
    write_csv(os.path.join(out, "accuracy_seeds_runs.csv"), rows)
    csv_rows, spread = settings_of(rows)
    write_csv(os.path.join(out, "accuracy_seeds_settings.csv"), csv_rows)
    table = markdown(csv_rows, spread)
    open(os.path.join(out, "accuracy_seeds_table.md"), "w").write(table)
    print(table)
    figure(csv_rows, spread, out)


def settings_of(rows):
    """Per setting, from the runs' rows (those of accuracy_seeds_runs.csv): the lines of
    accuracy_seeds_settings.csv, and the reference's own spread of each error (statistics())."""
    settings = []
    for r in rows:
        if r["setting"] not in settings:
            settings.append(r["setting"])
    by = {s: {r["seed"]: r for r in rows if r["setting"] == s} for s in settings}
    spread = {e: statistics([r[e] for r in by[REFERENCE].values()]) for e in ERRORS}
    csv_rows = []
    for s in settings:
        seeds = by[s]
        line = {"setting": s, "seeds": len(seeds)}
        for k in KNOBS:
            line[k] = next(iter(seeds.values()))[k]
        for e in ERRORS:
            n, mean, sd, se = statistics([r[e] for r in seeds.values() if math.isfinite(r[e])])
            line[e], line[e + "_se"] = mean, se
            if s != REFERENCE:
                line[e + "_beyond_spread"] = resolved(mean - spread[e][1], math.sqrt(se ** 2 + spread[e][3] ** 2),
                                                      welch_df(se, n, spread[e][3], spread[e][0])) \
                    if mean > spread[e][1] else "no"
        pairing = []  # whether each measure's change against the base is paired
        for m in MEASURES:
            base = {k: r[m] for k, r in by.get(BASE, {}).items() if math.isfinite(r[m])}
            other = {k: r[m] for k, r in seeds.items() if math.isfinite(r[m])}
            if s != BASE and base and other:
                # the one rule (post/seeds.py compare()): paired by seed where three or more seeds are
                # common and correlate positively, else Welch; at another N too, where the correlation
                # test decides (the seed draws the sample at each N)
                c = compare(base, other)
                line[m] = statistics(list(other.values()))[1]
                design = "paired" if c["design"].startswith("paired") else "Welch"
                pairing.append(design == "paired")
                line["vs_base_paired"] = "yes" if all(pairing) else "no" if not any(pairing) else "partly"
                line[m + "_vs_base"], line[m + "_vs_base_se"] = c["change"], c["se"]
                line[m + "_vs_base_resolved"] = c["resolved"]
                line[m + "_vs_base_design"] = design
            ref = {k: r[m] for k, r in by[REFERENCE].items() if math.isfinite(r[m])}
            if other:
                stats = statistics(list(other.values()))
                line[m], line[m + "_se"] = stats[1], stats[3]
            if s != REFERENCE and ref and other:
                c = compare(ref, other)  # the one rule, as against the base
                line[m + "_vs_reference"], line[m + "_vs_reference_se"] = c["change"], c["se"]
                line[m + "_vs_reference_resolved"] = c["resolved"]
                line[m + "_vs_reference_design"] = "paired" if c["design"].startswith("paired") else "Welch"
        # the cost: runtime over the base's in the same round
        ratios = [r["seconds"] / by[BASE][k]["seconds"] for k, r in seeds.items() if BASE in by and k in by[BASE]]
        line["seconds"] = statistics([r["seconds"] for r in seeds.values()])[1]
        if ratios:
            line["cost_vs_base_median"] = float(np.median(ratios))
            line["cost_vs_base_min"], line["cost_vs_base_max"] = min(ratios), max(ratios)
            n, mean, _, se = statistics(ratios)
            line["cost_vs_base_mean"], line["cost_vs_base_se"] = mean, se
            line["cost_vs_base_resolved"] = resolved(mean - 1.0, se, n - 1) if s != BASE else ""
        csv_rows.append(line)
    return csv_rows, spread


def markdown(lines, spread):
    out = ["Errors against the reference seeds' mean (mean +- se over the setting's seeds; '*': beyond the "
           "reference's own spread by its 95% t interval). The reference's row: each of its seeds against the mean of the others. "
           "Cost: the runtime over N2's in the same round, median and range of the rounds ('*': the rounds' mean "
           "differs from 1 by its 95% t interval).", "",
           "| setting | seeds | cost vs N2 (median, range) | dn | dK0 | dGSD (%) | dI_G | d events (%) | d yield (%) |",
           "|---|---|---|---|---|---|---|---|---|"]
    for line in lines:
        cells = [line["setting"], "%d" % line["seeds"]]
        cells.append("%.2f (%.2f - %.2f)%s" % (line["cost_vs_base_median"], line["cost_vs_base_min"], line["cost_vs_base_max"],
                                               "*" if line.get("cost_vs_base_resolved") == "yes" else "")
                     if "cost_vs_base_median" in line else "")
        for e, digits, scale in (("err_porosity", 4, 1), ("err_K0", 3, 1), ("err_gsd_percent", 2, 1), ("err_I_G", 4, 1),
                                 ("err_events_relative", 1, 100), ("err_yield_relative", 1, 100)):
            mean, se = line[e] * scale, line[e + "_se"] * scale
            mark = "*" if line.get(e + "_beyond_spread") == "yes" else ""
            cells.append(("%.*f" % (digits, mean)) + ("" if not math.isfinite(se) else " +- %.*f" % (digits, se)) + mark)
        out.append("| " + " | ".join(cells) + " |")
    out += ["", "Changes against the base N2 by the one rule (post/seeds.py): paired by seed where three or more "
            "seeds are common and correlate positively, else Welch ('u'); mean +- se, '*': resolved (95% t interval):",
            "",
            "| setting | n at 10 MPa | n at 100 MPa | K0 | I_G at 100 MPa | events per grain | yield (MPa) |",
            "|---|---|---|---|---|---|---|"]
    for line in lines:
        if "n_10MPa_vs_base" not in line:
            continue
        cells = [line["setting"]]
        for m, digits in (("n_10MPa", 4), ("n_100MPa", 4), ("K0_mean", 3), ("I_G_100MPa", 4), ("events_per_grain", 4),
                          ("yield_MPa", 2)):
            cells.append("%+.*f +- %.*f%s%s" % (digits, line[m + "_vs_base"], digits, line[m + "_vs_base_se"],
                                                 "*" if line[m + "_vs_base_resolved"] == "yes" else "",
                                                 " u" if line[m + "_vs_base_design"] == "Welch" else ""))
        out.append("| " + " | ".join(cells) + " |")
    return "\n".join(out) + "\n"


def figure(lines, spread, out):
    keys = [("err_porosity", "porosity n"), ("err_K0", "K0"), ("err_gsd_percent", "GSD at 100 MPa (% passing)"),
            ("err_I_G", "I_G"), ("err_events_relative", "events per grain (relative)")]
    fig, axes = plt.subplots(1, len(keys), figsize=(4.4 * len(keys), 4.6))
    for ax, (key, title) in zip(axes, keys):
        top = spread[key][1] + t_quantile(spread[key][0] - 1) * spread[key][3]
        ax.axhspan(0, top, color="0.85", label="reference's own spread (95% t upper bound)")
        for k, line in enumerate(lines):
            if line["setting"] == REFERENCE or "cost_vs_base_median" not in line:
                continue
            x = line["cost_vs_base_median"]
            xerr = [[x - line["cost_vs_base_min"]], [line["cost_vs_base_max"] - x]]
            se = line[key + "_se"] if math.isfinite(line[key + "_se"]) else 0
            half = t_quantile(line["seeds"] - 1) * se if line["seeds"] > 1 else 0
            ax.errorbar(x, line[key], yerr=half, xerr=xerr, fmt="o",
                        color="C3" if line.get(key + "_beyond_spread") == "yes" else "C0", ms=4, capsize=2)
            ax.annotate(line["setting"], (x, line[key]), fontsize=7, xytext=(3, 3 + 4 * (k % 3)), textcoords="offset points")
        ax.set_xscale("log")
        ax.set_xlabel("runtime over N2's in the same round")
        ax.set_ylabel("largest difference from the reference's mean")
        ax.set_title(title, fontsize=9)
    axes[0].legend(fontsize=7, loc="upper left")
    fig.suptitle("Accuracy against cost with seeds: mean and 95% t interval over seeds, cost median and range of rounds "
                 "(red: beyond the reference's spread)", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "pareto_seeds.png"), dpi=100)
    plt.close(fig)


if __name__ == "__main__":
    args = sys.argv[1:]
    if args[:1] == ["--reference"] and len(args) == 3:
        REFERENCE, args = args[1], args[2:]
    if len(args) != 1:
        sys.exit(__doc__)
    main(args[0])
