#!/usr/bin/python3
"""Figures and tables of the cone penetration tests of examples/penetration (in.cone), for any set of
tests of one chamber.

    post/penetration.py --N 60 --Dc 0.0357 [--dir .] [--out dense_N60] LABEL ...

Reads, for each LABEL (in.cone's label, e.g. dense_1 and dense_0), penetration_LABEL_N<N>.csv,
events_pen_LABEL_N<N>.csv and particles_LABEL_N<N>.liggghts in --dir, and the events of the
chamber's consolidation with crushing (in.chamber: --chamber, by default
events_chamber_<density>_N<N>.csv with the label's first word as the density, where it exists:
the volume those events removed is in the gradings too), and writes there:
  penetration_OUT.png    q_c (MPa) and the sleeve friction f_s (kPa) against the tip's depth (D_c)
  events_OUT.png         where the grains broke, in (r, z - z_tip) / D_c around the tip at each event:
                         grains loaded to their limit F_lim, and grains without strength (a zero draw
                         of the Table 3 reading, distribution normal_clipped_originals: force ratio
                         inf), which break under their first load wherever the crushing zone finds them
  gsd_OUT.png, gsd_OUT.csv   the grading (percent passing against the downscaled size) and I_G near
                         the final tip (within --zone D_c of it) and in the far field (beyond --far D_c
                         of the axis), the removed volume counted as fractal fines as compute crush/gsd
                         counts it
  penetration_OUT_summary.csv   per test: q_c and f_s averaged over the plateau (depths from
                         --plateau D_c to the end), their spread, events, particles, I_G near and far,
                         and (I_G_near0, I_G_far0) those zones' I_G in the consolidated chamber before
                         the test (chamber_<density>_N<N>.liggghts, in.chamber's dump); the
                         velocity, the inertial number at the tip and in the chamber, and the grains'
                         kinetic energy as a share of the penetrometer's work (over the plateau); the
                         crushing about the tip's path (the axis above the final tip, the tip below it):
                         the test's events within 1 and --path D_c of it (events_path1, events_path2)
                         and beyond --far D_c of the axis (events_far), I_G within --path D_c of it
                         after the test and before (I_G_path, I_G_path0); the sleeve's mean share in
                         the sand over the plateau (sleeve_in: f_s is over that length); q_c's slope
                         over the last 2 D_c (q_c_slope_last2, MPa per D_c: rows averaged in bins of
                         0.25 D_c, the bins fitted; levelled off where the seeds' interval of the
                         slopes holds zero, post/penetration_stats.py --levelling)
and prints the summary, and per test a LEVELLING line with the slope and one test's rough interval.
"""
import argparse
import csv
import math
import os
import sys

if not __package__:  # run as a file (python3 post/penetration.py): the folder above post/ holds the package
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from post import requires  # noqa: E402
from post.seeds import interval  # noqa: E402

requires("penetration", "matplotlib")
# after the check above: post/critical_state.py needs numpy, which a Python without matplotlib may lack
from post.critical_state import least_squares  # noqa: E402

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

FRACTAL_DIMENSION = 2.5  # fix crush's default fines_dimension
D_MAX = 0.42e-3  # the decks' dmax for I_G (m, downscaled: examples/fontainebleau/in.load_stage)
RHO = 2650.0  # the grains' density (kg/m^3, examples/fontainebleau/in.grading)
D50 = 0.21e-3  # NE34's d50 (m, downscaled)
SIEVES = [0.01e-3, 0.02e-3, 0.05e-3, 0.075e-3, 0.1e-3, 0.15e-3, 0.2e-3, 0.25e-3, 0.3e-3, 0.35e-3, 0.45e-3]


def read_csv(path):
    with open(path) as f:
        return [dict((k, float(v)) for k, v in row.items()) for row in csv.DictReader(f)]


