#!/usr/bin/python3
"""Analysis of bench/accuracy_vs_cost.sh: every setting's runtime and its error against the
reference (the finest setting), as a CSV, a Markdown table and two figures.

    bench/accuracy_vs_cost.py OUT_DIR

Errors, each the largest absolute difference from the reference:
  porosity   n against vertical stress, on a log grid from 0.2 to 100 MPa
  K0         K0 against vertical stress (5-row running mean), 1 to 100 MPa
  GSD        percent passing at 100 MPa, over the 11 sieves
  I_G        grading index against vertical stress, 1 to 100 MPa
and the yield stress: where the two straight lines of e against log(sigma_v) fitted to 0.2-1 MPa
and to 50-100 MPa meet (its relative difference). Writes OUT_DIR/accuracy_vs_cost.csv,
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

PAPER_PFC3D_MINUTES = {1304: 31.0, 3084: 67.0, 10397: 183.0}  # Table 3, O-2, O-1.5, O-1, one core
GRID = np.logspace(math.log10(2e5), 8, 60)


def read_csv(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0] if k is not None}


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
    """Intersection of the e - log10(sigma_v) lines fitted below 1 MPa and above 50 MPa (Pa)."""
    s, e = history["sigma_z"], history["void_ratio"]
    low = (s > 2e5) & (s < 1e6)
    high = (s > 5e7)
    if low.sum() < 2 or high.sum() < 2:
        return float("nan")
    a1, b1 = np.polyfit(np.log10(s[low]), e[low], 1)
    a2, b2 = np.polyfit(np.log10(s[high]), e[high], 1)
    return 10 ** ((b1 - b2) / (a2 - a1))


def load(folder):
    setting = read_csv(os.path.join(folder, "setting.csv"))
    name = os.path.basename(folder.rstrip("/"))
    history = read_csv(glob.glob(os.path.join(folder, "history_O*.csv"))[0])
    gsd = read_csv(glob.glob(os.path.join(folder, "gsd_O*_100MPa.csv"))[0])
    screen = open(os.path.join(folder, "screen.txt"), errors="replace").read()
    m = re.search(r"^SAMPLE N = \S+: (\d+) particles", screen, re.M)
    rss = re.search(r"Maximum resident set size \(kbytes\): (\d+)", open(os.path.join(folder, "time.txt")).read())
    return {
        "name": name, "N": float(setting["N"][0]), "L_R": float(setting["L_R"][0]),
        "dmin_mm": float(setting["dmin_mm"][0]), "dt_fraction": float(setting["dt_fraction"][0]),
        "crush_every": int(setting["crush_every"][0]), "ranks": int(setting["ranks"][0]),
        "seconds": float(setting["seconds"][0]), "initial": int(m.group(1)) if m else 0,
        "final": int(history["particles"][-1]), "events": int(history["events"][-1]),
        "rss_mb": int(rss.group(1)) / 1024.0 if rss else float("nan"),
        "history": history, "gsd": gsd, "yield": yield_stress(history),
    }


def errors(run, ref):
    def largest(column, lo=2e5, smooth=False):
        d = np.abs(on_grid(run["history"], column, lo, smooth) - on_grid(ref["history"], column, lo, smooth))
        return float(np.nanmax(d)) if np.any(~np.isnan(d)) else float("nan")
    return {
        "err_porosity": largest("porosity"),
        "err_K0": largest("K0", lo=1e6, smooth=True),
        "err_gsd_percent": float(np.max(np.abs(run["gsd"]["percent_passing"] - ref["gsd"]["percent_passing"]))),
        "err_I_G": largest("I_G", lo=1e6),
        "yield_MPa": run["yield"] / 1e6,
        "err_yield_relative": abs(run["yield"] / ref["yield"] - 1.0),
    }


COLUMNS = ["name", "N", "L_R", "dmin_mm", "dt_fraction", "crush_every", "ranks", "initial", "final", "events",
           "seconds", "speedup_vs_reference", "rss_mb", "err_porosity", "err_K0", "err_gsd_percent", "err_I_G",
           "yield_MPa", "err_yield_relative"]


def main(out):
    runs = [load(f) for f in sorted(glob.glob(os.path.join(out, "*", ""))) if os.path.exists(os.path.join(f, "done"))]
    ref = next((r for r in runs if r["name"] == "reference"), None)
    if ref is None:
        sys.exit("accuracy_vs_cost.py: no finished 'reference' run in " + out)
    rows = []
    for r in runs:
        row = {k: r[k] for k in COLUMNS if k in r}
        row.update(errors(r, ref))
        row["speedup_vs_reference"] = ref["seconds"] / r["seconds"]
        rows.append(row)
    with open(os.path.join(out, "accuracy_vs_cost.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=COLUMNS)
        w.writeheader()
        for row in rows:
            w.writerow({k: ("%.4g" % v if isinstance(v, float) else v) for k, v in row.items()})
    table = ["| setting | N | L_R | dmin (mm) | dt fraction | every | particles (initial, final) | events | runtime (s) | speed-up | max dn | max dK0 | max dGSD (%) | max dI_G | yield (MPa) |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        table.append("| %s | %g | %g | %s | %g | %d | %d, %d | %d | %.0f | %.1f | %.4f | %.3f | %.2f | %.4f | %.1f |" % (
            r["name"], r["N"], r["L_R"], "none" if r["dmin_mm"] == 0 else "%g" % r["dmin_mm"], r["dt_fraction"],
            r["crush_every"], r["initial"], r["final"], r["events"], r["seconds"], r["speedup_vs_reference"],
            r["err_porosity"], r["err_K0"], r["err_gsd_percent"], r["err_I_G"], r["yield_MPa"]))
    open(os.path.join(out, "accuracy_vs_cost_table.md"), "w").write("\n".join(table) + "\n")
    print("\n".join(table))
    pareto(rows, out)
    fig7(runs, out)


def pareto(rows, out):
    fig, axes = plt.subplots(1, 4, figsize=(18, 4.5))
    for ax, key, title in zip(axes, ["err_porosity", "err_K0", "err_gsd_percent", "err_I_G"],
                              ["porosity n", "K0", "GSD at 100 MPa (% passing)", "I_G"]):
        for r in rows:
            if r["name"] == "reference":
                continue
            ax.loglog(r["seconds"], max(r[key], 1e-6), "o")
            ax.annotate(r["name"], (r["seconds"], max(r[key], 1e-6)), fontsize=7)
        ax.set_xlabel("runtime (s, %d ranks)" % rows[0]["ranks"])
        ax.set_ylabel("largest difference from the reference")
        ax.set_title(title)
    fig.suptitle("Accuracy against cost: O-N to 100 MPa, errors against N = 1, L_R = 0.05, no dmin")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "pareto.png"), dpi=110)
    plt.close(fig)


def fig7(runs, out):
    fig, ax = plt.subplots(figsize=(6, 4.5))
    scale = [r for r in runs if r["L_R"] == 0.1 and r["dmin_mm"] == 0.05 and r["dt_fraction"] == 0.5
             and r["crush_every"] == 1]
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
