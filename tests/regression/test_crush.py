#!/usr/bin/env python3
"""Deck tests of fix crush and compute crush/gsd, run by the built liggghts.

  python3 test_crush.py LIGGGHTS WORKDIR CASE [RANKS]
"""
import math
import os
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liggghts_run import check, each_rank_count, edited_deck, printed, read_dump, read_thermo, run_deck, variants  # noqa: E402
from liggghts_run import read_events  # noqa: E402
from liggghts_run import main as test_main  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CRUSH = os.path.join(os.path.dirname(os.path.abspath(__file__)), "crush")
SINGLE = os.path.join(ROOT, "examples", "single_grain", "in.single_grain")
N0 = 512  # particles of the compression decks


def case_single_grain(liggghts, work):
    """A grain pushed onto a plane breaks when the wall force reaches the analytic F_lim, into the
    14 fragments of the layout; counts and volume books balance."""
    rate, dt = 8.0, 1e-8
    out = run_deck(liggghts, SINGLE, work)
    f_lim = printed(out, "F_LIM")
    # by hand: E' = 1/((1-0.09)/7.8e9 + (1-0.0841)/210e9), F_lim = (1e8 pi)^3 (3e-4/(4 E'))^2
    e_eff = 1.0 / ((1 - 0.09) / 7.8e9 + (1 - 0.29 ** 2) / 210e9)
    check(abs(f_lim / ((1e8 * math.pi) ** 3 * (3e-4 / (4 * e_eff)) ** 2) - 1) < 1e-12, "F_lim = %.6g N" % f_lim)
    events = read_events(os.path.join(work, "crush_events.csv"))
    check(len(events) == 1, "exactly one crushing event")
    step = int(events[0]["step"])
    applied = rate * step * dt
    check(abs(applied / f_lim - 1) < 0.01, "breaks at applied force %.6g N = %.4f F_lim" % (applied, applied / f_lim))
    check(float(events[0]["force_ratio"]) >= 1.0, "logged F_n/F_lim %.6f >= 1" % float(events[0]["force_ratio"]))
    # fragments right after their creation (fixed orientation): the 14-ball layout around the mother
    snaps = [s for s in read_dump(os.path.join(work, "fragments.dump")) if len(s[2]) == 14]
    check(snaps and snaps[0][0] == step + 1, "14 particles one step after the event")
    mother = [float(events[0][k]) for k in ("x", "y", "z")]
    R = 1e-4
    a, r1 = 2 - math.sqrt(2), math.sqrt(2) - 1
    s = 1 + r1
    b = (s * s - a * a) / (2 * s - 2 * a / math.sqrt(3))
    expected = [(tuple(a * R * (k == axis) * sign for k in range(3)), r1 * R)
                for axis in range(3) for sign in (1, -1)]
    expected += [((sx * b * R / math.sqrt(3), sy * b * R / math.sqrt(3), sz * b * R / math.sqrt(3)), (1 - b) * R)
                 for sx in (1, -1) for sy in (1, -1) for sz in (1, -1)]
    rows = snaps[0][2]
    worst_r = max(abs(row["radius"] - e[1]) / R for row, e in zip(rows, expected))
    check(worst_r < 1e-12, "fragment radii match the layout (%.1e R)" % worst_r)
    worst_x = max(math.dist([row[k] - m for k, m in zip("xyz", mother)], e[0]) / R for row, e in zip(rows, expected))
    check(worst_x < 1e-4, "fragment centres match the layout to %.1e R (the mother moved for one step)" % worst_x)
    check([int(row["id"]) for row in rows] == list(range(2, 16)), "fragments carry tags 2..15")
    v_mother = 4 / 3 * math.pi * R ** 3
    v_frag = sum(4 / 3 * math.pi * row["radius"] ** 3 for row in rows)
    thermo = read_thermo(os.path.join(work, "log.liggghts"))
    removed = thermo[-1]["crush[2]"]
    check(abs(v_frag + removed - v_mother) / v_mother < 1e-12, "fragments + removed volume = mother volume")
    check(abs(v_frag / v_mother - 0.523861) < 1e-6, "fragments keep 52.386% of the volume")
    # compute crush/gsd: 8 small fragments (d = 0.046 mm) and the removed volume (fractal, D = 2.5,
    # below the smallest fragment) pass 0.05 mm; 0.02 mm passes (0.02/0.046)^0.5 of the fines only.
    small = 2 * (1 - b) * R
    fines = removed / v_mother
    small_share = 8 * (1 - b) ** 3
    check(abs(printed(out, "PASSING_0.05MM") - 100 * (small_share + fines)) < 1e-9,
          "GSD at 0.05 mm: %.6f%% (small fragments + fines)" % printed(out, "PASSING_0.05MM"))
    check(abs(printed(out, "PASSING_0.02MM") - 100 * fines * math.sqrt(0.02e-3 / small)) < 1e-9,
          "GSD at 0.02 mm: %.6f%% (fractal fines only)" % printed(out, "PASSING_0.02MM"))
    check(abs(printed(out, "PASSING_0.1MM") - 100.0) < 1e-9, "GSD at 0.1 mm: 100%")


