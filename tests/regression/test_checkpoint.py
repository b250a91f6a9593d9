#!/usr/bin/env python3
"""Checkpoints: O-2 killed with SIGKILL and resumed with -var resume 1 ends as the uninterrupted run
(examples/fontainebleau, in.checkpoint; doc/checkpoint.txt), and broken checkpoints are refused by
name.

  python3 test_checkpoint.py LIGGGHTS WORKDIR CASE [RANKS]

The runs load the prepared N = 2 sample (in.prepare once, then reuse 1) to SIGMA_MAX with a
checkpoint every EVERY steps, so that a short run has several."""
import glob
import os
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liggghts_run import check, deck_command, each_rank_count, run_deck, variants  # noqa: E402
from liggghts_run import main as test_main  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DECKS = os.path.join(ROOT, "examples", "fontainebleau")
SIGMA_MAX = 2e6
EVERY = 300
VARIABLES = {"reuse": 1, "sigma_max": SIGMA_MAX, "checkpoint_every": EVERY, "vtk": 0}
OUTPUTS = ("history_O2.csv", "events_O2.csv", "dump_O2_2MPa.liggghts")
SAMPLE_PARTICLES = 1340  # the N = 2 sample from the default seed


def prepare(liggghts, work):
    """A folder with the decks and sample_N2.restart (in.prepare)."""
    folder = os.path.join(work, "sample")
    run_deck(liggghts, os.path.join(DECKS, "in.prepare"), folder)
    return folder


def copy_sample(sample, folder, checkpoints=False):
    """A copy of a run folder, without its checkpoints unless asked for."""
    if os.path.isdir(folder):
        shutil.rmtree(folder)
    shutil.copytree(sample, folder)
    if not checkpoints:
        for name in glob.glob(os.path.join(folder, "ckpt_*")):
            os.remove(name)
    return folder


def run(liggghts, folder, ranks, variables, deck="in.oedometer", expect_fail=False):
    """The deck in folder (which holds the decks); with expect_fail, it must end with an ERROR line
    and no signal."""
    proc = subprocess.run(deck_command(liggghts, deck, variables, ranks), cwd=folder, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, universal_newlines=True, errors="replace")
    if expect_fail:
        check(proc.returncode > 0 and "ERROR" in proc.stdout, "%s stopped with an error (exit %d)" % (deck, proc.returncode))
        return proc.stdout
    if proc.returncode != 0 or "ERROR" in proc.stdout:
        raise AssertionError("liggghts failed in %s (exit %d):\n%s" % (folder, proc.returncode, proc.stdout[-3000:]))
    return proc.stdout


def newest_checkpoint(folder, base="ckpt_O2"):
    """The newest step the marker records (None before the first checkpoint)."""
    try:
        with open(os.path.join(folder, base + ".last")) as f:
            rows = [line.split() for line in f if line.strip() and not line.startswith("#")]
    except FileNotFoundError:
        return None
    return int(rows[-1][0]) if rows else None


def kill_after(liggghts, folder, ranks, variables, step, delay, deck="in.oedometer", base="ckpt_O2"):
    """Starts the deck, SIGKILLs it (the whole process group: mpiexec and its ranks) `delay` seconds
    after the marker `base`.last names the checkpoint of `step` or a later one; returns the step of
    the newest checkpoint then."""
    proc = subprocess.Popen(deck_command(liggghts, deck, variables, ranks), cwd=folder, stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL, start_new_session=True)
    deadline = time.time() + 600
    while time.time() < deadline and proc.poll() is None:
        newest = newest_checkpoint(folder, base)
        if newest is not None and newest >= step:
            time.sleep(delay)
            break
        time.sleep(0.002)
    check(proc.poll() is None, "the run was still going when killed (checkpoint of step %d seen)" % step)
    # every process of the run's session: mpiexec's ranks may sit in process groups of their own
    subprocess.run(["pkill", "-KILL", "-s", str(proc.pid)])
    proc.wait()
    while subprocess.run(["pgrep", "-s", str(proc.pid)], stdout=subprocess.DEVNULL).returncode == 0:
        time.sleep(0.05)
    return newest_checkpoint(folder, base)


def read_rows(path):
    with open(path) as f:
        lines = f.read().splitlines()
    return lines[0], lines[1:]


