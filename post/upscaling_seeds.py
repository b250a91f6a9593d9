#!/usr/bin/python3
"""The paper's upscaling claim with seeds (doc/results.md, "Upscaling with seeds"): the oedometric and
isotropic tests at N = 1, 1.5 and 2, several seeds each, compared with N = 1 measure by measure.

    post/upscaling_seeds.py RUN_DIR [RUN_DIR ...] [--out DIR]

RUN_DIR: the folder of one run of the decks (history_<test><N>.csv, gsd_<test><N>_100MPa.csv and
screen.txt, as scripts/fontainebleau_runs.sh and bench/accuracy_vs_cost.sh leave them). Its seed is
read from setting.csv, else from a _s<seed> suffix of the folder's name, else it is the decks'.

Measures of a run, against the vertical stress (O) or the mean stress p' (I): the porosity at 1, 10
and 100 MPa; K0 averaged over log(sigma_v) from 1 to 100 MPa (O); I_G at 10 and 100 MPa; the events
per initial grain; the percent passing each sieve at 100 MPa. Each N's seeds give a mean and a
standard error; the change from N = 1 is unpaired (a seed draws another sample at each N, so the
seeds do not pair) and resolved where it passes 2 standard errors. Along the whole curve (0.5 - 99
MPa) the porosity's largest difference from N = 1 is reported with its standard error there, and
the largest |difference| / se anywhere on the curve; at 100 MPa the same over the sieves.

Writes DIR (default .)/upscaling_runs.csv (a row a run), upscaling_seeds.csv (a row a test, N and
measure) and upscaling_seeds.png (the mean curves and gradings with 2-se bands); prints the table
as Markdown.
"""
import argparse
import csv
import glob
import math
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from post.seeds import change, resolved, statistics  # noqa: E402

DECK_SEED = "15485863"
STRESS = {"O": "sigma_z", "I": "p"}  # the loading axis each test is read against
GRID = np.exp(np.linspace(math.log(5e5), math.log(9.9e7), 120))  # the curves' comparison, 0.5 - 99 MPa
# (a run to 100 MPa logs its last row at 99 - 99.7 MPa)
LEVELS = ((1e6, "1MPa"), (1e7, "10MPa"), (1e8, "100MPa"))


