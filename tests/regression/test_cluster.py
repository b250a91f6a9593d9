#!/usr/bin/env python3
"""The batch jobs of examples/cluster without a scheduler: o1.slurm run with a stand-in environment
(SLURM_NTASKS=2, mpiexec as srun, a requeue that does nothing), warned with USR1 as Slurm warns
before the wall-time limit, started again as the requeued job: it resumes, and its history and
events are those of an uninterrupted job (O-2 to 2 MPa, a checkpoint every 300 steps).

  python3 test_cluster.py LIGGGHTS WORKDIR CASE"""
import os
import shutil
import signal
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liggghts_run import check, each_rank_count, variants  # noqa: E402
from liggghts_run import main as test_main  # noqa: E402
from test_checkpoint import newest_checkpoint, read_rows  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
JOB = os.path.join(ROOT, "examples", "cluster", "o1.slurm")
EVERY = 300


def job_environment(liggghts, work, run_dir, ranks):
    env = dict(os.environ, CRUSH_ROOT=ROOT, LIGGGHTS=liggghts, LAUNCH="mpiexec -n %d --oversubscribe" % ranks,
               REQUEUE="true", SLURM_NTASKS=str(ranks), SLURM_JOB_ID="4242", SLURM_JOB_NAME="O1",
               SLURM_SUBMIT_DIR=work, RUN_DIR=run_dir, N="2",
               DECK_VARS="-var sigma_max 2e6 -var checkpoint_every %d -var vtk 0" % EVERY)
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    return env


def start(env, wait=True):
    proc = subprocess.Popen(["bash", JOB], env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            universal_newlines=True, start_new_session=True)
    if wait:
        out, _ = proc.communicate(timeout=900)
        return proc.returncode, out
    return proc


def history(folder):
    header, rows = read_rows(os.path.join(folder, "history_O2.csv"))
    names = header.split(",")
    return [dict(zip(names, map(float, r.split(",")))) for r in rows]


@variants(*each_rank_count(1, 2), timeout=900)
def case_slurm_requeue(liggghts, work, ranks):
    """o1.slurm on 1 and 2 ranks (SLURM_NTASKS): uninterrupted, then warned with USR1 after its second
    checkpoint (the job stops the run, calls the requeue, exits 0) and started again: the second
    start says it resumes, LIGGGHTS resumes from the newest checkpoint, the history has the
    uninterrupted job's rows (the same steps, none doubled), the books hold at every row (particles
    = initial + 13 x events), and a third start finds the folder done and runs nothing. On one rank
    the history and the event log are the uninterrupted job's to the last digit; on 2 the events are
    within the spread of summation orders (5% + 1: the sums run in another order after a resume)."""
    ranks = int(ranks)
    for folder in ("whole", "killed"):  # an earlier run's folders would be resumed, or found done
        shutil.rmtree(os.path.join(work, folder), ignore_errors=True)
    whole = os.path.join(work, "whole")
    rc, out = start(job_environment(liggghts, work, whole, ranks))
    folder = os.path.join(whole, "fontainebleau")
    check(rc == 0 and os.path.exists(os.path.join(folder, ".job_done")), "the uninterrupted job ended (%d): %s" % (rc, out[-300:]))
    reference = history(folder)
    first = int(reference[0]["step"])
    killed = os.path.join(work, "killed")
    env = job_environment(liggghts, work, killed, ranks)
    proc = start(env, wait=False)
    kfolder = os.path.join(killed, "fontainebleau")
    deadline = time.time() + 600
    while time.time() < deadline and proc.poll() is None:
        newest = newest_checkpoint(kfolder)
        if newest is not None and newest >= first + 2 * EVERY:
            break
        time.sleep(0.01)
    check(proc.poll() is None, "the job was still running at its second checkpoint")
    os.kill(proc.pid, signal.SIGUSR1)
    out, _ = proc.communicate(timeout=120)
    check(proc.returncode == 0 and "wall-time warning" in out and "requeueing" in out
          and not os.path.exists(os.path.join(kfolder, ".job_done")),
          "warned: the job stopped the run and requeued (exit %d): %s" % (proc.returncode, out.strip().splitlines()[-1]))
    newest = newest_checkpoint(kfolder)
    rc, out = start(env)
    screen = open(os.path.join(kfolder, "screen.txt")).read()
    check(rc == 0 and "resuming" in out and "CHECKPOINT resumed from" in screen and "at step %d" % newest in screen,
          "the requeued job resumed from the checkpoint of step %d (exit %d)" % (newest, rc))
    rows = history(kfolder)
    steps = [int(r["step"]) for r in rows]
    check(steps == [int(r["step"]) for r in reference], "the uninterrupted job's %d history rows, none doubled" % len(steps))
    initial = int(rows[0]["particles"] - 13 * rows[0]["events"])
    check(all(r["particles"] == initial + 13 * r["events"] for r in rows), "particles = %d + 13 x events at every row" % initial)
    events, ref_events = rows[-1]["events"], reference[-1]["events"]
    check(abs(events - ref_events) <= 0.05 * ref_events + 1 and ref_events > 0,
          "%d events against %d uninterrupted" % (events, ref_events))
    if ranks == 1:
        for name in ("history_O2.csv", "events_O2.csv"):
            a, b = (open(os.path.join(f, name)).read() for f in (folder, kfolder))
            check(a == b, "%s identical to the uninterrupted job's (%d lines)" % (name, a.count("\n")))
    rc, out = start(env)
    check(rc == 0 and "done already" in out, "a third start runs nothing: %s" % out.strip())


if __name__ == "__main__":
    test_main(globals(), sys.argv[1:])
