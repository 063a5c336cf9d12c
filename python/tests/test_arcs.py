"""Circular arcs through ``voronoi(arcs=...)``: every vertex and every
sampled edge point checked against distances to the sites computed here in
numpy, independently of the library; the site arrays of arcs; the errors
of arcs."""

from __future__ import annotations

import math

import numpy as np
import pytest
import shapely

import segvoronoi

Q = math.tan(math.pi / 8)  # the bulge of a quarter circle

# a slot: two sides and two half circles, start to end around it
SLOT_SEGMENTS = np.array([[[0.0, 0.0], [4.0, 0.0]], [[4.0, 2.0], [0.0, 2.0]]])
SLOT_ARCS = np.array([[4.0, 0.0, 4.0, 2.0, 1.0], [0.0, 2.0, 0.0, 0.0, 1.0]])

# a rounded rectangle: four sides, four quarter circles of radius 1
ROUNDED_SEGMENTS = np.array(
    [
        [[1.0, 0.0], [3.0, 0.0]],
        [[4.0, 1.0], [4.0, 2.0]],
        [[3.0, 3.0], [1.0, 3.0]],
        [[0.0, 2.0], [0.0, 1.0]],
    ]
)
ROUNDED_ARCS = np.array(
    [
        [3.0, 0.0, 4.0, 1.0, Q],
        [4.0, 2.0, 3.0, 3.0, Q],
        [1.0, 3.0, 0.0, 2.0, Q],
        [0.0, 1.0, 1.0, 0.0, Q],
    ]
)

# a clockwise arc among points, beside a segment
MIXED_POINTS = np.array([[0.0, 0.0], [5.0, 5.0], [-3.0, 4.0], [2.5, -1.0]])
MIXED_SEGMENTS = np.array([[[-4.0, -3.0], [-1.0, -3.5]]])
MIXED_ARCS = np.array([[3.0, 2.0, 1.0, 3.0, -0.7], [-2.0, 1.0, -1.0, 2.5, 2.5]])

CASES = {
    "slot": (None, SLOT_SEGMENTS, SLOT_ARCS),
    "rounded": (None, ROUNDED_SEGMENTS, ROUNDED_ARCS),
    "mixed": (MIXED_POINTS, MIXED_SEGMENTS, MIXED_ARCS),
    # the rounded rectangle about a point and a short segment: their
    # bisectors with the quarter circles are ellipses, within the outline
    "pocket": (np.array([[1.3, 1.1]]), np.concatenate([ROUNDED_SEGMENTS, [[[2.6, 1.9], [3.1, 2.2]]]]), ROUNDED_ARCS),
}


def arc_geometry(row):
    """Centre, radius, start angle and counter-clockwise sweep of an arc
    row ``[sx, sy, ex, ey, bulge]`` (from the bulge, as DXF defines it)."""
    sx, sy, ex, ey, bulge = row
    theta = 4.0 * math.atan(bulge)  # signed sweep
    mx, my = (sx + ex) / 2, (sy + ey) / 2
    dx, dy = ex - sx, ey - sy
    k = (1 - bulge * bulge) / (4 * bulge)
    cx, cy = mx - k * dy, my + k * dx
    r = math.hypot(sx - cx, sy - cy)
    if theta > 0:
        start = math.atan2(sy - cy, sx - cx)
    else:  # the same points walked counter-clockwise from the end
        start = math.atan2(ey - cy, ex - cx)
    return (cx, cy), r, start, abs(theta)


def distance_to_arc(p: np.ndarray, row) -> np.ndarray:
    """Distance of each row of ``p (n, 2)`` to the arc: to the circle when
    the direction from the centre lies in the arc's angular span, else to
    the nearer endpoint."""
    (cx, cy), r, start, sweep = arc_geometry(row)
    v = p - np.array([cx, cy])
    rel = np.mod(np.arctan2(v[:, 1], v[:, 0]) - start, 2 * math.pi)
    in_span = rel <= sweep
    to_circle = np.abs(np.hypot(v[:, 0], v[:, 1]) - r)
    to_ends = np.minimum(np.hypot(p[:, 0] - row[0], p[:, 1] - row[1]), np.hypot(p[:, 0] - row[2], p[:, 1] - row[3]))
    return np.where(in_span, to_circle, to_ends)


