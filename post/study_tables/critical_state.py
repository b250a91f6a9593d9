"""Critical state with crushing (studies/critical_state/README.md): the page's tables from the rows of
critical_states.csv (scripts/critical_state_study.sh's tests) and critical_states_precrushed.csv (its
group "precrushed"), fitted by post/critical_state.py's own functions: the critical states, the lines
and planes with their 95% t intervals, the pre-crushed samples and phi_cs between pressures by the
one rule, the cost, and the opening conclusions; the group "lab" (critical_states_lab.csv) apart.
Every sentence of the conclusions is keyed to the numbers it states."""
import os

from post import critical_state as cs
from post.seeds import holm, interval, one_sample, resolved
from post.study_tables.common import cell, conclusions

PAGE = "studies/critical_state/README.md"
CSVS = ("critical_states.csv", "critical_states_precrushed.csv")
# The group "lab" (the decks' reading, loose, cell 0.2 MPa, five seeds, to 40% axial strain), apart
# from the fits: its longer shearing would mix two windows of strain into one line.
LAB_CSV = "critical_states_lab.csv"
SETTLED = 0.05  # |dilatancy| at the end below which a test is at its critical state (the page's one count)
STUDY = "bash scripts/critical_state_study.sh"
DECKS = "rotation0"  # the decks' reading: normal_clipped_originals, grains that do not rotate
MAX_DILATANCY = 0.1  # the page's second reading of the fits: tests still changing volume left out
BARELY = 0.05  # a relative difference of rms residuals under which one line is "barely" lower than another

# Fontainebleau NE34's critical-state angle in drained triaxial compression (degrees) and the mean
# stresses of those tests (MPa): Li 2013, Latini & Zania 2016 and Zuern et al. 2025 in the
# 4TU.ResearchData sand triaxial test database (doi 10.4121/086847a6-ba39-4d66-973b-6b93028c7ad8),
# as studies/fontainebleau/history.md ("The triaxial calibration and grain rotation") quotes them:
# quoted, not measured here, and the database itself was not read.
NE34_PHI_CS = (31.4, 33.4)
NE34_P_MPA = (0.05, 0.4)

# The stress-history control the pre-crushed comparison lacks: uncrushable samples pre-compressed as
# weak_pre50 was, and the uncrushable ones it pairs with at 2 MPa (none ran the decks' seed alone there).
SEEDS = ("15485863", "179424673", "373587883")
CONTROL = " ".join(["none_pre50:dense:%s:sigma3:%s" % (p0, s) for p0 in (2, 10) for s in SEEDS]
                   + ["none:dense:2:sigma3:%s" % s for s in SEEDS[1:]])


def tests_of(folder, names=CSVS):
    return cs.read_csv([os.path.join(folder, name) for name in names])


def fitted_of(folder, max_dilatancy=None):
    tests = tests_of(folder)
    return tests, cs.fits(tests, max_dilatancy)


def lab_tests(folder):
    path = os.path.join(folder, LAB_CSV)
    return cs.read_csv([path]) if os.path.exists(path) else []


def shown_lines(fitted):
    """(variant, samples, line) of each row of the lines table (cs.lines_table()'s own choice)."""
    return [(variant, name, line) for variant, f in fitted.items() for name, line in f["lines"].items()
            if not (" + " in variant or (name in ("dense", "loose") and cs.line_count(f, name) == len(f["tests"])))]


def lowered(rms, other):
    """How Li & Wang's rms compares with another line's: 'lower', 'barely lower' (under BARELY of it),
    'no lower'."""
    if rms >= other:
        return "no lower"
    return "barely lower" if (other - rms) / other < BARELY else "lower"


def overlap(a, b, k):
    """Whether two lines' 95% intervals of coefficient k overlap."""
    (la, ha, _), (lb, hb, _) = [interval(f["coefficients"][k], f["se"][k], f["df"]) for f in (a, b)]
    return la <= hb and lb <= ha


