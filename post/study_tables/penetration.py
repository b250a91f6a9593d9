"""Cone and pile penetration (studies/penetration/README.md): the study's conclusions, the steps that
say how far the default chamber is converged and what crushing changes, and the settings of the
chamber 40 D_c wide with q_c by depth. From scripts/penetration_study.sh's study.csv rows
(penetration_study.csv, penetration_refined.csv) and post/penetration_depth.py's bins
(penetration_depth.csv), and the chambers' porosity and preparation (penetration_w40_chambers.csv); each
command is checked against cases.csv, whose groups must hold every case its row rests on. Holm's correction
runs over the 12 steps and over the rises of q_c by depth, each a family."""
import fnmatch
import math
import os
import statistics as py_statistics

from post import penetration_stats
from post.seeds import compare, holm, interval, statistics
from post.study_tables.common import cell, conclusions, interval_cell, read_rows

PAGE = "studies/penetration/README.md"
OUT = "runs/refined"  # the runner's OUT_DIR in the commands the tables give
DEPTH_BINS = ("1", "2", "3")  # the bins from 1, 2 and 3 D_c (each 1 D_c deep) of penetration_depth.csv
W40 = "refined_N34_pristine_w40"  # the default scene's chamber: pristine, D_c / d50 = 5, 40 D_c wide
# The default chamber's tests that shared the 2 cores with other work for part of their time (a build and
# short tests: history.md, the width study's table, note (***)); the third seed's ran alone.
W40_SHARED = {"refined_N34_pristine_w40_s1", "refined_N34_pristine_w40_s2"}
DEPTH_COMMAND = ("/usr/bin/python3 post/penetration_depth.py "
                 "%s/refined_N34_pristine_w40_*/penetration/penetration_*_N34.csv "
                 "--csv studies/penetration/penetration_depth.csv" % OUT)  # the bins of penetration_depth.csv


class Study:
    """The study's runs, one row a case, and the depth bins of each case's test."""

    def __init__(self, folder):
        self.folder = folder
        self.rows = read_rows(os.path.join(folder, "penetration_study.csv")) + \
            read_rows(os.path.join(folder, "penetration_refined.csv"))
        self.depth = {}
        for r in read_rows(os.path.join(folder, "penetration_depth.csv")):
            self.depth.setdefault(r["case"], {})[r["from_Dc"]] = float(r["q_c_MPa"])
        self.chambers = {}
        for r in read_rows(os.path.join(folder, "penetration_w40_chambers.csv")):
            self.chambers.setdefault(r["chamber"], {}).setdefault(r["seed"], r)
        self.groups = {}
        for r in read_rows(os.path.join(folder, "cases.csv")):
            for group in r["groups"].split():
                self.groups.setdefault(group, set()).add(r["case"])

    def cases(self, pattern):
        """The rows of the cases pattern names (fnmatch), the first of a seed kept; it must name some,
        all of one setting (penetration_stats.one_setting: a pattern never mixes two)."""
        matched = [r for r in self.rows if fnmatch.fnmatchcase(r["case"], pattern)]
        if not matched:
            raise SystemExit("penetration tables: no run of %s in %s" % (pattern, self.folder))
        penetration_stats.one_setting(matched, pattern)
        kept = {}
        for r in matched:
            kept.setdefault(r["seed"], r)
        return kept

    def values(self, pattern, column="q_c_MPa", scale=1.0):
        """{seed: value} of a column over the cases of pattern."""
        return dict((s, scale * float(r[column])) for s, r in self.cases(pattern).items()
                    if r[column] not in ("", "nan"))

    def bin(self, pattern, start):
        """{seed: q_c over the D_c from start} of the cases of pattern whose history was binned."""
        return dict((s, self.depth[r["case"]][start]) for s, r in self.cases(pattern).items()
                    if start in self.depth.get(r["case"], {}))

    def runs(self, *patterns):
        return ", ".join("`%s` (%d)" % (p, len(self.cases(p))) for p in patterns)

    def command(self, groups, *patterns):
        """The runner's command for groups, which together must hold every case of patterns."""
        held = set().union(*(self.groups.get(g, set()) for g in groups))
        missing = [r["case"] for p in patterns for r in self.cases(p).values() if r["case"] not in held]
        if missing:
            raise SystemExit("penetration tables: groups %s of cases.csv do not hold %s"
                             % (" ".join(groups), ", ".join(missing)))
        return "bash scripts/penetration_study.sh %s %s" % (OUT, " ".join(groups))

    def porosity(self, chamber):
        """{seed: porosity after the consolidation} of a chamber of penetration_w40_chambers.csv."""
        return dict((s, float(r["porosity"])) for s, r in self.chambers[chamber].items())


