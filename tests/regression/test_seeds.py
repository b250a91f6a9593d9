#!/usr/bin/env python3
"""post/seeds.py, the studies' seeds harness, and post/compression_seeds.py on stand-in studies and
runs whose effects are known (no liggghts needed).

  python3 test_seeds.py LIGGGHTS WORKDIR CASE"""
import csv
import math
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liggghts_run import check  # noqa: E402
from liggghts_run import main as test_main  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TOOL = os.path.join(ROOT, "post", "seeds.py")
COMPRESSION = os.path.join(ROOT, "post", "compression_seeds.py")
SEEDS = ("11", "22", "33", "44", "55")
BASE = (0.40, 0.42, 0.38, 0.44, 0.36)  # the reference's porosity by seed: mean 0.40, se 0.01414


def study(path, rows):
    with open(path, "w", newline="") as f:
        writer = csv.writer(f, lineterminator="\n")
        writer.writerow(["name", "N", "L_R", "seed", "porosity", "events"])
        writer.writerows(rows)
    return path


def run(work, path, *args):
    out = os.path.join(work, "changes.csv")
    proc = subprocess.run(["/usr/bin/python3", TOOL, path, "--setting", "N,L_R", "--measure", "porosity,events",
                           "--csv", out] + list(args), stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True)
    check(proc.returncode == 0, "post/seeds.py ran: %s" % proc.stderr[-400:])
    with open(out) as f:
        return dict(((r["setting"], r["measure"]), r) for r in csv.DictReader(f)), proc.stderr


def case_known_effects(liggghts, work):
    """Five seeds of a reference (N = 1) whose porosity spreads over 0.36 - 0.44 between seeds, and
    three settings against it. N = 2 adds 0.010 to every seed's porosity (+- 0.001): paired by seed
    the change is +0.010 +- 0.00045, resolved; unpaired (the seeds' spread, se 0.02) it is not. N =
    1.5 adds nothing (+- 0.002): resolved neither way. N = 3 ran one seed: no standard error, never
    resolved. The events rise by 10 (of 100 - 140) in N = 2 alone, with the seeds: resolved paired. A
    second row of one seed is counted once, with a warning."""
    del liggghts
    rows = []
    for k, seed in enumerate(SEEDS):
        rows.append(("ref_s%s" % seed, "1", "0.1", seed, BASE[k], 100 + 10 * k))
        rows.append(("n2_s%s" % seed, "2", "0.1", seed, BASE[k] + 0.010 + (0.001, -0.001, 0.0, 0.001, -0.001)[k], 110 + 10 * k))
        rows.append(("n15_s%s" % seed, "1.5", "0.1", seed, BASE[k] + (0.002, -0.002, 0.001, -0.001, 0.0)[k], 100 + 10 * k + (1, -1, 0, 1, -1)[k]))
    rows.append(("n3_s11", "3", "0.1", "11", 0.50, 200))
    rows.append(("ref_again", "1", "0.1", "11", 0.99, 999))
    changes, stderr = run(work, study(os.path.join(work, "study.csv"), rows), "--reference", "N=1")
    n2 = changes[("N=2 L_R=0.1", "porosity")]
    check((n2["change"], n2["resolved"], n2["paired_change"], n2["paired_se"], n2["paired_resolved"]) ==
          ("+0.01", "no", "+0.01", "0.000447", "yes (5)"),
          "N = 2: change %s (se %s) %s unpaired; paired %s +- %s, %s" % (n2["change"], n2["change_se"], n2["resolved"],
                                                                     n2["paired_change"], n2["paired_se"], n2["paired_resolved"]))
    n15 = changes[("N=1.5 L_R=0.1", "porosity")]
    check(n15["resolved"] == "no" and n15["paired_resolved"] == "no (5)" and abs(float(n15["paired_change"])) < 1e-9,
          "N = 1.5: change %s unpaired %s, paired %s %s" % (n15["change"], n15["resolved"], n15["paired_change"], n15["paired_resolved"]))
    n3 = changes[("N=3 L_R=0.1", "porosity")]
    check(n3["seeds"] == "1" and n3["resolved"] == "one seed" and n3["paired_resolved"] == "",
          "N = 3, one seed: %s, paired %r" % (n3["resolved"], n3["paired_resolved"]))
    events = changes[("N=2 L_R=0.1", "events")]
    ref = changes[("N=1 L_R=0.1", "porosity")]
    check(events["paired_change"] == "+10" and events["paired_resolved"] == "yes (5)" and ref["seeds"] == "5"
          and abs(float(ref["mean"]) - 0.40) < 1e-12 and "two rows of setting" in stderr,
          "N = 2 events +10 paired, resolved; the reference's mean %s over %s seeds (the second row of seed 11 dropped)"
          % (ref["mean"], ref["seeds"]))


