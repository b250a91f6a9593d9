#!/usr/bin/env python3
"""Degenerate input: decks with zero, negative, huge and non-finite sizes, densities, moduli and
strengths, coincident, overlapping and stray particles, missing materials, malformed data and
restart files, and keywords at the edges of their ranges. On 1 and 2 ranks each deck must either
run cleanly or end with an ERROR line, in the redirected output and in log.liggghts; none may end
with a signal (a crash) or an uncaught exception.

  python3 test_fuzz.py LIGGGHTS WORKDIR all RANKS      (every deck; one test per rank count)
  python3 test_fuzz.py LIGGGHTS WORKDIR one RANKS NAME (one deck, to look at it)

Each deck is BASE with one edit: eight grains in a box of six servo walls, under fix crush, fix
damp/local and fix dt/stiffness, 300 steps."""
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liggghts_run import check, deck_command, each_rank_count, variants  # noqa: E402
from liggghts_run import main as test_main  # noqa: E402

MATERIALS = """fix             m1 all property/global youngsModulus peratomtype 7.8e9 7.8e9
fix             m2 all property/global poissonsRatio peratomtype 0.3 0.3
fix             m3 all property/global coefficientRestitution peratomtypepair 2 0.9 0.9 0.9 0.9
fix             m4 all property/global coefficientFriction peratomtypepair 2 0.3 0.3 0.3 0.3
"""
BASE = """atom_style      granular
atom_modify     map array
boundary        f f f
newton          off
communicate     single vel yes
units           si
hard_particles  yes
region          box block 0 0.004 0 0.004 0 0.004 units box
create_box      2 box
neighbor        0.0001 bin
neigh_modify    delay 0
MATERIALS
ATOMS
set             group all diameter 0.00155 density 2650
pair_style      gran model hertz/scaled tangential mindlin/scaled
pair_coeff      * *
timestep        1e-8
fix             walls all wall/servo 0 0.004 0 0.004 0 0.004 type 2 x fixed y fixed z ramp ramp 1e5 1e7 0.1
fix             integr all nve/sphere
fix             dtfix all dt/stiffness fraction 0.5
fix             crush all crush sigma_lim0 5e8 cv 1 weibull_m 10 d0 2e-3 seed 32452843 dmin 1e-4 log events.csv
fix             damp all damp/local alpha 0.05
compute         gsd all crush/gsd crush sieves 0.1e-3 0.5e-3 1e-3
thermo_style    custom step atoms f_crush[1] c_gsd[1] f_walls[9]
thermo_modify   lost error
thermo          100
run             300
"""

# eight grains 1.5 mm apart, 1.55 mm across: they touch and push
LATTICE = "\n".join("create_atoms    1 single %g %g %g units box" % (x, y, z)
                    for x in (0.00125, 0.00275) for y in (0.00125, 0.00275) for z in (0.00125, 0.00275))
DATA = """LIGGGHTS data file

2 atoms
2 atom types

0 0.004 xlo xhi
0 0.004 ylo yhi
0 0.004 zlo zhi

Atoms

1 1 0.00155 2650 0.00125 0.002 0.002
2 1 0.00155 2650 0.00275 0.002 0.002
"""
READ_DATA = "read_data       grains.data"


def deck(*edits, atoms=LATTICE):
    text = BASE.replace("MATERIALS\n", MATERIALS).replace("ATOMS", atoms)
    for old, new in edits:
        if old not in text:
            raise AssertionError("fuzz setup: '%s' not in the base deck" % old)
        text = text.replace(old, new)
    return text


def material(which, value):
    names = {"E": ("youngsModulus peratomtype 7.8e9 7.8e9", "youngsModulus peratomtype %s %s"),
             "nu": ("poissonsRatio peratomtype 0.3 0.3", "poissonsRatio peratomtype %s %s"),
             "mu": ("coefficientFriction peratomtypepair 2 0.3 0.3 0.3 0.3",
                    "coefficientFriction peratomtypepair 2 %s %s %s %s")}
    old, new = names[which]
    return (old, new % ((value,) * new.count("%s")))