def lines_note(fitted):
    """The line under the lines table: where Li & Wang's curve has the lower rms, where only barely, where
    log e - log p' has the highest, and whether dense and loose lines' intervals overlap."""
    rows = shown_lines(fitted)
    words = [lowered(line["rms_li_wang"], line["rms"]) for _, _, line in rows]
    barely = sorted({v for (v, _, _), w in zip(rows, words) if w == "barely lower"})
    levels = dict((v, len({t["p0_MPa"] for t in fitted[v]["tests"]})) for v in barely)
    worst = sum(line["rms_power"] > max(line["rms"], line["rms_li_wang"]) for _, _, line in rows)
    both = [v for v, f in fitted.items() if " + " not in v and {"dense", "loose"} <= set(f["lines"])
            and all(cs.line_count(f, s) < len(f["tests"]) for s in ("dense", "loose"))]
    apart = [v for v in both if not all(overlap(fitted[v]["lines"]["dense"], fitted[v]["lines"]["loose"], k) for k in (0, 1))]
    one_way = sorted({v for v, f in fitted.items() if " + " not in v} - set(both))
    return ("(Li & Wang's curve has the lower rms in %d of %d rows%s. log e - log p' has the highest rms of the three "
            "in %d of %d. Dense and loose intervals of Gamma and lambda overlap in %d of the %d variants run both ways%s%s.)"
            % (sum(w != "no lower" for w in words), len(rows),
               "; barely (under %.0f%%) in %d: %s" % (100 * BARELY, sum(w == "barely lower" for w in words),
                                                ", ".join("`%s` (%d p'_0)" % (v, levels[v]) for v in barely))
               if barely else "", worst, len(rows), len(both) - len(apart), len(both),
               " (not in %s)" % ", ".join("`%s`" % v for v in apart) if apart else "",
               "; %s ran dense only" % " and ".join("`%s`" % v for v in one_way) if one_way else ""))


def critical_state_lines(folder):
    fitted = fitted_of(folder)[1]
    return "\n".join(cs.lines_table(fitted) + ["", lines_note(fitted)])


def critical_state_planes(folder):
    return "\n".join(cs.planes_table(fitted_of(folder)[1]))


def critical_state_settled(folder):
    """The pooled planes and the pre-crushed pairs without the tests whose |dilatancy| at the end
    exceeds MAX_DILATANCY."""
    tests, fitted = fitted_of(folder, MAX_DILATANCY)
    pooled = dict((k, f) for k, f in fitted.items() if " + " in k)
    return "\n".join(cs.planes_table(pooled) + [""] + cs.gradings_table(tests, MAX_DILATANCY)
                     + ["", cs.left_out(tests, MAX_DILATANCY)])


def critical_state_gradings(folder):
    return "\n".join(cs.gradings_table(tests_of(folder)))


def mean_phi(tests, variant, sample, p0):
    values = [t["phi_cs"] for t in tests if (t["variant"], t["sample"], t["path"], t["p0_MPa"]) == (variant, sample, "sigma3", p0)]
    return sum(values) / len(values)


def angles_note(tests):
    """The line under the angles table: phi_cs at the highest p'_0 against the lowest in each variant and
    sample (constant cell pressure; the mean over the seeds at each end), and rolling against rotation0
    test by test."""
    ends = []
    for variant, sample in sorted({(t["variant"], t["sample"]) for t in tests if t["path"] == "sigma3"}):
        levels = sorted({t["p0_MPa"] for t in tests if (t["variant"], t["sample"], t["path"]) == (variant, sample, "sigma3")})
        if len(levels) >= 2:
            ends.append(mean_phi(tests, variant, sample, levels[-1]) < mean_phi(tests, variant, sample, levels[0]))
    key = lambda t: (t["sample"], t["p0_MPa"], t["path"], t["seed"])  # noqa: E731
    decks = dict((key(t), t["phi_cs"]) for t in tests if t["variant"] == DECKS)
    pairs = [(t["phi_cs"], decks[key(t)]) for t in tests if t["variant"] == "rolling" and key(t) in decks]
    seeds = len({t["seed"] for t in tests if t["variant"] == "rolling"})
    return ("(From the lowest p'_0 run to the highest, phi_cs falls in %d of %d variant-sample lines at constant cell "
            "pressure, the mean over the seeds at each end. `rolling` lies below `%s` in %d of %d pairs at one sample, "
            "p'_0 and seed%s.)" % (sum(ends), len(ends), DECKS, sum(a < b for a, b in pairs), len(pairs),
                                    ", one seed each: not tested" if seeds == 1 else ""))


def critical_state_angles(folder):
    tests = tests_of(folder)
    return "\n".join(cs.angles_table(tests) + ["", angles_note(tests)])


