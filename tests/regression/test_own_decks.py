#!/usr/bin/env python3
"""Crushing in decks that LIGGGHTS users already have: LIGGGHTS' own tutorials (from the source the
build unpacks), each with the lines doc/own_deck.md tells a user to add and nothing else changed but
shorter runs and no dumps. Their contact laws are hooke (movingMeshGran: a bucket mesh moved through
falling grains), hertz (packing: grains grown by fix adapt) and hertz with sjkr cohesion (cohesion).
On 1 and 2 ranks: grains break in bursts, tags stay unique (fix crush's check_tags), and the books
balance exactly: every fragment and the removed volume add up to the mothers of the event log.

  python3 test_own_decks.py LIGGGHTS WORKDIR CASE [ARG ...]"""
import collections
import math
import os
import re
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liggghts_run import check, printed, read_dump, read_thermo, run_deck, variants  # noqa: E402
from liggghts_run import main as test_main  # noqa: E402
from liggghts_run import read_events  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
OWN_DECK = os.path.join(ROOT, "doc", "own_deck.md")


def tutorials(liggghts):
    """LIGGGHTS' tutorials in the source copy beside the built binary."""
    return os.path.join(os.path.dirname(os.path.abspath(liggghts)), "liggghts-3.8.0", "examples", "LIGGGHTS",
                        "Tutorials_public")


def copy_tutorial(liggghts, name, work):
    """The tutorial's folder copied afresh to work/deck; returns the copy."""
    source = os.path.join(tutorials(liggghts), name)
    if not os.path.isdir(source):
        raise AssertionError("LIGGGHTS' tutorial %s is missing from the source copy: %s" % (name, source))
    folder = os.path.join(work, "deck")
    if os.path.isdir(folder):
        shutil.rmtree(folder)
    shutil.copytree(source, folder)
    return folder


def largest_burst(events):
    """The most events logged in one step."""
    return max(collections.Counter(e["step"] for e in events).values())


def check_unique_tags(name, rows):
    tags = [int(r["id"]) for r in rows]
    check(len(tags) == len(set(tags)), "%s: %d particles, every tag unique" % (name, len(tags)))


def own_deck_lines():
    """The fix crush line of doc/own_deck.md's example, as a user copies it."""
    text = open(OWN_DECK).read()
    block = text.split("```\n# liggghts-crush: crushing\n", 1)[1].split("```", 1)[0]
    return [line for line in block.splitlines() if line.strip() and not line.startswith("#")]


# Per tutorial: its deck, the crush settings for its grains (sigma_lim0 so that a share of them break
# under impacts, their weight and the walls'; dmin above the largest fragment: fragments do not break
# again; movingMeshGran checks every 20 steps, as a user saving time would, and breaks in bursts),
# the edits that shorten it (run lengths) without changing what it does, and the line after which the
# fix goes (packing grows every grain with fix adapt, fragments too: its grains crush once grown).
TUTORIALS = {
    "packing": ("in.packing", {"sigma_lim0": "4e5", "d0": "0.016", "dmin": "0.012"},
                [("variable\tgrowts equal 50000", "variable\tgrowts equal 12000"),
                 ("variable\trelaxts equal 20000", "variable\trelaxts equal 4000")], "unfix\tgrow"),
    "cohesion": ("in.cohesion", {"sigma_lim0": "6e5", "d0": "0.003", "dmin": "0.0025"},
                 [("run\t\t\t50000 upto", "run\t\t\t13000 upto")], "pair_coeff"),
}


