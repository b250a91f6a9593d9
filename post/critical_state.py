#!/usr/bin/python3
"""Critical states of drained triaxial tests with crushing (examples/fontainebleau/in.triaxial,
scripts/critical_state_study.sh), the critical state line and plane, for studies/critical_state/README.md.

    post/critical_state.py [--out DIR] [--window W] [--max-dilatancy D] FOLDER ...
    post/critical_state.py --from-csv [--out DIR] [--max-dilatancy D] critical_states.csv ...

Reads every history_T<sample><N>.csv under the given folders (a test's folder is named
<sample>_<p0>MPa[_<path>][_s<seed>] inside a folder named after its variant, e.g. rotation0/dense_2MPa;
seconds.txt and cpu_seconds.txt beside it, if any, are its wall-clock and CPU time; the tables give
the CPU time, or the wall-clock time where there is none). For each test, from its shearing rows
(stage 1):
  - the critical state: the means of e, p', q/p over the last W of axial strain (default 0.05: 25 -
    30% for tests to 30%), I_G at the end, and the dilatancy -d eps_v / d eps_a there (least squares,
    eps_v compression positive: > 0 dilating, 0 at a critical state), with phi_cs = asin(3 M / (6 + M))
    (triaxial compression);
  - the peak q/p and its axial strain, e and I_G at the start of shearing, the crushing events during
    shearing;
and fits, for each variant, for rotation0 and normal together (one contact law, two gradings) and for
each variant with its pre-crushed samples (variant_pre<P>: one reading, gradings set apart at one p'):
  - the critical state line e_cs = Gamma - lambda ln(p'/1 kPa) of each sample (dense, loose) and of
    both together, and two curved lines through the same points (fit_curved);
  - the critical state plane e_cs = Gamma_0 - lambda ln(p'/1 kPa) - beta I_G of both samples together,
    and the curved plane e_cs = e_Gamma0 - lambda_c (p'/p_a)^0.7 - beta I_G, with the residuals of each
    test; for rotation0 + normal the curved plane also with a 0/1 indicator of the strength reading in
    place of I_G and beside it (over two readings the grading and the reading go together);
each coefficient with its standard error in fit.md, with its 95% t interval (df = tests - coefficients)
on the study page (a plane over a narrow range of I_G cannot separate beta); and, by seed (the seed
fixes the sample and the strengths; post/seeds.py's one rule, compare(), Holm over each table):
  - each pre-crushed sample against its variant at the same sample, p0 and path: the changes of e_cs,
    I_G and ln p' at the critical state, and beta = -de_cs / dI_G of each common seed with their mean's
    interval;
  - each variant's phi_cs between neighbouring cell pressures that two seeds or more ran.
--max-dilatancy D leaves the tests whose |dilatancy| at the end exceeds D (still changing volume: not
at a critical state) out of every fit and pairing; the tables list them and fit.md names them.
A folder without _s<seed> holds the decks' seed (15485863).
Writes DIR/critical_states.csv (a row a test), DIR/fit.md (the fits with their standard errors and
residuals) and the figures DIR/figures/critical_state_e_lnp.png (e against ln p', every test's path and critical
state, the lines), critical_state_IG_p.png (I_G against p' through compression and shearing, the
critical states), critical_state_plane.png (each plane seen edge-on: e_cs + lambda ln p' against I_G)
and critical_state_strain.png (q/p and e against axial strain). --from-csv reads the tests from
critical_states.csv files instead (the study's CSVs) and writes fit.md alone. The study page's tables
come from the same CSVs through post/tables.py (post/study_tables/critical_state.py: states_table(),
lines_table(), planes_table(), gradings_table(), angles_table() here).
"""
import argparse
import csv
import glob
import math
import os
import re
import sys

if not __package__:  # run as a file (python3 post/critical_state.py): the folder above post/ holds the package
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from post import requires  # noqa: E402
from post.seeds import compare, holm, interval, one_sample, resolved  # noqa: E402
from post.study_tables.common import change_cell  # noqa: E402

requires("critical_state", "numpy")

import numpy as np

KEPT_FOURTEEN = 0.52386  # share of a mother's volume its fourteen fragments keep (doc/fix_crush.txt)
STATE = re.compile(r"^STATE at \S+ MPa: \S+ particles, \S+ events, porosity (\S+),", re.M)
FOLDER_NAME = re.compile(r"^(dense|loose)_([0-9.]+)MPa(?:_(sigma3|p))?(?:_s([0-9]+))?$")
P_REF = 1e3  # Pa: ln(p'/1 kPa)
DECKS_SEED = "15485863"  # in.grains' seed, a test folder's where its name gives none


def friction_angle(m):
    """phi (degrees) of the stress ratio M = q/p in triaxial compression."""
    return math.degrees(math.asin(3.0 * m / (6.0 + m)))


