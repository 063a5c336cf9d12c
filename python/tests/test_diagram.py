"""Diagrams: the numpy arrays against the Rust library's canonical
topology text, exact texts of the Rust tests, the empty-circle property by
brute force, nearest sites, edge polylines, and array inputs of any layout."""

import numpy as np
import pytest
import shapely

import segvoronoi
from conftest import FIXTURES, even_odd, random_polygon_with_holes, read_boost, read_rings, DATA


def topology_from_arrays(d: segvoronoi.Diagram) -> str:
    """The Rust `topology()` text rebuilt from the arrays: sites named P<id>
    (point sites) or S<input index> (segments), each line sorted, lines
    sorted, EDGES from edge_sites and FACES from vertex_sites."""

    def name(s):
        j = d.site_segment_index[s]
        return (1, int(j)) if j >= 0 else (0, int(s))

    def section(title, rows):
        lines = sorted(sorted(name(s) for s in row) for row in rows)
        text = [f"{title} {len(lines)}"]
        text += [" ".join(("P" if k == 0 else "S") + str(i) for k, i in line) for line in lines]
        return "\n".join(text) + "\n"

    return section("EDGES", d.edge_sites) + section("FACES", d.vertex_sites)


def site_distance(d: segvoronoi.Diagram, s: int, p: np.ndarray) -> np.ndarray:
    a, b = d.site_coordinates[s]
    if d.site_kinds[s] == 0:
        return np.hypot(*(p - a).T)
    ab = b - a
    t = np.clip(((p - a) @ ab) / (ab @ ab), 0, 1)
    q = a + t[:, None] * ab
    return np.hypot(*(p - q).T)


def check_empty_circles(d: segvoronoi.Diagram, rel=1e-9):
    """Each vertex is at its clearance from its three sites and no site is
    closer (brute force), relative to the larger of the extent and the
    clearance (vertices of nearly parallel sites lie far out)."""
    if d.vertex_count == 0:
        return
    # vertices beyond the range of float (only for inputs spanning nearly
    # all of it) have an infinite clearance, as documented: not checkable
    finite = np.isfinite(d.clearances) & (np.abs(d.vertices).max(axis=1) < 1e150)
    v, r, sites = d.vertices[finite], d.clearances[finite], d.vertex_sites[finite]
    scale = max(np.ptp(d.site_coordinates.reshape(-1, 2), axis=0).max(), 1e-300)
    dist = np.array([site_distance(d, s, v) for s in range(d.site_count)])  # (S, V)
    tol = rel * np.maximum(scale, r)
    for k in range(3):
        own = dist[sites[:, k], np.arange(len(v))]
        assert np.all(np.abs(own - r) <= tol)
    assert np.all(dist.min(axis=0) >= r - tol)


def test_exact_texts_of_the_rust_tests():
    d = segvoronoi.voronoi(segments=[[[0.0, 0.0], [2.0, 1.0]]])
    assert (d.site_count, d.vertex_count, d.edge_count) == (3, 0, 2)
    assert d.topology() == "EDGES 2\nP0 S0\nP1 S0\nFACES 0\n"
    d = segvoronoi.voronoi(points=[[6.0, 3.0]], segments=[[[0.0, 0.0], [2.0, 1.0]], [[4.0, 2.0], [2.0, 1.0]]])
    assert d.topology() == "EDGES 5\nP0 P3\nP1 S0\nP2 S0\nP2 S1\nP3 S1\nFACES 0\n"
    d = segvoronoi.voronoi(points=[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])
    assert d.topology() == "EDGES 3\nP0 P1\nP0 P2\nP1 P2\nFACES 1\nP0 P1 P2\n"


FIXTURE_FILES = sorted(FIXTURES.glob("*.txt"))


@pytest.mark.parametrize("path", FIXTURE_FILES, ids=[p.stem for p in FIXTURE_FILES])
def test_fixtures_arrays_match_topology(path):
    pts, segs = read_boost(path)
    try:
        d = segvoronoi.voronoi(points=pts, segments=segs)
    except segvoronoi.IntersectingError:
        d = segvoronoi.voronoi(points=pts, segments=segs, split_crossings=True)
    d.validate()
    assert topology_from_arrays(d) == d.topology()
    assert d.topology(voronoi_pairs=True).startswith(d.topology())
    check_empty_circles(d, rel=1e-7)


@pytest.mark.parametrize("seed", range(5))
def test_random_points(seed):
    rng = np.random.default_rng(seed)
    pts = rng.integers(0, 20, (200, 2)).astype(float)  # a grid: many cocircular quadruples
    d = segvoronoi.voronoi(points=pts)
    assert topology_from_arrays(d) == d.topology()
    check_empty_circles(d)
    # every input row maps to the site at its coordinates (repeats merged)
    assert np.array_equal(d.site_coordinates[d.point_sites, 0], pts)
    # nearest site against brute force
    q = rng.uniform(-5, 25, (300, 2))
    got = d.nearest_site(q)
    site_pts = d.site_coordinates[:, 0]
    best = np.min(np.hypot(*(q[:, None, :] - site_pts[None]).transpose(2, 0, 1)), axis=1)
    assert np.allclose(np.hypot(*(q - site_pts[got]).T), best, rtol=0, atol=1e-12)