def read_dump(path):
    """{tag: (x, y, z, radius, generation, N)} of a dump custom 'id type x y z radius f_crush[2]' (by the
    header's names; N is the particle's own scale factor where the dump has f_grain_scale, the
    refined chambers' per-grain N, else None)."""
    atoms, lines = {}, open(path).read().split("\n")
    head = next(i for i, line in enumerate(lines) if line.startswith("ITEM: ATOMS"))
    names = lines[head].split()[2:]
    col = {name: k for k, name in enumerate(names)}
    scale = col.get("f_grain_scale")
    for line in lines[head + 1:]:
        w = line.split()
        if len(w) == len(names):
            atoms[int(w[col["id"]])] = (float(w[col["x"]]), float(w[col["y"]]), float(w[col["z"]]),
                                        float(w[col["radius"]]), float(w[col["f_crush[2]"]]),
                                        float(w[scale]) if scale is not None else None)
    return atoms


def tip_at(history, step):
    """The tip's z at a step, interpolated between the history's rows (tip_z column), and extrapolated
    from the last two rows past the last one (events after it, up to output_every steps, happen
    deeper; a snapshot after it sees the tip deeper). The one tip_at of post/ (pile_stress.py uses it)."""
    if step <= history[0]["step"]:
        return history[0]["tip_z"]
    for a, b in zip(history, history[1:]):
        if a["step"] <= step <= b["step"]:
            return a["tip_z"] + (step - a["step"]) / (b["step"] - a["step"]) * (b["tip_z"] - a["tip_z"])
    a, b = history[-2], history[-1]
    return b["tip_z"] + (step - b["step"]) / (b["step"] - a["step"]) * (b["tip_z"] - a["tip_z"])


def kept_fraction(events, atoms):
    """The volume fraction of a mother its fragments keep, measured on the first event whose fragments
    all remain (the layout's constant: about 0.53 for the 14 fragments)."""
    for e in events:
        tags = [int(v) for k, v in e.items() if k.startswith("fragment_")]
        if tags and all(t in atoms for t in tags):
            return sum((2 * atoms[t][3]) ** 3 for t in tags) / e["diameter"] ** 3
    return None


def grading(particles, removed, fines_top):
    """Percent passing at SIEVES and I_G of (sand size, model volume) particles plus a removed volume
    spread as fractal fines below fines_top (sizes downscaled: d / N of each particle)."""
    total = sum(v for _, v in particles) + removed

    def passing(size):
        solid = sum(v for d, v in particles if d < size)
        fines = removed * (min(size / fines_top, 1.0) ** (3 - FRACTAL_DIMENSION) if fines_top > 0 else 1.0)
        return (solid + fines) / total

    grid = [D_MAX * (k + 0.5) / 400 for k in range(400)]
    area = sum(passing(s) for s in grid) * D_MAX / 400
    limiting = D_MAX / (4.0 - FRACTAL_DIMENSION)
    return [100 * passing(s) for s in SIEVES], area / limiting


def zone_gradings(atoms, events, kept, tip, Dc, N, zone, far, fines_top):
    """The gradings within zone D_c of the tip's final place and beyond far D_c of the axis; events
    are every event of the sand's history up to the state of atoms, each removing 1 - kept of its
    mother as fines below fines_top."""
    near_p, far_p, near_removed, far_removed = [], [], 0.0, 0.0
    for x, y, z, r, _, n in atoms.values():
        d, v = 2 * r / (n or N), math.pi / 6 * (2 * r) ** 3
        if math.sqrt(x * x + y * y + (z - tip) ** 2) < zone * Dc:
            near_p.append((d, v))
        elif math.sqrt(x * x + y * y) > far * Dc:
            far_p.append((d, v))
    for e in events:
        removed = math.pi / 6 * e["diameter"] ** 3 * (1 - kept)
        if math.sqrt(e["x"] ** 2 + e["y"] ** 2 + (e["z"] - tip) ** 2) < zone * Dc:
            near_removed += removed
        elif math.sqrt(e["x"] ** 2 + e["y"] ** 2) > far * Dc:
            far_removed += removed
    return (grading(near_p, near_removed, fines_top), len(near_p)), (grading(far_p, far_removed, fines_top), len(far_p))


