#!/usr/bin/env python3
"""The penetrometer of examples/penetration: the meshes penetrometer.py writes (geometry against the
analytic cone and shaft), those meshes pushed into a bed of grains by fix move/mesh, feeding fix
crush through fix wall/gran hertz/scaled, and the scene's decks on a small chamber (in.chamber,
in.cone: 3 D_c of penetration into some 700 grains, D_c / d50 = 2.1), with post/penetration.py on
their outputs; post/penetration_stats.py on stand-in study CSVs and on studies/penetration/penetration_study.csv (the
cases stats_*, which need no liggghts).

  python3 test_penetration.py LIGGGHTS WORKDIR CASE"""
import csv
import math
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liggghts_run import check, deck_command, each_rank_count, printed, read_thermo, run_deck, variants  # noqa: E402
from liggghts_run import main as test_main  # noqa: E402
from liggghts_run import read_balance_moves, read_dump  # noqa: E402
from test_checkpoint import kill_after  # noqa: E402
from test_vtk import has_vtk_dumps  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
from post.penetration import tip_at  # noqa: E402  (the one tip_at: the test reads events as the tool does)

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCRIPT = os.path.join(ROOT, "examples", "penetration", "penetrometer.py")
DECK = os.path.join(os.path.dirname(os.path.abspath(__file__)), "penetration", "in.push")
EXAMPLES = os.path.join(ROOT, "examples")
POST = os.path.join(ROOT, "post", "penetration.py")
PILE_POST = os.path.join(ROOT, "post", "pile_stress.py")
# the small chamber: 6 D_c wide (a quarter of 3 D_c a side), 3 D_c of penetration and 2 D_c below it,
# of grains ten times weaker than Table 1's: consolidated with crushing (in.chamber), Table 1's break
# too rarely under a short push to test the books
CHAMBER = {"N": 80, "width": 6, "depth": 3, "below": 2, "sigma_lim0": 5e8}
DC = 0.0357
STATS = os.path.join(ROOT, "post", "penetration_stats.py")
STUDY = os.path.join(ROOT, "scripts", "penetration_study.sh")
STUDY_CSV = os.path.join(ROOT, "studies", "penetration", "penetration_study.csv")
CASES_CSV = os.path.join(ROOT, "studies", "penetration", "cases.csv")  # the study's cases, read by STUDY
SEEDS = ("15485863", "179424673", "373587883")
DEFAULTS_NAMED = {"tip_shape": "cone", "sigma_lim0": "5e9", "neighbor_style": "multi"}  # in.cone's


def write_meshes(folder, diameter, shaft, tip, segments, *options):
    subprocess.run(["/usr/bin/python3", SCRIPT, "--diameter", str(diameter), "--shaft", str(shaft), "--tip", str(tip),
                    "--segments", str(segments), "--out", folder] + list(options), check=True, stdout=subprocess.DEVNULL)


def read_stl(path):
    """[(normal, (a, b, c))] of an ASCII STL."""
    facets, normal, corners = [], None, []
    for line in open(path):
        words = line.split()
        if words[:2] == ["facet", "normal"]:
            normal, corners = tuple(map(float, words[2:5])), []
        elif words[:1] == ["vertex"]:
            corners.append(tuple(map(float, words[1:4])))
        elif words[:1] == ["endfacet"]:
            facets.append((normal, tuple(corners)))
    return facets


def area(a, b, c):
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    return 0.5 * math.sqrt(sum(x * x for x in n))


def case_penetrometer_geometry(liggghts, work):
    """A 60-degree cone of D_c = 2 mm below a 10 mm shaft, 96 facets around: the cone's height is
    (D_c/2)/tan(30 deg), its lateral area pi r s (s = 2r), the shaft's pi D_c L, within the polygon's
    error; every normal is a unit vector pointing away from the axis (the cone's also downwards, at
    30 degrees from the horizontal); the shaft starts on the cone's base ring."""
    del liggghts
    D, L, tip, n = 0.002, 0.01, 0.001, 96
    write_meshes(work, D, L, tip, n)
    cone, shaft = read_stl(os.path.join(work, "cone.stl")), read_stl(os.path.join(work, "shaft.stl"))
    r = D / 2
    height = r / math.tan(math.radians(30))
    check(len(cone) == n and len(shaft) == 2 * n, "%d cone and %d shaft facets" % (len(cone), len(shaft)))
    zs = [p[2] for _, f in cone for p in f]
    check(abs(min(zs) - tip) < 1e-12 and abs(max(zs) - (tip + height)) < 1e-12,
          "the tip at %.4g m, the cone's base %.6g m above it (0.866 D_c)" % (min(zs), max(zs) - min(zs)))
    polygon = 2 * math.pi * r * r * math.cos(math.pi / n)  # the inscribed polygon's slant faces, to first order
    cone_area = sum(area(*f) for _, f in cone)
    check(abs(cone_area / (2 * math.pi * r * r) - 1) < 2e-3 and abs(cone_area / polygon - 1) < 2e-3,
          "cone lateral area %.6g m^2 against pi r s = %.6g" % (cone_area, 2 * math.pi * r * r))
    shaft_area = sum(area(*f) for _, f in shaft)
    check(abs(shaft_area / (math.pi * D * L) - 1) < 2e-3, "shaft area %.6g m^2 against pi D_c L = %.6g"
          % (shaft_area, math.pi * D * L))
    for name, facets in (("cone", cone), ("shaft", shaft)):
        check(all(abs(sum(x * x for x in n_) - 1) < 1e-6 and n_[0] * sum(p[0] for p in f) + n_[1] * sum(p[1] for p in f) > 0
                  for n_, f in facets), "every %s normal is a unit vector pointing away from the axis" % name)
    slopes = [n_[2] for n_, _ in cone]
    check(all(abs(z + 0.5 * math.cos(math.pi / n)) < 1e-3 for z in slopes),
          "the cone's normals point down at 30 degrees from the horizontal (n_z = %.4f)" % slopes[0])
    base = {tuple(round(x, 12) for x in p) for _, f in cone for p in f if abs(p[2] - (tip + height)) < 1e-12}
    bottom = {tuple(round(x, 12) for x in p) for _, f in shaft for p in f if abs(p[2] - (tip + height)) < 1e-12}
    check(base == bottom and len(base) == n, "the shaft starts on the cone's base ring (%d points)" % len(base))


def check_test_books(folder, label):
    """The books of a finished test: particles = grains + 13 x events at every history row, and the
    final dump (up to output_every steps after the last row) holds grains + 13 x the logged events,
    every tag once. Returns the history, the grains and the logged events."""
    history = read_rows(os.path.join(folder, "penetration_%s_N80.csv" % label))
    n0 = grains0(folder)
    check(all(r["particles"] == n0 + 13 * r["events"] for r in history),
          "particles = %d + 13 x events at every one of %d rows (%d events at the end)" % (n0, len(history), history[-1]["events"]))
    events = read_rows(os.path.join(folder, "events_pen_%s_N80.csv" % label))
    _, _, atoms = read_dump(os.path.join(folder, "particles_%s_N80.liggghts" % label))[0]
    tags = [int(a["id"]) for a in atoms]
    check(len(set(tags)) == len(tags) == n0 + 13 * len(events),
          "%d particles at the end = %d + 13 x %d logged events, every tag unique" % (len(tags), n0, len(events)))
    return history, n0, events