LAWS = ("hertz", "hertz_stiffness", "hooke", "hooke_stiffness", "hertz_scaled")


@variants(*[(law, wall) for law in LAWS for wall in ("primitive", "mesh")])
def case_single_grain_law(liggghts, work, law, wall):
    """The single grain on a primitive plane or a mesh plane, with each contact law: F_lim depends on
    E' and r' alone (eq. 5), so every law breaks the grain when the quasi-static wall force (the
    applied one) reaches the analytic F_lim, through LIGGGHTS' pair loop and wall contact (patches/0009)."""
    rate, dt = 8.0, 1e-8
    out = run_deck(liggghts, SINGLE, work, {"law": law, "wall": wall})
    e_eff = 1.0 / ((1 - 0.09) / 7.8e9 + (1 - 0.29 ** 2) / 210e9)
    f_lim = (1e8 * math.pi) ** 3 * (3e-4 / (4 * e_eff)) ** 2
    check(abs(printed(out, "F_LIM") / f_lim - 1) < 1e-12, "F_lim = %.6g N" % f_lim)
    events = read_events(os.path.join(work, "crush_events.csv"))
    check(len(events) == 1, "%s on a %s plane: exactly one crushing event" % (law, wall))
    applied = rate * int(events[0]["step"]) * dt
    check(abs(applied / f_lim - 1) < 0.01, "%s on a %s plane: breaks at applied force %.6g N = %.4f F_lim"
          % (law, wall, applied, applied / f_lim))
    check(1.0 <= float(events[0]["force_ratio"]) < 1.01, "logged F_n/F_lim %.6f" % float(events[0]["force_ratio"]))
    check(read_thermo(os.path.join(work, "log.liggghts"))[-1]["Atoms"] == 14, "the 14 fragments replace the grain")


