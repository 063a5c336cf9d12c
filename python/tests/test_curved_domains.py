"""Polygons bounded by circular arcs (``segvoronoi.CurvedPolygon``, issue
32) against references computed here, apart from the library: the same
rings densified to 2048 points per full circle and handed to shapely/GEOS
(distances to the boundary, buffers), and closed forms where there are
some (a slot's inscribed circle is its half-width).

The densified rings are inscribed in the arcs, so they are off by at most
the sagitta of one chord, ``R * (1 - cos(pi / 2048)) ~ 1.2e-6 R``: the
tolerances below are that, GEOS's own arcs (``quad_segs``) and our chords
(``tolerance``), each stated where it is used.

The shapes are nobody's tuned inputs: an oblique slot, a rounded
rectangle off the origin with a round hole, an L filleted at every
corner (its inner corner by a concave arc), with radii and positions
picked as odd decimals."""

from __future__ import annotations

import math
import pickle

import numpy as np
import pytest
import shapely
from shapely.geometry import Polygon

import segvoronoi
from conftest import even_odd
from segvoronoi import CurvedPolygon
from test_arcs import arc_geometry

PER_CIRCLE = 2048  # points of the reference per full turn
QUAD_SEGS = 512  # GEOS's buffer arcs, per quarter circle


def slot(c1, c2, r: float) -> np.ndarray:
    """A slot of half-width ``r`` about the segment ``c1``-``c2``,
    counter-clockwise: a side, a half circle about ``c2``, a side, a half
    circle about ``c1``."""
    c1, c2 = np.asarray(c1, dtype=float), np.asarray(c2, dtype=float)
    u = (c2 - c1) / np.hypot(*(c2 - c1))
    n = np.array([-u[1], u[0]])
    return np.array([[*(c1 - r * n), 0.0], [*(c2 - r * n), 1.0], [*(c2 + r * n), 0.0], [*(c1 + r * n), 1.0]])


def filleted(vertices, radii) -> np.ndarray:
    """A polygon's vertices with each corner ``k`` rounded by a tangent arc
    of radius ``radii[k]`` (counter-clockwise where the ring turns left,
    clockwise where it turns right)."""
    v = np.asarray(vertices, dtype=float)
    rows = []
    for k in range(len(v)):
        p, q, s = v[k - 1], v[k], v[(k + 1) % len(v)]
        a, b = (p - q) / np.hypot(*(p - q)), (s - q) / np.hypot(*(s - q))
        half = 0.5 * math.acos(float(np.clip(a @ b, -1, 1)))  # half the angle at the corner
        t = radii[k] / math.tan(half)
        turn = math.copysign(1.0, float(-a[0] * b[1] + a[1] * b[0]))  # left turn: +1
        rows.append([*(q + t * a), turn * math.tan((math.pi - 2 * half) / 4)])
        rows.append([*(q + t * b), 0.0])
    return np.array(rows)


def circle(centre, r: float) -> np.ndarray:
    """A circle as two half circles, counter-clockwise."""
    x, y = centre
    return np.array([[x - r, y, 1.0], [x + r, y, 1.0]])


def rounded_rectangle(x0: float, y0: float, w: float, h: float, r: float) -> np.ndarray:
    return filleted([(x0, y0), (x0 + w, y0), (x0 + w, y0 + h), (x0, y0 + h)], [r] * 4)


SLOTS = {
    "oblique": slot((0.3, -1.2), (5.13, 2.9), 0.731),
    "steep": slot((-2.71, 0.05), (-2.43, 7.9), 1.337),
    "small": slot((1e3 + 0.113, -7.7e2), (1e3 + 0.419, -7.7e2 + 0.0071), 0.0093),
}

SHAPES = {
    "slot": CurvedPolygon(SLOTS["oblique"]),
    "rounded with a hole": CurvedPolygon(
        rounded_rectangle(-3.1, 1.4, 7.3, 4.1, 0.9), holes=[circle((-0.93, 3.17), 0.83)]
    ),
    "filleted L": CurvedPolygon(
        filleted([(0.2, 0.1), (6.3, 0.1), (6.3, 2.2), (2.1, 2.2), (2.1, 5.9), (0.2, 5.9)], [0.55, 0.4, 0.61, 0.7, 0.35, 0.47])
    ),
}


