#!/usr/bin/env python3
"""Bursts: many grains breaking in one step, on periodic and processor boundaries, on any number of
ranks, and a restart written with the replacement still pending (tests/regression/burst/).

  python3 test_burst.py LIGGGHTS WORKDIR CASE RANKS     CASE: all, half, restart, inherit, density or scale
  python3 test_burst.py --list

Every case asserts: every tag unique, particles = initial + 13 x events at every thermo row, the
volume books to 1e-12, no broken grain left, and the events of the burst step exactly those the
deck implies (which grains, and their fragment tags), whatever the number of ranks.
"""
import math
import os
import re
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liggghts_run import check, each_rank_count, read_dump, read_thermo, run_deck, variants  # noqa: E402
from liggghts_run import FRAGMENTS, inheritance_errors, read_balance_moves, read_events  # noqa: E402
from liggghts_run import main as test_main  # noqa: E402

BURST = os.path.join(os.path.dirname(os.path.abspath(__file__)), "burst")
CELLS = 12              # grains per box edge: 1728 grains
SPACING = 0.21e-3       # m, lattice spacing and box = CELLS x SPACING
DIAMETER = 0.2121e-3    # m: 1% overlap with each neighbour


def grain_type(i, j, k):
    """Type 2 (breakable in case 'half') for about half the grains, scattered by a fixed hash."""
    return 2 if ((i * 7919 + j * 104729 + k * 1299709) * 2654435761 >> 7) % 2 else 1


def write_data(path):
    """The lattice, tagged in a fixed order (x fastest), so that tags do not depend on the ranks."""
    box = CELLS * SPACING
    lines = ["LIGGGHTS data file: burst lattice, %d grains" % CELLS ** 3, "",
             "%d atoms" % CELLS ** 3, "2 atom types", "",
             "0 %.17g xlo xhi" % box, "0 %.17g ylo yhi" % box, "0 %.17g zlo zhi" % box, "", "Atoms", ""]
    tag = 0
    types = {}
    for k in range(CELLS):
        for j in range(CELLS):
            for i in range(CELLS):
                tag += 1
                types[tag] = grain_type(i, j, k)
                lines.append("%d %d %.17g 2650 %.17g %.17g %.17g" % (tag, types[tag], DIAMETER, i * SPACING,
                                                                      j * SPACING, k * SPACING))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return types


def run_burst(liggghts, deck, work, case, ranks, extra=None, variables=None):
    """Runs a burst deck in work, with burst.data (and any extra files) beside it, and the deck's
    further variables."""
    if os.path.isdir(work):
        shutil.rmtree(work)
    os.makedirs(work)
    types = write_data(os.path.join(work, "burst.data"))
    for name in extra or []:
        shutil.copy(name, work)
    run_deck(liggghts, os.path.join(BURST, deck), work,
             dict({"case": case, "log": "events.csv", "out": "final.dump"}, **(variables or {})), ranks=ranks, keep=True)
    return types