def case_single_grain_every(liggghts, work):
    """fix crush 'every 500' on the single grain: the contact forces are recorded on check steps only,
    so the grain breaks at the first multiple of 500 at or after the step where 'every 1' breaks it,
    the logged F_n/F_lim is that of the force applied by then (analytic F_lim), and the F_n/F_lim
    output between checks is that of the last check."""
    rate, dt, every = 8.0, 1e-8, 500
    steps, ratios = {}, {}
    for k in (1, every):
        out = run_deck(liggghts, SINGLE, os.path.join(work, "every%d" % k), {"every": k})
        events = read_events(os.path.join(work, "every%d" % k, "crush_events.csv"))
        check(len(events) == 1, "every %d: one crushing event" % k)
        steps[k], ratios[k] = int(events[0]["step"]), float(events[0]["force_ratio"])
        f_lim = printed(out, "F_LIM")
        # the last thermo row of the first run (step n_before, not a multiple of 500)
        first = [r for r in read_thermo(os.path.join(work, "every%d" % k, "log.liggghts")) if r["Atoms"] == 1][-1]
        last_check = first["Step"] // k * k
        check(first["Step"] % every != 0 and abs(first["crush[3]"] / (rate * last_check * dt / f_lim) - 1) < 2e-3,
              "every %d: F_n/F_lim %.5f at step %d = applied force / F_lim at step %d, the last check"
              % (k, first["crush[3]"], first["Step"], last_check))
    expected = -(-steps[1] // every) * every
    check(steps[every] == expected, "every %d breaks at step %d, the first check at or after step %d (every 1)"
          % (every, steps[every], steps[1]))
    applied = rate * steps[every] * dt / f_lim
    check(abs(ratios[every] / applied - 1) < 0.01 and ratios[every] > ratios[1],
          "logged F_n/F_lim %.5f at the check = applied force / F_lim %.5f (every 1: %.5f)"
          % (ratios[every], applied, ratios[1]))


def case_neighbor_advice(liggghts, work):
    """A deck on 'neighbor ... bin' whose radii will spread past 4:1 (grains of 0.1 mm radius, the
    fourteen fragments' smallest 1 - b = 0.2301 of their mother's radius at dmin 0.02 mm: 1e-4 /
    (0.2301 x 1e-5) = 43:1) is told once, over two runs, that style multi finds the same pairs; not
    on style multi, and not where nothing can break (dmin 1 mm: the grains alone, 1:1)."""
    deck = os.path.join(CRUSH, "in.neighbor_advice")
    advice = "'neighbor SKIN multi' finds the same pairs"
    a, r1 = 2 - math.sqrt(2), math.sqrt(2) - 1
    s = 1 + r1
    b = (s * s - a * a) / (2 * s - 2 * a / math.sqrt(3))  # the layout's corner fragments: radius (1 - b) R
    for style, dmin, times in (("bin", "2e-5", 1), ("multi", "2e-5", 0), ("bin", "1e-3", 0)):
        out = run_deck(liggghts, deck, os.path.join(work, "%s_%s" % (style, dmin)), {"style": style, "dmin": dmin})
        lines = [l for l in out.splitlines() if advice in l]
        check(len(lines) == times, "style %s, dmin %s: the advice %d time(s) (%d)" % (style, dmin, times, len(lines)))
        if times:
            smallest = (1 - b) * 0.5 * float(dmin)
            check("(%.0f:1)" % (1e-4 / smallest) in lines[0] and "from 0.0001 m to %g m" % smallest in lines[0],
                  "the spread it names, 0.1 mm to the smallest fragment at dmin (%.0f:1): %s" % (1e-4 / smallest, lines[0]))


@variants(ranks=4)
def case_single_grain_ranks(liggghts, work):
    """The single-grain case on 1, 2 and 4 ranks (the grain sits on the processor boundary): the
    same tags break at the same step into the same fragment tags."""
    logs = {}
    for ranks in (1, 2, 4):
        run_deck(liggghts, SINGLE, os.path.join(work, "np%d" % ranks), ranks=ranks)
        logs[ranks] = open(os.path.join(work, "np%d" % ranks, "crush_events.csv")).read().splitlines()
    check(len(logs[1]) == 2, "one event")
    for ranks in (2, 4):
        a = [line.split(",") for line in logs[1]]
        b = [line.split(",") for line in logs[ranks]]
        same = all(x[:2] + x[3:4] + x[8:] == y[:2] + y[3:4] + y[8:] for x, y in zip(a, b))
        check(same, "%d ranks: same step, tag, generation and fragment tags as 1 rank" % ranks)


def case_two_scales(liggghts, work):
    """Two grains with their own N (scale_atom: d 0.2 mm at N 1, d 0.4 mm at N 4) on a plane: each
    strength is eq. 10 with its own N, each grain breaks at the first step its wall force reaches its
    own analytic F_lim (F_n / F_lim read back against the wall force to 1e-6), its fragments keep its
    N, and the grading downscales each particle by its own N."""
    out = run_deck(liggghts, os.path.join(CRUSH, "in.two_scales"), work)
    e_eff = 1.0 / ((1 - 0.09) / 7.8e9 + (1 - 0.29 ** 2) / 210e9)
    radius = {1: 1e-4, 2: 2e-4}
    scale = {1: 1.0, 2: 4.0}
    sigma = {t: 1e8 * (2 * radius[t] / (scale[t] * 2e-4)) ** -0.3 for t in (1, 2)}
    f_lim = {t: (sigma[t] * math.pi) ** 3 * (3 * radius[t] / (4 * e_eff)) ** 2 for t in (1, 2)}
    check(all(abs(printed(out, "F_LIM%d" % t) / f_lim[t] - 1) < 1e-12 for t in (1, 2)),
          "F_lim %.6g N (N = 1) and %.6g N (N = 4), %.3f times: the N of grain 2 alone makes it stronger"
          % (f_lim[1], f_lim[2], f_lim[2] / f_lim[1]))
    drawn = {int(r["id"]): r for r in read_dump(os.path.join(work, "strengths.dump"))[0][2]}
    check(all(abs(drawn[t]["f_crush[1]"] / sigma[t] - 1) < 1e-12 and drawn[t]["f_grain_scale"] == scale[t]
              for t in (1, 2)), "each grain's sigma_lim is eq. 10 with its own N: %.6g and %.6g Pa"
          % (drawn[1]["f_crush[1]"], drawn[2]["f_crush[1]"]))
    events = {int(e["tag"]): e for e in read_events(os.path.join(work, "crush_events.csv"))}
    check(sorted(events) == [1, 2], "both grains break, once each")
    window = {snap[0]: {int(r["id"]): r for r in snap[2]} for snap in read_dump(os.path.join(work, "window.dump"))}
    for t in (1, 2):
        step = int(events[t]["step"])
        at, before = window[step][t], window[step - 1][t]
        check(before["f_crush[3]"] < 1.0 <= at["f_crush[3]"],
              "grain %d breaks at step %d, the first at which F_n / F_lim reaches 1 (%.8f, then %.8f)"
              % (t, step, before["f_crush[3]"], at["f_crush[3]"]))
        for row in (before, at):
            wall = row["f_force_floor[3]"]
            check(abs(row["f_crush[3]"] * f_lim[t] / wall - 1) < 1e-6,
                  "grain %d: F_n / F_lim x its analytic F_lim = its wall force %.9g N (%.1e)"
                  % (t, wall, row["f_crush[3]"] * f_lim[t] / wall - 1))
    final = read_dump(os.path.join(work, "final.dump"))[-1][2]
    check(len(final) == 28 and all(r["f_crush[2]"] == 1 for r in final), "28 first-generation fragments")
    mother = {int(events[t]["fragment_%d" % (f + 1)]): t for t in (1, 2) for f in range(14)}
    check(all(r["f_grain_scale"] == scale[mother[int(r["id"])]] for r in final),
          "each fragment keeps its mother's N (1 or 4)")
    # the grading in sand sizes: d / N_i, by model volume; the removed volume as fines (D = 2.5) below the
    # smallest fragment's sand size, 0.2300932 x min(0.2 / 1, 0.4 / 4) mm
    sieves = [0.02e-3, 0.05e-3, 0.1e-3, 0.15e-3, 0.25e-3]
    thermo = read_thermo(os.path.join(work, "log.liggghts"))[-1]
    removed = thermo["crush[2]"]
    volume = sum(math.pi / 6 * (2 * r["radius"]) ** 3 for r in final)
    a, s1 = 2 - math.sqrt(2), math.sqrt(2)
    d_f = (1 - (s1 * s1 - a * a) / (2 * s1 - 2 * a / math.sqrt(3))) * 1e-4  # the small fragment of grain 2, / N
    for k, s in enumerate(sieves):
        passing = sum(math.pi / 6 * (2 * r["radius"]) ** 3 for r in final if 2 * r["radius"] / r["f_grain_scale"] < s)
        fines = removed * min(1.0, (s / d_f) ** 0.5)
        expected = 100 * (passing + fines) / (volume + removed)
        check(abs(thermo["gsd[%d]" % (k + 1)] - expected) < 1e-6,
              "passing %.2f mm: %.6f%% (sand sizes d / N_i)" % (s * 1e3, thermo["gsd[%d]" % (k + 1)]))


def compression(liggghts, work, ranks):
    run_deck(liggghts, os.path.join(CRUSH, "in.compression"), work, {"log": "events.csv", "out": "final.dump"},
             ranks=ranks)
    return read_thermo(os.path.join(work, "log.liggghts"))


@variants(*each_rank_count(1, 2, 4))
def case_compression(liggghts, work, ranks=1):
    """Compression with crushing on RANKS ranks: the invariants hold at every thermo step; strengths
    are a function of the tag alone (identical to the 1-rank run)."""
    ranks = int(ranks)
    thermo = compression(liggghts, os.path.join(work, "run"), ranks)
    check(len(thermo) > 50, "%d thermo rows" % len(thermo))
    v0 = thermo[0]["gsd"]
    events = thermo[-1]["crush[1]"]
    check(events >= 20, "%d crushing events" % events)
    for row in thermo:
        if row["Atoms"] != N0 + 13 * row["crush[1]"]:
            raise AssertionError("step %d: %d particles, %d events" % (row["Step"], row["Atoms"], row["crush[1]"]))
        if abs(row["gsd"] - v0) > 1e-12 * v0:
            raise AssertionError("step %d: solid volume %.17g, initially %.17g" % (row["Step"], row["gsd"], v0))
    check(True, "every thermo step: particles = 512 + 13 x events, particle + removed volume = initial (1e-12)")
    final = read_dump(os.path.join(work, "run", "final.dump"))[-1][2]
    tags = [int(r["id"]) for r in final]
    check(len(tags) == len(set(tags)) == thermo[-1]["Atoms"], "%d unique tags, none lost" % len(tags))
    volume = sum(4 / 3 * math.pi * r["radius"] ** 3 for r in final)
    check(abs(volume + thermo[-1]["crush[2]"] - v0) / v0 < 1e-12, "final books balance")
    events_log = read_events(os.path.join(work, "run", "events.csv"))
    check(len(events_log) == events, "the event log has every event")
    box = 8 * 0.00021
    crossing = [e for e in events_log if min(float(e[k]) % (box * 0.88) for k in "xyz") < 0.0001]
    print("note: %d events within a radius of a periodic face" % len(crossing))
    initial = {int(r["id"]): r for r in read_dump(os.path.join(work, "run", "strengths0.dump"))[0][2]}
    check(len(initial) == N0 and all(r["f_crush[1]"] > 0.0 for r in initial.values()),
          "every strength drawn before the first step (a dump at step 0 shows them)")
    if ranks > 1:
        reference = os.path.join(work, "np1")
        compression(liggghts, reference, 1)
        # create_atoms numbers the lattice per processor, so a tag may name a grain of the other size
        # on 1 rank; a strength is a function of tag and size: identical where both agree.
        ref_initial = {int(r["id"]): r for r in read_dump(os.path.join(reference, "strengths0.dump"))[0][2]}
        same_size = [t for t in initial if initial[t]["radius"] == ref_initial[t]["radius"]]
        check(len(same_size) > N0 // 3 and all(initial[t]["f_crush[1]"] == ref_initial[t]["f_crush[1]"]
                                               for t in same_size),
              "initial strengths of the %d tags with the same size as on 1 rank identical" % len(same_size))
        # Summation order differs with the decomposition, so which grain reaches its limit first may
        # differ late in the run: stated tolerance, 5% of the events plus one.
        reference_events = read_thermo(os.path.join(reference, "log.liggghts"))[-1]["crush[1]"]
        check(abs(events - reference_events) <= 0.05 * reference_events + 1,
              "%d events against %d on 1 rank (within 5%% + 1)" % (events, reference_events))
        ref_final = {int(r["id"]): r for r in read_dump(os.path.join(reference, "final.dump"))[-1][2]}
        # Where the runs' histories part (summation order), a tag may name fragments of different
        # mothers; for the same tag and size the strength must be the same.
        common = [r for r in final if int(r["id"]) in ref_final
                  and r["radius"] == ref_final[int(r["id"])]["radius"]]
        same = all(r["f_crush[1]"] == ref_final[int(r["id"])]["f_crush[1]"] for r in common)
        check(len(common) > N0 and same, "strengths of the %d particles with the same tag and size in both "
                                         "runs are identical" % len(common))


