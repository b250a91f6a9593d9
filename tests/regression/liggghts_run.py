"""Helpers for the deck tests: run the built liggghts on a deck and read its outputs (LIGGGHTS' own
log and dump formats). Plain Python 3, no third-party modules."""
import os
import re
import shutil
import subprocess


def check(condition, message):
    """A test assertion that prints what it checked."""
    if not condition:
        raise AssertionError(message)
    print("ok: " + message)


def run_deck(liggghts, deck, workdir, variables=None, ranks=1, expect_fail=False, keep=False):
    """Runs `liggghts -in deck` in workdir (created afresh, or kept with keep=True: to run a deck on
    the outputs of another) with -var name value pairs; returns the screen output. Decks may include
    files from their own folder: they are run from a copy of it."""
    if os.path.isdir(workdir) and not keep:
        shutil.rmtree(workdir)
    shutil.copytree(os.path.dirname(os.path.abspath(deck)), workdir, dirs_exist_ok=True)
    cmd = [liggghts, "-in", os.path.basename(deck), "-log", "log.liggghts"]
    for name, value in (variables or {}).items():
        cmd += ["-var", name, str(value)]
    if ranks > 1:
        cmd = ["mpiexec", "-n", str(ranks), "--oversubscribe"] + cmd
        os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
        os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    proc = subprocess.run(cmd, cwd=workdir, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True, errors="replace")
    if expect_fail:
        if proc.returncode == 0 and "ERROR" not in proc.stdout:
            raise AssertionError("expected %s to stop with an error, it ran to the end" % deck)
        return proc.stdout
    if proc.returncode != 0 or "ERROR" in proc.stdout:
        raise AssertionError("liggghts failed on %s (exit %d):\n%s" % (deck, proc.returncode,
                                                                      proc.stdout[-3000:]))
    return proc.stdout


def edited_deck(deck, folder, replacements):
    """Copies the deck's folder to folder (afresh) with each (old, new) text replaced in the deck;
    returns the copied deck's path. A replacement whose text is not in the deck is a test error."""
    if os.path.isdir(folder):
        shutil.rmtree(folder)
    shutil.copytree(os.path.dirname(os.path.abspath(deck)), folder)
    path = os.path.join(folder, os.path.basename(deck))
    text = open(path).read()
    for old, new in replacements:
        if old not in text:
            raise AssertionError("test setup: '%s' not in %s" % (old, deck))
        text = text.replace(old, new)
    open(path, "w").write(text)
    return path


def printed(output, key):
    """The number printed by a deck's `print "KEY value"` line."""
    m = re.search(r"^%s\s+(\S+)\s*$" % re.escape(key), output, re.M)
    if not m:
        raise AssertionError("the run printed no '%s' line" % key)
    return float(m.group(1))


def read_thermo(log):
    """Rows of the thermo output (dicts keyed by the header) from a LIGGGHTS log file."""
    rows, header = [], None
    for line in open(log, errors="replace"):
        words = line.split()
        if words and words[0] == "Step":
            header = words
            continue
        if header and len(words) == len(header):
            try:
                rows.append(dict(zip(header, map(float, words))))
            except ValueError:
                header = None
        elif header and words and not words[0].lstrip("-").isdigit():
            header = None
    return rows


def read_dump(path):
    """Snapshots of a LIGGGHTS 'dump custom' file: a list of (step, columns, rows), rows as dicts."""
    snapshots = []
    with open(path) as f:
        lines = f.read().splitlines()
    k = 0
    while k < len(lines):
        if lines[k].startswith("ITEM: TIMESTEP"):
            step = int(lines[k + 1])
            natoms = int(lines[k + 3])
            columns = lines[k + 8].split()[2:]
            rows = [dict(zip(columns, map(float, lines[k + 9 + n].split()))) for n in range(natoms)]
            snapshots.append((step, columns, rows))
            k += 9 + natoms
        else:
            k += 1
    if not snapshots:
        raise AssertionError("no snapshot in dump %s" % path)
    return snapshots
