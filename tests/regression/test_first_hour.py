#!/usr/bin/env python3
"""The errors a new user meets first each come with one line that says what to do (patches/0007,
examples/fontainebleau/in.sample, scripts/mpi_env.sh).

  python3 test_first_hour.py LIGGGHTS WORKDIR CASE
  python3 test_first_hour.py --list

Cases:
  wrong_directory  liggghts -in fontainebleau/in.oedometer from the folder above: the includes are
                   beside the deck, and the error says to run there (cd fontainebleau)
  missing_include  a deck whose include is missing: the error names the file and the folder liggghts
                   looked in
  missing_sample   -var reuse 1 without a sample_N2.restart: the error names the file and the folder,
                   and the line before it the deck that writes it (and -var reuse 0)
  mpirun_root      as root, scripts/mpi_env.sh says in one line which variables Open MPI needs, and
                   mpirun then runs the smoke deck on 2 ranks (not root: nothing to say, nothing to test)
"""
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liggghts_run import check, variants  # noqa: E402
from liggghts_run import main as test_main  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
FONTAINEBLEAU = os.path.join(ROOT, "examples", "fontainebleau")


def failing(cmd, cwd):
    """Runs a command that must stop with an error; returns its output (stdout and stderr) lines."""
    proc = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True, errors="replace")
    check(proc.returncode != 0, "%s stops with exit status %d" % (" ".join(cmd[-3:]), proc.returncode))
    return proc.stdout.splitlines()


def error_line(lines):
    errors = [line for line in lines if line.startswith("ERROR")]
    check(len(errors) == 1, "one ERROR line: %s" % errors)
    return errors[0]


def copy_of_examples(work):
    folder = os.path.join(work, "fontainebleau")
    shutil.rmtree(folder, ignore_errors=True)
    shutil.copytree(FONTAINEBLEAU, folder, ignore=lambda d, names: [n for n in names if not n.startswith("in.")])
    return folder


def case_wrong_directory(liggghts, work):
    copy_of_examples(work)
    line = error_line(failing([liggghts, "-in", "fontainebleau/in.oedometer", "-log", "none"], work))
    check("Cannot open input script in.load_controlled: it is in fontainebleau, the folder of the input "
          "script; run liggghts there (cd fontainebleau)" in line, "the error says where to run: " + line)


def case_missing_include(liggghts, work):
    folder = copy_of_examples(work)
    os.remove(os.path.join(folder, "in.load_controlled"))
    line = error_line(failing([liggghts, "-in", "in.oedometer", "-log", "none"], folder))
    check("Cannot open input script in.load_controlled: no such file in %s" % folder in line,
          "the error names the file and the folder: " + line)


def case_missing_sample(liggghts, work):
    folder = copy_of_examples(work)
    lines = failing([liggghts, "-in", "in.oedometer", "-var", "reuse", "1", "-log", "none"], folder)
    line = error_line(lines)
    check("Cannot open restart file sample_N2.restart: no such file in %s" % folder in line,
          "the error names the restart file and the folder: " + line)
    before = lines[:lines.index(line)]
    check(any("which liggghts -in in.prepare -var N 2 writes here" in b and "-var reuse 0" in b for b in before),
          "the line before it names the deck that writes the sample, and -var reuse 0")


@variants(ranks=2)
def case_mpirun_root(liggghts, work):
    if os.geteuid() != 0:
        print("not root: Open MPI has nothing to refuse")
        return
    env = {k: v for k, v in os.environ.items() if not k.startswith("OMPI_")}
    deck = os.path.join(ROOT, "examples", "smoke", "in.smoke")
    script = 'source "%s" && mpirun -np 2 "%s" -in "%s" -log none' % (
        os.path.join(ROOT, "scripts", "mpi_env.sh"), liggghts, deck)
    proc = subprocess.run(["bash", "-c", script], cwd=work, env=env, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, universal_newlines=True, errors="replace")
    hints = [line for line in proc.stdout.splitlines() if "OMPI_ALLOW_RUN_AS_ROOT=1" in line]
    check(len(hints) == 1 and "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1" in hints[0],
          "one line names both variables: %s" % hints)
    check(proc.returncode == 0 and "SMOKE_DONE atoms=100" in proc.stdout, "mpirun -np 2 then runs as root")


if __name__ == "__main__":
    test_main(globals(), sys.argv[1:])