@variants(*each_rank_count(1, 2))
def case_region(liggghts, work, ranks):
    """fix crush ... region lower: the compression breaks grains below z = 3.6 lattice spacings only
    (between two grain layers all run long: the box shrinks about its centre, 4 spacings), where
    without the region it breaks them on both sides; the books hold as always."""
    ranks = int(ranks)
    middle = 3.6 * 0.00021
    full = compression(liggghts, os.path.join(work, "everywhere"), ranks)
    everywhere = read_events(os.path.join(work, "everywhere", "events.csv"))
    check(any(float(e["z"]) > middle for e in everywhere) and any(float(e["z"]) < middle for e in everywhere),
          "without a region, grains break on both sides (%d events)" % len(everywhere))
    deck = edited_deck(os.path.join(CRUSH, "in.compression"), os.path.join(work, "deck"),
                       [("fix             crush all crush", "region          lower block INF INF INF INF INF %.17g units box\n"
                         "fix             crush all crush" % middle),
                        ("dmin 0.0001 log ${log}", "dmin 0.0001 log ${log} region lower")],
                       includes=("in.crush_fixes",))
    run_deck(liggghts, deck, os.path.join(work, "lower"), {"log": "events.csv", "out": "final.dump"}, ranks=ranks)
    thermo = read_thermo(os.path.join(work, "lower", "log.liggghts"))
    lower = read_events(os.path.join(work, "lower", "events.csv"))
    check(len(lower) > 0 and all(float(e["z"]) < middle for e in lower),
          "with region lower: %d events, every one below z = %.5g m" % (len(lower), middle))
    check(len(lower) < len(everywhere), "fewer than without the region (%d)" % full[-1]["crush[1]"])
    check(all(row["Atoms"] == N0 + 13 * row["crush[1]"] for row in thermo), "particles = 512 + 13 x events")


