#!/usr/bin/env python3
"""VTK output (dump custom/vtk, patches/0005), read back with VTK's Python module (python3-vtk9).

  python3 test_vtk.py LIGGGHTS WORKDIR CASE [ARG]
  python3 test_vtk.py --list

A build without VTK, or a Python without VTK's module, skips every case but variable.

Cases: dump FORMAT [RANKS] (a known particle set, compressed with crushing, written as .vtu, .pvtu,
.vtp or .vtk: the particle count, the tags, the radii of the data file, the types and fix crush's
strength, generation and F_n/F_lim, f_crush[1..3], by tag), fontainebleau (the .vtu of the Fontainebleau decks'
in.write_gsd against their .liggghts dump), fontainebleau_off (-var vtk 0: no .vtu) and variable
(the predefined liggghts_vtk is 1 where 'liggghts -h' lists dump custom/vtk, 0 where not)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import subprocess  # noqa: E402

from liggghts_run import check, printed, read_dump, run_deck, skip, variants  # noqa: E402
from liggghts_run import main as test_main  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DECKS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "vtk")
FONTAINEBLEAU = os.path.join(ROOT, "examples", "fontainebleau")
SPACING = 0.00021                       # simple cubic lattice of the data file
CELLS = 6                               # 6^3 = 216 spheres
DIAMETERS = (0.0002, 0.00018, 0.00015)  # by tag: DIAMETERS[tag % 3]
ARRAYS = ("id", "type", "radius", "f_crush[1]", "f_crush[2]", "f_crush[3]")  # strength, generation, F_n/F_lim


def has_vtk_dumps(liggghts):
    """Whether the binary lists the dump style custom/vtk ('liggghts -h')."""
    out = subprocess.run([liggghts, "-h"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         universal_newlines=True, errors="replace").stdout
    dumps = out.split("* Dump styles:")[-1].split("* Command styles")[0]
    return "custom/vtk" in dumps.split()


def needs_vtk(liggghts):
    if not has_vtk_dumps(liggghts):
        skip("liggghts built without VTK (libvtk9-dev, LIGGGHTS_CRUSH_VTK)")
    try:
        import vtk  # noqa: F401
    except ImportError:
        skip("no VTK Python module (python3-vtk9)")


def known_diameter(tag):
    return DIAMETERS[tag % 3]


def known_type(tag):
    return 1 + tag % 2


def write_data(path):
    """vtk_particles.data: CELLS^3 spheres on a simple cubic lattice in a periodic box, diameters and
    types by tag; returns the particle count."""
    n = CELLS ** 3
    size = CELLS * SPACING
    lines = ["LIGGGHTS data file: a known particle set for test_vtk.py", "",
             "%d atoms" % n, "2 atom types", "",
             "0 %.17g xlo xhi" % size, "0 %.17g ylo yhi" % size, "0 %.17g zlo zhi" % size, "",
             "Atoms", ""]
    tag = 0
    for i in range(CELLS):
        for j in range(CELLS):
            for k in range(CELLS):
                tag += 1
                lines.append("%d %d %.17g 2650 %.17g %.17g %.17g" % (
                    tag, known_type(tag), known_diameter(tag), (i + 0.5) * SPACING, (j + 0.5) * SPACING,
                    (k + 0.5) * SPACING))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return n


def read_vtk(path):
    """The point data of a VTK file as {name: [values or tuples]}, with 'points' and the class name."""
    import vtk  # python3-vtk9
    from vtk.util.numpy_support import vtk_to_numpy
    readers = {".vtu": vtk.vtkXMLUnstructuredGridReader, ".pvtu": vtk.vtkXMLPUnstructuredGridReader,
               ".vtp": vtk.vtkXMLPolyDataReader, ".vtk": vtk.vtkDataSetReader}
    reader = readers[os.path.splitext(path)[1]]()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    check(data is not None and data.GetNumberOfPoints() > 0, "VTK read %s: %s with %d points"
          % (os.path.basename(path), data.GetClassName(), data.GetNumberOfPoints()))
    point_data = data.GetPointData()
    arrays = {"points": vtk_to_numpy(data.GetPoints().GetData()).tolist(), "class": data.GetClassName(),
              "cells": data.GetNumberOfCells()}
    for i in range(point_data.GetNumberOfArrays()):
        array = point_data.GetArray(i)
        check(array.GetNumberOfComponents() == 1, "array %s has one component" % array.GetName())
        arrays[array.GetName()] = vtk_to_numpy(array).tolist()
    return arrays


def by_tag(arrays):
    """{tag: {name: value}} of read_vtk's arrays, with x y z from the points."""
    rows = {}
    for n, tag in enumerate(arrays["id"]):
        row = {name: arrays[name][n] for name in ARRAYS if name in arrays}
        row["x"], row["y"], row["z"] = arrays["points"][n]
        rows[int(tag)] = row
    return rows


