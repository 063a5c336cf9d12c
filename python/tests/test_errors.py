"""Bad input raises the documented exceptions, never crashes."""

import math
import pickle

import numpy as np
import pytest
import shapely
from shapely.geometry import LineString, Point, Polygon

import segvoronoi
from segvoronoi import _errors


def test_crossing_segments_name_both_and_the_point():
    with pytest.raises(segvoronoi.IntersectingError) as info:
        segvoronoi.voronoi(segments=[[[0, 0], [4, 0]], [[1, 1], [2, 2]], [[2, -1], [2, 1]]])
    e = info.value
    assert e.indices == (0, 2) and e.point == (2.0, 0.0)
    assert "0" in e.message and "2" in e.message
    assert isinstance(e, segvoronoi.Error) and isinstance(e, ValueError)
    # the same input splits
    d = segvoronoi.voronoi(segments=[[[0, 0], [4, 0]], [[2, -1], [2, 1]]], split_crossings=True)
    assert d.stats["crossings"] == 1


def test_overlap_point_is_where_it_begins():
    with pytest.raises(segvoronoi.IntersectingError) as info:
        segvoronoi.voronoi(segments=[[[0, 0], [4, 0]], [[3, 0], [6, 0]]])
    assert info.value.point == (3.0, 0.0)


def test_self_crossing_polygon():
    bowtie = Polygon([(0, 0), (2, 2), (2, 0), (0, 2)])
    with pytest.raises(segvoronoi.IntersectingError) as info:
        segvoronoi.medial_axis(bowtie)
    assert info.value.point == (1.0, 1.0)
    assert "polygon 0" in info.value.message
    axis = segvoronoi.medial_axis(bowtie, split_crossings=True)
    assert len(axis.geoms) > 0


@pytest.mark.filterwarnings("ignore:invalid value encountered")
def test_non_finite_coordinates_are_named():
    with pytest.raises(segvoronoi.InvalidCoordinateError, match="3"):
        segvoronoi.voronoi(points=[[0, 0], [1, 0], [0, 1], [np.nan, 2]])
    with pytest.raises(segvoronoi.InvalidCoordinateError, match="1"):
        segvoronoi.voronoi(segments=[[[0, 0], [1, 0]], [[0, 1], [np.inf, 1]]])
    poly = Polygon([(0, 0), (1, 0), (1, np.nan), (0, 1)])
    with pytest.raises(segvoronoi.InvalidCoordinateError, match="polygon 0, ring 0: point 2"):
        segvoronoi.medial_axis(poly)


def test_degenerate_ring():
    flat = Polygon([(0, 0), (1, 0), (1, 0), (0, 0)])
    with pytest.raises(segvoronoi.InvalidPolygonError) as info:
        segvoronoi.offset(flat, 1.0)
    assert info.value.indices == (0, 0)


def test_bad_arguments():
    sq = Polygon([(0, 0), (1, 0), (1, 1), (0, 1)])
    for call in [
        lambda: segvoronoi.offset(sq, 0.0),
        lambda: segvoronoi.offset(sq, math.nan),
        lambda: segvoronoi.offsets(sq, [1.0, math.inf]),
        lambda: segvoronoi.medial_axis(sq, tolerance=-1),
        lambda: segvoronoi.medial_axis(sq, tolerance=0),
        lambda: segvoronoi.medial_axis(sq, corner_angle=200),
        lambda: segvoronoi.medial_axis(sq, prune_spurs=math.nan),
        lambda: segvoronoi.medial_axis([sq], threads=0),
        lambda: segvoronoi.medial_axis([sq], errors="ignore"),
        lambda: segvoronoi.voronoi(geometry=sq).edge_polylines(0),
    ]:
        with pytest.raises(segvoronoi.InvalidArgumentError):
            call()


def test_not_geometries():
    with pytest.raises(segvoronoi.InvalidGeometryError):
        segvoronoi.medial_axis("POLYGON ((0 0, 1 0, 1 1, 0 0))")
    with pytest.raises(segvoronoi.InvalidGeometryError):
        segvoronoi.voronoi(points=np.zeros((4, 3)))
    with pytest.raises(segvoronoi.InvalidGeometryError):
        segvoronoi.voronoi(segments=np.zeros((4, 3, 2)))
    with pytest.raises(segvoronoi.InvalidGeometryError):
        segvoronoi.medial_axis({"type": "Polygon", "coordinates": "nonsense"})


def test_vectorised_errors_carry_the_geometry_index():
    good = Point(0, 0).buffer(1)
    bad = Polygon([(0, 0), (2, 2), (2, 0), (0, 2)])
    with pytest.raises(segvoronoi.IntersectingError) as info:
        segvoronoi.medial_axis([good, good, bad, good])
    assert info.value.geometry_index == 2 and str(info.value).startswith("geometry 2: ")
    out = segvoronoi.medial_axis([good, bad, None], errors="coerce")
    assert out[1] is None and out[2].is_empty and len(out[0].geoms) > 0
    circles = segvoronoi.max_inscribed_circle([bad, good], errors="coerce")
    assert np.isnan(circles[0]).all() and circles[1, 2] > 0.99
    table = segvoronoi.offsets([bad, good], [1.0, 2.0], errors="coerce")
    assert table[0, 0] is None and table[1, 1].area > 9


def test_every_kind_has_its_class_and_pickles():
    kinds = {
        "InvalidCoordinate": segvoronoi.InvalidCoordinateError,
        "TooLarge": segvoronoi.TooLargeError,
        "Intersecting": segvoronoi.IntersectingError,
        "InvalidPolygon": segvoronoi.InvalidPolygonError,
        "InvalidArc": segvoronoi.InvalidArcError,
        "InvalidArgument": segvoronoi.InvalidArgumentError,
        "OutOfMemory": segvoronoi.OutOfMemoryError,
        "Internal": segvoronoi.InternalError,
        "UnsupportedRange": segvoronoi.UnsupportedRangeError,
        "SomethingNew": segvoronoi.Error,
    }
    for kind, cls in kinds.items():
        e = _errors.error_of((3, kind, "msg", [1, 2], (0.5, 1.5)), True)
        assert type(e) is cls and e.geometry_index == 3
        back = pickle.loads(pickle.dumps(e))
        assert type(back) is cls and (back.indices, back.point, back.geometry_index, str(back)) == (
            (1, 2),
            (0.5, 1.5),
            3,
            str(e),
        )


def test_huge_span_does_not_crash():
    # coordinates spanning far beyond 2^480: built and checked, or refused by name
    try:
        d = segvoronoi.voronoi(points=[[0, 0], [1e-300, 0], [1e300, 1], [5, 5]])
        d.validate()
    except segvoronoi.UnsupportedRangeError:
        pass


def test_lines_only_is_not_a_domain():
    assert segvoronoi.max_inscribed_circle(LineString([(0, 0), (1, 0)])) is None
    assert segvoronoi.medial_axis(shapely.Point(0, 0)).is_empty
