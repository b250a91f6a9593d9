#!/usr/bin/python3
"""Figures of Ciantia et al. (2014) from the outputs of examples/fontainebleau, for any set of runs.

    post/plot.py [--out DIR] RUN_DIR_OR_FILE ...

Reads history_<O|I><N>.csv, gsd_<O|I><N>_100MPa.csv and history_T<sample><N>.csv found in the given
folders (or given as files) and writes PNGs to --out (default: the current folder):
  fig3a_triaxial.png     q and volumetric strain against axial strain (drained triaxial, Fig. 3a)
  fig4_oedometric.png    n and K0 against vertical stress, GSD at 100 MPa (Fig. 4a-c)
  fig5_isotropic.png     n against mean stress p', GSD at 100 MPa (Fig. 5a-b)
  fig6_stress_paths.png  q - p' paths and I_G against p' (Fig. 6)
  fig_crushing.png       crushing events and particles against the controlling stress
  fig_gsd_evolution.png  GSD before loading (0) and at 1, 10, 50 and 100 MPa for every N, downscaled
                         (gsd_<O|I><N>_<s>MPa.csv)
Triaxial curves are labelled with their folder's name, so that runs of one sample with different
settings (e.g. -var rotation 0 and 1) can be drawn together. Only the figures for which runs were given are drawn. Stresses are plotted in MPa.
"""
import argparse
import csv
import glob
import os
import re
import sys

if not __package__:  # run as a file (python3 post/plot.py): the folder above post/ holds the package
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from post import requires  # noqa: E402

requires("plot", "matplotlib")

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

RUN_NAME = re.compile(r"history_([OI])([0-9.]+)\.csv$")
TRIAXIAL_NAME = re.compile(r"history_T([a-z]+)([0-9.]+)\.csv$")
GSD_NAME = re.compile(r"gsd_([OI])([0-9.]+)_100MPa\.csv$")
GSD_LEVEL_NAME = re.compile(r"gsd_([OI])([0-9.]+)_([0-9]+)MPa\.csv$")
LEVEL_COLOUR = {"0": "black", "1": "tab:blue", "10": "tab:green", "50": "tab:orange", "100": "tab:red"}
STYLE = {"1": "-", "1.5": "--", "2": ":"}


def read_csv(path, skip=()):
    """Columns of a numeric CSV file as lists of floats, keyed by the header; columns named in skip
    (text) are left out."""
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {key: [float(r[key]) for r in rows] for key in rows[0] if key is not None and key not in skip} if rows else {}


def collect(paths):
    """Every history, triaxial history (keyed by sample, N and folder) and GSD file (100 MPa, and by
    stress level) under the given folders or files."""
    files = []
    for p in paths:
        files += sorted(glob.glob(os.path.join(p, "*.csv"))) if os.path.isdir(p) else [p]
    runs, triaxial, gsd, levels = {}, {}, {}, {}
    for f in files:
        name = os.path.basename(f)
        for pattern, table in ((RUN_NAME, runs), (GSD_NAME, gsd)):
            m = pattern.search(name)
            if m:
                table[(m.group(1), m.group(2))] = read_csv(f)
        m = TRIAXIAL_NAME.search(name)
        if m:
            triaxial[(m.group(1), m.group(2), os.path.basename(os.path.dirname(os.path.abspath(f))))] = read_csv(f)
        m = GSD_LEVEL_NAME.search(name)
        if m:
            levels[(m.group(1), m.group(2), m.group(3))] = read_csv(f)
    return runs, triaxial, gsd, levels


def label(test, n):
    return "%s-%s" % (test, n)


def mpa(values):
    return [v * 1e-6 for v in values]


def plot_gsd(ax, gsd, test):
    for (t, n), g in sorted(gsd.items()):
        if t == test:
            ax.semilogx(g["size_mm"], g["percent_passing"], STYLE.get(n, "-"), marker="o", ms=3, label=label(t, n))
    ax.set_xlabel("particle size (mm)")
    ax.set_ylabel("percent passing by mass")
    ax.set_title("GSD at 100 MPa")
    ax.legend()


def figure_oedometric(runs, gsd, out):
    oedo = {n: h for (t, n), h in runs.items() if t == "O"}
    if not oedo:
        return None
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.5))
    for n, h in sorted(oedo.items()):
        axes[0].semilogx(mpa(h["sigma_z"]), h["porosity"], STYLE.get(n, "-"), label="O-" + n)
        axes[1].semilogx(mpa(h["sigma_z"]), h["K0"], STYLE.get(n, "-"), label="O-" + n)
    axes[0].set_xlabel("vertical stress (MPa)")
    axes[0].set_ylabel("porosity n")
    axes[1].set_xlabel("vertical stress (MPa)")
    axes[1].set_ylabel("K0 = sigma_h / sigma_v")
    for ax in axes[:2]:
        ax.legend()
    plot_gsd(axes[2], gsd, "O")
    fig.suptitle("One-dimensional compression (Fig. 4)")
    return save(fig, out, "fig4_oedometric.png")


