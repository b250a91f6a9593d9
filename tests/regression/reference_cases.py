"""The reference-log regression cases: a deck, its variables, the dump to compare, and the tolerance
of each quantity (exact for counts and tags, relative for forces and positions)."""
import os

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

EXACT = 0.0
# Relative tolerances. Counts and tags are exact; continuous quantities of one deterministic serial
# run on one toolchain agree to rounding, the tolerance leaves room for libm differences.
TOLERANCES = {
    "Step": EXACT, "Atoms": EXACT, "id": EXACT, "type": EXACT,
    "crush[1]": EXACT,                               # events
    "f_crush[2]": EXACT,                             # generation
}
DEFAULT_RELATIVE = 1e-8
IGNORED = {"CPU", "Cpu", "cpu", "CPULeft"}  # timings

CASES = {
    "single_grain": {
        "deck": os.path.join(ROOT, "examples", "single_grain", "in.single_grain"),
        "vars": {},
        "dump": "fragments.dump",
    },
    "compression": {
        "deck": os.path.join(HERE, "crush", "in.compression"),
        "vars": {"log": "events.csv", "out": "final.dump"},
        "dump": "final.dump",
    },
    "restart_mid_crushing": {
        "deck": os.path.join(HERE, "crush", "in.restart_first"),
        "vars": {"log": "events.csv", "out": "final.dump"},
        "dump": "final.dump",
    },
    # The second half of restart_mid_crushing from its restart file: the same final particles.
    "restart_continued": {
        "before": os.path.join(HERE, "crush", "in.restart_first"),
        "deck": os.path.join(HERE, "crush", "in.restart_second"),
        "vars": {"log": "events.csv", "out": "final.dump"},
        "dump": "final.dump",
        "reference": "restart_mid_crushing",
        "thermo": False,
    },
    # The truncated draw for every particle (fix crush's own default).
    "fontainebleau_oedometer_short": {
        "deck": os.path.join(ROOT, "examples", "fontainebleau", "in.oedometer"),
        "vars": {"sigma_max": 3e6, "distribution": "normal"},
        "dump": None,
    },
    "fontainebleau_isotropic_short": {
        "deck": os.path.join(ROOT, "examples", "fontainebleau", "in.isotropic"),
        "vars": {"sigma_max": 3e6, "distribution": "normal"},
        "dump": None,
    },
    # The decks' default, Table 3's reading: original grains clipped, fragments truncated.
    "fontainebleau_oedometer_clipped_originals": {
        "deck": os.path.join(ROOT, "examples", "fontainebleau", "in.oedometer"),
        "vars": {"sigma_max": 1e6},
        "dump": None,
    },
    "contact_wall_servo": {
        "deck": os.path.join(HERE, "contact", "in.servo"),
        "vars": {},
        "dump": None,
    },
    "contact_oblique_wall": {
        "deck": os.path.join(HERE, "contact", "in.oblique"),
        "vars": {"out": "oblique.dump"},
        "dump": "oblique.dump",
    },
    "contact_assembly": {
        "deck": os.path.join(HERE, "contact", "in.assembly"),
        "vars": {"model": "hertz/scaled", "tmodel": "mindlin/scaled", "mu": 0.5,
                 "out": "final.dump", "contacts": "contacts.dump"},
        "dump": "final.dump",
    },
}


def tolerance(column):
    return TOLERANCES.get(column, DEFAULT_RELATIVE)


if __name__ == "__main__":
    # The case names, for tests/regression/CMakeLists.txt to register one test each.
    print(" ".join(CASES))
