#!/usr/bin/python3
"""What a geotechnical engineer reads from a cone penetration test: the normalised cone resistance
Q_tn, the friction ratio F_r, the soil behaviour type index I_c and its zone, and the relative
density that the chamber-test correlations of silica sands give, for each setting of a penetration
study (scripts/penetration_study.sh's study.csv, the settings as post/penetration_stats.py groups
them), with the mean and standard error over the seeds.

    post/cpt_interpretation.py study.csv [more.csv ...] [--cases PATTERN] [--K 1.0] [--markdown] [--csv OUT]
                               [--plot OUT.png]

The chamber is dry: q_t = q_c, sigma_v0 = sigma'_v0 = sigma_v, the stress the cone meets: the study's
sigma_v_axis where it has one (the vertical stress of the column about the axis, r < 2 D_c, measured
before the test from in.cone's first stress dump: the refined chamber's fine column carries less
than its top wall), else the top wall's nominal sigma_v (a warning names those rows); the mean stress sigma'_m = sigma_v (1 + 2 K) / 3 (in.chamber's K, 1 by default). Per test:
  F_r  = f_s / (q_t - sigma_v0) x 100 %
  Q_tn = ((q_t - sigma_v0) / p_a) (p_a / sigma'_v0)^n,  p_a = 100 kPa,
         n = 0.381 I_c + 0.05 sigma'_v0 / p_a - 0.15 (at most 1), iterated with I_c to a fixed point
  I_c  = ((3.47 - log10 Q_tn)^2 + (log10 F_r + 1.22)^2)^0.5, and its zone: 7 below 1.31 (gravelly
         sand to dense sand), 6 to 2.05 (clean sand to silty sand), 5 to 2.60, 4 to 2.95, 3 to 3.60,
         2 above (Robertson 2009, as the Settle3 theory manual and the groundhog library state them)
  D_r  Baldi et al. (1986), normally consolidated Ticino sand: (1 / 2.41) ln(q_c / (157 sigma'_v0^0.55)),
         q_c and sigma'_v0 in kPa (as the Datgel CPT Tool guide and groundhog state it)
  D_r  Jamiolkowski et al. (2003), dry sand: (1 / 2.96) ln((q_c / p_a) / (24.94 (sigma'_m / p_a)^0.46))
         (groundhog; the same in kPa, C0 = 300, in the BlueDrop documentation)
D_r is printed as the correlation gives it, below 0 or above 1 too: the correlations were fitted
over D_r of about 0.2 - 1 and stresses of 50 - 400 kPa.
"""
import argparse
import csv
import fnmatch
import math
import os
import sys

if not __package__:  # run as a file (python3 post/cpt_interpretation.py): the folder above post/ holds the package
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from post import penetration_stats, requires  # noqa: E402
from post.seeds import t_quantile  # noqa: E402

P_A = 100.0  # kPa
ZONES = [(1.31, 7), (2.05, 6), (2.60, 5), (2.95, 4), (3.60, 3), (float("inf"), 2)]
ZONE_NAMES = {7: "gravelly sand to dense sand", 6: "clean sand to silty sand", 5: "silty sand to sandy silt",
              4: "clayey silt to silty clay", 3: "clay", 2: "organic soil"}


def friction_ratio(q_t, f_s, sigma_v0):
    """F_r (%) of q_t, f_s and sigma_v0 in one unit."""
    return 100.0 * f_s / (q_t - sigma_v0)


def index_of(q_tn, f_r):
    """Robertson's soil behaviour type index I_c."""
    return math.hypot(3.47 - math.log10(q_tn), math.log10(f_r) + 1.22)


def normalised(q_t, f_s, sigma_v0, sigma_v0_eff):
    """(Q_tn, F_r, I_c, n) of one test (kPa): n and I_c iterated to their fixed point from n = 1."""
    f_r = friction_ratio(q_t, f_s, sigma_v0)
    n = 1.0
    for _ in range(100):
        q_tn = (q_t - sigma_v0) / P_A * (P_A / sigma_v0_eff) ** n
        i_c = index_of(q_tn, f_r)
        n_next = min(1.0, 0.381 * i_c + 0.05 * sigma_v0_eff / P_A - 0.15)
        if abs(n_next - n) < 1e-9:
            break
        n = n_next
    return q_tn, f_r, i_c, n