def crush(keyword, value):
    line = "fix             crush all crush sigma_lim0 5e8 cv 1 weibull_m 10 d0 2e-3 seed 32452843 dmin 1e-4 log events.csv"
    words = line.split()
    if keyword in words:
        words[words.index(keyword) + 1] = value
    else:
        words += [keyword, value]
    return (line, " ".join(words[:1]).ljust(16) + " ".join(words[1:]))


def data_deck(data):
    """A deck that reads grains.data (given text) instead of creating its box and grains."""
    text = deck(("region          box block 0 0.004 0 0.004 0 0.004 units box\ncreate_box      2 box\n", READ_DATA + "\n"),
                ("set             group all diameter 0.00155 density 2650\n", ""), atoms="")
    return text, {"grains.data": data}


RESTART_DECK = """atom_style      granular
atom_modify     map array
read_restart    grains.restart
newton          off
hard_particles  yes
communicate     single vel yes
neighbor        0.0001 bin
neigh_modify    delay 0
MATERIALS
pair_coeff      * *
fix             integr all nve/sphere
run             10
""".replace("MATERIALS\n", MATERIALS)


def restart_deck(content):
    """A deck that reads a restart file of the given bytes (None: a complete one of the base deck; a
    number: that percentage of it)."""
    return RESTART_DECK, content


def replacing(old, **cases):
    """One deck per case: BASE with `old` replaced by the case's text."""
    return [(name, deck((old, new))) for name, new in cases.items()]


SIZES = replacing("diameter 0.00155", diameter_zero="diameter 0", diameter_negative="diameter -1e-3",
                  diameter_huge="diameter 1e3", diameter_nan="diameter nan", diameter_inf="diameter inf") + \
    replacing("density 2650", density_zero="density 0", density_negative="density -2650", density_nan="density nan",
              density_huge="density 1e300") + [
         ("density_zero_outside_group", deck(("set             group all diameter 0.00155 density 2650",
                                              "set             group all diameter 0.00155 density 2650\n"
                                              "set             atom 8 density 0\ngroup           grains id 1:7"),
                                             ("crush all crush", "crush grains crush"),
                                             ("fix             dtfix all dt/stiffness fraction 0.5\n", "")))]
MODULI = [("youngs_zero", deck(material("E", "0"))),
          ("youngs_negative", deck(material("E", "-7.8e9"))),
          ("youngs_nan", deck(material("E", "nan"))),
          ("youngs_huge", deck(material("E", "1e300"))),
          ("poisson_half", deck(material("nu", "0.5"))),
          ("poisson_minus_one", deck(material("nu", "-1"))),
          ("friction_negative", deck(material("mu", "-0.3"))),
          ("friction_huge", deck(material("mu", "1e300")))]
STRENGTHS = [("strength_zero", deck(crush("sigma_lim0", "0"))),
             ("strength_negative", deck(crush("sigma_lim0", "-5e8"))),
             ("strength_nan", deck(crush("sigma_lim0", "nan"))),
             ("strength_inf", deck(crush("sigma_lim0", "inf"))),
             ("strength_tiny", deck(crush("sigma_lim0", "1e-300"))),
             ("strength_low_edge", deck(crush("sigma_lim0", "1e3"))),
             ("strength_high_edge", deck(crush("sigma_lim0", "1e30"))),
             ("weibull_tiny", deck(crush("weibull_m", "1e-300"))),
             ("weibull_low_edge", deck(crush("weibull_m", "0.5"))),
             ("d0_tiny", deck(crush("d0", "1e-300"))),
             ("d0_edge", deck(crush("d0", "10"))),
             ("cv_edge", deck(crush("cv", "10"))),
             ("cv_nan", deck(crush("cv", "nan"))),
             ("scale_edge", deck(crush("scale", "1e4"))),
             ("dmin_edge", deck(crush("dmin", "10"))),
             ("dmin_zero", deck(crush("dmin", "0"))),
             ("fines_edge", deck(crush("fines_dimension", "2.999"))),
             ("fragment_density_scaled", deck(crush("fragment_density", "scaled"))),
             ("fragment_density_word", deck(crush("fragment_density", "yes")))]