def marker_variable(folder, base, name):
    """A kept variable of the newest checkpoint, as its marker records it."""
    with open(os.path.join(folder, base + ".last")) as f:
        rows = [line.split() for line in f if line.strip() and not line.startswith("#")]
    return float([w for w in rows[-1] if w.startswith(name + "=")][0].split("=")[1])


def first_step(folder):
    """The ramp's first step, as the checkpoints keep it (variable first_step in the marker)."""
    return int(marker_variable(folder, "ckpt_O2", "first_step"))


def event_steps(folder):
    return [int(row.split(",")[0]) for row in read_rows(os.path.join(folder, "events_O2.csv"))[1]]


def pending_interval(reference):
    """A checkpoint interval that puts a checkpoint on a step whose events are still pending (decided
    at that step, replaced at the next): the offset of an event decided before the reference run's
    first checkpoint. Up to its first checkpoint a run with that interval computes what the
    reference run computed, so the event is decided there too."""
    start = first_step(reference)
    offsets = [s - start for s in event_steps(reference) if 50 <= s - start < EVERY]
    check(len(offsets) > 0, "an event decided between steps 50 and %d of the ramp (%s)" % (EVERY, offsets[:5]))
    return offsets[0]


def resume_and_compare(liggghts, name, folder, reference, newest, variables, outputs=OUTPUTS):
    events_before = event_steps(folder)
    out = run(liggghts, folder, 1, dict(variables, resume=1))
    check("CHECKPOINT resumed from" in out and "at step %d" % newest in out,
          "%s: resumed from the checkpoint of step %d" % (name, newest))
    later = [s for s in events_before if s >= newest]
    print("%s: the killed run had logged %d events at or after step %d" % (name, len(later), newest))
    for output in outputs:
        a = open(os.path.join(reference, output)).read()
        b = open(os.path.join(folder, output)).read()
        check(a == b, "%s: %s identical to the uninterrupted run's (%d lines)" % (name, output, a.count("\n")))
    steps = [int(r.split(",")[0]) for r in read_rows(os.path.join(folder, "history_O2.csv"))[1]]
    check(steps == sorted(set(steps)), "%s: history rows unique and in order" % name)


@variants(timeout=600)
def case_resume_exact(liggghts, work):
    """On one rank, O-2 killed in the middle of a stretch, and killed right after a checkpoint written
    with events pending, each resumed with -var resume 1: the same history, events and particles as
    the uninterrupted run, to the last digit; the rows the killed run wrote after its checkpoint are
    dropped, none is duplicated."""
    sample = prepare(liggghts, work)
    reference = copy_sample(sample, os.path.join(work, "uninterrupted"))
    out = run(liggghts, reference, 1, VARIABLES)
    check(out.count("CHECKPOINT step") >= 4, "the uninterrupted run wrote %d checkpoints" % out.count("CHECKPOINT step"))
    folder = copy_sample(sample, os.path.join(work, "mid_stretch"))
    newest = kill_after(liggghts, folder, 1, VARIABLES, first_step(reference) + 2 * EVERY, 0.1)
    resume_and_compare(liggghts, "mid_stretch", folder, reference, newest, VARIABLES)

    every = pending_interval(reference)
    pending = dict(VARIABLES, checkpoint_every=every)
    reference = copy_sample(sample, os.path.join(work, "uninterrupted_pending"))
    run(liggghts, reference, 1, pending)
    step = first_step(reference) + every
    check(step in set(event_steps(reference)), "events decided at step %d, the first checkpoint's (every %d)" % (step, every))
    # the kill must land before the next checkpoint, 'every' steps later: a busy machine may let the
    # run pass it, then the attempt is made again
    for attempt in range(5):
        folder = copy_sample(sample, os.path.join(work, "pending"))
        newest = kill_after(liggghts, folder, 1, pending, step, 0.0)
        if newest == step:
            break
        print("attempt %d: the run had passed the next checkpoint (%d) when killed" % (attempt + 1, newest))
    check(newest == step, "killed with the checkpoint of step %d, events pending, the newest" % step)
    resume_and_compare(liggghts, "pending", folder, reference, newest, pending)