def resolved_words(c, p_holm=None, family=""):
    """'resolved' or 'not resolved', how the one rule compared (paired by seed or Welch), and for a
    resolved change of a family whether it survives Holm's correction over it (p_holm, its adjusted p)."""
    words = "%s (%s)" % ("resolved" if c["resolved"] == "yes" else "not resolved",
                         "paired" if c["design"].startswith("paired") else "Welch")
    if c["resolved"] == "yes" and p_holm is not None:
        words += ", %s after Holm's correction over the %s (adj. p %.3f)" % (
            "also" if p_holm < 0.05 else "not", family, p_holm)
    return words


def count_words(k):
    return "none" if k == 0 else "%d" % k


def spread_cell(values, digits=1):
    """'median (min - max)': a run's time depends on what else shared the cores, so no interval."""
    values = sorted(values)
    return "%.*f (%.*f - %.*f)" % (digits, py_statistics.median(values), digits, values[0], digits, values[-1])


def ratio_cell(values, digits=2):
    """Each seed's own ratio, its mean and 95% interval, and whether that interval excludes 1."""
    n, mean, _, se = statistics(list(values))
    low, high, _ = interval(mean, se, n - 1) if n > 1 else (float("nan"),) * 3
    excluded = math.isfinite(low) and (low > 1 or high < 1)
    return "%s, %s from 1" % (cell(values, digits), "resolved" if excluded else "not resolved"), excluded


def paired(a, b, transform):
    """{seed: transform(a, b)} over the seeds both ran."""
    return dict((s, transform(a[s], b[s])) for s in a if s in b)


def step_tests(st):
    """{label: step} over STEPS, in order: each step's two sides, its change by the one rule, and its
    adjusted p after Holm's correction over the steps (one family)."""
    steps = {}
    for label, chamber, before, after, groups in STEPS:
        a, b = st.values(before), st.values(after)
        st.command(groups, before, after)
        steps[label] = dict(label=label, chamber=chamber, before=before, after=after, groups=groups, a=a, b=b,
                            c=compare(a, b))
    for step, p in zip(steps.values(), holm([t["c"]["p"] for t in steps.values()])):
        step["holm"] = p
    return steps


def rise_tests(st):
    """{label: rise} over the settings of W40_SETTINGS whose tests' bins were kept: the fourth D_c's q_c
    against the third's by the one rule, with its adjusted p after Holm's correction over them (one family)."""
    rises = {}
    for label, pattern in W40_SETTINGS:
        if st.bin(pattern, "3"):
            rises[label] = dict(label=label, pattern=pattern, c=compare(st.bin(pattern, "2"), st.bin(pattern, "3")))
    for rise, p in zip(rises.values(), holm([r["c"]["p"] for r in rises.values()])):
        rise["holm"] = p
    return rises


def up(c):
    return c["resolved"] == "yes" and c["change"] > 0


