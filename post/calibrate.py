#!/usr/bin/env python3
"""Calibrating fix crush for another sand (doc/calibration.md): from single-particle crushing tests
to the fix crush line, checked by the DEM, and against an oedometric compression curve.

  calibrate.py single-particle DATA.csv [--d0 D0] [--grain-E E --grain-nu NU] [--platen-E E
                                        --platen-nu NU] [--scale N] [--seed S] [--out DIR]
  calibrate.py synthetic OUT.csv --sigma_lim0 S --cv C --weibull_m M --d0 D0 --sizes D1,D2,...
                                 --per-size N --seed SEED [--distribution normal|weibull]
  calibrate.py summary SUMMARY.csv [--d0 D0] [--grain-E E ...] [--scale N] [--out DIR]
                                 (published summary statistics: per size class d, n, m_t and F_0 or sigma_0)
  calibrate.py moduli MODULI.csv [--out DIR]  (published moduli without strengths, against Table 1)
  calibrate.py population FIT_DIR --per-size N --out DIR      (the grains of the DEM check)
  calibrate.py compare DATA.csv FIT_DIR RUN_DIR [--out DIR]   (DEM failure forces against the data)
  calibrate.py oedometer LAB.csv [--sigma_lim0 S1,S2,..] [--cv C1,C2,..] [--from FIT_DIR]
                                 [--liggghts PATH] [--ranks R] [--sigma_max P] [--out DIR]

Data (single-particle): a CSV with a header and one row per crushed grain; lines starting with '#'
are comments. Columns: d (grain diameter, m) and F_f (force at failure, N), required; E_grain,
nu_grain, E_platen, nu_platen (Pa, -), optional, per row (otherwise --grain-E ... or their defaults);
size_class, optional (a label: grains of one sieve fraction; otherwise grains of equal d form a class).

Data (summary): one row per size class, for papers that give only summary statistics: d (the class's
diameter, m), n (grains tested), m_t (the Weibull modulus of the class's failure forces, or of F/d^2:
the same at one size) and F_0 (the characteristic failure force, 37% survival, N) or sigma_0 (the
characteristic F/d^2, Pa); the moduli columns as above, optional.

Data (moduli): published statistics without strengths, one a row: source, material, quantity (m_t:
the Weibull modulus of the failure forces of one size; strength_ratio: the characteristic F/d^2 of
d_small over that of d_large), low and high (the stated range), d_small and d_large (m, for a ratio).

The model's limit (Ciantia et al. 2014, eq. 5) is a contact stress:
    F_lim = [sigma_lim pi (3 r'/(4 E'))^(2/3)]^3
A grain squeezed between platens touches each as a sphere on a plane (r' = R = d/2), with
E' = ((1 - nu_g^2)/E_g + (1 - nu_p^2)/E_p)^-1 (eq. 4). Hence each failure force gives the strength
    sigma_lim = F_f^(1/3) (4 E'/(3 r'))^(2/3) / pi
and the size effect of fix crush (eq. 6/10: sigma_lim = s (d/(N d0))^(-3/m), s drawn with mean
sigma_lim0) is a straight line of log sigma_lim against log d with slope -3/m. E_g is the modulus of
the grains in the deck (the DEM checks F against F_lim with the deck's E'), not the mineral's."""
import os
import sys

if not __package__:  # run as a file (python3 post/calibrate.py): the folder above post/ holds the package
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from post import requires  # noqa: E402

requires("calibrate", "numpy", "scipy", "matplotlib")

import argparse  # noqa: E402

from post.calibration.data import DataError  # noqa: E402
from post.calibration.dem_check import compare, population  # noqa: E402
from post.calibration.moduli import published_moduli  # noqa: E402
from post.calibration.oedometer import REPO, oedometer  # noqa: E402
from post.calibration.single_particle import single_particle, synthetic  # noqa: E402
from post.calibration.strength import DEFAULT_GRAIN, DEFAULT_PLATEN  # noqa: E402
from post.calibration.summary import summary  # noqa: E402


# ---------------------------------------------------------------------------------------------
# the command line

