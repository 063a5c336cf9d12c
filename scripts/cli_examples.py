#!/usr/bin/env python3
"""Writes the CLI's example inputs in examples/data/ from the test data.

    python3 scripts/cli_examples.py [OUT_DIR]    (default examples/data)

From tests/data/*.rings (km, equirectangular around a centre named in the
file's header; see tests/data/README.md):
  glyph_B.wkt         the glyph B of DejaVu Sans, one WKT POLYGON (font units)
  luxembourg.wkt      a country, WKT POLYGON, km
  switzerland.ewkt    a country as PostGIS writes it: SRID=4326, lon/lat degrees
  countries.geojson   Luxembourg, Lesotho and Switzerland side by side, a
                      FeatureCollection (km, each moved so they do not overlap)
  road.geojson        a piece of a curved road 7 m wide with a traffic island
                      (a hole) and two bollards (points), a Feature, metres
Every ring is written closed (first point repeated), outer rings first.
"""
import json
import math
import os
import re
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
DATA = os.path.join(ROOT, "tests", "data")


def read_rings(name):
    """The rings of a .rings file and its header's centre (lon, lat) if any."""
    text = open(os.path.join(DATA, name)).read()
    centre = re.search(r"around lon ([-0-9.]+) lat ([-0-9.]+)", text)
    words = " ".join(l for l in text.splitlines() if not l.lstrip().startswith("#")).split()
    assert words[0] == "rings"
    k, rings = 2, []
    for _ in range(int(words[1])):
        n = int(words[k])
        k += 1
        rings.append([(float(words[k + 2 * i]), float(words[k + 2 * i + 1])) for i in range(n)])
        k += 2 * n
    return rings, (float(centre.group(1)), float(centre.group(2))) if centre else None


def area(ring):
    return sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(ring, ring[1:] + ring[:1])) / 2


def closed(ring):
    return list(ring) + [ring[0]]


def oriented(ring, ccw):
    """RFC 7946: outer rings counter-clockwise, holes clockwise."""
    return ring if (area(ring) > 0) == ccw else ring[::-1]


def num(v):
    return repr(round(v, 6)) if isinstance(v, float) else repr(v)


def wkt_ring(ring):
    return "(" + ", ".join(f"{num(x)} {num(y)}" for x, y in closed(ring)) + ")"


def polygon(rings):
    """Rings as one polygon: the largest first, then the others (holes or,
    for the even-odd domain, islands: the CLI reads them alike)."""
    return sorted(rings, key=lambda r: -abs(area(r)))


def geojson_polygon(rings):
    rings = polygon(rings)
    return [[list(p) for p in closed(oriented(r, i == 0))] for i, r in enumerate(rings)]


def to_lonlat(ring, centre):
    lon0, lat0 = centre
    r = 6371.0
    return [(lon0 + math.degrees(x / (r * math.cos(math.radians(lat0)))), lat0 + math.degrees(y / r)) for x, y in ring]


def moved(rings, dx, dy):
    return [[(x + dx, y + dy) for x, y in r] for r in rings]


def road():
    """A road 7 m wide along a gentle S curve 120 m long, with a traffic
    island (a hole) in its widening and two bollards."""
    centre = [(t, 12 * math.sin(t / 120 * 2 * math.pi)) for t in [i * 4.0 for i in range(31)]]
    left, right = [], []
    for i, (x, y) in enumerate(centre):
        a, b = centre[max(i - 1, 0)], centre[min(i + 1, len(centre) - 1)]
        dx, dy = b[0] - a[0], b[1] - a[1]
        n = math.hypot(dx, dy)
        # 3.5 m each side, widening to 7 m around the island at x = 60
        half = 3.5 + 3.5 * math.exp(-((x - 60) / 14) ** 2)
        left.append((x - dy / n * half, y + dx / n * half))
        right.append((x + dy / n * half, y - dx / n * half))
    outer = right + left[::-1]
    island = [(60 + 8 * math.cos(t * math.pi / 8), 2.0 * math.sin(t * math.pi / 8)) for t in range(16)]
    island = [(x, y + 12 * math.sin(x / 120 * 2 * math.pi)) for x, y in island]
    return [outer, island], [(20.0, 12 * math.sin(20 / 120 * 2 * math.pi) + 1.0), (100.0, 12 * math.sin(100 / 120 * 2 * math.pi) - 1.0)]


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "examples", "data")
    os.makedirs(out, exist_ok=True)

    def write(name, text):
        with open(os.path.join(out, name), "w") as f:
            f.write(text)

    glyph, _ = read_rings("glyph_B.rings")
    write("glyph_B.wkt", "POLYGON (" + ", ".join(wkt_ring(r) for r in polygon(glyph)) + ")\n")
    lu, _ = read_rings("dcw_LU.rings")
    write("luxembourg.wkt", "POLYGON (" + ", ".join(wkt_ring(r) for r in polygon(lu)) + ")\n")
    ch, ch_centre = read_rings("dcw_CH.rings")
    write("switzerland.ewkt", "SRID=4326;POLYGON (" + ", ".join(wkt_ring(to_lonlat(r, ch_centre)) for r in polygon(ch)) + ")\n")
    ls, _ = read_rings("dcw_LS.rings")
    features = []
    for name, rings, dx in [("Luxembourg", lu, 0.0), ("Lesotho", ls, 250.0), ("Switzerland", ch, 600.0)]:
        features.append({
            "type": "Feature",
            "properties": {"name": name, "units": "km"},
            "geometry": {"type": "Polygon", "coordinates": geojson_polygon(moved(rings, dx, 0.0))},
        })
    write("countries.geojson", json.dumps({"type": "FeatureCollection", "features": features}) + "\n")
    rings, bollards = road()
    geometries = [{"type": "Polygon", "coordinates": geojson_polygon(rings)}] + [
        {"type": "Point", "coordinates": [round(x, 6), round(y, 6)]} for x, y in bollards]
    write("road.geojson", json.dumps({
        "type": "Feature",
        "properties": {"name": "road piece with a traffic island and two bollards", "units": "m"},
        "geometry": {"type": "GeometryCollection", "geometries": geometries},
    }) + "\n")


if __name__ == "__main__":
    main()