def case_tip_example(liggghts, work):
    """examples/tip: with its region following the tip, every event lies within 1.5 tip radii of
    the tip's axis; without the region (reach 0) the same push breaks more grains, some far away;
    with 'every adaptive' the same events as checking every step."""
    tip = os.path.join(ROOT, "examples", "tip", "in.tip")
    axis, reach = (0.00105, 0.00105), 1.5 * 0.0004

    def distances(folder, variables):
        run_deck(liggghts, tip, os.path.join(work, folder), variables)
        events = read_events(os.path.join(work, folder, "tip_events.csv"))
        return [math.hypot(float(e["x"]) - axis[0], float(e["y"]) - axis[1]) for e in events]
    near, everywhere = distances("region", {}), distances("everywhere", {"reach": 0})
    check(len(near) >= 10 and max(near) <= reach,
          "region: %d events, all within %.2g mm of the tip's axis" % (len(near), reach * 1e3))
    check(len(everywhere) > len(near) and max(everywhere) > reach,
          "no region: %d events, up to %.2g mm away" % (len(everywhere), max(everywhere) * 1e3))
    # 'every adaptive' with the moving region and the tip moved by fix move: the same events.
    run_deck(liggghts, tip, os.path.join(work, "adaptive"), {"every": "adaptive"})
    with open(os.path.join(work, "region", "tip_events.csv")) as a, \
            open(os.path.join(work, "adaptive", "tip_events.csv")) as b:
        check(a.read() == b.read(), "every adaptive: the same %d events at the same steps" % len(near))


def case_restart(liggghts, work):
    """write_restart in the middle of crushing, read_restart, continue: the same strengths, counters,
    removed volume and event numbering as the uninterrupted run (here bit for bit)."""
    run_deck(liggghts, os.path.join(CRUSH, "in.restart_first"), work, {"log": "first.csv", "out": "first.dump"})
    mid = read_thermo(os.path.join(work, "log.liggghts"))
    at3000 = [r for r in mid if r["Step"] == 3000][0]
    check(at3000["crush[1]"] > 0, "crushing under way at the restart (%d events)" % at3000["crush[1]"])
    second = os.path.join(work, "second")
    os.makedirs(second, exist_ok=True)
    for name in os.listdir(CRUSH):
        shutil.copy(os.path.join(CRUSH, name), second)
    shutil.copy(os.path.join(work, "mid.restart"), second)
    out = run_deck(liggghts, os.path.join(second, "in.restart_second"), os.path.join(work, "run2"),
                   {"log": "second.csv", "out": "second.dump"})
    resumed = read_thermo(os.path.join(work, "run2", "log.liggghts"))
    check(resumed[0]["crush[1]"] == at3000["crush[1]"] and resumed[0]["crush[2]"] == at3000["crush[2]"],
          "counters and removed volume restored")
    first_events = [e for e in read_events(os.path.join(work, "first.csv")) if int(e["step"]) >= 3000]
    second_events = read_events(os.path.join(work, "run2", "second.csv"))
    check(len(second_events) > 0 and first_events == second_events,
          "the %d events after the restart are the same, with the same fragment tags" % len(second_events))
    a = open(os.path.join(work, "first.dump")).read()
    b = open(os.path.join(work, "run2", "second.dump")).read()
    check(a == b, "final particles (tags, positions, strengths, generations) identical")
    del out


