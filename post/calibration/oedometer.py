"""Against a compression curve (calibrate.py oedometer): O-N runs of examples/fontainebleau for a grid
of (sigma_lim0, cv), each curve's yield stress and compression slope against the lab's."""
import json
import math
import os
import shutil
import subprocess
import time

import numpy as np

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from post.calibration.data import DataError, data_rows, number, positive_number  # noqa: E402

# the repository root (post/calibration/ is two folders down): examples/ and build/liggghts
REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


# ---------------------------------------------------------------------------------------------
# oedometer: O-2 (examples/fontainebleau/in.oedometer) for a grid of (sigma_lim0, cv)

def finite_number(path, n, row, column):
    value = number(path, n, row, column)
    if not math.isfinite(value):
        raise DataError("%s, line %d: %s = %s must be finite" % (path, n, column, row[column]))
    return value


def read_curve(path, stress="sigma_v", ratio="e", booked=False):
    """sigma and e of a compression curve. A lab's e is positive; a run's booked e (booked=True) may
    not be: its removed volume, counted as solid, can outgrow the void space (doc/design.md, 8)."""
    header, rows = data_rows(path)
    for column in (stress, ratio):
        if column not in header:
            raise DataError("%s: no column '%s' in the header (%s)" % (path, column, ",".join(header)))
    s = np.array([positive_number(path, n, r, stress) for n, r in rows])
    e = np.array([(finite_number if booked else positive_number)(path, n, r, ratio) for n, r in rows])
    return s, e


def overbooked_at(s, e):
    """The first stress at which a run's booked void ratio is no longer positive (None if never)."""
    gone = np.nonzero(e <= 0.0)[0]
    return float(s[gone[0]]) if len(gone) else None


def yield_and_slope(s, e, low, high):
    """Bilinear fit of e against log10 sigma_v (studies/accuracy/README.md): lines fitted to the ranges
    low and high (Pa); returns the yield stress (their intersection) and the slope of the second
    (the normal compression line, de/dlog10 sigma)."""
    lo = (s >= low[0]) & (s <= low[1])
    hi = (s >= high[0]) & (s <= high[1])
    if lo.sum() < 2 or hi.sum() < 2:
        return math.nan, math.nan
    a1, b1 = np.polyfit(np.log10(s[lo]), e[lo], 1)
    a2, b2 = np.polyfit(np.log10(s[hi]), e[hi], 1)
    return 10 ** ((b1 - b2) / (a2 - a1)), a2


def fit_ranges(s_lab):
    """The paper's ranges (0.3-3 MPa, 50-100 MPa), scaled to a lab curve that ends elsewhere: the
    first decade above the lab's start and the top half of its last decade."""
    smax, smin = s_lab.max(), s_lab.min()
    if smax >= 1e8 and smin <= 3e5:
        return (3e5, 3e6), (5e7, 1e8)
    return (smin * 1.01, smin * 10.0), (0.5 * smax, smax)


def run_oedometer(args, sigma_lim0, cv, weibull_m, d0, folder):
    """One O-N run in folder (a copy of examples/fontainebleau with in.grains' cv, weibull_m, d0
    replaced); its history (sigma_z, void_ratio) and wall-clock seconds."""
    source = os.path.join(REPO, "examples", "fontainebleau")
    if os.path.isdir(folder):
        shutil.rmtree(folder)
    shutil.copytree(source, folder)
    grains = os.path.join(folder, "in.grains")
    text = open(grains).read()
    old = "cv 1 weibull_m 10 d0 2e-3"
    if old not in text:
        raise DataError("%s: the fix crush line no longer reads '%s'" % (grains, old))
    open(grains, "w").write(text.replace(old, "cv %g weibull_m %g d0 %g" % (cv, weibull_m, d0)))
    cmd = args.command.format(liggghts=args.liggghts, ranks=args.ranks, N=args.N, sigma_lim0=sigma_lim0,
                              sigma_max=args.sigma_max).split()
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    start = time.time()
    with open(os.path.join(folder, "screen.txt"), "w") as screen:
        rc = subprocess.call(cmd, cwd=folder, stdout=screen, stderr=subprocess.STDOUT, env=env)
    seconds = time.time() - start
    if rc != 0:
        raise DataError("the run in %s failed (exit %d): %s" % (folder, rc, " ".join(cmd)))
    history = os.path.join(folder, "history_O%s.csv" % args.N)
    s, e = read_curve(history, "sigma_z", "void_ratio", booked=True)
    return s, e, seconds