def figure_isotropic(runs, gsd, out):
    iso = {n: h for (t, n), h in runs.items() if t == "I"}
    if not iso:
        return None
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.5))
    for n, h in sorted(iso.items()):
        axes[0].semilogx(mpa(h["p"]), h["porosity"], STYLE.get(n, "-"), label="I-" + n)
    axes[0].set_xlabel("mean effective stress p' (MPa)")
    axes[0].set_ylabel("porosity n")
    axes[0].legend()
    plot_gsd(axes[1], gsd, "I")
    fig.suptitle("Isotropic compression (Fig. 5)")
    return save(fig, out, "fig5_isotropic.png")


def figure_stress_paths(runs, out):
    if not runs:
        return None
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.5))
    for (t, n), h in sorted(runs.items()):
        axes[0].plot(mpa(h["p"]), mpa(h["q"]), STYLE.get(n, "-"), label=label(t, n))
        axes[1].semilogx(mpa(h["p"]), h["I_G"], STYLE.get(n, "-"), label=label(t, n))
    axes[0].set_xlabel("p' (MPa)")
    axes[0].set_ylabel("q (MPa)")
    axes[1].set_xlabel("p' (MPa)")
    axes[1].set_ylabel("grading index I_G")
    for ax in axes:
        ax.legend()
    fig.suptitle("Stress paths and grading index (Fig. 6)")
    return save(fig, out, "fig6_stress_paths.png")


def figure_crushing(runs, out):
    if not runs:
        return None
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.5))
    for (t, n), h in sorted(runs.items()):
        stress = mpa(h["sigma_z"] if t == "O" else h["p"])
        axes[0].semilogx(stress, h["events"], STYLE.get(n, "-"), label=label(t, n))
        axes[1].semilogx(stress, h["particles"], STYLE.get(n, "-"), label=label(t, n))
    for ax in axes:
        ax.set_xlabel("vertical stress (O) or p' (I) (MPa)")
        ax.legend()
    axes[0].set_ylabel("crushing events")
    axes[1].set_ylabel("particles")
    fig.suptitle("Crushing against stress")
    return save(fig, out, "fig_crushing.png")


def figure_triaxial(triaxial, out):
    if not triaxial:
        return None
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.5))
    for (sample, n, folder), h in sorted(triaxial.items()):
        name = "%s, N = %s (%s)" % (sample, n, folder)
        if "stage" in h:  # the shearing rows, without an isotropic compression before them
            h = {k: [v for v, s in zip(column, h["stage"]) if s == 1] for k, column in h.items()}
        axes[0].plot([100 * e for e in h["axial_strain"]], mpa(h["q"]), label=name)
        axes[1].plot([100 * e for e in h["axial_strain"]], [100 * e for e in h["volumetric_strain"]], label=name)
    axes[0].set_ylabel("deviatoric stress q (MPa)")
    axes[1].set_ylabel("volumetric strain (%, compression positive)")
    for ax in axes:
        ax.set_xlabel("axial strain (%)")
        ax.legend()
    fig.suptitle("Drained triaxial compression (Fig. 3a)")
    return save(fig, out, "fig3a_triaxial.png")


def figure_gsd_evolution(levels, out):
    """The grading evolving: GSD at each output stress (colour) for each N (line style), downscaled."""
    tests = sorted({t for t, _, _ in levels})
    if not tests:
        return None
    fig, axes = plt.subplots(1, len(tests), figsize=(6.5 * len(tests), 4.8), squeeze=False)
    for ax, test in zip(axes[0], tests):
        for (t, n, level), g in sorted(levels.items(), key=lambda item: (item[0][1], float(item[0][2]))):
            if t == test:
                ax.semilogx(g["size_mm"], g["percent_passing"], STYLE.get(n, "-"), color=LEVEL_COLOUR.get(level),
                            label="%s, %s" % (label(t, n), "before loading" if level == "0" else level + " MPa"))
        ax.set_xlabel("particle size / N (mm)")
        ax.set_ylabel("percent passing by mass")
        ax.set_title({"O": "one-dimensional", "I": "isotropic"}[test] + " compression")
        ax.legend(fontsize=7, ncol=2)
    fig.suptitle("Grading before loading and at 1, 10, 50 and 100 MPa, every scale factor (downscaled)")
    return save(fig, out, "fig_gsd_evolution.png")


def save(fig, out, name):
    path = os.path.join(out, name)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", default=".", help="folder for the PNGs (default: .)")
    parser.add_argument("inputs", nargs="+", help="run folders or CSV files")
    args = parser.parse_args(argv)
    runs, triaxial, gsd, levels = collect(args.inputs)
    if not (runs or triaxial):
        sys.exit("post/plot.py: no history_<O|I|T...><N>.csv among " + " ".join(args.inputs))
    os.makedirs(args.out, exist_ok=True)
    written = [figure_triaxial(triaxial, args.out), figure_oedometric(runs, gsd, args.out),
               figure_isotropic(runs, gsd, args.out), figure_stress_paths(runs, args.out),
               figure_crushing(runs, args.out), figure_gsd_evolution(levels, args.out)]
    for path in written:
        if path:
            print("wrote " + path)


if __name__ == "__main__":
    main(sys.argv[1:])