def grouped(tests, lab):
    """(variant, tests) of the CSVs' variants, then the group lab as a row of its own."""
    out = [(v, [t for t in tests if t["variant"] == v]) for v in sorted({t["variant"] for t in tests})]
    return out + ([("%s (lab, to 40%% strain)" % " + ".join(sorted({t["variant"] for t in lab})), lab)] if lab else [])


def critical_state_grading(folder):
    """Breakage while shearing, by variant: the events and the change of I_G from the start of shearing
    to its end (columns events_shearing, IG0 and IG_cs of the CSVs)."""
    lines = ["| variant | tests | events in shearing | I_G at the start of shearing | its rise to the end |",
             "|---|---|---|---|---|"]
    for variant, group in grouped(tests_of(folder), lab_tests(folder)):
        events, start = [t["events_shearing"] for t in group], [t["IG0"] for t in group]
        rise = [t["IG_cs"] - t["IG0"] for t in group]
        lines.append("| %s | %d | %.0f - %.0f | %.3f - %.3f | %.3f - %.3f |" % (
            variant, len(group), min(events), max(events), min(start), max(start), min(rise), max(rise)))
    return "\n".join(lines)


def cpu_or_wall(t):
    return t["cpu_seconds"] if t["cpu_seconds"] == t["cpu_seconds"] else t["seconds"]


def critical_state_cost(folder):
    """CPU seconds, particles and steps by variant and path (the wall-clock time where a test has no CPU
    time); the group lab (critical_states_lab.csv, to 40% strain) in a row of its own."""
    lines = ["| variant | path | tests | CPU s | per test | particles at the end | steps (M) |", "|---|---|---|---|---|---|---|"]
    tests, lab = tests_of(folder), lab_tests(folder)
    rows = [((v, p), [t for t in tests if (t["variant"], t["path"]) == (v, p)])
            for v, p in sorted({(t["variant"], t["path"]) for t in tests})]
    if lab:
        rows.append(((grouped([], lab)[0][0], " + ".join(sorted({t["path"] for t in lab}))), lab))
    for (variant, path), group in rows:
        seconds = [cpu_or_wall(t) for t in group]
        wall = sum(t["cpu_seconds"] != t["cpu_seconds"] for t in group)
        particles, steps = [t["particles_end"] for t in group], [t["steps"] / 1e6 for t in group]
        lines.append("| %s | %s | %d | %.0f%s | %.0f - %.0f | %.0f - %.0f | %.2f - %.2f |"
                     % (variant, path, len(group), sum(seconds), " (%d wall-clock)" % wall if wall else "",
                        min(seconds), max(seconds), min(particles), max(particles), min(steps), max(steps)))
    total = sum(cpu_or_wall(t) for t in tests + lab)
    return "\n".join(lines + ["", "(%d tests, %.0f CPU s in all: %.1f hours of one core)"
                              % (len(tests + lab), total, total / 3600)])


def coefficient(fit, k):
    """A least-squares coefficient against zero in compare()'s terms."""
    value, se = fit["coefficients"][k], fit["se"][k]
    low, high, p = interval(value, se, fit["df"])
    return dict(change=value, low=low, high=high, p=p, resolved=resolved(value, se, fit["df"]))


def span(c, digits, signed=False):
    """'value (low .. high)' of a change or coefficient with its 95% interval."""
    f = "%+.*f" if signed else "%.*f"
    return (f + " (" + f + " .. " + f + ")") % (digits, c["change"], digits, c["low"], digits, c["high"])


def lab_gap(lab):
    """phi_cs over the seeds less the top of NE34's range, as a change with its 95% t interval."""
    mean, se, df = one_sample([t["phi_cs"] - NE34_PHI_CS[1] for t in lab])
    low, high, p = interval(mean, se, df)
    return dict(change=mean, se=se, df=df, low=low, high=high, p=p, resolved=resolved(mean, se, df))


def settled(t):
    return abs(t["dilatancy_end"]) <= SETTLED


def dilating(tests):
    return [t for t in tests if t["dilatancy_end"] > SETTLED]


def contracting(tests):
    return [t for t in tests if t["dilatancy_end"] < -SETTLED]


