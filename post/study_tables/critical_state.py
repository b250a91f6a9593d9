"""Critical state with crushing (studies/critical_state/README.md): the page's tables from the rows of
critical_states.csv (scripts/critical_state_study.sh's tests) and critical_states_precrushed.csv (its
group "precrushed"), fitted by post/critical_state.py's own functions: the critical states, the lines
and planes with their 95% t intervals, the pre-crushed samples and phi_cs between pressures by the
one rule, the cost, and the opening conclusions."""
import os

from post import critical_state as cs
from post.seeds import holm, interval, one_sample
from post.study_tables.common import cell, conclusions

PAGE = "studies/critical_state/README.md"
CSVS = ("critical_states.csv", "critical_states_precrushed.csv")
# The group "lab" (the decks' reading, loose, cell 0.2 MPa, five seeds, to 40% axial strain), apart
# from the fits: its longer shearing would mix two windows of strain into one line.
LAB_CSV = "critical_states_lab.csv"
SETTLED = 0.05  # |dilatancy| at the end below which a test is at its critical state
STUDY = "bash scripts/critical_state_study.sh"
DECKS = "rotation0"  # the decks' reading: normal_clipped_originals, grains that do not rotate
MAX_DILATANCY = 0.1  # the page's second reading of the fits: tests still changing volume left out

# Fontainebleau NE34's critical-state angle in drained triaxial compression (degrees) and the mean
# stresses of those tests (MPa): Li 2013, Latini & Zania 2016 and Zuern et al. 2025 in the
# 4TU.ResearchData sand triaxial test database (doi 10.4121/086847a6-ba39-4d66-973b-6b93028c7ad8),
# as studies/fontainebleau/README.md quotes them.
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


def critical_state_lines(folder):
    return "\n".join(cs.lines_table(fitted_of(folder)[1]))


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


def critical_state_angles(folder):
    return "\n".join(cs.angles_table(tests_of(folder)))


def critical_state_cost(folder):
    """CPU seconds, particles and steps by variant and path (the wall-clock time where a test has no CPU
    time)."""
    lines = ["| variant | path | tests | CPU s | per test | particles at the end | steps (M) |", "|---|---|---|---|---|---|---|"]
    tests = tests_of(folder)
    for variant, path in sorted({(t["variant"], t["path"]) for t in tests}):
        group = [t for t in tests if (t["variant"], t["path"]) == (variant, path)]
        seconds = [t["cpu_seconds"] if t["cpu_seconds"] == t["cpu_seconds"] else t["seconds"] for t in group]
        wall = sum(t["cpu_seconds"] != t["cpu_seconds"] for t in group)
        particles, steps = [t["particles_end"] for t in group], [t["steps"] / 1e6 for t in group]
        lines.append("| %s | %s | %d | %.0f%s | %.0f - %.0f | %.0f - %.0f | %.2f - %.2f |"
                     % (variant, path, len(group), sum(seconds), " (%d wall-clock)" % wall if wall else "",
                        min(seconds), max(seconds), min(particles), max(particles), min(steps), max(steps)))
    total = sum(t["cpu_seconds"] if t["cpu_seconds"] == t["cpu_seconds"] else t["seconds"] for t in tests)
    return "\n".join(lines + ["", "(%d tests, %.0f CPU s in all: %.1f hours of one core)" % (len(tests), total, total / 3600)])


def coefficient(fit, k):
    """A least-squares coefficient against zero in compare()'s terms."""
    value, se = fit["coefficients"][k], fit["se"][k]
    low, high, p = interval(value, se, fit["df"])
    return dict(change=value, low=low, high=high, p=p, resolved="yes" if low > 0 or high < 0 else "no")


def span(c, digits, signed=False):
    """'value (low .. high)' of a change or coefficient with its 95% interval."""
    f = "%+.*f" if signed else "%.*f"
    return (f + " (" + f + " .. " + f + ")") % (digits, c["change"], digits, c["low"], digits, c["high"])


def lab_tests(folder):
    path = os.path.join(folder, LAB_CSV)
    return cs.read_csv([path]) if os.path.exists(path) else []


def lab_gap(lab):
    """phi_cs over the seeds less the top of NE34's range, as a change with its 95% t interval."""
    mean, se, df = one_sample([t["phi_cs"] - NE34_PHI_CS[1] for t in lab])
    low, high, p = interval(mean, se, df)
    return dict(change=mean, se=se, df=df, low=low, high=high, p=p,
                resolved="yes" if low > 0 or high < 0 else "no")


def settled(t):
    return abs(t["dilatancy_end"]) <= SETTLED