def case_bad_input(liggghts, work):
    """Errors name the keyword and the expected value."""
    crush_line = ("fix             crush all crush sigma_lim0 2e8 cv 1 weibull_m 10 d0 2e-3 seed 32452843 "
                  "scale 1 &\n                dmin 0.0001 log ${log}\n")
    cases = [
        ("missing keyword", crush_line, crush_line.replace("weibull_m 10 ", ""), "'weibull_m' is required"),
        ("negative cv", crush_line, crush_line.replace("cv 1", "cv -1"), "'cv' expects"),
        ("zero scale", crush_line, crush_line.replace("scale 1", "scale 0"), "'scale' expects"),
        ("unknown option", crush_line, crush_line.replace("scale 1", "scale 1 colour red"), "unknown keyword 'colour'"),
        ("newton on", "newton          off\n", "newton          on\n", "newton pair off"),
        ("time step", "timestep        1e-8\n", "timestep        5e-8\n", "exceeds"),
        ("gsd without fix", "compute         gsd all crush/gsd crush", "compute         gsd all crush/gsd nofix",
         "'nofix' is not the ID of a fix crush"),
        ("infinite strength", "sigma_lim0 2e8", "sigma_lim0 inf", "Fix crush (id crush): keyword 'sigma_lim0' expects"),
        ("overflowing dmin", "dmin 0.0001", "dmin 1e999", "Fix crush (id crush): keyword 'dmin' expects"),
        ("nan damping", "damp/local alpha 0.1", "damp/local alpha nan", "Fix damp/local (id damp): keyword 'alpha' expects"),
        ("nan sieve", "sieves 0.00005", "sieves nan", "Compute crush/gsd (id gsd): keyword 'sieves' expects"),
        ("missing region", "dmin 0.0001 log ${log}", "dmin 0.0001 log ${log} region nowhere",
         "Fix crush (id crush): keyword 'region': no region 'nowhere'"),
    ]
    # any granular contact model feeds the check (patches/0009), but not every one has what a keyword reads
    pair = "pair_style      gran model hertz/scaled tangential mindlin/scaled"
    model_cases = [
        ("adaptive with hooke", [(pair, "fix             m5 all property/global characteristicVelocity scalar 0.1\n"
                                        "pair_style      gran model hooke tangential history"),
                                 ("dmin 0.0001 log", "dmin 0.0001 every adaptive log")],
         "'every adaptive' bounds the growth of Hertzian contact forces (eq. 8, model hertz/scaled), but "
         "pair_style gran uses model hooke"),
        ("plastic model without force total", [(pair, "fix             m5 all property/global characteristicVelocity scalar 0.1\n"
                                                      "fix             m6 all property/global coefficientMaxElasticStiffness peratomtypepair 2 2 2 2 2\n"
                                                      "fix             m7 all property/global coefficientAdhesionStiffness peratomtypepair 2 0.2 0.2 0.2 0.2\n"
                                                      "fix             m8 all property/global coefficientPlasticityDepth peratomtypepair 2 0.05 0.05 0.05 0.05\n"
                                                      "pair_style      gran model hooke/hysteresis tangential history")],
         "not the elastic force of pair_style gran's model hooke/hysteresis"),
        ("no atom map", [("atom_modify     map array\n", "")], "fix crush needs an atom map: add 'atom_modify map array'"),
        # each particle's own N (scale_atom): the property must exist, and every N be finite and > 0
        ("scale_atom without property", [("dmin 0.0001 log", "dmin 0.0001 scale_atom nowhere log")],
         "keyword 'scale_atom': no scalar fix property/atom named 'nowhere'"),
        ("scale_atom of zero", [("dmin 0.0001 log", "dmin 0.0001 scale_atom grainScale log"),
                                (pair, "fix             grain_scale all property/atom grainScale scalar yes no no 0.\n" + pair)],
         "keyword 'scale_atom': particle 1 has grainScale = 0"),
        # the balance command's arguments
        ("balance thresh", [("pair_coeff      * *\n", "pair_coeff      * *\nbalance 0.5 shift x 20 1.0\n")],
         "balance: thresh expects a number >= 1"),
        ("balance axes", [("pair_coeff      * *\n", "pair_coeff      * *\nbalance 1.0 shift xx 20 1.0\n")],
         "balance: dimstr expects the axes x, y, z"),
        ("balance niter", [("pair_coeff      * *\n", "pair_coeff      * *\nbalance 1.0 shift x 2.5 1.0\n")],
         "balance: niter expects a whole number in [1, 60]"),
        # fix balance's: its own Nevery and out, then the balance command's settings named by the fix
        ("fix balance nevery", [("pair_coeff      * *\n", "pair_coeff      * *\nfix bal all balance 0 1.0 shift x 20 1.0\n")],
         "fix balance (id bal): Nevery expects a whole number of steps >= 1, got '0'"),
        ("fix balance weight", [("pair_coeff      * *\n", "pair_coeff      * *\nfix bal all balance 100 1.0 shift x 20 1.0 weight time\n")],
         "fix balance (id bal): expected 'weight neighbors' after stopthresh, got 'weight time'"),
        ("fix balance out", [("pair_coeff      * *\n", "pair_coeff      * *\nfix bal all balance 100 1.0 shift x 20 1.0 out /nonexistent/b.txt\n")],
         "fix balance (id bal): cannot open the out file '/nonexistent/b.txt'"),
        # hooke/stiffness needs no E: fix crush still does, for E' of eq. 4
        ("no youngs modulus", [("fix             m1 all property/global youngsModulus peratomtype 7.8e9 7.8e9\n", ""),
                               (pair, "fix             m5 all property/global kn peratomtypepair 2 1e5 1e5 1e5 1e5\n"
                                      "fix             m6 all property/global kt peratomtypepair 2 1e5 1e5 1e5 1e5\n"
                                      "fix             m7 all property/global gamman peratomtypepair 2 0 0 0 0\n"
                                      "fix             m8 all property/global gammat peratomtypepair 2 0 0 0 0\n"
                                      "pair_style      gran model hooke/stiffness tangential history")],
         "needs the grains' Hertzian contact area, from E and nu of every type: define 'fix ID all "
         "property/global youngsModulus"),
    ]
    for label, old, expected in [(c[0], [(c[1], c[2])], c[3]) for c in cases] + model_cases:
        deck = edited_deck(os.path.join(CRUSH, "in.compression"), os.path.join(work, label.replace(" ", "_"), "deck"),
                           old, includes=("in.crush_fixes", "in.compression_setup"))
        out = run_deck(liggghts, deck, os.path.join(work, label.replace(" ", "_"), "run"),
                       {"log": "ev.csv", "out": "f.dump"}, expect_fail=True)
        check(expected.lower() in out.lower(), "%s -> error mentions '%s'" % (label, expected))