def read_history(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def describe(folder):
    """variant, sample, p0 (MPa), path and seed of a test folder."""
    m = FOLDER_NAME.match(os.path.basename(os.path.normpath(folder)))
    if not m:
        return None
    variant = os.path.basename(os.path.dirname(os.path.normpath(folder)))
    return {"variant": variant, "sample": m.group(1), "p0_MPa": float(m.group(2)),
            "path": m.group(3) or "sigma3", "seed": m.group(4) or DECKS_SEED}


def critical_state(h, window):
    """The critical state and the other measures of one test's history (columns of in.triaxial)."""
    shear = h["stage"] == 1
    eps = h["axial_strain"][shear]
    if len(eps) < 3:
        raise ValueError("fewer than 3 shearing rows")
    tail = eps >= eps[-1] - window
    if tail.sum() < 2:
        raise ValueError("fewer than 2 rows in the last %g of axial strain" % window)
    ratio = h["q_over_p"][shear]
    ipk = int(np.argmax(ratio))
    dilatancy = np.polyfit(eps[tail], h["volumetric_strain"][shear][tail], 1)[0]
    m_cs = float(np.mean(ratio[tail]))
    events = h["events"][shear]
    return {"e0": h["void_ratio"][shear][0], "IG0": h["I_G"][shear][0],
            "eps_end": eps[-1], "e_cs": float(np.mean(h["void_ratio"][shear][tail])),
            "p_cs_MPa": float(np.mean(h["p"][shear][tail])) / 1e6, "M_cs": m_cs,
            "phi_cs": friction_angle(m_cs), "IG_cs": h["I_G"][shear][-1],
            "dilatancy_end": -dilatancy, "M_peak": ratio[ipk], "eps_peak": eps[ipk],
            "phi_peak": friction_angle(ratio[ipk]), "events_shearing": events[-1] - events[0],
            "particles_end": h["particles"][shear][-1]}


def standard_errors(a, residuals):
    """Standard errors of least-squares coefficients: sqrt(diag(s^2 (A^T A)^-1)), s^2 = RSS/(n - k);
    infinite where the data cannot separate a coefficient (n <= k, or A^T A singular)."""
    n, k = a.shape
    if n <= k:
        return np.full(k, np.inf)
    s2 = float(np.sum(residuals ** 2)) / (n - k)
    try:
        return np.sqrt(np.abs(np.diag(s2 * np.linalg.inv(a.T @ a))))
    except np.linalg.LinAlgError:
        return np.full(k, np.inf)


def lens_volume(x, r):
    """Total volume of the lenses where spheres (centres x, radii r) overlap: Hertzian overlaps stand
    for the grains' elastic flattening, and the decks count their volume twice as solid."""
    total = 0.0
    for start in range(0, len(r), 500):
        d = np.linalg.norm(x[start:start + 500, None, :] - x[None, :, :], axis=2)
        r1, r2 = r[start:start + 500, None], r[None, :]
        index = np.arange(start, min(start + 500, len(r)))[:, None] < np.arange(len(r))[None, :]
        touch = index & (d < r1 + r2) & (d > 0)
        d, r1, r2 = d[touch], np.broadcast_to(r1, touch.shape)[touch], np.broadcast_to(r2, touch.shape)[touch]
        total += float(np.sum(np.pi * (r1 + r2 - d) ** 2 * (d * d + 2 * d * (r1 + r2) - 3 * (r1 - r2) ** 2) / (12 * d)))
    return total


def without_overlaps(folder):
    """The void ratio at the end of shearing as the decks count it (removed volume as solid) and with
    the lens volume of the particles' overlaps taken out of the solid, and that volume's share of the
    solid, from the final dump, the event log and the STATE line; None without them."""
    dumps = glob.glob(os.path.join(folder, "dump_T*_sheared.liggghts"))
    logs = glob.glob(os.path.join(folder, "events_T*.csv"))
    screen = os.path.join(folder, "screen.txt")
    if not (dumps and logs and os.path.exists(screen)):
        return None
    states = STATE.findall(open(screen).read())
    if not states:
        return None
    n = float(states[-1])
    with open(dumps[0]) as f:
        lines = f.read().splitlines()
    count, columns = int(lines[3]), lines[8].split()[2:]
    data = np.array([[float(v) for v in line.split()] for line in lines[9:9 + count]])
    x = data[:, [columns.index(c) for c in ("x", "y", "z")]]
    r = data[:, columns.index("radius")]
    with open(logs[0]) as f:
        mothers = np.array([float(row["diameter"]) for row in csv.DictReader(f)])
    solid = float(np.sum(4.0 / 3.0 * np.pi * r ** 3)) + (1 - KEPT_FOURTEEN) * float(np.sum(np.pi / 6 * mothers ** 3))
    share = lens_volume(x, r) / solid
    # V = solid / (1 - n); true solid = solid (1 - share)
    return {"e_end": n / (1 - n), "e_end_no_overlap": (1 - (1 - n) * (1 - share)) / ((1 - n) * (1 - share)),
            "overlap_share": share}


def least_squares(columns, y):
    """Least squares of y on the given columns: the coefficients, residuals, rms residual, R^2 and
    standard errors."""
    a = np.column_stack(columns)
    y = np.asarray(y)
    coefficients, *_ = np.linalg.lstsq(a, y, rcond=None)
    residuals = y - a @ coefficients
    total = np.sum((y - y.mean()) ** 2)
    return {"coefficients": coefficients, "residuals": residuals, "se": standard_errors(a, residuals),
            "df": a.shape[0] - a.shape[1], "rms": float(np.sqrt(np.mean(residuals ** 2))),
            "R2": float(1.0 - np.sum(residuals ** 2) / total) if total > 0 else 1.0}


def log_pressure(p_mpa):
    return np.log(np.asarray(p_mpa) * 1e6 / P_REF)


def li_wang_pressure(p_mpa):
    return (np.asarray(p_mpa) * 1e6 / 101e3) ** 0.7


def fit_line(p_mpa, e):
    """Gamma, lambda of e = Gamma - lambda ln(p'/1 kPa), the residuals and R^2."""
    x = log_pressure(p_mpa)
    fit = least_squares([np.ones_like(x), -x], e)
    fit["Gamma"], fit["lambda"] = fit["coefficients"]
    return fit


def fit_curved(p_mpa, e):
    """Two curved critical state lines, each linear in its own coordinates, with their rms residuals:
    log e = log e_1 - b log(p'/1 kPa) (a straight line in log e - log p', de Bono & McDowell 2018) and
    e = e_Gamma - lambda_c (p'/p_a)^0.7 (Li & Wang 1998, p_a = 101 kPa)."""
    e = np.asarray(e)
    x = log_pressure(p_mpa)
    (log_e1, b) = least_squares([np.ones_like(x), -x], np.log(e))["coefficients"]
    power = np.exp(log_e1 - b * x)
    x2 = li_wang_pressure(p_mpa)
    li_wang = least_squares([np.ones_like(x2), -x2], e)
    e_gamma, lam_c = li_wang["coefficients"]
    return {"e1": float(np.exp(log_e1)), "b": b, "rms_power": float(np.sqrt(np.mean((e - power) ** 2))),
            "e_gamma": e_gamma, "lambda_c": lam_c, "rms_li_wang": li_wang["rms"]}


def fit_plane(p_mpa, ig, e):
    """Gamma_0, lambda, beta of e = Gamma_0 - lambda ln(p'/1 kPa) - beta I_G and the residuals."""
    x = log_pressure(p_mpa)
    fit = least_squares([np.ones_like(x), -x, -np.asarray(ig)], e)
    fit["Gamma0"], fit["lambda"], fit["beta"] = fit["coefficients"]
    return fit


def fit_plane_curved(p_mpa, ig, e, reading=None):
    """e_Gamma0, lambda_c, beta of e = e_Gamma0 - lambda_c (p'/p_a)^0.7 - beta I_G (Li & Wang's curved
    line shifted by the grading) and the residuals; with reading (0/1 a test: which strength reading
    drew it), also delta of a term - delta reading: whether the grading or the reading shifts the line."""
    x = li_wang_pressure(p_mpa)
    columns = [np.ones_like(x), -x, -np.asarray(ig)] + ([] if reading is None else [-np.asarray(reading, float)])
    fit = least_squares(columns, e)
    fit["e_gamma0"], fit["lambda_c"], fit["beta"] = fit["coefficients"][:3]
    if reading is not None:
        fit["delta"] = fit["coefficients"][3]
    return fit


def collect(folders, window):
    tests = []
    for top in folders:
        for path in sorted(glob.glob(os.path.join(top, "**", "history_T*.csv"), recursive=True)):
            folder = os.path.dirname(path)
            info = describe(folder)
            if info is None:
                continue
            h = read_history(path)
            if "stage" not in h:
                sys.exit("post/critical_state.py: %s has no stage column (an in.triaxial from before the "
                         "critical-state study)" % path)
            try:
                info.update(critical_state(h, window))
            except ValueError as e:
                print("post/critical_state.py: %s skipped: %s" % (folder, e), file=sys.stderr)
                continue
            for key in ("seconds", "cpu_seconds"):
                path_s = os.path.join(folder, key + ".txt")
                info[key] = float(open(path_s).read()) if os.path.exists(path_s) else float("nan")
            info["steps"] = int(h["step"][-1] - h["step"][0])
            info.update(without_overlaps(folder) or {"e_end": float("nan"), "e_end_no_overlap": float("nan"),
                                                     "overlap_share": float("nan")})
            info["history"] = h
            info["folder"] = folder
            tests.append(info)
    tests.sort(key=lambda t: (t["variant"], t["path"], t["sample"], t["seed"], t["p0_MPa"]))
    return tests


COLUMNS = ["variant", "sample", "p0_MPa", "path", "seed", "e0", "IG0", "M_peak", "eps_peak", "phi_peak",
           "eps_end", "p_cs_MPa", "e_cs", "M_cs", "phi_cs", "IG_cs", "dilatancy_end", "e_end", "overlap_share", "e_end_no_overlap", "events_shearing",
           "particles_end", "steps", "seconds", "cpu_seconds"]


def write_csv(tests, path):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(COLUMNS)
        for t in tests:
            w.writerow([t[c] if isinstance(t[c], str) else "%.6g" % t[c] for c in COLUMNS])


TEXT_COLUMNS = ("variant", "sample", "path", "seed")


def read_csv(paths):
    """The tests of critical_states.csv files (write_csv()'s rows) as collect() gives them, less their
    histories: every table and fit from the CSVs alone (no figures). An empty seed is the decks'."""
    tests = []
    for path in paths:
        with open(path) as f:
            rows = list(csv.DictReader(f))
        missing = [c for c in COLUMNS if rows and c not in rows[0]]
        if not rows or missing:
            sys.exit("post/critical_state.py: %s: %s" % (path, "no rows" if not rows else "no column " + ", ".join(missing)))
        for row in rows:
            t = dict((c, row[c] if c in TEXT_COLUMNS else float(row[c] or "nan")) for c in COLUMNS)
            t["seed"] = t["seed"] or DECKS_SEED
            tests.append(t)
    tests.sort(key=lambda t: (t["variant"], t["path"], t["sample"], t["seed"], t["p0_MPa"]))
    return tests


POOLED = ("rotation0", "normal")  # one contact law, two strength readings: two gradings at one p'


def groups(tests):
    """The groups fitted: each variant's tests on the sigma3 path, those of rotation0 and normal
    together (grains that do not rotate, with and without the zero-strength sixth: the gradings
    differ by what broke at the first load, the plane's test), and each variant with its pre-crushed
    samples (variant_pre<P>, in.triaxial's precrush: gradings that differ at one p' within one
    strength reading)."""
    out = [(v, [t for t in tests if t["variant"] == v and t["path"] == "sigma3"])
           for v in sorted({t["variant"] for t in tests})]
    pooled = [t for t in tests if t["variant"] in POOLED and t["path"] == "sigma3"]
    if {t["variant"] for t in pooled} == set(POOLED):
        out.append((" + ".join(POOLED), pooled))
    # one reading, several gradings at one p': a variant with its pre-crushed samples (variant_pre<P>)
    for base in sorted({t["variant"] for t in tests if "_pre" not in t["variant"]}):
        family = [t for t in tests if t["path"] == "sigma3" and t["variant"].split("_pre")[0] == base]
        if any("_pre" in t["variant"] for t in family) and any(t["variant"] == base for t in family):
            out.append((base + " + pre-crushed", family))
    return [(name, group) for name, group in out if group]


def lines_through(members, column):
    """The straight and the curved lines through the tests' critical states (p'_cs, column)."""
    p, e = [t["p_cs_MPa"] for t in members], [t[column] for t in members]
    line = fit_line(p, e)
    line.update(fit_curved(p, e))
    return line


def at_critical_state(t, max_dilatancy):
    """Whether a fit takes the test: always without a bound; with one, where its volume has stopped
    changing to within it (|dilatancy| at the end)."""
    return max_dilatancy is None or abs(t["dilatancy_end"]) <= max_dilatancy


def fits(tests, max_dilatancy=None):
    """Per group (groups()): the line of each sample and of both, curved lines, and the plane, over
    the tests at_critical_state(); for rotation0 + normal also the curved plane with an indicator of
    the strength reading in place of I_G and beside it (the two gradings are the two readings)."""
    out = {}
    for variant, group in groups(tests):
        group = [t for t in group if at_critical_state(t, max_dilatancy)]
        if not group:
            continue
        result = {"tests": group, "lines": {}}
        for name, members in (("dense", [t for t in group if t["sample"] == "dense"]),
                              ("loose", [t for t in group if t["sample"] == "loose"]), ("both", group)):
            if len({t["p0_MPa"] for t in members}) >= 2:
                result["lines"][name] = lines_through(members, "e_cs")
        clean = [t for t in group if t["e_end_no_overlap"] == t["e_end_no_overlap"]]
        if len({t["p0_MPa"] for t in clean}) >= 2:
            # the void ratio at the end with the overlaps' volume taken out of the solid
            result["lines"]["both, overlaps removed"] = lines_through(clean, "e_end_no_overlap")
        p, ig, e = [t["p_cs_MPa"] for t in group], [t["IG_cs"] for t in group], [t["e_cs"] for t in group]
        if len(group) >= 4 and max(ig) - min(ig) > 1e-6:  # (an uncrushable group has one grading: no plane)
            result["plane"] = fit_plane(p, ig, e)
            result["curved_plane"] = fit_plane_curved(p, ig, e)
            reading = [float(t["variant"] == POOLED[1]) for t in group]
            if variant == " + ".join(POOLED) and len(group) >= 5 and 0 < sum(reading) < len(group):
                result["reading_plane"] = fit_plane_curved(p, reading, e)
                result["reading_and_grading"] = fit_plane_curved(p, ig, e, reading)
        out[variant] = result
    return out


def by_seed(tests, variant, sample, p0, path, max_dilatancy):
    """{seed: test} of one setting, the tests a fit takes."""
    return dict((t["seed"], t) for t in tests if (t["variant"], t["sample"], t["p0_MPa"], t["path"]) ==
                (variant, sample, p0, path) and at_critical_state(t, max_dilatancy))


def of_seeds(seeds, column, transform=float):
    return dict((s, transform(t[column])) for s, t in seeds.items())


def over_seeds(values):
    """The mean of per-seed values (each seed's beta) against zero with its 95% t interval, in
    compare()'s terms."""
    mean, se, df = one_sample(values)
    low, high, p = interval(mean, se, df)
    return dict(change=mean, se=se, df=df, low=low, high=high, p=p, resolved=resolved(mean, se, df),
                pairs=len(values), r=float("nan"), design="paired (%d seeds)" % len(values))


def paired_gradings(tests, max_dilatancy=None):
    """Each pre-crushed variant (variant_pre<P>) against its variant at the same sample, p0 and path:
    (variant, pre-crushed variant, sample, p0, path, common seeds, compare() of e_cs, I_G,cs and
    ln p'_cs (post/seeds.py's one rule), over_seeds() of beta = -de_cs / dI_G,cs over the common seeds
    (None where the gradings do not differ: an uncrushable pair), each seed's beta)."""
    rows = []
    for pre in sorted({t["variant"] for t in tests if "_pre" in t["variant"]}):
        base = pre.split("_pre")[0]
        for sample, p0, path in sorted({(t["sample"], t["p0_MPa"], t["path"]) for t in tests if t["variant"] == pre}):
            a = by_seed(tests, base, sample, p0, path, max_dilatancy)
            b = by_seed(tests, pre, sample, p0, path, max_dilatancy)
            seeds = sorted(set(a) & set(b))
            if not seeds:
                continue
            changes = [compare(of_seeds(a, c, f), of_seeds(b, c, f))
                       for c, f in (("e_cs", float), ("IG_cs", float), ("p_cs_MPa", math.log))]
            de = [b[s]["e_cs"] - a[s]["e_cs"] for s in seeds]
            dig = [b[s]["IG_cs"] - a[s]["IG_cs"] for s in seeds]
            beta = [-x / y for x, y in zip(de, dig) if y != 0]
            rows.append((base, pre, sample, p0, path, seeds, *changes,
                         over_seeds(beta) if len(beta) == len(seeds) else None, beta))
    return rows


def paired_angles(tests, max_dilatancy=None):
    """phi_cs of each variant, sample and path between neighbouring cell pressures that two seeds or
    more ran: (variant, sample, path, p0 low, p0 high, common seeds, compare() of phi_cs: paired by
    seed where the one rule pairs, else Welch)."""
    rows = []
    for variant, sample, path in sorted({(t["variant"], t["sample"], t["path"]) for t in tests}):
        levels = {}
        for p0 in sorted({t["p0_MPa"] for t in tests if (t["variant"], t["sample"], t["path"]) == (variant, sample, path)}):
            seeds = by_seed(tests, variant, sample, p0, path, max_dilatancy)
            if len(seeds) >= 2:
                levels[p0] = seeds
        pressures = sorted(levels)
        for lo, hi in zip(pressures, pressures[1:]):
            seeds = sorted(set(levels[lo]) & set(levels[hi]))
            if len(seeds) >= 2:
                rows.append((variant, sample, path, lo, hi, seeds,
                             compare(of_seeds(levels[lo], "phi_cs"), of_seeds(levels[hi], "phi_cs"))))
    return rows


# the column of each named coefficient in least_squares()'s fits (fit_line, fit_plane, fit_plane_curved)
COEFFICIENT = {"Gamma": 0, "Gamma0": 0, "e_gamma0": 0, "lambda": 1, "lambda_c": 1, "beta": 2, "delta": 3}


def estimate(fit, name, digits):
    """A least-squares coefficient with its 95% t interval (df = tests - coefficients); alone where
    the fit cannot give one."""
    k = COEFFICIENT[name]
    value = fit["coefficients"][k]
    low, high, _ = interval(value, fit["se"][k], fit["df"])
    if low != low:
        return "%.*f" % (digits, value)
    return "%.*f (%.*f .. %.*f)" % (digits, value, digits, low, digits, high)


def coefficient_resolved(fit, name):
    k = COEFFICIENT[name]
    return resolved(fit["coefficients"][k], fit["se"][k], fit["df"])


def tally(changes, adjusted):
    """The line under a table of changes: how many, resolved, and surviving Holm over them."""
    known = [(c, p) for c, p in zip(changes, adjusted) if c["p"] == c["p"]]
    return ("(%d comparisons: %d resolved, %d after Holm's correction over them; '*' resolved, '**' also after Holm; "
            "'u': unpaired, Welch)" % (len(known), sum(c["resolved"] == "yes" for c, _ in known),
                                       sum(c["resolved"] == "yes" and p < 0.05 for c, p in known)))


def states_table(tests):
    """Each test's critical state and the other measures: a row a test."""
    lines = ["| variant | sample | p'_0 (MPa) | path | seed | e_0 | I_G,0 | peak q/p (at eps_a) | phi_peak | "
             "p'_cs (MPa) | e_cs | q/p cs | phi_cs | I_G,cs | dilatancy at end | overlaps / solid | "
             "e at end, overlaps removed | events in shearing | particles | steps | CPU s |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for t in tests:
        lines.append("| %s | %s | %g | %s | %s | %.3f | %.3f | %.3f (%.1f%%) | %.1f | %.3g | %.3f | %.3f | %.1f | "
                     "%.3f | %.3f | %.4f | %.3f | %d | %d | %d | %s |"
                     % (t["variant"], t["sample"], t["p0_MPa"], t["path"], t["seed"] or "-", t["e0"], t["IG0"],
                        t["M_peak"], 100 * t["eps_peak"], t["phi_peak"], t["p_cs_MPa"], t["e_cs"], t["M_cs"],
                        t["phi_cs"], t["IG_cs"], t["dilatancy_end"], t["overlap_share"], t["e_end_no_overlap"],
                        t["events_shearing"], t["particles_end"],
                        t["steps"], "%.0f" % t["cpu_seconds"] if t["cpu_seconds"] == t["cpu_seconds"]
                        else "%.0f wall" % t["seconds"]))
    return lines


def line_count(f, name):
    """The tests of a group's line: a sample's, or all of them ("both", "both, overlaps removed")."""
    return len([t for t in f["tests"] if name.startswith("both") or t["sample"] == name])


def lines_table(fitted):
    """The study page's lines: the straight line's coefficients with their 95% t intervals, and the
    rms residuals of the two curved lines through the same critical states; each variant's (a pooled
    group's single line is the planes table's comparison), a sample's only where it is not all of its
    variant (then it is "both")."""
    lines = ["| group | samples | tests | Gamma (95% interval) | lambda (95% interval) | R^2 | rms residual | "
             "Li & Wang: e_Gamma | lambda_c | rms residual | log e - log p': rms residual |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for variant, f in fitted.items():
        for name, line in f["lines"].items():
            if " + " in variant or (name in ("dense", "loose") and line_count(f, name) == len(f["tests"])):
                continue
            lines.append("| %s | %s | %d | %s | %s | %.3f | %.4f | %.4f | %.4f | %.4f | %.4f |"
                         % (variant, name, line_count(f, name), estimate(line, "Gamma", 3), estimate(line, "lambda", 4),
                            line["R2"], line["rms"], line["e_gamma"], line["lambda_c"], line["rms_li_wang"],
                            line["rms_power"]))
    return lines


def planes_table(fitted):
    """The study page's planes: each group's straight and curved plane with beta's 95% t interval and
    whether it is resolved; for rotation0 + normal also the reading's indicator in place of I_G and
    beside it."""
    lines = ["| group | tests | form | Gamma_0 or e_Gamma0 | lambda or lambda_c | beta (95% interval) | beta resolved | "
             "rms residual | rms of the single line | I_G range |", "|---|---|---|---|---|---|---|---|---|---|"]
    for variant, f in fitted.items():
        if "plane" not in f:
            continue
        single = f["lines"].get("both", {"rms": float("nan")})["rms"]
        ig = [t["IG_cs"] for t in f["tests"]]
        forms = [("straight", f["plane"], "Gamma0", "lambda", "beta", "%.3f - %.3f" % (min(ig), max(ig))),
                 ("curved", f["curved_plane"], "e_gamma0", "lambda_c", "beta", "")]
        if "reading_plane" in f:
            forms += [("curved, the reading (0/1) in place of I_G", f["reading_plane"], "e_gamma0", "lambda_c", "beta", ""),
                      ("curved, I_G and the reading (its coefficient %s)" % estimate(f["reading_and_grading"], "delta", 3),
                       f["reading_and_grading"], "e_gamma0", "lambda_c", "beta", "")]
        for form, fit, gamma, lam, beta, span in forms:
            lines.append("| %s | %d | %s | %s | %s | %s | %s | %.4f | %.4f | %s |"
                         % (variant, len(f["tests"]), form, estimate(fit, gamma, 3),
                            estimate(fit, lam, 4 if lam == "lambda" else 5), estimate(fit, beta, 2),
                            coefficient_resolved(fit, beta), fit["rms"], single, span))
    return lines


def gradings_table(tests, max_dilatancy=None, page=True):
    """The pre-crushed samples against their variant at one p', by the one rule; on the page each
    change with its 95% interval and Holm over the table, in fit.md also beta's mean +- s.e."""
    rows = paired_gradings(tests, max_dilatancy)
    if not rows:
        return []
    found = [c for row in rows for c in row[6:10] if c is not None]
    family = holm([c["p"] for c in found])
    adjusted = iter(family)
    lines = ["| variant | pre-crushed | sample | p'_0 (MPa) | path | seeds | de_cs | dI_G,cs | d ln p'_cs | "
             "beta of each seed | beta = -de_cs / dI_G,cs |" + ("" if page else " beta, mean +- s.e. |"),
             "|---|---|---|---|---|---|---|---|---|---|---|" + ("" if page else "---|")]
    for base, pre, sample, p0, path, seeds, de, dig, dlnp, beta, each in rows:
        cells = [change_cell(c, 4 if c is not dlnp else 3, next(adjusted)) for c in (de, dig, dlnp)]
        cells += [", ".join("%.2f" % x for x in each),
                  change_cell(beta, 2, next(adjusted)) if beta else "(no change of I_G)"]
        if not page:
            cells.append("%.3f +- %.3f" % (beta["change"], beta["se"]) if beta else "")
        lines.append("| %s | %s | %s | %g | %s | %d | %s |" % (base, pre, sample, p0, path, len(seeds), " | ".join(cells)))
    return lines + ["", tally(found, family)]


def angles_table(tests, max_dilatancy=None):
    """phi_cs between neighbouring cell pressures by the one rule, with Holm over the table."""
    rows = paired_angles(tests, max_dilatancy)
    if not rows:
        return []
    adjusted = holm([row[6]["p"] for row in rows])
    lines = ["| variant | sample | path | p'_0 from (MPa) | to | seeds | change of phi_cs (deg) | p | design |",
             "|---|---|---|---|---|---|---|---|---|"]
    for (variant, sample, path, lo, hi, seeds, c), p_holm in zip(rows, adjusted):
        lines.append("| %s | %s | %s | %g | %g | %d | %s | %s | %s |"
                     % (variant, sample, path, lo, hi, len(seeds), change_cell(c, 2, p_holm),
                        "%.2g" % c["p"] if c["p"] == c["p"] else "", c["design"]))
    return lines + ["", tally([row[6] for row in rows], adjusted)]


def left_out(tests, max_dilatancy):
    out = [t for t in tests if not at_critical_state(t, max_dilatancy)]
    return ("Left out of every fit and pairing (|dilatancy| at the end above %g): %s"
            % (max_dilatancy, ", ".join("%s %s %g MPa seed %s (%.3f)" % (t["variant"], t["sample"], t["p0_MPa"],
                                                                         t["seed"], t["dilatancy_end"]) for t in out)
               if out else "none"))


def markdown(tests, fitted, window, max_dilatancy=None):
    """fit.md: every table of the fit, each coefficient with its standard error (the study page's
    tables, post/study_tables/critical_state.py, give the 95% t intervals)."""
    lines = ["### Critical states (mean over the last %g of axial strain)" % window, ""] + states_table(tests)
    lines += ["", "(dilatancy: -d eps_v / d eps_a over the window, eps_v compression positive: > 0 dilating, < 0 "
              "contracting, 0 at a critical state)", "", "### Critical state lines e_cs = Gamma - lambda ln(p'/1 kPa)", "",
              "| variant | samples | tests | Gamma | lambda | R^2 | rms residual | s.e. Gamma | s.e. lambda |",
              "|---|---|---|---|---|---|---|---|---|"]
    for variant, f in fitted.items():
        for name, line in f["lines"].items():
            lines.append("| %s | %s | %d | %.4f | %.4f | %.3f | %.4f | %.4f | %.4f |"
                         % (variant, name, line_count(f, name), line["Gamma"], line["lambda"], line["R2"], line["rms"],
                            *line["se"]))
    lines += ["", "### Curved critical state lines: log e_cs = log e_1 - b log(p'/1 kPa) and "
              "e_cs = e_Gamma - lambda_c (p'/p_a)^0.7", "",
              "| variant | samples | e_1 | b | rms residual | e_Gamma | lambda_c | rms residual | rms of the straight line |",
              "|---|---|---|---|---|---|---|---|---|"]
    for variant, f in fitted.items():
        for name, line in f["lines"].items():
            lines.append("| %s | %s | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f |"
                         % (variant, name, line["e1"], line["b"], line["rms_power"], line["e_gamma"], line["lambda_c"],
                            line["rms_li_wang"], line["rms"]))
    lines += ["", "### Critical state plane e_cs = Gamma_0 - lambda ln(p'/1 kPa) - beta I_G", "",
              "| variant | tests | Gamma_0 | lambda | beta | R^2 | rms residual | rms of the single line | "
              "s.e. Gamma_0 | s.e. lambda | s.e. beta | I_G range |",
              "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for variant, f in fitted.items():
        if "plane" in f:
            pl = f["plane"]
            single = f["lines"].get("both", {"rms": float("nan")})["rms"]
            ig = [t["IG_cs"] for t in f["tests"]]
            lines.append("| %s | %d | %.4f | %.4f | %.4f | %.3f | %.4f | %.4f | %.4f | %.4f | %.4f | %.3f - %.3f |"
                         % (variant, len(f["tests"]), pl["Gamma0"], pl["lambda"], pl["beta"], pl["R2"], pl["rms"],
                            single, *pl["se"], min(ig), max(ig)))
    lines += ["", "### Curved critical state plane e_cs = e_Gamma0 - lambda_c (p'/p_a)^0.7 - beta I_G [- delta reading]",
              "", "| variant | form | tests | e_Gamma0 | lambda_c | beta | rms residual | s.e. e_Gamma0 | s.e. lambda_c | "
              "s.e. beta | delta (s.e.) |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    for variant, f in fitted.items():
        for key, form in (("curved_plane", "I_G"), ("reading_plane", "reading in place of I_G"),
                          ("reading_and_grading", "I_G and reading")):
            if key in f:
                cp = f[key]
                lines.append("| %s | %s | %d | %.4f | %.5f | %.4f | %.4f | %.4f | %.5f | %.4f | %s |"
                             % (variant, form, len(f["tests"]), cp["e_gamma0"], cp["lambda_c"], cp["beta"], cp["rms"],
                                *cp["se"][:3], "%.4f (%.4f)" % (cp["delta"], cp["se"][3]) if "delta" in cp else ""))
    lines += ["", "### Residuals of the plane", "",
              "| group | variant | sample | p'_0 (MPa) | I_G,cs | e_cs | plane | residual | curved plane | residual |",
              "|---|---|---|---|---|---|---|---|---|---|"]
    for variant, f in fitted.items():
        if "plane" in f:
            for t, r, rc in zip(f["tests"], f["plane"]["residuals"], f["curved_plane"]["residuals"]):
                lines.append("| %s | %s | %s | %g | %.4f | %.4f | %.4f | %+.4f | %.4f | %+.4f |"
                             % (variant, t["variant"], t["sample"], t["p0_MPa"], t["IG_cs"], t["e_cs"], t["e_cs"] - r, r,
                                t["e_cs"] - rc, rc))
    gradings = gradings_table(tests, max_dilatancy, page=False)
    if gradings:
        lines += ["", "### Gradings at one p', by seed: beta = -de_cs / dI_G,cs", ""] + gradings
    angles = angles_table(tests, max_dilatancy)
    if angles:
        lines += ["", "### phi_cs between cell pressures, by seed", ""] + angles
    if max_dilatancy is not None:
        lines += ["", left_out(tests, max_dilatancy)]
    return "\n".join(lines) + "\n"


def figures(tests, fitted, out):
    requires("critical_state", "matplotlib")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    os.makedirs(out, exist_ok=True)
    variants = sorted({t["variant"] for t in tests})
    pressures = sorted({t["p0_MPa"] for t in tests})
    cmap = plt.get_cmap("viridis")
    colour = {p: cmap(i / max(1, len(pressures) - 1)) for i, p in enumerate(pressures)}
    dash = {"dense": "-", "loose": "--"}
    marker = {"dense": "o", "loose": "s"}
    written = []

    def paths(ax, variant, column, at_cs):
        """Each test's path of a history column against p' and its critical state (a marker)."""
        for t in (t for t in tests if t["variant"] == variant):
            h = t["history"]
            ax.plot(h["p"] / 1e6, h[column], dash[t["sample"]], color=colour[t["p0_MPa"]], lw=0.7, alpha=0.6)
            ax.plot(t["p_cs_MPa"], t[at_cs], marker[t["sample"]], color=colour[t["p0_MPa"]],
                    mfc="none" if t["sample"] == "loose" else colour[t["p0_MPa"]])

    fig, axes = plt.subplots(1, len(variants), figsize=(6 * len(variants), 4.5), squeeze=False)
    for ax, variant in zip(axes[0], variants):
        paths(ax, variant, "void_ratio", "e_cs")
        p = np.logspace(np.log10(min(pressures) / 2), np.log10(max(t["p_cs_MPa"] for t in tests) * 1.5), 50)
        for name, line in fitted[variant]["lines"].items():
            if name not in ("dense", "loose", "both"):
                continue
            ax.plot(p, line["Gamma"] - line["lambda"] * np.log(p * 1e6 / P_REF), {"dense": "k-", "loose": "k--",
                    "both": "r:"}[name], lw=1, label="CSL %s: %.3f - %.4f ln p'" % (name, line["Gamma"], line["lambda"]))
            if name == "both":
                ax.plot(p, line["e_gamma"] - line["lambda_c"] * (p * 1e6 / 101e3) ** 0.7, "-.", color="grey", lw=1,
                        label="both: %.3f - %.4f (p'/p_a)^0.7" % (line["e_gamma"], line["lambda_c"]))
        ax.set_xscale("log")
        ax.set_xlabel("p' (MPa)")
        ax.set_ylabel("void ratio e")
        ax.set_title("%s (filled: dense, open: loose)" % variant)
        ax.legend(fontsize=7)
    fig.tight_layout()
    written.append(os.path.join(out, "critical_state_e_lnp.png"))
    fig.savefig(written[-1], dpi=120)
    plt.close(fig)

    fig, axes = plt.subplots(1, len(variants), figsize=(6 * len(variants), 4.5), squeeze=False)
    for ax, variant in zip(axes[0], variants):
        paths(ax, variant, "I_G", "IG_cs")
        ax.set_xscale("log")
        ax.set_xlabel("p' (MPa)")
        ax.set_ylabel("grading index I_G")
        ax.set_title("%s: compression and shearing (markers: critical state)" % variant, fontsize=9)
    fig.tight_layout()
    written.append(os.path.join(out, "critical_state_IG_p.png"))
    fig.savefig(written[-1], dpi=120)
    plt.close(fig)

    planes = [(name, f) for name, f in fitted.items() if "plane" in f]
    fig, axes = plt.subplots(1, len(planes), figsize=(5.5 * len(planes), 4.5), squeeze=False)
    for ax, (name, f) in zip(axes[0], planes):
        pl = f["plane"]
        # e_cs + lambda ln(p'/kPa) against I_G: the plane seen edge-on, a line Gamma_0 - beta I_G
        for t in f["tests"]:
            ax.plot(t["IG_cs"], t["e_cs"] + pl["lambda"] * np.log(t["p_cs_MPa"] * 1e6 / P_REF), marker[t["sample"]],
                    color=colour[t["p0_MPa"]], mfc="none" if t["sample"] == "loose" else colour[t["p0_MPa"]])
        ig = np.linspace(min(t["IG_cs"] for t in f["tests"]) - 0.01, max(t["IG_cs"] for t in f["tests"]) + 0.01, 10)
        ax.plot(ig, pl["Gamma0"] - pl["beta"] * ig, "k-", lw=1,
                label="%.3f - %.3f I_G (lambda %.4f)" % (pl["Gamma0"], pl["beta"], pl["lambda"]))
        ax.set_xlabel("grading index I_G at the critical state")
        ax.set_ylabel("e_cs + lambda ln(p'/1 kPa)")
        ax.set_title(name, fontsize=9)
        ax.legend(fontsize=7)
    fig.tight_layout()
    written.append(os.path.join(out, "critical_state_plane.png"))
    fig.savefig(written[-1], dpi=120)
    plt.close(fig)

    fig, axes = plt.subplots(2, len(variants), figsize=(6 * len(variants), 7), squeeze=False, sharex=True)
    for j, variant in enumerate(variants):
        for t in (t for t in tests if t["variant"] == variant and t["path"] == "sigma3"):
            h = t["history"]
            shear = h["stage"] == 1
            label = "%g MPa" % t["p0_MPa"] if t["sample"] == "dense" else None
            axes[0][j].plot(100 * h["axial_strain"][shear], h["q_over_p"][shear], dash[t["sample"]],
                            color=colour[t["p0_MPa"]], lw=0.8, label=label)
            axes[1][j].plot(100 * h["axial_strain"][shear], h["void_ratio"][shear], dash[t["sample"]],
                            color=colour[t["p0_MPa"]], lw=0.8)
        axes[0][j].set_ylabel("q/p'")
        axes[0][j].set_title("%s (solid: dense, dashed: loose)" % variant)
        axes[0][j].legend(fontsize=7, ncol=2)
        axes[1][j].set_ylabel("void ratio e")
        axes[1][j].set_xlabel("axial strain (%)")
    fig.tight_layout()
    written.append(os.path.join(out, "critical_state_strain.png"))
    fig.savefig(written[-1], dpi=120)
    plt.close(fig)
    return written


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("folders", nargs="+", help="run folders (with --from-csv: critical_states.csv files)")
    parser.add_argument("--out", default=".", help="folder for critical_states.csv, fit.md and figures/")
    parser.add_argument("--from-csv", action="store_true", help="read the tests from critical_states.csv files "
                        "instead of runs: fit.md alone (the window is the one the CSVs were written with)")
    parser.add_argument("--window", type=float, default=0.05, help="axial strain at the end over which the "
                        "critical state is averaged (0.05)")
    parser.add_argument("--max-dilatancy", type=float, default=None, help="leave the tests whose |dilatancy| at "
                        "the end exceeds this out of the fits and pairings (default: none left out)")
    parser.add_argument("--no-figures", action="store_true")
    a = parser.parse_args(argv)
    tests = read_csv(a.folders) if a.from_csv else collect(a.folders, a.window)
    if not tests:
        sys.exit("post/critical_state.py: no in.triaxial histories in folders named <sample>_<p0>MPa under %s"
                 % " ".join(a.folders))
    os.makedirs(a.out, exist_ok=True)
    if not a.from_csv:
        write_csv(tests, os.path.join(a.out, "critical_states.csv"))
    fitted = fits(tests, a.max_dilatancy)
    text = markdown(tests, fitted, a.window, a.max_dilatancy)
    with open(os.path.join(a.out, "fit.md"), "w") as f:
        f.write(text)
    print(text)
    if not (a.no_figures or a.from_csv):
        for path in figures(tests, fitted, os.path.join(a.out, "figures")):
            print("wrote", path)


if __name__ == "__main__":
    main(sys.argv[1:])