def case_pile_geometry(liggghts, work):
    """The closed-ended pile (--tip-shape flat), a quarter of it: its base is the disc sector at the
    tip's height, area pi r^2 / 4 within the polygon's error, every normal straight down; the shaft
    starts on the base's ring at the tip's height."""
    del liggghts
    D, L, tip, n = 0.002, 0.01, 0.001, 96
    write_meshes(work, D, L, tip, n, "--sector", "90", "--tip-shape", "flat")
    base, shaft = read_stl(os.path.join(work, "cone.stl")), read_stl(os.path.join(work, "shaft.stl"))
    r = D / 2
    check(len(base) == n // 4 and len(shaft) == 2 * n // 4, "%d base and %d shaft facets" % (len(base), len(shaft)))
    check(all(abs(p[2] - tip) < 1e-15 for _, f in base for p in f), "the base lies at the tip's height")
    base_area = sum(area(*f) for _, f in base)
    polygon = 0.25 * n * 0.5 * r * r * math.sin(2 * math.pi / n)
    check(abs(base_area / polygon - 1) < 1e-9 and abs(base_area / (math.pi * r * r / 4) - 1) < 1e-3,
          "base area %.6g m^2: the polygon's, and pi r^2 / 4 = %.6g within 0.1%%" % (base_area, math.pi * r * r / 4))
    check(all(abs(n_[0]) < 1e-9 and abs(n_[1]) < 1e-9 and abs(n_[2] + 1) < 1e-9 for n_, _ in base),
          "every base normal points straight down")
    ring_base = {tuple(round(x, 12) for x in p) for _, f in base for p in f if math.hypot(p[0], p[1]) > 0.5 * r}
    bottom = {tuple(round(x, 12) for x in p) for _, f in shaft for p in f if abs(p[2] - tip) < 1e-12}
    check(ring_base == bottom and len(bottom) == n // 4 + 1, "the shaft starts on the base's ring (%d points)" % len(bottom))


@variants(*each_rank_count(1, 2))
def case_pile_short(liggghts, work, ranks):
    """The closed-ended pile (in.cone -var tip_shape flat) jacked 2 D_c into the small chamber with
    crushing in the zone, on 1 and 2 ranks: the books at every row and unique tags at the end; the
    base resistance (the q_c column) positive, and more than half its 1 - 2 D_c value already over
    the first 0.5 D_c (a cone's builds up over its height)."""
    ranks = int(ranks)
    folder = prepare_chamber(liggghts, work, ranks)
    push(liggghts, folder, ranks, crushing="region", vtk=0, label="pile", depth=2, tip_shape="flat", stress_every=0.5)
    history, _, _ = check_test_books(folder, "pile")
    mean = lambda v: sum(v) / len(v)  # noqa: E731
    shallow = [r["q_c"] for r in history if r["depth_Dc"] < 0.5]
    deep = [r["q_c"] for r in history if r["depth_Dc"] > 1.0]
    # a flat base bears on the grains at its first contact, where a cone's resistance builds up over
    # its height (case cone_short: q_c over 2 - 3 D_c more than twice that over 0 - 0.5 D_c)
    check(min(deep) > 0 and mean(shallow) > 0.5 * mean(deep),
          "q_b > 0, and from the first contact: %.3g MPa over 0 - 0.5 D_c, %.3g over 1 - 2 D_c"
          % (mean(shallow) / 1e6, mean(deep) / 1e6))
    out = subprocess.run(["/usr/bin/python3", PILE_POST, "--label", "pile", "--N", "80", "--Dc", str(DC), "--from", "1.0",
                          "--out", "pile"], cwd=folder, stdout=subprocess.PIPE, universal_newlines=True, check=True).stdout
    shaft = read_rows(os.path.join(folder, "pile_shaft.csv"))
    rings = read_rows(os.path.join(folder, "pile_rings.csv"))
    # the base carries q_b, some 20 times the chamber's 100 kPa: the rings just below it (r < R,
    # -R < h < 0) hold a vertical stress far above the chamber's (a wrong sign, frame or volume would
    # not); beside the shaft, a grain or two per ring here, the stresses are the relaxed ones of
    # studies/penetration/history.md and are not checked
    below = [r["sigma_zz"] for r in rings if r["r_over_R"] < 1 and -1 < r["h_over_R"] < 0]
    check(len(shaft) >= 3 and len(below) >= 2 and sum(below) / len(below) > 5 * 1e5
          and os.path.exists(os.path.join(folder, "pile_maps.png")),
          "post/pile_stress.py: sigma_zz below the base %.2f MPa (mean of %d rings, q_b %.2f MPa), the shaft at %d"
          " heights, the maps drawn" % (sum(below) / len(below) / 1e6, len(below), mean(deep) / 1e6, len(shaft)))


@variants(*each_rank_count(1, 2))
def case_chamber_protocol(liggghts, work, ranks):
    """The element tests' protocol (in.chamber, chamber_crushing 1), on 1 and 2 ranks: consolidated
    with crushing, the chamber keeps no grain of zero strength (the Table 3 reading draws about a
    sixth) and counts its events in events0; a short push with crushing in the zone then breaks only
    grains it loaded (every event's force ratio finite); the uncrushable reference on the same
    chamber (crushing 0) draws every strength anew (redraw yes: 1e30 Pa) and breaks none, where the
    strengths the restart brings would break grains (the small chamber's weak grains)."""
    ranks = int(ranks)
    folder = prepare_chamber(liggghts, work, ranks)
    _, _, atoms = read_dump(os.path.join(folder, "chamber_dense_N80.liggghts"))[0]
    originals = [a for a in atoms if int(float(a["f_crush[2]"])) == 0]
    events0 = int(float(open(os.path.join(folder, "chamber_dense_N80.in")).read().split("variable events0 equal")[1].split()[0]))
    consolidation = read_rows(os.path.join(folder, "events_chamber_dense_N80.csv"), numeric=False)
    check(len(consolidation) == events0 > 0 and len(atoms) == grains0(folder),
          "%d consolidation events logged, as events0 says; grains0 = the %d particles of the chamber"
          % (len(consolidation), len(atoms)))
    strengths = [float(a["f_crush[1]"]) for a in atoms]
    check(min(strengths) > 0 and len(originals) < len(atoms),
          "no grain of zero strength after the consolidation: the weakest %.3g Pa, %d of the original grains left"
          % (min(strengths), len(originals)))
    push(liggghts, folder, ranks, crushing="region", vtk=0, depth=2)
    history, _, events = check_test_books(folder, "dense_region")
    check(len(events) > 0 and all(math.isfinite(float(e["force_ratio"])) and float(e["force_ratio"]) >= 1.0 for e in events),
          "every one of the push's %d events a grain loaded to its limit (force ratios %s)"
          % (len(events), sorted(round(e["force_ratio"], 3) for e in events)[-5:]))
    push(liggghts, folder, ranks, crushing=0, vtk=0, depth=2)
    history, _, events = check_test_books(folder, "dense_0")
    _, _, after = read_dump(os.path.join(folder, "particles_dense_0_N80.liggghts"))[0]
    check(len(events) == 0 and history[-1]["events"] == 0 and len(after) == len(atoms),
          "the uncrushable reference: no event in %d rows, %d particles" % (len(history), len(after)))


REFINED = {"refine": 1, "coarsen": 1.25, "fine_radius": 1, "mid_radius": 2}


def zone_scale(x, y):
    """The N of the small refined chamber's zone at (x, y): 80 within 1 D_c of the axis, 100 to 2 D_c,
    125 beyond (REFINED)."""
    r = math.hypot(x, y) / 0.0357
    return 80.0 if r < 1 else 100.0 if r < 2 else 125.0


def fragments_share_scale(events, atoms):
    """The events whose fragments, all present in atoms, do not all hold one N."""
    scale = {int(a["id"]): a["f_grain_scale"] for a in atoms}
    odd = []
    for e in events:
        tags = [int(float(v)) for k, v in e.items() if k.startswith("fragment_")]
        if all(t in scale for t in tags) and len({scale[t] for t in tags}) != 1:
            odd.append(e["tag"])
    return odd


@variants(*each_rank_count(1, 2))
def case_refined_chamber(liggghts, work, ranks):
    """A refined chamber (in.chamber refine 1, in.zones: N 80 within 1 D_c of the axis, 100 to 2 D_c,
    125 beyond), on 1 and 2 ranks: each grain holds its zone's N (fix crush scale_atom), the zones
    hold one sand grading (d / N alike, model sizes growing with N), the consolidation's fragments
    keep their mother's N, the profile dump reads back through post/chamber_profiles.py, and a
    short push with crushing in the zone keeps its books."""
    ranks = int(ranks)
    folder = prepare_chamber(liggghts, work, ranks, **REFINED)
    _, _, atoms = read_dump(os.path.join(folder, "chamber_dense_N80.liggghts"))[0]
    originals = [a for a in atoms if a["f_crush[2]"] == 0]
    scales = sorted({a["f_grain_scale"] for a in atoms})
    check(scales == [80.0, 100.0, 125.0], "the zones' N: %s" % scales)
    placed = sum(1 for a in originals if a["f_grain_scale"] == zone_scale(a["x"], a["y"]))
    check(placed >= 0.8 * len(originals), "%d of the %d unbroken grains hold the N of the zone they lie in (grains near an interface cross it as they grow)"
          % (placed, len(originals)))
    by_zone = {n: [2 * a["radius"] for a in originals if a["f_grain_scale"] == n] for n in scales}
    model = {n: sum(d) / len(d) for n, d in by_zone.items()}
    sand = [model[n] / n for n in scales]
    check(max(sand) / min(sand) < 1.15 and model[125.0] > model[100.0] > model[80.0],
          "mean model diameters %s mm grow with N; as sand sizes (d / N) %s mm they agree within 15%%"
          % (["%.2f" % (model[n] * 1e3) for n in scales], ["%.4f" % (x * 1e3) for x in sand]))
    consolidation = read_rows(os.path.join(folder, "events_chamber_dense_N80.csv"), numeric=False)
    odd = fragments_share_scale(consolidation, atoms)
    check(consolidation and not odd, "the fragments of each of the %d consolidation events hold one N (%d do not)"
          % (len(consolidation), len(odd)))
    profiles = subprocess.run([sys.executable, os.path.join(ROOT, "post", "chamber_profiles.py"),
                               os.path.join(folder, "chamber_dense_N80_profile.liggghts"), "--interfaces", "1,2",
                               "--dr", "0.5", "--out", os.path.join(folder, "profiles")],
                              capture_output=True, text=True)
    # (the porosity and the mean stress of each annulus; a blank is a column without data, e.g. no rattler-free grain)
    rows = [{k: float(r[k]) for k in ("porosity", "p")}
            for r in read_rows(os.path.join(folder, "profiles.csv"), numeric=False)] if profiles.returncode == 0 else []
    check(rows and all(0.2 < r["porosity"] < 0.7 for r in rows) and all(r["p"] > 0 for r in rows),
          "post/chamber_profiles.py on the profile dump: %d annuli, porosity %s, p %s kPa"
          % (len(rows), ["%.3f" % r["porosity"] for r in rows], ["%.0f" % (r["p"] / 1e3) for r in rows])
          if rows else "post/chamber_profiles.py failed: %s" % profiles.stderr[-500:])
    push(liggghts, folder, ranks, crushing="region", vtk=0, depth=1.5, **REFINED)
    history, _, events = check_test_books(folder, "dense_region")
    _, _, after = read_dump(os.path.join(folder, "particles_dense_region_N80.liggghts"))[0]
    odd = fragments_share_scale(events, after)
    check(not odd and {a["f_grain_scale"] for a in after} == set(scales),
          "the push's %d events: each one's fragments hold one N; the zones' N kept" % len(events))


@variants(*each_rank_count(1, 2))
def case_penetrometer_push(liggghts, work, ranks):
    """The meshes pushed into 50 grains by fix move/mesh, on 1 and 2 ranks: the cone takes an upward
    force from the grains; with strong grains nothing breaks, with weak ones the grains the tip loads
    break (fix crush through fix wall/gran hertz/scaled), the books hold and every tag stays unique
    (check_tags)."""
    results = {}
    for name, sigma in (("strong", 1e12), ("weak", 3e7)):
        folder = os.path.join(work, name)
        if os.path.isdir(folder):
            shutil.rmtree(folder)
        os.makedirs(folder)
        write_meshes(folder, 0.002, 0.008, 0.0033, 48)
        out = run_deck(liggghts, DECK, folder, {"sigma": sigma}, ranks=int(ranks), keep=True)
        rows = read_thermo(os.path.join(folder, "log.liggghts"))
        results[name] = (out, rows)
    _, strong = results["strong"]
    check(max(r["force[1]"] for r in strong) > 0.1, "the grains push the cone up (largest 500-step mean %.3g N)"
          % max(r["force[1]"] for r in strong))
    check(all(r["crush[1]"] == 0 and r["Atoms"] == 50 for r in strong), "strong grains: no event, 50 particles")
    _, weak = results["weak"]
    events = weak[-1]["crush[1]"]
    check(events > 0, "weak grains: %d broke under the tip" % events)
    check(all(r["Atoms"] == 50 + 13 * r["crush[1]"] for r in weak), "particles = 50 + 13 x events at every row")
    with open(os.path.join(work, "weak", "events.csv")) as f:
        header = f.readline().strip().split(",")
        rows = [dict(zip(header, line.strip().split(","))) for line in f if line.strip()]
    near = [abs(float(e["x"])) < 0.002 and abs(float(e["y"])) < 0.002 for e in rows]
    check(len(rows) == events and all(near), "the %d events are grains within D_c of the axis" % len(rows))


@variants(*each_rank_count(1, 2))
def case_adaptive(liggghts, work, ranks):
    """fix crush 'every adaptive' with a moving mesh: the cone pushed into weak grains gives the same
    events, at the same steps and with the same fragment tags, as 'every 1' (the bound covers the
    mesh nodes' displacement), on 1 and 2 ranks; and it skips steps."""
    logs, checked = {}, {}
    for every in ("1", "adaptive"):
        folder = os.path.join(work, every)
        if os.path.isdir(folder):
            shutil.rmtree(folder)
        os.makedirs(folder)
        write_meshes(folder, 0.002, 0.008, 0.0033, 48)
        out = run_deck(liggghts, DECK, folder, {"sigma": 3e8, "every": every}, ranks=int(ranks), keep=True)
        logs[every] = open(os.path.join(folder, "events.csv")).read()
        checked[every] = int(printed(out, "CHECKED"))
    events = logs["1"].count("\n") - 1
    check(events > 0 and logs["adaptive"] == logs["1"],
          "every adaptive: the same %d events at the same steps as every 1" % events)
    check(checked["adaptive"] < checked["1"], "every adaptive checked %d of the %d steps" % (checked["adaptive"], checked["1"]))


def prepare_chamber(liggghts, work, ranks, density="dense", **extra):
    """examples/penetration and examples/fontainebleau (whose files in.cone includes) copied into
    work, and the small chamber prepared there (in.chamber); returns the penetration folder."""
    for name in ("penetration", "fontainebleau"):
        target = os.path.join(work, name)
        if os.path.isdir(target):
            shutil.rmtree(target)
        shutil.copytree(os.path.join(EXAMPLES, name), target)
    folder = os.path.join(work, "penetration")
    variables = dict(CHAMBER, density=density, **extra)
    run_deck(liggghts, os.path.join(EXAMPLES, "penetration", "in.chamber"), folder, variables, ranks=ranks, keep=True)
    return folder


def push(liggghts, folder, ranks, **variables):
    """in.cone on the small chamber (v = 2 m/s unless given); returns the screen output."""
    settings = dict(CHAMBER, v=2, **variables)
    return run_deck(liggghts, os.path.join(EXAMPLES, "penetration", "in.cone"), folder, settings, ranks=ranks, keep=True)


def read_rows(path, numeric=True):
    """The rows of a CSV file as dicts, their values as floats unless numeric=False."""
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return [dict((k, float(v)) for k, v in row.items()) for row in rows] if numeric else rows


def grains0(folder):
    text = open(os.path.join(folder, "chamber_dense_N80.in")).read()
    return int(float(text.split("variable grains0 equal")[1].split()[0]))


def all_in_zone(events, history):
    """Whether every event lies inside in.cone's zone of crushing region at its step: within 1.5 D_c
    of the axis, from 1.5 D_c below the tip to 1 D_c above it (the tip from the history), to 0.02 D_c."""
    tolerance = 0.02 * DC
    return all(math.hypot(e["x"], e["y"]) <= 1.5 * DC + tolerance
               and -1.5 * DC - tolerance <= e["z"] - tip_at(history, e["step"]) <= 1.0 * DC + tolerance for e in events)


def check_sleeve(history, share=4.0, cone=0.866):
    """f_s is the sleeve's force over its length in the sand: sleeve_in (its embedded share of 3.75
    D_c) is 0 while the sleeve stands above the sand (the tip less than its cone's 0.866 D_c deep,
    give or take the top wall's rise), grows with the tip's depth past that, never exceeds 1; f_s is 0
    where it is 0, and elsewhere f_s pi D_c (3.75 D_c sleeve_in) / share is the sleeve's force."""
    inside = [r for r in history if r["sleeve_in"] > 0]
    check(all(0.0 <= r["sleeve_in"] <= 1.0 for r in history) and inside
          and all(r["f_s"] == 0 for r in history if r["sleeve_in"] == 0)
          and all(r["sleeve_in"] == 0 for r in history if r["depth_Dc"] < cone - 0.3),
          "sleeve_in within 0 - 1, 0 (and f_s 0) above the sand, %d rows with the sleeve in it" % len(inside))
    worst = max(abs(r["sleeve_in"] * 3.75 - (r["depth_Dc"] - cone)) for r in inside)
    check(worst < 0.3, "the embedded length follows the tip's depth less the cone's height (largest gap %.3f D_c: the"
          " top wall's rise)" % worst)
    force = max(abs(r["f_s"] * math.pi * DC * 3.75 * DC * r["sleeve_in"] / share - r["F_sleeve"])
                / max(abs(r["F_sleeve"]), 1e-9) for r in inside if abs(r["F_sleeve"]) > 0)
    check(force < 1e-6, "f_s times the embedded area is the sleeve's force (largest relative gap %.1e)" % force)


@variants(*each_rank_count(1, 2))
def case_cone_short(liggghts, work, ranks):
    """A short penetration (3 D_c) with crushing in the zone that follows the tip, on 1 and 2 ranks:
    the books (particles = grains + 13 x events at every row) and unique tags; q_c > 0 and rising
    with depth; every event inside the moving zone (1.5 D_c around the axis, from 1.5 D_c below the
    tip to 1 D_c above it) at its step; the VTK files of the particles and of the penetrometer read
    back; f_s over the sleeve's length in the sand (check_sleeve); post/penetration.py draws and
    summarises the test: the cone raised I_G near its tip above that zone's in the consolidated
    chamber, and left the far field's as it was."""
    ranks = int(ranks)
    folder = prepare_chamber(liggghts, work, ranks)
    out = push(liggghts, folder, ranks, crushing="region", vtk_every=1)
    history, n0, events = check_test_books(folder, "dense_region")
    shallow = [r["q_c"] for r in history if r["depth_Dc"] < 0.5]
    deep = [r["q_c"] for r in history if r["depth_Dc"] > 2.0]
    mean = lambda v: sum(v) / len(v)  # noqa: E731
    check(min(deep) >= 0 and mean(deep) > 0 and mean(deep) > 2 * mean(shallow),
          "q_c rises with depth: %.3g MPa over 2 - 3 D_c against %.3g over 0 - 0.5 D_c" % (mean(deep) / 1e6, mean(shallow) / 1e6))
    by_last_row = sum(1 for e in events if e["step"] <= history[-1]["step"])
    check(by_last_row == history[-1]["events"] and len(events) > 0,
          "%d events logged, %d of them by the last row, as it counts" % (len(events), by_last_row))
    check(all_in_zone(events, history), "every event inside the zone around the tip at its step")
    check_sleeve(history)
    if has_vtk_dumps(liggghts):
        try:
            import vtk
        except ImportError:
            vtk = None
        if vtk is not None:
            reader = vtk.vtkXMLUnstructuredGridReader()
            reader.SetFileName(os.path.join(folder, "vtk_dense_region_N80_end.vtu"))
            reader.Update()
            points = reader.GetOutput().GetNumberOfPoints()
            check(points == n0 + 13 * len(events), "the final .vtu holds the %d particles" % points)
            meshes = sorted(f for f in os.listdir(folder) if f.startswith("mesh_dense_region_N80_") and f.endswith(".vtk"))
            mesh = vtk.vtkDataSetReader()
            mesh.SetFileName(os.path.join(folder, meshes[-1]))
            mesh.Update()
            cells = mesh.GetOutput().GetNumberOfCells()
            check(len(meshes) >= 2 and cells == 12 + 24 + 24,
                  "%d penetrometer .vtk files, the last with the %d facets of cone, sleeve and shaft" % (len(meshes), cells))
    check("PENETRATION dense_region: depth" in out and "min left" in out, "progress lines with the depth and the time left")
    plot = subprocess.run(["/usr/bin/python3", POST, "--N", "80", "--Dc", str(DC), "--plateau", "1.5", "--out", "test",
                           "dense_region"], cwd=folder, stdout=subprocess.PIPE, universal_newlines=True, check=True).stdout
    check(all(os.path.exists(os.path.join(folder, f)) for f in ("penetration_test.png", "events_test.png", "gsd_test.png")),
          "post/penetration.py drew q_c, the events and the gradings")
    summary = read_rows(os.path.join(folder, "penetration_test_summary.csv"), numeric=False)
    row = dict((k, float(v)) for k, v in summary[0].items() if k != "label")
    # the chamber was consolidated with crushing everywhere: the cone's grading shows against the same
    # zones before the test (in.chamber's dump and events), not against the far field
    check(row["q_c_MPa"] > 0 and row["I_G_near"] > row["I_G_near0"] + 0.01 and abs(row["I_G_far"] - row["I_G_far0"]) < 0.01
          and row["chamber_events"] > 0,
          "summary: q_c %.3g MPa over the plateau; I_G near the tip %.3f against %.3f there before the test, far from it"
          " %.3f against %.3f (no event there); the gradings count the chamber's %d events (%s)"
          % (row["q_c_MPa"], row["I_G_near"], row["I_G_near0"], row["I_G_far"], row["I_G_far0"], row["chamber_events"],
             plot.strip()))


@variants(*each_rank_count(1, 2))
def case_cone_adaptive(liggghts, work, ranks):
    """fix crush 'every adaptive' in the scene (crushing everywhere: the burst of the grains without
    strength at the start, then the grains the cone loads): the same events at the same steps, with
    the same fragment tags, as 'every 1', on 1 and 2 ranks. (It checks every step here, as an
    unloaded grain of zero strength allows no step, and it did with the truncated normal too; the
    test is of exactness.)"""
    ranks = int(ranks)
    folder = prepare_chamber(liggghts, work, ranks)
    logs = {}
    for every in ("1", "adaptive"):
        push(liggghts, folder, ranks, crushing=1, crush_every=every, label="every_" + every, depth=2, vtk=0)
        logs[every] = open(os.path.join(folder, "events_pen_every_%s_N80.csv" % every)).read()
    events = logs["1"].count("\n") - 1
    check(events > 0 and logs["adaptive"] == logs["1"], "every adaptive: the same %d events as every 1" % events)


def check_balanced_books(folder, label):
    """A balanced push's books (check_test_books), with some events to balance."""
    history, _, _ = check_test_books(folder, label)
    check(history[-1]["events"] > 0, "%d events in the push" % history[-1]["events"])


@variants(*each_rank_count(2, 3, 4))
def case_cone_balance(liggghts, work, ranks):
    """The short penetration with the shift balancer before each stretch (balance, doc/balance.txt)
    on 2, 3 and 4 ranks (grids 2 x 1 x 1, 3 x 1 x 1, 2 x 2 x 1): the planes move with the fragments
    and never lose a particle (the books at every row, unique tags), each call leaves the particles
    at most 2% off even on 2 ranks (two slabs: the whole way in one call) and no fuller than before
    on 3 and 4."""
    ranks = int(ranks)
    folder = prepare_chamber(liggghts, work, ranks)
    out = push(liggghts, folder, ranks, crushing="region", vtk=0, label="balanced", balance=1, progress_every=5000)
    lines = [line for line in out.splitlines() if line.startswith("BALANCE:")]
    check(len(lines) >= 3, "%d balance calls, one before each stretch" % len(lines))
    before = [float(line.split()[2]) for line in lines]
    after = [float(line.split("->")[1].split()[0]) for line in lines]
    if ranks == 2:
        check(max(after) <= 1.02, "the fuller processor holds at most 2%% over the mean after each call (%.4f)"
              % max(after))
    else:
        # more than two slabs along x move one hop a call; a 2 x 2 grid cannot even out four quarters
        check(all(a <= b + 1e-12 for a, b in zip(after, before)) and after[-1] < before[-1] + 1e-12,
              "no call leaves the fullest processor fuller (%s)" % ", ".join("%.3f->%.3f" % p for p in zip(before, after)))
    check_balanced_books(folder, "balanced")


@variants(*each_rank_count(2, 3))
def case_cone_balance_z(liggghts, work, ranks):
    """The short penetration on slabs across the axis (grid "1 1 *", doc/running.md's choice for a
    refined chamber on many ranks) with the balancer moving the planes along z alone (balance_dims
    z) before each stretch, on 2 and 3 ranks: the uniform slabs of the box would leave the sand to
    the lowest ranks (the box reaches far above it, for the penetrometer); after each call the
    fullest holds at most 5% over the mean (one plane a call moves the whole way on 2 ranks, and the
    calls follow one another on 3), the books at every row and unique tags at the end."""
    ranks = int(ranks)
    folder = prepare_chamber(liggghts, work, ranks)
    out = push(liggghts, folder, ranks, crushing="region", vtk=0, label="slabs", balance=1, balance_dims="z",
               grid="1 1 *", progress_every=5000)
    lines = [line for line in out.splitlines() if line.startswith("BALANCE:")]
    check(len(lines) >= 3, "%d balance calls, one before each stretch" % len(lines))
    after = [float(line.split("->")[1].split()[0]) for line in lines]
    check(max(after[1:]) <= 1.05, "the fullest rank holds at most 5%% over the mean after each call but the first (%s)"
          % ", ".join("%.3f" % a for a in after))
    check_balanced_books(folder, "slabs")


@variants(ranks=2)
def case_cone_balance_work(liggghts, work):
    """The short penetration on slabs across the axis balanced along z by work (balance_weight 1:
    'weight neighbors', each particle 1 + its neighbour pairs) before each stretch, on 2 ranks: every
    call weighs by work, leaves the fuller rank at most 5% over the mean work after the first, and the
    books hold at every row with unique tags."""
    folder = prepare_chamber(liggghts, work, 2)
    out = push(liggghts, folder, 2, crushing="region", vtk=0, label="work", balance=1, balance_dims="z",
               balance_weight=1, grid="1 1 *", progress_every=5000)
    lines = [line for line in out.splitlines() if line.startswith("BALANCE:")]
    check(len(lines) >= 3 and all("largest work" in line for line in lines),
          "%d balance calls, one before each stretch, each by work" % len(lines))
    after = [float(line.split("->")[1].split()[0]) for line in lines]
    check(max(after[1:]) <= 1.05, "the fuller rank's work at most 5%% over the mean after each call but the first (%s)"
          % ", ".join("%.3f" % a for a in after))
    check_balanced_books(folder, "work")


@variants(*each_rank_count(2, 3))
def case_cone_fix_balance(liggghts, work, ranks):
    """The short penetration on slabs across the axis with fix balance (balance_every 1000: the planes
    move within the stretches, by work, along z; doc/fix_balance.txt) on 2 and 3 ranks: the meshes,
    the contact histories and fix crush's grains cross the moving planes. It moves the planes, every
    move leaves the fullest rank's work at most 5% over the mean after the first (one hop a move: 3
    slabs need two), every move starts above the fix's threshold (2% over the mean, to the four
    digits the out file prints), the books hold at every row, the tags are unique."""
    ranks = int(ranks)
    folder = prepare_chamber(liggghts, work, ranks)
    push(liggghts, folder, ranks, crushing="region", vtk=0, label="fixbal", balance_every=1000, balance_dims="z",
         balance_weight=1, grid="1 1 *", progress_every=5000)
    moves = read_balance_moves(os.path.join(folder, "balance_fixbal.txt"))
    after = [m["after"] for m in moves]
    before = [m["before"] for m in moves]
    check(len(moves) >= 2 and all(m["by_work"] for m in moves) and before[0] >= 1.5,
          "%d moves of the planes, each by work, the first at the setup from equal slabs (%.3f: the sand lies in "
          "the lowest part of the box)" % (len(moves), before[0] if moves else 0))
    check(max(after[2:] or [0]) <= 1.05 and all(b >= 1.02 for b in before),
          "the fullest rank's work at most 5%% over the mean after each move but the first two (%s), each move from "
          "above 1.02 (%s)" % (", ".join("%.3f" % a for a in after), ", ".join("%.4f" % b for b in before)))
    check_balanced_books(folder, "fixbal")


COLLECTIVES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "collectives", "count_collectives.c")


@variants(*each_rank_count(2))
def case_cone_event_lists(liggghts, work, ranks):
    """The short penetration of cone_short with fix crush's check_lists: event steps replaced without a
    rebuild (the fragments added to the granular list and to the moving cone's triangle lists) and,
    at every step until the next build, every touching pair in the list and every particle touching
    a triangle in that triangle's list (the run stops otherwise); the books as in cone_short."""
    ranks = int(ranks)
    folder = prepare_chamber(liggghts, work, ranks)
    out = push(liggghts, folder, ranks, crushing="region", crush_lists="check_lists yes")
    _, _, events = check_test_books(folder, "dense_region")
    inserted = int(float(re.search(r"EVENT STEPS WITHOUT A REBUILD (\S+)", out).group(1)))
    steps = len({e["step"] for e in events})
    check(1 <= inserted <= steps, "%d of the test's %d event steps replaced without a rebuild, the lists checked at "
          "every step until the next build" % (inserted, steps))


@variants(*each_rank_count(2))
def case_cone_collectives(liggghts, work, ranks):
    """The global collectives of the short penetration's steps on 2 ranks, counted by an MPI
    interposer (collectives/count_collectives.c, preloaded: each step's calls on rank 0, a step
    delimited by fix wall/servo's reduction): an ordinary step makes 6 (the distance check with the
    meshes' and fix crush's rebuild requests, the servo walls, dt/stiffness, and the three meshes'
    force and torque in one reduction each), where LIGGGHTS 3.8.0 made 16 (each mesh's bounding box
    and rebuild flag in reductions of their own, its force and torque in two: patches/0016) and fix
    crush one more (its events and particle count, now agreed at the rebuilds). The books hold and
    the tags are unique."""
    ranks = int(ranks)
    library = os.path.join(work, "libcount_collectives.so")
    os.makedirs(work, exist_ok=True)
    subprocess.run(["mpicc", "-shared", "-fPIC", "-O2", "-o", library, COLLECTIVES], check=True)
    folder = prepare_chamber(liggghts, work, ranks)
    counts = os.path.join(folder, "collectives.txt")
    command = deck_command(liggghts, "in.cone", dict(CHAMBER, v=2, crushing="region", vtk=0, label="coll"), ranks)
    at = command.index(liggghts)  # the interposer, for the ranks mpiexec starts
    command[at:at] = ["-x", "LD_PRELOAD=" + library, "-x", "COUNT_COLLECTIVES_OUT=" + counts]
    proc = subprocess.run(command, cwd=folder, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
    check(proc.returncode == 0 and "ERROR" not in proc.stdout, "in.cone ran under the interposer:\n" + proc.stdout[-2000:])
    histogram = dict(tuple(int(w) for w in line.split()) for line in open(counts))
    steps = sum(histogram.values())
    ordinary = max(histogram, key=histogram.get)
    check(steps > 10000 and histogram[ordinary] > 0.9 * steps and ordinary <= 6,
          "%d of %d steps make %d collectives (at most 6; 16 without patches/0016, 7 with fix crush's own); "
          "the others: %s"
          % (histogram[ordinary], steps, ordinary,
             ", ".join("%d x %d" % (n, k) for k, n in sorted(histogram.items()) if k != ordinary)))
    check_balanced_books(folder, "coll")


@variants(ranks=2, timeout=900)
def case_cone_fix_balance_resume(liggghts, work):
    """A test with fix balance (balance_every 1000, by work, slabs along z) killed right after a
    checkpoint and resumed (-var resume 1): the restart keeps no planes, so the resumed run starts
    from equal slabs and the fix balances them at its setup; the history up to the checkpoint is
    the uninterrupted one's, the books hold at every row after it, the test ends within a history
    row of the uninterrupted one, and the fix moved the planes in the resumed run."""
    folder = prepare_chamber(liggghts, work, 2)
    settings = dict(CHAMBER, v=2, crushing="region", vtk=0, checkpoint_every=5000, balance_every=1000,
                    balance_dims="z", balance_weight=1, grid="1 1 *")
    run_deck(liggghts, os.path.join(EXAMPLES, "penetration", "in.cone"), folder, dict(settings, label="whole"),
             ranks=2, keep=True)
    variables = dict(settings, label="killed")
    newest = kill_after(liggghts, folder, 2, variables, 90000 + 10000, 0.3, deck="in.cone", base="ckpt_pen_killed_N80")
    check(newest is not None and newest >= 100000, "killed after the checkpoint of step %s" % newest)
    os.remove(os.path.join(folder, "balance_killed.txt"))
    run_deck(liggghts, os.path.join(EXAMPLES, "penetration", "in.cone"), folder, dict(variables, resume=1),
             ranks=2, keep=True)
    whole = read_rows(os.path.join(folder, "penetration_whole_N80.csv"))
    resumed = read_rows(os.path.join(folder, "penetration_killed_N80.csv"))
    before = [r for r in resumed if r["step"] <= newest]
    # after the checkpoint the planes differ (equal slabs again, then the fix's), the sums' order with
    # them: the time steps part, and the test may end a history row later or earlier
    check(before == whole[:len(before)] and abs(len(resumed) - len(whole)) <= 1,
          "the resumed history's %d rows up to step %d are the uninterrupted one's; %d rows in all against %d"
          % (len(before), newest, len(resumed), len(whole)))
    n0 = grains0(folder)
    check(all(r["particles"] == n0 + 13 * r["events"] for r in resumed),
          "particles = %d + 13 x events at every row after the resume (%d events)" % (n0, resumed[-1]["events"]))
    moves = read_balance_moves(os.path.join(folder, "balance_killed.txt"))
    check(moves and moves[0]["step"] == newest,
          "the resumed run's fix balance moved the planes from equal slabs at its setup, step %s (%d moves)"
          % (moves[0]["step"] if moves else "-", len(moves)))


@variants(*each_rank_count(1, 2))
def case_cone_resume(liggghts, work, ranks):
    """A test killed right after a checkpoint resumes (-var resume 1) to the same history and events
    as the uninterrupted one: the meshes, their motion and the tip's clock come back. On 2 ranks,
    with the balancer's planes set again from the restart before the first stretch: the history up
    to the checkpoint is the uninterrupted one's, and the books hold at every row after it (a
    resumed run sums forces in another order there: the digits part)."""
    ranks = int(ranks)
    folder = prepare_chamber(liggghts, work, ranks)
    settings = dict(CHAMBER, v=2, crushing="region", vtk=0, checkpoint_every=5000, balance=int(ranks > 1))
    run_deck(liggghts, os.path.join(EXAMPLES, "penetration", "in.cone"), folder, dict(settings, label="whole"),
             ranks=ranks, keep=True)
    variables = dict(settings, label="killed")
    # in.chamber ends at step 90000, where the test begins: killed after its second checkpoint
    newest = kill_after(liggghts, folder, ranks, variables, 90000 + 10000, 0.3, deck="in.cone", base="ckpt_pen_killed_N80")
    check(newest is not None and newest >= 100000, "killed after the checkpoint of step %s" % newest)
    run_deck(liggghts, os.path.join(EXAMPLES, "penetration", "in.cone"), folder, dict(variables, resume=1),
             ranks=ranks, keep=True)
    if ranks > 1:
        whole = read_rows(os.path.join(folder, "penetration_whole_N80.csv"))
        resumed = read_rows(os.path.join(folder, "penetration_killed_N80.csv"))
        before = [r for r in resumed if r["step"] <= newest]
        # after the checkpoint the sums' order differs (the restart's particle order against the
        # fragments' slots of event steps replaced in place): the time steps part, and the test may
        # end a history row later or earlier
        check(before == whole[:len(before)] and abs(len(resumed) - len(whole)) <= 1,
              "the resumed history's %d rows up to step %d are the uninterrupted one's; %d rows in all against %d"
              % (len(before), newest, len(resumed), len(whole)))
        n0 = grains0(folder)
        check(all(r["particles"] == n0 + 13 * r["events"] for r in resumed),
              "particles = %d + 13 x events at every row after the resume (%d events)" % (n0, resumed[-1]["events"]))
        return
    for name in ("penetration_%s_N80.csv", "events_pen_%s_N80.csv"):
        whole = open(os.path.join(folder, name % "whole")).read()
        resumed = open(os.path.join(folder, name % "killed")).read()
        check(whole == resumed and whole.count("\n") > 2, "%s: the resumed test's %d lines are the uninterrupted one's"
              % (name % "killed", resumed.count("\n")))


@variants(*each_rank_count(2))
def case_whole_chamber(liggghts, work, ranks):
    """The whole chamber (in.geometry's sector 360) on 2 ranks, the ranks' cut through the axis, 4 D_c
    wide, and the quarter chamber of that width: the whole one's sand fills both sides of the axis
    from the lo walls at -half, about a quarter of the grains in each quadrant; a push with crushing in the zone keeps the books and every tag unique, with every
    event inside the zone; q_c is the whole cone's force over the whole cone's area, and it lies near
    the quarter chamber's q_c on the same grains' draw (the quarter's factor 4 on the whole cone would
    read four times it)."""
    ranks = int(ranks)
    q_c = {}
    for sector in (90, 360):
        folder = prepare_chamber(liggghts, os.path.join(work, str(sector)), ranks, sector=sector, width=4)
        push(liggghts, folder, ranks, crushing="region", vtk=0, depth=2, sector=sector, width=4)
        history, _, events = check_test_books(folder, "dense_region")
        q_c[sector] = sum(r["q_c"] for r in history if r["depth_Dc"] > 1.0) / sum(1 for r in history if r["depth_Dc"] > 1.0)
        if sector == 90:
            continue
        _, _, atoms = read_dump(os.path.join(folder, "chamber_dense_N80.liggghts"))[0]
        half = 0.5 * 4 * DC
        quadrants = [sum(1 for a in atoms if (a["x"] > 0) == sx and (a["y"] > 0) == sy) / len(atoms)
                     for sx in (True, False) for sy in (True, False)]
        lowest = min(min(a["x"] - a["radius"], a["y"] - a["radius"]) for a in atoms)
        overlap = 0.05 * max(a["radius"] for a in atoms)  # the grains press into the walls a little
        check(all(0.2 < q < 0.3 for q in quadrants) and -half - overlap <= lowest < -half + 0.1 * half,
              "%d grains, %s of them in each quadrant; the sand reaches the lo walls at -%.4f m (%.4f m)"
              % (len(atoms), ["%.3f" % q for q in quadrants], half, lowest))
        area = math.pi * DC ** 2 / 4
        worst = max(abs(r["q_c"] - r["F_cone"] / area) for r in history) / max(r["q_c"] for r in history)
        check(worst < 1e-6, "q_c = F_cone / (pi D_c^2 / 4) at every row, the whole cone's force (to %.1e)" % worst)
        check(events and all_in_zone(events, history), "the whole chamber's %d events inside the zone around the tip" % len(events))
    ratio = q_c[360] / q_c[90]
    check(0.4 < ratio < 2.5, "q_c over 1 - 2 D_c: %.3g MPa in the whole chamber, %.3g in the quarter (ratio %.2f, "
          "within 0.4 - 2.5)" % (q_c[360] / 1e6, q_c[90] / 1e6, ratio))


def case_sector_refused(liggghts, work):
    """A sector other than 90 or 360 stops in.chamber before anything is built, with a line that names
    the variable and the two values it takes."""
    out = run_deck(liggghts, os.path.join(EXAMPLES, "penetration", "in.chamber"), os.path.join(work, "penetration"),
                   dict(CHAMBER, sector=180), expect_fail=True)
    check("sector 180: expected 90 (a quarter chamber) or 360 (the whole chamber)" in out and "ERROR" in out
          and "Created" not in out, "sector 180 refused before the box is made: %s" % out.strip().splitlines()[-1])


def study_header():
    """The columns of scripts/penetration_study.sh's study.csv (its header line)."""
    script = open(STUDY).read()
    columns = [re.search(r'^%s="([^"]*)"' % name, script, re.M).group(1) for name in ("header0", "path_columns", "steady_columns")]
    check(re.search(r'^header="\$header0,\$path_columns,\$steady_columns"', script, re.M) is not None,
          "penetration_study.sh's header is header0, path_columns and steady_columns")
    return ",".join(columns).split(",")


def dry_run(work, names, cases=None):
    """scripts/penetration_study.sh --dry-run on names (cases: another table than cases.csv): (exit status,
    {case: (ranks, in.cone's -var pairs)}, {case: in.chamber's -var pairs}, stderr, the cases run twice)."""
    env = dict(os.environ, PENETRATION_CASES=cases or CASES_CSV)
    proc = subprocess.run(["bash", STUDY, "--dry-run", os.path.join(work, "dry")] + list(names), env=env,
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True)
    pairs = lambda text: [tuple(w.split(" ", 1)) for w in text.split(" -var ")[1:]]  # noqa: E731
    tests, chambers, twice = {}, {}, []
    for line in proc.stdout.splitlines():
        m = re.match(r"== (\S+): mpirun -np (\d+) liggghts -in in\.cone( .*)$", line)
        if m:
            twice += [m.group(1)] if m.group(1) in tests else []
            tests[m.group(1)] = (m.group(2), pairs(m.group(3)))
        m = re.match(r"== (\S+): chamber \S+: mpirun -np 2 liggghts -in in\.chamber( .*)$", line)
        if m:
            chambers[m.group(1)] = pairs(m.group(2))
    return proc.returncode, tests, chambers, proc.stderr, twice


def case_study_cases(liggghts, work):
    """studies/penetration/cases.csv and scripts/penetration_study.sh agree: the runner's dry run of every
    case of the table runs it once, on its row's ranks, with its row's settings as in.cone's variables
    (density, N, crushing, v, width, distribution, sigma_v, seed, the case's label, fragment_density,
    depth, then test_vars and chamber_vars) and in.chamber's (density, N, width, depth, sigma_v, seed,
    fragment_density, then chamber_vars); each group runs the cases whose groups column names it. A
    table with a bad value in any row (a crushing mode the decks lack, a velocity that is no number,
    a variable without its value, a case named twice) stops the runner before anything runs, with a
    message that names the row's case, the column and the value; so does an unknown name."""
    del liggghts
    with open(CASES_CSV) as f:
        rows = list(csv.DictReader(f))
    names = [r["case"] for r in rows]
    rc, tests, chambers, err, twice = dry_run(work, names)
    check(rc == 0 and sorted(tests) == sorted(names) and sorted(chambers) == sorted(names) and not twice,
          "the dry run of the table's %d cases runs each once (%d tests, %d chambers, twice: %s)%s"
          % (len(names), len(tests), len(chambers), twice, "" if rc == 0 else ": " + err.strip()[-300:]))
    wrong = []
    for r in rows:
        listed = lambda column: [tuple(kv.split("=", 1)) for kv in r[column].split(";") if kv]  # noqa: E731
        cone = [(c, r[c]) for c in ("density", "N", "crushing", "v", "width", "distribution", "sigma_v", "seed")]
        cone += [("label", r["case"]), ("fragment_density", r["fragment_density"]), ("depth", r["depth"])]
        cone += listed("test_vars") + listed("chamber_vars")
        chamber = [(c, r[c]) for c in ("density", "N", "width", "depth", "sigma_v", "seed", "fragment_density")]
        chamber += listed("chamber_vars")
        if tests[r["case"]] != (r["ranks"], cone) or chambers[r["case"]] != chamber:
            wrong.append(r["case"])
    check(not wrong, "every case runs with its row's settings (not: %s)" % ", ".join(wrong[:5]))
    groups, wrong = sorted({g for r in rows for g in r["groups"].split()}), []
    for group in groups:
        rc, tests, _, _, twice = dry_run(work, [group])
        if rc != 0 or twice or sorted(tests) != sorted(r["case"] for r in rows if group in r["groups"].split()):
            wrong.append(group)
    check(not wrong, "each of the %d groups runs the cases that name it, each once (not: %s)" % (len(groups), ", ".join(wrong)))
    def table(name, changed):
        """A copy of the table, its rows as changed gives them."""
        path = os.path.join(work, name)
        with open(path, "w") as f:
            writer = csv.DictWriter(f, list(rows[0]), lineterminator="\n")
            writer.writeheader()
            writer.writerows(changed)
        return path
    at = names.index("refined_N34_pristine_w40_s2")
    for column, value, words in (("crushing", "sometimes", "crushing 'sometimes' is not one of region, 0, 1"),
                                 ("v", "fast", "v 'fast' is not a positive number"),
                                 ("chamber_vars", "refine", "chamber_vars 'refine' is not a list name=value")):
        bad = table("bad_%s.csv" % column, rows[:at] + [dict(rows[at], **{column: value})] + rows[at + 1:])
        rc, tests, _, err, _ = dry_run(work, ["dense_region"], bad)
        check(rc == 2 and not tests and "line %d, case refined_N34_pristine_w40_s2: %s" % (at + 2, words) in err,
              "a bad %s in another row stops the runner, naming the row, the column and the value: %s"
              % (column, err.strip().splitlines()[-1:]))
    rc, tests, _, err, _ = dry_run(work, ["dense_region"], table("twice.csv", rows + [rows[at]]))
    check(rc == 2 and not tests and "a second row of case refined_N34_pristine_w40_s2" in err,
          "a case named twice in the table is refused: %s" % err.strip().splitlines()[-1:])
    rc, tests, _, err, _ = dry_run(work, ["pristine_widest"])
    check(rc == 2 and not tests and "unknown case or group pristine_widest" in err,
          "an unknown name is refused: %s" % err.strip().splitlines()[-1:])


def write_study(path, rows, drop=()):
    """A stand-in study.csv: each row (case, seed, q_c, settings) on the doc's dense cone at 0.5 m/s, the
    columns in drop left out (an older study.csv)."""
    header = [c for c in study_header() if c not in drop]
    base = {"density": "dense", "N": "80", "D_c_over_d50": "2.125", "crushing": "region", "v": "0.5", "width": "10",
            "ranks": "2", "distribution": "normal_clipped_originals", "sigma_v": "1e5", "fragment_density": "scaled",
            "depth": "4", "tip_shape": "cone", "sigma_lim0": "5e9", "neighbor_style": "multi", "extra": "",
            "sigma_v_axis": "", "q_c_slope_last2": ""}
    with open(path, "w") as f:
        writer = csv.DictWriter(f, header, restval="1", extrasaction="ignore")
        writer.writeheader()
        for case, seed, q_c, settings in rows:
            writer.writerow(dict(base, case=case, seed=seed, q_c_MPa=q_c, **settings))
    return path


def run_stats(*args):
    """post/penetration_stats.py --markdown --members on args: ({label: (seeds, mean q_c)},
    {label: [cases]}, the other lines, the warnings)."""
    proc = subprocess.run([sys.executable, STATS, "--markdown", "--members"] + list(args), stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, universal_newlines=True, check=True)
    table, members, rest, listing = {}, {}, [], False
    for line in proc.stdout.splitlines():
        cells = [c.strip() for c in line.strip("| ").split(" | ")]
        listing = line.startswith("cases of each setting") or (listing and line != "")
        if line.startswith("| ") and len(cells) > 3 and cells[1].isdigit():
            table[cells[0]] = (int(cells[1]), float(cells[2]))
        elif listing and ": " in line:
            label, cases = line.rsplit(": ", 1)
            members[label] = cases.split(",")
        else:
            rest.append(line)
    return table, members, rest, [w for w in proc.stderr.splitlines() if "warning" in w]


def fields(label):
    return dict(word.split("=", 1) for word in label.split())


def case_stats_groups(liggghts, work):
    """post/penetration_stats.py tells apart what the study's columns tell apart: a cone, a pile
    (tip_shape flat; its stress_every, an output, names no setting), the weak sand's cone (sigma_lim0
    5e8) and its pile, on the same density, N, crushing, v and seeds, are four settings with their own
    means, named in the output;
    the same rows without those columns (an older study.csv) fall into one setting of in.cone's
    defaults, and the tool warns that rows of one seed there differ in q_c."""
    del liggghts
    groups = {"cone_s": ({}, (1.0, 1.2, 1.4)), "pile_s": ({"tip_shape": "flat", "extra": "stress_every=0.5"}, (5.0, 6.0, 7.0)),
              "weak_cone_s": ({"sigma_lim0": "5e8"}, (0.8, 0.9, 1.0)),
              "weak_pile_s": ({"tip_shape": "flat", "sigma_lim0": "5e8", "extra": "stress_every=0.5"}, (2.0, 2.5, 3.0))}
    rows = [(name + str(k + 1), seed, q[k], settings) for name, (settings, q) in groups.items() for k, seed in enumerate(SEEDS)]
    table, members, _, warnings = run_stats(write_study(os.path.join(work, "study.csv"), rows))
    check(len(table) == 4 and not warnings, "four settings, no warning: %s" % "; ".join(table))
    for name, (settings, q) in groups.items():
        label = [lab for lab, cases in members.items() if cases == [name + "1", name + "2", name + "3"]]
        check(len(label) == 1 and table[label[0]] == (3, round(sum(q) / 3, 2))
              and all(fields(label[0]).get(k) == v for k, v in dict(DEFAULTS_NAMED, **settings).items() if v and k != "extra")
              and "extra" not in fields(label[0]),
              "%s*: a setting of its own, 3 seeds, q_c %.2f MPa, named %s" % (name, sum(q) / 3, label and label[0]))
    old = write_study(os.path.join(work, "old.csv"), rows, drop=("tip_shape", "sigma_lim0", "neighbor_style", "extra"))
    table, members, _, warnings = run_stats(old)
    check(len(table) == 1, "without the columns the four fall into one setting: %s" % "; ".join(table))
    label, = table
    check(table[label] == (3, 1.2) and "tip_shape=cone sigma_lim0=5e9 neighbor_style=multi" in label
          and len(members[label]) == 12 and len(warnings) == 9,
          "without the columns: one setting of the defaults (%s), the first seed's rows kept, %d warnings (%s)"
          % (label, len(warnings), warnings[0]))


def case_stats_study_csv(liggghts, work):
    """studies/penetration/penetration_study.csv has penetration_study.sh's columns, and penetration_stats.py on it
    puts no pile with a cone nor the weak sand with Table 1's (told from the case names: pile_*,
    weak_*), warns of no two rows of one setting and seed that differ; the weak pile with crushing
    everywhere (the "dense, crushing 1, 100 kPa, 2.11 MPa, 61 events" setting the older grouping
    called a cone) is a setting of its own; and q_c falls with v by studies/penetration/history.md's 0.19 +- 0.05
    MPa per halving (the 30 rate runs, one intercept per seed)."""
    del liggghts, work
    header = open(STUDY_CSV).readline().strip().split(",")
    check(header == study_header(), "studies/penetration/penetration_study.csv has the columns penetration_study.sh writes (%d)" % len(header))
    table, members, rest, warnings = run_stats(STUDY_CSV, "--fit-log2", "v")
    check(not warnings, "no two rows of one setting and seed differ in q_c")
    mixed = []
    for label, cases in members.items():
        tips = {"flat" if re.match(r"(weak_)?pile_", c) else "cone" for c in cases}
        strengths = {"5e8" if c.startswith("weak_") else "5e9" for c in cases}
        if tips != {fields(label)["tip_shape"]} or strengths != {fields(label)["sigma_lim0"]}:
            mixed.append(",".join(cases))
    check(len(members) == len(table) == 22 and not mixed,
          "%d settings of %d cases, none with two tip shapes or two sigma_lim0, none named for another (%s)"
          % (len(members), sum(map(len, members.values())), "; ".join(mixed)))
    weak_pile = [lab for lab, cases in members.items() if cases == ["weak_pile_1_s1", "weak_pile_1_s2", "weak_pile_1_s3"]]
    cone_1 = [lab for lab in table if (fields(lab)["crushing"], fields(lab)["sigma_v"], fields(lab)["tip_shape"]) == ("1", "1e5", "cone")]
    check(len(weak_pile) == 1 and table[weak_pile[0]] == (3, 2.11) and not cone_1,
          "the weak pile everywhere: its own setting (%s), 3 seeds, 2.11 MPa; no cone crushing everywhere at 100 kPa"
          % (weak_pile and weak_pile[0]))
    fit = [re.search(r"([-+]\d\.\d+) \+- (\d\.\d+) per halving.*\((\d+) runs, (\d+) seeds\)", line) for line in rest]
    fit = [m.groups() for m in fit if m]
    check(fit == [("-0.188", "0.048", "30", "6")], "q_c against log2 v: %s per halving, runs, seeds" % fit)


def case_stats_fit_log2(liggghts, work):
    """--fit-log2 v on a stand-in ladder whose slope and standard error are known: q_c = a_seed +
    0.2 log2 v + e over v = 0.5, 1, 2 and three seeds (a = 1, 2, 3), e = (+0.1, -0.2, +0.1) in each
    seed (orthogonal to the intercept and to log2 v): the slope is 0.2, the residuals' sum of squares
    0.18 over 9 - 3 - 1 = 5 degrees of freedom, the squares of log2 v about each seed's mean sum to
    6, so se = sqrt(0.18 / 5 / 6) = 0.0775; a second setting (crushing 0) is fitted apart."""
    del liggghts
    e = {"0.5": 0.1, "1": -0.2, "2": 0.1}
    rows = [("%s_v%s_s%d" % (crushing, v, k + 1), seed, a + 0.2 * math.log2(float(v)) + e[v] + offset, {"v": v, "crushing": crushing})
            for crushing, offset in (("region", 0.0), ("0", 5.0)) for k, (seed, a) in enumerate(zip(SEEDS, (1, 2, 3)))
            for v in e]
    _, _, rest, _ = run_stats(write_study(os.path.join(work, "ladder.csv"), rows), "--fit-log2", "v")
    fit = [m.groups() for m in (re.search(r"crushing=(\S+) .*: v = 0.5, 1, 2: \+(\d\.\d+) \+- (\d\.\d+) MPa per doubling"
                                          r".*\((\d+) runs, (\d+) seeds\)", line) for line in rest) if m]
    check(sorted(fit) == [("0", "0.200", "0.077", "9", "3"), ("region", "0.200", "0.077", "9", "3")],
          "slope 0.200 +- 0.077 per doubling of v, for each of the two settings: %s" % fit)


def case_stats_versus(liggghts, work):
    """--versus A B on stand-in studies of known means: B's q_c (2.0, 2.2, 2.4) against A's (1.0, 1.2, 1.4
    and a second row of one seed, dropped) differ by +1.000 +- 0.163 (each se 0.2 / sqrt(3)): Welch's df
    4, t 2.776, the 95% interval +0.547 .. +1.45, resolved; B against a set of the same mean (1.9, 2.2,
    2.5: se 0.173) by 0.000 +- 0.208, df 3.49, interval -0.613 .. +0.613, not resolved."""
    del liggghts
    rows = [("a_s%d" % (k + 1), seed, q, {}) for k, (seed, q) in enumerate(zip(SEEDS, (1.0, 1.2, 1.4)))]
    rows += [("a_again_s1", SEEDS[0], 9.9, {})]
    rows += [("b_s%d" % (k + 1), seed, q, {"N": "34"}) for k, (seed, q) in enumerate(zip(SEEDS, (2.0, 2.2, 2.4)))]
    rows += [("c_s%d" % (k + 1), seed, q, {"N": "17"}) for k, (seed, q) in enumerate(zip(SEEDS, (1.9, 2.2, 2.5)))]
    study = write_study(os.path.join(work, "versus.csv"), rows)
    _, _, rest, _ = run_stats(study, "--versus", "a_*", "b_*", "--versus", "b_*", "c_*")
    changes = [line.strip() for line in rest if line.strip().startswith("change")]
    check(changes == ["change +1 +- 0.163 (unpaired, Welch), 95% interval +0.547 .. +1.45, p 0.0036, resolved: yes",
                      "change +0 +- 0.208 (unpaired, Welch), 95% interval -0.613 .. +0.613, p 1, resolved: no"],
          "b against a: %s; c against b: %s" % tuple(changes + ["?", "?"])[:2])


def stats_run(*args):
    """post/penetration_stats.py on args: (exit status, stdout, stderr), whatever the status."""
    proc = subprocess.run([sys.executable, STATS] + list(args), stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          universal_newlines=True)
    return proc.returncode, proc.stdout, proc.stderr


def case_stats_settings_apart(liggghts, work):
    """The statistics never mix settings silently. --versus and --ratio stop, naming the columns that
    vary, where one side's pattern matches cases of two settings (a cone at 100 kPa and a pile at
    400 kPa under one pattern: the mix that read 3.55 as a ratio); an output-only variable
    (stress_every in extra) does not split the pile from the cone, so --vary tip_shape compares them;
    --vary crushing compares every pair of modes (0 -> 1, 0 -> region and 1 -> region); and
    post/cpt_interpretation.py refuses a flat tip (its q_c column is a pile's q_b)."""
    del liggghts
    rows = [("cone_s%d" % (k + 1), seed, q, {}) for k, (seed, q) in enumerate(zip(SEEDS, (1.0, 1.2, 1.4)))]
    rows += [("cone_hi_s%d" % (k + 1), seed, q, {"sigma_v": "4e5"}) for k, (seed, q) in enumerate(zip(SEEDS, (3.0, 3.3, 3.6)))]
    rows += [("pile_s%d" % (k + 1), seed, q, {"tip_shape": "flat", "extra": "stress_every=0.5"})
             for k, (seed, q) in enumerate(zip(SEEDS, (2.0, 2.4, 2.8)))]
    rows += [("all_s%d" % (k + 1), seed, q, {"crushing": "1"}) for k, (seed, q) in enumerate(zip(SEEDS, (0.6, 0.8, 1.0)))]
    rows += [("off_s%d" % (k + 1), seed, q, {"crushing": "0"}) for k, (seed, q) in enumerate(zip(SEEDS, (1.5, 1.7, 1.9)))]
    study = write_study(os.path.join(work, "apart.csv"), rows)
    for option in ("--versus", "--ratio"):
        rc, out, err = stats_run(study, option, "cone_*", "pile_*")
        check(rc != 0 and "cone_*" in err and "sigma_v" in err and "2 settings" in err,
              "%s with cone_* matching 100 and 400 kPa stops, naming sigma_v: %s" % (option, err.strip()[-200:]))
        rc, out, err = stats_run(study, option, "cone_s*", "pile_*")
        check(rc == 0, "%s on one setting a side runs: %s" % (option, err.strip()[-200:]))
    rc, out, err = stats_run(study, "--vary", "tip_shape")
    check(rc == 0 and re.search(r"tip_shape cone -> flat: 1\.20 -> 2\.40 MPa", out) is not None,
          "--vary tip_shape compares the pile with the cone (stress_every does not split them): %s"
          % [line for line in out.splitlines() if "tip_shape" in line])
    rc, out, err = stats_run(study, "--vary", "crushing")
    pairs = re.findall(r"crushing (\S+) -> (\S+):", out)
    check(sorted(pairs) == [("0", "1"), ("0", "region"), ("1", "region")],
          "--vary crushing compares every pair of modes: %s" % pairs)
    proc = subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "post", "cpt_interpretation.py"), study],
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True)
    check(proc.returncode != 0 and "pile_s1" in proc.stderr and "q_b" in proc.stderr,
          "the CPT interpretation refuses the flat tip: %s" % proc.stderr.strip()[-200:])
    proc = subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "post", "cpt_interpretation.py"), study, "--cases", "cone_s*"],
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True)
    check(proc.returncode == 0, "and reads the cones alone: %s" % proc.stderr.strip()[-200:])