class Findings:
    """What the page's opening line and conclusions say, each from the CSVs by the one rule."""

    def __init__(self, folder):
        self.st = st = Study(folder)
        self.steps, self.rises = step_tests(st), rise_tests(st)
        self.w40, self.w50, self.below = W40 + "_s?", "refined_N34_pristine_w50_s?", W40 + "_below5_s?"
        self.q = st.values(self.w40)
        self.width = self.steps["width 40 -> 50 D_c"]
        self.step_before = self.steps["width 30 -> 40 D_c"]
        self.base = self.steps["sand below the tip 2.5 -> 5 D_c"]
        self.denser = compare(st.porosity("w40"), st.porosity("below5"))
        self.resolved_rises = [r for r in self.rises.values() if r["c"]["resolved"] == "yes"]
        self.holm_rises = [r for r in self.resolved_rises if r["holm"] < 0.05]
        self.dense100 = [r for label, r in self.rises.items() if label.startswith("dense, 100 kPa")]
        self.default_binned = bool(st.bin(self.w40, "3"))

    def width_words(self):
        """How far the width study converged: by the last step and whether its interval admits the one before."""
        c, before = self.width["c"], self.step_before["c"]
        if c["resolved"] == "yes":
            return "not converged"
        return "only weakly" if c["high"] >= before["change"] else "by the rule"

    def not_shown(self):
        """The directions in which the default q_c is not shown converged (the conclusions' rows)."""
        out = ["in the base (row 4)"] if up(self.base["c"]) else []
        # an unresolved rise does not show a steady state either: no test here shows one (row 5)
        return out + ["in depth (row 5)"]


def answer_penetration(folder):
    """The page's answer under its title: the default q_c with its interval, and how far it is converged."""
    f = Findings(folder)
    shown = f.not_shown()
    return ("**The answer**: the default scene's chamber, dense at 100 kPa, gives q_c = %s MPa over 2 - 4 D_c "
            "(%d seeds). It is not shown converged %s, and in width %s (row 2)." % (
                cell(f.q.values(), 2), len(f.q), " or ".join(shown), f.width_words()))