def with_crushing(text, settings, after):
    """The tutorial with doc/own_deck.md's lines: an atom map where it has none, the fix crush line
    (with this tutorial's strengths, and every tag checked after each replacement) after the line
    that starts with 'after', and a summary printed at the end."""
    if "atom_modify" not in text:
        at = text.index("\n", text.index("atom_style")) + 1
        text = text[:at] + "atom_modify\tmap array\n" + text[at:]
    crush = []
    for line in own_deck_lines():
        words = line.split()
        if words[:1] == ["fix"]:
            for key, value in settings.items():
                if key in words:
                    words[words.index(key) + 1] = value
                else:
                    words += [key, value]
            words += ["check_tags", "yes"]
        crush.append(" ".join(words))
    at = text.index("\n", text.index(after)) + 1
    text = text[:at] + "\n".join(crush) + "\n" + text[at:]
    text = "\n".join("#" + line if line.startswith(("dump", "undump")) else line for line in text.splitlines())
    summary = ('variable events equal f_crush[1]\n'
               'print "EVENTS ${events}"\n'
               'print "REMOVED $(f_crush[2])"\n'
               'write_dump all custom final.dump id radius f_crush[2] modify format "%d %.17g %g"\n')
    return text + "\n" + summary


@variants(*[(name, ranks) for name in TUTORIALS for ranks in (1, 2)], timeout=300)
def case_tutorial(liggghts, work, name, ranks):
    """One tutorial with crushing added, on 1 or 2 ranks: bursts of events, unique tags, exact books."""
    deck_name, settings, edits, after = TUTORIALS[name]
    folder = copy_tutorial(liggghts, name, work)
    text = open(os.path.join(folder, deck_name)).read()
    for old, new in edits:
        check(old in text, "the tutorial has '%s'" % old.strip())
        text = text.replace(old, new)
    open(os.path.join(folder, deck_name), "w").write(with_crushing(text, settings, after))
    out = run_deck(liggghts, os.path.join(folder, deck_name), os.path.join(work, "run"), ranks=int(ranks))
    events = read_events(os.path.join(work, "run", "crush_events.csv"))
    check(printed(out, "EVENTS") == len(events) and len(events) >= 20,
          "%s: %d events, all in the log" % (name, len(events)))
    check(largest_burst(events) >= 3, "%s: bursts (up to %d events in one step)" % (name, largest_burst(events)))
    rows = read_dump(os.path.join(work, "run", "final.dump"))[-1][2]
    check_unique_tags(name, rows)
    fragments = [r for r in rows if r["f_crush[2]"] >= 1]
    check(len(fragments) == 14 * len(events), "%s: 14 fragments an event (%d)" % (name, len(fragments)))
    volume = lambda d: math.pi * d ** 3 / 6  # noqa: E731
    mothers = sum(volume(float(e["diameter"])) for e in events)
    kept = sum(volume(2 * r["radius"]) for r in fragments)
    removed = printed(out, "REMOVED")
    # the event log gives the mothers' diameters to 10 digits: a lost or doubled fragment is 1/14 of one
    check(abs(kept + removed - mothers) <= 1e-9 * mothers,
          "%s: fragments + removed volume = the mothers' volume (%.3e of it)" % (name, (kept + removed) / mothers - 1))


# Decks whose grains leave a fixed box (chute_wear: streamed onto a chute, they leave at its foot;
# 'thermo_modify lost ignore') or move a shrink-wrapped one (movingMeshGran: 'boundary m m m', a bucket
# mesh moved through the bed), whole: deck, crush settings (dmin above the largest fragment), the line
# after which fix crush goes, the fix that inserts the grains (and their density), and whether grains
# must leave.
OUTFLOW_TUTORIALS = {
    "chute_wear": ("in.chute_wear", {"sigma_lim0": "2e5", "d0": "0.005", "dmin": "0.004"}, "pair_coeff", 2500.0, True),
    "movingMeshGran": ("in.movingMeshGran", {"sigma_lim0": "6e5", "d0": "0.08", "dmin": "0.05", "every": "20"},
                       "pair_coeff", 2500.0, False),
}