def lab_conclusion(lab):
    gap = lab_gap(lab)
    at_cs = sum(settled(t) for t in lab)
    place = "above" if gap["low"] > 0 else ("below" if gap["high"] < 0 else "not resolved from")
    dilating = sum(t["dilatancy_end"] > SETTLED for t in lab)
    caveat = (" %d of the %d tests still dilate at 40%%: their angles, and so the gap, are upper bounds."
              % (dilating, len(lab))) if dilating else ""
    return ("Sheared where the laboratory measured it (cell 0.2 MPa, loose, to 40%% strain), the decks' phi_cs "
            "lies %s the top of NE34's %.1f - %.1f deg.%s" % ((place,) + NE34_PHI_CS + (caveat,)),
            "phi_cs %s deg at p' %s MPa; above %.1f by %s; %d of %d tests within |dilatancy| %.2f at the end"
            % (cell([t["phi_cs"] for t in lab], 1), cell([t["p_cs_MPa"] for t in lab], 2), NE34_PHI_CS[1],
               span(gap, 1, True), at_cs, len(lab), SETTLED),
            runs(lab), "AXIAL_MAX=0.4 %s runs/critical_state_lab lab" % STUDY)


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


def conclusions_critical_state(folder):
    tests, fitted = fitted_of(folder)
    rows, tested = [], []

    line = fitted[DECKS]["lines"]["both"]
    lam, gamma = coefficient(line, 1), coefficient(line, 0)
    tested.append(lam)
    rows.append(("The decks' reading (`%s`, dense and loose): Li & Wang's curved critical state line fits %s than "
                 "a straight one." % (DECKS, "better" if line["rms_li_wang"] < line["rms"] else "no better"),
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

    lab = lab_tests(folder)
    if len(lab) >= 3:
        rows.append(lab_conclusion(lab))
        tested.append(lab_gap(lab))
    low = [t for t in tests if t["variant"] == DECKS and t["path"] == "sigma3" and t["p_cs_MPa"] <= NE34_P_MPA[1]]
    place = "above" if all(t["phi_cs"] > NE34_PHI_CS[1] for t in low) else "not all above"
    rows.append(("At the published tests' pressures (%g - %g kPa) the decks' phi_cs lies %s NE34's %.1f - %.1f "
                 "deg; a dilating test's angle is an upper bound."
                 % ((1e3 * NE34_P_MPA[0], 1e3 * NE34_P_MPA[1], place) + NE34_PHI_CS),
                 "; ".join("%s %.1f deg at %.2f MPa, %+.1f above, dilatancy %+.3f%s"
                           % (t["sample"], t["phi_cs"], t["p_cs_MPa"], t["phi_cs"] - NE34_PHI_CS[1], t["dilatancy_end"],
                              ": upper bound" if t["dilatancy_end"] > 0 else "") for t in low),
                 runs(low) + ": no interval",
                 "%s runs/critical_state %s" % (STUDY, " ".join("%s:%s:%g" % (DECKS, t["sample"], t["p0_MPa"]) for t in low))))

    for variant, breakage in (("none", "Without breakage"), ("weak", "With breakage")):
        for name, sample, path, lo, hi, seeds, c in cs.paired_angles(tests):
            if (name, sample) != (variant, "dense"):
                continue
            ends = [t for t in tests if (t["variant"], t["sample"], t["path"]) == (name, sample, path)
                    and t["p0_MPa"] in (lo, hi)]
            by = dict(((t["seed"], t["p0_MPa"]), t["phi_cs"]) for t in ends)
            falls = sum(by[(s, hi)] < by[(s, lo)] for s in seeds)
            dilating = sum(t["dilatancy_end"] > 0 for t in ends)
            tested.append(c)
            finding = "%s (`%s`, dense) phi_cs %s with p': %s%s." % (
                breakage, variant, "falls" if c["change"] < 0 else "rises", verdict(c),
                "; its tests still dilate (upper bounds)" if dilating == len(ends) else "")
            rows.append((finding, "%s deg from p'_0 %g to %g MPa, %s: %s; falls in %d of %d seeds; %d of %d tests dilating"
                         % (span(c, 2, True), lo, hi, "paired by seed" if c["design"].startswith("paired") else "Welch",
                            verdict(c), falls, len(seeds), dilating, len(ends)),
                         runs(ends), "%s runs/precrushed precrushed" % STUDY))

    adjusted = holm([c["p"] for c in tested])
    return conclusions(rows) + "\n\n(%d tests against zero in this table: %d resolved, %d after Holm's correction over them)" % (
        len(tested), sum(c["resolved"] == "yes" for c in tested),
        sum(c["resolved"] == "yes" and p < 0.05 for c, p in zip(tested, adjusted)))


TABLES = {"conclusions_critical_state": conclusions_critical_state,
          "critical_state_lines": critical_state_lines,
          "critical_state_planes": critical_state_planes, "critical_state_settled": critical_state_settled,
          "critical_state_gradings": critical_state_gradings,
          "critical_state_angles": critical_state_angles, "critical_state_cost": critical_state_cost,
          "critical_state_lab": critical_state_lab}