def bound(t):
    """What a test's phi_cs is: a dilating test's q/p lies above its critical value, a contracting one's below."""
    return ("an upper bound" if t["dilatancy_end"] > SETTLED else
            "still contracting, a lower bound" if t["dilatancy_end"] < -SETTLED else "settled")


def in_range(phi):
    return NE34_PHI_CS[0] <= phi <= NE34_PHI_CS[1]


def holm_verdict(c, p_holm):
    """The one rule's verdict on a change of the conclusions table, with Holm's over the table."""
    if c["resolved"] != "yes":
        return "not resolved"
    return ("resolved, also after Holm's correction over this table" if p_holm < 0.05
            else "not resolved after Holm's correction over this table")


def lab_conclusion(lab, p_holm):
    """The group lab against NE34's range: where its p'_cs lie against the laboratory's, the mean less the
    top of the range (Holm's p over the conclusions table), its bounds, and the settled tests in the range."""
    gap, mean = lab_gap(lab), sum(t["phi_cs"] for t in lab) / len(lab)
    above_p = sum(t["p_cs_MPa"] > NE34_P_MPA[1] for t in lab)
    where = ("Within" if not above_p else "At and just above the top of" if above_p < len(lab) else "Above")
    place = "above" if mean > NE34_PHI_CS[1] else ("below" if mean < NE34_PHI_CS[0] else "within")
    up, down, calm = dilating(lab), contracting(lab), [t for t in lab if settled(t)]
    inside = sum(in_range(t["phi_cs"]) for t in calm)
    if up and down:
        bounds = "%d of %d tests still dilate and %d contract; the gap is" % (len(up), len(lab), len(down))
    elif up or down:
        bounds = "%d of %d tests still %s, so the gap is %s bound; it is" % (
            len(up or down), len(lab), "dilate" if up else "contract", "an upper" if up else "a lower")
    else:
        bounds = "The gap is"
    finding = ("%s the laboratory's pressures (loose, cell 0.2 MPa, to 40%% strain) the decks' mean phi_cs lies %s "
               "NE34's %.1f - %.1f deg. %s %s. %s"
               % ((where, place) + NE34_PHI_CS + (bounds, holm_verdict(gap, p_holm),
                  "%d of the %d settled tests %s in the range." % (inside, len(calm), "lies" if inside == 1 else "lie")
                  if calm else "No test has settled.")))
    measured = ("phi_cs %s deg at p'_cs %s MPa (%d of %d above %.2f); mean less %.1f: %s, p %.2g, after Holm %.2g; "
                "settled (dilatancy at the end within %.2f either way): %s"
                % (cell([t["phi_cs"] for t in lab], 1), cell([t["p_cs_MPa"] for t in lab], 2), above_p, len(lab),
                   NE34_P_MPA[1], NE34_PHI_CS[1], span(gap, 1, True), gap["p"], p_holm, SETTLED,
                   ", ".join("%.1f deg (seed %s%s)" % (t["phi_cs"], t["seed"], ", in the range" if in_range(t["phi_cs"]) else "")
                             for t in calm) or "none"))
    return finding, measured, runs(lab), "AXIAL_MAX=0.4 %s runs/critical_state_lab lab" % STUDY


def critical_state_lab(folder):
    """Each test of the group lab: its critical state, and whether it has settled there."""
    lab = lab_tests(folder)
    lines = ["| seed | e_0 | p'_cs (MPa) | e_cs | q/p cs | phi_cs (deg) | dilatancy at end | at its critical state | "
             "I_G,cs | events in shearing |", "|---|---|---|---|---|---|---|---|---|---|"]
    for t in lab:
        lines.append("| %s | %.3f | %.3f | %.3f | %.3f | %.1f | %+.3f | %s | %.3f | %d |" % (
            t["seed"], t["e0"], t["p_cs_MPa"], t["e_cs"], t["M_cs"], t["phi_cs"], t["dilatancy_end"],
            "yes" if settled(t) else "no", t["IG_cs"], t["events_shearing"]))
    if not lab:
        lines.append("| not run | | | | | | | | | |")
    else:
        lines.append("| mean (95%% interval) | | | | | %s | | %d of %d | | |" % (
            cell([t["phi_cs"] for t in lab], 1), sum(settled(t) for t in lab), len(lab)))
    return "\n".join(lines)


def verdict(c):
    return "resolved" if c["resolved"] == "yes" else "not resolved"