@variants(timeout=1800, label="slow")
def case_resume_full(liggghts, work):
    """The decks as a user runs them: `liggghts -in in.oedometer` (O-2 to 100 MPa, the sample
    prepared in the run, a checkpoint every 20000 steps), killed a few seconds after its first
    checkpoint and resumed with -var resume 1 in the same folder: the history, the events and the
    particles and grading at 100 MPa are those of the uninterrupted run, to the last digit."""
    variables = {"vtk": 0}
    outputs = ("history_O2.csv", "events_O2.csv", "dump_O2_100MPa.liggghts", "gsd_O2_100MPa.csv")
    reference = copy_sample(DECKS, os.path.join(work, "uninterrupted"))
    start = time.time()
    out = run(liggghts, reference, 1, variables)
    check("CHECKPOINT step" in out, "the uninterrupted run wrote checkpoints (%.0f s)" % (time.time() - start))
    folder = copy_sample(DECKS, os.path.join(work, "killed"))
    step = first_step(reference) + 20000
    newest = kill_after(liggghts, folder, 1, variables, step, 3.0)
    resume_and_compare(liggghts, "full", folder, reference, newest, variables, outputs)


@variants(timeout=600)
def case_resume_triaxial(liggghts, work):
    """The triaxial deck, killed after its first checkpoint and resumed: the same history as the
    uninterrupted run to the last digit (its strain reference H0, V0 kept by the checkpoint)."""
    sample = prepare(liggghts, work)
    variables = {"reuse": 1, "axial_max": 0.004, "checkpoint_every": 5000}
    history = "history_Tdense2.csv"

    def triaxial(folder, extra=None):
        return run(liggghts, folder, 1, dict(variables, **(extra or {})), deck="in.triaxial")

    reference = copy_sample(sample, os.path.join(work, "uninterrupted"))
    triaxial(reference)
    folder = copy_sample(sample, os.path.join(work, "killed"))
    newest = kill_after(liggghts, folder, 1, variables, 0, 0.1, deck="in.triaxial", base="ckpt_Tdense2")
    check(newest is not None, "killed after the first checkpoint (step %s)" % newest)
    out = triaxial(folder, {"resume": 1})
    check("CHECKPOINT resumed from" in out, "resumed from a checkpoint")
    a, b = open(os.path.join(reference, history)).read(), open(os.path.join(folder, history)).read()
    check(a == b and a.count("\n") > 3, "%s identical to the uninterrupted run's (%d lines)" % (history, a.count("\n")))


def kill_and_resume_triaxial(liggghts, sample, work, reference, variables, when, stage, what, outputs):
    """in.triaxial on a copy of the sample, killed `when` = (step, delay) after a checkpoint of
    `stage` and resumed: the outputs identical to the uninterrupted run's in `reference`."""
    folder = copy_sample(sample, os.path.join(work, "killed"))
    newest = kill_after(liggghts, folder, 1, variables, when[0], when[1], deck="in.triaxial", base="ckpt_Tdense2")
    check(newest is not None and marker_variable(folder, "ckpt_Tdense2", "stage") == stage,
          "killed after a checkpoint of %s (step %s)" % (what, newest))
    out = run(liggghts, folder, 1, dict(variables, resume=1), deck="in.triaxial")
    check("CHECKPOINT resumed from" in out, "resumed from a checkpoint")
    for name in outputs:
        a, b = open(os.path.join(reference, name)).read(), open(os.path.join(folder, name)).read()
        check(a == b and a.count("\n") > 3, "%s identical to the uninterrupted run's (%d lines)" % (name, a.count("\n")))
    return folder


@variants(timeout=600)
def case_resume_triaxial_compression(liggghts, work):
    """in.triaxial with crushing, killed during its isotropic compression (stage 0) and resumed: the
    same history, events and gradings as the uninterrupted run to the last digit, through the rest
    of the compression, the switch to shearing and the shearing."""
    sample = prepare(liggghts, work)
    variables = {"reuse": 1, "crushing": 1, "cell": 1e6, "settle": 2000, "axial_max": 0.003,
                 "checkpoint_every": 1000, "vtk": 0}
    outputs = ("history_Tdense2.csv", "events_Tdense2.csv", "gsd_Tdense2_1MPa.csv", "gsd_Tdense2_sheared.csv")
    reference = copy_sample(sample, os.path.join(work, "uninterrupted"))
    run(liggghts, reference, 1, variables, deck="in.triaxial")
    folder = kill_and_resume_triaxial(liggghts, sample, work, reference, variables, (0, 0.05), 0,
                                      "the isotropic compression", outputs)
    rows = open(os.path.join(folder, outputs[0])).read().splitlines()
    stages = [row.rsplit(",", 1)[1] for row in rows[1:]]
    check("0" in stages and "1" in stages, "the history holds both stages (%d rows of compression, %d of "
          "shearing)" % (stages.count("0"), stages.count("1")))