def path_distance(x, y, z, tip):
    """The distance of (x, y, z) from the tip's path: the axis above the tip's final place, the tip
    below it."""
    r = math.hypot(x, y)
    return r if z >= tip else math.hypot(r, z - tip)


def path_crushing(atoms, events, test_events, kept, tip, Dc, N, path, far, fines_top):
    """Crushing about the tip's path: the test's events within 1 and path D_c of the path and beyond
    far D_c of the axis, and I_G within path D_c of the path (events are the sand's history up to the
    state of atoms, each removing 1 - kept of its mother as fines below fines_top)."""
    near_p, near_removed = [], 0.0
    for x, y, z, r, _, n in atoms.values():
        if path_distance(x, y, z, tip) < path * Dc:
            near_p.append((2 * r / (n or N), math.pi / 6 * (2 * r) ** 3))
    for e in events:
        if path_distance(e["x"], e["y"], e["z"], tip) < path * Dc:
            near_removed += math.pi / 6 * e["diameter"] ** 3 * (1 - kept)
    within = [path_distance(e["x"], e["y"], e["z"], tip) / Dc for e in test_events]
    return {"events_path1": sum(1 for d in within if d < 1.0), "events_path2": sum(1 for d in within if d < path),
            "events_far": sum(1 for e in test_events if math.hypot(e["x"], e["y"]) > far * Dc),
            "I_G_path": grading(near_p, near_removed, fines_top)[1] if near_p else float("nan")}


def smallest_fragment(atoms, N):
    """The fines' top size (downscaled): the smallest fragment of atoms, d / N with its own N where the
    dump has it, 0 where none broke."""
    fragments = [2 * r / (n or N) for _, _, _, r, g, n in atoms.values() if g > 0]
    return min(fragments) if fragments else 0.0


def rate_measures(history, plateau, Dc, N):
    """The push's velocity, the inertial number I = (v / D_c) d50 sqrt(rho / p) at the tip (p = q_c)
    and in the chamber (p = the walls' mean stress), both over the plateau, and the grains' kinetic
    energy as a share of the penetrometer's work so far (the quarter's forces times the tip's
    travel, interval by interval), averaged over the plateau."""
    first, last = history[0], history[-1]
    v = (first["tip_z"] - last["tip_z"]) / (last["time"] - first["time"]) if last["time"] > first["time"] else float("nan")
    work, shares = 0.0, []
    for a, b in zip(history, history[1:]):
        work += (b["F_cone"] + b["F_sleeve"] + b["F_shaft"]) * (a["tip_z"] - b["tip_z"])
        if b in plateau and work > 0 and "ke" in b:
            shares.append(b["ke"] / work)
    mean = lambda values: sum(values) / len(values) if values else float("nan")  # noqa: E731
    rate = v / Dc * D50 * N * math.sqrt(RHO)
    q_c = mean([r["q_c"] for r in plateau])
    p = mean([(r["sigma_x"] + r["sigma_y"] + r["sigma_z"]) / 3 for r in plateau])
    return {"v": v, "I_tip": rate / math.sqrt(q_c) if q_c > 0 else float("nan"),
            "I_chamber": rate / math.sqrt(p) if p > 0 else float("nan"), "ke_share": mean(shares)}


LATE_SPAN = 2.0  # D_c: q_c has levelled off where its slope over the last LATE_SPAN of depth is not resolved
LATE_BIN = 0.25  # D_c: rows averaged in bins of this depth before the fit (neighbouring rows are correlated)