@variants(*[(name, ranks) for name in OUTFLOW_TUTORIALS for ranks in (1, 2)], timeout=900)
def case_outflow(liggghts, work, name, ranks):
    """A tutorial whose grains leave the box or move it, run to its end with crushing added: grains
    break, tags stay unique, and the books hold with the volume that left: particles +
    removed volume + outflow = the volume the insertion fix created, to 1e-9."""
    deck_name, settings, after, density, leaves = OUTFLOW_TUTORIALS[name]
    folder = copy_tutorial(liggghts, name, work)
    text = open(os.path.join(folder, deck_name)).read()
    unfix = re.search(r"^unfix\s+ins\s*$", text, re.M)
    check(unfix is not None, "%s stops inserting with 'unfix ins'" % name)
    text = text[:unfix.start()] + 'print "INSERTED_MASS $(f_ins[2])"\n' + text[unfix.start():]
    text = with_crushing(text, settings, after)
    text += 'print "OUTFLOW $(f_crush[6])"\nprint "OUTFLOW_N $(f_crush[7])"\n'
    open(os.path.join(folder, deck_name), "w").write(text)
    out = run_deck(liggghts, os.path.join(folder, deck_name), os.path.join(work, "run"), ranks=int(ranks))
    events = read_events(os.path.join(work, "run", "crush_events.csv"))
    check(len(events) >= 20,
          "%s on %s rank(s) ran to its end: %d events, up to %d in one step" % (name, ranks, len(events),
                                                                             largest_burst(events)))
    rows = read_dump(os.path.join(work, "run", "final.dump"))[-1][2]
    check_unique_tags(name, rows)
    left = printed(out, "OUTFLOW_N")
    if leaves:
        check(left > 0 and "leave the box at step" in out, "%d particles left the box, and the log says so" % left)
    volume = lambda d: math.pi * d ** 3 / 6  # noqa: E731
    present = sum(volume(2 * r["radius"]) for r in rows)
    inserted = printed(out, "INSERTED_MASS") / density
    books = present + printed(out, "REMOVED") + printed(out, "OUTFLOW")
    check(abs(books - inserted) <= 1e-9 * inserted,
          "%s: particles + removed + outflow (%.6e m^3) = the inserted volume (%.6e m^3; %.1e of it)"
          % (name, books, inserted, abs(books / inserted - 1)))


HEAT_SETTINGS = {"sigma_lim0": "3e5", "d0": "0.008", "dmin": "0.006"}
HEAT_RUN = ("run\t\t50000 upto", "run\t\t30000 upto")  # 10,000 steps of conduction after the events begin


