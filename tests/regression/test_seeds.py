#!/usr/bin/env python3
"""post/seeds.py, the studies' seeds harness, on stand-in studies whose effects are known (no liggghts
needed).

  python3 test_seeds.py LIGGGHTS WORKDIR CASE"""
import csv
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liggghts_run import check  # noqa: E402
from liggghts_run import main as test_main  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TOOL = os.path.join(ROOT, "post", "seeds.py")
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


if __name__ == "__main__":
    test_main(globals(), sys.argv[1:])