def check_run(work, case, ranks, types, thermo_from_restart=False, straddle=True):
    """The invariants of a finished burst run in work (straddle: some mothers lie on the equal slabs'
    planes)."""
    n0 = CELLS ** 3
    # (the rows of fix crush's runs: in.burst_scale runs once before fix crush exists)
    thermo = [row for row in read_thermo(os.path.join(work, "log.liggghts")) if "crush[1]" in row]
    v0 = n0 * math.pi / 6 * DIAMETER ** 3
    for row in thermo:
        if any(v != v for v in row.values()):
            raise AssertionError("NaN at step %d" % row["Step"])
        if row["Atoms"] != n0 + 13 * row["crush[1]"]:
            raise AssertionError("step %d: %d particles, %d events" % (row["Step"], row["Atoms"], row["crush[1]"]))
        if abs(row["gsd"] - v0) > 1e-12 * v0:
            raise AssertionError("step %d: solid volume %.17g, initially %.17g" % (row["Step"], row["gsd"], v0))
    breakable = sorted(t for t, ty in types.items() if case == "all" or ty == 2)
    events = thermo[-1]["crush[1]"]
    check(events == len(breakable), "%s on %d rank(s): %d events, one per breakable grain"
          % (case, ranks, events))
    check(True, "every thermo row (%d, from step %d): particles = %d + 13 x events, particle + removed volume = "
          "initial (1e-12), no NaN" % (len(thermo), thermo[0]["Step"], n0))
    log = read_events(os.path.join(work, "events.csv"))
    check([int(e["tag"]) for e in log] == breakable and all(e["step"] == "1" for e in log),
          "the burst step (1) breaks exactly the %d breakable grains, in tag order" % len(breakable))
    expected = [[str(n0 + 1 + FRAGMENTS * k + f) for f in range(FRAGMENTS)] for k in range(len(breakable))]
    check([[e["fragment_%d" % (f + 1)] for f in range(FRAGMENTS)] for e in log] == expected,
          "their fragment tags are %d + 14 k + (0..13), as on any number of ranks" % (n0 + 1))
    final = read_dump(os.path.join(work, "final.dump"))[-1][2]
    tags = [int(r["id"]) for r in final]
    check(len(tags) == len(set(tags)) == thermo[-1]["Atoms"], "%d particles, every tag unique" % len(tags))
    check(not set(breakable) & set(tags), "no broken grain left")
    check(sum(1 for r in final if r["f_crush[2]"] == 1) == FRAGMENTS * len(breakable),
          "%d first-generation fragments" % (FRAGMENTS * len(breakable)))
    volume = sum(math.pi / 6 * (2 * r["radius"]) ** 3 for r in final)
    check(abs(volume + thermo[-1]["crush[2]"] - v0) / v0 < 1e-12, "final books balance to 1e-12")
    if ranks > 1 and straddle:
        # Grains within a radius of a processor boundary (x = L/2 on 2 and 4 ranks, L/3 and 2L/3 on 3)
        # have fragments on both sides: they migrate in the step they are born.
        box = CELLS * SPACING
        planes = [box / 3, 2 * box / 3] if ranks == 3 else [box / 2]
        on_boundary = [e for e in log if min(abs(float(e["x"]) - p) for p in planes) < DIAMETER / 2]
        check(len(on_boundary) > 0, "%d mothers straddle a processor boundary" % len(on_boundary))
    return log, final


def burst(liggghts, work, case, ranks):
    ranks = int(ranks)
    types = run_burst(liggghts, "in.burst", work, case, ranks)
    check_run(work, case, ranks, types)


@variants(*each_rank_count(1, 2, 3, 4), timeout=600)
def case_all(liggghts, work, ranks):
    """Every grain breaks in the burst step."""
    burst(liggghts, work, "all", ranks)


@variants(*each_rank_count(1, 2, 3, 4), timeout=600)
def case_half(liggghts, work, ranks):
    """A random half of the grains (type 2) breaks in the burst step."""
    burst(liggghts, work, "half", ranks)


@variants(*each_rank_count(1, 2, 3, 4), timeout=600)
def case_restart(liggghts, work, ranks):
    """in.burst writes burst.restart right after the burst step (replacement pending) and goes on;
    in.burst_restart continues from the file: the same events, fragment tags and final particles."""
    ranks = int(ranks)
    first = os.path.join(work, "uninterrupted")
    types = run_burst(liggghts, "in.burst", first, "half", ranks)
    log, final = check_run(first, "half", ranks, types)
    second = os.path.join(work, "continued")
    run_burst(liggghts, "in.burst_restart", second, "half", ranks, [os.path.join(first, "burst.restart")])
    log2, final2 = check_run(second, "half", ranks, types)
    check(log2 == log, "the continued run logs the same %d events (step, tags, positions, fragments)" % len(log))
    same = len(final) == len(final2) and all(
        a["id"] == b["id"] and max(abs(a[k] - b[k]) for k in "xyz") < 1e-9 for a, b in zip(final, final2))
    check(same, "the same %d particles at the end, positions within 1 nm" % len(final))