def distance_to_segment(p: np.ndarray, a, b) -> np.ndarray:
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    d = b - a
    t = np.clip(((p - a) @ d) / (d @ d), 0.0, 1.0)
    q = a + t[:, None] * d
    return np.hypot(*(p - q).T)


def site_distance(d: segvoronoi.Diagram, arcs: np.ndarray, site: int, p: np.ndarray) -> np.ndarray:
    """Distance of each row of ``p`` to ``site``, from the input rows (the
    arcs) and the site coordinates (points and segments)."""
    kind = d.site_kinds[site]
    a, b = d.site_coordinates[site]
    if kind == 0:
        return np.hypot(*(p - a).T)
    if kind == 1:
        return distance_to_segment(p, a, b)
    assert kind == 2
    return distance_to_arc(p, arcs[d.site_arc_index[site]])


def build(name):
    points, segments, arcs = CASES[name]
    return segvoronoi.voronoi(points=points, segments=segments, arcs=arcs), arcs


def scale_of(arcs: np.ndarray) -> float:
    xy = np.concatenate([arcs[:, 0:2], arcs[:, 2:4]])
    return float(np.hypot(*(xy.max(axis=0) - xy.min(axis=0))))


@pytest.mark.parametrize("name", sorted(CASES))
def test_vertex_clearances_are_distances_to_their_three_sites(name):
    d, arcs = build(name)
    d.validate()
    assert d.vertex_count > 0 and (d.site_kinds == 2).sum() == len(arcs)
    tol = 1e-9 * scale_of(arcs)
    p = d.vertices
    for k in range(3):
        sites = d.vertex_sites[:, k]
        dist = np.array([site_distance(d, arcs, int(s), p[i : i + 1])[0] for i, s in enumerate(sites)])
        assert np.max(np.abs(dist - d.clearances)) <= tol, (k, np.max(np.abs(dist - d.clearances)))
    # and no site is nearer than the clearance (the vertex is a Voronoi vertex)
    for s in range(d.site_count):
        dist = site_distance(d, arcs, s, p)
        assert (dist >= d.clearances - tol).all(), s


def test_slot_axis_is_its_centre_line():
    d, _ = build("slot")
    inner = (d.vertices[:, 1] > 0) & (d.vertices[:, 1] < 2) & (d.vertices[:, 0] >= 0) & (d.vertices[:, 0] <= 4)
    assert inner.any()
    assert np.allclose(d.vertices[inner, 1], 1.0) and np.allclose(d.clearances[inner], 1.0)


@pytest.mark.parametrize("name", sorted(CASES))
def test_site_arrays_of_arcs(name):
    points, segments, arcs = CASES[name]
    d, _ = build(name)
    kinds = d.site_kinds
    assert set(kinds.tolist()) <= {0, 1, 2}
    # point sites, then segments, then arcs
    assert (np.diff(kinds) >= 0).all()
    assert (kinds == 1).sum() == len(segments) and (kinds == 2).sum() == len(arcs)
    is_arc = kinds == 2
    assert sorted(d.site_arc_index[is_arc].tolist()) == list(range(len(arcs)))
    assert (d.site_arc_index[~is_arc] == -1).all()
    assert (d.site_segment_index[is_arc] == -1).all()
    assert d.arc_circles.shape == (d.site_count, 4)
    assert np.isnan(d.arc_circles[~is_arc]).all()
    for s in np.flatnonzero(is_arc):
        row = arcs[d.site_arc_index[s]]
        assert d.site_coordinates[s].tolist() == [[row[0], row[1]], [row[2], row[3]]]
        (cx, cy), r, _, _ = arc_geometry(row)
        assert np.allclose(d.arc_circles[s, :3], [cx, cy, r], rtol=0, atol=1e-12)
        assert d.arc_circles[s, 3] == row[4]
    # every arc endpoint is a point site
    ends = {tuple(xy) for xy in np.concatenate([arcs[:, 0:2], arcs[:, 2:4]]).tolist()}
    point_sites = {tuple(xy) for xy in d.site_coordinates[kinds == 0, 0].tolist()}
    assert ends <= point_sites


