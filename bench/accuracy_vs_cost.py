#!/usr/bin/python3
"""Analysis of bench/accuracy_vs_cost.sh: every setting's runtime and its error against the
reference (the finest affordable setting), as a CSV, a Markdown table and two figures.

    bench/accuracy_vs_cost.py OUT_DIR

Errors, each the largest absolute difference from the reference:
  porosity   n against vertical stress, on a log grid from 0.2 to 100 MPa
  K0         K0 against vertical stress (5-row running mean), 1 to 100 MPa
  GSD        percent passing at 100 MPa, over the 11 sieves
  I_G        grading index against vertical stress, 1 to 100 MPa
  events     the crushing events to 100 MPa per initial grain (relative difference)
and the yield stress: where the two straight lines of e against log(sigma_v) fitted to 0.3-3 MPa
and to 50-100 MPa meet (its relative difference). A setting that changes one knob at N = 1.5 or 2
is also compared with the base setting of its own N (L_R 0.1, dmin 0.05 mm, dt fraction 0.5,
dt every 1, crush every 1, layout fourteen): that difference is the knob's alone, without the change
of sample that N brings. A setting is on the Pareto front of a measure when no other setting is both
as fast and closer to the reference in it; the table names the measures where each setting is.
A run stopped by the script's time limit is listed with the stress it reached and no errors.
Also reported: the smallest time step of the run and the physical time it covered. Writes OUT_DIR/accuracy_vs_cost.csv,
accuracy_vs_cost_table.md, pareto.png (error against runtime) and fig7_runtime.png (runtime against
initial particles, with the PFC3D runtimes of the paper's Table 3).
"""
import csv
import glob
import math
import os
import re
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from post import compression_seeds, plot  # noqa: E402

PAPER_PFC3D_MINUTES = {1304: 31.0, 3084: 67.0, 10397: 183.0}  # Table 3, O-2, O-1.5, O-1, one core
GRID = np.logspace(math.log10(2e5), 8, 60)


def read_csv(path):
    """post/plot.py's reader, columns as numpy arrays."""
    return {k: np.array(v) for k, v in plot.read_csv(path).items()}