@variants(*each_rank_count(1, 2, 3, 4), timeout=600)
def case_inherit(liggghts, work, ranks):
    """A user's fix property/atom, scalar and vector, set from each grain's tag (in.burst_inherit):
    after the burst of the breakable half, each of the fragments holds its mother's values exactly
    (tag, 2 tag, -tag), and each unbroken grain its own, whatever the ranks."""
    ranks = int(ranks)
    types = run_burst(liggghts, "in.burst_inherit", work, "half", ranks)
    log, final = check_run(work, "half", ranks, types)
    mother, wrong = inheritance_errors(final, log)
    check(not wrong, "on %d rank(s) all %d fragments hold their mother's scalar and vector, the %d grains their "
          "own (%d wrong)" % (ranks, len(mother), len(final) - len(mother), len(wrong)))


def check_densities(work, log, final, ranks):
    """fragment_density scaled: each fragment's density is its mother's (2650) times (R/r)^2 and its mass
    that density times its volume; every true density is 2650; fix crush's mass at true density is
    2650 times the volume of its group (type 2), the largest density scale (R/r_small)^2."""
    rho, R = 2650.0, DIAMETER / 2
    fragments = {int(e["fragment_%d" % (f + 1)]) for e in log for f in range(FRAGMENTS)}
    wrong = []
    for r in final:
        scale = (R / r["radius"]) ** 2 if r["id"] in fragments else 1.0
        volume = math.pi / 6 * (2 * r["radius"]) ** 3
        if (abs(r["density"] - rho * scale) > 1e-12 * rho * scale
                or abs(r["mass"] - rho * scale * volume) > 1e-12 * rho * scale * volume
                or r["f_crush_true_density_crush"] != rho):
            wrong.append(r["id"])
    check(not wrong, "on %d rank(s) the %d fragments have density 2650 (R/r)^2 and mass to match, every particle "
          "true density 2650 (%d wrong)" % (ranks, len(fragments), len(wrong)))
    thermo = read_thermo(os.path.join(work, "log.liggghts"))[-1]
    volume = sum(math.pi / 6 * (2 * r["radius"]) ** 3 for r in final if r["type"] == 2)
    scaled = sum(r["mass"] for r in final if r["type"] == 2)
    check(abs(thermo["crush[8]"] - rho * volume) < 1e-12 * rho * volume,
          "the group's (type 2) mass at true density %.9g kg = 2650 x its volume; the scaled mass is %.4g "
          "times it" % (thermo["crush[8]"], scaled / thermo["crush[8]"]))
    small = 1 / 0.2300932 ** 2
    check(abs(thermo["crush[9]"] - small) < 1e-5 * small,
          "largest density scale %.6f = (R / r_small)^2 = %.6f" % (thermo["crush[9]"], small))


@variants(*each_rank_count(1, 2, 3, 4), timeout=600)
def case_density(liggghts, work, ranks):
    """fragment_density scaled (in.burst_density): the breakable half bursts; the fragments' densities,
    masses and true densities, and fix crush's outputs of them; the run continued from the restart
    written with the replacement pending gives the same."""
    ranks = int(ranks)
    first = os.path.join(work, "uninterrupted")
    types = run_burst(liggghts, "in.burst_density", first, "half", ranks)
    log, final = check_run(first, "half", ranks, types)
    check_densities(first, log, final, ranks)
    second = os.path.join(work, "continued")
    run_burst(liggghts, "in.burst_density_restart", second, "half", ranks, [os.path.join(first, "burst.restart")])
    log2, final2 = check_run(second, "half", ranks, types)
    check_densities(second, log2, final2, ranks)
    same = len(final) == len(final2) and all(
        a["id"] == b["id"] and a["density"] == b["density"] and max(abs(a[k] - b[k]) for k in "xyz") < 1e-9
        for a, b in zip(final, final2))
    check(same, "the continued run ends with the same %d particles and densities" % len(final))


SAND_SIEVES = [0.02e-3, 0.03e-3, 0.045e-3, 0.05e-3, 0.06e-3, 0.09e-3]  # between the fragments' sand sizes
# the small fragments' diameter over their mother's (layout fourteen: tangent to the six large ones)
SMALLEST_FRAGMENT = 1 - (2 - (2 - math.sqrt(2)) ** 2) / (2 * math.sqrt(2) - 2 * (2 - math.sqrt(2)) / math.sqrt(3))