GEOMETRY = [("coincident", deck(atoms=LATTICE + "\ncreate_atoms    1 single 0.00125 0.00125 0.00125 units box")),
            ("overlap_deep", deck(atoms=LATTICE + "\ncreate_atoms    1 single 0.00126 0.00125 0.00125 units box")),
            ("outside_box", deck(("set             group all diameter", "set             atom 8 x 0.01\nset             group all diameter"))),
            ("on_box_face", deck(atoms=LATTICE + "\ncreate_atoms    1 single 0.002 0.002 0.0 units box")),
            ("no_atoms", deck(atoms="")),
            ("timestep_huge", deck(("timestep        1e-8", "timestep        1e-3"), ("fix             dtfix all dt/stiffness fraction 0.5\n", ""))),
            ("timestep_nan", deck(("timestep        1e-8", "timestep        nan")))]
MISSING = [("no_youngs", deck(("fix             m1 all property/global youngsModulus peratomtype 7.8e9 7.8e9\n", ""))),
           ("no_poisson", deck(("fix             m2 all property/global poissonsRatio peratomtype 0.3 0.3\n", ""))),
           ("no_friction", deck(("fix             m4 all property/global coefficientFriction peratomtypepair 2 0.3 0.3 0.3 0.3\n", ""))),
           ("no_pair_coeff", deck(("pair_coeff      * *\n", ""))),
           ("one_type_material", deck(("youngsModulus peratomtype 7.8e9 7.8e9", "youngsModulus peratomtype 7.8e9")))]
QUASI_STATIC = replacing("damp/local alpha 0.05", damp_edge="damp/local alpha 0.999", damp_one="damp/local alpha 1") + \
    replacing("z ramp ramp 1e5 1e7 0.1", servo_stress_edge="z stress 1e12", servo_stress_zero="z stress 0",
              servo_velocity_huge="z velocity -1e4") + \
    replacing("ramp 1e5 1e7 0.1", servo_rate_edge="ramp 1e5 1e7 100") + \
    replacing("x fixed y fixed z ramp ramp 1e5 1e7 0.1", servo_mean="x mean 1e6 y mean 1e6 z velocity -0.01",
              servo_mean_all="x mean 1e6 y mean 1e6 z mean 1e6", servo_mean_huge="x mean 1e12 y mean 1e12 z fixed") + \
    replacing("wall/servo 0 0.004", servo_walls_crossed="wall/servo 0.004 0") + \
    replacing("dt/stiffness fraction 0.5", dt_fraction_edge="dt/stiffness fraction 1",
              dt_fraction_zero="dt/stiffness fraction 0", dt_growth_edge="dt/stiffness fraction 0.5 growth 10")
DATA_FILES = [("data_good", data_deck(DATA)),
              ("data_truncated", data_deck(DATA[:DATA.index("2 1 0.00155")])),
              ("data_not_a_number", data_deck(DATA.replace("2 1 0.00155 2650", "2 1 abc 2650"))),
              ("data_zero_diameter", data_deck(DATA.replace("1 1 0.00155", "1 1 0"))),
              ("data_missing_columns", data_deck(DATA.replace("2 1 0.00155 2650 0.00275 0.002 0.002", "2 1 0.00155"))),
              ("data_empty", data_deck(""))]