def stand_in_run(folder, test, n, porosity, events, grains=1000, setting_seed=None, void_ratio=None):
    """A run folder as the decks leave it: a history from 0.2 to 99.5 MPa whose porosity is
    porosity(log10 of the stress in MPa), K0 0.4 (O), I_G 0.8 and, where given, the void ratio
    void_ratio(log10 of the stress in MPa); a grading at 100 MPa; the SAMPLE line. A folder left by
    an earlier run of the test is replaced."""
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    column = "sigma_z" if test == "O" else "p"
    with open(os.path.join(folder, "history_%s%s.csv" % (test, n)), "w") as f:
        f.write("step,%s,porosity,K0,I_G,events%s\n" % (column, ",void_ratio" if void_ratio else ""))
        for k in range(60):
            mpa = 0.2 * (99.5 / 0.2) ** (k / 59.0)
            f.write("%d,%.9g,%.9g,0.4,0.8,%d%s\n" % (k, mpa * 1e6, porosity(math.log10(mpa)), events * k // 59,
                                                ",%.12g" % void_ratio(math.log10(mpa)) if void_ratio else ""))
    with open(os.path.join(folder, "gsd_%s%s_100MPa.csv" % (test, n)), "w") as f:
        f.write("size_mm,percent_passing\n0.1,%.9g\n0.2,50\n0.45,100\n" % (10.0 + events / 100.0))
    with open(os.path.join(folder, "screen.txt"), "w") as f:
        f.write("SAMPLE N = %s: %d particles, porosity 0.4\n" % (n, grains))
    if setting_seed:
        with open(os.path.join(folder, "setting.csv"), "w") as f:
            f.write("name,N,seed\nN%s,%s,%s\n" % (n, n, setting_seed))


def compression_seeds(out, *args, fails=False):
    proc = subprocess.run(["/usr/bin/python3", COMPRESSION, "--out", out] + list(args), stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, universal_newlines=True)
    if not fails:
        check(proc.returncode == 0, "post/compression_seeds.py ran: %s" % proc.stderr[-400:])
    return proc