def case_levelling(liggghts, work):
    """Where q_c has levelled off. post/penetration.py's slope over the last 2 D_c on a stand-in
    history whose q_c rises 2 MPa per D_c to 6 D_c and 0.3 after it (rows every 0.05 D_c to 8 D_c):
    0.300 MPa per D_c over 8 bins, the early rise left out; penetration_stats.py --levelling over the
    seeds' slopes of two settings: (0.1, -0.1, 0.02) levelled off (mean +0.007, its interval holding
    zero), (0.5, 0.6, 0.7) still rising (+0.600, 95% interval +0.352 .. +0.848 with df 2)."""
    del liggghts
    sys.path.insert(0, os.path.dirname(POST))
    import penetration  # noqa: E402
    history = [{"depth_Dc": 0.05 * k, "q_c": 1e6 * (5 + 2 * min(0.05 * k, 6.0) + 0.3 * max(0.05 * k - 6.0, 0.0))}
               for k in range(161)]
    slope, low, high, bins = penetration.late_slope(history)
    check(abs(slope - 0.3) < 1e-9 and bins == 8 and abs(low - 0.3) < 1e-9 and abs(high - 0.3) < 1e-9,
          "slope over the last 2 D_c %.6f (%.6f .. %.6f) over %d bins" % (slope, low, high, bins))
    rows = [("flat_s%d" % (k + 1), seed, 10.0, {"q_c_slope_last2": s}) for k, (seed, s) in enumerate(zip(SEEDS, (0.1, -0.1, 0.02)))]
    rows += [("rising_s%d" % (k + 1), seed, 12.0, {"q_c_slope_last2": s, "sigma_v": "4e5"})
             for k, (seed, s) in enumerate(zip(SEEDS, (0.5, 0.6, 0.7)))]
    study = write_study(os.path.join(work, "levelling.csv"), rows)
    rc, out, err = stats_run(study, "--levelling")
    flat = [line for line in out.splitlines() if "sigma_v=1e5" in line and "per D_c" in line]
    rising = [line for line in out.splitlines() if "sigma_v=4e5" in line and "per D_c" in line]
    check(rc == 0 and len(flat) == 1 and "+0.007 MPa per D_c" in flat[0] and "levelled off" in flat[0],
          "(0.1, -0.1, 0.02): levelled off: %s" % flat)
    check(len(rising) == 1 and "+0.600 MPa per D_c (+0.352 .. +0.848" in rising[0] and "still rising" in rising[0],
          "(0.5, 0.6, 0.7): still rising: %s" % rising)