HARD_CASES = ("all_break", "weak", "jump", "corner", "step50", "generations", "periodic", "overlap")


@variants(*[(which, ranks) for which in HARD_CASES for ranks in (1, 2, 4)])
def case_hard(liggghts, work, which, ranks=1):
    """Hard cases (in.hard_cases; corner, generations, periodic: in.hard_<case>): the run ends
    normally, every thermo row keeps the books (particles = initial + 13 x events, particle + removed
    volume = initial to 1e-12), no NaN, and the largest speed stays below 50 m/s (100 m/s for the
    generations case)."""
    corner = which in ("corner", "step50")
    single = which in ("corner", "step50", "generations", "periodic")
    deck = os.path.join(CRUSH, "in.hard_corner" if corner else ("in.hard_" + which if single else "in.hard_cases"))
    stress = 5e7 if which == "step50" else 3e7
    run_deck(liggghts, deck, work, {"case": which, "out": "final.dump", "stress": stress}, ranks=int(ranks))
    n0 = 1 if single else N0
    # Tiny second-generation fragments released from a wall overlap under 20 MPa move fast.
    speed_bound = 100.0 if which == "generations" else 50.0
    thermo = read_thermo(os.path.join(work, "log.liggghts"))
    v0 = thermo[0]["gsd"]
    for row in thermo:
        values = list(row.values())
        if any(v != v for v in values):
            raise AssertionError("NaN at step %d" % row["Step"])
        if row["Atoms"] != n0 + 13 * row["crush[1]"] or abs(row["gsd"] - v0) > 1e-12 * v0:
            raise AssertionError("books broken at step %d: %s" % (row["Step"], row))
        if row["vmax"] > speed_bound:
            raise AssertionError("speed %.3g m/s at step %d" % (row["vmax"], row["Step"]))
    check(True, "%s: %d events, books balance and speeds stay below %g m/s in all %d rows (largest %.3g m/s)"
          % (which, thermo[-1]["crush[1]"], speed_bound, len(thermo), max(r["vmax"] for r in thermo)))
    final = read_dump(os.path.join(work, "final.dump"))[-1][2]
    check(all(all(v == v for v in r.values()) for r in final), "no NaN in the final particles")
    if which == "overlap":
        check(thermo[-1]["crush[1]"] == 0 and thermo[-1]["Atoms"] == N0, "no breakage, no particle lost")
    if which == "all_break":
        check(thermo[-1]["crush[1]"] == N0, "all 512 grains broke")
    if which == "generations":
        check(thermo[-1]["crush[1]"] == 15, "the grain and its 14 fragments broke (15 events)")
        check(all(r["f_crush[2]"] == 2 and 2 * r["radius"] < 4e-5 for r in final),
              "196 second-generation fragments, all below dmin, at the largest allowed time step")
    if which == "periodic":
        check(thermo[-1]["crush[1]"] == 1 and sorted(int(r["id"]) for r in final) == list(range(2, 16)),
              "on %s rank(s) the grain on the periodic corner broke into fragments 2..15" % ranks)
    if corner:
        check(thermo[-1]["crush[1]"] == 1, "the grain in the corner broke")
        inside = all(0 < r["x"] < 3e-4 and 0 < r["y"] < 3e-4 and 0 < r["z"] < 2e-4 for r in final)
        check(inside, "its 14 fragments stay between the walls")
        check(abs(thermo[-1]["walls[9]"] / stress - 1) < 1e-3,
              "the top wall holds the %g MPa step after the event" % (stress / 1e6))