def case_upscaling(liggghts, work):
    """post/compression_seeds.py on stand-in O runs at N = 1, 1.5 and 2, three seeds each. N = 1's
    porosity is 0.4 - 0.05 log10(sigma / MPa) plus the seed's offset (-0.01, 0, +0.01: se 0.00577).
    N = 2 adds 0.003 + 0.002 log10(sigma / MPa) to it, a change that grows to 0.007 at 100 MPa: its
    seeds keep their offsets (they correlate with N = 1's, r 1), so the change is paired and every
    seed's own difference is +0.007: resolved, where unpaired (se 0.00816, Welch's df 4) it would not
    be. N = 1.5 adds the same but its seeds' offsets run the other way (+0.01, 0, -0.01: r -1):
    unpaired, +0.007 +- 0.00816, 95% interval -0.0157 .. +0.0297, not resolved. The events per grain
    are 0.30 at N = 2 where N = 1's are 0.20, with a spread of 0.01: resolved. The seed comes from
    setting.csv or the folder's _s<seed>. A second run of one test, N and seed is refused by name."""
    del liggghts
    offsets = {"11": -0.01, "22": 0.0, "33": 0.01}
    folders = []
    for seed, off in offsets.items():
        k = int(seed) // 11 - 1
        one = os.path.join(work, "O1_s%s" % seed)
        stand_in_run(one, "O", "1", lambda x, o=off: 0.4 - 0.05 * x + o, 200 + 10 * (k - 1))
        two = os.path.join(work, "N2_run%d" % k)  # its seed only in setting.csv
        stand_in_run(two, "O", "2", lambda x, o=off: 0.4 - 0.05 * x + o + 0.003 + 0.002 * x, 300 + 10 * (k - 1),
                     setting_seed=seed)
        reversed_seed = os.path.join(work, "O1.5_s%s" % seed)
        stand_in_run(reversed_seed, "O", "1.5", lambda x, o=off: 0.4 - 0.05 * x - o + 0.003 + 0.002 * x, 250)
        folders += [one, two, reversed_seed]
    out = os.path.join(work, "out")
    compression_seeds(out, "--name", "upscaling", *folders)
    with open(os.path.join(out, "upscaling_seeds.csv")) as f:
        rows = dict(((r["N"], r["measure"]), r) for r in csv.DictReader(f))
    n100 = rows[("2", "n_100MPa")]
    check(abs(float(n100["change"]) - 0.007) < 1e-5 and float(n100["change_se"]) < 1e-9 and n100["resolved"] == "yes"
          and n100["seeds"] == "3" and n100["design"] == "paired (3 seeds, r 1.00)",
          "N = 2, n at 100 MPa: change %s +- %s, %s: %s" % (n100["change"], n100["change_se"], n100["design"],
                                                          n100["resolved"]))
    n15 = rows[("1.5", "n_100MPa")]
    check(abs(float(n15["change"]) - 0.007) < 1e-5 and abs(float(n15["change_se"]) - 0.0081650) < 1e-5
          and abs(float(n15["df"]) - 4) < 1e-9 and abs(float(n15["low"]) + 0.01567) < 1e-4
          and n15["resolved"] == "no" and n15["design"].startswith("unpaired (Welch, r -1.00"),
          "N = 1.5, n at 100 MPa: change %s +- %s, df %s, interval %s .. %s, %s: %s"
          % (n15["change"], n15["change_se"], n15["df"], n15["low"], n15["high"], n15["design"], n15["resolved"]))
    n1 = rows[("2", "n_1MPa")]
    check(abs(float(n1["change"]) - 0.003) < 1e-5, "n at 1 MPa: change %s, expected +0.003" % n1["change"])
    curve = rows[("2", "n_curve_largest")]
    check(abs(float(curve["change"]) - 0.003 - 0.002 * math.log10(99)) < 2e-4 and float(curve["at_MPa"]) > 90,
          "the curve's largest difference %s at %s MPa, expected +0.007 near 99 MPa" % (curve["change"], curve["at_MPa"]))
    events = rows[("2", "events_per_grain")]
    check(abs(float(events["change"]) - 0.1) < 1e-9 and events["resolved"] == "yes",
          "events per grain: change %s (%s), expected +0.1, resolved" % (events["change"], events["resolved"]))
    k0 = rows[("1", "K0_mean")]
    check(abs(float(k0["mean"]) - 0.4) < 1e-12, "K0 averaged over 1 - 100 MPa: %s, expected 0.4" % k0["mean"])
    twin = os.path.join(work, "O1_twin_s22")
    stand_in_run(twin, "O", "1", lambda x: 0.4, 200)
    proc = compression_seeds(out, *(folders + [twin]), fails=True)
    check(proc.returncode != 0 and "O1_twin_s22" in proc.stderr and "seed 22" in proc.stderr,
          "a second O-1 of seed 22 refused by name: %s" % proc.stderr[-300:])


def case_readings(liggghts, work):
    """post/compression_seeds.py --by-folder: two readings of the strengths, each a folder of O-2 and
    I-2 runs with three seeds; the readings' runs are told apart by their folder and compared with
    the reference reading's runs of the same test. The other reading's porosity is 0.02 higher at
    every stress (resolved: se 0.00816) and its yield stress 2 MPa higher: the histories' void ratio
    falls 0.02 a decade of stress up to y MPa and 0.30 a decade beyond, so the lines fitted to
    0.3 - 3 MPa and above 50 MPa meet at y, 9 - 11 MPa in the reference. Without --by-folder the
    two readings would be one setting: refused, since they share seeds."""
    del liggghts
    folders = []
    for reading, dn, dy in (("clipped", 0.0, 0.0), ("normal", 0.02, 2.0)):
        for k, seed in enumerate(("11", "22", "33")):
            y = 9.0 + k + dy
            for test in ("O", "I"):
                folder = os.path.join(work, reading, "%s2_s%s" % (test, seed))
                stand_in_run(folder, test, "2", lambda x, o=(k - 1) * 0.01 + dn: 0.4 - 0.05 * x + o, 300,
                             void_ratio=lambda x, y=y: 0.6 - 0.02 * x - (0.28 * (x - math.log10(y)) if x > math.log10(y) else 0.0))
                folders.append(folder)
    out = os.path.join(work, "out")
    compression_seeds(out, "--by-folder", "--reference", "folder=clipped", "--name", "readings", *folders)
    with open(os.path.join(out, "readings_seeds.csv")) as f:
        rows = dict(((r["test"], r["folder"], r["measure"]), r) for r in csv.DictReader(f))
    for test in ("O", "I"):
        n10 = rows[(test, "normal", "n_10MPa")]
        check(abs(float(n10["change"]) - 0.02) < 1e-9 and n10["resolved"] == "yes",
              "%s-2 normal against clipped, n at 10 MPa: %s (%s), expected +0.02, resolved" % (test, n10["change"], n10["resolved"]))
        ref = rows[(test, "clipped", "yield_MPa")]
        other = rows[(test, "normal", "yield_MPa")]
        check(abs(float(ref["mean"]) - 10.0) < 1e-3 and abs(float(other["change"]) - 2.0) < 1e-3,
              "%s-2 yield: clipped %s MPa (expected 10), normal's change %s (expected +2)" % (test, ref["mean"], other["change"]))
    proc = compression_seeds(out, *folders, fails=True)
    check(proc.returncode != 0 and "with seed" in proc.stderr, "the readings without --by-folder refused: %s" % proc.stderr[-200:])