def running_mean(values, width=5):
    if len(values) < width:
        return values
    kernel = np.ones(width) / width
    padded = np.concatenate([np.full(width // 2, values[0]), values, np.full(width // 2, values[-1])])
    return np.convolve(padded, kernel, mode="valid")


def on_grid(history, column, lo=2e5, smooth=False):
    """The column against log(vertical stress) on GRID (NaN outside the run's range or below lo)."""
    stress, values = history["sigma_z"], history[column]
    order = np.argsort(stress)
    stress, values = stress[order], values[order]
    if smooth:
        values = running_mean(values)
    out = np.interp(np.log(GRID), np.log(stress), values, left=np.nan, right=np.nan)
    out[GRID < lo] = np.nan
    return out


def yield_stress(history):
    """Intersection of the e - log10(sigma_v) lines fitted to 0.3-3 MPa and above 50 MPa (Pa):
    post/compression_seeds.py's reading of a compression curve."""
    return compression_seeds.yield_stress(history["sigma_z"], history["void_ratio"])


def load(folder):
    with open(os.path.join(folder, "setting.csv")) as f:
        setting = {k: [v] for k, v in next(csv.DictReader(f)).items()}  # one row, text
    name = os.path.basename(folder.rstrip("/"))
    history = read_csv(glob.glob(os.path.join(folder, "history_O*.csv"))[0])
    gsd_files = glob.glob(os.path.join(folder, "gsd_O*_100MPa.csv"))  # none in a run stopped before 100 MPa
    gsd = read_csv(gsd_files[0]) if gsd_files else None
    screen = open(os.path.join(folder, "screen.txt"), errors="replace").read()
    m = re.search(r"^SAMPLE N = \S+: (\d+) particles", screen, re.M)
    rss = re.search(r"Maximum resident set size \(kbytes\): (\d+)", open(os.path.join(folder, "time.txt")).read())
    checked = re.search(r"^CHECKED STEPS (\d+) OF (\d+)", screen, re.M)
    return {
        "name": name, "N": float(setting["N"][0]), "L_R": float(setting["L_R"][0]),
        "dmin_mm": float(setting["dmin_mm"][0]), "dt_fraction": float(setting["dt_fraction"][0]),
        "crush_every": str(setting["crush_every"][0]), "ranks": int(setting["ranks"][0]),
        # runs made before these knobs existed: step updated every step, the fourteen fragments, no limit
        "dt_every": int(setting["dt_every"][0]) if "dt_every" in setting else 1,
        "layout": str(setting["layout"][0]) if "layout" in setting else "fourteen",
        "fragment_density": str(setting["fragment_density"][0]) if "fragment_density" in setting else "true",
        "seed": str(setting["seed"][0]) if "seed" in setting else "15485863",
        "finished": int(setting["finished"][0]) if "finished" in setting else 1,
        "sigma_end_MPa": float(history["sigma_z"][-1]) / 1e6,
        "checked_percent": 100.0 * int(checked.group(1)) / int(checked.group(2)) if checked else float("nan"),
        "seconds": float(setting["seconds"][0]), "initial": int(m.group(1)) if m else 0,
        "final": int(history["particles"][-1]), "events": int(history["events"][-1]),
        "rss_mb": int(rss.group(1)) / 1024.0 if rss else float("nan"),
        "history": history, "gsd": gsd, "yield": yield_stress(history),
        "dt_min": float(np.min(history["dt"])), "time_end": float(history["time"][-1]),
    }


def errors(run, ref, suffix=""):
    def largest(column, lo=2e5, smooth=False):
        d = np.abs(on_grid(run["history"], column, lo, smooth) - on_grid(ref["history"], column, lo, smooth))
        return float(np.nanmax(d)) if np.any(~np.isnan(d)) else float("nan")
    out = {
        "err_porosity": largest("porosity"),
        "err_K0": largest("K0", lo=1e6, smooth=True),
        "err_gsd_percent": float(np.max(np.abs(run["gsd"]["percent_passing"] - ref["gsd"]["percent_passing"]))),
        "err_I_G": largest("I_G", lo=1e6),
        "err_yield_relative": abs(run["yield"] / ref["yield"] - 1.0),
        # events per initial grain (the paper's "broken" share): the grain count changes with N
        "err_events_relative": (abs(run["events"] * ref["initial"] / (ref["events"] * run["initial"]) - 1.0)
                                if ref["events"] and run["initial"] else float("nan")),
    }
    return {k + suffix: v for k, v in out.items()}


def is_base(r):
    return (r["L_R"] == 0.1 and r["dmin_mm"] == 0.05 and r["dt_fraction"] == 0.5 and r["crush_every"] == "1"
            and r["dt_every"] == 1 and r["layout"] == "fourteen" and r["fragment_density"] == "true")


ERRORS = ["err_porosity", "err_K0", "err_gsd_percent", "err_I_G", "err_yield_relative", "err_events_relative"]
FRONT = {"err_porosity": "n", "err_K0": "K0", "err_gsd_percent": "GSD", "err_I_G": "I_G",
         "err_events_relative": "events"}
COLUMNS = (["name", "N", "L_R", "dmin_mm", "dt_fraction", "dt_every", "crush_every", "layout", "ranks", "finished",
            "sigma_end_MPa", "initial", "final", "events", "checked_percent", "seconds", "speedup_vs_reference", "rss_mb",
            "dt_min", "time_end", "yield_MPa"] + ERRORS + [e + "_vs_base" for e in ERRORS] + ["pareto_front"])


def pareto_front(rows, key):
    """Names of the finished settings that no other is both at least as fast as and closer than in key."""
    done = [r for r in rows if r["finished"] and r["name"] != "reference" and not math.isnan(r.get(key, math.nan))]
    return {r["name"] for r in done
            if not any(o is not r and o["seconds"] <= r["seconds"] and o[key] < r[key] for o in done)}


def main(out):
    runs = [load(f) for f in sorted(glob.glob(os.path.join(out, "*", ""))) if os.path.exists(os.path.join(f, "done"))]
    ref = next((r for r in runs if r["name"] == "reference"), None)
    if ref is None:
        sys.exit("accuracy_vs_cost.py: no finished 'reference' run in " + out)
    bases = {r["N"]: r for r in runs if is_base(r) and r["finished"]}
    rows = []
    for r in runs:
        row = {k: r[k] for k in COLUMNS if k in r}
        row["speedup_vs_reference"] = ref["seconds"] / r["seconds"]
        if r["finished"]:
            row.update(errors(r, ref))
            base = bases.get(r["N"])
            if base is not None and base is not r and r["name"] != "reference":
                row.update(errors(r, base, "_vs_base"))
            row["yield_MPa"] = r["yield"] / 1e6
        rows.append(row)
    fronts = {key: pareto_front(rows, key) for key in FRONT}
    for row in rows:
        row["pareto_front"] = " ".join(label for key, label in FRONT.items() if row["name"] in fronts[key])
    with open(os.path.join(out, "accuracy_vs_cost.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=COLUMNS)
        w.writeheader()
        for row in rows:
            w.writerow({k: ("%.4g" % row[k] if isinstance(row.get(k), float) else row.get(k, "")) for k in COLUMNS})
    table = ["| setting | N | L_R | dmin (mm) | dt fraction | dt every | crush every | layout | particles (initial, final) "
             "| events | runtime (s) | speed-up | smallest dt (s) | max dn | max dK0 | max dGSD (%) | max dI_G | d events (%) "
             "| yield (MPa) | vs own-N base: dn, dK0, dGSD, dI_G, d events (%) | on the Pareto front of |",
             "|" + "---|" * 21]
    for r in rows:
        setting = "| %s | %g | %g | %s | %g | %d | %s | %s | %d, %d | %d | " % (
            r["name"], r["N"], r["L_R"], "none" if r["dmin_mm"] == 0 else "%g" % r["dmin_mm"], r["dt_fraction"],
            r["dt_every"], r["crush_every"], r["layout"], r["initial"], r["final"], r["events"])
        if not r["finished"]:
            table.append(setting + "stopped at %.0f, at %.1f MPa | | %.2g |%s" % (r["seconds"], r["sigma_end_MPa"], r["dt_min"],
                                                                               " |" * 8))
            continue
        vs_base = ("%.4f, %.3f, %.2f, %.4f, %.0f" % (r["err_porosity_vs_base"], r["err_K0_vs_base"], r["err_gsd_percent_vs_base"],
                                                    r["err_I_G_vs_base"], 100 * r["err_events_relative_vs_base"])
                   if "err_porosity_vs_base" in r else "")
        table.append(setting + "%.0f | %.1f | %.2g | %.4f | %.3f | %.2f | %.4f | %.0f | %.1f | %s | %s |" % (
            r["seconds"], r["speedup_vs_reference"], r["dt_min"], r["err_porosity"], r["err_K0"], r["err_gsd_percent"],
            r["err_I_G"], 100 * r["err_events_relative"], r["yield_MPa"], vs_base, r["pareto_front"]))
    open(os.path.join(out, "accuracy_vs_cost_table.md"), "w").write("\n".join(table) + "\n")
    print("\n".join(table))
    pareto(rows, fronts, out)
    fig7(runs, out)


def pareto(rows, fronts, out):
    """Top: every setting against the reference, its Pareto front drawn. Bottom: each knob against its
    own N's base setting."""
    keys = list(FRONT)
    titles = ["porosity n", "K0", "GSD at 100 MPa (% passing)", "I_G", "events per initial grain (relative)"]
    fig, axes = plt.subplots(2, len(keys), figsize=(4.4 * len(keys), 9))
    for row_axes, suffix, what in ((axes[0], "", "the reference (N = 1, L_R = 0.05, dmin = 0.025 mm)"),
                                   (axes[1], "_vs_base", "the base setting of the same N")):
        for ax, key, title in zip(row_axes, keys, titles):
            for k, r in enumerate(rows):
                if r["name"] == "reference" or key + suffix not in r:
                    continue
                y = max(r[key + suffix], 1e-5)
                on_front = not suffix and r["name"] in fronts[key]
                ax.loglog(r["seconds"], y, "o", color="C3" if on_front else "C0")
                ax.annotate(r["name"], (r["seconds"], y), fontsize=7, xytext=(3, 3 + 4 * (k % 3)),
                            textcoords="offset points")
            if not suffix:
                front = sorted((r["seconds"], max(r[key], 1e-5)) for r in rows if r["name"] in fronts[key])
                if front:
                    ax.step(*zip(*front), where="post", color="C3", lw=1, label="Pareto front")
                    ax.legend(fontsize=7)
            ax.set_xlabel("runtime (s, %d ranks)" % rows[0]["ranks"])
            ax.set_ylabel("largest difference")
            ax.set_title("%s, against\n%s" % (title, what), fontsize=8)
    fig.suptitle("Accuracy against cost: O-N to 100 MPa with the paper's crushing")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "pareto.png"), dpi=100)
    plt.close(fig)


def fig7(runs, out):
    fig, ax = plt.subplots(figsize=(6, 4.5))
    scale = [r for r in runs if is_base(r) and r["finished"]]
    scale.sort(key=lambda r: r["initial"])
    ax.loglog([r["initial"] for r in scale], [r["seconds"] / 60 for r in scale], "o-",
              label="liggghts-crush, %d ranks" % (scale[0]["ranks"] if scale else 2))
    for r in scale:
        ax.annotate("O-%g" % r["N"], (r["initial"], r["seconds"] / 60), fontsize=8)
    ax.loglog(list(PAPER_PFC3D_MINUTES), list(PAPER_PFC3D_MINUTES.values()), "s--", label="PFC3D, 1 core (paper, Table 3)")
    ax.set_xlabel("initial particles")
    ax.set_ylabel("runtime to 100 MPa (min)")
    ax.set_title("Runtime against initial particles (Fig. 7)")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fig7_runtime.png"), dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
