#!/usr/bin/env python3
"""The install step and the Debian package (cmake/Install.cmake), as a user meets them.

  python3 test_install.py BUILD_DIR WORKDIR CASE
  python3 test_install.py --list

Cases:
  prefix  `cmake --install BUILD_DIR --prefix P`, then, with only P/bin added to PATH, `liggghts -in
          in.oedometer` (a short O-2) runs in a copy of the installed examples/fontainebleau, and
          `liggghts` is the plugin's binary (its styles listed by -h).
  deb     `cpack -G DEB` builds liggghts-crush_<version>_<arch>.deb; dpkg installs it into a private
          root (dpkg --root, no system change): /usr/bin/liggghts-crush and no /usr/bin/liggghts
          (Debian's liggghts package keeps that name), the binary runs the smoke deck from an
          unrelated folder, and removing the package leaves no file behind.
"""
import glob
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liggghts_run import check, variants  # noqa: E402
from liggghts_run import main as test_main  # noqa: E402

STYLES = ("crush", "wall/servo", "damp/local", "dt/stiffness", "hertz/scaled")


def run(cmd, cwd, env=None, allowed_status=(0,)):
    proc = subprocess.run(cmd, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True, errors="replace")
    if proc.returncode not in allowed_status:
        raise AssertionError("%s failed (exit %d):\n%s" % (" ".join(cmd), proc.returncode, proc.stdout[-3000:]))
    return proc.stdout


def clean_env(path_dirs):
    """The environment of a user whose PATH holds only the given folders and the system's."""
    env = dict(os.environ)
    env["PATH"] = ":".join(path_dirs + ["/usr/bin", "/bin"])
    return env


@variants(timeout=600)
def case_prefix(build, work):
    prefix = os.path.join(work, "prefix")
    run(["cmake", "--install", build, "--prefix", prefix], work)
    binary = os.path.join(prefix, "bin", "liggghts")
    check(os.path.islink(binary) and os.readlink(binary) == "liggghts-crush",
          "bin/liggghts is a link to bin/liggghts-crush")
    env = clean_env([os.path.join(prefix, "bin")])
    styles = run(["liggghts", "-h"], work, env, allowed_status=(0, 1))  # LIGGGHTS' -h exits with 1
    check(all(s in styles for s in STYLES), "the 'liggghts' on PATH lists the plugin's styles")
    for page in ("fix_crush.txt", "design.md", "results.md", "critical_state.md"):
        check(os.path.exists(os.path.join(prefix, "share", "doc", "liggghts-crush", page)),
              "doc page %s installed" % page)
    share = os.path.join(prefix, "share", "liggghts-crush")
    for name in ("examples/single_grain/plane.stl", "examples/fontainebleau/in.triaxial_box", "post/critical_state.py"):
        check(os.path.exists(os.path.join(share, name)), "%s installed (the mesh-wall single grain, the decks, "
              "the fit)" % name)
    examples = os.path.join(prefix, "share", "liggghts-crush", "examples", "fontainebleau")
    user_copy = os.path.join(work, "fontainebleau")
    shutil.rmtree(user_copy, ignore_errors=True)
    shutil.copytree(examples, user_copy)
    out = run(["liggghts", "-in", "in.oedometer", "-var", "sigma_max", "1e6"], user_copy, env)
    check("STATE at 1 MPa:" in out, "liggghts -in in.oedometer runs from the installed examples to 1 MPa")
    summary = run([sys.executable, os.path.join(prefix, "share", "liggghts-crush", "post", "summary.py"),
                   user_copy], work)
    check("O-2" in summary and "1304 -> 4372" in summary, "the installed post/summary.py reads the run")


@variants(timeout=600)
def case_deb(build, work):
    out_dir = os.path.join(work, "package")
    shutil.rmtree(out_dir, ignore_errors=True)
    run(["cpack", "-G", "DEB", "-B", out_dir], build)
    debs = glob.glob(os.path.join(out_dir, "liggghts-crush_*_*.deb"))
    check(len(debs) == 1, "cpack wrote liggghts-crush_<version>_<arch>.deb (%s)" % [os.path.basename(d) for d in debs])
    fields = run(["dpkg-deb", "-f", debs[0], "Package", "Depends"], work)
    check("Package: liggghts-crush" in fields and "libopenmpi" in fields,
          "the package is liggghts-crush and depends on Open MPI's library")
    root = os.path.join(work, "root")
    shutil.rmtree(root, ignore_errors=True)
    admin = os.path.join(root, "var", "lib", "dpkg")
    for sub in ("info", "updates", "triggers"):
        os.makedirs(os.path.join(admin, sub))
    for name in ("status", "available"):
        open(os.path.join(admin, name), "w").close()
    dpkg = ["dpkg", "--root=" + root, "--log=/dev/null", "--force-not-root", "--force-depends",
            "--force-script-chrootless"]
    run(dpkg + ["-i", debs[0]], work)
    binary = os.path.join(root, "usr", "bin", "liggghts-crush")
    check(os.access(binary, os.X_OK), "/usr/bin/liggghts-crush installed")
    check(not os.path.exists(os.path.join(root, "usr", "bin", "liggghts")),
          "no /usr/bin/liggghts: Debian's liggghts package can sit beside it")
    elsewhere = os.path.join(work, "elsewhere")
    os.makedirs(elsewhere, exist_ok=True)
    smoke = os.path.join(root, "usr", "share", "liggghts-crush", "examples", "smoke", "in.smoke")
    out = run([binary, "-in", smoke, "-log", "none"], elsewhere)
    check("SMOKE_DONE atoms=100" in out, "the packaged binary runs the packaged smoke deck from another folder")
    run(dpkg + ["-r", "liggghts-crush"], work)
    left = [os.path.join(d, f) for d, _, files in os.walk(os.path.join(root, "usr")) for f in files]
    check(not left, "dpkg -r leaves no file under /usr (%d left)" % len(left))


if __name__ == "__main__":
    test_main(globals(), sys.argv[1:])
