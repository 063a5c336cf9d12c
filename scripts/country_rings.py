#!/usr/bin/env python3
"""Country outlines from the Digital Chart of the World as GMT ships it
(Debian: gmt-dcw, /usr/share/gmt-dcw/dcw-gmt.nc), projected to kilometres
as a GIS user would, in the rings format (testgen/src/rings.rs), for the
medial-axis and offset tests on real outlines (issue 27).

    scripts/country_rings.py CODE [CODE ...] [--out DIR]

writes DIR/dcw_CODE.rings (default DIR: tests/data) for each two-letter
country code of dcw-countries.txt.

The file (netCDF-4, read with h5py; the layout follows GMT's gmt_dcw.c):
per country CODE, the arrays CODE_lon and CODE_lat of 16-bit unsigned
integers, a coordinate being `min + value / scale` (attributes of each
array). A longitude of 65535 starts a new polygon; the latitude beside it
is 1 when that polygon is a hole (a country inside the country, as
Lesotho in South Africa), 0 otherwise. The domain is the even-odd region of
all rings, so holes need no other mark here.

The projection is the local equirectangular one around the outline's
centre, x = R (lon - lon0) cos(lat0), y = R (lat - lat0), R = 6371 km:
each axis an affine map of the stored integers, rounded to double, so the
many points that lie on one line in the integer grid (borders along a
parallel or a meridian, straight digitised stretches) become straight or
nearly straight vertices, as in every reprojected outline. Repeated
consecutive points are dropped (and a ring's closing repeat).
"""

import argparse
import math
import os
import sys

try:
    import h5py
    import numpy as np
except ImportError:
    sys.exit("needs h5py and numpy (pip install h5py numpy)")

DCW = "/usr/share/gmt-dcw/dcw-gmt.nc"
EARTH_RADIUS_KM = 6371.0


def polygons(f, code):
    """The country's polygons as lists of (lon, lat) in degrees."""
    lon_var, lat_var = f[code + "_lon"], f[code + "_lat"]
    lon_raw, lat_raw = lon_var[:].astype(np.int64), lat_var[:].astype(np.int64)

    def decode(var, raw):
        low, scale = float(var.attrs["min"][0]), float(var.attrs["scale"][0])
        return low + raw / scale

    lon, lat = decode(lon_var, lon_raw), decode(lat_var, lat_raw)
    out, current = [], []
    for k in range(len(lon_raw)):
        if lon_raw[k] == 65535:
            if current:
                out.append(current)
            current = []
            continue
        current.append((float(lon[k]), float(lat[k])))
    if current:
        out.append(current)
    return out


def project(rings):
    lons = [p[0] for r in rings for p in r]
    lats = [p[1] for r in rings for p in r]
    lon0, lat0 = (min(lons) + max(lons)) / 2, (min(lats) + max(lats)) / 2
    kx = EARTH_RADIUS_KM * math.radians(1.0) * math.cos(math.radians(lat0))
    ky = EARTH_RADIUS_KM * math.radians(1.0)
    return [[((lon - lon0) * kx, (lat - lat0) * ky) for lon, lat in r] for r in rings], (lon0, lat0)


def clean(ring):
    out = []
    for p in ring:
        if not out or out[-1] != p:
            out.append(p)
    while len(out) > 1 and out[0] == out[-1]:
        out.pop()
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("codes", nargs="+")
    parser.add_argument("--out", default=os.path.join(os.path.dirname(__file__), "..", "tests", "data"))
    args = parser.parse_args()
    with h5py.File(DCW, "r") as f:
        for code in args.codes:
            rings, (lon0, lat0) = project(polygons(f, code.upper()))
            rings = [r for r in map(clean, rings) if len(r) >= 3]
            path = os.path.join(args.out, "dcw_%s.rings" % code.upper())
            with open(path, "w") as out:
                out.write("# %s from the Digital Chart of the World (gmt-dcw, %s), by scripts/country_rings.py\n" % (code.upper(), DCW))
                out.write("# km, equirectangular around lon %.6f lat %.6f, R = %g km\n" % (lon0, lat0, EARTH_RADIUS_KM))
                out.write("rings %d\n" % len(rings))
                for r in rings:
                    out.write("%d\n" % len(r))
                    for x, y in r:
                        out.write("%r %r\n" % (x, y))
            print("%s: %d rings, %d points" % (path, len(rings), sum(len(r) for r in rings)))


if __name__ == "__main__":
    main()
