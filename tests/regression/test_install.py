#!/usr/bin/env python3
"""The install step and the Debian package (cmake/Install.cmake), as a user meets them.

  python3 test_install.py BUILD_DIR WORKDIR CASE
  python3 test_install.py --list

Cases:
  prefix  `cmake --install BUILD_DIR --prefix P`, then, with only P/bin added to PATH, `liggghts -in
          in.oedometer` (a short O-2) runs in a copy of the installed examples/fontainebleau, and
          `liggghts` is the plugin's binary (its styles listed by -h). The post-processing
          commands (post/__init__.py's TOOLS) sit beside it, bound to a Python that has numpy,
          scipy and matplotlib: crush-summary reads the run from another folder, and a command
          started by a Python without them names the command to use.
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
from liggghts_run import check, skip, variants  # noqa: E402
from liggghts_run import main as test_main  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
from post import TOOLS  # noqa: E402

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
    for page in ("doc/fix_crush.txt", "doc/design.md", "studies/fontainebleau/README.md",
                 "studies/critical_state/critical_states.csv", "studies/penetration/figures/penetration_qc_N60.png"):
        check(os.path.exists(os.path.join(prefix, "share", "doc", "liggghts-crush", page)),
              "doc page %s installed (doc/ and studies/ side by side: the relative links hold)" % page)
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
    check_commands(prefix, env, user_copy, work)


def check_commands(prefix, env, run_dir, work):
    """The installed post-processing commands: one per tool, each bound to a Python with numpy, scipy
    and matplotlib, working from any folder; under a Python without them, the message."""
    bound = {}
    for command in TOOLS:
        path = os.path.join(prefix, "bin", command)
        check(os.access(path, os.X_OK), "%s installed beside liggghts-crush" % command)
        bound[command] = open(path).readline()[2:].strip()
    python = bound["crush-summary"]
    check(len(set(bound.values())) == 1 and subprocess.run([python, "-c", "import numpy, scipy, matplotlib"]).returncode == 0,
          "every command is bound to %s, which imports numpy, scipy and matplotlib" % python)
    elsewhere = os.path.join(work, "elsewhere")
    os.makedirs(elsewhere, exist_ok=True)
    summary = run(["crush-summary", run_dir], elsewhere, env)
    check("O-2" in summary and "1304 -> 4372" in summary, "crush-summary reads the run from another folder")
    figures = os.path.join(elsewhere, "figures")
    run(["crush-plot", "--out", figures, run_dir], elsewhere, env)
    check(os.path.exists(os.path.join(figures, "fig4_oedometric.png")), "crush-plot draws the run's figure 4")
    proc = subprocess.run([python, "-S", os.path.join(prefix, "bin", "crush-plot"), "--help"], cwd=elsewhere,
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True)
    check(proc.returncode == 1 and "no module named 'matplotlib'" in proc.stderr and "crush-plot" in proc.stderr
          and "Run it with the Python that has them: %s" % python in proc.stderr,
          "crush-plot under a Python without matplotlib says so and what to run: %s" % proc.stderr.strip())


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


REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SETUP = os.path.join(REPO, "scripts", "setup.sh")


def cluster_path(folder, without=("dpkg", "apt", "sudo"), also_without=()):
    """A folder of links to every program of /usr/local/bin, /usr/bin and /bin but dpkg*, apt* and
    sudo (and also_without): the PATH of a machine without Debian's package tools."""
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    for d in ("/usr/local/bin", "/usr/bin", "/bin"):
        for name in sorted(os.listdir(d)) if os.path.isdir(d) else []:
            target = os.path.join(d, name)
            if name.startswith(without) or name in also_without or os.path.lexists(os.path.join(folder, name)):
                continue
            if os.path.isfile(target) and os.access(target, os.X_OK):
                os.symlink(target, os.path.join(folder, name))
    return folder


def as_user(cmd):
    """cmd as an unprivileged user: nobody when this test runs as root."""
    if os.getuid() != 0:
        return cmd
    return ["setpriv", "--reuid=nobody", "--regid=nogroup", "--clear-groups"] + cmd


def skip_unless_readable(paths):
    """Skips (CTest's 77) where the unprivileged user cannot read the repository's files (a checkout
    in a private folder): the test is about setup.sh, not the checkout's permissions."""
    if os.getuid() != 0:
        return
    for path in paths:
        if subprocess.run(as_user(["test", "-r", path]), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).returncode:
            skip("user nobody cannot read %s (a private checkout): the unprivileged build is not tried" % path)


def cluster_env(home, path):
    return {"HOME": home, "PATH": path, "LANG": "C.UTF-8", "TMPDIR": "/tmp"}


def tarball_of(build):
    """The LIGGGHTS tarball the main build was configured with."""
    for line in open(os.path.join(build, "CMakeCache.txt")):
        if line.startswith("LIGGGHTS_TARBALL:"):
            return line.split("=", 1)[1].strip()
    raise AssertionError("no LIGGGHTS_TARBALL in %s/CMakeCache.txt" % build)


