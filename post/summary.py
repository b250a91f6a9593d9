#!/usr/bin/python3
"""A short, readable summary of one oedometric or isotropic run of examples/fontainebleau.

    post/summary.py RUN_DIR [--figures DIR] [--seconds S] [--ranks R]

Reads the STATE lines that the decks print before loading and as the ramp passes 1, 10, 50 and
100 MPa (in RUN_DIR's screen.txt or log.liggghts) and prints particles, crushing events, porosity and
I_G at each, the paper's Table 3 row beside them, and the PNGs found in --figures."""
import argparse
import glob
import os
import re
import sys

if not __package__:  # run as a file (python3 post/summary.py): the folder above post/ holds the package
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from post.paper import TABLE3  # noqa: E402

HISTORY = re.compile(r"history_([OI])([0-9.]+)\.csv$")
STATE = re.compile(r"^STATE at (\S+) MPa: (\S+) particles, (\S+) events, porosity (\S+), I_G (\S+)", re.M)
SHOWN_MPA = ("0", "1", "10", "100")


def find_test(run_dir):
    for path in sorted(glob.glob(os.path.join(run_dir, "history_*.csv"))):
        m = HISTORY.search(os.path.basename(path))
        if m:
            return m.group(1), m.group(2)
    sys.exit("post/summary.py: no history_<O|I><N>.csv in %s (run in.oedometer or in.isotropic there)" % run_dir)


def states(run_dir):
    """{stress in MPa: (particles, events, porosity, I_G)} from the first output that has STATE lines."""
    for name in ("screen.txt", "log.liggghts"):
        path = os.path.join(run_dir, name)
        if os.path.exists(path):
            found = {m.group(1): (int(float(m.group(2))), int(float(m.group(3))), float(m.group(4)), float(m.group(5)))
                     for m in STATE.finditer(open(path).read())}
            if found:
                return found
    sys.exit("post/summary.py: no STATE lines in %s/screen.txt or log.liggghts" % run_dir)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run_dir")
    parser.add_argument("--figures", help="folder of the run's PNGs (post/plot.py --out)")
    parser.add_argument("--seconds", type=float, help="wall-clock time of the run")
    parser.add_argument("--ranks", type=int, help="MPI ranks of the run")
    args = parser.parse_args(argv)
    test, n = find_test(args.run_dir)
    found = states(args.run_dir)
    kind = "oedometric compression (stress: sigma_z)" if test == "O" else "isotropic compression (stress: p)"
    timing = "" if args.seconds is None else ", %.0f s" % args.seconds
    if args.ranks:
        timing += " on %d rank%s" % (args.ranks, "" if args.ranks == 1 else "s")
    print("%s-%s: %s, N = %s%s" % (test, n, kind, n, timing))
    print("  %-15s %10s %8s %9s %7s" % ("stress", "particles", "events", "porosity", "I_G"))
    for mpa in SHOWN_MPA:
        label = "before loading" if mpa == "0" else mpa + " MPa"
        if mpa in found:
            print("  %-15s %10d %8d %9.3f %7.3f" % ((label,) + found[mpa]))
        else:
            print("  %-15s %s" % (label, "not reached"))
    paper = TABLE3.get(test + n)
    if paper:
        print("  paper, Table 3: %d -> %d particles, %d events at 100 MPa" % paper[:3])
    if args.figures and os.path.isdir(args.figures):
        for png in sorted(glob.glob(os.path.join(args.figures, "*.png"))):
            print("  figure: %s" % os.path.abspath(png))


if __name__ == "__main__":
    main(sys.argv[1:])