def densify(ring: np.ndarray) -> np.ndarray:
    """A ring of rows x, y, bulge as points: each arc by points on its
    circle, ``PER_CIRCLE`` per full turn (the ends exact)."""
    out = []
    for k, (x, y, bulge) in enumerate(ring):
        out.append((x, y))
        if bulge == 0:
            continue
        nx, ny = ring[(k + 1) % len(ring)][:2]
        (cx, cy), r, _, _ = arc_geometry((x, y, nx, ny, bulge))
        sweep = 4 * math.atan(bulge)
        steps = max(2, math.ceil(abs(sweep) / (2 * math.pi) * PER_CIRCLE))
        start = math.atan2(y - cy, x - cx)
        for t in np.arange(1, steps) / steps:
            out.append((cx + r * math.cos(start + t * sweep), cy + r * math.sin(start + t * sweep)))
    return np.array(out)


def reference(shape: CurvedPolygon):
    """The shape as a valid shapely geometry of its densified rings (even-odd)."""
    return even_odd([densify(r) for r in shape.rings])


def sagitta(shape: CurvedPolygon, d: float = 0.0) -> float:
    """The largest gap between an arc of the shape (grown or shrunk by
    ``d``) and the chords of its reference: ``R (1 - cos(pi / PER_CIRCLE))``."""
    radii = [arc_geometry((*r[k, :2], *r[(k + 1) % len(r), :2], r[k, 2]))[1] for r in shape.rings for k in range(len(r)) if r[k, 2]]
    return (max(radii, default=0.0) + abs(d)) * (1 - math.cos(math.pi / PER_CIRCLE))


def scale(geom) -> float:
    x0, y0, x1, y1 = geom.bounds
    return math.hypot(x1 - x0, y1 - y0)


@pytest.mark.parametrize("name", sorted(SLOTS))
def test_a_slots_largest_inscribed_circle_is_its_half_width(name):
    ring = SLOTS[name]
    x, y, r = segvoronoi.max_inscribed_circle(CurvedPolygon(ring))
    half_width = 0.5 * math.hypot(*(ring[3, :2] - ring[0, :2]))
    assert abs(r - half_width) <= 1e-12 * half_width, (r, half_width)
    # its centre is on the segment between the half circles' centres
    c1, c2 = 0.5 * (ring[0, :2] + ring[3, :2]), 0.5 * (ring[1, :2] + ring[2, :2])
    u = (c2 - c1) / np.hypot(*(c2 - c1))
    w = np.array([x, y]) - c1
    assert abs(float(u[0] * w[1] - u[1] * w[0])) <= 1e-12 * np.hypot(*(c2 - c1)) + 1e-12 * half_width
    assert -1e-9 <= float(u @ (np.array([x, y]) - c1)) <= np.hypot(*(c2 - c1)) + 1e-9


@pytest.mark.parametrize("name", sorted(SHAPES))
def test_largest_inscribed_circle_against_the_densified_boundary(name):
    shape = SHAPES[name]
    ref = reference(shape)
    x, y, r = segvoronoi.max_inscribed_circle(shape)
    slack = sagitta(shape) + 1e-9 * scale(ref)
    centre = shapely.Point(x, y)
    assert ref.contains(centre)
    # its clearance is its distance to the boundary
    assert abs(ref.boundary.distance(centre) - r) <= slack
    # and no circle of GEOS's (a search to 1e-6) is larger
    if hasattr(shapely, "maximum_inscribed_circle"):
        geos = shapely.maximum_inscribed_circle(ref, 1e-6).length
        assert r >= geos - 1e-6 - slack, (r, geos)