def case_path_crushing(liggghts, work):
    """post/penetration.py's crushing about the tip's path on grains and events at known places (D_c =
    1, the final tip at z = 0): the path's distance is the radius above the tip and the distance to
    the tip below it, so of five events at distances 0.5 (above), 1.5 (above), 1.5 (below, on the
    axis), 0.5 (level with the tip) and 4 (beside it, beyond the far field's 3), two lie within 1, four within
    2, one in the far field; I_G about the path is the grading of the four grains within 2 (not of the
    one at radius 2.5, 2 below the tip: 3.2 away) with the four events' removed volume."""
    del liggghts, work
    sys.path.insert(0, os.path.dirname(POST))
    import penetration  # noqa: E402
    places = [(0.5, 0.0, 5.0), (1.5, 0.0, 2.0), (0.0, 0.0, -1.5), (0.3, 0.4, -0.0), (4.0, 0.0, 0.0), (2.5, 0.0, -2.0)]
    distances = [penetration.path_distance(x, y, z, 0.0) for x, y, z in places]
    check(all(abs(d - e) < 1e-12 for d, e in zip(distances, (0.5, 1.5, 1.5, 0.5, 4.0, math.hypot(2.5, 2.0)))),
          "distances from the path %s" % distances)
    atoms = dict((k + 1, (x, y, z, 0.1 * (k + 1), 0.0, None)) for k, (x, y, z) in enumerate(places))
    events = [{"x": x, "y": y, "z": z, "diameter": 0.3} for x, y, z in places[:5]]
    kept, N, fines_top = 0.53, 2.0, 0.01
    got = penetration.path_crushing(atoms, events, events, kept, 0.0, 1.0, N, 2.0, 3.0, fines_top)
    near = [(2 * 0.1 * k / N, math.pi / 6 * (2 * 0.1 * k) ** 3) for k in (1, 2, 3, 4)]
    expected = penetration.grading(near, 4 * math.pi / 6 * 0.3 ** 3 * (1 - kept), fines_top)[1]
    check((got["events_path1"], got["events_path2"], got["events_far"]) == (2, 4, 1) and abs(got["I_G_path"] - expected) < 1e-12,
          "events within 1 and 2 D_c of the path and in the far field %s, I_G %.6f (%.6f)"
          % ((got["events_path1"], got["events_path2"], got["events_far"]), got["I_G_path"], expected))