def conclusions_penetration(folder):
    """The study's answers, each from the runs' CSVs."""
    f = Findings(folder)
    st, q, w40, w50, below = f.st, f.st.values, f.w40, f.w50, f.below
    n_steps, n_rises = len(f.steps), len(f.rises)
    family = "%d steps" % n_steps

    def step_words(label):
        t = f.steps[label]
        return resolved_words(t["c"], t["holm"], family)

    fine5, fine10 = "refined_N34_pristine_region_s?", "refined_N17_pristine_s?"
    resolution = f.steps["D_c / d50 5 -> 10"]["c"]
    width, before, base = f.width["c"], f.step_before["c"], f.base["c"]
    crush100 = f.steps["no crushing -> crushing in the zone, 100 kPa"]["c"]
    crush400 = f.steps["no crushing -> crushing in the zone, 400 kPa"]["c"]
    weak_none, weak_zone = W40 + "_weak_0_s?", W40 + "_weak_region_s?"
    weak = f.steps["no crushing -> crushing in the zone, weak grains"]["c"]
    weak_share = paired(q(weak_none), q(weak_zone), lambda a, b: b / a)
    pile100 = paired(q(w40), q(W40 + "_pile_s?"), lambda a, b: b / a)
    pile400 = paired(q(W40 + "_dense_400kPa_s?"), q(W40 + "_pile_400kPa_s?"), lambda a, b: b / a)
    pile_text, pile_up = ratio_cell(pile100.values())
    power = lambda low, high: paired(q(low), q(high), lambda a, b: math.log(b / a) / math.log(4))  # noqa: E731
    n40 = power(w40, W40 + "_dense_400kPa_s?")
    n10 = power(fine5, "refined_N34_pristine_dense_400kPa_s?")
    n40_text, n40_below = ratio_cell(n40.values(), 3)
    walls = compare(n10, n40)
    ranks = "/".join(sorted({r["ranks"] for r in st.cases(w40).values()}))
    depth_seeds = "/".join(sorted({str(len(st.cases(r["pattern"]))) for r in f.rises.values()}))
    # each sentence follows its measure: what the rule resolves, and which way
    if width["resolved"] == "yes":
        width_text = "q_c still changes, so the width is not converged"
    elif width["high"] >= before["change"]:
        width_text = "no resolved change, but the interval admits a step as large as 30 -> 40 D_c's, so the width " \
            "is not shown converged"
    else:
        width_text = "no resolved change, and the interval excludes a step as large as 30 -> 40 D_c's"
    denser = f.denser["resolved"] == "yes" and f.denser["change"] < 0
    if up(base):
        base_text = "q_c rises%s%s; the base is not shown converged%s" % (
            "" if f.base["holm"] < 0.05 else " (not after Holm's correction over the steps)",
            ", in chambers that also pack denser" if denser else "",
            ", and the two effects are not separated" if denser else "")
    else:
        base_text = "no resolved rise of q_c" if base["resolved"] != "yes" else "q_c falls"
    k, k_holm = len(f.resolved_rises), len(f.holm_rises)
    if k:
        depth_text = "q_c still rises over the fourth D_c in %d of %d settings (%s after Holm's correction over " \
            "the %d)" % (k, n_rises, count_words(k_holm), n_rises)
    else:
        depth_text = "the rise of q_c over the fourth D_c is resolved in none of %d settings" % n_rises
    dense_up = sum(r["c"]["resolved"] == "yes" for r in f.dense100)
    if f.dense100:
        depth_text += "; in the dense 100 kPa settings the rise is %s" % (
            "not resolved" if not dense_up else "resolved in %d of %d" % (dense_up, len(f.dense100)))
    if not f.default_binned:
        depth_text += ", and the default scene's bins were not kept by seed"
    depth_text += ". A steady state by 4 D_c is neither shown reached nor shown not reached"
    def survivor_cell(r):
        return "%s: %s MPa (adj. p %.3f)" % (r["label"], interval_cell(r["c"], 2), r["holm"])

    def rise_cell(r):
        return "%s: %s MPa, %s" % (r["label"], interval_cell(r["c"], 2), resolved_words(r["c"]))

    shown = f.not_shown()
    seconds = dict((r["case"], float(r["seconds"]) / 60.0) for r in st.cases(w40).values())
    alone = sorted((m, case) for case, m in seconds.items() if case not in W40_SHARED)
    shared = sorted((m, case) for case, m in seconds.items() if case in W40_SHARED)
    prepared = [float(r["prepared_s"]) / 60.0 for r in st.chambers["w40"].values()]
    notes = sorted({r["note"] for r in st.chambers["w40"].values()})
    suffix = lambda case: "`_%s`" % case.rsplit("_", 1)[1]  # noqa: E731
    rows = [
        ("The default scene's chamber, dense at 100 kPa, gives this q_c over 2 - 4 D_c. It is not shown converged "
         "%s, and in width %s (row 2)." % (" or ".join(shown), f.width_words()),
         "q_c %s MPa" % cell(f.q.values(), 2), st.runs(w40), st.command(["pristine_wider"], w40)),
        ("Widening the chamber from 40 to 50 D_c: %s." % width_text,
         "%s MPa, %s; 30 -> 40 D_c: %s MPa, %s" % (interval_cell(width, 2), step_words("width 40 -> 50 D_c"),
                                                  interval_cell(before, 2), step_words("width 30 -> 40 D_c")),
         st.runs(w40, w50), st.command(["pristine_wider"], w40, w50)),
        ("Ten grains across the cone instead of five (D_c / d50): %s, in chambers 10 D_c wide."
         % ("no resolved change of q_c" if resolution["resolved"] != "yes" else "q_c changes"),
         "%s MPa, %s" % (interval_cell(resolution, 2), step_words("D_c / d50 5 -> 10")), st.runs(fine5, fine10),
         st.command(["pristine_resolution"], fine5, fine10)),
        ("Twice the sand below the final tip (5 D_c, not 2.5): %s." % base_text,
         "%s MPa, %s; porosity after the consolidation, 2.5 D_c below: %s, 5 D_c below: %s, change %s, %s" % (
             interval_cell(base, 2), step_words("sand below the tip 2.5 -> 5 D_c"),
             cell(st.porosity("w40").values(), 4), cell(st.porosity("below5").values(), 4),
             interval_cell(f.denser, 4), resolved_words(f.denser)),
         st.runs(w40, below), st.command(["pristine_base"], w40, below)),
        ("%s." % depth_text,
         "rise resolved in %d of %d settings, %s after Holm%s; %s" % (
             k, n_rises, count_words(k_holm), (": " + "; ".join(survivor_cell(r) for r in f.holm_rises))
             if f.holm_rises else "",
             "; ".join(rise_cell(r) for r in f.dense100)),
         "%d settings, %s seeds each (the table below)" % (n_rises, depth_seeds),
         st.command(W40_GROUPS, *[r["pattern"] for r in f.rises.values()]) + " && " + DEPTH_COMMAND),
        ("In quartz-strength grains crushing in the zone %s of q_c against the uncrushable reference."
         % ("leaves no resolved change" if "yes" not in (crush100["resolved"], crush400["resolved"])
            else "makes a change"),
         "100 kPa: %s MPa, %s; 400 kPa: %s MPa, %s" % (
             interval_cell(crush100, 2), step_words("no crushing -> crushing in the zone, 100 kPa"),
             interval_cell(crush400, 2), step_words("no crushing -> crushing in the zone, 400 kPa")),
         st.runs(W40 + "_below5_0_s?", below, W40 + "_0_400kPa_s?", W40 + "_dense_400kPa_s?"),
         st.command(["pristine_reference_w40", "pristine_w40_400kPa"], W40 + "_below5_0_s?", below,
                    W40 + "_0_400kPa_s?", W40 + "_dense_400kPa_s?")),
        ("In grains ten times weaker crushing in the zone %s q_c." % (
            "lowers" if weak["resolved"] == "yes" and weak["change"] < 0 else "does not resolvably lower"),
         "%s MPa, %s; with crushing over without: %s" % (
             interval_cell(weak, 2), step_words("no crushing -> crushing in the zone, weak grains"),
             cell(weak_share.values(), 2)),
         st.runs(weak_none, weak_zone), st.command(["pristine_weak_w40"], weak_none, weak_zone)),
        ("The closed-ended pile's base resistance q_b %s the cone's q_c in the same chambers."
         % ("exceeds" if pile_up else "is not resolved from"),
         "q_b / q_c, 100 kPa: %s; 400 kPa: %s" % (pile_text, ratio_cell(pile400.values())[0]),
         st.runs(w40, W40 + "_pile_s?", W40 + "_dense_400kPa_s?", W40 + "_pile_400kPa_s?"),
         st.command(["pristine_wider", "pristine_pile_w40", "pristine_w40_400kPa"], w40, W40 + "_pile_s?",
                    W40 + "_dense_400kPa_s?", W40 + "_pile_400kPa_s?")),
        ("From 100 to 400 kPa q_c grows as sigma_v^n, n %s 1; %s." % (
            "below" if n40_below else "not resolved from",
            "the walls of a chamber 10 D_c wide raise n" if walls["resolved"] == "yes" and walls["change"] < 0
            else "a chamber 10 D_c wide gives no resolved change of n"),
         "n, 40 D_c: %s; 10 D_c: %s; 40 less 10 D_c: %s, %s" % (n40_text, cell(n10.values(), 3),
                                                              interval_cell(walls, 3), resolved_words(walls)),
         st.runs(w40, W40 + "_dense_400kPa_s?", fine5, "refined_N34_pristine_dense_400kPa_s?"),
         st.command(["pristine_stress_w40", "pristine_stress"], w40, W40 + "_dense_400kPa_s?", fine5,
                    "refined_N34_pristine_dense_400kPa_s?")),
        ("A test of the default scene takes this long on %s ranks of the study's machine; its chamber is timed "
         "apart." % ranks,
         "test alone on the cores: %s; sharing them for part of its time: %s; the chamber: %.1f - %.1f min (%s)" % (
             ", ".join("%.1f min (%s)" % (m, suffix(case)) for m, case in alone) or "none",
             ", ".join("%.1f min (%s)" % (m, suffix(case)) for m, case in shared) or "none",
             min(prepared), max(prepared), "; ".join(n for n in notes if n) or "alone"),
         st.runs(w40), st.command(["pristine_wider"], w40)),
    ]
    return conclusions(rows)


