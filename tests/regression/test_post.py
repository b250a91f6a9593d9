#!/usr/bin/env python3
"""post/ as a package (post/__init__.py): every tool of TOOLS runs from another folder, as a file and
as a module, and under a Python without the modules it needs it stops with a message that names the
interpreter, the missing module and the command to use instead (no liggghts needed). The installed
commands: test_install.py's prefix case.

  python3 test_post.py LIGGGHTS WORKDIR CASE"""
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liggghts_run import check  # noqa: E402
from liggghts_run import main as test_main  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, ROOT)
from post import TOOLS  # noqa: E402

# The module each tool cannot start without (None: the standard library is enough for --help).
NEEDS = {"calibrate": "numpy", "chamber_profiles": "numpy", "compression_seeds": "numpy", "cpt_interpretation": None, "critical_state": "numpy",
         "decomposition": "numpy", "penetration": "matplotlib", "penetration_depth": None,
         "penetration_stats": None, "pile_stress": "matplotlib", "plot": "matplotlib", "ring_stress": None,
         "seeds": None, "summary": None, "tables": None}


def run(args, cwd, env=None):
    proc = subprocess.run(args, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          universal_newlines=True)
    return proc.returncode, proc.stdout, proc.stderr


def elsewhere(work):
    folder = os.path.join(work, "elsewhere")
    os.makedirs(folder, exist_ok=True)
    return folder


def case_tools_any_folder(liggghts, work):
    """Every tool's --help, from a folder outside the repository: as a file (python3 /.../post/X.py)
    and as a module of the package (python3 -m post.X with the repository on PYTHONPATH)."""
    check(sorted(NEEDS) == sorted(TOOLS.values()), "the test knows every tool of TOOLS (%s)" % sorted(TOOLS.values()))
    cwd = elsewhere(work)
    env = dict(os.environ, PYTHONPATH=ROOT)
    for command, module in sorted(TOOLS.items()):
        rc, out, err = run([sys.executable, os.path.join(ROOT, "post", module + ".py"), "--help"], cwd)
        check(rc == 0 and "usage:" in out, "%s: post/%s.py --help from another folder (%s)" % (command, module, err[-300:]))
        rc, out, err = run([sys.executable, "-m", "post." + module, "--help"], cwd, env)
        check(rc == 0 and "usage:" in out, "%s: python3 -m post.%s --help (%s)" % (command, module, err[-300:]))


def case_missing_module(liggghts, work):
    """Under a Python that cannot import numpy, scipy or matplotlib (this one with -S: no site
    packages), a tool that needs them exits with status 1 and says which interpreter ran it, which
    module is missing, and which command to use: the Python that has them (this one, started
    normally) with the tool's file, and the installed command. The others still run."""
    cwd = elsewhere(work)
    for command, module in sorted(TOOLS.items()):
        tool = os.path.join(ROOT, "post", module + ".py")
        rc, out, err = run([sys.executable, "-S", tool, "--help"], cwd)
        if NEEDS[module] is None:
            check(rc == 0 and "usage:" in out, "%s runs without site packages (%s)" % (module, err[-300:]))
            continue
        check(rc == 1 and "Traceback" not in err, "%s: exit status 1 and no traceback (%d: %s)" % (module, rc, err[-300:]))
        check("this Python (%s, %d.%d)" % (sys.executable, sys.version_info[0], sys.version_info[1]) in err,
              "%s names the interpreter" % module)
        check("no module named '%s'" % NEEDS[module] in err, "%s names the missing module %s" % (module, NEEDS[module]))
        check("Run it with the Python that has them: %s %s" % (sys.executable, tool) in err
              or "Run it with the Python that has them: /usr/bin/python3 %s" % tool in err,
              "%s says which Python to use" % module)
        check(command in err, "%s names the installed command %s" % (module, command))


def case_tables(liggghts, work):
    """post/tables.py: every results table of studies/ is the one its CSVs give (--check on the
    repository's pages: a number typed into a table, or a CSV row added without rewriting the page,
    fails here). On a copy of studies/: a cell edited by hand is found by --check (exit 1, naming the
    table) and put back by a plain run; a CSV row added changes the table (O-2 gains a seed); a page
    without a table's markers is refused by name."""
    import shutil
    del liggghts
    tool = os.path.join(ROOT, "post", "tables.py")
    rc, out, err = run([sys.executable, tool, "--check"], ROOT)
    check(rc == 0 and "up to date" in out, "the studies' tables are written from their CSVs: %s%s" % (out.strip(), err[-300:]))
    root = os.path.join(work, "root")
    shutil.rmtree(root, ignore_errors=True)
    shutil.copytree(os.path.join(ROOT, "studies"), os.path.join(root, "studies"))
    study = os.path.join(root, "studies", "fontainebleau")
    page = os.path.join(study, "README.md")
    text = open(page).read()
    row = next(line for line in text.splitlines() if line.startswith("| O-2 | "))
    open(page, "w").write(text.replace(row, row.replace("| O-2 | ", "| O-2 | 9", 1)))
    rc, out, err = run([sys.executable, tool, "--check", "--root", root], ROOT)
    check(rc == 1 and "table3 in studies/fontainebleau/README.md" in err, "a hand-edited cell is found: %s" % err.strip())
    rc, out, err = run([sys.executable, tool, "--root", root], ROOT)
    check(rc == 0 and open(page).read() == text, "a plain run writes the table back as the CSV gives it")
    with open(os.path.join(study, "table3_runs.csv"), "a") as f:
        f.write("O,2,999,2,1340,5000,280,40.0\n")
    run([sys.executable, tool, "--root", root], ROOT)
    seeds = next(line for line in open(page).read().splitlines() if line.startswith("| O-2 | ")).split("|")[2].strip()
    check(seeds == str(int(row.split("|")[2]) + 1), "a run added to the CSV is a seed more in the table (%s)" % seeds)
    open(page, "w").write(text.replace("<!-- end table table3 -->", ""))
    rc, out, err = run([sys.executable, tool, "--check", "--root", root], ROOT)
    check(rc != 0 and "no markers of table table3" in err, "a page without the markers is refused: %s" % err.strip())


if __name__ == "__main__":
    test_main(globals(), sys.argv[1:])
