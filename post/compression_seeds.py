#!/usr/bin/python3
"""The compression tests' seeds gathered (studies/fontainebleau/README.md, "Upscaling" and "The strength
reading side by side"): oedometric and isotropic runs, several seeds each, grouped into settings
and compared with a reference setting measure by measure.

    post/compression_seeds.py RUN_DIR [RUN_DIR ...] [--by-folder] [--reference N=1 | folder=NAME]
                              [--out DIR] [--name NAME]

RUN_DIR: the folder of one run of the decks (history_<test><N>.csv, gsd_<test><N>_100MPa.csv and
screen.txt, as scripts/fontainebleau_runs.sh and bench/accuracy_vs_cost.sh leave them). Its seed is
read from setting.csv, else from a _s<seed> suffix of the folder's name, else it is the decks'.
A setting is the test and N, and with --by-folder also the name of the folder that holds the run
(scripts/strength_readings.sh puts each reading's runs in a folder of its own). --reference: the
setting each test is compared with, N=1 (the default: the upscaling) or folder=NAME.

Measures of a run, against the vertical stress (O) or the mean stress p' (I): the porosity at 1, 10
and 100 MPa; K0 averaged over log(sigma_v) from 1 to 100 MPa (O); I_G at the history's first row
(the first load) and at 1, 10 and 100 MPa; the events per initial grain by 1 MPa and at the end;
the yield stress (where the e - log(stress) lines fitted to 0.3 - 3 MPa and above 50 MPa meet); the
percent passing each sieve at 100 MPa. Each setting's seeds give a mean and a standard error. The
change from the reference follows post/seeds.py's one rule: paired on the common seeds where three
or more are common and the two settings correlate positively over them (under another N a seed
draws another sample, yet the seeds rank the same way at N = 1, 1.5 and 2), else unpaired (Welch);
resolved where its 95% Student-t interval excludes zero; each row says which design it used. Along
the whole curve (0.5 - 99 MPa) the porosity's largest difference of the mean curves is reported with
its standard error, Welch's df and interval there, and the largest |difference| / se anywhere on
the curve; at 100 MPa the same over the sieves.

Writes DIR (default .)/NAME_runs.csv (a row a run), NAME_seeds.csv (a row a setting and measure),
NAME_seeds.png (the mean porosity curves and gradings at 100 MPa with 95% t bands) and NAME_curves.png
(porosity, I_G and events per grain against the stress, the gradings at 1, 10, 50 and 100 MPa), NAME
default compression; prints the table as Markdown.
"""
import argparse
import csv
import glob
import math
import os
import re
import sys
import warnings

if not __package__:  # run as a file (python3 post/compression_seeds.py): the folder above post/ holds the package
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from post import requires  # noqa: E402

requires("compression_seeds", "numpy", "matplotlib")

import numpy as np  # noqa: E402

from post.seeds import compare as compare_seeds, interval, resolved, statistics, t_quantile, welch_df, write_csv  # noqa: E402

DECK_SEED = "15485863"
STRESS = {"O": "sigma_z", "I": "p"}  # the loading axis each test is read against
# the curves' comparison, 0.5 - 99 MPa (a run to 100 MPa logs its last row at 99 - 99.7 MPa)
GRID = np.exp(np.linspace(math.log(5e5), math.log(9.9e7), 120))
LEVELS = ((1e6, "1MPa"), (1e7, "10MPa"), (1e8, "100MPa"))
GSD_LEVELS = ("1", "10", "50", "100")  # MPa: the decks' gradings during loading (in.write_gsd)
NOT_MEASURES = ("test", "N", "folder_name", "seed", "folder", "sieves", "passing", "curve", "curves", "gsd_levels")


