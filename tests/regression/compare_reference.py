#!/usr/bin/env python3
"""Runs a reference case and compares its thermo log and final per-atom dump (sorted by tag) with the
stored reference, column by column, with the tolerance of reference_cases.py. On a difference it
prints the first differing step, column and both values.

  python3 compare_reference.py LIGGGHTS WORKDIR CASE               compare (a test)
  python3 compare_reference.py LIGGGHTS WORKDIR CASE --regenerate  rewrite the reference, on purpose
"""
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liggghts_run import read_dump, read_thermo, run_deck  # noqa: E402
from reference_cases import CASES, IGNORED, ROOT, tolerance  # noqa: E402

REFERENCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "reference")


def outputs(liggghts, work, case):
    spec = CASES[case]
    if "before" in spec:
        run_deck(liggghts, spec["before"], work, spec["vars"])
    out = run_deck(liggghts, spec["deck"], work, spec["vars"], keep="before" in spec)
    thermo = read_thermo(os.path.join(work, "log.liggghts"))
    step, rows = -1, []
    if spec["dump"]:
        step, _, rows = read_dump(os.path.join(work, spec["dump"]))[-1]
        rows = sorted(rows, key=lambda r: r["id"])
    version = next((line for line in out.splitlines() if line.startswith("LIGGGHTS (Version")), "unknown")
    return {"thermo": thermo, "dump_step": step, "dump": rows, "liggghts": version}


def differs(a, b, column):
    tol = tolerance(column)
    if tol == 0.0:
        return a != b
    return abs(a - b) > tol * max(abs(a), abs(b), 1e-300)


def compare(ref, new, thermo=True):
    if not thermo:
        ref, new = dict(ref, thermo=[]), dict(new, thermo=[])
    if len(ref["thermo"]) != len(new["thermo"]):
        return "thermo: %d rows, reference %d" % (len(new["thermo"]), len(ref["thermo"]))
    for r, n in zip(ref["thermo"], new["thermo"]):
        for column in r:
            if column in IGNORED:
                continue
            if column not in n:
                return "thermo: column %s missing" % column
            if differs(r[column], n[column], column):
                return "thermo, step %d, column %s: %.17g, reference %.17g" % (r["Step"], column, n[column], r[column])
    if len(ref["dump"]) != len(new["dump"]):
        return "dump at step %d: %d atoms, reference %d" % (new["dump_step"], len(new["dump"]), len(ref["dump"]))
    for r, n in zip(ref["dump"], new["dump"]):
        for column in r:
            if differs(r[column], n[column], column):
                return "dump at step %d, atom %d, column %s: %.17g, reference %.17g" % (
                    new["dump_step"], r["id"], column, n[column], r[column])
    return None


def build_info(liggghts):
    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "HEAD"], stdout=subprocess.PIPE,
                            universal_newlines=True).stdout.strip()
    cache = os.path.join(os.path.dirname(os.path.abspath(liggghts)), "CMakeCache.txt")
    options = {}
    if os.path.exists(cache):
        for line in open(cache):
            for key in ("CMAKE_BUILD_TYPE", "CMAKE_CXX_COMPILER", "LIGGGHTS_CRUSH_MPI", "LIGGGHTS_CRUSH_SANITIZE"):
                if line.startswith(key + ":"):
                    options[key] = line.split("=", 1)[1].strip()
    return {"git_commit": commit, "build": options}


def main():
    liggghts, work, case = sys.argv[1:4]
    regenerate = "--regenerate" in sys.argv[4:]
    os.makedirs(work, exist_ok=True)
    new = outputs(os.path.abspath(liggghts), os.path.abspath(work), case)
    spec = CASES[case]
    path = os.path.join(REFERENCE, spec.get("reference", case) + ".json")
    if regenerate and "reference" in spec:
        print("%s is checked against the reference of %s: nothing to write" % (case, spec["reference"]))
        return
    if regenerate:
        os.makedirs(REFERENCE, exist_ok=True)
        new["recorded_with"] = build_info(liggghts)
        with open(path, "w") as f:
            json.dump(new, f, indent=0, sort_keys=True)
        print("reference written: %s (%d thermo rows, %d atoms)" % (path, len(new["thermo"]), len(new["dump"])))
        return
    ref = json.load(open(path))
    problem = compare(ref, new, spec.get("thermo", True))
    if problem:
        print("FAILED %s: %s\n(reference recorded with %s; regenerate on purpose with "
              "scripts/regen_references.sh)" % (case, problem, ref.get("recorded_with")))
        sys.exit(1)
    print("PASSED %s: %d thermo rows and %d atoms match the reference" % (case, len(new["thermo"]), len(new["dump"])))


if __name__ == "__main__":
    main()
