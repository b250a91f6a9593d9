#!/usr/bin/env python3
"""Errors reach the output file and log.liggghts when the output is redirected, as in a batch job:
`liggghts -in deck > out.txt 2>&1`, serially and on 2 ranks, without stdbuf (patches/0004).

  python3 test_errors.py LIGGGHTS WORKDIR redirected WHICH RANKS
  python3 test_errors.py --list

WHICH: event_log (fix crush cannot open its log: error->one on proc 0), time_step (a time step above
the stable one: error->all), lost (a particle leaves the box under 'thermo_modify lost error'), one_rank (an invalid atom type in a
data file, found only by the proc that owns the atom: on 2 ranks proc 1 raises error->one alone),
coincident (two grains created at one point: the contact has no normal, patches/0008 stops the run
naming both tags, error->one on the proc that computes the contact), size_classes ('neighbor ...
multi' with decreasing bounds for its size classes: 'neigh_modify size_classes', patches/0012).
"""
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liggghts_run import check, edited_deck, variants  # noqa: E402
from liggghts_run import main as test_main  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SINGLE = os.path.join(ROOT, "examples", "single_grain", "in.single_grain")

BAD_DATA = """LIGGGHTS data file: atom 2 has a type the box does not have

2 atoms
2 atom types

0 0.001 xlo xhi
0 0.001 ylo yhi
0 0.001 zlo zhi

Atoms

1 1 0.0002 2650 0.0001 0.0001 0.0001
2 3 0.0002 2650 0.0009 0.0009 0.0009
"""

DATA_DECK = """atom_style      granular
atom_modify     map array
boundary        p p p
newton          off
units           si
read_data       bad.data
run             0
"""


def failing_deck(case, work):
    """The failing deck of the case, in work/deck, and the message its error must carry."""
    folder = os.path.join(work, "deck")
    if case == "event_log":
        return edited_deck(SINGLE, folder, [("log crush_events.csv", "log /nonexistent/dir/x.csv")]), \
            "fix crush: cannot open the event log '/nonexistent/dir/x.csv'"
    if case == "time_step":
        return edited_deck(SINGLE, folder, [("timestep        1e-8", "timestep        1e-6")]), \
            "fix crush: time step 1e-06 s exceeds"
    if case == "lost":
        return edited_deck(SINGLE, folder, [("fix             load all addforce 0.0 0.0 v_push",
                                             "fix             load all addforce 0.0 0.0 1.0"),
                                            ("thermo_modify   format float %.15g",
                                             "thermo_modify   format float %.15g lost error")]), \
            "fix crush: 1 particles leave the box at step"
    if case == "size_classes":
        return edited_deck(SINGLE, folder, [("neighbor        0.00005 bin", "neighbor        0.00005 multi\n"
                                             "neigh_modify    size_classes 2 0.0002 0.0001")]), \
            "neigh_modify size_classes: expected the bounds in increasing order"
    if case == "coincident":
        single = "create_atoms    1 single 0.0 0.0 0.0001 units box"
        deck = edited_deck(SINGLE, folder, [(single, single + "\n" + single),
                                           ("set             atom 1 diameter", "set             group all diameter")])
        return deck, "Pair gran: particles 1 and 2 touch with their centres at one point"
    if case == "one_rank":
        os.makedirs(folder, exist_ok=True)
        open(os.path.join(folder, "bad.data"), "w").write(BAD_DATA)
        open(os.path.join(folder, "in.bad_data"), "w").write(DATA_DECK)
        return os.path.join(folder, "in.bad_data"), "Invalid atom type in Atoms section of data file"
    raise SystemExit("unknown case " + case)


def check_error(liggghts, work, case, ranks):
    ranks = int(ranks)
    deck, message = failing_deck(case, work)
    folder = os.path.dirname(deck)
    launcher = "mpiexec -n %d --oversubscribe " % ranks if ranks > 1 else ""
    os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    command = "%s'%s' -in %s > out.txt 2>&1" % (launcher, liggghts, os.path.basename(deck))
    proc = subprocess.run(["bash", "-c", command], cwd=folder)
    check(proc.returncode != 0, "%s on %d rank(s) stops with exit status %d" % (case, ranks, proc.returncode))
    out = open(os.path.join(folder, "out.txt"), errors="replace").read()
    log = open(os.path.join(folder, "log.liggghts"), errors="replace").read()
    check(message in out, "out.txt (stdout and stderr redirected) has '%s'" % message)
    check(message in log, "log.liggghts has it too")
    if case == "one_rank" and ranks > 1:
        check("ERROR on proc 1: " + message in out, "raised on proc 1 alone, and named so")


@variants(*[(which, ranks) for which in ("event_log", "time_step", "lost", "one_rank",
                                                                 "coincident", "size_classes") for ranks in (1, 2)])
def case_redirected(liggghts, work, which, ranks):
    check_error(liggghts, work, which, ranks)


if __name__ == "__main__":
    test_main(globals(), sys.argv[1:])