def oedometer(args):
    s_lab, e_lab = read_curve(args.lab)
    weibull_m, d0 = args.weibull_m, args.d0
    if args.fit:
        p = json.load(open(os.path.join(args.fit, "parameters.json")))
        weibull_m, d0 = p["weibull_m"], p["d0"]
    low, high = fit_ranges(s_lab)
    y_lab, c_lab = yield_and_slope(s_lab, e_lab, low, high)
    print("lab: yield stress %.4g Pa, NCL slope de/dlog10(sigma_v) = %.4g (lines on %.3g-%.3g and %.3g-%.3g Pa)"
          % (y_lab, c_lab, low[0], low[1], high[0], high[1]))
    grid = [(float(s), float(c)) for s in args.sigma_lim0.split(",") for c in args.cv.split(",")]
    print("search: %d runs (sigma_lim0 in %s Pa x cv in %s), weibull_m = %g, d0 = %g m; command: %s"
          % (len(grid), args.sigma_lim0, args.cv, weibull_m, d0, args.command))
    os.makedirs(args.out, exist_ok=True)
    runs = []
    for k, (s0, cv) in enumerate(grid):
        s, e, seconds = run_oedometer(args, s0, cv, weibull_m, d0, os.path.join(args.out, "run_%d" % k))
        y, c = yield_and_slope(s, e, low, high)
        overbooked = overbooked_at(s, e)
        # a cascade's curve past zero booked porosity is not a result, however well it fits
        err = math.hypot(math.log(y / y_lab), (c - c_lab) / c_lab) if math.isfinite(y) and overbooked is None else math.inf
        runs.append({"sigma_lim0": s0, "cv": cv, "yield": y, "slope": c, "seconds": seconds, "misfit": err,
                     "overbooked_at": overbooked, "s": s, "e": e})
        print("run %d: sigma_lim0 = %.4g Pa, cv = %g: yield %.4g Pa (lab %.4g), slope %.4g (lab %.4g), misfit %.3g, %.1f s"
              % (k, s0, cv, y, y_lab, c, c_lab, err, seconds))
        if overbooked is not None:
            print("run %d: the booked void ratio reaches %.3g (<= 0 from %.4g Pa): the removed volume outgrows "
                  "the void space (a cascade, doc/design.md section 8); not a candidate" % (k, e.min(), overbooked))
    total = sum(r["seconds"] for r in runs)
    print("search: %d runs, %.1f s in all, %.1f s a run" % (len(runs), total, total / len(runs)))
    candidates = [r for r in runs if math.isfinite(r["misfit"])]
    best = min(candidates, key=lambda r: r["misfit"]) if candidates else None
    if best is not None:
        print("best: sigma_lim0 = %.4g Pa, cv = %g (misfit %.3g: |log yield ratio| and relative slope error, "
              "combined)" % (best["sigma_lim0"], best["cv"], best["misfit"]))
    keys = ("sigma_lim0", "cv", "yield", "slope", "seconds", "misfit", "overbooked_at")
    json.dump({"lab_yield": y_lab, "lab_slope": c_lab,
               "best": {k: best[k] for k in ("sigma_lim0", "cv", "yield", "slope")} if best else None,
               "runs": [{k: (r[k] if r[k] != math.inf else None) for k in keys} for r in runs]},
              open(os.path.join(args.out, "oedometer.json"), "w"), indent=1)
    fig, ax = plt.subplots(figsize=(6, 4.2))
    ax.semilogx(s_lab / 1e6, e_lab, "ko", ms=4, label="lab")
    for r in runs:
        ax.semilogx(r["s"] / 1e6, r["e"], "-" if r["overbooked_at"] is None else ":", lw=2 if r is best else 0.8,
                    label="sigma_lim0 %.3g GPa, cv %g%s" % (r["sigma_lim0"] / 1e9, r["cv"],
                                                          "" if r["overbooked_at"] is None else " (booked e <= 0)"))
    ax.set_xlabel("sigma_v (MPa)")
    ax.set_ylabel("void ratio e")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "oedometer.png"), dpi=90)
    plt.close(fig)
    print("wrote %s/oedometer.json, oedometer.png" % args.out)
    if best is None:
        raise DataError("no run of the grid is a candidate (each lacks a yield or books more solid than the "
                        "box holds); widen --sigma_lim0 and --cv")