def zone(i_c):
    return next(z for top, z in ZONES if i_c < top)


def dr_baldi(q_c, sigma_v0_eff):
    """D_r of Baldi et al. (1986), normally consolidated Ticino sand (kPa)."""
    return math.log(q_c / (157.0 * sigma_v0_eff ** 0.55)) / 2.41


def dr_jamiolkowski(q_c, sigma_m_eff):
    """D_r of Jamiolkowski et al. (2003), dry sand, from the mean stress (kPa)."""
    return math.log((q_c / P_A) / (24.94 * (sigma_m_eff / P_A) ** 0.46)) / 2.96


def interpret(row, K):
    """The measures of one study row: q_c (MPa), Q_tn, F_r (%), I_c, n, D_r by both correlations."""
    # the stress the cone meets: the fine column's measured sigma_zz before the test where the study
    # has it (sigma_v_axis, Pa), else the top wall's nominal sigma_v
    q_c, f_s = float(row["q_c_MPa"]) * 1e3, float(row["f_s_kPa"])
    sigma_v = float(row.get("sigma_v_axis") or row["sigma_v"]) / 1e3
    q_tn, f_r, i_c, n = normalised(q_c, f_s, sigma_v, sigma_v)
    return {"q_c_MPa": q_c / 1e3, "q_c_over_sigma_v": q_c / sigma_v, "Q_tn": q_tn, "F_r": f_r, "I_c": i_c, "n": n,
            "D_r_Baldi": dr_baldi(q_c, sigma_v), "D_r_Jamiolkowski": dr_jamiolkowski(q_c, sigma_v * (1 + 2 * K) / 3)}


MEASURES = ["q_c_MPa", "q_c_over_sigma_v", "Q_tn", "F_r", "I_c", "n", "D_r_Baldi", "D_r_Jamiolkowski"]


def table(rows, K):
    """[(setting, {measure: (n, mean, sd, se)}, zone of the mean I_c, cases)] per setting, one row per seed."""
    out = []
    for setting, members in penetration_stats.groups(rows).items():
        values = [interpret(r, K) for r in members]
        stats = dict((m, penetration_stats.statistics([v[m] for v in values])) for m in MEASURES)
        out.append((setting, stats, zone(stats["I_c"][1]), [r["case"] for r in members]))
    return out


