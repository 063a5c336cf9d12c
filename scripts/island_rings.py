#!/usr/bin/env python3
"""Coastline islands from GSHHG (Debian: gmt-gshhg-low), projected to
kilometres, in the rings format (testgen/src/rings.rs), for the
medial-axis and offset tests on real outlines (issue 27).

    scripts/island_rings.py NAME WEST EAST SOUTH NORTH [--resolution l]
                            [--out DIR]

writes DIR/gshhg_islands_NAME.rings (default DIR: tests/data): every
island of the box that GSHHG stores whole in one bin (a closed coastline
polygon of level 1, land; the bins are read by scripts/coastlines.py),
each its own ring, so the domain is the islands and the sea between them
is outside. Coordinates: GSHHG's integer offsets in the bins (exact), then
the local equirectangular projection of scripts/country_rings.py, so
points on one line of the integer grid become straight or nearly straight
vertices.
"""

import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import coastlines  # noqa: E402

EARTH_RADIUS_KM = 6371.0


def islands(resolution, box):
    path = os.path.join(coastlines.DATA_DIR, "binned_%s_%s.nc" % (coastlines.FILE_STEM["coast"], resolution))
    lines, size_minutes, _ = coastlines.polylines(path, "coast", box, {1})
    degrees_per_unit = size_minutes / 60.0 / coastlines.UNITS
    rings = []
    for points in lines:
        if len(points) < 4 or points[0] != points[-1]:
            continue  # a coast cut at a bin's side, not a whole island
        ring = []
        for p in points[:-1]:
            if not ring or ring[-1] != p:
                ring.append(p)
        if len(ring) >= 3:
            # rows count from the south pole: latitude = y - 90 degrees
            rings.append([(x * degrees_per_unit, y * degrees_per_unit - 90.0) for x, y in ring])
    return rings


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("name")
    parser.add_argument("box", nargs=4, type=float, metavar="WEST EAST SOUTH NORTH")
    parser.add_argument("--resolution", default="l")
    parser.add_argument("--out", default=os.path.join(os.path.dirname(__file__), "..", "tests", "data"))
    args = parser.parse_args()
    rings = islands(args.resolution, args.box)
    if not rings:
        sys.exit("no whole island in the box")
    lons = [p[0] for r in rings for p in r]
    lats = [p[1] for r in rings for p in r]
    lon0, lat0 = (min(lons) + max(lons)) / 2, (min(lats) + max(lats)) / 2
    kx = EARTH_RADIUS_KM * math.radians(1.0) * math.cos(math.radians(lat0))
    ky = EARTH_RADIUS_KM * math.radians(1.0)
    path = os.path.join(args.out, "gshhg_islands_%s.rings" % args.name)
    with open(path, "w") as out:
        out.write("# islands of GSHHG %s (%s), box %s, by scripts/island_rings.py\n" % (args.resolution, coastlines.DATA_DIR, args.box))
        out.write("# km, equirectangular around lon %.6f lat %.6f, R = %g km\n" % (lon0, lat0, EARTH_RADIUS_KM))
        out.write("rings %d\n" % len(rings))
        for r in rings:
            out.write("%d\n" % len(r))
            for lon, lat in r:
                out.write("%r %r\n" % ((lon - lon0) * kx, (lat - lat0) * ky))
    print("%s: %d islands, %d points" % (path, len(rings), sum(len(r) for r in rings)))


if __name__ == "__main__":
    main()