@variants(timeout=600)
def case_resume_triaxial_precrush(liggghts, work):
    """in.triaxial with a pre-crushed sample (precrush 2 MPa, cell 0.5 MPa): compressed to 2 MPa
    (stage 0), unloaded by halving stresses, 1 MPa held 4000 steps, then 0.5 MPa held 8000 (stage 2),
    then sheared (stage 1). The stages come in that order, each unloading level's last row holds its
    stress within 3% (the servo overshoots each halving, then settles), and a run killed
    during the unloading and resumed gives the uninterrupted run's history, events and gradings to
    the last digit."""
    sample = prepare(liggghts, work)
    variables = {"reuse": 1, "crushing": 1, "precrush": 2e6, "cell": 5e5, "settle": 8000, "unload_steps": 4000,
                 "axial_max": 0.002, "checkpoint_every": 1000, "vtk": 0}
    outputs = ("history_Tdense2.csv", "events_Tdense2.csv", "gsd_Tdense2_2MPa.csv", "gsd_Tdense2_0.5MPa_unloaded.csv",
               "gsd_Tdense2_sheared.csv")
    reference = copy_sample(sample, os.path.join(work, "uninterrupted"))
    run(liggghts, reference, 1, variables, deck="in.triaxial")
    header, rows = read_rows(os.path.join(reference, outputs[0]))
    col = dict((name, k) for k, name in enumerate(header.split(",")))
    table = [[float(x) for x in row.split(",")] for row in rows]
    stages = [int(r[col["stage"]]) for r in table]
    order = [s for k, s in enumerate(stages) if k == 0 or s != stages[k - 1]]
    check(order == [0, 2, 1], "stages in the order 0, 2, 1 (%s)" % order)
    unloading = [r for r in table if r[col["stage"]] == 2]
    # rows every 1000 steps: the first level's four rows come first, the cell's eight last
    held = [unloading[3][col["p"]], unloading[-1][col["p"]]]
    check(len(unloading) == 12, "12 rows of unloading (%d)" % len(unloading))
    check(abs(held[0] / 1e6 - 1) < 0.03 and abs(held[1] / 5e5 - 1) < 0.03,
          "the unloading holds 1 MPa, then 0.5 MPa (p %.4g, %.4g Pa)" % tuple(held))
    kill_and_resume_triaxial(liggghts, sample, work, reference, variables, (int(unloading[2][0]), 0.01), 2,
                             "the unloading", outputs)


@variants(*each_rank_count(2), timeout=600)
def case_resume_mpi(liggghts, work, ranks):
    """On 2 ranks, killed in the middle of a stretch and resumed: the books hold at every history row
    (particles = initial + 13 x events), the events are those of an uninterrupted run within the
    spread of rank counts (5% + 1), every tag is unique and no history row is missing or doubled."""
    ranks = int(ranks)
    sample = prepare(liggghts, work)
    reference = copy_sample(sample, os.path.join(work, "uninterrupted"))
    run(liggghts, reference, ranks, VARIABLES)
    folder = copy_sample(sample, os.path.join(work, "killed"))
    newest = kill_after(liggghts, folder, ranks, VARIABLES, first_step(reference) + 2 * EVERY, 0.1)
    out = run(liggghts, folder, ranks, dict(VARIABLES, resume=1))
    check("at step %d" % newest in out, "resumed from the checkpoint of step %d" % newest)
    header, rows = read_rows(os.path.join(folder, "history_O2.csv"))
    names = header.split(",")
    table = [dict(zip(names, map(float, r.split(",")))) for r in rows]
    initial = SAMPLE_PARTICLES
    check(all(r["particles"] == initial + 13 * r["events"] for r in table),
          "particles = %d + 13 x events at all %d rows" % (initial, len(table)))
    steps = [int(r["step"]) for r in table]
    ref_steps = [int(r.split(",")[0]) for r in read_rows(os.path.join(reference, "history_O2.csv"))[1]]
    check(steps == ref_steps, "the same %d history rows (steps) as the uninterrupted run" % len(steps))
    events, ref_events = len(event_steps(folder)), len(event_steps(reference))
    check(abs(events - ref_events) <= 0.05 * ref_events + 1, "%d events against %d uninterrupted" % (events, ref_events))
    tags = [line.split()[0] for line in open(os.path.join(folder, "dump_O2_2MPa.liggghts")).read().split(
        "ITEM: ATOMS")[1].splitlines()[1:] if line.strip()]
    check(len(tags) == len(set(tags)) == initial + 13 * events,
          "%d particles at the end, every tag unique, as the %d events of the log make" % (len(tags), events))