def test_without_arcs_nothing_changes():
    segments = SLOT_SEGMENTS
    d = segvoronoi.voronoi(segments=segments)
    assert (d.site_arc_index == -1).all() and np.isnan(d.arc_circles).all()
    assert set(d.site_kinds.tolist()) == {0, 1}
    # an empty arcs array goes the arc route and gives the same diagram
    e = segvoronoi.voronoi(segments=segments, arcs=np.zeros((0, 5)))
    assert e.topology() == d.topology()
    assert np.array_equal(e.vertices, d.vertices) and np.array_equal(e.clearances, d.clearances)


@pytest.mark.parametrize("name", sorted(CASES))
def test_edge_polylines_of_arcs_are_equidistant_from_their_sites(name):
    d, arcs = build(name)
    tol = 1e-9 * scale_of(arcs)
    lines = d.edge_polylines(1e-3)
    curved = 0
    checked = 0
    for e, line in enumerate(lines):
        s, t = (int(x) for x in d.edge_sites[e])
        if len(line) == 0 or 2 not in (d.site_kinds[s], d.site_kinds[t]):
            continue
        a = site_distance(d, arcs, s, line)
        b = site_distance(d, arcs, t, line)
        assert np.max(np.abs(a - b)) <= tol, (e, np.max(np.abs(a - b)))
        checked += 1
        curved += len(line) > 2
    if name in ("mixed", "pocket"):
        # the slot's and the rounded rectangle's edges with an arc are rays
        # from its centre, to infinity
        assert checked > 0 and curved > 0


def test_arcs_with_a_line_geometry():
    # a geometry's lines and points are obstacles beside the arcs
    d = segvoronoi.voronoi(
        geometry=shapely.MultiLineString([[(-3, -3), (3, -3)], [(-3, 3), (3, 3)]]), arcs=[[-1.0, 0.0, 1.0, 0.0, 1.0]]
    )
    assert (d.site_kinds == 2).sum() == 1 and (d.site_kinds == 1).sum() == 2
    assert d.site_arc_index[d.site_kinds == 2].tolist() == [0]
    d.validate()


def test_arcs_inside_a_polygon_build():
    # a domain bounded by a polygon, an arc obstacle inside it (issue 32:
    # polygons together with arcs build)
    d = segvoronoi.voronoi(geometry=shapely.box(-10, -10, 10, 10), arcs=[[-1.0, 0.0, 1.0, 0.0, 1.0]])
    d.validate()
    assert (d.site_kinds == 2).sum() == 1
    assert d.site_arc_index[d.site_kinds == 2].tolist() == [0]


def test_crossing_arcs_raise_intersecting_naming_both():
    # the upper unit half circle, and the right half of the circle of
    # radius 1 about (0, 1): they cross at (sqrt(3)/2, 1/2)
    arcs = np.array([[-1.0, 0.0, 1.0, 0.0, -1.0], [0.0, 0.0, 0.0, 2.0, 1.0]])
    with pytest.raises(segvoronoi.IntersectingError) as info:
        segvoronoi.voronoi(arcs=arcs)
    assert sorted(info.value.indices) == [0, 1]
    assert "arcs 0 and 1" in info.value.message
    assert info.value.point is None


def test_arc_crossing_a_segment_names_both():
    with pytest.raises(segvoronoi.IntersectingError) as info:
        segvoronoi.voronoi(segments=[[[0.0, -2.0], [0.0, 2.0]]], arcs=[[-1.0, 0.0, 1.0, 0.0, 1.0]])
    assert info.value.message == "arc 0 and segment 0 cross"
    assert info.value.indices == (0, 0) and info.value.point is None


def test_point_on_an_arc_names_both():
    with pytest.raises(segvoronoi.IntersectingError) as info:
        segvoronoi.voronoi(points=[[5.0, 5.0], [0.0, 1.0]], arcs=[[-1.0, 0.0, 1.0, 0.0, -1.0]])
    assert info.value.message == "point 1 lies on arc 0"
    assert info.value.indices == (1, 0) and info.value.point is None


def test_crossing_segments_beside_arcs_keep_their_point():
    with pytest.raises(segvoronoi.IntersectingError) as info:
        segvoronoi.voronoi(segments=[[[0, 0], [4, 0]], [[2, -1], [2, 1]]], arcs=[[10.0, 0.0, 12.0, 0.0, 1.0]])
    assert info.value.indices == (0, 1) and info.value.point == (2.0, 0.0)


