"""Cone and pile penetration (studies/penetration/README.md): the study's conclusions, the steps that
say how far the default chamber is converged and what crushing changes, and the settings of the
chamber 40 D_c wide with q_c by depth. From scripts/penetration_study.sh's study.csv rows
(penetration_study.csv, penetration_refined.csv) and post/penetration_depth.py's bins
(penetration_depth.csv); each command is checked against cases.csv, whose groups must hold every
case its row rests on."""
import fnmatch
import math
import os
import statistics as py_statistics

from post.seeds import compare, interval, statistics
from post.study_tables.common import cell, conclusions, interval_cell, read_rows

PAGE = "studies/penetration/README.md"
OUT = "runs/refined"  # the runner's OUT_DIR in the commands the tables give
DEPTH_BINS = ("1", "2", "3")  # the bins from 1, 2 and 3 D_c (each 1 D_c deep) of penetration_depth.csv
W40 = "refined_N34_pristine_w40"  # the default scene's chamber: pristine, D_c / d50 = 5, 40 D_c wide


class Study:
    """The study's runs, one row a case, and the depth bins of each case's test."""

    def __init__(self, folder):
        self.folder = folder
        self.rows = read_rows(os.path.join(folder, "penetration_study.csv")) + \
            read_rows(os.path.join(folder, "penetration_refined.csv"))
        self.depth = {}
        for r in read_rows(os.path.join(folder, "penetration_depth.csv")):
            self.depth.setdefault(r["case"], {})[r["from_Dc"]] = float(r["q_c_MPa"])
        self.groups = {}
        for r in read_rows(os.path.join(folder, "cases.csv")):
            for group in r["groups"].split():
                self.groups.setdefault(group, set()).add(r["case"])

    def cases(self, pattern):
        """The rows of the cases pattern names (fnmatch), the first of a seed kept; it must name some."""
        kept = {}
        for r in self.rows:
            if fnmatch.fnmatchcase(r["case"], pattern):
                kept.setdefault(r["seed"], r)
        if not kept:
            raise SystemExit("penetration tables: no run of %s in %s" % (pattern, self.folder))
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


def resolved_words(c):
    """'resolved' or 'not resolved', and how the one rule compared (paired by seed or Welch)."""
    return "%s (%s)" % ("resolved" if c["resolved"] == "yes" else "not resolved",
                        "paired" if c["design"].startswith("paired") else "Welch")


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


