#!/usr/bin/env python3
"""The dedicated pair loop of hertz/scaled + mindlin/scaled (pair_gran_hertz_mindlin_scaled_pass.h)
gives LIGGGHTS' generic loop's forces to the bit (tests/regression/loop/in.loop).

  python3 test_dedicated_loop.py LIGGGHTS WORKDIR CASE [ARGS]    (--list: the cases)

Each case runs in.loop with 'dedicated_loop on' and 'off' on the same ranks and asserts: the log of
the 'on' run says the dedicated loop computed the forces and the 'off' log does not; the thermo
rows (time step, events, largest F_n/F_lim, kinetic energy, 17 digits), the event logs and every
particle's final force, torque, velocity and spin are identical as text. The assembly relaxes from
overlaps, a sixth of its grains burst at the first steps (fix crush's recorder) and fix dt/stiffness
sums the stiffness every step, so any difference in any contact's arithmetic grows into all of them.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liggghts_run import check, each_rank_count, read_thermo, run_deck, variants  # noqa: E402
from liggghts_run import main as test_main  # noqa: E402

DECK = os.path.join(os.path.dirname(os.path.abspath(__file__)), "loop", "in.loop")
NOTE = "forces by their dedicated loop"


def both_loops(liggghts, work, ranks, close):
    out = {}
    for loop in ("on", "off"):
        folder = os.path.join(work, loop)
        screen = run_deck(liggghts, DECK, folder, {"dedicated_loop": loop, "close": close}, ranks=int(ranks))
        with open(os.path.join(folder, "forces.dump")) as f:
            dump = f.read().split("ITEM: ATOMS", 1)[1]
        with open(os.path.join(folder, "events.csv")) as f:
            events = f.read()
        out[loop] = (screen, read_thermo(os.path.join(folder, "log.liggghts")), events, dump)
    (screen_on, thermo_on, events_on, dump_on), (screen_off, thermo_off, events_off, dump_off) = out["on"], out["off"]
    check(NOTE in screen_on and NOTE not in screen_off,
          "the 'on' run's forces come from the dedicated loop, the 'off' run's from LIGGGHTS' generic loop")
    events = events_on.count("\n") - 1
    check(events > 50 and thermo_on[-1]["Atoms"] > thermo_on[0]["Atoms"],
          "%d events: fragments and their contacts take part" % events)
    check(thermo_on == thermo_off, "the %d thermo rows (dt, events, largest F_n/F_lim, ke) are identical" % len(thermo_on))
    check(events_on == events_off, "the event logs are identical")
    check(dump_on == dump_off, "on %s rank(s), contact_distance_factor %s: the %d particles' forces, torques, "
          "velocities and spins are identical to the bit" % (ranks, close, int(thermo_on[-1]["Atoms"])))


@variants(*each_rank_count(1, 2, 3), timeout=300)
def case_assembly(liggghts, work, ranks):
    """The assembly with contact_distance_factor 1 (the decks')."""
    both_loops(liggghts, work, ranks, 1)


@variants(*each_rank_count(1, 2), timeout=300)
def case_close(liggghts, work, ranks):
    """contact_distance_factor 1.05: pairs just apart pass through the models' surfacesClose."""
    both_loops(liggghts, work, ranks, 1.05)


if __name__ == "__main__":
    test_main(globals(), sys.argv[1:])
