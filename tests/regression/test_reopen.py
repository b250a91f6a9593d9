#!/usr/bin/env python3
"""A contact that opens forgets its springs (patches/0011): a sphere slides and rolls against a second
sphere, a plane wall or a mesh plane, is pulled clear, and pushed straight back to the same overlap
(contact/in.reopen). With no tangential or rolling motion since it closed again, the tangential force
and the torque must be zero: |F_t3| <= 1e-6 |F_t1|, |T3| <= 1e-6 |T1|, for every tangential and rolling
model LIGGGHTS compiles; unpatched LIGGGHTS 3.8.0 keeps 0.3-3% of the old tangential spring. The same
with neighbour lists rebuilt every step, and across a migration to another processor on 2 ranks: there
unpatched LIGGGHTS loses the spring too (a neighbour build carries the history of touching pairs only,
neigh_gran.cpp), and these cases check that the patch keeps both paths exact.

  python3 test_reopen.py LIGGGHTS WORKDIR CASE [ARG ...]"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liggghts_run import check, read_dump, run_deck, variants  # noqa: E402
from liggghts_run import main as test_main  # noqa: E402

DECK = os.path.join(os.path.dirname(os.path.abspath(__file__)), "contact", "in.reopen")
BODIES = ("pair", "primitive", "mesh")
# (normal, tangential, rolling): every tangential model with its usual normal law, and every rolling
# model that keeps a spring or acts on the spin
MODELS = [("hertz", "history", "off"), ("hooke", "history", "off"), ("hertz/scaled", "mindlin/scaled", "off"),
          ("hertz", "no_history", "off"), ("hertz", "history", "cdt"), ("hertz", "history", "epsd"),
          ("hertz", "history", "epsd2"), ("hertz", "history", "epsd3"),
          ("hertz/scaled", "mindlin/scaled", "epsd2")]
SPRING_MODELS = ("history", "mindlin/scaled")   # a tangential spring: F_t1 > 0 after the slide


def mover_state(path, body):
    """(tangential force, torque) magnitudes on the moving sphere (atom 1) and the contact normal."""
    rows = {int(r["id"]): r for r in read_dump(path)[-1][2]}
    a = rows[1]
    if body == "pair":
        b = rows[2]
        n = [a[k] - b[k] for k in "xyz"]
        length = math.sqrt(sum(c * c for c in n))
        n = [c / length for c in n]
    else:
        n = [0.0, 0.0, 1.0]
    f = [a["f" + k] for k in "xyz"]
    fn = sum(fc * nc for fc, nc in zip(f, n))
    ft = math.sqrt(sum((fc - fn * nc) ** 2 for fc, nc in zip(f, n)))
    torque = math.sqrt(sum(a["tq" + k] ** 2 for k in "xyz"))
    return ft, torque, fn


def reopen(liggghts, work, body, rebuild=0, cross=0, ranks=1):
    worst = []
    for nmodel, tmodel, rmodel in MODELS:
        name = "_".join(m.replace("/", "-") for m in (nmodel, tmodel, rmodel))
        folder = os.path.join(work, name)
        rolling = {"rolling": "rolling_friction", "rmodel": rmodel} if rmodel != "off" else {}
        run_deck(liggghts, DECK, folder, dict(body=body, nmodel=nmodel, tmodel=tmodel, rebuild=rebuild, cross=cross,
                                              **rolling), ranks=ranks)
        ft1, t1, fn1 = mover_state(os.path.join(folder, "phase1.dump"), body)
        ft3, t3, fn3 = mover_state(os.path.join(folder, "phase3.dump"), body)
        check(abs(fn3 - fn1) <= 1e-6 * abs(fn1), "%s %s: back at the same overlap (F_n %.6g N, then %.6g N)"
              % (body, name, fn1, fn3))
        if tmodel in SPRING_MODELS:
            check(ft1 > 1e-3 * abs(fn1), "%s %s: the slide loaded the tangential spring (F_t1 = %.4g N)"
                  % (body, name, ft1))
        if rmodel != "off":
            check(t1 > 0.0, "%s %s: the roll loaded the rolling model (T1 = %.4g N m)" % (body, name, t1))
        check(ft3 <= 1e-6 * max(ft1, 1e-6 * abs(fn1)),
              "%s %s: no tangential force after reclosing (F_t3 = %.3g N, F_t1 = %.3g N)" % (body, name, ft3, ft1))
        check(t3 <= 1e-6 * max(t1, 1e-12), "%s %s: no torque after reclosing (T3 = %.3g N m, T1 = %.3g N m)"
              % (body, name, t3, t1))
        worst.append(ft3 / ft1 if ft1 > 0 else 0.0)
    print("largest F_t3 / F_t1: %.3g" % max(worst))


@variants(*[(body, rebuild) for body in BODIES for rebuild in (0, 1)], timeout=300)
def case_reopen(liggghts, work, body, rebuild):
    """Open and reclose in one run: with no neighbour build between (0) or one every step (1)."""
    reopen(liggghts, work, body, rebuild=int(rebuild))


@variants(*[(body,) for body in BODIES], ranks=2, timeout=300)
def case_reopen_cross(liggghts, work, body):
    """2 ranks split at y = 0: while apart the sphere migrates to the other processor and back, with
    neighbour lists (and exchanges) every step."""
    reopen(liggghts, work, body, rebuild=1, cross=1, ranks=2)


if __name__ == "__main__":
    test_main(globals(), sys.argv[1:])
