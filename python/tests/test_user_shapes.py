"""What users hold, beyond the generated families: rings touching at a
point (a hole touching its shell, two squares sharing a corner), a point
exactly on a segment, and coordinates far from the origin."""

import numpy as np
import shapely
from shapely.affinity import translate
from shapely.geometry import MultiPolygon, Polygon

import segvoronoi
from checks import check_clearances, check_offset, square
from conftest import random_polygon_with_holes


def hole_touching_its_shell() -> Polygon:
    # a valid OGC polygon: the triangular hole touches the shell at (0, 5)
    return Polygon(square(0, 0, 10).exterior.coords, [[(0, 5), (3, 4), (3, 6)]])


def test_hole_touching_its_shell():
    poly = hole_touching_its_shell()
    assert poly.is_valid
    check_clearances(poly, segvoronoi.medial_axis(poly, tolerance=1e-6))
    for d, ours in zip([-0.7, -0.2, 0.5], segvoronoi.offsets(poly, [-0.7, -0.2, 0.5], tolerance=1e-4)):
        check_offset(poly, ours, d, 1e-4)


def test_squares_sharing_a_corner():
    pair = MultiPolygon([square(0, 0, 4), square(4, 4, 4)])
    assert pair.is_valid
    check_clearances(pair, segvoronoi.medial_axis(pair, tolerance=1e-6))
    x, y, r = segvoronoi.max_inscribed_circle(pair)
    assert abs(r - 2.0) < 1e-12
    for d, ours in zip([-1.0, 0.3], segvoronoi.offsets(pair, [-1.0, 0.3], tolerance=1e-4)):
        check_offset(pair, ours, d, 1e-4)


def test_point_exactly_on_a_segment():
    # the point splits the segment there: a valid diagram, with the point's
    # site on the segment's line
    diagram = segvoronoi.voronoi(points=np.array([[1.0, 0.0]]), segments=np.array([[[0.0, 0.0], [2.0, 0.0]]]))
    diagram.validate()
    assert diagram.stats["split_at_vertices"] == 1
    assert diagram.stats["pieces"] == 2
    assert diagram.topology().startswith("EDGES 4\n")


def test_far_from_the_origin():
    # the same polygon moved 1e7 units away (an ulp there is 2e-9): the
    # clearances still equal the distances to the boundary, and the largest
    # circle keeps its radius
    poly = random_polygon_with_holes(3)
    far = translate(poly, 1e7, -1e7)
    check_clearances(far, segvoronoi.medial_axis(far, tolerance=1e-3), rel=1e-8)
    (_, _, r), (_, _, r_far) = segvoronoi.max_inscribed_circle(poly), segvoronoi.max_inscribed_circle(far)
    assert abs(r - r_far) <= 1e-8 * 1e7
    for d, ours in zip([-2.0, 3.0], segvoronoi.offsets(far, [-2.0, 3.0], tolerance=1e-3)):
        check_offset(far, ours, d, 1e-3)
    assert shapely.is_valid(segvoronoi.offset(far, -2.0, tolerance=1e-3))