def case_depth_bins(liggghts, work):
    """post/penetration_depth.py on two stand-in histories whose q_c is known in each bin of depth:
    test a reads 1 MPa on 0 - 1 D_c and 3 MPa on 1 - 2 (rows at 0.25, 0.75, 1.25, 1.75 D_c; 1 and 1
    MPa, then 2 and 4), test b 2 and 5 MPa and stops before 2 D_c; a row at 2 D_c falls in no bin
    of --to 2: the bins' means 1.5 +- 0.5 and 4.0 +- 1.0 MPa over the two tests. --csv writes each
    test's bins under its case, the study's folder above penetration/ (a_s1, b_s1)."""
    del liggghts
    paths = []
    for name, rows in (("a", ((0.25, 1), (0.75, 1), (1.25, 2), (1.75, 4), (2.0, 99))), ("b", ((0.5, 2), (1.5, 5)))):
        folder = os.path.join(work, "%s_s1" % name, "penetration")
        os.makedirs(folder, exist_ok=True)
        path = os.path.join(folder, "penetration_%s_N34.csv" % name)
        with open(path, "w") as f:
            f.write("step,depth_Dc,q_c\n" + "".join("%d,%g,%g\n" % (k, d, q * 1e6) for k, (d, q) in enumerate(rows)))
        paths.append(path)
    table = os.path.join(work, "depth.csv")
    if os.path.exists(table):  # --csv appends: a rerun in the same folder starts a new table
        os.remove(table)
    out = subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "post", "penetration_depth.py")] + paths + ["--to", "2", "--csv", table],
                         stdout=subprocess.PIPE, universal_newlines=True, check=True).stdout.splitlines()
    check(out == ["0 - 1 D_c: 2 tests, q_c 1.500 +- 0.500 MPa", "1 - 2 D_c: 2 tests, q_c 4.000 +- 1.000 MPa"],
          "bins: %s" % out)
    with open(table) as f:
        rows = f.read().splitlines()
    check(rows == ["case,from_Dc,to_Dc,q_c_MPa", "a_s1,0,1,1", "a_s1,1,2,3", "b_s1,0,1,2", "b_s1,1,2,5"], "the bins' rows: %s" % rows)