# The steps each study took (label, chamber, from, to: patterns of cases) and the groups that run them
STEPS = [
    ("width 10 -> 20 D_c", "pristine, D_c / d50 = 5", "refined_N34_pristine_region_s?", "refined_N34_pristine_w20_s?",
     ["pristine_width"]),
    ("width 20 -> 30 D_c", "pristine, D_c / d50 = 5", "refined_N34_pristine_w20_s?", "refined_N34_pristine_w30_s?",
     ["pristine_width"]),
    ("width 30 -> 40 D_c", "pristine, D_c / d50 = 5", "refined_N34_pristine_w30_s?", W40 + "_s?",
     ["pristine_width", "pristine_wider"]),
    ("width 40 -> 50 D_c", "pristine, D_c / d50 = 5", W40 + "_s?", "refined_N34_pristine_w50_s?", ["pristine_wider"]),
    ("D_c / d50 5 -> 10", "pristine, 10 D_c wide", "refined_N34_pristine_region_s?", "refined_N17_pristine_s?",
     ["pristine_resolution"]),
    ("sand below the tip 2.5 -> 5 D_c", "pristine, 40 D_c wide", W40 + "_s?", W40 + "_below5_s?", ["pristine_base"]),
    ("v halved", "Table 3 reading, D_c / d50 = 5, 10 D_c wide", "refined_N34_w10_s?", "refined_N34_half_s?",
     ["halving"]),
    ("quarter -> whole chamber", "Table 3 reading, D_c / d50 = 5, 10 D_c wide", "refined_N34_w10_s?",
     "refined_N34_whole_s?", ["whole_refined"]),
    ("no crushing -> crushing in the zone, 100 kPa", "pristine, 40 D_c wide, 5 D_c below", W40 + "_below5_0_s?",
     W40 + "_below5_s?", ["pristine_reference_w40"]),
    ("no crushing -> crushing in the zone, 400 kPa", "pristine, 40 D_c wide", W40 + "_0_400kPa_s?",
     W40 + "_dense_400kPa_s?", ["pristine_w40_400kPa"]),
    ("no crushing -> crushing in the zone, weak grains", "pristine, 40 D_c wide", W40 + "_weak_0_s?",
     W40 + "_weak_region_s?", ["pristine_weak_w40"]),
    ("crushing in the zone -> everywhere, weak grains", "pristine, 40 D_c wide", W40 + "_weak_region_s?",
     W40 + "_weak_1_s?", ["pristine_weak_w40", "pristine_weak_w40_everywhere"]),
]


