"""Offsets against GEOS's buffer: valid polygons, and the area between
ours and GEOS's within the two chord errors."""

import math

import numpy as np
import pytest
import shapely
from shapely.geometry import LineString, MultiPoint, Point, Polygon

import segvoronoi
from checks import check_offset, extent, square
from conftest import integer_polygon_with_straight_vertices, random_polygon_with_holes


@pytest.mark.parametrize("seed", range(8))
def test_random_polygons(seed):
    poly = random_polygon_with_holes(seed)
    distances = [-15.0, -7.3, -2.1, -0.4, 0.6, 3.3, 12.0, 40.0]
    tol = 1e-3
    results = segvoronoi.offsets(poly, distances, tolerance=tol)
    assert len(results) == len(distances)
    for d, ours in zip(distances, results):
        check_offset(poly, ours, d, tol)


@pytest.mark.parametrize("seed", range(3))
def test_straight_vertices(seed):
    poly = integer_polygon_with_straight_vertices(seed)
    for d, ours in zip([-50.0, 25.0], segvoronoi.offsets(poly, [-50.0, 25.0], tolerance=1e-2)):
        check_offset(poly, ours, d, 1e-2)


def test_glyphs(glyphs):
    for glyph in glyphs.values():
        e = extent(glyph)
        distances = [-0.02 * e, -0.005 * e, 0.01 * e, 0.05 * e]
        tol = 1e-5 * e
        for d, ours in zip(distances, segvoronoi.offsets(glyph, distances, tolerance=tol)):
            check_offset(glyph, ours, d, tol)


def test_countries(countries):
    for country in countries.values():
        e = extent(country)
        distances = [-0.03 * e, 0.02 * e]
        tol = 1e-5 * e
        for d, ours in zip(distances, segvoronoi.offsets(country, distances, tolerance=tol)):
            check_offset(country, ours, d, tol)


def test_one_equals_many():
    poly = random_polygon_with_holes(1)
    many = segvoronoi.offsets(poly, [-3.0, 5.0], tolerance=1e-3)
    assert shapely.equals_exact(segvoronoi.offset(poly, 5.0, tolerance=1e-3), many[1], 0)


def test_exact_areas():
    ring = Polygon(square(0, 0, 10).exterior.coords, [square(4, 4, 2).exterior.coords])
    shrunk, grown = segvoronoi.offsets(ring, [-1, 1], tolerance=1e-7)
    assert len(shrunk.geoms) == 1 and len(shrunk.geoms[0].interiors) == 1
    assert math.isclose(shrunk.area, 64 - (4 + 8 + math.pi), rel_tol=1e-8)
    assert math.isclose(grown.area, 100 + 40 + math.pi, rel_tol=1e-8)
    assert len(grown.geoms[0].interiors) == 0  # the hole closed


def test_lines_and_points_only_grow():
    line = LineString([(0, 0), (10, 0), (10, 5)])
    grown = segvoronoi.offset(line, 1.0, tolerance=1e-4)
    check_offset(line, grown, 1.0, 1e-4)
    # a negative distance of a line is empty, as buffer's is
    assert segvoronoi.offset(line, -1.0).is_empty and line.buffer(-1.0).is_empty
    pts = MultiPoint([(0, 0), (3, 0)])
    check_offset(pts, segvoronoi.offset(pts, 2.0, tolerance=1e-5), 2.0, 1e-5)
    disk = segvoronoi.offset(Point(1, 1), 1.0, tolerance=1e-8)
    assert math.isclose(disk.area, math.pi, rel_tol=1e-7)


def test_shrunk_away_is_empty():
    assert segvoronoi.offset(square(0, 0, 2), -1.5).is_empty
    out = segvoronoi.offsets([square(0, 0, 2), square(0, 0, 10)], [-1.5, 1.0])
    assert out.shape == (2, 2) and out[0, 0].is_empty and not out[1, 0].is_empty
