"""The largest inscribed circle against GEOS's maximum_inscribed_circle."""

import math

import numpy as np
import pytest
import shapely
from shapely.geometry import Point, Polygon

import segvoronoi
from checks import extent, square
from conftest import integer_polygon_with_straight_vertices, random_polygon_with_holes


def geos_radius(geom, tol: float) -> float:
    """GEOS's largest inscribed radius, within ``tol`` below the best:
    maximum_inscribed_circle (shapely 2.1), else polylabel per part."""
    if hasattr(shapely, "maximum_inscribed_circle"):
        return shapely.maximum_inscribed_circle(geom, tol).length
    from shapely.ops import polylabel

    return max(p.boundary.distance(polylabel(p, tol)) for p in getattr(geom, "geoms", [geom]))


def check_circle(geom, circle):
    x, y, r = circle
    centre = Point(x, y)
    assert geom.covers(centre)
    scale = extent(geom)
    # touches the boundary: its radius is the centre's clearance
    assert abs(geom.boundary.distance(centre) - r) <= 1e-9 * scale
    # at least as large as GEOS's, which is within its tolerance of the best
    tol = 1e-4 * scale
    geos = geos_radius(geom, tol)
    assert r >= geos - 1e-9 * scale
    assert r <= geos + 2 * tol


@pytest.mark.parametrize("seed", range(10))
def test_random(seed):
    poly = random_polygon_with_holes(seed)
    check_circle(poly, segvoronoi.max_inscribed_circle(poly))


@pytest.mark.parametrize("seed", range(3))
def test_straight_vertices(seed):
    poly = integer_polygon_with_straight_vertices(seed)
    check_circle(poly, segvoronoi.max_inscribed_circle(poly))


def test_glyphs_and_countries(glyphs, countries):
    for geom in [*glyphs.values(), *countries.values()]:
        check_circle(geom, segvoronoi.max_inscribed_circle(geom))


def test_exact_values():
    assert segvoronoi.max_inscribed_circle(square(0, 0, 10)) == (5.0, 5.0, 5.0)
    ring = Polygon(square(0, 0, 10).exterior.coords, [square(4, 4, 2).exterior.coords])
    assert math.isclose(segvoronoi.max_inscribed_circle(ring)[2], 8 - 4 * math.sqrt(2), rel_tol=1e-12)


def test_none_without_polygons():
    assert segvoronoi.max_inscribed_circle(shapely.LineString([(0, 0), (1, 1)])) is None
    rows = segvoronoi.max_inscribed_circle([shapely.Point(0, 0), square(0, 0, 2)])
    assert np.isnan(rows[0]).all() and rows[1].tolist() == [1.0, 1.0, 1.0]