def late_slope(history, span=LATE_SPAN, width=LATE_BIN):
    """q_c's slope (MPa per D_c) over the last span of the tip's depth: the rows averaged in bins of
    width, the bins' means fitted by least squares; (slope, its 95% t interval low and high, bins).
    One test's interval is rough (the bins still correlate); the seeds' interval of the slopes
    (post/penetration_stats.py --levelling) decides whether q_c has levelled off."""
    end = history[-1]["depth_Dc"]
    bins = {}
    for r in history:
        if r["depth_Dc"] >= end - span:
            bins.setdefault(min(int((end - r["depth_Dc"]) / width), int(span / width) - 1), []).append(r)
    points = [(sum(r["depth_Dc"] for r in b) / len(b), sum(r["q_c"] for r in b) / len(b) / 1e6) for b in bins.values()]
    n = len(points)
    if n < 3:
        return float("nan"), float("nan"), float("nan"), n
    fit = least_squares([[1.0] * n, [x for x, _ in points]], [y for _, y in points])
    slope, se = float(fit["coefficients"][1]), float(fit["se"][1])
    low, high, _ = interval(slope, se, fit["df"])
    return slope, low, high, n


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("labels", nargs="+", help="the tests' labels (or one comma-separated list)")
    parser.add_argument("--N", type=float, required=True, help="the scale factor of the tests")
    parser.add_argument("--Dc", type=float, required=True, help="the cone's diameter (m)")
    parser.add_argument("--dir", default=".")
    parser.add_argument("--out", default="penetration")
    parser.add_argument("--plateau", type=float, default=4.0, help="start of the plateau (D_c)")
    parser.add_argument("--zone", type=float, default=1.5, help="near-tip zone radius (D_c)")
    parser.add_argument("--far", type=float, default=3.0, help="far field: beyond this distance from the axis (D_c)")
    parser.add_argument("--path", type=float, default=2.0, help="the zone about the tip's path: within this distance"
                        " of the axis above the final tip and of the tip below it (D_c)")
    parser.add_argument("--chamber", help="the chamber's consolidation events (in.chamber's events_chamber_*.csv;"
                        " default: events_chamber_<the label's first word>_N<N>.csv where it exists)")
    a = parser.parse_args()
    a.labels = [label for arg in a.labels for label in arg.split(",") if label]  # in.penetration joins them
    n_label = "%g" % a.N
    summary, tests = [], []
    for label in a.labels:
        path = os.path.join(a.dir, "penetration_%s_N%s.csv" % (label, n_label))
        if not os.path.exists(path):
            sys.exit("penetration.py: no %s (run in.cone with -var label %s -var N %s)" % (path, label, n_label))
        history = read_csv(path)
        events_path = os.path.join(a.dir, "events_pen_%s_N%s.csv" % (label, n_label))
        events = read_csv(events_path) if os.path.exists(events_path) else []
        dump = os.path.join(a.dir, "particles_%s_N%s.liggghts" % (label, n_label))
        atoms = read_dump(dump) if os.path.exists(dump) else {}
        chamber = a.chamber or os.path.join(a.dir, "events_chamber_%s_N%s.csv" % (label.split("_")[0], n_label))
        if a.chamber and not os.path.exists(chamber):
            sys.exit("penetration.py: no %s (--chamber)" % chamber)
        consolidation = read_csv(chamber) if os.path.exists(chamber) else []
        before = chamber.replace("events_chamber_", "chamber_")[:-len(".csv")] + ".liggghts"
        atoms0 = read_dump(before) if consolidation and os.path.exists(before) else {}
        tests.append((label, history, events, atoms))
        plateau = [r for r in history if r["depth_Dc"] >= a.plateau]
        qc = [r["q_c"] for r in plateau]
        fs = [r["f_s"] for r in plateau]
        # the sleeve's share in the sand (in.cone's sleeve_in; a history written before it: nan, its
        # f_s then over the whole sleeve)
        sleeve_in = [r["sleeve_in"] for r in plateau if "sleeve_in" in r]
        mean = lambda v: sum(v) / len(v) if v else float("nan")  # noqa: E731
        sd = lambda v: math.sqrt(sum((x - mean(v)) ** 2 for x in v) / len(v)) if v else float("nan")  # noqa: E731
        row = {"label": label, "q_c_MPa": mean(qc) / 1e6, "q_c_sd_MPa": sd(qc) / 1e6, "f_s_kPa": mean(fs) / 1e3,
               "f_s_sd_kPa": sd(fs) / 1e3, "sleeve_in": mean(sleeve_in), "depth_Dc": history[-1]["depth_Dc"],
               "q_c_slope_last2": late_slope(history)[0], "events": history[-1]["events"],
               "particles": history[-1]["particles"],
               "events_loaded": sum(1 for e in events if math.isfinite(e["force_ratio"])), "I_G_near": float("nan"), "I_G_far": float("nan"),
               "I_G_near0": float("nan"), "I_G_far0": float("nan"),
               "grains_near": 0, "grains_far": 0, "chamber_events": len(consolidation),
               "events_path1": float("nan"), "events_path2": float("nan"), "events_far": float("nan"),
               "I_G_path": float("nan"), "I_G_path0": float("nan")}
        history_events = consolidation + events
        kept = kept_fraction(history_events, atoms) if history_events else 1.0
        if atoms and kept is not None:
            tip, fines_top = history[-1]["tip_z"], smallest_fragment(atoms, a.N)
            (near, n_near), (far, n_far) = zone_gradings(atoms, history_events, kept, tip, a.Dc, a.N, a.zone, a.far, fines_top)
            row.update({"I_G_near": near[1], "I_G_far": far[1], "grains_near": n_near, "grains_far": n_far,
                        "near": near[0], "far": far[0]})
            row.update(path_crushing(atoms, history_events, events, kept, tip, a.Dc, a.N, a.path, a.far, fines_top))
            if atoms0:  # the same zones in the consolidated chamber, before the test
                (near0, _), (far0, _) = zone_gradings(atoms0, consolidation, kept, tip, a.Dc, a.N, a.zone, a.far, fines_top)
                row.update({"I_G_near0": near0[1], "I_G_far0": far0[1], "near0": near0[0],
                            "I_G_path0": path_crushing(atoms0, consolidation, [], kept, tip, a.Dc, a.N, a.path, a.far,
                                                       fines_top)["I_G_path"]})
        row.update(rate_measures(history, plateau, a.Dc, a.N))
        summary.append(row)

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 5), sharey=True)
    for label, history, _, _ in tests:
        depth = [r["depth_Dc"] for r in history]
        ax1.plot([r["q_c"] / 1e6 for r in history], depth, label=label)
        ax2.plot([r["f_s"] / 1e3 for r in history], depth, label=label)
    ax1.set_xlabel("q_c (MPa)")
    ax2.set_xlabel("f_s (kPa)")
    ax1.set_ylabel("depth of the tip (D_c)")
    ax1.invert_yaxis()
    for ax in (ax1, ax2):
        ax.grid(alpha=0.3)
        ax.legend()
    fig.suptitle("Cone penetration, N = %s, D_c / d50 = %.2f" % (n_label, a.Dc / (0.21e-3 * a.N)))
    fig.tight_layout()
    fig.savefig(os.path.join(a.dir, "penetration_%s.png" % a.out), dpi=120)

    broken = [(label, history, events) for label, history, events, _ in tests if events]
    if broken:
        fig, axes = plt.subplots(1, len(broken), figsize=(5 * len(broken), 6), squeeze=False)
        for ax, (label, history, events) in zip(axes[0], broken):
            depth = [r_["depth_Dc"] for r_ in history]
            for kind, chosen, marker in (("loaded to F_lim", [e for e in events if math.isfinite(e["force_ratio"])], "o"),
                                         ("no strength (first load)", [e for e in events if not math.isfinite(e["force_ratio"])], "x")):
                r = [math.hypot(e["x"], e["y"]) / a.Dc for e in chosen]
                z = [(e["z"] - tip_at(history, e["step"])) / a.Dc for e in chosen]
                ax.scatter(r, z, s=10, marker=marker, label="%s: %d" % (kind, len(chosen)))
            ax.legend(fontsize=8, loc="upper right")
            ax.plot([0, 0.5, 0.5], [0, 0.866, 4], color="k", lw=1)  # the cone and the sleeve's side
            ax.set_xlabel("r / D_c")
            ax.set_ylabel("(z - z_tip) / D_c")
            ax.set_title("%s: %d events to %.1f D_c" % (label, len(events), depth[-1]))
            ax.set_ylim(-4, 4)
            ax.set_xlim(0, 5)
            ax.grid(alpha=0.3)
        fig.tight_layout()
        fig.savefig(os.path.join(a.dir, "events_%s.png" % a.out), dpi=120)

    graded = [row for row in summary if "near" in row]
    if graded:
        with open(os.path.join(a.dir, "gsd_%s.csv" % a.out), "w") as f:
            f.write("size_mm," + ",".join("%s_near,%s_far" % (r["label"], r["label"]) for r in graded) + "\n")
            for k, s in enumerate(SIEVES):
                f.write("%g," % (s * 1e3) + ",".join("%.4f,%.4f" % (r["near"][k], r["far"][k]) for r in graded) + "\n")
        fig, ax = plt.subplots(figsize=(6, 5))
        for r in graded:
            line, = ax.semilogx([s * 1e3 for s in SIEVES], r["near"], label="%s near the tip (I_G %.3f)" % (r["label"], r["I_G_near"]))
            ax.semilogx([s * 1e3 for s in SIEVES], r["far"], ls="--", color=line.get_color(),
                        label="%s far field (I_G %.3f)" % (r["label"], r["I_G_far"]))
            if "near0" in r:
                ax.semilogx([s * 1e3 for s in SIEVES], r["near0"], ls=":", color=line.get_color(),
                            label="%s near the tip, before the test (I_G %.3f)" % (r["label"], r["I_G_near0"]))
        ax.set_xlabel("size (mm, downscaled)")
        ax.set_ylabel("percent passing")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(a.dir, "gsd_%s.png" % a.out), dpi=120)

    columns = ["label", "q_c_MPa", "q_c_sd_MPa", "f_s_kPa", "f_s_sd_kPa", "sleeve_in", "q_c_slope_last2", "depth_Dc", "events", "events_loaded", "particles",
               "I_G_near", "I_G_far", "I_G_near0", "I_G_far0", "grains_near", "grains_far", "chamber_events",
               "v", "I_tip", "I_chamber", "ke_share", "events_path1", "events_path2", "events_far", "I_G_path", "I_G_path0"]
    with open(os.path.join(a.dir, "penetration_%s_summary.csv" % a.out), "w") as f:
        f.write(",".join(columns) + "\n")
        for row in summary:
            f.write(",".join(row[c] if isinstance(row[c], str) else "%.6g" % row[c] for c in columns) + "\n")
    for row in summary:
        print("PENETRATION %s: q_c %.3f MPa (sd %.3f) and f_s %.2f kPa over %.1f - %.1f D_c, %d events (%d loaded to"
              " F_lim), %d particles, I_G %.3f near the tip, %.3f far (before the test %.3f and %.3f); v %.3g m/s,"
              " inertial number %.2g at the tip and %.2g in the chamber, kinetic energy %.2g of the work"
              % (row["label"], row["q_c_MPa"], row["q_c_sd_MPa"], row["f_s_kPa"], a.plateau, row["depth_Dc"],
                 row["events"], row["events_loaded"], row["particles"], row["I_G_near"], row["I_G_far"],
                 row["I_G_near0"], row["I_G_far0"], row["v"], row["I_tip"], row["I_chamber"], row["ke_share"]))
    for label, history, _, _ in tests:
        slope, low, high, bins = late_slope(history)
        print("LEVELLING %s: q_c's slope over the last %g D_c (to %.2f D_c), %d bins of %g D_c: %+.3f MPa per D_c "
              "(one test's 95%% interval %+.3f .. %+.3f; the seeds' interval decides: penetration_stats.py --levelling)"
              % (label, LATE_SPAN, history[-1]["depth_Dc"], bins, LATE_BIN, slope, low, high))


if __name__ == "__main__":
    main()