def penetration_steps(folder):
    steps = step_tests(Study(folder))
    lines = ["| step | chamber | runs | q_c before (MPa) | q_c after (MPa) | change (MPa, 95% interval) | resolved | "
             "after Holm (adj. p) | design | group |", "|" + "---|" * 10]
    for t in steps.values():
        c = t["c"]
        lines.append("| %s | %s | %d, %d | %s | %s | %s | %s | %s (%.3f) | %s | `%s` |" % (
            t["label"], t["chamber"], len(t["a"]), len(t["b"]), cell(t["a"].values(), 2), cell(t["b"].values(), 2),
            interval_cell(c, 2), c["resolved"], "yes" if c["resolved"] == "yes" and t["holm"] < 0.05 else "no",
            t["holm"], c["design"], " ".join(t["groups"])))
    resolved = sum(t["c"]["resolved"] == "yes" for t in steps.values())
    survive = sum(t["c"]["resolved"] == "yes" and t["holm"] < 0.05 for t in steps.values())
    return "\n".join(lines) + "\n\n(%d steps: %d resolved; %s after Holm's correction over the %d.)" % (
        len(steps), resolved, count_words(survive), len(steps))


# The settings of the default scene's chamber, 40 D_c wide (dense, 100 kPa, crushing in the zone,
# 2.5 D_c below the final tip unless a label says otherwise), and the groups that run them
W40_SETTINGS = [
    ("dense, 100 kPa (the default scene)", W40 + "_s?"),
    ("dense, 100 kPa, 5 D_c below", W40 + "_below5_s?"),
    ("dense, 100 kPa, 5 D_c below, no crushing", W40 + "_below5_0_s?"),
    ("dense, 200 kPa", W40 + "_dense_200kPa_s?"),
    ("dense, 400 kPa", W40 + "_dense_400kPa_s?"),
    ("dense, 400 kPa, no crushing", W40 + "_0_400kPa_s?"),
    ("loose, 100 kPa", W40 + "_loose_100kPa_s?"),
    ("loose, 200 kPa", W40 + "_loose_200kPa_s?"),
    ("loose, 400 kPa", W40 + "_loose_400kPa_s?"),
    ("pile (q_b), 100 kPa", W40 + "_pile_s?"),
    ("pile (q_b), 400 kPa", W40 + "_pile_400kPa_s?"),
    ("weak grains, crushing in the zone", W40 + "_weak_region_s?"),
    ("weak grains, no crushing", W40 + "_weak_0_s?"),
    ("weak grains, crushing everywhere", W40 + "_weak_1_s?"),
]
W40_GROUPS = ["pristine_base", "pristine_stress_w40", "pristine_w40_400kPa", "pristine_reference_w40",
              "pristine_pile_w40", "pristine_weak_w40", "pristine_weak_w40_everywhere"]