@pytest.mark.parametrize("name", sorted(SHAPES))
def test_medial_axis_z_is_the_distance_to_the_boundary_and_inside(name):
    shape = SHAPES[name]
    ref = reference(shape)
    tolerance = 1e-4
    axis = segvoronoi.medial_axis(shape, tolerance=tolerance)
    pts = shapely.get_coordinates(axis, include_z=True)
    assert len(axis.geoms) >= 1 and len(pts) >= (2 if name == "slot" else 20)
    slack = sagitta(shape) + 1e-9 * scale(ref)
    d = shapely.distance(shapely.points(pts[:, :2]), ref.boundary)
    assert np.max(np.abs(d - pts[:, 2])) <= slack, np.max(np.abs(d - pts[:, 2]))
    assert shapely.covers(ref.buffer(slack), shapely.points(pts[:, :2])).all()
    # no point repeats the one before it
    for line in axis.geoms:
        c = np.asarray(line.coords)
        assert (np.abs(np.diff(c, axis=0)).max(axis=1) > 0).all()
    # the chords between samples stay within the tolerance of the axis:
    # their middles are (nearly) as far from the boundary as the ends say
    for line in axis.geoms:
        c = np.asarray(line.coords)
        mid = 0.5 * (c[1:] + c[:-1])
        dm = shapely.distance(shapely.points(mid[:, :2]), ref.boundary)
        assert np.max(np.abs(dm - mid[:, 2])) <= 2 * tolerance + slack


DISTANCES = [-0.55, -0.3, -0.05, 0.07, 0.4, 1.3]


@pytest.mark.parametrize("name", sorted(SHAPES))
def test_offset_areas_against_the_buffer_of_the_densified_shape(name):
    shape = SHAPES[name]
    ref = reference(shape)
    tolerance = 1e-6
    ours = segvoronoi.offsets(shape, DISTANCES, tolerance=tolerance)
    for d, region in zip(DISTANCES, ours):
        assert region.is_valid, shapely.is_valid_reason(region)
        want = ref.buffer(d, quad_segs=QUAD_SEGS)
        geos = abs(d) * (1 - math.cos(math.pi / (4 * QUAD_SEGS)))
        # the two boundaries are apart by our chords, the reference's and GEOS's
        allowed = (region.length + want.length) * (tolerance + sagitta(shape, d) + geos)
        assert abs(region.area - want.area) <= allowed, (d, region.area, want.area, allowed)
        assert shapely.symmetric_difference(region, want).area <= allowed, d


def reverse(ring: np.ndarray) -> np.ndarray:
    """The same ring walked the other way: the piece from row ``k + 1`` to
    row ``k`` has the bulge of row ``k``, negated."""
    xy = ring[::-1, :2]
    bulge = -np.roll(ring[:, 2], 1)[::-1]
    return np.column_stack([xy, bulge])


def mirror(ring: np.ndarray) -> np.ndarray:
    """The ring mirrored in the y axis: every arc turns the other way."""
    return np.column_stack([-ring[:, 0], ring[:, 1], -ring[:, 2]])


@pytest.mark.parametrize("name", sorted(SHAPES))
def test_reversed_and_mirrored_rings_give_the_same_areas(name):
    shape = SHAPES[name]
    distances = [-0.3, 0.4]
    want = [p.area for p in segvoronoi.offsets(shape, distances, tolerance=1e-7)]
    for change in (reverse, mirror, lambda r: reverse(mirror(r))):
        rings = [change(r) for r in shape.rings]
        other = CurvedPolygon(rings[0], rings[1:])
        got = [p.area for p in segvoronoi.offsets(other, distances, tolerance=1e-7)]
        assert np.allclose(got, want, rtol=1e-9, atol=0), (got, want)
        assert abs(segvoronoi.max_inscribed_circle(other)[2] - segvoronoi.max_inscribed_circle(shape)[2]) <= 1e-12 * scale(
            reference(shape)
        )


def input_arcs(shape: CurvedPolygon):
    """Centre and radius of every arc of the shape."""
    return [
        arc_geometry((*r[k, :2], *r[(k + 1) % len(r), :2], r[k, 2]))[:2] for r in shape.rings for k in range(len(r)) if r[k, 2]
    ]