def read_columns(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return dict((k, np.array([float(r[k]) for r in rows])) for k in rows[0])


def sorted_by(stress, values):
    order = np.argsort(stress)
    return np.log(stress[order]), values[order]


def at(stress, values, target):
    """The value at a stress, interpolated in log(stress); the last row's where the run ended within
    2% below it (a run to 100 MPa logs its last row at 99 - 99.7 MPa); NaN outside the run."""
    log_s, v = sorted_by(stress, values)
    x = math.log(target)
    if log_s[-1] < x <= log_s[-1] + math.log(1.02):
        return float(v[-1])
    return float(np.interp(x, log_s, v, left=np.nan, right=np.nan))


def on_grid(stress, values, grid=GRID):
    log_s, v = sorted_by(stress, values)
    return np.interp(np.log(grid), log_s, v, left=np.nan, right=np.nan)


def yield_stress(stress, void_ratio):
    """Where the e - log10(stress) lines fitted to 0.3 - 3 MPa and above 50 MPa meet (Pa); NaN where a
    range has under two rows. bench/accuracy_vs_cost.py reads the oedometric curves with it."""
    low, high = (stress > 3e5) & (stress < 3e6), stress > 5e7
    if low.sum() < 2 or high.sum() < 2:
        return float("nan")
    a1, b1 = np.polyfit(np.log10(stress[low]), void_ratio[low], 1)
    a2, b2 = np.polyfit(np.log10(stress[high]), void_ratio[high], 1)
    return float(10 ** ((b1 - b2) / (a2 - a1)))


def seed_of(folder):
    setting = os.path.join(folder, "setting.csv")
    if os.path.exists(setting):
        with open(setting) as f:
            row = next(csv.DictReader(f))
        if row.get("seed"):
            return row["seed"]
    m = re.search(r"_s(\d+)$", os.path.basename(folder.rstrip("/")))
    return m.group(1) if m else DECK_SEED


def initial_grains(folder):
    with open(os.path.join(folder, "screen.txt"), errors="replace") as f:
        m = re.search(r"^SAMPLE N = \S+: (\d+) particles", f.read(), re.M)
    if not m:
        sys.exit("compression_seeds.py: %s: no SAMPLE line in screen.txt" % folder)
    return int(m.group(1))


def load(folder):
    """One run: its test, N, folder name, seed, measures, porosity curve on GRID and passing at 100 MPa."""
    histories = glob.glob(os.path.join(folder, "history_[OI]*.csv"))
    if len(histories) != 1:
        sys.exit("compression_seeds.py: %s: expected one history_O*.csv or history_I*.csv" % folder)
    name = os.path.basename(histories[0])[len("history_"):-len(".csv")]
    test, n = name[0], name[1:]
    h = read_columns(histories[0])
    stress = h[STRESS[test]]
    grains = initial_grains(folder)
    run = {"test": test, "N": n, "folder_name": os.path.basename(os.path.dirname(os.path.abspath(folder))),
           "seed": seed_of(folder), "folder": folder}
    for level, tag in LEVELS:
        run["n_" + tag] = at(stress, h["porosity"], level)
    if test == "O":
        run["K0_mean"] = float(np.nanmean(on_grid(stress, h["K0"], np.exp(np.linspace(math.log(1e6), math.log(1e8), 60)))))
    run["I_G_first_load"] = float(h["I_G"][0])
    for level, tag in LEVELS:
        run["I_G_" + tag] = at(stress, h["I_G"], level)
    run["events_per_grain_1MPa"] = at(stress, h["events"], 1e6) / grains
    run["events_per_grain"] = h["events"][-1] / grains
    run["yield_MPa"] = yield_stress(stress, h["void_ratio"]) / 1e6 if "void_ratio" in h else float("nan")
    gsd = read_columns(os.path.join(folder, "gsd_%s_100MPa.csv" % name))
    run["sieves"] = gsd["size_mm"]
    run["passing"] = gsd["percent_passing"]
    for d, p in zip(gsd["size_mm"], gsd["percent_passing"]):
        run["pass_%g" % d] = float(p)
    run["curve"] = on_grid(stress, h["porosity"])
    run["curves"] = {"I_G": on_grid(stress, h["I_G"]), "events": on_grid(stress, h["events"]) / grains}
    run["gsd_levels"] = {}
    for level in GSD_LEVELS:
        path = os.path.join(folder, "gsd_%s_%sMPa.csv" % (name, level))
        if os.path.exists(path):
            run["gsd_levels"][level] = read_columns(path)["percent_passing"]
    return run


def measure_names(runs):
    names = []
    for r in runs:
        names += [k for k in r if k not in names and k not in NOT_MEASURES]
    return names


def group(runs, by_folder):
    """{(test, N, folder name or ""): {seed: run}}; a second run of one setting and seed is refused."""
    out = {}
    for r in runs:
        key = (r["test"], r["N"], r["folder_name"] if by_folder else "")
        seeds = out.setdefault(key, {})
        if r["seed"] in seeds:
            sys.exit("compression_seeds.py: %s and %s are both %s-%s%s with seed %s"
                     % (seeds[r["seed"]]["folder"], r["folder"], r["test"], r["N"],
                        " in %s" % key[2] if by_folder else "", r["seed"]))
        seeds[r["seed"]] = r
    return out


def reference_of(key, reference):
    """The reference setting of a setting's test: (test, N given, same folder) or (test, same N,
    folder given)."""
    what, value = reference
    test, n, folder = key
    return (test, value, folder) if what == "N" else (test, n, value)


def mean_se(arrays):
    """The mean, standard error and count of the runs at each point; NaN where fewer than two runs reach it."""
    a = np.array(arrays)
    count = np.sum(np.isfinite(a), axis=0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # points that one run alone reaches
        return np.nanmean(a, axis=0), np.nanstd(a, axis=0, ddof=1) / np.sqrt(count), count


def largest_difference(reference, other, where):
    """The mean curves' (or gradings') largest |difference| with its unpaired se and Welch's df there,
    the point (where[i]), and the largest |difference| / se over the points with a spread."""
    (m0, s0, n0), (m1, s1, n1) = reference, other
    d, se = m1 - m0, np.hypot(s0, s1)
    i = int(np.nanargmax(np.abs(d)))
    spread = np.isfinite(d) & (se > 0)  # the coarsest sieve passes 100% in every run
    worst = float(np.max(np.abs(d[spread]) / se[spread])) if spread.any() else float("nan")
    df = welch_df(float(s0[i]), int(n0[i]), float(s1[i]), int(n1[i]))
    return float(d[i]), float(se[i]), df, float(where[i]), worst


def band(se, count):
    """Half the 95% Student-t interval of each point's mean (df = runs - 1); NaN under two runs."""
    q = np.array([t_quantile(n - 1) if n > 1 else np.nan for n in np.atleast_1d(count)])
    return se * q


def tested(change, se, df):
    """A comparison's cells: change, se, df, its 95% interval and p, resolved."""
    low, high, p = interval(change, se, df)
    return dict(change=change, change_se=se, df=df, low=low, high=high, p=p, resolved=resolved(change, se, df))


def compare(groups, reference):
    """Rows (test, N, folder, measure, seeds, mean, se, change, change_se, resolved); then, for each
    setting but its reference, the curve's and the sieves' largest differences."""
    rows = []
    order = sorted(groups, key=lambda k: (k[0] == "I", k[2], float(k[1])))
    for key in order:
        by_seed = groups[key]
        ref_key = reference_of(key, reference)
        ref = groups.get(ref_key) if ref_key != key else None
        base = {"test": key[0], "N": key[1], "folder": key[2]}
        for m in measure_names(list(by_seed.values())):
            values = dict((s, r[m]) for s, r in by_seed.items() if m in r and math.isfinite(r[m]))
            ref_values = dict((s, r[m]) for s, r in ref.items() if m in r and math.isfinite(r[m])) if ref else {}
            if not values:
                continue
            stats = statistics(list(values.values()))
            row = dict(base, measure=m, seeds=stats[0], mean=stats[1], se=stats[3])
            if ref_values:
                c = compare_seeds(ref_values, values)
                row.update(tested(c["change"], c["se"], c["df"]), design=c["design"])
            rows.append(row)
        if ref:
            d, se, df, where, worst = largest_difference(mean_se([r["curve"] for r in ref.values()]),
                                                         mean_se([r["curve"] for r in by_seed.values()]), GRID / 1e6)
            rows.append(dict(base, measure="n_curve_largest", seeds=len(by_seed), at_MPa=where, design="unpaired (Welch)",
                             largest_change_over_se=worst, **tested(d, se, df)))
            d, se, df, where, worst = largest_difference(mean_se([r["passing"] for r in ref.values()]),
                                                         mean_se([r["passing"] for r in by_seed.values()]),
                                                         next(iter(ref.values()))["sieves"])
            rows.append(dict(base, measure="passing_largest", seeds=len(by_seed), at_mm=where, design="unpaired (Welch)",
                             largest_change_over_se=worst, **tested(d, se, df)))
    return rows


def markdown(rows, by_folder):
    lines = ["| test | N |%s measure | seeds | mean +- se | change from the reference +- se | 95%% interval | p | "
             "resolved | design |" % (" setting |" if by_folder else ""),
             "|---|---|%s---|---|---|---|---|---|---|---|" % ("---|" if by_folder else "")]
    for r in rows:
        if "mean" in r:
            value = "%.4g +- %.2g" % (r["mean"], r["se"]) if math.isfinite(r["se"]) else "%.4g" % r["mean"]
        else:
            value = ("at %.3g MPa" % r["at_MPa"]) if "at_MPa" in r else ("at %g mm" % r["at_mm"])
        delta = "%+.3g +- %.2g" % (r["change"], r["change_se"]) if "change" in r else ""
        span = "%+.3g .. %+.3g" % (r["low"], r["high"]) if "low" in r and math.isfinite(r["low"]) else ""
        p = "%.2g" % r["p"] if "p" in r and math.isfinite(r["p"]) else ""
        worst = " (largest \\|change\\|/se on it %.1f)" % r["largest_change_over_se"] if "largest_change_over_se" in r else ""
        lines.append("| %s | %s |%s %s | %d | %s | %s | %s | %s | %s%s | %s |" % (
            r["test"], r["N"], " %s |" % r["folder"] if by_folder else "", r["measure"], r["seeds"], value, delta, span,
            p, r.get("resolved", ""), worst, r.get("design", "")))
    return "\n".join(lines)


def figure(groups, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, 2, figsize=(10, 8))
    for col, test in enumerate(("O", "I")):
        for key in sorted((k for k in groups if k[0] == test), key=lambda k: (k[2], float(k[1]))):
            runs = list(groups[key].values())
            label = "%s-%s%s (%d seeds)" % (test, key[1], " " + key[2] if key[2] else "", len(runs))
            m, se, n = mean_se([r["curve"] for r in runs])
            line, = axes[0, col].plot(GRID / 1e6, m, label=label)
            half = band(se, n)
            axes[0, col].fill_between(GRID / 1e6, m - half, m + half, color=line.get_color(), alpha=0.25)
            pm, pse, pn = mean_se([r["passing"] for r in runs])
            axes[1, col].plot(runs[0]["sieves"], pm, "o-", color=line.get_color(), label=label)
            half = band(pse, pn)
            axes[1, col].fill_between(runs[0]["sieves"], pm - half, pm + half, color=line.get_color(), alpha=0.25)
        axes[0, col].set_xscale("log")
        axes[0, col].set_xlabel("vertical stress (MPa)" if test == "O" else "mean stress p' (MPa)")
        axes[0, col].set_ylabel("porosity n")
        axes[0, col].set_title("%s: mean of the seeds, band 95%% (t)" % ("oedometric" if test == "O" else "isotropic"))
        axes[1, col].set_xscale("log")
        axes[1, col].set_xlabel("size (mm)")
        axes[1, col].set_ylabel("percent passing at 100 MPa")
        for ax in axes[:, col]:
            if ax.get_legend_handles_labels()[0]:
                ax.legend(fontsize=8)
            ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def figure_settings(groups, path):
    """Each setting's mean over its seeds, a row a test: porosity, I_G and events per initial grain
    against the stress (95% t bands), and the gradings at 1, 10, 50 and 100 MPa (line style by level)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    tests = [t for t in ("O", "I") if any(k[0] == t for k in groups)]
    fig, axes = plt.subplots(len(tests), 4, figsize=(18, 4.3 * len(tests)), squeeze=False)
    styles = dict(zip(GSD_LEVELS, (":", "-.", "--", "-")))
    for row, test in zip(axes, tests):
        axis = "vertical stress (MPa)" if test == "O" else "mean stress p' (MPa)"
        for key in sorted((k for k in groups if k[0] == test), key=lambda k: (k[2], float(k[1]))):
            runs = list(groups[key].values())
            label = "%s-%s%s (%d seeds)" % (test, key[1], " " + key[2] if key[2] else "", len(runs))
            colour = None
            for ax, curves in zip(row[:3], ([r["curve"] for r in runs], [r["curves"]["I_G"] for r in runs],
                                            [r["curves"]["events"] for r in runs])):
                m, se, n = mean_se(curves)
                line, = ax.plot(GRID / 1e6, m, color=colour, label=label)
                colour = line.get_color()
                half = band(se, n)
                ax.fill_between(GRID / 1e6, m - half, m + half, color=colour, alpha=0.25)
            for level in GSD_LEVELS:
                passing = [r["gsd_levels"][level] for r in runs if level in r["gsd_levels"]]
                if len(passing) == len(runs):
                    row[3].semilogx(runs[0]["sieves"], np.mean(passing, axis=0), styles[level], color=colour,
                                    label="%s, %s MPa" % (label.split(" (")[0], level))
        for ax, ylabel in zip(row, ("porosity n", "grading index I_G", "events per initial grain",
                                    "percent passing (mean of the seeds)")):
            ax.set_ylabel(ylabel)
            ax.grid(True, which="both", alpha=0.3)
            if ax is not row[3]:
                ax.set_xscale("log")
                ax.set_xlabel(axis)
        row[3].set_xlabel("size / N (mm)")
        row[0].set_title("%s compression: mean of the seeds, bands 95%% (t)" % ("oedometric" if test == "O" else "isotropic"),
                         loc="left")
        row[0].legend(fontsize=7)
        row[3].legend(fontsize=6, ncol=2)
    fig.tight_layout()
    fig.savefig(path, dpi=100)


def parse_reference(text):
    what, _, value = text.partition("=")
    if what not in ("N", "folder") or not value:
        sys.exit("compression_seeds.py: --reference %s: expected N=VALUE or folder=NAME" % text)
    return what, value


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--by-folder", action="store_true", help="a setting is also its runs' folder")
    parser.add_argument("--reference", default="N=1", help="N=VALUE (default N=1) or folder=NAME")
    parser.add_argument("--out", default=".")
    parser.add_argument("--name", default="compression", help="the outputs' prefix")
    a = parser.parse_args(argv)
    reference = parse_reference(a.reference)
    if reference[0] == "folder" and not a.by_folder:
        sys.exit("compression_seeds.py: --reference folder=%s needs --by-folder" % reference[1])
    runs = [load(f) for f in a.runs]
    groups = group(runs, a.by_folder)
    if not any(reference_of(k, reference) == k for k in groups):
        sys.exit("compression_seeds.py: no run is the reference %s=%s" % reference)
    os.makedirs(a.out, exist_ok=True)
    keep = ["test", "N"] + (["folder_name"] if a.by_folder else []) + ["seed"] + measure_names(runs)
    write_csv(os.path.join(a.out, a.name + "_runs.csv"),
              [dict((k, r[k]) for k in keep if k in r)
               for r in sorted(runs, key=lambda r: (r["test"], r["folder_name"], float(r["N"]), r["seed"]))])
    rows = compare(groups, reference)
    write_csv(os.path.join(a.out, a.name + "_seeds.csv"), rows)
    figure(groups, os.path.join(a.out, a.name + "_seeds.png"))
    figure_settings(groups, os.path.join(a.out, a.name + "_curves.png"))
    print(markdown(rows, a.by_folder))


if __name__ == "__main__":
    main()
