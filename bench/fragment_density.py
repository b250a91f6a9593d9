#!/usr/bin/env python3
"""The fragments' time-step knob (fix crush 'fragment_density scaled') against the true density, on
the oedometric test O-2 and the penetration test dense_region, each over three seeds
(bench/fragment_density.sh runs them; studies/accuracy/README.md reads the table).

  python3 bench/fragment_density.py O2_TRUE_DIR O2_SCALED_DIR PENETRATION_STUDY_CSV

O2_*_DIR: outputs of scripts/fontainebleau_runs.sh (one folder per seed: O2, O2_s<seed>);
PENETRATION_STUDY_CSV: scripts/penetration_study.sh's study.csv with the cases dense_region,
dense_region_N60_s2, dense_region_N60_s3 and dense_region_scaled[_s2|_s3]. Prints, per test: each seed's results with both densities, the
effect of the knob (scaled - true, same seed) against the seeds' scatter (the sample standard
deviation over the seeds, true density), the cost (steps, seconds), and the inertial numbers
I = rate d sqrt(rho / p) of the grains and of the fragments.
"""
import csv
import glob
import math
import os
import statistics
import sys

RHO = 2650.0          # kg/m^3, the decks' grains (in.grading)
D_CONE = 0.0357       # m (penetrometer.py)
V_CONE = 2.0          # m/s (the velocity of the study cases it reads: scripts/penetration_study.sh)


def rows(path):
    with open(path) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def seed_of(folder):
    name = os.path.basename(folder)
    return name.split("_s")[1] if "_s" in name else "decks"


def o2_run(folder):
    """n, K0 (mean of the last 5 rows), events, I_G at 100 MPa; the n - sigma_v curve; the percent
    passing at 100 MPa; steps, physical time, the inertial numbers at 10 and 100 MPa."""
    history = rows(glob.glob(os.path.join(folder, "history_*.csv"))[0])
    gsd = rows(glob.glob(os.path.join(folder, "gsd_*_100MPa.csv"))[0])
    with open(glob.glob(os.path.join(folder, "events_*.csv"))[0]) as f:
        events = list(csv.DictReader(f))
    last = history[-1]
    broken_grains = [float(e["diameter"]) for e in events if e["generation"] == "0"]
    run = {"n": last["porosity"], "K0": statistics.mean(r["K0"] for r in history[-5:]),
           "events": last["events"], "I_G": last["I_G"], "history": history,
           "passing": [r["percent_passing"] for r in gsd], "steps": last["step"] - history[0]["step"],
           "time": last["time"] - history[0]["time"], "dt_end": last["dt"]}
    # I = (d eps_a / dt) d sqrt(rho / p): eps_a from the void ratio (oedometric: eps_v = eps_a),
    # over the rows around each level; d: the grains' mean broken diameter (a scaled fragment keeps its
    # grain's d sqrt(rho)), or the fragments' own (1/4.65 of it on average, fourteen layout, by number).
    e0 = history[0]["void_ratio"]
    for level in (1e7, 1e8):
        k = min(range(1, len(history)), key=lambda m: abs(history[m]["sigma_z"] - level))
        a, b = history[k - 1], history[k]
        rate = ((a["void_ratio"] - b["void_ratio"]) / (1 + e0)) / (b["time"] - a["time"])
        run["I_%g" % level] = rate * statistics.mean(broken_grains) * math.sqrt(RHO / b["p"])
    return run


def curve_difference(a, b):
    """Largest |n_a - n_b| along sigma_v (0.2 - 100 MPa), b interpolated at a's stresses."""
    sb = [r["sigma_z"] for r in b]
    nb = [r["porosity"] for r in b]
    worst = 0.0
    for r in a:
        s = r["sigma_z"]
        if s < 2e5 or s > min(sb[-1], 1e8):
            continue
        k = next(m for m in range(1, len(sb)) if sb[m] >= s)
        n = nb[k - 1] + (nb[k] - nb[k - 1]) * (s - sb[k - 1]) / (sb[k] - sb[k - 1])
        worst = max(worst, abs(r["porosity"] - n))
    return worst