@pytest.mark.parametrize("name", sorted(SHAPES))
def test_exact_pieces_keep_the_arcs(name):
    shape = SHAPES[name]
    size = scale(reference(shape))
    arcs = input_arcs(shape)
    corners = np.concatenate([r[:, :2] for r in shape.rings])
    for d, pieces, region in zip(
        DISTANCES, segvoronoi.offset_pieces(shape, DISTANCES), segvoronoi.offsets(shape, DISTANCES, tolerance=1e-7)
    ):
        assert isinstance(pieces, segvoronoi.OffsetPieces) and pieces.distance == d
        assert len(pieces.loops) == len(pieces.holes) == len(pieces.parents) > 0
        rows = np.concatenate(pieces.loops)
        assert rows.shape[1] == len(segvoronoi.PIECE_COLUMNS) == 9
        arc_rows = rows[rows[:, 0] == 1]
        assert len(arc_rows) > 0
        for _, x0, y0, x1, y1, cx, cy, radius, bulge in arc_rows:
            # concentric with an input arc at R + |d| or R - |d|, or about a
            # corner (a vertex of the rings) at |d|
            near = [abs(radius - (r + s * abs(d))) for (ax, ay), r in arcs for s in (1, -1) if math.hypot(cx - ax, cy - ay) <= 1e-9 * size]
            at_corner = np.min(np.hypot(*(corners - [cx, cy]).T)) <= 1e-12 * size and abs(radius - abs(d)) <= 1e-12 * size
            assert (near and min(near) <= 1e-9 * size) or at_corner, (d, cx, cy, radius)
            # the ends are on the circle; the bulge is that of the arc between them
            assert abs(math.hypot(x0 - cx, y0 - cy) - radius) <= 1e-9 * size
            assert abs(math.hypot(x1 - cx, y1 - cy) - radius) <= 1e-9 * size
            if math.hypot(x1 - x0, y1 - y0) <= 1e-12 * size:
                continue  # a piece of no length where the loop passes a tangent join
            (bx, by), br, _, _ = arc_geometry((x0, y0, x1, y1, bulge))
            assert math.hypot(bx - cx, by - cy) <= 1e-7 * size and abs(br - radius) <= 1e-7 * size
        lines = rows[rows[:, 0] == 0]
        assert np.isnan(lines[:, 5:8]).all() and (lines[:, 8] == 0).all()
        for loop in pieces.loops:  # each piece starts where the one before ends
            assert np.array_equal(loop[:, 1:3], np.roll(loop[:, 3:5], 1, axis=0))
        # the loops as LWPOLYLINE rings bound the same region
        again = even_odd([densify(r) for r in pieces.bulged_rings()])
        assert abs(again.area - region.area) <= region.length * (sagitta(shape, d) + 1e-7), (d, again.area, region.area)
        round_trip = pieces.curved_polygon()
        assert isinstance(round_trip, CurvedPolygon) and len(round_trip.rings) == len(pieces.loops)


def test_the_slots_pieces_are_its_sides_and_half_circles():
    shape = CurvedPolygon(SLOTS["oblique"])
    half_width = 0.731
    for d in (-0.25, 0.25):
        (pieces,) = segvoronoi.offset_pieces(shape, [d])
        (loop,) = pieces.loops
        # less the pieces of no length where the loop passes a tangent join
        # (the point between a side and its half circle), at most one each
        length = np.hypot(loop[:, 3] - loop[:, 1], loop[:, 4] - loop[:, 2])
        assert (length <= 1e-12).sum() <= 4
        loop = loop[length > 1e-12]
        assert sorted(loop[:, 0].tolist()) == [0, 0, 1, 1]
        arcs = loop[loop[:, 0] == 1]
        assert np.allclose(arcs[:, 7], half_width + d, rtol=0, atol=1e-12)
        assert np.allclose(arcs[:, 8], 1.0, rtol=0, atol=1e-12)  # half circles, counter-clockwise
        assert pieces.holes.tolist() == [False] and pieces.parents.tolist() == [-1]


def test_a_round_hole_offset_outward_has_a_hole_loop_of_a_smaller_circle():
    shape = SHAPES["rounded with a hole"]
    (pieces,) = segvoronoi.offset_pieces(shape, [0.3])
    assert pieces.holes.tolist() == [False, True] and pieces.parents.tolist() == [-1, 0]
    hole = pieces.loops[1]
    assert (hole[:, 0] == 1).all() and np.allclose(hole[:, 7], 0.83 - 0.3, rtol=0, atol=1e-12)
    assert np.allclose(hole[:, 5:7], [-0.93, 3.17], rtol=0, atol=1e-12)
    assert (hole[:, 8] < 0).all()  # a hole runs clockwise