def runs(tests):
    seeds = len({t["seed"] for t in tests})
    return "%d tests, %s" % (len(tests), "one seed" if seeds == 1 else "%d seeds" % seeds)


def at_pressures(tests):
    """'N at P, M at Q MPa' over the pressures of tests (p'_0)."""
    levels = sorted({t["p0_MPa"] for t in tests})
    return ", ".join("%d at %g" % (sum(t["p0_MPa"] == p for t in tests), p) for p in levels) + " MPa" if tests else ""


def angle_rows(tests):
    """Each dense fall of phi_cs of the conclusions (none, weak): (finding, measured, runs, command, change)."""
    out = []
    for variant, breakage in (("none", "Without breakage"), ("weak", "With breakage")):
        strict = dict(((r[0], r[1], r[2], r[3], r[4]), r[6]) for r in cs.paired_angles(tests, MAX_DILATANCY))
        for name, sample, path, lo, hi, seeds, c in cs.paired_angles(tests):
            if (name, sample) != (variant, "dense"):
                continue
            ends = [t for t in tests if (t["variant"], t["sample"], t["path"]) == (name, sample, path)
                    and t["p0_MPa"] in (lo, hi)]
            by = dict(((t["seed"], t["p0_MPa"]), t["phi_cs"]) for t in ends)
            falls = sum(by[(s, hi)] < by[(s, lo)] for s in seeds)
            up, down = dilating(ends), contracting(ends)
            other = strict.get((name, sample, path, lo, hi))
            if c["resolved"] == "yes":
                finding = "%s (`%s`, dense) phi_cs %s with p': resolved, %s without the tests whose dilatancy at the end exceeds %g either way." % (
                    breakage, variant, "falls" if c["change"] < 0 else "rises",
                    "also" if other and other["resolved"] == "yes" else "but not", MAX_DILATANCY)
            else:
                finding = "%s (`%s`, dense) the change of phi_cs with p' is not resolved (falls in %d of %d seeds)." % (
                    breakage, variant, falls, len(seeds))
            if up or down:
                finding += " " + "; ".join("%d of %d tests still %s (%s bounds)" % (len(group), len(ends), verb, word)
                                           for group, verb, word in ((up, "dilate", "upper"), (down, "contract", "lower"))
                                           if group) + "."
            moving = ", ".join("%d %s (%s bounds; %s)" % (len(group), verb, word, at_pressures(group))
                               for group, verb, word in ((up, "dilating", "upper"), (down, "contracting", "lower")) if group)
            measured = ("%s deg from p'_0 %g to %g MPa, %s: %s; falls in %d of %d seeds; dilatancy beyond %.2f either way: "
                        "%s; without the tests beyond %g: %s"
                        % (span(c, 2, True), lo, hi, "paired by seed" if c["design"].startswith("paired") else "Welch",
                           verdict(c), falls, len(seeds), SETTLED, moving or "none", MAX_DILATANCY,
                           "%s, %s, %d tests: %s" % (span(other, 2, True), "paired by seed" if other["design"].startswith("paired")
                                                     else "Welch", sum(cs.at_critical_state(t, MAX_DILATANCY) for t in ends),
                                                     verdict(other)) if other else "no pair left"))
            out.append((finding, measured, runs(ends), "%s runs/precrushed precrushed" % STUDY, c))
    return out