def test_glyph_segments_and_polylines():
    rings = read_rings(DATA / "glyph_B.rings")
    segs = np.concatenate([np.stack([r, np.roll(r, -1, axis=0)], axis=1) for r in rings])
    d = segvoronoi.voronoi(segments=segs)
    assert topology_from_arrays(d) == d.topology()
    check_empty_circles(d)
    # a polyline of each finite edge: its points equidistant from both sites
    polylines = d.edge_polylines(0.01)
    assert len(polylines) == d.edge_count
    for e, line in enumerate(polylines[:400]):
        if len(line) == 0:
            assert (d.edge_vertices[e] == -1).any()
            continue
        a, b = d.edge_sites[e]
        assert np.allclose(site_distance(d, a, line), site_distance(d, b, line), atol=1e-9 * 2048)


def test_domain_queries_equal_functions():
    poly = random_polygon_with_holes(4)
    d = segvoronoi.voronoi(geometry=poly)
    assert d.has_domain
    assert shapely.equals_exact(d.medial_axis(), segvoronoi.medial_axis(poly), 0)
    assert d.max_inscribed_circle() == segvoronoi.max_inscribed_circle(poly)
    ours = d.offsets([-2.0, 3.0], tolerance=1e-3)
    ref = segvoronoi.offsets(poly, [-2.0, 3.0], tolerance=1e-3)
    assert all(shapely.equals_exact(a, b, 0) for a, b in zip(ours, ref))
    # locations: inside where shapely says so
    rng = np.random.default_rng(0)
    q = rng.uniform(-100, 100, (500, 2))
    where = d.locate(q)
    inside = shapely.contains_xy(poly, q[:, 0], q[:, 1])
    on_boundary = where == 0
    assert np.array_equal(where[~on_boundary] == 1, inside[~on_boundary])
    assert (d.vertex_locations == 1).sum() > 0 and (d.edge_locations == -1).sum() > 0


def test_array_layouts_give_the_same_diagram():
    rng = np.random.default_rng(7)
    base = rng.uniform(0, 100, (300, 3))
    contiguous = np.ascontiguousarray(base[:, :2])
    strided = base[:, :2]  # not contiguous
    fortran = np.asfortranarray(contiguous)
    as_float32_ints = np.round(contiguous).astype(np.int32)
    t = segvoronoi.voronoi(points=contiguous).topology()
    assert segvoronoi.voronoi(points=strided).topology() == t
    assert segvoronoi.voronoi(points=fortran).topology() == t
    assert segvoronoi.voronoi(points=contiguous.tolist()).topology() == t
    d = segvoronoi.voronoi(points=as_float32_ints)
    assert topology_from_arrays(d) == d.topology()
    segs = rng.uniform(0, 1, (40, 3, 2))[:, ::2, :]  # (40, 2, 2), strided
    segs[:, 1] = segs[:, 0] + 1e-3  # tiny, so they do not cross
    a = segvoronoi.voronoi(segments=segs)
    b = segvoronoi.voronoi(segments=np.ascontiguousarray(segs).reshape(40, 4))
    assert a.topology() == b.topology()


def test_geometry_inputs():
    poly = random_polygon_with_holes(2)

    class Feature:  # anything with __geo_interface__
        __geo_interface__ = {"type": "Feature", "geometry": shapely.geometry.mapping(poly), "properties": {}}

    ref = segvoronoi.medial_axis(poly)
    assert shapely.equals_exact(segvoronoi.medial_axis(Feature()), ref, 0)
    assert shapely.equals_exact(segvoronoi.medial_axis(shapely.geometry.mapping(poly)), ref, 0)
    # points and lines go with polygons as obstacles
    d = segvoronoi.voronoi(points=[[0.0, 0.0]], geometry=shapely.GeometryCollection([poly, shapely.LineString([(-5, -5), (5, -5)])]))
    assert d.point_sites.tolist() == [0] and d.has_domain
    assert repr(d).startswith("<segvoronoi.Diagram:")
    assert d.stats["input_points"] == 1


def test_threads_give_one_canonical_text():
    """A build large enough to run in halves on two threads (60k sites and
    more) gives the one-thread diagram: the canonical text with the
    Voronoi pairs, byte for byte, on random points and on a lattice
    (cocircular sites across the cut), and the same vertex positions."""
    rng = np.random.default_rng(5)
    lattice = np.array([[x, y] for x in range(300) for y in range(220)], dtype=float)
    for pts in (rng.random((70_000, 2)), lattice):
        one = segvoronoi.voronoi(points=pts, threads=1)
        two = segvoronoi.voronoi(points=pts, threads=2)
        texts = [d.topology(voronoi_pairs=True, canonical_cuts=True) for d in (one, two)]
        assert texts[0] == texts[1]
        assert one.vertices.shape == two.vertices.shape
        rows = [d.vertices[np.lexsort(d.vertices.T[::-1])] for d in (one, two)]
        assert np.array_equal(rows[0], rows[1])
