"""liggghts-crush's post-processing: the figures, summaries, fits and statistics of its decks.

An importable package (the folder above post/ on sys.path: `from post.seeds import statistics`).
Each tool runs three ways, with the same arguments:
  crush-summary RUN_DIR                 the command installed beside liggghts-crush (setup.sh), bound
                                        to the Python that has numpy, scipy and matplotlib
  python3 -m post.summary RUN_DIR       from the folder above post/
  python3 post/summary.py RUN_DIR       the file itself
TOOLS maps each command to its module; a tool whose Python lacks a module it needs stops with
requires()'s message: this interpreter, the missing module, and the command to use instead."""
import importlib.util
import os
import subprocess
import sys

# command -> module of post/ (cmake/PostTools.cmake installs one command each)
TOOLS = {
    "crush-calibrate": "calibrate",
    "crush-chamber-profiles": "chamber_profiles",
    "crush-cpt": "cpt_interpretation",
    "crush-compression-seeds": "compression_seeds",
    "crush-critical-state": "critical_state",
    "crush-decomposition": "decomposition",
    "crush-penetration": "penetration",
    "crush-penetration-depth": "penetration_depth",
    "crush-penetration-stats": "penetration_stats",
    "crush-pile-stress": "pile_stress",
    "crush-plot": "plot",
    "crush-ring-stress": "ring_stress",
    "crush-seeds": "seeds",
    "crush-summary": "summary",
    "crush-tables": "tables",
}

HERE = os.path.dirname(os.path.abspath(__file__))
# Written by the install (cmake/PostTools.cmake): the Python the installed commands are bound to.
INTERPRETER_FILE = os.path.join(HERE, "interpreter")


def command_of(module):
    """The installed command that runs a module of post/ (None for a module that is not a tool)."""
    return next((c for c, m in TOOLS.items() if m == module), None)


def _bound_interpreter():
    """The Python the installed commands are bound to (None in a source tree, which has no install)."""
    return open(INTERPRETER_FILE).read().strip() if os.path.exists(INTERPRETER_FILE) else None


def _interpreter_with(modules, bound):
    """A Python that imports all of modules: bound (the one the install bound the commands to), else
    /usr/bin/python3 (Debian's python3-numpy, -scipy, -matplotlib); None when neither does."""
    candidates = [bound] if bound else []
    candidates.append("/usr/bin/python3")
    probe = "import " + ", ".join(modules)
    for python in candidates:
        if python and os.access(python, os.X_OK):
            if subprocess.run([python, "-c", probe], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).returncode == 0:
                return python
    return None


def requires(tool, *modules):
    """Stops the tool (a module name of post/) with exit status 1 and a message when this Python
    cannot import one of modules: which interpreter ran it, which module is missing, and which
    command to use instead. Call it before importing them."""
    missing = [m for m in modules if importlib.util.find_spec(m) is None]
    if not missing:
        return
    lines = ["%s: this Python (%s, %d.%d) has no module named '%s'; the tool needs %s (missing here: %s)."
             % (tool, sys.executable, sys.version_info[0], sys.version_info[1], missing[0], ", ".join(modules),
                ", ".join(missing))]
    bound = _bound_interpreter()
    python = _interpreter_with(modules, bound)
    command = command_of(tool)
    if python:
        lines.append("Run it with the Python that has them: %s %s ..." % (python, os.path.join(HERE, tool + ".py")))
        # the installed command runs under the Python it is bound to: named where that one has them
        if command and (bound is None or os.path.realpath(bound) == os.path.realpath(python)):
            lines.append("or with the command setup.sh installs beside liggghts-crush: %s ..." % command)
    else:
        lines.append("No Python here has them: install them into this one (python3 -m pip install %s), "
                     "or on Debian apt-get install %s." % (" ".join(modules), " ".join("python3-" + m for m in modules)))
    sys.stderr.write("\n".join(lines) + "\n")
    raise SystemExit(1)