def case_t_rule(liggghts, work):
    """The 95% Student-t rule. Three seeds whose paired change is +0.3 +- 0.115 (t = 2.6): 2 standard
    errors would call it resolved; the t interval (df 2, 4.30 se) is -0.197 .. +0.797, p 0.12: not
    resolved. Five seeds with the same mean change, +0.3 +- 0.0707 (t = 4.24, df 4, 2.78 se): resolved,
    p 0.013. Pairing: the two sides correlate over the common seeds (r 0.99). A setting that shares no
    seed with the reference is compared unpaired, Welch: the reference's five seeds (variance 0.625)
    and its three (variance 1) give df (0.125 + 1/3)^2 / (0.125^2 / 4 + (1/3)^2 / 2) = 3.53.
    Holm's correction of p = 0.01, 0.04, 0.03, 0.2 gives 0.04, 0.09, 0.09, 0.2."""
    del liggghts
    ref, rows = (1.0, 2.0, 3.0, 1.5, 2.5), []
    for k, (seed, d) in enumerate(zip(SEEDS, (0.1, 0.3, 0.5, 0.2, 0.4))):
        rows.append(("ref_%s" % seed, "1", "0.1", seed, ref[k], 100))
        if k < 3:
            rows.append(("three_%s" % seed, "2", "0.1", seed, ref[k] + d, 100))
        rows.append(("five_%s" % seed, "3", "0.1", seed, ref[k] + d, 100))
    for k, seed in enumerate(("66", "77", "88")):
        rows.append(("other_%s" % seed, "4", "0.1", seed, (1.0, 2.0, 3.0)[k] + 1.0, 100))
    changes, _ = run(work, study(os.path.join(work, "study.csv"), rows), "--reference", "N=1")
    three = changes[("N=2 L_R=0.1", "porosity")]
    check((three["paired_change"], three["paired_df"], three["paired_interval"], three["paired_p"],
           three["paired_resolved"]) == ("+0.3", "2", "-0.1968 .. +0.7968", "0.122", "no (3)")
          and float(three["paired_change"]) > 2 * float(three["paired_se"]),
          "three seeds: +0.3 +- %s paired, beyond 2 se, yet its 95%% interval %s (p %s): %s"
          % (three["paired_se"], three["paired_interval"], three["paired_p"], three["paired_resolved"]))
    five = changes[("N=3 L_R=0.1", "porosity")]
    check((five["paired_df"], five["paired_p"], five["paired_resolved"]) == ("4", "0.0132", "yes (5)")
          and float(five["paired_r"]) > 0.99,
          "five seeds: +0.3 +- %s, interval %s, p %s: %s; r %s" % (five["paired_se"], five["paired_interval"],
                                                                 five["paired_p"], five["paired_resolved"], five["paired_r"]))
    other = changes[("N=4 L_R=0.1", "porosity")]
    check(other["paired_change"] == "" and other["change_df"] == "3.53",
          "no common seed: unpaired, Welch's df %s" % other["change_df"])
    sys.path.insert(0, ROOT)
    from post.seeds import holm
    adjusted = [round(p, 12) for p in holm([0.01, 0.04, 0.03, 0.2])]
    check(adjusted == [0.04, 0.09, 0.09, 0.2], "Holm: %s" % adjusted)

if __name__ == "__main__":
    test_main(globals(), sys.argv[1:])
