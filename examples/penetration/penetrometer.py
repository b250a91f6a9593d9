#!/usr/bin/env python3
"""The penetrometer of examples/penetration as STL meshes for fix mesh/surface: a 60-degree cone
(cone.stl, the tip: its axial force over pi D_c^2 / 4 is q_c) and the shaft above it (shaft.stl, the
sleeve: its axial force is the shaft friction), of diameter D_c, the tip at (x, y, z_tip) pointing
down (-z). The surfaces are open (no base, no top: grains touch only the outside) and their facet
normals point outwards, as LIGGGHTS' contact detection expects.

  python3 penetrometer.py --diameter 0.002 --shaft 0.02 [--x 0 --y 0 --tip 0] [--segments 48] [--out .]

Cone height: (D_c / 2) / tan(30 deg) = 0.866 D_c. Units: metres."""
import argparse
import math
import os

APEX_ANGLE = 60.0  # degrees, the standard cone (ISO 22476-1)


def ring(cx, cy, z, radius, segments):
    """The polygon of a circle of the given radius at height z, counter-clockwise seen from above."""
    return [(cx + radius * math.cos(2 * math.pi * k / segments), cy + radius * math.sin(2 * math.pi * k / segments), z)
            for k in range(segments)]


def normal(a, b, c):
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    length = math.sqrt(sum(x * x for x in n))
    return [x / length for x in n]


def cone_facets(cx, cy, tip, diameter, segments):
    """Triangles from the tip to the base ring, wound so that the normals point away from the axis."""
    height = 0.5 * diameter / math.tan(math.radians(APEX_ANGLE / 2))
    base = ring(cx, cy, tip + height, 0.5 * diameter, segments)
    apex = (cx, cy, tip)
    return [(apex, base[(k + 1) % segments], base[k]) for k in range(segments)]


def shaft_facets(cx, cy, bottom, diameter, length, segments):
    """Two triangles per side of the prism from the cone's base ring up by length."""
    low = ring(cx, cy, bottom, 0.5 * diameter, segments)
    high = ring(cx, cy, bottom + length, 0.5 * diameter, segments)
    facets = []
    for k in range(segments):
        n = (k + 1) % segments
        facets += [(low[k], low[n], high[n]), (low[k], high[n], high[k])]
    return facets


def write_stl(path, name, facets):
    with open(path, "w") as f:
        f.write("solid %s\n" % name)
        for a, b, c in facets:
            f.write("  facet normal %.9e %.9e %.9e\n    outer loop\n" % tuple(normal(a, b, c)))
            for p in (a, b, c):
                f.write("      vertex %.9e %.9e %.9e\n" % p)
            f.write("    endloop\n  endfacet\n")
        f.write("endsolid %s\n" % name)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--diameter", type=float, required=True, help="D_c (m)")
    parser.add_argument("--shaft", type=float, required=True, help="shaft length above the cone (m)")
    parser.add_argument("--x", type=float, default=0.0)
    parser.add_argument("--y", type=float, default=0.0)
    parser.add_argument("--tip", type=float, default=0.0, help="height of the tip (m)")
    parser.add_argument("--segments", type=int, default=48, help="facets around the axis (>= 8)")
    parser.add_argument("--out", default=".", help="folder for cone.stl and shaft.stl")
    a = parser.parse_args()
    if not (a.diameter > 0 and a.shaft > 0 and a.segments >= 8):
        parser.error("--diameter and --shaft must be > 0 and --segments >= 8")
    height = 0.5 * a.diameter / math.tan(math.radians(APEX_ANGLE / 2))
    os.makedirs(a.out, exist_ok=True)
    write_stl(os.path.join(a.out, "cone.stl"), "cone", cone_facets(a.x, a.y, a.tip, a.diameter, a.segments))
    write_stl(os.path.join(a.out, "shaft.stl"), "shaft",
              shaft_facets(a.x, a.y, a.tip + height, a.diameter, a.shaft, a.segments))
    print("penetrometer: D_c %g m, cone height %g m, shaft %g m, %d segments: %s" %
          (a.diameter, height, a.shaft, a.segments, os.path.join(a.out, "{cone,shaft}.stl")))


if __name__ == "__main__":
    main()