def check_scales(work, log, final, types, ranks):
    """scale_atom (in.burst_scale): each fragment holds its mother's N (1 for type 1, 2 for type 2), and
    compute crush/gsd's passing and I_G are those of the sand sizes d / N_i, weighed by model volume,
    with the removed volume as fractal fines below the smallest fragment's sand size."""
    scale = {1: 1.0, 2: 2.0}
    mother = {int(e["fragment_%d" % (f + 1)]): int(e["tag"]) for e in log for f in range(FRAGMENTS)}
    wrong = [r["id"] for r in final if r["f_grain_scale"] != scale[types[mother[int(r["id"])]]]]
    check(not wrong, "on %d rank(s) each of the %d fragments holds its mother's N (%d wrong)"
          % (ranks, len(final), len(wrong)))
    row = read_thermo(os.path.join(work, "log.liggghts"))[-1]
    removed = row["crush[2]"]
    volumes = [(2 * r["radius"] / r["f_grain_scale"], math.pi / 6 * (2 * r["radius"]) ** 3) for r in final]
    total = sum(v for _, v in volumes) + removed
    d_f = SMALLEST_FRAGMENT * DIAMETER / 2.0  # the smallest fragment of an N = 2 grain
    for k, sieve in enumerate(SAND_SIEVES):
        expected = 100 * (sum(v for d, v in volumes if d < sieve) + removed * min(1.0, (sieve / d_f) ** 0.5)) / total
        check(abs(row["sand[%d]" % (k + 1)] - expected) < 1e-9,
              "passing %.3f mm %.9f%% = the sand sizes' %.9f%%" % (sieve * 1e3, row["sand[%d]" % (k + 1)], expected))
    d_max = DIAMETER  # the largest sand size at the start: an N = 1 grain
    area = d_max * sum(v for _, v in volumes) - sum(d * v for d, v in volumes) + removed * (d_f / 1.5 + d_max - d_f)
    i_g = area / total / (d_max / 1.5)
    check(abs(row["sand[7]"] - i_g) < 1e-9, "I_G %.9f against d_max = the largest grain's sand size: %.9f"
          % (row["sand[7]"], i_g))


@variants(*each_rank_count(1, 2, 3, 4), timeout=600)
def case_scale(liggghts, work, ranks):
    """A burst in a box of two scale factors (scale_atom, in.burst_scale): every grain breaks in the
    first step; books, tags and fragment tags as every burst; fragments keep their mother's N; the
    grading in sand sizes; continued from the restart written with the replacement pending, the same."""
    ranks = int(ranks)
    first = os.path.join(work, "uninterrupted")
    types = run_burst(liggghts, "in.burst_scale", first, "all", ranks)
    log, final = check_run(first, "all", ranks, types)
    check_scales(first, log, final, types, ranks)
    second = os.path.join(work, "continued")
    run_burst(liggghts, "in.burst_scale_restart", second, "all", ranks, [os.path.join(first, "burst.restart")])
    log2, final2 = check_run(second, "all", ranks, types)
    check_scales(second, log2, final2, types, ranks)
    same = len(final) == len(final2) and all(
        a["id"] == b["id"] and a["f_grain_scale"] == b["f_grain_scale"] and max(abs(a[k] - b[k]) for k in "xyz") < 1e-9
        for a, b in zip(final, final2))
    check(same, "the continued run ends with the same %d particles and N" % len(final))


LOW_LAYERS = 3  # in.burst_balance: the grains of the lattice's layers k = 0, 1, 2 (z < 2.5 spacings) break


