"""Checks against shapely/GEOS shared by the tests."""

from __future__ import annotations

import math

import numpy as np
import shapely
from shapely.geometry import Polygon


def extent(geom) -> float:
    x0, y0, x1, y1 = geom.bounds
    return math.hypot(x1 - x0, y1 - y0)


def axis_points(axis) -> np.ndarray:
    """The ``(k, 3)`` points of a MultiLineString Z."""
    return shapely.get_coordinates(axis, include_z=True)


def check_clearances(geom, axis, rel: float = 1e-9) -> None:
    """Every sampled point of the medial axis lies in the geometry and its
    z is its distance to the boundary."""
    pts = axis_points(axis)
    assert len(pts) > 0
    boundary = geom.boundary
    d = shapely.distance(shapely.points(pts[:, :2]), boundary)
    scale = extent(geom)
    assert np.max(np.abs(d - pts[:, 2])) <= rel * scale, np.max(np.abs(d - pts[:, 2]))
    inside = shapely.covers(geom.buffer(rel * scale), shapely.points(pts[:, :2]))
    assert inside.all()


def convex_corners(geom) -> int:
    """Ring vertices whose angle inside the domain is below 180 degrees
    (exactly: integer or short coordinates), the places where the medial
    axis meets the boundary."""
    count = 0
    for poly in getattr(geom, "geoms", [geom]):
        poly = shapely.orient_polygons(poly) if hasattr(shapely, "orient_polygons") else shapely.geometry.polygon.orient(poly)
        for ring in [poly.exterior, *poly.interiors]:
            c = np.asarray(ring.coords)[:-1]
            u, v = c - np.roll(c, 1, axis=0), np.roll(c, -1, axis=0) - c
            # domain on the left of every ring: convex where it turns left
            cross = u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0]
            count += int(np.sum(cross > 0))
    return count


def axis_corner_ends(axis, geom) -> int:
    """Ends of the axis's lines on the boundary (clearance 0)."""
    ends = set()
    for line in axis.geoms:
        c = np.asarray(line.coords)
        for p in (c[0], c[-1]):
            if p[2] == 0:
                ends.add((p[0], p[1]))
    return len(ends)


def check_offset(geom, ours, d: float, tolerance: float, quad_segs: int = 64) -> None:
    """Our offset against GEOS's buffer: valid, and the area between them no
    more than their boundaries times the two chord errors (ours within
    ``tolerance``, GEOS's arcs of ``quad_segs`` per quarter circle)."""
    assert ours.is_valid, shapely.is_valid_reason(ours)
    ref = geom.buffer(d, quad_segs=quad_segs)
    geos_error = abs(d) * (1 - math.cos(math.pi / (4 * quad_segs)))
    allowed = (ours.length + ref.length) * (tolerance + geos_error) + 1e-9 * extent(geom) ** 2
    diff = shapely.symmetric_difference(ours, ref).area
    assert diff <= allowed, (d, diff, allowed)


def square(x: float, y: float, s: float) -> Polygon:
    return Polygon([(x, y), (x + s, y), (x + s, y + s), (x, y + s)])