def report_o2(true_dir, scaled_dir):
    true = {seed_of(d): o2_run(d) for d in sorted(glob.glob(os.path.join(true_dir, "O2*"))) if os.path.isdir(d)}
    scaled = {seed_of(d): o2_run(d) for d in sorted(glob.glob(os.path.join(scaled_dir, "O2*"))) if os.path.isdir(d)}
    seeds = [s for s in true if s in scaled]
    print("O-2 to 100 MPa, true density against fragment_density scaled, %d seeds" % len(seeds))
    print("| seed | density | n | K0 | events | I_G | steps | physical time (s) | dt at 100 MPa (s) | I grains 10, 100 MPa |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for s in seeds:
        for label, run in (("true", true[s]), ("scaled", scaled[s])):
            print("| %s | %s | %.4f | %.3f | %d | %.4f | %d | %.4g | %.3g | %.2g, %.2g |" % (
                s, label, run["n"], run["K0"], run["events"], run["I_G"], run["steps"], run["time"],
                run["dt_end"], run["I_1e+07"], run["I_1e+08"]))
    print()
    print("| measure | knob effect, same seed (mean, largest) | seeds' scatter (sd, true) | scatter (sd, scaled) |")
    print("|---|---|---|---|")
    for key, fmt in (("n", "%.4f"), ("K0", "%.3f"), ("events", "%.1f"), ("I_G", "%.4f")):
        effects = [scaled[s][key] - true[s][key] for s in seeds]
        print("| %s | %s, %s | %s | %s |" % (key, fmt % statistics.mean(effects), fmt % max(effects, key=abs),
                                             fmt % statistics.stdev(true[s][key] for s in seeds),
                                             fmt % statistics.stdev(scaled[s][key] for s in seeds)))
    curve_knob = max(curve_difference(true[s]["history"], scaled[s]["history"]) for s in seeds)
    curve_seeds = max(curve_difference(true[a]["history"], true[b]["history"]) for a in seeds for b in seeds if a < b)
    gsd_knob = max(max(abs(x - y) for x, y in zip(true[s]["passing"], scaled[s]["passing"])) for s in seeds)
    gsd_seeds = max(max(abs(x - y) for x, y in zip(true[a]["passing"], true[b]["passing"]))
                    for a in seeds for b in seeds if a < b)
    print("| n along sigma_v, largest difference | %.4f (knob, same seed) | %.4f (between seeds, true) | |"
          % (curve_knob, curve_seeds))
    print("| percent passing at 100 MPa, largest difference | %.2f (knob, same seed) | %.2f (between seeds, true) | |"
          % (gsd_knob, gsd_seeds))
    print()


def report_penetration(study):
    with open(study) as f:
        cases = {r["case"]: r for r in csv.DictReader(f)}
    pairs = [("dense_region", "dense_region_scaled"), ("dense_region_N60_s2", "dense_region_scaled_s2"),
             ("dense_region_N60_s3", "dense_region_scaled_s3")]
    pairs = [(t, s) for t, s in pairs if t in cases and s in cases]
    print("Penetration dense_region (N = 60, crushing in the zone), true density against scaled, %d seeds"
          % len(pairs))
    print("| seed | density | q_c (MPa) | sd | f_s (kPa) | events (loaded) | I_G near the tip | particles | steps | time (s) |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for t, s in pairs:
        for label, c in (("true", cases[t]), ("scaled", cases[s])):
            print("| %s | %s | %.2f | %.2f | %.1f | %s (%s) | %.3f | %s | %s | %s |" % (
                c["seed"], label, float(c["q_c_MPa"]), float(c["q_c_sd_MPa"]), float(c["f_s_kPa"]), c["events"],
                c["events_loaded"], float(c["I_G_near"]), c["particles"], c["steps"], c["seconds"]))
    qt = [float(cases[t]["q_c_MPa"]) for t, _ in pairs]
    qs = [float(cases[s]["q_c_MPa"]) for _, s in pairs]
    steps = [float(cases[s]["steps"]) / float(cases[t]["steps"]) for t, s in pairs]
    seconds = [float(cases[s]["seconds"]) / float(cases[t]["seconds"]) for t, s in pairs]
    print()
    print("q_c: true %.2f MPa (sd over seeds %.2f), scaled %.2f (sd %.2f): knob effect %+.2f MPa, %.1f sd of "
          "the true seeds' scatter" % (statistics.mean(qt), statistics.stdev(qt), statistics.mean(qs),
                                       statistics.stdev(qs), statistics.mean(qs) - statistics.mean(qt),
                                       abs(statistics.mean(qs) - statistics.mean(qt)) / statistics.stdev(qt)))
    print("cost, scaled / true, same seed: steps %.3f (%.3f - %.3f), wall time %.3f (%.3f - %.3f)" % (
        statistics.median(steps), min(steps), max(steps), statistics.median(seconds), min(seconds), max(seconds)))
    # I at the tip: rate v / D_c, p = q_c; grains d50 = 0.21 mm x N; a scaled fragment keeps its grain's
    # d sqrt(rho), a true one (r/R) times it (0.23 - 0.41 for the first generation).
    n = float(cases[pairs[0][0]]["N"])
    grain = V_CONE / D_CONE * 0.21e-3 * n * math.sqrt(RHO / (statistics.mean(qt) * 1e6))
    print("inertial number at the tip (v / D_c, p = q_c): grains %.3f; fragments %.3f with scaled density "
          "(their grains'), %.4f - %.4f with the true one" % (grain, grain, 0.2300932 * grain, 0.4142136 * grain))


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    report_o2(sys.argv[1], sys.argv[2])
    report_penetration(sys.argv[3])
