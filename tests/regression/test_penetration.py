#!/usr/bin/env python3
"""The penetrometer of examples/penetration: the meshes penetrometer.py writes (geometry against the
analytic cone and shaft), and those meshes pushed into a bed of grains by fix move/mesh, feeding fix
crush through fix wall/gran hertz/scaled.

  python3 test_penetration.py LIGGGHTS WORKDIR CASE"""
import math
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liggghts_run import check, each_rank_count, printed, read_thermo, run_deck, variants  # noqa: E402
from liggghts_run import main as test_main  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCRIPT = os.path.join(ROOT, "examples", "penetration", "penetrometer.py")
DECK = os.path.join(os.path.dirname(os.path.abspath(__file__)), "penetration", "in.push")


def write_meshes(folder, diameter, shaft, tip, segments):
    subprocess.run(["/usr/bin/python3", SCRIPT, "--diameter", str(diameter), "--shaft", str(shaft), "--tip", str(tip),
                    "--segments", str(segments), "--out", folder], check=True, stdout=subprocess.DEVNULL)


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


if __name__ == "__main__":
    test_main(globals(), sys.argv[1:])