def penetration_w40(folder):
    st = Study(folder)
    st.command(W40_GROUPS, *[p for _, p in W40_SETTINGS])
    rises = rise_tests(st)
    lines = ["| setting | case | seeds | q_c (MPa), 2 - 4 D_c | 1 - 2 D_c | 2 - 3 D_c | 3 - 4 D_c | "
             "3 - 4 less 2 - 3 D_c | events in the test | test (minutes: median, range) |", "|" + "---|" * 10]
    for label, pattern in W40_SETTINGS:
        bins = [st.bin(pattern, b) for b in DEPTH_BINS]
        if label in rises:
            c, p_holm = rises[label]["c"], rises[label]["holm"]
            rise = interval_cell(c, 2) + ("" if c["resolved"] != "yes" else "**" if p_holm < 0.05 else "*")
        else:
            rise = "per-seed bins not kept"
        lines.append("| %s | `%s` | %d | %s | %s | %s | %s | %s | %s | %s |" % (
            label, pattern, len(st.cases(pattern)), cell(st.values(pattern).values(), 2),
            *[cell(b.values(), 2) for b in bins], rise, cell(st.values(pattern, "events").values(), 0),
            spread_cell(st.values(pattern, "seconds", 1 / 60.0).values())))
    resolved = sum(r["c"]["resolved"] == "yes" for r in rises.values())
    survive = sum(r["c"]["resolved"] == "yes" and r["holm"] < 0.05 for r in rises.values())
    return "\n".join(lines) + "\n\n('*' resolved: the 95%% interval of the change over the seeds excludes zero; '**' " \
        "also after Holm's correction over the %d rises. %d resolved, %s after Holm.)" % (
            len(rises), resolved, count_words(survive))


TABLES = {"answer_penetration": answer_penetration, "conclusions_penetration": conclusions_penetration,
          "penetration_steps": penetration_steps, "penetration_w40": penetration_w40}
