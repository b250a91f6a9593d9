#!/usr/bin/python3
"""Table 3 of Ciantia et al. (2014) against the runs of scripts/fontainebleau_runs.sh.

    scripts/table3.py RUNS_DIR

Reads RUNS_DIR/runtimes.csv and each run's history; prints a Markdown table: initial and final
particles, events, their deviation from the paper, events per initial grain, I_G at the start and
at 100 MPa, and the runtime; with several seeds of one test (TEST_sSEED folders), the mean and the
spread (min - max) as well. Then the upscaling check of the default-seed runs: the largest porosity
difference from N = 1 along the compression curve (0.5 - 100 MPa), the largest GSD difference at
100 MPa, and K0 above 1 MPa."""
import csv
import glob
import os
import statistics
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "post"))
from paper import TABLE3 as PAPER  # noqa: E402  (N_i, N_e, events, runtime in minutes)


def history(folder):
    path = glob.glob(os.path.join(folder, "history_*.csv"))[0]
    with open(path) as f:
        return [dict((k, float(v)) for k, v in r.items()) for r in csv.DictReader(f)]


def main(runs):
    rows = list(csv.DictReader(open(os.path.join(runs, "runtimes.csv"))))
    by_test = {}
    for r in rows:
        test = r["test"].split(":")[0]
        folder = os.path.join(runs, r["test"] if ":" not in r["test"] else "%s_s%s" % (test, r["test"].split(":")[1]))
        h = history(folder)
        by_test.setdefault(test, []).append({
            "initial": int(r["initial_particles"]), "final": int(r["final_particles"]), "events": int(r["events"]),
            "seconds": float(r["seconds"]), "ranks": r["ranks"], "IG0": h[0]["I_G"], "IG": h[-1]["I_G"],
            "n": h[-1]["porosity"], "seed": r["test"].split(":")[1] if ":" in r["test"] else "default"})
    print("| test | seeds | N_i | N_e | events | events / N_i | paper N_i, N_e, events | N_e, events vs paper "
          "| I_G after the first load -> 100 MPa | n at 100 MPa | runtime |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for test in ("O2", "O1.5", "O1", "I2", "I1.5", "I1"):
        if test not in by_test:
            continue
        runs_ = by_test[test]
        paper = PAPER[test]

        def span(key, fmt):
            values = [r[key] for r in runs_]
            if len(values) == 1:
                return fmt % values[0]
            return (fmt + " (" + fmt + " - " + fmt + ")") % (statistics.mean(values), min(values), max(values))
        share = [r["events"] / r["initial"] for r in runs_]
        final = statistics.mean(r["final"] for r in runs_)
        events = statistics.mean(r["events"] for r in runs_)
        print("| %s-%s | %d | %s | %s | %s | %s | %d, %d, %d | %+.0f%%, %+.0f%% | %s -> %s | %s | %s s (%s rank%s) |" % (
            test[0], test[1:], len(runs_), span("initial", "%.0f"), span("final", "%.0f"), span("events", "%.0f"),
            ("%.1f%%" % (100 * statistics.mean(share))) + ("" if len(share) == 1 else " (%.1f - %.1f%%)" % (
                100 * min(share), 100 * max(share))),
            paper[0], paper[1], paper[2], 100 * (final / paper[1] - 1), 100 * (events / paper[2] - 1),
            span("IG0", "%.3f"), span("IG", "%.3f"), span("n", "%.3f"), span("seconds", "%.0f"), runs_[0]["ranks"],
            "" if runs_[0]["ranks"] == "1" else "s"))


def upscaling(runs):
    grid = np.exp(np.linspace(np.log(5e5), np.log(1e8), 200))
    for test, column in (("O", "sigma_z"), ("I", "p")):
        curves, gsd = {}, {}
        for n in ("2", "1.5", "1"):
            path = os.path.join(runs, test + n, "history_%s%s.csv" % (test, n))
            if not os.path.exists(path):
                continue
            h = list(csv.DictReader(open(path)))
            stress = np.array([float(r[column]) for r in h])
            order = np.argsort(stress)
            curves[n] = np.interp(grid, stress[order], np.array([float(r["porosity"]) for r in h])[order],
                                  left=np.nan, right=np.nan)
            if test == "O":
                k0 = [float(r["K0"]) for r in h if float(r["sigma_target"]) > 1e6]
                print("K0 above 1 MPa, O-%s: %.2f - %.2f" % (n, min(k0), max(k0)))
            g = os.path.join(runs, test + n, "gsd_%s%s_100MPa.csv" % (test, n))
            if os.path.exists(g):
                rows = list(csv.DictReader(open(g)))
                gsd[n] = np.array([float(r["percent_passing"]) for r in rows])
        for n in ("2", "1.5"):
            if n in curves and "1" in curves:
                dn = np.nanmax(np.abs(curves[n] - curves["1"]))
                dg = np.max(np.abs(gsd[n] - gsd["1"])) if n in gsd and "1" in gsd else float("nan")
                print("%s-%s against %s-1: porosity within %.4f (0.5 - 100 MPa), GSD at 100 MPa within %.2f points"
                      % (test, n, test, dn, dg))


if __name__ == "__main__":
    main(sys.argv[1])
    upscaling(sys.argv[1])