def draw(path, rows, K):
    """q_c against sigma'_v, each test a point and each setting's mean with its standard error, beside
    Baldi et al.'s (1986) q_c at D_r = 0.2, 0.5 and 0.9 (log axes: a power law is a line)."""
    requires("cpt_interpretation", "matplotlib")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.5, 5))
    stresses = [50.0 * 1.1 ** k for k in range(40) if 50.0 * 1.1 ** k < 600]
    for d_r, style in ((0.2, ":"), (0.5, "--"), (0.9, "-.")):
        ax.loglog(stresses, [157.0 * s ** 0.55 * math.exp(2.41 * d_r) / 1e3 for s in stresses], style, color="grey",
                  label="Baldi et al. (1986), D_r = %.1f" % d_r)
    colours = {}
    result = table(rows, K)
    # the legend names the fields that tell the plotted settings apart (the stress is the axis)
    fields = penetration_stats.SETTING
    same = [f for k, f in enumerate(fields) if f == "sigma_v" or len({s[k] for s, _, _, _ in result}) == 1]
    for setting, stats, _, cases in result:
        # one colour for the settings that differ in the stress alone
        name = penetration_stats.label(setting, skip=same) or "the tests"
        first = name not in colours
        colour = colours.setdefault(name, "C%d" % (len(colours) % 10))
        members = [r for r in rows if r["case"] in cases]
        x = [float(r["sigma_v"]) / 1e3 for r in members]
        ax.loglog(x, [float(r["q_c_MPa"]) for r in members], "o", color=colour, alpha=0.4, ms=4)
        n = stats["q_c_MPa"][0]
        half = t_quantile(n - 1) * stats["q_c_MPa"][3] if n > 1 else 0.0
        ax.errorbar([x[0]], [stats["q_c_MPa"][1]], yerr=[half], fmt="s", color=colour, capsize=3,
                    label=name if first else None)
    ax.set_xlabel("sigma'_v (kPa)")
    ax.set_ylabel("q_c (MPa)")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7, loc="lower right")
    ax.set_title("q_c: each test, and the mean with its 95% t interval")
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("studies", nargs="+", help="study.csv files of scripts/penetration_study.sh")
    parser.add_argument("--cases", default="*", help="only the cases whose names match one of these patterns"
                        " (fnmatch, comma-separated)")
    parser.add_argument("--K", type=float, default=1.0, help="the chamber's K = sigma_h / sigma_v (in.chamber's K)")
    parser.add_argument("--markdown", action="store_true", help="the table in markdown")
    parser.add_argument("--csv", help="write the table here too")
    parser.add_argument("--plot", help="draw q_c against sigma'_v beside Baldi et al.'s D_r lines here")
    a = parser.parse_args()
    rows = []
    for path in a.studies:
        with open(path) as f:
            rows += [r for r in csv.DictReader(f) if any(fnmatch.fnmatch(r["case"], p) for p in a.cases.split(","))]
    if not rows:
        sys.exit("cpt_interpretation.py: no case matches %s in %s" % (a.cases, " ".join(a.studies)))
    whole = [r["case"] for r in rows if not r.get("sleeve_in")]
    if whole:
        # f_s of a test run before in.cone divided by the sleeve's length in the sand: F_r reads low
        sys.stderr.write("cpt_interpretation.py: warning: %s: f_s over the whole sleeve (no sleeve_in: run before in.cone "
                         "divided by the embedded length); F_r and I_c read low where the sleeve was partly above the "
                         "sand\n" % ", ".join(whole))
    nominal = [r["case"] for r in rows if not r.get("sigma_v_axis")]
    if nominal:
        sys.stderr.write("cpt_interpretation.py: warning: %s: normalised by the top wall's nominal sigma_v (no "
                         "sigma_v_axis: run without a stress dump); the column about the cone may carry less\n"
                         % ", ".join(nominal))
    piles = [r["case"] for r in rows if (r.get("tip_shape") or "cone") != "cone"]
    if piles:
        # a flat base's q_c column is the pile's base resistance q_b: the CPT's correlations do not apply
        sys.exit("cpt_interpretation.py: %s %s a flat tip (tip_shape flat: the column q_c is a pile's base "
                 "resistance q_b, not a cone's q_c); name the cone tests alone with --cases"
                 % (", ".join(piles), "has" if len(piles) == 1 else "have"))
    result = table(rows, a.K)
    head = ["setting", "seeds"] + ["%s (se)" % m for m in MEASURES] + ["zone"]
    sep = " | " if a.markdown else "  "
    print(("| " if a.markdown else "") + sep.join(head) + (" |" if a.markdown else ""))
    if a.markdown:
        print("|" + "---|" * len(head))
    for setting, stats, z, _ in result:
        cells = [penetration_stats.label(setting), "%d" % stats["q_c_MPa"][0]]
        cells += ["%.3g (%.2g)" % (stats[m][1], stats[m][3]) for m in MEASURES]
        cells += ["%d (%s)" % (z, ZONE_NAMES[z])]
        print(("| " if a.markdown else "") + sep.join(cells) + (" |" if a.markdown else ""))
    if a.plot:
        draw(a.plot, rows, a.K)
    if a.csv:
        with open(a.csv, "w") as f:
            f.write(",".join(["setting", "seeds", "cases"] + ["%s%s" % (m, s) for m in MEASURES for s in ("", "_se")]
                             + ["zone"]) + "\n")
            for setting, stats, z, cases in result:
                f.write(",".join(['"%s"' % penetration_stats.label(setting), "%d" % stats["q_c_MPa"][0], ";".join(cases)]
                                 + ["%.6g,%.6g" % (stats[m][1], stats[m][3]) for m in MEASURES] + ["%d" % z]) + "\n")


if __name__ == "__main__":
    main()
