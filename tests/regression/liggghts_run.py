"""Helpers for the deck tests: run the built liggghts on a deck and read its outputs (LIGGGHTS' own
log and dump formats). Plain Python 3, no third-party modules."""
import inspect
import os
import re
import shutil
import subprocess


def check(condition, message):
    """A test assertion that prints what it checked."""
    if not condition:
        raise AssertionError(message)
    print("ok: " + message)


def deck_command(liggghts, deck_name, variables=None, ranks=1):
    """The command line of `liggghts -in deck_name -log log.liggghts -var ...`, under mpiexec beyond
    one rank (oversubscribed, and allowed as root: containers, CI)."""
    cmd = [liggghts, "-in", deck_name, "-log", "log.liggghts"]
    for name, value in (variables or {}).items():
        cmd += ["-var", name, str(value)]
    if ranks > 1:
        cmd = ["mpiexec", "-n", str(ranks), "--oversubscribe"] + cmd
        os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
        os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    return cmd


def run_deck(liggghts, deck, workdir, variables=None, ranks=1, expect_fail=False, keep=False):
    """Runs `liggghts -in deck` in workdir (created afresh, or kept with keep=True: to run a deck on
    the outputs of another) with -var name value pairs; returns the screen output. Decks may include
    files from their own folder: they are run from a copy of it."""
    if os.path.isdir(workdir) and not keep:
        shutil.rmtree(workdir)
    shutil.copytree(os.path.dirname(os.path.abspath(deck)), workdir, dirs_exist_ok=True)
    cmd = deck_command(liggghts, os.path.basename(deck), variables, ranks)
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


def edited_deck(deck, folder, replacements, includes=()):
    """Copies the deck's folder to folder (afresh) with each (old, new) text replaced in the deck and
    in the named files it includes, wherever it occurs; returns the copied deck's path. A
    replacement whose text is in none of them is a test error."""
    if os.path.isdir(folder):
        shutil.rmtree(folder)
    shutil.copytree(os.path.dirname(os.path.abspath(deck)), folder)
    paths = [os.path.join(folder, name) for name in [os.path.basename(deck)] + list(includes)]
    texts = {path: open(path).read() for path in paths}
    for old, new in replacements:
        found = [path for path in paths if old in texts[path]]
        if not found:
            raise AssertionError("test setup: '%s' not in %s" % (old.strip(), ", ".join(
                [os.path.basename(deck)] + list(includes))))
        for path in found:
            texts[path] = texts[path].replace(old, new)
    for path, text in texts.items():
        open(path, "w").write(text)
    return paths[0]


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


def read_events(path):
    """fix crush's event log (its 'log' file), one dict an event, the values as text."""
    with open(path) as f:
        header = f.readline().strip().split(",")
        return [dict(zip(header, line.strip().split(","))) for line in f if line.strip()]


FRAGMENTS = 14  # fix crush's fragments a grain (the 'fourteen' layout)


def inheritance_errors(final, events):
    """The burst decks' inheritance check (burst/in.burst_inherit_run): ({fragment tag: mother tag},
    the ids in the final dump whose tagCopy and tagVector are not their mother's (tag, tag, 2 tag,
    -tag), or, for a particle no event made, not its own)."""
    mother = {int(e["fragment_%d" % (f + 1)]): int(e["tag"]) for e in events for f in range(FRAGMENTS)}
    wrong = [r["id"] for r in final
             if [r["f_tag_copy"], r["f_tag_vector[1]"], r["f_tag_vector[2]"], r["f_tag_vector[3]"]]
             != [float(m) for m in (lambda t: (t, t, 2 * t, -t))(mother.get(int(r["id"]), int(r["id"])))]]
    return mother, wrong


SKIPPED = 77  # exit status of a test that cannot run in this build (CTest's SKIP_RETURN_CODE)


def read_balance_moves(path):
    """fix balance's moves, from its out file (doc/fix_balance.txt): one dict a move with its step, the
    imbalance before and after, the planes {axis: cuts} and whether it weighed by work."""
    moves = []
    for line in open(path):
        if line.startswith("#"):
            continue
        head, tail = line.split(": imbalance ", 1)
        numbers = tail.split()
        cuts, axis = {}, None
        for word in tail.replace(",", " ").split():
            if word in ("x", "y", "z"):
                axis = word
                cuts[axis] = []
            elif axis and word != "cuts":
                cuts[axis].append(float(word))
        moves.append({"step": int(head.split()[-1]), "before": float(numbers[0]), "after": float(numbers[2]),
                      "cuts": cuts, "by_work": "largest work" in tail})
    return moves


def skip(reason):
    """Ends a test that this build cannot run (e.g. VTK output without VTK), as skipped."""
    print("SKIPPED: " + reason)
    raise SystemExit(SKIPPED)


def variants(*argument_lists, ranks=1, timeout=300, label="regression"):
    """Marks a case_NAME function of a test script: it is one test per argument list (the values
    after LIGGGHTS and WORKDIR; none: one test without). An argument named ranks gives the MPI ranks
    of that test; ranks= gives them for a case that starts its own multi-rank runs. label 'slow'
    keeps a test out of the default suite."""
    def mark(function):
        function.variants = [tuple(str(a) for a in args) for args in argument_lists] or [()]
        function.ranks, function.timeout, function.label = ranks, timeout, label
        return function
    return mark


def each_rank_count(*counts):
    """Argument lists for variants(): one test per rank count."""
    return [(n,) for n in counts]


def listed_tests(namespace):
    """(name, ranks, timeout, label, case, arguments) of every test of a script's case_ functions."""
    tests = []
    for attr, function in sorted(namespace.items()):
        if not attr.startswith("case_") or not callable(function):
            continue
        case = attr[len("case_"):]
        parameters = list(inspect.signature(function).parameters)[2:]
        for args in getattr(function, "variants", [()]):
            bound = dict(zip(parameters, args))
            ranks = int(bound.get("ranks", getattr(function, "ranks", 1)))
            words = [a for p, a in zip(parameters, args) if p != "ranks"]
            name = "_".join([case] + words + (["np%d" % ranks] if "ranks" in bound and ranks > 1 else []))
            tests.append((name, ranks, getattr(function, "timeout", 300), getattr(function, "label", "regression"),
                          case, args))
    return tests


def main(namespace, argv):
    """The command line of every deck-test script:
         script.py --list                       one test a line: name ranks timeout label case args...
         script.py LIGGGHTS WORKDIR CASE [ARG ...]   run one (CMake registers the listed ones)"""
    if argv[:1] == ["--list"]:
        for name, ranks, timeout, label, case, args in listed_tests(namespace):
            print(" ".join([name, str(ranks), str(timeout), label, case] + list(args)))
        return
    if len(argv) < 3 or "case_" + argv[2] not in namespace:
        cases = sorted(n[len("case_"):] for n in namespace if n.startswith("case_"))
        raise SystemExit("usage: %s LIGGGHTS WORKDIR CASE [ARG ...]  (cases: %s) | --list"
                         % (os.path.basename(namespace.get("__file__", "test")), " ".join(cases)))
    liggghts, work, case = os.path.abspath(argv[0]), os.path.abspath(argv[1]), argv[2]
    os.makedirs(work, exist_ok=True)
    namespace["case_" + case](liggghts, work, *argv[3:])
    print("PASSED " + " ".join([case] + argv[3:]))