def conclusions_penetration(folder):
    """The study's answers, each from the runs' CSVs."""
    st = Study(folder)
    q = st.values
    w40, w50 = W40 + "_s?", "refined_N34_pristine_w50_s?"
    width = compare(q(w40), q(w50))
    fine5, fine10 = "refined_N34_pristine_region_s?", "refined_N17_pristine_s?"
    resolution = compare(q(fine5), q(fine10))
    below = W40 + "_below5_s?"
    base = compare(q(w40), q(below))
    rises = [compare(st.bin(p, "2"), st.bin(p, "3")) for _, p in W40_SETTINGS if st.bin(p, "3")]
    up = sum(c["change"] > 0 for c in rises)
    up_resolved = sum(c["change"] > 0 and c["resolved"] == "yes" for c in rises)
    crush100 = compare(q(W40 + "_below5_0_s?"), q(below))
    crush400 = compare(q(W40 + "_0_400kPa_s?"), q(W40 + "_dense_400kPa_s?"))
    weak_none, weak_zone = W40 + "_weak_0_s?", W40 + "_weak_region_s?"
    weak = compare(q(weak_none), q(weak_zone))
    weak_share = paired(q(weak_none), q(weak_zone), lambda a, b: b / a)
    pile100 = paired(q(w40), q(W40 + "_pile_s?"), lambda a, b: b / a)
    pile400 = paired(q(W40 + "_dense_400kPa_s?"), q(W40 + "_pile_400kPa_s?"), lambda a, b: b / a)
    pile_text, pile_up = ratio_cell(pile100.values())
    power = lambda low, high: paired(q(low), q(high), lambda a, b: math.log(b / a) / math.log(4))  # noqa: E731
    n40 = power(w40, W40 + "_dense_400kPa_s?")
    n10 = power(fine5, "refined_N34_pristine_dense_400kPa_s?")
    n40_text, n40_below = ratio_cell(n40.values(), 3)
    walls = compare(n10, n40)
    minutes = q(w40, "seconds", 1 / 60.0)
    ranks = "/".join(sorted({r["ranks"] for r in st.cases(w40).values()}))
    depth_seeds = "/".join(sorted({str(len(st.cases(p))) for _, p in W40_SETTINGS if st.bin(p, "3")}))
    # each sentence follows its measure: what the rule resolves, and which way
    ends = "no resolved change, so the width study ends at 40 D_c, weakly"
    quartz = "yes" not in (crush100["resolved"], crush400["resolved"])
    rows = [
        ("The default scene's chamber, dense at 100 kPa, gives this q_c over 2 - 4 D_c.",
         "q_c %s MPa" % cell(q(w40).values(), 2), st.runs(w40), st.command(["pristine_wider"], w40)),
        ("Widening the chamber from 40 to 50 D_c: %s." % (ends if width["resolved"] != "yes" else "q_c still changes"),
         "%s MPa, %s" % (interval_cell(width, 2), resolved_words(width)), st.runs(w40, w50),
         st.command(["pristine_wider"], w40, w50)),
        ("Ten grains across the cone instead of five (D_c / d50): %s, in chambers 10 D_c wide."
         % ("no resolved change of q_c" if resolution["resolved"] != "yes" else "q_c changes"),
         "%s MPa, %s" % (interval_cell(resolution, 2), resolved_words(resolution)), st.runs(fine5, fine10),
         st.command(["pristine_resolution"], fine5, fine10)),
        ("Twice the sand below the final tip (5 D_c, not 2.5): %s." % (
            "q_c rises, so the base study has not converged" if base["resolved"] == "yes" and base["change"] > 0
            else "no resolved rise of q_c" if base["resolved"] != "yes" else "q_c falls"),
         "%s MPa, %s" % (interval_cell(base, 2), resolved_words(base)), st.runs(w40, below),
         st.command(["pristine_base"], w40, below)),
        ("q_c has %sreached a steady state by 4 D_c: the fourth D_c against the third, at 40 D_c."
         % ("not " if up else ""),
         "the seeds' mean rises in %d of %d settings; the rise is resolved in %d" % (up, len(rises), up_resolved),
         "%d settings, %s seeds each (the table below)" % (len(rises), depth_seeds),
         st.command(W40_GROUPS, *[p for _, p in W40_SETTINGS if st.bin(p, "3")])),
        ("In quartz-strength grains crushing in the zone %s of q_c against the uncrushable reference."
         % ("leaves no resolved change" if quartz else "makes a change"),
         "100 kPa: %s MPa, %s; 400 kPa: %s MPa, %s" % (interval_cell(crush100, 2), resolved_words(crush100),
                                                        interval_cell(crush400, 2), resolved_words(crush400)),
         st.runs(W40 + "_below5_0_s?", below, W40 + "_0_400kPa_s?", W40 + "_dense_400kPa_s?"),
         st.command(["pristine_reference_w40", "pristine_w40_400kPa"], W40 + "_below5_0_s?", below,
                    W40 + "_0_400kPa_s?", W40 + "_dense_400kPa_s?")),
        ("In grains ten times weaker crushing in the zone %s q_c." % (
            "lowers" if weak["resolved"] == "yes" and weak["change"] < 0 else "does not resolvably lower"),
         "%s MPa, %s; with crushing over without: %s" % (interval_cell(weak, 2), resolved_words(weak),
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
        ("A test of the default scene, its chamber aside, takes this long on the study's machine.",
         "median (range) %s min a test on %s ranks" % (spread_cell(minutes.values()), ranks), st.runs(w40),
         st.command(["pristine_wider"], w40)),
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
    st = Study(folder)
    lines = ["| step | chamber | runs | q_c before (MPa) | q_c after (MPa) | change (MPa, 95% interval) | resolved | "
             "design | group |", "|---|---|---|---|---|---|---|---|---|"]
    for label, chamber, before, after, groups in STEPS:
        a, b = st.values(before), st.values(after)
        c = compare(a, b)
        st.command(groups, before, after)
        lines.append("| %s | %s | %d, %d | %s | %s | %s | %s | %s | `%s` |" % (
            label, chamber, len(a), len(b), cell(a.values(), 2), cell(b.values(), 2), interval_cell(c, 2),
            c["resolved"], c["design"], " ".join(groups)))
    return "\n".join(lines)


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
    lines = ["| setting | case | seeds | q_c (MPa), 2 - 4 D_c | 1 - 2 D_c | 2 - 3 D_c | 3 - 4 D_c | "
             "3 - 4 less 2 - 3 D_c | events in the test | test (min, median and range) |", "|" + "---|" * 10]
    for label, pattern in W40_SETTINGS:
        bins = [st.bin(pattern, b) for b in DEPTH_BINS]
        if bins[-1]:
            c = compare(bins[1], bins[2])
            rise = interval_cell(c, 2) + ("*" if c["resolved"] == "yes" else "")
        else:
            rise = "history not kept"
        lines.append("| %s | `%s` | %d | %s | %s | %s | %s | %s | %s | %s |" % (
            label, pattern, len(st.cases(pattern)), cell(st.values(pattern).values(), 2),
            *[cell(b.values(), 2) for b in bins], rise, cell(st.values(pattern, "events").values(), 0),
            spread_cell(st.values(pattern, "seconds", 1 / 60.0).values())))
    return "\n".join(lines) + "\n\n(* resolved: the 95% interval of the change over the seeds excludes zero.)"


TABLES = {"conclusions_penetration": conclusions_penetration, "penetration_steps": penetration_steps,
          "penetration_w40": penetration_w40}
