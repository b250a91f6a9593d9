#!/usr/bin/python3
"""q_c by depth over the seeds of a setting: each test's history (in.cone's penetration_LABEL_N<N>.csv)
averaged over bins of depth, then the mean and standard error of those averages over the tests.

    post/penetration_depth.py HISTORY.csv [HISTORY.csv ...] [--bin 1.0] [--to 4.0] [--csv OUT.csv]

A history's rows whose depth_Dc lies in [k bin, (k + 1) bin) make its bin k; a bin a history does not
reach is left out of that history. Prints one line a bin: depth range (D_c), tests, mean and se of q_c
(MPa). --csv appends each test's own bins to OUT.csv (case, from_Dc, to_Dc, q_c_MPa; the case is the
study's folder above the history's penetration/ folder, else the history's file name), so that the
seeds' bins can be paired and recomputed without the histories.
"""
import argparse
import csv
import math
import os
import sys

if not __package__:  # run as a file (python3 post/penetration_depth.py): the folder above post/ holds the package
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from post.seeds import statistics  # noqa: E402


def binned(path, width, end):
    """{bin: mean q_c (MPa)} of one history."""
    sums = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            depth = float(row["depth_Dc"])
            if 0 <= depth < end:
                k = int(math.floor(depth / width))
                total, n = sums.get(k, (0.0, 0))
                sums[k] = (total + float(row["q_c"]) / 1e6, n + 1)
    return dict((k, total / n) for k, (total, n) in sums.items())


def case_of(path):
    """The study's case a history belongs to: OUT_DIR/<case>/penetration/penetration_*.csv."""
    folder = os.path.dirname(os.path.abspath(path))
    if os.path.basename(folder) == "penetration":
        return os.path.basename(os.path.dirname(folder))
    return os.path.basename(path)


def append_rows(out, histories, tests, width):
    """Each test's bins as rows of OUT (its header written when OUT is new)."""
    new = not os.path.exists(out)
    with open(out, "a") as f:
        if new:
            f.write("case,from_Dc,to_Dc,q_c_MPa\n")
        for path, bins in zip(histories, tests):
            for k in sorted(bins):
                f.write("%s,%g,%g,%.6g\n" % (case_of(path), k * width, (k + 1) * width, bins[k]))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("histories", nargs="+")
    parser.add_argument("--bin", type=float, default=1.0, help="the bins' width (D_c)")
    parser.add_argument("--to", type=float, default=4.0, help="the last bin's end (D_c)")
    parser.add_argument("--csv", help="append each test's bins to this CSV")
    a = parser.parse_args()
    tests = [binned(path, a.bin, a.to) for path in a.histories]
    if a.csv:
        append_rows(a.csv, a.histories, tests, a.bin)
    for k in range(int(round(a.to / a.bin))):
        values = [t[k] for t in tests if k in t]
        if values:
            n, mean, _, se = statistics(values)
            print("%.2g - %.2g D_c: %d tests, q_c %.3f +- %.3f MPa" % (k * a.bin, (k + 1) * a.bin, n, mean, se))


if __name__ == "__main__":
    main()