def read_columns(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


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
        sys.exit("upscaling_seeds.py: %s: no SAMPLE line in screen.txt" % folder)
    return int(m.group(1))


def load(folder):
    """One run: its test, N, seed, measures, porosity curve on GRID and passing at 100 MPa."""
    histories = glob.glob(os.path.join(folder, "history_[OI]*.csv"))
    if len(histories) != 1:
        sys.exit("upscaling_seeds.py: %s: expected one history_O*.csv or history_I*.csv" % folder)
    name = os.path.basename(histories[0])[len("history_"):-len(".csv")]
    test, n = name[0], name[1:]
    h = read_columns(histories[0])
    stress = h[STRESS[test]]
    run = {"test": test, "N": n, "seed": seed_of(folder), "folder": folder}
    for level, tag in LEVELS:
        run["n_" + tag] = at(stress, h["porosity"], level)
    if test == "O":
        run["K0_mean"] = float(np.nanmean(on_grid(stress, h["K0"], np.exp(np.linspace(math.log(1e6), math.log(1e8), 60)))))
    run["I_G_10MPa"] = at(stress, h["I_G"], 1e7)
    run["I_G_100MPa"] = at(stress, h["I_G"], 1e8)
    run["events_per_grain"] = h["events"][-1] / initial_grains(folder)
    gsd = read_columns(os.path.join(folder, "gsd_%s_100MPa.csv" % name))
    run["sieves"] = gsd["size_mm"]
    run["passing"] = gsd["percent_passing"]
    for d, p in zip(gsd["size_mm"], gsd["percent_passing"]):
        run["pass_%g" % d] = float(p)
    run["curve"] = on_grid(stress, h["porosity"])
    return run


def measure_names(runs):
    names = []
    for r in runs:
        names += [k for k in r if k not in names and k not in ("test", "N", "seed", "folder", "sieves", "passing", "curve")]
    return names


def by_setting(runs):
    """{(test, N): {seed: run}}; a second run of one test, N and seed is refused."""
    out = {}
    for r in runs:
        seeds = out.setdefault((r["test"], r["N"]), {})
        if r["seed"] in seeds:
            sys.exit("upscaling_seeds.py: %s and %s are both %s-%s with seed %s"
                     % (seeds[r["seed"]]["folder"], r["folder"], r["test"], r["N"], r["seed"]))
        seeds[r["seed"]] = r
    return out


def curve_difference(reference, other):
    """The mean curves' largest |difference| (0.5 - 99 MPa) with its unpaired se there, and the
    largest |difference| / se anywhere along them."""
    def mean_se(runs):
        c = np.array([r["curve"] for r in runs])
        return np.nanmean(c, axis=0), np.nanstd(c, axis=0, ddof=1) / np.sqrt(np.sum(np.isfinite(c), axis=0))
    (m0, s0), (m1, s1) = mean_se(reference), mean_se(other)
    d, se = m1 - m0, np.hypot(s0, s1)
    i = int(np.nanargmax(np.abs(d)))
    return float(d[i]), float(se[i]), float(GRID[i]), float(np.nanmax(np.abs(d) / se))


def sieve_difference(reference, other):
    """The same over the sieves at 100 MPa: (largest |change|, its se, its sieve, largest |change|/se)."""
    def mean_se(runs):
        p = np.array([r["passing"] for r in runs])
        return p.mean(axis=0), p.std(axis=0, ddof=1) / math.sqrt(len(runs))
    (m0, s0), (m1, s1) = mean_se(reference), mean_se(other)
    d, se = m1 - m0, np.hypot(s0, s1)
    i = int(np.argmax(np.abs(d)))
    spread = se > 0  # the coarsest sieve passes 100% in every run
    return float(d[i]), float(se[i]), float(reference[0]["sieves"][i]), float(np.max(np.abs(d[spread]) / se[spread]))


def compare(groups, reference_n="1"):
    """Rows (test, N, measure, seeds, mean, se, change, change_se, resolved), N = 1 first, then the
    curve's and the sieves' largest differences."""
    rows = []
    for (test, n), by_seed in sorted(groups.items(), key=lambda kv: (kv[0][0] == "I", float(kv[0][1]))):
        ref = groups.get((test, reference_n))
        for m in measure_names(list(by_seed.values())):
            values = dict((s, r[m]) for s, r in by_seed.items() if m in r and math.isfinite(r[m]))
            ref_values = dict((s, r[m]) for s, r in ref.items() if m in r and math.isfinite(r[m])) if ref else {}
            stats = statistics(list(values.values()))
            row = {"test": test, "N": n, "measure": m, "seeds": stats[0], "mean": stats[1], "se": stats[3]}
            if n != reference_n and ref_values:
                _, _, (dx, se), _ = change(ref_values, values)  # unpaired: the seeds do not pair across N
                row.update(change=dx, change_se=se, resolved=resolved(dx, se))
            rows.append(row)
        if n != reference_n and ref:
            d, se, where, worst = curve_difference(list(ref.values()), list(by_seed.values()))
            rows.append({"test": test, "N": n, "measure": "n_curve_largest", "seeds": len(by_seed), "at_MPa": where / 1e6,
                         "change": d, "change_se": se, "resolved": resolved(d, se), "largest_change_over_se": worst})
            d, se, where, worst = sieve_difference(list(ref.values()), list(by_seed.values()))
            rows.append({"test": test, "N": n, "measure": "passing_largest", "seeds": len(by_seed), "at_mm": where,
                         "change": d, "change_se": se, "resolved": resolved(d, se), "largest_change_over_se": worst})
    return rows


def write_csv(path, rows):
    columns = []
    for row in rows:
        columns += [k for k in row if k not in columns]
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns, lineterminator="\n")
        w.writeheader()
        for row in rows:
            w.writerow(dict((k, "%.6g" % v if isinstance(v, float) else v) for k, v in row.items()))


