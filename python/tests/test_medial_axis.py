"""The medial axis against shapely/GEOS: every sampled point inside, its z
the distance to the boundary, a branch to every convex corner, and the
largest z the inscribed circle's radius."""

import numpy as np
import pytest
import shapely
from shapely.geometry import MultiPolygon, Polygon

import segvoronoi
from checks import axis_corner_ends, axis_points, check_clearances, convex_corners, extent, square
from conftest import integer_polygon_with_straight_vertices, random_polygon_with_holes


def test_rectangle_exact():
    axis = segvoronoi.medial_axis(Polygon([(0, 0), (4, 0), (4, 2), (0, 2)]))
    assert axis.has_z and len(axis.geoms) == 5
    assert sorted(map(tuple, axis_points(axis).tolist()))[-1] == (4.0, 2.0, 0.0)
    middle = [l for l in axis.geoms if all(z == 1 for z in np.asarray(l.coords)[:, 2])]
    assert len(middle) == 1 and sorted(middle[0].coords) == [(1, 1, 1), (3, 1, 1)]


@pytest.mark.parametrize("seed", range(12))
def test_random_polygons_with_holes(seed):
    poly = random_polygon_with_holes(seed)
    axis = segvoronoi.medial_axis(poly)
    check_clearances(poly, axis)
    # the axis reaches every convex corner once (random corners are never straight)
    assert axis_corner_ends(axis, poly) == convex_corners(poly)
    # and it is connected around each hole: one component for the polygon
    assert shapely.get_num_geometries(shapely.line_merge(shapely.union_all(shapely.force_2d(axis)))) >= 1
    assert shapely.union_all(shapely.force_2d(axis)).is_valid


@pytest.mark.parametrize("seed", range(6))
def test_straight_vertices(seed):
    poly = integer_polygon_with_straight_vertices(seed)
    axis = segvoronoi.medial_axis(poly)
    check_clearances(poly, axis)
    # straight (180 degree) vertices get no branch; convex ones one each
    assert axis_corner_ends(axis, poly) == convex_corners(poly)


def test_glyphs(glyphs):
    assert len(glyphs) >= 3
    for name, glyph in glyphs.items():
        axis = segvoronoi.medial_axis(glyph)
        check_clearances(glyph, axis)
        assert axis_corner_ends(axis, glyph) == convex_corners(glyph), name
        # the corner filter drops the spurs of flattened curves, never the
        # cycles around the counters
        filtered = segvoronoi.medial_axis(glyph, corner_angle=150)
        check_clearances(glyph, filtered)
        assert len(filtered.geoms) < len(axis.geoms)
        assert filtered.length < axis.length


def test_countries(countries):
    assert len(countries) >= 5
    for name, country in countries.items():
        axis = segvoronoi.medial_axis(country)
        check_clearances(country, axis, rel=1e-8)
        x, y, r = segvoronoi.max_inscribed_circle(country)
        assert abs(axis_points(axis)[:, 2].max() - r) <= 1e-9 * extent(country), name


def test_prune_spurs_removes_leaves_only():
    poly = random_polygon_with_holes(3)
    full = segvoronoi.medial_axis(poly)
    pruned = segvoronoi.medial_axis(poly, prune_spurs=2.0)
    check_clearances(poly, pruned)
    assert pruned.length < full.length
    # what is left is part of the full axis
    assert shapely.force_2d(full).buffer(1e-9 * extent(poly)).covers(shapely.force_2d(pruned))


def test_tolerance_controls_sampling():
    circle_like = Polygon(shapely.Point(0, 0).buffer(10, quad_segs=2).exterior.coords)
    poly = shapely.difference(square(-20, -20, 40), circle_like)
    coarse = segvoronoi.medial_axis(poly, tolerance=1.0)
    fine = segvoronoi.medial_axis(poly, tolerance=1e-4)
    assert len(axis_points(fine)) > len(axis_points(coarse))
    check_clearances(poly, fine)


def test_lines_and_points_without_domain():
    # without polygons the axis is every edge between two sites (rays cut)
    axis = segvoronoi.medial_axis(shapely.MultiPoint([(0, 0), (2, 0), (1, 2), (1, 0.7)]))
    assert len(axis.geoms) == 3
    assert all(abs(z - np.hypot(x - 1, y - 0.7)) < 1e-12 for x, y, z in axis_points(axis))


def test_multipolygon_and_collection():
    a, b = square(0, 0, 2), square(5, 0, 4)
    axis = segvoronoi.medial_axis(MultiPolygon([a, b]))
    check_clearances(MultiPolygon([a, b]), axis)
    both = segvoronoi.medial_axis(shapely.GeometryCollection([a, b]))
    assert shapely.equals_exact(axis, both, 0)


def test_overlapping_glyphs_split():
    """Composite glyphs whose rings overlap: refused as they are, and with
    split_crossings the axis of their even-odd region (every point at its
    distance from the boundary, up to the snapping, a pixel of 2^-46)."""
    from conftest import DATA, even_odd, read_rings

    paths = sorted(DATA.glob("overlap_*.rings"))
    assert len(paths) >= 3
    refused = 0
    for path in paths:
        rings = read_rings(path)
        region = even_odd(rings)
        raw = shapely.MultiPolygon([Polygon(r) for r in rings])  # rings as given, overlapping
        try:
            segvoronoi.medial_axis(raw)
        except segvoronoi.IntersectingError as e:
            # the indices count the rings' segments in order (closing
            # segment last); the point lies on both
            segments = [
                shapely.LineString([c[k], c[(k + 1) % len(c)]])
                for poly in raw.geoms
                for c in [np.asarray(poly.exterior.coords)[:-1]]
                for k in range(len(c))
            ]
            assert len(e.indices) == 2 and e.point is not None
            p = shapely.Point(e.point)
            assert all(segments[i].distance(p) <= 1e-9 * extent(region) for i in e.indices), (e, path)
            refused += 1
        axis = segvoronoi.medial_axis(raw, split_crossings=True)
        check_clearances(region, axis, rel=1e-8)
    assert refused >= 3