def test_many_curved_polygons_and_shapely_geometries_at_once():
    geoms = [SHAPES["slot"], shapely.box(0, 0, 4, 2), None, SHAPES["filleted L"]]
    circles = segvoronoi.max_inscribed_circle(geoms, threads=2)
    assert circles.shape == (4, 3) and np.isnan(circles[2]).all()
    for g, row in zip(geoms, circles):
        if g is not None:
            assert np.array_equal(row, segvoronoi.max_inscribed_circle(g))
    axes = segvoronoi.medial_axis(geoms, tolerance=1e-3)
    assert [a.equals_exact(segvoronoi.medial_axis(g, tolerance=1e-3), 0) for a, g in zip(axes, geoms) if g is not None] == [True] * 3
    table = segvoronoi.offsets(geoms, [-0.1, 0.2], tolerance=1e-4)
    assert table.shape == (4, 2) and table[2, 0].is_empty
    assert table[3, 1].equals_exact(segvoronoi.offset(geoms[3], 0.2, tolerance=1e-4), 0)
    pieces = segvoronoi.offset_pieces(geoms, [-0.1, 0.2])
    assert pieces.shape == (4, 2) and pieces[2, 1].loops == []
    for k in (0, 1, 3):
        for j, one in enumerate(segvoronoi.offset_pieces(geoms[k], [-0.1, 0.2])):
            assert all(np.array_equal(a, b, equal_nan=True) for a, b in zip(pieces[k, j].loops, one.loops))


def test_a_diagram_of_a_curved_polygon():
    shape = SHAPES["rounded with a hole"]
    d = segvoronoi.voronoi(geometry=shape)
    d.validate()
    assert d.has_domain and (d.site_kinds == 2).sum() == 6  # four corners, two half circles
    # cut off by the corner arc at (-3.1, 1.4), in the hole, inside
    assert d.locate([[-3.0, 1.5], [-0.93, 3.17], [-2.9, 1.9]]).tolist() == [-1, -1, 1]
    assert d.max_inscribed_circle() == segvoronoi.max_inscribed_circle(shape)
    assert d.medial_axis(tolerance=1e-3).equals_exact(segvoronoi.medial_axis(shape, tolerance=1e-3), 0)
    mine, theirs = d.offset_pieces([-0.2])[0], segvoronoi.offset_pieces(shape, [-0.2])[0]
    assert all(np.array_equal(a, b, equal_nan=True) for a, b in zip(mine.loops, theirs.loops))
    # an obstacle arc inside comes first among the arcs
    e = segvoronoi.voronoi(geometry=shape, arcs=[[1.5, 4.0, 2.5, 4.0, 0.5]])
    assert e.site_arc_index[e.site_kinds == 2].tolist() == [0, 1, 2, 3, 4, 5, 6]


def test_curved_polygons_pickle_and_compare():
    shape = SHAPES["rounded with a hole"]
    again = pickle.loads(pickle.dumps(shape))
    assert again == shape and again is not shape and len(again.holes) == 1
    assert "2 rings" in repr(shape)
    assert CurvedPolygon(shape.shell) != shape


SQUARE = [[0, 0, 0], [10, 0, 0], [10, 10, 0], [0, 10, 0]]


def test_a_ring_of_two_vertices_without_an_arc_is_refused_naming_it():
    with pytest.raises(segvoronoi.InvalidPolygonError) as info:
        segvoronoi.max_inscribed_circle(CurvedPolygon(SQUARE, holes=[circle((3, 3), 1), [[4, 4, 0], [6, 4, 0]]]))
    assert info.value.indices == (0, 2) and "ring 2" in info.value.message


@pytest.mark.parametrize("bad", [math.nan, math.inf], ids=["nan", "inf"])
def test_a_non_finite_bulge_is_refused_naming_ring_and_vertex(bad):
    hole = [[2, 2, 0], [5, 2, bad], [5, 5, 0]]
    with pytest.raises(segvoronoi.InvalidCoordinateError) as info:
        segvoronoi.offsets(CurvedPolygon(SQUARE, holes=[hole]), [-1])
    assert info.value.indices == (0, 1, 1) and "ring 1: vertex 1" in info.value.message