@variants(*[(bed, ranks) for bed in ("uniform", "half") for ranks in (1, 2)], timeout=300)
def case_heat_transfer(liggghts, work, bed, ranks):
    """LIGGGHTS' tutorial heatTransfer_1 (fix heat/gran: conduction between grains at 300 K and 800 K),
    whole, with crushing added once the bed has settled, when the temperatures are set: every grain
    at 800 K (uniform) or the tutorial's own half bed. A fragment is born at its mother's temperature:
    with a uniform bed every particle is at 800 K at the end, and the thermal energy sum(m c T) has
    lost only the removed volumes' share, rho c T V_removed; with the half bed (conduction conserves
    sum(m c T)) each event step changes it by -rho c T V_removed, with T between 300 and 800 K."""
    ranks = int(ranks)
    folder = copy_tutorial(liggghts, "heatTransfer_1", work)
    text = open(os.path.join(folder, "in.heatGran")).read()
    temperature = "set             region halfbed property/atom Temp 800."
    check(temperature in text, "the tutorial sets the half bed to 800 K")
    check(HEAT_RUN[0] in text, "the tutorial runs to step 50000")
    text = text.replace(*HEAT_RUN)
    if bed == "uniform":
        text = text.replace(temperature, "set             group all property/atom Temp 800.")
    text = with_crushing(text, HEAT_SETTINGS, "property/atom Temp 800.")
    every_step = ("thermo_style    custom step atoms f_heattransfer f_crush[1] f_crush[2]\n"
                  "thermo          1\nthermo_modify   lost ignore norm no format float %.17g\n")
    at = text.index("\n", text.index("fix crush")) + 1
    text = text[:at] + every_step + text[at:]
    text += 'write_dump all custom temperatures.dump id radius f_Temp[0] modify format "%d %.17g %.17g"\n'
    open(os.path.join(folder, "in.heatGran"), "w").write(text)
    out = run_deck(liggghts, os.path.join(folder, "in.heatGran"), os.path.join(work, "run"), ranks=ranks)
    run = os.path.join(work, "run")
    events = read_events(os.path.join(run, "crush_events.csv"))
    check(len(events) >= 20, "%s bed on %d rank(s): %d events" % (bed, ranks, len(events)))
    rows = [r for r in read_thermo(os.path.join(run, "log.liggghts")) if "crush[1]" in r]
    key = next(k for k in rows[0] if k.startswith("heattran"))  # LIGGGHTS cuts the header to 8 characters
    energy = {int(r["Step"]): r[key] for r in rows}
    removed_total = printed(out, "REMOVED")
    volume = lambda d: math.pi * d ** 3 / 6  # noqa: E731
    removed_share = removed_total / sum(volume(float(e["diameter"])) for e in events)
    rho_c = 8000.0 * 10.0
    if bed == "uniform":
        final = read_dump(os.path.join(run, "temperatures.dump"))[-1][2]
        hot = [r["f_Temp[0]"] for r in final]
        check(all(abs(t - 800.0) <= 1e-9 * 800.0 for t in hot),
              "all %d particles at 800 K at the end (%.12g - %.12g K)" % (len(hot), min(hot), max(hot)))
        first, last = rows[0][key], rows[-1][key]
        expected = first - rho_c * 800.0 * removed_total
        check(abs(last - expected) <= 1e-9 * first,
              "sum(m c T) %.12g J -> %.12g J: less the removed volume's share, %.12g J (%.2e of it)"
              % (first, last, expected, abs(last - expected) / first))
        return
    by_step = {}
    for e in events:
        by_step.setdefault(int(e["step"]), []).append(volume(float(e["diameter"])) * removed_share)
    temperatures = []
    for step, removed in sorted(by_step.items()):
        # logged at the step that found them; replaced in the next one
        change = energy[step + 1] - energy[step]
        temperatures.append(-change / (rho_c * sum(removed)))
    check(all(300.0 - 1e-6 <= t <= 800.0 + 1e-6 for t in temperatures),
          "each of the %d event steps changes sum(m c T) by -rho c T V_removed with T in [300, 800] K "
          "(%.6g - %.6g K)" % (len(temperatures), min(temperatures), max(temperatures)))


# LIGGGHTS' conveyor tutorial (insert/stream carries each grain through the insertion volume until its
# release step; a belt mesh carries them off) with crushing as a user adds it: 'neighbor 0.01 multi'
# and one fix crush line after 'fix integr', optionally own_deck.md's balancer line. Free grains
# bounce into grains the stream still carries; some reach their limit before their release, and
# f_crush[11] counts the checks that found one (in.held_stream tests the rule grain by grain).
CONVEYOR_CRUSH = ("fix crush all crush sigma_lim0 1e6 cv 0.5 weibull_m 10 d0 0.05 seed 1234567 dmin 0.005 "
                  "log crush_events.csv check_tags yes")
CONVEYOR_BALANCE = "fix bal all balance 1000 1.05 shift xyz 20 1.0 weight neighbors"


def conveyor_deck(liggghts, work, steps, balancer):
    """The conveyor tutorial in work/deck, run to step `steps`, with the lines above (the thermo output
    with the events and the held grains' checks) and a summary."""
    folder = copy_tutorial(liggghts, "conveyor", work)
    path = os.path.join(folder, "in.conveyor")
    text = open(path).read()
    edits = [("neighbor\t0.01 bin", "neighbor\t0.01 multi"),
             ("fix\t\tintegr nve_group nve/sphere\n",
              "fix\t\tintegr nve_group nve/sphere\n" + CONVEYOR_CRUSH + "\n"
              + (CONVEYOR_BALANCE + "\n" if balancer == "balance" else "")),
             ("f_ts[1] f_ts[2] vol\n", "f_ts[1] f_ts[2] vol f_crush[1] f_crush[11]\n"),
             ("run\t\t\t140000 upto", "run\t\t\t%d upto" % steps),
             ("\nunfix\t\tins", '\nprint "INSERTED $(f_ins[1])"\nunfix\t\tins')]
    for old, new in edits:
        check(old in text, "the tutorial has '%s'" % old.strip())
        text = text.replace(old, new)
    text = text.replace("\ndump\t\tdmp", "\n#dump\t\tdmp")
    text += ('print "EVENTS $(f_crush[1])"\nprint "HELD_AT_LIMIT $(f_crush[11])"\n'
             'write_dump all custom final.dump id radius f_crush[2] modify format "%d %.17g %g"\n')
    open(path, "w").write(text)
    return path