def case_broken_checkpoints(liggghts, work):
    """A cut newest checkpoint: the resume falls back to the one before, with a warning. Both cut: an
    error naming the files. A fix crush section of an unknown version: refused by name. A marker that
    is not one: an error naming it."""
    sample = prepare(liggghts, work)
    folder = copy_sample(sample, os.path.join(work, "run"))
    run(liggghts, folder, 1, dict(VARIABLES, sigma_max=7e5))
    marker = os.path.join(folder, "ckpt_O2.last")
    rows = [line.split() for line in open(marker) if line.strip() and not line.startswith("#")]
    check(len(rows) == 2, "the marker names the two newest checkpoints")
    (old_step, _, old_file), (new_step, new_size, new_file) = rows[0][:3], rows[1][:3]
    keep = {name: open(os.path.join(folder, name), "rb").read() for name in (old_file, new_file)}
    resume = dict(VARIABLES, sigma_max=7e5, resume=1)

    def cut(target, name, size):
        with open(os.path.join(target, name), "wb") as f:
            f.write(keep[name][:size])

    # the newest cut short: back to the one before
    target = copy_sample(folder, os.path.join(work, "newest_cut"), True)
    cut(target, new_file, int(new_size) // 2)
    out = run(liggghts, target, 1, resume)
    check("is incomplete; resuming from the one before, " + old_file in out and "at step %s" % old_step in out,
          "the cut newest checkpoint is passed over for %s (step %s)" % (old_file, old_step))
    # both cut: no checkpoint to resume from, the deck says so and starts again
    target = copy_sample(folder, os.path.join(work, "both_cut"), True)
    for name in (old_file, new_file):
        cut(target, name, 100)
    out = run(liggghts, target, 1, dict(resume, sigma_max=2e5))
    check("no complete checkpoint ckpt_O2.1.restart or ckpt_O2.2.restart here" in out,
          "with both checkpoints cut the deck starts from the beginning and says why")
    # a cut file read directly: an error naming it
    target = copy_sample(folder, os.path.join(work, "read_cut"), True)
    with open(os.path.join(target, "in.read_cut"), "w") as f:
        f.write("atom_style granular\natom_modify map array\nread_restart %s\n" % new_file)
    cut(target, new_file, int(new_size) * 3 // 4)
    out = run(liggghts, target, 1, {}, deck="in.read_cut", expect_fail=True)
    check("Restart file %s" % new_file in out and "truncated" in out, "a cut restart file is named in the error")
    # fix crush's section of another version
    target = copy_sample(folder, os.path.join(work, "version"), True)
    data = bytearray(keep[new_file])
    at = data.find(b"crush\x00\x00\x00")
    check(at > 0, "the fix crush section starts with its name")
    data[at + 8:at + 12] = (99).to_bytes(4, "little")
    with open(os.path.join(target, new_file), "wb") as f:
        f.write(bytes(data))
    out = run(liggghts, target, 1, resume, expect_fail=True)
    check("fix crush section is version 99; this build reads versions 3 and 4" in out, "an unknown section version is refused by name")
    # a marker that is not one
    target = copy_sample(folder, os.path.join(work, "marker"), True)
    with open(os.path.join(target, "ckpt_O2.last"), "w") as f:
        f.write("this is not a marker\n")
    out = run(liggghts, target, 1, resume, expect_fail=True)
    check("the marker ckpt_O2.last is not a checkpoint marker" in out, "a bad marker is named in the error")


if __name__ == "__main__":
    test_main(globals(), sys.argv[1:])