def test_a_bulge_that_makes_no_arc_is_refused_naming_ring_and_vertex():
    # (a bulge of 1e300 makes a circle beyond the doubles)
    with pytest.raises(segvoronoi.InvalidArcError) as info:
        segvoronoi.medial_axis(CurvedPolygon([[0, 0, 0], [1e10, 0, 0], [1e10, 1e10, 1e300]]))
    assert info.value.indices == (0, 0, 2) and "vertex 2" in info.value.message
    # a bulge of 1e-300 is straight to within the rounding of its centre:
    # that side is a segment, and the triangle is the plain one
    curved = segvoronoi.max_inscribed_circle(CurvedPolygon([[0, 0, 0], [1e10, 0, 0], [1e10, 1e10, 1e-300]]))
    plain = segvoronoi.max_inscribed_circle(shapely.Polygon([[0, 0], [1e10, 0], [1e10, 1e10]]))
    assert np.allclose(curved, plain, rtol=1e-12)


def test_crossing_pieces_are_named_by_ring_and_vertex():
    # a hole's side runs out through the square's right side
    with pytest.raises(segvoronoi.IntersectingError) as info:
        segvoronoi.max_inscribed_circle(CurvedPolygon(SQUARE, holes=[[[4, 3, 0], [12, 3, 0], [12, 4, 0], [4, 4, 0]]]))
    m = info.value.message
    assert "vertex 1 of polygon 0, ring 0" in m and "vertex 0 of polygon 0, ring 1" in m, m
    assert info.value.point == (10.0, 3.0)
    # an arc of a hole (after a repeated row: the caller's row is named)
    hole = [[4, 3, 0], [4, 3, 0], [7, 3, 0.3], [12, 4, 0], [4, 4, 0]]
    with pytest.raises(segvoronoi.IntersectingError) as info:
        segvoronoi.medial_axis(CurvedPolygon(SQUARE, holes=[hole]))
    m = info.value.message
    assert m.startswith("arc 0 and segment 1 cross") and "arc 0 is the piece from vertex 2 of polygon 0, ring 1" in m, m
    # a ring whose side cuts back through its own half circle
    with pytest.raises(segvoronoi.IntersectingError) as info:
        segvoronoi.max_inscribed_circle(CurvedPolygon([[0, 0, -1], [2, 0, 0], [0.5, 2, 0]]))
    m = info.value.message
    assert "arc 0 is the piece from vertex 0 of polygon 0, ring 0" in m, m
    assert "segment 0 is the piece from vertex 1 of polygon 0, ring 0" in m and info.value.point is None, m


def test_bad_input_shapes_and_options_are_refused():
    with pytest.raises(segvoronoi.InvalidGeometryError, match="ring 1"):
        CurvedPolygon(SQUARE, holes=[[[1, 1], [2, 1], [2, 2]]])
    with pytest.raises(segvoronoi.InvalidGeometryError):
        CurvedPolygon([1, 2, 3])
    # (splitting curved polygons was refused until issue 32's split with
    # polygons and arcs; a slot that meets nothing splits into itself)
    split = segvoronoi.medial_axis(SHAPES["slot"], split_crossings=True)
    plain = segvoronoi.medial_axis(SHAPES["slot"])
    assert shapely.length(split) == pytest.approx(shapely.length(plain), rel=1e-12)


def test_errors_coerce_keeps_the_good_curved_polygons():
    bad = CurvedPolygon(SQUARE, holes=[[[4, 3, 0], [12, 3, 0], [12, 4, 0], [4, 4, 0]]])
    circles = segvoronoi.max_inscribed_circle([SHAPES["slot"], bad], errors="coerce")
    assert np.isnan(circles[1]).all() and circles[0, 2] == pytest.approx(0.731, rel=1e-12)
    pieces = segvoronoi.offset_pieces([bad, SHAPES["slot"]], [-0.1], errors="coerce")
    assert pieces[0, 0] is None and len(pieces[1, 0].loops) == 1
    with pytest.raises(segvoronoi.IntersectingError) as info:
        segvoronoi.offset_pieces([SHAPES["slot"], bad], [-0.1])
    assert info.value.geometry_index == 1
