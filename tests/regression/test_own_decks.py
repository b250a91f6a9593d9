#!/usr/bin/env python3
"""Crushing in decks that LIGGGHTS users already have: LIGGGHTS' own tutorials (from the source the
build unpacks), each with the lines doc/own_deck.md tells a user to add and nothing else changed but
shorter runs and no dumps. Their contact laws are hooke (movingMeshGran: a bucket mesh moved through
falling grains), hertz (packing: grains grown by fix adapt) and hertz with sjkr cohesion (cohesion).
On 1 and 2 ranks: grains break in bursts, tags stay unique (fix crush's check_tags), and the books
balance exactly: every fragment and the removed volume add up to the mothers of the event log.

  python3 test_own_decks.py LIGGGHTS WORKDIR CASE [ARG ...]"""
import math
import os
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liggghts_run import check, printed, read_dump, run_deck, variants  # noqa: E402
from liggghts_run import main as test_main  # noqa: E402
from test_crush import read_events  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
OWN_DECK = os.path.join(ROOT, "doc", "own_deck.md")


def tutorials(liggghts):
    """LIGGGHTS' tutorials in the source copy beside the built binary."""
    return os.path.join(os.path.dirname(os.path.abspath(liggghts)), "liggghts-3.8.0", "examples", "LIGGGHTS",
                        "Tutorials_public")


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
    "movingMeshGran": ("in.movingMeshGran", {"sigma_lim0": "6e5", "d0": "0.08", "dmin": "0.05", "every": "20"},
                       [("run\t\t29999 upto", "run\t\t10000 upto"), ("run\t\t30000 upto", "run\t\t10001 upto"),
                        ("run\t\t15000", "run\t\t5000"), ("run\t\t\t25000", "run\t\t\t3000")], "pair_coeff"),
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
    source = os.path.join(tutorials(liggghts), name)
    if not os.path.isdir(source):
        raise AssertionError("LIGGGHTS' tutorial %s is missing from the source copy: %s" % (name, source))
    deck_name, settings, edits, after = TUTORIALS[name]
    folder = os.path.join(work, "deck")
    if os.path.isdir(folder):
        shutil.rmtree(folder)
    shutil.copytree(source, folder)
    text = open(os.path.join(folder, deck_name)).read()
    for old, new in edits:
        check(old in text, "the tutorial has '%s'" % old.strip())
        text = text.replace(old, new)
    open(os.path.join(folder, deck_name), "w").write(with_crushing(text, settings, after))
    out = run_deck(liggghts, os.path.join(folder, deck_name), os.path.join(work, "run"), ranks=int(ranks))
    events = read_events(os.path.join(work, "run", "crush_events.csv"))
    check(printed(out, "EVENTS") == len(events) and len(events) >= 20,
          "%s: %d events, all in the log" % (name, len(events)))
    steps = {}
    for e in events:
        steps[e["step"]] = steps.get(e["step"], 0) + 1
    check(max(steps.values()) >= 3, "%s: bursts (up to %d events in one step)" % (name, max(steps.values())))
    rows = read_dump(os.path.join(work, "run", "final.dump"))[-1][2]
    tags = [int(r["id"]) for r in rows]
    check(len(tags) == len(set(tags)), "%s: %d particles, every tag unique" % (name, len(tags)))
    fragments = [r for r in rows if r["f_crush[2]"] >= 1]
    check(len(fragments) == 14 * len(events), "%s: 14 fragments an event (%d)" % (name, len(fragments)))
    volume = lambda d: math.pi * d ** 3 / 6  # noqa: E731
    mothers = sum(volume(float(e["diameter"])) for e in events)
    kept = sum(volume(2 * r["radius"]) for r in fragments)
    removed = printed(out, "REMOVED")
    # the event log gives the mothers' diameters to 10 digits: a lost or doubled fragment is 1/14 of one
    check(abs(kept + removed - mothers) <= 1e-9 * mothers,
          "%s: fragments + removed volume = the mothers' volume (%.3e of it)" % (name, (kept + removed) / mothers - 1))


if __name__ == "__main__":
    test_main(globals(), sys.argv[1:])