def low_types():
    """in.burst_balance's types: 2 (breakable) in the lowest LOW_LAYERS layers along z, 1 elsewhere
    (write_data's tags run x fastest, z slowest)."""
    return {tag: 2 if (tag - 1) // CELLS ** 2 < LOW_LAYERS else 1 for tag in range(1, CELLS ** 3 + 1)}


def balance_moves(work):
    """fix balance's moves in the burst decks' out file, balance.txt."""
    return read_balance_moves(os.path.join(work, "balance.txt"))


def work_per_processor(final, cuts):
    """Each processor's work under the planes cuts ({axis: fractions of the box}; an axis without
    cuts is not divided): 1 + the particle's neighbours closer than r_i + r_j + skin, across the
    periodic faces too (as the fix weighs particles; skin 2e-5 m, in.burst_setup's neighbor)."""
    import numpy as np
    from scipy.spatial import cKDTree
    box = CELLS * SPACING
    xyz = np.array([[r[k] % box for k in "xyz"] for r in final])
    radius = np.array([r["radius"] for r in final])
    skin = 2e-5
    pairs = cKDTree(xyz, boxsize=box).query_pairs(2 * radius.max() + skin, output_type="ndarray")
    d = xyz[pairs[:, 0]] - xyz[pairs[:, 1]]
    d -= box * np.round(d / box)
    close = pairs[np.sum(d * d, axis=1) < (radius[pairs[:, 0]] + radius[pairs[:, 1]] + skin) ** 2]
    weight = np.ones(len(final)) + np.bincount(close.ravel(), minlength=len(final))
    index = np.zeros(len(final), dtype=int)
    for dim, axis in enumerate("xyz"):
        planes = cuts.get(axis, [])
        index = index * (len(planes) + 1) + np.searchsorted(planes, xyz[:, dim] / box, side="right")
    return np.bincount(index, weights=weight)


def periodic_drift(final, other):
    """The largest distance along an axis between the particles of two runs, row by row, taken across
    the periodic faces (a particle on a face may be wrapped to either side)."""
    box = CELLS * SPACING
    return max(max(abs((a[k] - b[k]) - box * round((a[k] - b[k]) / box)) for k in "xyz") for a, b in zip(final, other))


def imbalance(work_per_rank):
    return max(work_per_rank) * len(work_per_rank) / sum(work_per_rank)


@variants(*each_rank_count(1, 2, 3, 4, 8), timeout=600)
def case_balance(liggghts, work, ranks):
    """fix balance (doc/fix_balance.txt) every 20 steps, by work, in a burst that crowds the fragments
    into the lowest quarter of the box along z (in.burst_balance): the books, tags and events of every
    burst; on more than one rank the planes move, and the work each processor holds at the end under
    the last planes (the test's own count of neighbour pairs from the final particles) is within 15% of
    the mean, where equal slabs leave the fullest processor 1.4 times the mean or more; and the run ends
    as the one without fix balance, positions within 1 nm: the same physics, summed in another order."""
    ranks = int(ranks)
    types = low_types()
    balanced = os.path.join(work, "balanced")
    run_burst(liggghts, "in.burst_balance", balanced, "half", ranks)
    log, final = check_run(balanced, "half", ranks, types, straddle=False)
    reference = os.path.join(work, "reference")
    run_burst(liggghts, "in.burst_balance", reference, "half", ranks, variables={"balance_every": 0})
    log0, final0 = check_run(reference, "half", ranks, types, straddle=False)
    check(log == log0, "the same %d events (steps, tags, positions, fragment tags) as without fix balance" % len(log))
    drift = periodic_drift(final, final0)
    check([a["id"] for a in final] == [b["id"] for b in final0] and drift < 1e-9,
          "the same %d particles at the end as without fix balance, positions within 1 nm (%.2g m)"
          % (len(final), drift))
    rows = read_thermo(os.path.join(balanced, "log.liggghts"))
    thermo = rows[-1]
    check(thermo["bal[4]"] - rows[-11]["bal[4]"] == 5, "checked at steps 20, 40, 60, 80 and 100 (%d checks from step "
          "%d to 100)" % (thermo["bal[4]"] - rows[-11]["bal[4]"], rows[-11]["Step"]))
    moves = balance_moves(balanced)
    if ranks == 1:
        check(not moves and thermo["bal"] == 1.0, "one rank: nothing to move, imbalance 1")
        return
    check(moves and moves[0]["before"] > 1.4, "the first move at step %s, from an imbalance of %s (the burst's "
          "crowding)" % (moves[0]["step"] if moves else "-", moves[0]["before"] if moves else "-"))
    last = moves[-1]["cuts"]
    equal = {axis: [k / (len(c) + 1.0) for k in range(1, len(c) + 1)] for axis, c in last.items()}
    held, uniform = imbalance(work_per_processor(final, last)), imbalance(work_per_processor(final, equal))
    check(held <= 1.15 and uniform >= 1.4,
          "%d ranks: the fullest processor's work at the end %.3f of the mean under the last planes %s, %.3f "
          "under equal slabs (the fix's own reading after its last move: %.3f)" % (ranks, held, last, uniform, moves[-1]["after"]))


@variants(*each_rank_count(2, 3, 4), timeout=600)
def case_balance_restart(liggghts, work, ranks):
    """in.burst_balance writes burst.restart after the burst step (replacement pending) and goes on;
    in.burst_balance_restart reads it, with equal planes again, and fix balance moves them from there:
    the same events, fragment tags and books, and the same particles at the end to 1 nm."""
    ranks = int(ranks)
    types = low_types()
    first = os.path.join(work, "uninterrupted")
    run_burst(liggghts, "in.burst_balance", first, "half", ranks)
    log, final = check_run(first, "half", ranks, types, straddle=False)
    second = os.path.join(work, "continued")
    run_burst(liggghts, "in.burst_balance_restart", second, "half", ranks, [os.path.join(first, "burst.restart")])
    log2, final2 = check_run(second, "half", ranks, types, straddle=False)
    check(log2 == log, "the continued run logs the same %d events" % len(log))
    check(balance_moves(second), "fix balance moved the planes in the continued run")
    drift = periodic_drift(final, final2)
    check([a["id"] for a in final] == [b["id"] for b in final2] and drift < 1e-9,
          "the same %d particles at the end, positions within 1 nm (%.2g m)" % (len(final), drift))


# in.burst_driven: the burst's breakable half driven by another fix (doc/fix_crush.txt, the inheritance
# table). The lattice is at rest and balanced until the burst (step 1, replaced at step 2), so each
# mother's place at her event is her lattice site; a fragment's offset from it is R - r long.
DRIVEN_STEPS, DT, MOVE_VELOCITY, SPRING_K = 100, 1e-8, 1.0, 1e4


def fragments_of(log, final):
    """[(fragment row, mother's event row)] of every fragment in the final dump."""
    events = {int(e["fragment_%d" % (f + 1)]): e for e in log for f in range(FRAGMENTS)}
    return [(r, events[int(r["id"])]) for r in final if int(r["id"]) in events]


def offset_errors(pairs, shift):
    """Per fragment: | |x_f - shift - x_mother| - (R - r_f) | (m), x_f unwrapped and the difference taken
    to the nearest periodic image: 0 when the fragment sits where it was born, moved by shift (m)."""
    box = CELLS * SPACING
    errors = []
    for r, e in pairs:
        d = [r[u] - s - float(e[k]) for u, s, k in zip(("xu", "yu", "zu"), shift, "xyz")]
        d = [c - box * round(c / box) for c in d]
        errors.append(abs(math.sqrt(sum(c * c for c in d)) - (float(e["diameter"]) / 2 - r["radius"])))
    return errors


@variants(*[(driver, ranks) for driver in ("move", "freeze", "spring") for ranks in (1, 2, 3, 4)], timeout=600)
def case_driven(liggghts, work, driver, ranks):
    """The breakable half moved by fix move linear, frozen by fix freeze or tethered by fix spring/self
    bursts in one step, on 1 - 4 ranks, with the burst's books; then each fragment follows its driver
    from its own place: moved by exactly v (T - 1) dt from its offset (fix move's reference of a new
    atom); frozen where it was born, its compute displace/atom displacement 0 (its original position
    the mother's shifted by its offset, not hers: that would read R - r); tethered to its mother's
    anchor shifted by its offset: the springs' energy right after the replacement is that of the
    grains' rest, not 0.5 K sum (R - r)^2 (copied anchors), and after 100 steps every fragment is
    still within 5% of R of its place (pulled to the mother's anchor it would not be)."""
    ranks = int(ranks)
    types = run_burst(liggghts, "in.burst_driven", work, "half", ranks, variables={"driver": driver})
    log, final = check_run(work, "half", ranks, types)
    pairs = fragments_of(log, final)
    R = DIAMETER / 2
    if driver == "move":
        errors = offset_errors(pairs, (MOVE_VELOCITY * (DRIVEN_STEPS - 1) * DT, 0.0, 0.0))
        check(max(errors) < 1e-12, "%d moved fragments each at its offset from its mother's path, moved %.3g m "
              "(largest error %.2g m)" % (len(errors), MOVE_VELOCITY * (DRIVEN_STEPS - 1) * DT, max(errors)))
    elif driver == "freeze":
        errors = offset_errors(pairs, (0.0, 0.0, 0.0))
        check(max(errors) < 1e-12, "%d frozen fragments where they were born (largest error %.2g m)"
              % (len(errors), max(errors)))
        displaced = max(r["c_disp[4]"] for r, e in pairs)
        check(displaced < 1e-12, "their displacement from their original positions 0 (largest %.2g m)" % displaced)
    else:
        thermo = {row["Step"]: row for row in read_thermo(os.path.join(work, "log.liggghts"))}
        copied = 0.5 * SPRING_K * sum((float(e["diameter"]) / 2 - r["radius"]) ** 2 for r, e in pairs)
        check(thermo[2]["drive"] < 1e-12 * copied, "the springs' energy after the replacement %.3g J (copied "
              "anchors: %.3g J)" % (thermo[2]["drive"], copied))
        errors = offset_errors(pairs, (0.0, 0.0, 0.0))
        check(max(errors) < 0.05 * R, "after %d steps every fragment within %.2g of R of its place"
              % (DRIVEN_STEPS, max(errors) / R))


REFUSALS = {"move_variable": "is moved by fix move (style variable), which cannot take new atoms",
            "rigid": "belongs to a rigid body of fix rigid"}


@variants(*[(driver, ranks) for driver in sorted(REFUSALS) for ranks in (1, 2)])
def case_driven_refused(liggghts, work, driver, ranks):
    """A grain of fix crush's group moved by fix move variable (LIGGGHTS cannot give it fragments) or
    in a fix rigid body: the run stops at its start, before its first step, naming a particle of type 2."""
    if os.path.isdir(work):
        shutil.rmtree(work)
    os.makedirs(work)
    types = write_data(os.path.join(work, "burst.data"))
    out = run_deck(liggghts, os.path.join(BURST, "in.burst_driven"), work,
                   {"driver": driver, "log": "events.csv", "out": "final.dump"}, ranks=int(ranks),
                   expect_fail=True, keep=True)
    named = re.search(r"particle (\d+) " + re.escape(REFUSALS[driver]), out)
    check(named is not None and types[int(named.group(1))] == 2 and "Step" not in out,
          "on %s rank(s) the run stops before its first step: 'particle %s %s'"
          % (ranks, named.group(1) if named else "?", REFUSALS[driver]))

@variants(*each_rank_count(1, 2, 3, 4))
def case_coincide(liggghts, work, ranks):
    """Two fragments of one event put on one point before they first interact (in.burst_coincide):
    the run stops at the next setup with fix crush's error naming both and their grain, not with the
    pair style's "no contact normal exists"."""
    if os.path.isdir(work):
        shutil.rmtree(work)
    os.makedirs(work)
    write_data(os.path.join(work, "burst.data"))
    first = CELLS ** 3 + 1
    out = run_deck(liggghts, os.path.join(BURST, "in.burst_coincide"), work,
                   {"log": "events.csv", "first": first}, ranks=int(ranks), expect_fail=True, keep=True)
    mother = read_events(os.path.join(work, "events.csv"))[0]["tag"]
    said = re.search(r"fragments %d and %d of grain %s \(replaced at step 2\) lie (\S+) m apart at step 2, less "
                     r"than the smaller one's radius" % (first, first + 1, mother), out)
    check(said is not None and float(said.group(1)) < 1e-12 and "no contact normal" not in out,
          "on %s rank(s) the run stops naming fragments %d and %d of grain %s, %s m apart"
          % (ranks, first, first + 1, mother, said.group(1) if said else "?"))

if __name__ == "__main__":
    test_main(globals(), sys.argv[1:])