def check_conveyor(out, run, ranks, balancer):
    """Books exact: particles = inserted + 13 x events, every tag once; returns the checks that found a
    held grain at its limit."""
    events = read_events(os.path.join(run, "crush_events.csv"))
    rows = read_dump(os.path.join(run, "final.dump"))[-1][2]
    inserted = int(printed(out, "INSERTED"))
    check(printed(out, "EVENTS") == len(events) > 0, "%d events, all in the log" % len(events))
    check_unique_tags("conveyor", rows)
    check(len(rows) == inserted + 13 * len(events), "%d particles = %d inserted + 13 x %d events (%s rank(s), %s)"
          % (len(rows), inserted, len(events), ranks, balancer))
    return printed(out, "HELD_AT_LIMIT")


# The steps of each length: the shortened run of the default set, and the whole tutorial (long set).
# On 2 ranks the stream's grains are first found at their limit at steps 53,000 - 54,000 (equal
# slabs) and 44,000 - 45,000 (with the balancer), and the shortened run must reach them; on 1 rank
# the tutorial's trajectory meets none in its 140,000 steps (measured, both lines), and the run
# checks the books.
CONVEYOR_STEPS = {"short": 60000, "whole": 140000}


@variants(*[("short", ranks, balancer) for ranks in (1, 2) for balancer in ("slabs", "balance")]
          + [("whole", 2, balancer) for balancer in ("slabs", "balance")], timeout=1200)
def case_conveyor(liggghts, work, length, ranks, balancer):
    """LIGGGHTS' conveyor tutorial with crushing, on 1 and 2 ranks, with and without the balancer:
    it runs, the books are exact, and on 2 ranks the run reaches grains the stream still carries at
    their limit (they wait for their release: with their fragments given the release data, the
    whole run stopped at step 43,5xx on 2 ranks, every fragment on its mother's path)."""
    path = conveyor_deck(liggghts, work, CONVEYOR_STEPS[length], balancer)
    run = os.path.join(work, "run")
    out = run_deck(liggghts, path, run, ranks=int(ranks))
    held = check_conveyor(out, run, ranks, balancer)
    if int(ranks) == 2:
        check(held > 0, "%d checks found a grain the stream still carried at its limit" % held)


def case_multisphere(liggghts, work):
    """LIGGGHTS' multisphere tutorial (stones of 50 spheres each, inserted at its first run) with the
    fix crush line after 'fix integr': the next run stops at its start, naming a sphere of a stone,
    instead of breaking a piece of a rigid clump into free fragments."""
    folder = copy_tutorial(liggghts, "multisphere_stone_restitution", work)
    path = os.path.join(folder, "in.multisphere")
    text = open(path).read()
    line = "fix\t\tintegr all multisphere\n"
    check(line in text, "the tutorial integrates its stones with '%s'" % line.strip())
    text = text.replace(line, line + "fix crush all crush sigma_lim0 1e5 cv 0.5 weibull_m 10 d0 0.05 seed 1234567\n")
    text = text.replace("\ndump", "\n#dump")
    open(path, "w").write(text)
    out = run_deck(liggghts, path, os.path.join(work, "run"), expect_fail=True)
    said = re.search(r"particle (\d+) belongs to a rigid body of fix multisphere", out)
    check(said is not None, "the run stops: 'particle %s belongs to a rigid body of fix multisphere'"
          % (said.group(1) if said else "?"))

if __name__ == "__main__":
    test_main(globals(), sys.argv[1:])