def markdown(rows):
    lines = ["| test | N | measure | seeds | mean +- se | change from N = 1 +- se | resolved |", "|---|---|---|---|---|---|---|"]
    for r in rows:
        if "mean" in r:
            value = "%.4g +- %.2g" % (r["mean"], r["se"]) if math.isfinite(r["se"]) else "%.4g" % r["mean"]
        else:
            value = ("at %.3g MPa" % r["at_MPa"]) if "at_MPa" in r else ("at %g mm" % r["at_mm"])
        delta = "%+.3g +- %.2g" % (r["change"], r["change_se"]) if "change" in r else ""
        worst = " (largest |change|/se on it %.1f)" % r["largest_change_over_se"] if "largest_change_over_se" in r else ""
        lines.append("| %s | %s | %s | %d | %s | %s | %s%s |" % (r["test"], r["N"], r["measure"], r["seeds"], value,
                                                                delta, r.get("resolved", ""), worst))
    return "\n".join(lines)


def figure(groups, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, 2, figsize=(10, 8))
    for col, test in enumerate(("O", "I")):
        for (t, n), by_seed in sorted(groups.items(), key=lambda kv: float(kv[0][1])):
            if t != test:
                continue
            runs = list(by_seed.values())
            label = "%s-%s (%d seeds)" % (test, n, len(runs))
            c = np.array([r["curve"] for r in runs])
            m, se = np.nanmean(c, axis=0), np.nanstd(c, axis=0, ddof=1) / math.sqrt(len(runs))
            line, = axes[0, col].plot(GRID / 1e6, m, label=label)
            axes[0, col].fill_between(GRID / 1e6, m - 2 * se, m + 2 * se, color=line.get_color(), alpha=0.25)
            p = np.array([r["passing"] for r in runs])
            pm, pse = p.mean(axis=0), p.std(axis=0, ddof=1) / math.sqrt(len(runs))
            axes[1, col].plot(runs[0]["sieves"], pm, "o-", color=line.get_color(), label=label)
            axes[1, col].fill_between(runs[0]["sieves"], pm - 2 * pse, pm + 2 * pse, color=line.get_color(), alpha=0.25)
        axes[0, col].set_xscale("log")
        axes[0, col].set_xlabel("vertical stress (MPa)" if test == "O" else "mean stress p' (MPa)")
        axes[0, col].set_ylabel("porosity n")
        axes[0, col].set_title("%s: mean of the seeds, band 2 se" % ("oedometric" if test == "O" else "isotropic"))
        axes[1, col].set_xscale("log")
        axes[1, col].set_xlabel("size (mm)")
        axes[1, col].set_ylabel("percent passing at 100 MPa")
        for ax in axes[:, col]:
            if ax.get_legend_handles_labels()[0]:
                ax.legend(fontsize=8)
            ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--out", default=".")
    a = parser.parse_args(argv)
    runs = [load(f) for f in a.runs]
    groups = by_setting(runs)
    os.makedirs(a.out, exist_ok=True)
    keep = ["test", "N", "seed"] + measure_names(runs)
    write_csv(os.path.join(a.out, "upscaling_runs.csv"),
              [dict((k, r[k]) for k in keep if k in r) for r in sorted(runs, key=lambda r: (r["test"], float(r["N"]), r["seed"]))])
    rows = compare(groups)
    write_csv(os.path.join(a.out, "upscaling_seeds.csv"), rows)
    figure(groups, os.path.join(a.out, "upscaling_seeds.png"))
    print(markdown(rows))


if __name__ == "__main__":
    main()