def case_cluster_messages(build, work):
    """setup.sh on a machine without dpkg, apt and sudo, as an unprivileged user, stops before building
    with what it lacks: without an MPI compiler wrapper, the wrapper (and where the cluster's lines
    are); without a LIGGGHTS tarball, the file to give, its SHA256 and the option."""
    skip_unless_readable([SETUP, os.path.join(REPO, "cmake", "LiggghtsSource.cmake"), tarball_of(build)])
    root = os.path.join(work, "messages")
    shutil.rmtree(root, ignore_errors=True)
    os.makedirs(os.path.join(root, "home"))
    os.chmod(root, 0o777)
    os.chmod(os.path.join(root, "home"), 0o777)
    env = cluster_env(os.path.join(root, "home"), cluster_path(os.path.join(root, "path-no-mpi"),
                                                               also_without=("mpicxx", "mpic++", "mpiCC", "mpicc")))
    env.update(LIGGGHTS_CRUSH_BUILD_DIR=os.path.join(root, "build"), LIGGGHTS_CRUSH_DOWNLOAD_DIR=os.path.join(root, "dl"))
    out = run(as_user(["bash", SETUP, "--no-run", "--tarball", tarball_of(build)]), root, env, allowed_status=(1,))
    check("no apt here" in out and "cannot build: missing" in out and "MPI C++ compiler wrapper" in out
          and "On a cluster" in out, "without mpicxx: it names the wrapper and where the lines are:\n" + out)
    env["PATH"] = cluster_path(os.path.join(root, "path"))
    out = run(as_user(["bash", SETUP, "--no-build"]), root, env, allowed_status=(1,))
    sha = open(os.path.join(REPO, "cmake", "LiggghtsSource.cmake")).read().split('LIGGGHTS_TARBALL_SHA256 "')[1][:64]
    check("liggghts_3.8.0+repack1.orig.tar.xz" in out and sha in out and "--tarball" in out,
          "without a tarball: it names the file, its SHA256 and --tarball:\n" + out)
    check(not os.path.exists(os.path.join(root, "build")), "nothing built")


@variants(timeout=3000)
def case_cluster_build(build, work):
    """A cluster's build: setup.sh as an unprivileged user, on a PATH without dpkg, apt and sudo, in a
    fresh folder, from the tarball given with --tarball, GoogleTest and VTK switched off: the compiler
    is mpicxx, no unit test and no VTK dump is built, and the binary runs O-2 to 1 MPa on 2 ranks
    (the same state at 1 MPa, on 1 rank, as the main build's binary)."""
    skip_unless_readable([SETUP, os.path.join(REPO, "CMakeLists.txt"), tarball_of(build)])
    root = os.path.join(work, "cluster")
    shutil.rmtree(root, ignore_errors=True)
    os.makedirs(os.path.join(root, "home"))
    for d in (root, os.path.join(root, "home")):
        os.chmod(d, 0o777)
    env = cluster_env(os.path.join(root, "home"), cluster_path(os.path.join(root, "path")))
    fresh = os.path.join(root, "build")
    env.update(LIGGGHTS_CRUSH_BUILD_DIR=fresh, LIGGGHTS_CRUSH_DOWNLOAD_DIR=os.path.join(root, "dl"),
               CCACHE_DIR=os.path.join(root, "ccache"),
               LIGGGHTS_CRUSH_CMAKE_ARGS="-DLIGGGHTS_CRUSH_TESTS=OFF -DLIGGGHTS_CRUSH_VTK=OFF")
    out = run(as_user(["bash", SETUP, "--no-run", "--tarball", tarball_of(build)]), root, env)
    check("no apt here" in out and "compilers: " in out and "built: " + os.path.join(fresh, "liggghts") in out,
          "setup.sh built without apt, with the MPI wrappers")
    cache = open(os.path.join(fresh, "CMakeCache.txt")).read()
    compiler = [l.split("=", 1)[1] for l in cache.splitlines() if l.startswith("CMAKE_CXX_COMPILER:")][0]
    check(os.path.basename(compiler) == "mpicxx", "the C++ compiler is %s" % compiler)
    check(not os.path.exists(os.path.join(fresh, "tests", "unit")), "no unit tests configured (GoogleTest off)")
    binary = os.path.join(fresh, "liggghts")
    check(os.stat(binary).st_uid == (os.getuid() if os.getuid() != 0 else 65534), "built by the unprivileged user")
    styles = run(as_user([binary, "-h"]), root, env, allowed_status=(0, 1))
    check("crush" in styles and "custom/vtk" not in styles, "the plugin's styles, and no VTK dump style")
    states = {}
    for name, exe, ranks in (("cluster_np2", binary, 2), ("cluster_np1", binary, 1), ("main_np1", os.path.join(build, "liggghts"), 1)):
        folder = os.path.join(root, name)
        shutil.rmtree(folder, ignore_errors=True)
        shutil.copytree(os.path.join(REPO, "examples", "fontainebleau"), folder)
        os.chmod(folder, 0o777)
        launch = ["mpirun", "-np", str(ranks)] if ranks > 1 else []
        out = run(as_user(launch + [exe, "-in", "in.oedometer", "-var", "sigma_max", "1e6", "-log", "none"]), folder, env)
        lines = [l for l in out.splitlines() if l.startswith("STATE at 1 MPa:")]
        check(len(lines) == 1, "%s: O-2 ran to 1 MPa (%s)" % (name, lines))
        states[name] = lines[0]
    check(states["cluster_np1"] == states["main_np1"], "on 1 rank the cluster build's state at 1 MPa is the main "
          "build's: %s" % states["cluster_np1"])


if __name__ == "__main__":
    test_main(globals(), sys.argv[1:])
