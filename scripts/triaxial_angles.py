#!/usr/bin/python3
"""Friction angles of drained triaxial runs (examples/fontainebleau/in.triaxial), for studies/fontainebleau/README.md.

    scripts/triaxial_angles.py FOLDER ...          (each holding one history_T<sample><N>.csv)

For each run: the peak stress ratio M = q/p and the axial strain where it occurs, the mean M over the
last quarter of the test (15 - 20% axial strain for axial_max 0.2: the critical state), each as a
friction angle phi = asin(3 M / (6 + M)) (triaxial compression), the largest contraction and the
final volumetric strain (compression positive). Prints a Markdown table."""
import csv
import glob
import math
import os
import sys


def phi(m):
    return math.degrees(math.asin(3.0 * m / (6.0 + m)))


def angles(folder, last=0.25):
    path = sorted(glob.glob(os.path.join(folder, "history_T*.csv")))[0]
    rows = [dict((k, float(v)) for k, v in r.items()) for r in csv.DictReader(open(path))]
    rows = [r for r in rows if r.get("stage", 1) == 1]  # shearing only (in.triaxial's stage 1)
    eps = [r["axial_strain"] for r in rows]
    m = [r["q_over_p"] for r in rows]
    vol = [r["volumetric_strain"] for r in rows]
    ipk = max(range(len(m)), key=m.__getitem__)
    start = eps[-1] * (1.0 - last)
    tail = [mi for e, mi in zip(eps, m) if e >= start]
    m_cs = sum(tail) / len(tail)
    return {"run": os.path.basename(os.path.normpath(folder)), "M_peak": m[ipk], "eps_peak": eps[ipk],
            "phi_peak": phi(m[ipk]), "M_cs": m_cs, "phi_cs": phi(m_cs), "eps_end": eps[-1],
            "tail_from": start, "max_contraction": max(vol), "vol_end": vol[-1]}


def main(folders):
    print("| run | peak q/p (axial strain) | phi peak | q/p over %s | phi end | max contraction | final volumetric |"
          % "last 25%")
    print("|---|---|---|---|---|---|---|")
    for f in folders:
        a = angles(f)
        print("| %s | %.3f (%.1f%%) | %.1f deg | %.3f (%.1f - %.1f%%) | %.1f deg | %.1f%% | %+.1f%% |" % (
            a["run"], a["M_peak"], 100 * a["eps_peak"], a["phi_peak"], a["M_cs"], 100 * a["tail_from"],
            100 * a["eps_end"], a["phi_cs"], 100 * a["max_contraction"], 100 * a["vol_end"]))


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