RESTART_FILES = [("restart_good", restart_deck(None)),
                 ("restart_text", restart_deck(b"this is not a restart file\n")),
                 ("restart_empty", restart_deck(b"")),
                 ("restart_zeros", restart_deck(b"\0" * 4096)),
                 ("restart_random", restart_deck(bytes((i * 2654435761) % 251 for i in range(5000))))] + \
                [("restart_cut_%d" % p, restart_deck(p)) for p in (1, 5, 20, 50, 80, 95, 99)]
# neighbour lists by size class: any bounds give style bin's lists; bad bounds stop at neigh_modify
NEIGHBOR = replacing("neighbor        0.0001 bin\nneigh_modify    delay 0",
                     multi_auto="neighbor 0.0001 multi\nneigh_modify delay 0 size_classes auto",
                     multi_bounds="neighbor 0.0001 multi\nneigh_modify delay 0 size_classes 2 0.0005 0.001",
                     multi_bound_tiny="neighbor 0.0001 multi\nneigh_modify delay 0 size_classes 1 1e-30",
                     size_classes_decreasing="neighbor 0.0001 multi\nneigh_modify delay 0 size_classes 2 0.001 0.0005",
                     size_classes_zero="neighbor 0.0001 multi\nneigh_modify delay 0 size_classes 1 0",
                     size_classes_nan="neighbor 0.0001 multi\nneigh_modify delay 0 size_classes 1 nan",
                     size_classes_too_few="neighbor 0.0001 multi\nneigh_modify delay 0 size_classes 3 1e-4",
                     size_classes_word="neighbor 0.0001 multi\nneigh_modify delay 0 size_classes many")
CASES = SIZES + MODULI + STRENGTHS + GEOMETRY + MISSING + QUASI_STATIC + NEIGHBOR + DATA_FILES + RESTART_FILES
SIGNALS = ("terminate called", "what():", "Segmentation fault", "core dumped", "Signal: ", "Aborted")


def good_restart(liggghts, work):
    """A complete restart file of the base deck, for the cut ones."""
    folder = os.path.join(work, "_restart_source")
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "in.deck"), "w") as f:
        f.write(deck(("run             300", "run             50\nwrite_restart   grains.restart")))
    subprocess.run([liggghts, "-in", "in.deck", "-log", "none"], cwd=folder, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL, check=True)
    with open(os.path.join(folder, "grains.restart"), "rb") as f:
        return f.read()