def test_zero_bulge_raises_invalid_arc_naming_the_row():
    arcs = np.array([[0.0, 0.0, 1.0, 0.0, 1.0], [5.0, 0.0, 6.0, 0.0, 0.0]])
    with pytest.raises(segvoronoi.InvalidArcError) as info:
        segvoronoi.voronoi(arcs=arcs)
    assert info.value.indices == (1,)
    assert "row 1" in str(info.value) and "bulge" in str(info.value)
    assert isinstance(info.value, ValueError) and isinstance(info.value, segvoronoi.Error)


@pytest.mark.parametrize(
    "row",
    [[0.0, 0.0, 0.0, 0.0, 1.0], [0.0, 0.0, 1.0, 0.0, math.nan], [0.0, math.inf, 1.0, 0.0, 1.0]],
    ids=["equal-ends", "nan-bulge", "inf-coordinate"],
)
def test_invalid_rows_raise_invalid_arc(row):
    with pytest.raises(segvoronoi.InvalidArcError) as info:
        segvoronoi.voronoi(arcs=[[3.0, 0.0, 4.0, 0.0, 0.5], row])
    assert info.value.indices == (1,)


def test_arcs_crossed_by_a_segment_are_split():
    # the slot crossed lengthwise by a segment through both half circles
    across = np.array([[[-2.0, 1.0], [6.0, 1.0]]])
    with pytest.raises(segvoronoi.IntersectingError):
        segvoronoi.voronoi(segments=np.concatenate([SLOT_SEGMENTS, across]), arcs=SLOT_ARCS)
    d = segvoronoi.voronoi(segments=np.concatenate([SLOT_SEGMENTS, across]), arcs=SLOT_ARCS, split_crossings=True)
    d.validate()
    assert d.stats["crossings"] == 2
    # each half circle cut in two at the crossing: four arc pieces
    assert sorted(d.site_arc_index[d.site_arc_index >= 0].tolist()) == [0, 1, 2, 3]
    # the crossing points are shared ends: (4 + 1, 1) right, (0 - 1, 1) left
    ends = {tuple(p) for p in d.site_coordinates[d.site_kinds == 0, 0].tolist()}
    assert {(5.0, 1.0), (-1.0, 1.0)} <= ends


def test_arcs_with_polygons_and_split_crossings():
    # the slot's half circles touch the box's sides from inside (refused
    # before issue 32's split with polygons): each is cut where it touches,
    # and the box's domain is as it was
    d = segvoronoi.voronoi(geometry=shapely.box(-1, -1, 5, 3), arcs=SLOT_ARCS, split_crossings=True)
    d.validate()
    assert d.stats["touchings"] == 2
    assert (d.site_kinds == 2).sum() == 4
    plain = segvoronoi.voronoi(geometry=shapely.box(-1, -1, 5, 3))
    assert d.locate([[2.0, 1.0], [6.0, 1.0], [-0.5, -0.5]]).tolist() == plain.locate([[2.0, 1.0], [6.0, 1.0], [-0.5, -0.5]]).tolist()


def test_arcs_with_many_geometries_are_refused():
    with pytest.raises(segvoronoi.InvalidArgumentError):
        segvoronoi.voronoi(geometry=[shapely.box(0, 0, 1, 1), shapely.box(0, 0, 2, 1)], arcs=SLOT_ARCS)


def test_arcs_of_the_wrong_shape_are_refused():
    with pytest.raises(segvoronoi.InvalidGeometryError):
        segvoronoi.voronoi(arcs=np.zeros((2, 4)))


def test_arcs_of_any_dtype_and_strides():
    wide = np.zeros((2, 10))
    wide[:, ::2] = SLOT_ARCS
    d = segvoronoi.voronoi(segments=SLOT_SEGMENTS, arcs=wide[:, ::2])
    e = segvoronoi.voronoi(segments=SLOT_SEGMENTS, arcs=SLOT_ARCS.astype(np.float32).tolist())
    assert d.topology() == e.topology() == segvoronoi.voronoi(segments=SLOT_SEGMENTS, arcs=SLOT_ARCS).topology()