def conclusions_critical_state(folder):
    tests, fitted = fitted_of(folder)
    rows, tested = [], []

    line = fitted[DECKS]["lines"]["both"]
    lam, gamma = coefficient(line, 1), coefficient(line, 0)
    tested.append(lam)
    lower = lowered(line["rms_li_wang"], line["rms"])
    rows.append(("The decks' reading (`%s`, dense and loose): Li & Wang's curved critical state line has %s rms "
                 "than a straight one (a comparison, not a test)."
                 % (DECKS, lower if lower == "no lower" else "a " + lower),
                 "lambda %s, Gamma %s; rms %.4f straight, %.4f Li & Wang's curve"
                 % (span(lam, 4), span(gamma, 3), line["rms"], line["rms_li_wang"]),
                 runs(fitted[DECKS]["tests"]), "%s runs/critical_state" % STUDY))

    pooled = fitted[" + ".join(cs.POOLED)]
    straight, curved = coefficient(pooled["plane"], 2), coefficient(pooled["curved_plane"], 2)
    tested += [straight, curved]
    rows.append(("Across two strength readings (`%s`) beta is %s, but the reading's 0/1 indicator fits nearly as "
                 "well: the two are confounded." % (" + ".join(cs.POOLED), verdict(curved)),
                 "beta %s straight, %s curved: %s; curved rms %.4f with I_G, %.4f with the reading in its place"
                 % (span(straight, 2), span(curved, 2), " and ".join(sorted({verdict(straight), verdict(curved)})),
                    pooled["curved_plane"]["rms"], pooled["reading_plane"]["rms"]),
                 runs(pooled["tests"]), "%s runs/critical_state" % STUDY))

    gradings = [r for r in cs.paired_gradings(tests) if r[9] is not None]
    tested += [r[9] for r in gradings]
    rows.append(("The plane within one reading is not shown: pre-crushing to 50 MPa changes the grading and "
                 "the stress history together.",
                 "; ".join("beta %s at p'_0 %g MPa: %s" % (span(r[9], 2), r[3], verdict(r[9])) for r in gradings),
                 runs([t for t in tests if t["variant"] in {v for r in gradings for v in r[:2]} and t["sample"] == "dense"
                       and t["p0_MPa"] in {r[3] for r in gradings}]),
                 "%s runs/precrushed precrushed" % STUDY))

    control = [r for r in cs.paired_gradings(tests) if r[0] == "none"]
    rows.append(("The control that would separate them: uncrushable samples pre-compressed alike (`none_pre50`, "
                 "dense, three seeds).",
                 "; ".join("de_cs %s at p'_0 %g MPa" % (span(r[6], 4, True), r[3]) for r in control)
                 if control else "not run: no `none_pre50` rows in the CSVs",
                 "%d tests" % sum(2 * len(r[5]) for r in control), "%s runs/precrushed %s" % (STUDY, CONTROL)))

    # the group lab's row needs Holm's p over the whole table: its place is kept, its words written last
    lab = lab_tests(folder)
    lab_row = lab_tested = None
    if len(lab) >= 3:
        lab_row, lab_tested = len(rows), len(tested)
        rows.append(None)
        tested.append(lab_gap(lab))
    low = [t for t in tests if t["variant"] == DECKS and t["path"] == "sigma3" and t["p_cs_MPa"] <= NE34_P_MPA[1]]
    calm = [t for t in low if settled(t)]
    rows.append(("At the published tests' pressures (%g - %g kPa) the decks' reading has %s: not tested against NE34's "
                 "%.1f - %.1f deg; %s."
                 % ((1e3 * NE34_P_MPA[0], 1e3 * NE34_P_MPA[1], runs(low)) + NE34_PHI_CS
                    + ("neither has settled" if len(low) == 2 and not calm else
                       "%d of %d have settled" % (len(calm), len(low)),)),
                 "; ".join("%s %.1f deg at %.2f MPa, dilatancy %+.3f: %s"
                           % (t["sample"], t["phi_cs"], t["p_cs_MPa"], t["dilatancy_end"], bound(t)) for t in low),
                 runs(low) + ": not tested",
                 "%s runs/critical_state %s" % (STUDY, " ".join("%s:%s:%g" % (DECKS, t["sample"], t["p0_MPa"]) for t in low))))

    for finding, measured, count, command, c in angle_rows(tests):
        tested.append(c)
        rows.append((finding, measured, count, command))

    adjusted = holm([c["p"] for c in tested])
    if lab_row is not None:
        rows[lab_row] = lab_conclusion(lab, adjusted[lab_tested])
    return conclusions(rows) + "\n\n(%d tests against zero in this table: %d resolved, %d after Holm's correction over them)" % (
        len(tested), sum(c["resolved"] == "yes" for c in tested),
        sum(c["resolved"] == "yes" and p < 0.05 for c, p in zip(tested, adjusted)))


TABLES = {"conclusions_critical_state": conclusions_critical_state,
          "critical_state_lines": critical_state_lines,
          "critical_state_planes": critical_state_planes, "critical_state_settled": critical_state_settled,
          "critical_state_gradings": critical_state_gradings,
          "critical_state_angles": critical_state_angles, "critical_state_grading": critical_state_grading,
          "critical_state_cost": critical_state_cost, "critical_state_lab": critical_state_lab}