def case_stats_ratio_power(liggghts, work):
    """--ratio and --fit-power on stand-in studies of known values. Dense (2.0, 2.2, 2.4) over loose
    (1.0, 1.2, 1.4) on the same seeds: the ratio of the means 2.2 / 1.2 = 1.833, its standard error
    1.833 ((0.1155 / 1.2)^2 + (0.1155 / 2.2)^2)^0.5 = 0.201; each seed's own ratio (2, 1.833, 1.714)
    1.849 +- 0.083; from 1, the 95% intervals +0.275 .. +1.39 (Welch's df 4) and +0.493 .. +1.21 (df 2):
    both resolved. q_c = a_seed sigma_v^0.6 2^e at 100, 200, 400 kPa, e = (+0.1,
    -0.2, +0.1) in each seed (orthogonal to the intercepts and to log2 sigma_v): the exponent 0.600 +-
    0.077, as --fit-log2's slope on the same ladder (df 9 - 3 - 1 = 5: 0.401 .. 0.799); between neighbouring levels 0.6 - 0.3 = 0.300 and
    0.6 + 0.3 = 0.900 in every seed, a change of +0.600 +- 0.000, resolved."""
    del liggghts
    rows = [("loose_s%d" % (k + 1), seed, q, {"density": "loose"}) for k, (seed, q) in enumerate(zip(SEEDS, (1.0, 1.2, 1.4)))]
    rows += [("dense_s%d" % (k + 1), seed, q, {}) for k, (seed, q) in enumerate(zip(SEEDS, (2.0, 2.2, 2.4)))]
    e = {"1e5": 0.1, "2e5": -0.2, "4e5": 0.1}
    rows += [("p%s_s%d" % (p, k + 1), seed, a * (float(p) / 1e5) ** 0.6 * 2 ** e[p], {"sigma_v": p, "crushing": "0"})
             for k, (seed, a) in enumerate(zip(SEEDS, (1.0, 2.0, 3.0))) for p in e]
    study = write_study(os.path.join(work, "ratio.csv"), rows)
    _, _, rest, _ = run_stats(study, "--ratio", "loose_*", "dense_*", "--fit-power", "sigma_v")
    text = "\n".join(rest)
    check("ratio of the means 1.833 +- 0.201 (unpaired, 3 and 3 seeds), from 1: 95% interval +0.275 .. +1.39, p 0.014, "
          "resolved: yes" in text
          and "paired by seed: 1.849 +- 0.083 (3 seeds), from 1: 95% interval +0.493 .. +1.21, p 0.0094, resolved: yes" in text,
          "dense over loose: 1.833 +- 0.201 unpaired, 1.849 +- 0.083 paired")
    powers = re.findall(r"sigma_v = 1e5, 2e5, 4e5: exponent (\S+) \+- (\S+), 95% interval (\S+) \.\. (\S+) "
                        r"\((\d+) runs, (\d+) seeds\)", text)
    check(powers == [("0.600", "0.077", "0.401", "0.799", "9", "3")],
          "q_c against sigma_v: exponent, se, interval, runs, seeds %s" % powers)
    local = re.findall(r"(\S+) -> (\S+): exponent (\S+) \+- (\S+) \((\d+) seeds\)", text)
    change = re.findall(r"change from the step to 2e5 to the next: (\S+) \+- (\S+) \(paired, 3 seeds\), .*resolved: (\w+)",
                        text)
    check(local == [("1e5", "2e5", "0.300", "0.000", "3"), ("2e5", "4e5", "0.900", "0.000", "3")]
          and change == [("+0.600", "0.000", "yes")],
          "local exponents %s, their change %s" % (local, change))