@variants(("ignore",), ("warn",), ("error",))
def case_particle_lost(liggghts, work, policy):
    """Of two grains, one is pushed out through the fixed top of the box: LIGGGHTS drops it. fix crush follows
    'thermo_modify lost': with ignore (LIGGGHTS' default) and warn the run goes on and the grain's
    volume leaves the books as outflow (f_crush[6], one particle in f_crush[7]), said once in the log;
    with error the run stops at the exchange that would drop it."""
    single = "create_atoms    1 single 0.0 0.0 0.0001 units box"
    edits = [(single, single + "\ncreate_atoms    1 single 0.0005 0.0 0.0001 units box\ngroup first id 1"),
             ("set             atom 1 diameter", "set             group all diameter"),
             ("fix             load all addforce 0.0 0.0 v_push", "fix             load first addforce 0.0 0.0 1.0"),
             ("thermo_modify   format float %.15g", "thermo_modify   format float %.15g lost " + policy),
             ('print           "EVENTS ${events}"',
              'print           "EVENTS ${events}"\nprint "OUTFLOW $(f_crush[6])"\nprint "OUTFLOW_N $(f_crush[7])"')]
    deck = edited_deck(SINGLE, os.path.join(work, "deck"), edits)
    out = run_deck(liggghts, deck, os.path.join(work, "run"), expect_fail=policy == "error")
    if policy == "error":
        check("fix crush: 1 particles leave the box at step" in out and "'thermo_modify lost error' forbids it" in out,
              "the run stops: 'fix crush: 1 particles leave the box ... lost error forbids it'")
        return
    volume = math.pi / 6 * 2e-4 ** 3
    check(abs(printed(out, "OUTFLOW") / volume - 1) < 1e-9 and printed(out, "OUTFLOW_N") == 1,
          "lost %s: the grain's volume %.4e m^3 left the books as outflow (%.4e), one particle"
          % (policy, volume, printed(out, "OUTFLOW")))
    check(out.count("particles (") == 1 and "1 particles (%g m^3) leave the box" % volume in out,
          "the log says it once: 'fix crush: 1 particles (... m^3) leave the box'")
    check(printed(out, "EVENTS") == 0, "no event")


def case_time_step_after_event(liggghts, work):
    """Without dmin the time step is checked after every event against the particles present: the
    single grain at a time step fine for it but too large for its fragments stops at the event."""
    deck = edited_deck(SINGLE, os.path.join(work, "deck"),
                       [("timestep        1e-8", "timestep        3e-8"), (" dmin 1.9e-4", "")])
    out = run_deck(liggghts, deck, os.path.join(work, "run"), expect_fail=True)
    check("present after crushing" in out and "exceeds" in out,
          "the run stops at the event with the time-step error naming both numbers")
    check("Step" in out, "it ran before the event")


@variants(*each_rank_count(1, 2, 3, 4))
def case_held_stream(liggghts, work, ranks):
    """Grains fix insert/stream still carries, pressed into a frozen layer (crush/in.held_stream):
    they reach their limit while held (f_crush[11] counts those checks) and each breaks only after
    its release step; most of the 40 break (the decomposition orders the sums: 38 - 40), their
    fragments free (the run goes on), and the
    books hold: particles = 100 + inserted + 13 x events, every tag once. With the fragments given
    their mother's release data, insert/stream put all fourteen on one point and the pair style stopped."""
    out = run_deck(liggghts, os.path.join(CRUSH, "in.held_stream"), work,
                   {"log": "events.csv", "out": "final.dump", "release": "release.dump"}, ranks=int(ranks))
    release = {int(r["id"]): int(r["f_release_fix_insert_stream[5]"])
               for r in read_dump(os.path.join(work, "release.dump"))[-1][2]}
    events = read_events(os.path.join(work, "events.csv"))
    held = printed(out, "HELD_AT_LIMIT")
    after = [int(e["step"]) - release[int(e["tag"])] for e in events]
    check(held > 0 and len(release) == 40 and len(events) >= 30 and min(after) >= 1,
          "on %s rank(s) %d checks found held grains at their limit; %d of the 40 broke, %d - %d steps after "
          "their release" % (ranks, held, len(events), min(after), max(after)))
    rows = read_dump(os.path.join(work, "final.dump"))[-1][2]
    tags = [int(r["id"]) for r in rows]
    check(len(tags) == len(set(tags)) == 100 + printed(out, "INSERTED") + 13 * len(events),
          "%d particles = 100 + %d inserted + 13 x %d events, every tag once" % (len(tags), printed(out, "INSERTED"),
                                                                                len(events)))

if __name__ == "__main__":
    test_main(globals(), sys.argv[1:])
