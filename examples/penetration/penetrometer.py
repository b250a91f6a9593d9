#!/usr/bin/env python3
"""The penetrometer of examples/penetration as STL meshes for fix mesh/surface: a 60-degree cone
(cone.stl, the tip: its axial force over pi D_c^2 / 4 is q_c), optionally a friction sleeve right
above it (sleeve.stl, --sleeve L: its axial force over pi D_c L is the sleeve friction f_s) and the
shaft above that (shaft.stl), of diameter D_c, the tip at (x, y, z_tip) pointing down (-z). The
surfaces are open (no base, no top: grains touch only the outside) and their facet normals point
outwards, as LIGGGHTS' contact detection expects. --sector 90 (or 180) writes only the part between
the angles 0 and 90 (180) degrees around the axis: the penetrometer of a quarter (half) chamber whose
symmetry planes pass through the axis; its forces are that fraction of the whole one's.
--tip-shape flat writes a flat base instead of the cone (cone.stl keeps the name: the tip's force):
the closed-ended pile of calibration-chamber tests, whose base resistance is that force over
pi D^2 / 4.

  python3 penetrometer.py --diameter 0.002 --shaft 0.02 [--sleeve 0.0075] [--x 0 --y 0 --tip 0]
                          [--segments 48] [--sector 360] [--tip-shape cone|flat] [--out .]

Cone height: (D_c / 2) / tan(30 deg) = 0.866 D_c (a flat base: 0). Units: metres."""
import argparse
import math
import os

APEX_ANGLE = 60.0  # degrees, the standard cone (ISO 22476-1)


def ring(cx, cy, z, radius, segments):
    """The polygon of a circle of the given radius at height z, counter-clockwise seen from above
    (segments + 1 points: the last closes the circle, or ends a sector)."""
    return [(cx + radius * math.cos(2 * math.pi * k / segments), cy + radius * math.sin(2 * math.pi * k / segments), z)
            for k in range(segments + 1)]


def normal(a, b, c):
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    length = math.sqrt(sum(x * x for x in n))
    return [x / length for x in n]


def cone_facets(cx, cy, tip, diameter, segments, sides):
    """Triangles from the tip to the base ring (the first sides of segments), wound so that the
    normals point away from the axis."""
    height = 0.5 * diameter / math.tan(math.radians(APEX_ANGLE / 2))
    base = ring(cx, cy, tip + height, 0.5 * diameter, segments)
    apex = (cx, cy, tip)
    return [(apex, base[k + 1], base[k]) for k in range(sides)]


def flat_facets(cx, cy, tip, diameter, segments, sides):
    """The base disc at the tip's height, a fan from the axis wound so that the normals point down."""
    base = ring(cx, cy, tip, 0.5 * diameter, segments)
    centre = (cx, cy, tip)
    return [(centre, base[k + 1], base[k]) for k in range(sides)]


def tip_height(diameter, shape):
    """The height of the tip's part: the 60-degree cone's, or 0 for a flat base."""
    return 0.5 * diameter / math.tan(math.radians(APEX_ANGLE / 2)) if shape == "cone" else 0.0


def shaft_facets(cx, cy, bottom, diameter, length, segments, sides):
    """Two triangles per side of the prism from the ring at bottom up by length."""
    low = ring(cx, cy, bottom, 0.5 * diameter, segments)
    high = ring(cx, cy, bottom + length, 0.5 * diameter, segments)
    facets = []
    for k in range(sides):
        facets += [(low[k], low[k + 1], high[k + 1]), (low[k], high[k + 1], high[k])]
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
    parser.add_argument("--shaft", type=float, required=True, help="shaft length above the cone or sleeve (m)")
    parser.add_argument("--sleeve", type=float, default=0.0, help="friction sleeve length right above the cone (m; 0: none)")
    parser.add_argument("--x", type=float, default=0.0)
    parser.add_argument("--y", type=float, default=0.0)
    parser.add_argument("--tip", type=float, default=0.0, help="height of the tip (m)")
    parser.add_argument("--segments", type=int, default=48, help="facets around the axis (>= 8)")
    parser.add_argument("--sector", type=float, default=360.0, choices=(90.0, 180.0, 360.0),
                        help="degrees around the axis, from the +x direction counter-clockwise")
    parser.add_argument("--tip-shape", default="cone", choices=("cone", "flat"),
                        help="the 60-degree cone, or a flat base (a closed-ended pile)")
    parser.add_argument("--out", default=".", help="folder for cone.stl and shaft.stl")
    a = parser.parse_args()
    if not (a.diameter > 0 and a.shaft > 0 and a.sleeve >= 0 and a.segments >= 8 and a.segments % 4 == 0):
        parser.error("--diameter and --shaft must be > 0, --sleeve >= 0, --segments >= 8 and a multiple of 4")
    height = tip_height(a.diameter, a.tip_shape)
    sides = int(a.segments * a.sector / 360.0)
    os.makedirs(a.out, exist_ok=True)
    tip = cone_facets if a.tip_shape == "cone" else flat_facets
    write_stl(os.path.join(a.out, "cone.stl"), "cone", tip(a.x, a.y, a.tip, a.diameter, a.segments, sides))
    names = ["cone"]
    if a.sleeve > 0:
        write_stl(os.path.join(a.out, "sleeve.stl"), "sleeve",
                  shaft_facets(a.x, a.y, a.tip + height, a.diameter, a.sleeve, a.segments, sides))
        names.append("sleeve")
    write_stl(os.path.join(a.out, "shaft.stl"), "shaft",
              shaft_facets(a.x, a.y, a.tip + height + a.sleeve, a.diameter, a.shaft, a.segments, sides))
    names.append("shaft")
    print("penetrometer: D_c %g m, %s tip of height %g m, sleeve %g m, shaft %g m, %d of %d segments: %s" %
          (a.diameter, a.tip_shape, height, a.sleeve, a.shaft, sides, a.segments,
           os.path.join(a.out, "{%s}.stl" % ",".join(names))))


if __name__ == "__main__":
    main()