def parser():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = ap.add_subparsers(dest="command_name", required=True)

    def command(name, help):
        return sub.add_parser(name, help=help, formatter_class=argparse.ArgumentDefaultsHelpFormatter)

    def moduli(p):
        p.add_argument("--grain-E", type=float, default=DEFAULT_GRAIN[0], help="grain Young's modulus (Pa) of the deck")
        p.add_argument("--grain-nu", type=float, default=DEFAULT_GRAIN[1], help="grain Poisson ratio of the deck")
        p.add_argument("--platen-E", type=float, default=DEFAULT_PLATEN[0], help="platen Young's modulus (Pa)")
        p.add_argument("--platen-nu", type=float, default=DEFAULT_PLATEN[1], help="platen Poisson ratio")

    sp = command("single-particle", "fit fix crush's parameters to crushing tests")
    sp.add_argument("data", help="CSV: one grain a row, columns d (m), F_f (N); optional E_grain, nu_grain, E_platen, nu_platen, size_class")
    sp.add_argument("--d0", type=float, default=None, help="reference diameter (m; default: the median size)")
    sp.add_argument("--scale", type=float, default=1.0, help="the deck's upscaling factor N (scale keyword)")
    sp.add_argument("--bootstrap", type=int, default=400, help="bootstrap resamples for the intervals")
    sp.add_argument("--seed", type=int, default=2, help="seed of the bootstrap")
    sp.add_argument("--crush-seed", type=int, default=15485863, help="seed written in the fix crush line")
    sp.add_argument("--out", default="calibration", help="folder for parameters.json and the figures")
    moduli(sp)
    sp.set_defaults(run=single_particle)

    su = command("summary", "fix crush's parameters from published summary statistics per size")
    su.add_argument("data", help="CSV: one size class a row, columns d (m), n, m_t, and F_0 (N) or sigma_0 (Pa)")
    su.add_argument("--d0", type=float, default=None, help="reference diameter (m; default: the classes' geometric mean)")
    su.add_argument("--scale", type=float, default=1.0, help="the deck's upscaling factor N (scale keyword)")
    su.add_argument("--bootstrap", type=int, default=400, help="resamples for the intervals")
    su.add_argument("--seed", type=int, default=2, help="seed of the resamples")
    su.add_argument("--crush-seed", type=int, default=15485863, help="seed written in the fix crush line")
    su.add_argument("--out", default="calibration", help="folder for parameters.json and the figures")
    moduli(su)
    su.set_defaults(run=summary)

    mo = command("moduli", "published Weibull moduli and size ratios (no strengths) against Table 1")
    mo.add_argument("data", help="CSV: source, material, quantity (m_t or strength_ratio), low, high, d_small, d_large")
    mo.add_argument("--out", default="moduli", help="folder for moduli.json")
    mo.set_defaults(run=published_moduli)

    sy = command("synthetic", "draw tests from known parameters")
    sy.add_argument("out_csv", help="the CSV to write (d, F_f)")
    for name in ("--sigma_lim0", "--cv", "--weibull_m", "--d0"):
        sy.add_argument(name, type=float, required=True)
    sy.add_argument("--sizes", required=True, help="diameters (m), comma-separated")
    sy.add_argument("--per-size", type=int, required=True, help="grains per size class")
    sy.add_argument("--seed", type=int, required=True, help="seed of the draws")
    sy.add_argument("--distribution", choices=("normal", "weibull"), default="normal", help="law of the strengths")
    moduli(sy)
    sy.set_defaults(run=synthetic)

    po = command("population", "grains and variables of the DEM check")
    po.add_argument("fit", help="the --out folder of single-particle")
    po.add_argument("--per-size", type=int, default=30, help="grains per size class")
    po.add_argument("--density", type=float, default=2650.0, help="grain density (kg/m^3)")
    po.add_argument("--seed", type=int, default=15485863, help="fix crush's seed in the run")
    po.add_argument("--distribution", default=None, help="instead of the fitted line's (e.g. constant)")
    po.add_argument("--out", default="population", help="folder for grains.include and variables.txt")
    po.set_defaults(run=population)

    co = command("compare", "DEM failure forces against the tests")
    co.add_argument("data", help="the tests' CSV (as for single-particle)")
    co.add_argument("fit", help="the --out folder of single-particle")
    co.add_argument("run_dir", help="the folder of the DEM run (population's --out)")
    co.add_argument("--out", default=None, help="default: the run's folder")
    co.set_defaults(run=compare)

    oe = command("oedometer", "O-N runs for a grid of (sigma_lim0, cv) against a lab curve")
    oe.add_argument("lab", help="CSV with columns sigma_v (Pa), e")
    oe.add_argument("--sigma_lim0", default="2.5e9,5e9,1e10", help="candidate values (Pa), comma-separated")
    oe.add_argument("--cv", default="0.5,1", help="candidate values, comma-separated")
    oe.add_argument("--weibull_m", type=float, default=10.0, help="size effect modulus of the runs")
    oe.add_argument("--d0", type=float, default=2e-3, help="reference diameter (m) of the runs")
    oe.add_argument("--from", dest="fit", default=None, help="take weibull_m and d0 from a single-particle fit")
    oe.add_argument("--N", default="2", help="the upscaling factor of the run (O-N)")
    oe.add_argument("--sigma_max", type=float, default=1e8, help="largest vertical stress of the runs (Pa)")
    oe.add_argument("--ranks", type=int, default=2, help="MPI ranks of each run")
    # the repository's build, or (installed under share/, beside no build) liggghts on the PATH
    built = os.path.join(REPO, "build", "liggghts")
    oe.add_argument("--liggghts", default=built if os.path.exists(built) else "liggghts", help="the executable")
    oe.add_argument("--command", default="mpirun -np {ranks} --oversubscribe {liggghts} -in in.oedometer -var N {N} "
                    "-var sigma_lim0 {sigma_lim0} -var sigma_max {sigma_max} -log log.liggghts",
                    help="the run's command line ({liggghts} {ranks} {N} {sigma_lim0} {sigma_max} filled in)")
    oe.add_argument("--out", default="oedometer", help="folder for the runs, oedometer.json and the figure")
    oe.set_defaults(run=oedometer)
    return ap


def main(argv):
    args = parser().parse_args(argv)
    if getattr(args, "out", "") is None:
        args.out = args.run_dir
    try:
        args.run(args)
    except DataError as e:
        print("calibrate.py: error: %s" % e, file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
