"""Draws python/docs/centerlines.svg, the picture of python/README.md: the
countries of examples/data/countries.geojson, each with its medial axis
coloured by clearance (the corner filter at 150 degrees) and its largest
inscribed circle. Needs only shapely and segvoronoi:

    python python/examples/picture.py
"""

from __future__ import annotations

import json
from pathlib import Path

import shapely

import segvoronoi

ROOT = Path(__file__).resolve().parents[2]
SOURCE = ROOT / "examples" / "data" / "countries.geojson"
OUT = ROOT / "python" / "docs" / "centerlines.svg"


def colour(t: float) -> str:
    """Blue (near the boundary) to red (the centre), t in [0, 1]."""
    r, g, b = int(40 + 200 * t), int(90 + 60 * (1 - abs(2 * t - 1))), int(220 - 190 * t)
    return f"#{r:02x}{g:02x}{b:02x}"


def main() -> None:
    features = json.loads(SOURCE.read_text())["features"]
    names = [f["properties"]["name"] for f in features]
    geoms = [shapely.geometry.shape(f["geometry"]) for f in features]
    # one vectorised call for the layer
    axes = segvoronoi.medial_axis(geoms, corner_angle=150, tolerance=0.05)
    circles = segvoronoi.max_inscribed_circle(geoms)

    panel, gap = 300.0, 20.0
    parts = []
    for k, (name, geom, axis, (cx, cy, r)) in enumerate(zip(names, geoms, axes, circles)):
        x0, y0, x1, y1 = geom.bounds
        s = panel / max(x1 - x0, y1 - y0)
        ox = k * (panel + gap) + gap

        def tx(x, y):
            return ox + (x - x0) * s, gap + 30 + (y1 - y) * s  # y up

        def path(ring):
            return "M" + " L".join("%.1f,%.1f" % tx(x, y) for x, y in ring.coords) + " Z"

        polys = getattr(geom, "geoms", [geom])
        d = " ".join(path(r) for p in polys for r in [p.exterior, *p.interiors])
        parts.append(f'<path d="{d}" fill="#eef2e6" stroke="#556" stroke-width="0.8" fill-rule="evenodd"/>')
        for line in axis.geoms:
            c = list(line.coords)
            # a polyline per chain, coloured by its mean clearance
            points = " ".join("%.1f,%.1f" % tx(x, y) for x, y, _ in c)
            mean = sum(z for _, _, z in c) / len(c)
            parts.append(f'<polyline points="{points}" fill="none" stroke="{colour(mean / r)}" stroke-width="1.4"/>')
        px, py = tx(cx, cy)
        parts.append(f'<circle cx="{px:.2f}" cy="{py:.2f}" r="{r * s:.2f}" fill="none" stroke="#c33" stroke-dasharray="4 3"/>')
        parts.append(f'<text x="{ox:.0f}" y="{gap + 16:.0f}" font-family="sans-serif" font-size="15">{name}</text>')
    width = len(geoms) * (panel + gap) + gap
    svg = (
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{width:.0f}" height="{panel + 2 * gap + 60:.0f}">'
        f"<title>Medial axes of a layer of countries, coloured by clearance, with the largest inscribed circles</title>"
        '<rect width="100%" height="100%" fill="white"/>' + "".join(parts) + f'<text x="{gap}" y="{panel + 2 * gap + 50:.0f}" '
        'font-family="sans-serif" font-size="13" fill="#444">segvoronoi.medial_axis(layer.geometry, corner_angle=150): '
        "blue near the border, red at the centre; dashed: max_inscribed_circle</text></svg>\n"
    )
    OUT.parent.mkdir(parents=True, exist_ok=True)
    OUT.write_text(svg)
    print(f"wrote {OUT}")


if __name__ == "__main__":
    main()