def close(a, b, rel):
    return abs(a - b) <= rel * max(abs(a), abs(b), 1e-300)


@variants(("vtu", 1), ("vtp", 1), ("vtk", 1), ("pvtu", 1), ("vtu", 2), ("pvtu", 2))
def case_dump(liggghts, work, fmt, ranks=1):
    """The known particle set compressed with crushing on RANKS ranks, written as FORMAT: as many
    points (and vertex cells) as particles, each tag once, the data file's radius and type for every
    original grain, fragments smaller, and strength, generation and F_n/F_lim equal to the dump
    custom columns f_crush[1..3] of the same tag (generation 0 for the originals, 1 or more for the
    fragments)."""
    needs_vtk(liggghts)
    ranks = int(ranks)
    os.makedirs(work, exist_ok=True)
    n0 = write_data(os.path.join(work, "vtk_particles.data"))
    name = "particles." + fmt
    out = run_deck(liggghts, os.path.join(DECKS, "in.vtk_dump"), work, {"file": name}, ranks=ranks, keep=True)
    atoms, events = int(printed(out, "ATOMS")), int(printed(out, "EVENTS"))
    check(events > 0 and atoms == n0 + 13 * events, "%d events: %d particles" % (events, atoms))
    if fmt == "pvtu":
        pieces = [f for f in os.listdir(work) if f.startswith("particles_") and f.endswith(".vtu")]
        check(len(pieces) == ranks, "one .vtu piece per rank (%s)" % sorted(pieces))
        check(os.path.isfile(os.path.join(work, "particles_boundingBox.vtr")),
              "the bounding box is a serial .vtr (not .pvtr)")
    arrays = read_vtk(os.path.join(work, name))
    check(all(a in arrays for a in ARRAYS), "point arrays %s present" % ", ".join(ARRAYS))
    check(len(arrays["radius"]) == atoms and arrays["cells"] == atoms,
          "%d points and %d cells = the deck's %d particles" % (len(arrays["radius"]), arrays["cells"], atoms))
    rows = by_tag(arrays)
    check(len(rows) == atoms, "every tag once")
    text = {int(r["id"]): r for r in read_dump(os.path.join(work, "particles.txt"))[-1][2]}
    check(sorted(rows) == sorted(text), "the same tags as the dump custom file")
    originals = [t for t in rows if t <= n0]
    fragments = [t for t in rows if t > n0]
    check(len(originals) == n0 - events and len(fragments) == 14 * events,
          "%d original grains and %d fragments" % (len(originals), len(fragments)))
    check(all(rows[t]["radius"] == known_diameter(t) / 2 for t in originals),
          "the radius of every original grain is the data file's diameter / 2, exactly")
    check(all(int(rows[t]["type"]) == known_type(t) for t in originals), "the type of every original grain")
    check(all(rows[t]["radius"] < max(DIAMETERS) / 2 * 0.42 for t in fragments),
          "fragments are smaller than 0.42 of the largest radius")
    check(all(rows[t]["radius"] == text[t]["radius"] and int(rows[t]["type"]) == int(text[t]["type"]) for t in rows),
          "radius and type of every particle equal the dump custom columns")
    for name in ("f_crush[1]", "f_crush[2]", "f_crush[3]"):
        check(all(rows[t][name] == text[t][name] for t in rows),
              "%s of every particle equals the dump custom column, exactly" % name)
    check(all(rows[t]["f_crush[2]"] == 0 for t in originals) and all(rows[t]["f_crush[2]"] >= 1 for t in fragments),
          "generation (f_crush[2]) 0 for original grains, 1 or more for fragments")
    check(all(rows[t]["f_crush[1]"] > 0 for t in rows), "every strength (f_crush[1]) > 0")
    check(max(rows[t]["f_crush[3]"] for t in rows) > 0, "F_n/F_lim (f_crush[3]) recorded")
    # positions: single precision in LIGGGHTS' VTK points, unwrapped the same way as the text dump
    worst = max(abs(rows[t][k] - text[t][k]) for t in rows for k in "xyz")
    check(worst < 1e-9, "positions equal the dump custom ones to %.1e m (single precision)" % worst)