def case_cpt_interpretation(liggghts, work):
    """post/cpt_interpretation.py on stand-in tests of q_c 10 MPa and f_s 50 kPa. At sigma_v = p_a =
    100 kPa Q_tn is free of n: Q_tn = 99, F_r = 50 / 9900 = 0.505 %, I_c = ((3.47 - log 99)^2 + (log
    0.505 + 1.22)^2)^0.5 = 1.740 (zone 6, clean sand to silty sand), n = 0.381 I_c - 0.1 = 0.563,
    D_r = ln(10000 / (157 100^0.55)) / 2.41 = 0.673 (Baldi) and ln(100 / 24.94) / 2.96 = 0.469
    (Jamiolkowski, K = 1). At 400 kPa n is the fixed point n = 0.381 I_c + 0.05 x 4 - 0.15 with I_c of
    Q_tn = 96 / 4^n (0.902, Q_tn 27.49, I_c 2.236: zone 5); D_r 0.356 and 0.254. Two seeds of q_c 9
    and 11 MPa give the mean of their own values, not the values of the mean q_c."""
    del liggghts
    rows = [("a_s1", SEEDS[0], 10.0, {"sigma_v": "1e5", "f_s_kPa": "50"}),
            ("b_s1", SEEDS[0], 10.0, {"sigma_v": "4e5", "f_s_kPa": "50"}),
            ("c_s1", SEEDS[0], 9.0, {"sigma_v": "1e5", "f_s_kPa": "50", "density": "loose"}),
            ("c_s2", SEEDS[1], 11.0, {"sigma_v": "1e5", "f_s_kPa": "50", "density": "loose"}),
            ("d_s1", SEEDS[0], 10.0, {"sigma_v": "1e5", "f_s_kPa": "50", "sigma_v_axis": "8e4", "N": "34"})]
    study = write_study(os.path.join(work, "cpt.csv"), rows)
    out = os.path.join(work, "cpt_out.csv")
    proc = subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "post", "cpt_interpretation.py"), study, "--csv", out],
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True)
    check(proc.returncode == 0, "post/cpt_interpretation.py ran: %s" % proc.stderr[-300:])
    with open(out) as f:
        table = dict((row["cases"], row) for row in csv.DictReader(f))
    expected = {"a_s1": (99.0, 0.50505, 1.73963, 0.56280, 0.67272, 0.46915, 6),
                "b_s1": (27.4891, 0.52083, 2.23645, 0.90209, 0.35634, 0.25372, 5)}
    names = ("Q_tn", "F_r", "I_c", "n", "D_r_Baldi", "D_r_Jamiolkowski")
    for case, values in expected.items():
        got = [float(table[case][m]) for m in names] + [int(table[case]["zone"])]
        check(all(abs(g - v) < 1e-4 * max(1.0, abs(v)) for g, v in zip(got[:-1], values[:-1])) and got[-1] == values[-1],
              "%s: Q_tn, F_r, I_c, n, D_r (Baldi, Jamiolkowski), zone %s against %s" % (case, got, values))
    q_tn = [(q - 100.0) / 100.0 for q in (9000.0, 11000.0)]
    f_r = [100 * 50.0 / (q - 100.0) for q in (9000.0, 11000.0)]
    i_c = [math.hypot(3.47 - math.log10(q), math.log10(f) + 1.22) for q, f in zip(q_tn, f_r)]
    pair = table["c_s1;c_s2"]
    check(abs(float(pair["Q_tn"]) - 99.0) < 1e-9 and abs(float(pair["I_c"]) - sum(i_c) / 2) < 1e-5
          and abs(float(pair["Q_tn_se"]) - 10.0) < 1e-9,
          "two seeds: Q_tn %s +- %s (99 +- 10), I_c %s the mean of theirs (%.6f)"
          % (pair["Q_tn"], pair["Q_tn_se"], pair["I_c"], sum(i_c) / 2))

    # normalised by the stress the cone meets (sigma_v_axis 80 kPa, the top wall's 100): the fixed point
    # of n = 0.381 I_c + 0.05 (80 / 100) - 0.15 with Q_tn = ((10000 - 80) / 100) (100 / 80)^n
    n_fix = 0.5
    for _ in range(200):
        q_fix = (10000.0 - 80.0) / 100.0 * (100.0 / 80.0) ** n_fix
        i_fix = math.hypot(3.47 - math.log10(q_fix), math.log10(100.0 * 50.0 / (10000.0 - 80.0)) + 1.22)
        n_fix = min(1.0, 0.381 * i_fix + 0.05 * 0.8 - 0.15)
    measured = table["d_s1"]
    check(abs(float(measured["Q_tn"]) - q_fix) < 1e-3 * q_fix and abs(float(measured["I_c"]) - i_fix) < 1e-4,
          "normalised by sigma_v_axis (80 kPa): Q_tn %s, I_c %s (expected %.4f, %.5f)" % (measured["Q_tn"], measured["I_c"], q_fix, i_fix))
    nominal = [line for line in proc.stderr.splitlines() if "nominal" in line]
    check(len(nominal) == 1 and "a_s1" in nominal[0] and "d_s1" not in nominal[0],
          "the rows without sigma_v_axis are named as normalised by the nominal stress: %s" % nominal)

if __name__ == "__main__":
    test_main(globals(), sys.argv[1:])