def run_case(liggghts, work, ranks, name, case, restart_bytes):
    """Runs one deck; returns 'clean' or 'error', or raises naming what went wrong."""
    folder = os.path.join(work, "%s_np%d" % (name, ranks))
    os.makedirs(folder, exist_ok=True)
    text, files = (case, {}) if isinstance(case, str) else case
    if name.startswith("restart_"):
        content = files
        if content is None:
            content = restart_bytes
        elif isinstance(content, int):
            content = restart_bytes[: len(restart_bytes) * content // 100]
        files = {"grains.restart": content}
    with open(os.path.join(folder, "in.deck"), "w") as f:
        f.write(text)
    for fname, content in files.items():
        with open(os.path.join(folder, fname), "wb" if isinstance(content, bytes) else "w") as f:
            f.write(content)
    log = os.path.join(folder, "log.liggghts")
    if os.path.exists(log):
        os.remove(log)
    try:
        proc = subprocess.run(deck_command(liggghts, "in.deck", ranks=ranks), cwd=folder, stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, universal_newlines=True, errors="replace", timeout=120)
    except subprocess.TimeoutExpired:
        raise AssertionError("%s (%d ranks): no end within 120 s" % (name, ranks))
    out = proc.stdout
    crashed = [s for s in SIGNALS if s in out]
    if proc.returncode < 0 or proc.returncode >= 128 or crashed:
        raise AssertionError("%s (%d ranks): ended with a signal or an exception (exit %d, %s):\n%s"
                             % (name, ranks, proc.returncode, crashed, out[-2000:]))
    logged = open(log, errors="replace").read() if os.path.exists(log) else ""
    if proc.returncode == 0 and "ERROR" not in out:
        return "clean"
    if "ERROR" not in out or "ERROR" not in logged or proc.returncode == 0:
        raise AssertionError("%s (%d ranks): exit %d without an ERROR line in the output (%s) and the log (%s):\n%s"
                             % (name, ranks, proc.returncode, "ERROR" in out, "ERROR" in logged, out[-2000:]))
    return "error"


def run_all(liggghts, work, ranks, names):
    restart_bytes = good_restart(liggghts, work)
    outcomes, failures = {}, []
    for name, case in CASES:
        if names and name not in names:
            continue
        try:
            outcomes[name] = run_case(liggghts, work, ranks, name, case, restart_bytes)
        except AssertionError as e:
            failures.append(str(e))
    for name in sorted(outcomes):
        print("%-24s %s" % (name, outcomes[name]))
    check(not failures, "%d decks on %d ranks: each ran cleanly or stopped with an ERROR line%s"
          % (len(outcomes) + len(failures), ranks, "" if not failures else ":\n" + "\n".join(failures)))
    return outcomes


# Decks that must run (the edges of the ranges, the good files) and decks that must stop: an edge
# value refused, or a wrong value accepted, is a test failure too. The others may do either (grains
# on the box's face or nearly coincident fly out of the box, which stops the run by name).
MUST_RUN = {"strength_low_edge", "strength_high_edge", "weibull_low_edge", "d0_edge", "cv_edge", "scale_edge",
            "dmin_edge", "dmin_zero", "fines_edge", "damp_edge", "servo_stress_edge", "servo_rate_edge",
            "dt_fraction_edge", "dt_growth_edge", "data_good", "restart_good", "density_huge", "multi_auto",
            "multi_bounds", "multi_bound_tiny", "fragment_density_scaled"}
MUST_STOP = {"diameter_zero", "diameter_negative", "diameter_nan", "diameter_inf", "density_zero",
             "density_negative", "density_nan", "density_zero_outside_group", "youngs_zero", "youngs_negative", "youngs_nan", "strength_zero",
             "strength_negative", "strength_nan", "strength_inf", "strength_tiny", "weibull_tiny", "d0_tiny",
             "cv_nan", "coincident", "outside_box", "no_atoms", "poisson_minus_one", "youngs_huge", "timestep_huge", "timestep_nan", "no_youngs", "no_poisson",
             "no_friction", "no_pair_coeff", "one_type_material", "damp_one", "servo_stress_zero",
             "servo_walls_crossed", "servo_velocity_huge", "dt_fraction_zero", "data_truncated",
             "data_not_a_number", "data_zero_diameter", "data_missing_columns", "data_empty", "restart_text",
             "restart_empty", "restart_zeros", "restart_random", "size_classes_decreasing", "size_classes_zero",
             "size_classes_nan", "size_classes_too_few", "size_classes_word", "fragment_density_word"} | \
    {"restart_cut_%d" % p for p in (1, 5, 20, 50, 80, 95, 99)}


@variants(*each_rank_count(1, 2), timeout=900)
def case_all(liggghts, work, ranks):
    """Every deck of CASES on this rank count."""
    outcomes = run_all(liggghts, work, int(ranks), None)
    check(len(outcomes) >= 40, "%d degenerate decks" % len(outcomes))
    wrong = sorted(n for n in MUST_RUN if outcomes.get(n) != "clean") + \
        sorted(n for n in MUST_STOP if outcomes.get(n) != "error")
    check(not wrong, "edges run and invalid input stops%s" % ("" if not wrong else ": not so for " + ", ".join(wrong)))


if __name__ == "__main__":
    if sys.argv[3:4] == ["one"]:
        liggghts, work, ranks, name = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2]), int(sys.argv[4]), sys.argv[5]
        os.makedirs(work, exist_ok=True)
        run_all(liggghts, work, ranks, {name})
    else:
        test_main(globals(), sys.argv[1:])