def fontainebleau(liggghts, work, variables):
    return run_deck(liggghts, os.path.join(FONTAINEBLEAU, "in.oedometer"), work,
                    dict({"sigma_max": 2e5}, **variables))


@variants(timeout=600)
def case_fontainebleau(liggghts, work):
    """O-2 loaded to 0.2 MPa: in.write_gsd writes dump_O2_0MPa.vtu beside dump_O2_0MPa.liggghts, with
    the same particles (tags, radii, types, positions) and fix crush's arrays."""
    needs_vtk(liggghts)
    fontainebleau(liggghts, work, {})
    vtu = os.path.join(work, "dump_O2_0MPa.vtu")
    check(os.path.isfile(vtu), "dump_O2_0MPa.vtu written by default (liggghts_vtk = 1)")
    text = {int(r["id"]): r for r in read_dump(os.path.join(work, "dump_O2_0MPa.liggghts"))[-1][2]}
    arrays = read_vtk(vtu)
    check(all(a in arrays for a in ARRAYS), "point arrays %s present" % ", ".join(ARRAYS))
    rows = by_tag(arrays)
    check(len(arrays["id"]) == len(rows) == len(text) == 1340,
          "%d particles, as in the .liggghts dump (N = 2 sample)" % len(rows))
    check(sorted(rows) == sorted(text), "the same tags")
    # the .liggghts dump is written with LIGGGHTS' default %g: 6 significant digits
    check(all(close(rows[t]["radius"], text[t]["radius"], 1e-5) for t in rows), "radii equal the .liggghts ones")
    check(all(int(rows[t]["type"]) == int(text[t]["type"]) for t in rows), "types equal the .liggghts ones")
    check(all(abs(rows[t][k] - text[t][k]) < 1e-8 for t in rows for k in "xyz"), "positions equal the .liggghts ones")
    check(all(rows[t]["f_crush[2]"] == 0 for t in rows), "before loading: every grain of generation 0")
    check(len(set(rows[t]["f_crush[1]"] for t in rows)) > 1000, "a strength per grain")


@variants(timeout=600)
def case_fontainebleau_off(liggghts, work):
    """-var vtk 0: the same deck writes no VTK file (and the .liggghts dump as before)."""
    needs_vtk(liggghts)
    fontainebleau(liggghts, work, {"vtk": 0})
    check(os.path.isfile(os.path.join(work, "dump_O2_0MPa.liggghts")), "dump_O2_0MPa.liggghts written")
    check(not [f for f in os.listdir(work) if f.endswith((".vtu", ".vtr"))], "no .vtu or .vtr with vtk 0")


def case_variable(liggghts, work):
    """The binary predefines liggghts_vtk: 1 with the VTK dump styles, 0 without."""
    expected = 1 if has_vtk_dumps(liggghts) else 0
    out = run_deck(liggghts, os.path.join(DECKS, "in.vtk_variable"), work)
    value = printed(out, "LIGGGHTS_VTK")
    check(value == float(expected), "liggghts_vtk = %g (expected %s)" % (value, expected))
    styles = run_deck(liggghts, os.path.join(DECKS, "in.vtk_variable"), work, {"liggghts_vtk": 7})
    check(printed(styles, "LIGGGHTS_VTK") == 7, "-var liggghts_vtk 7 takes precedence")


if __name__ == "__main__":
    test_main(globals(), sys.argv[1:])
