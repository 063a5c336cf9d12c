"""The Voronoi diagram of points, segments and geometries, read as numpy
arrays: :func:`voronoi` and :class:`Diagram`."""

from __future__ import annotations

from functools import cached_property
from typing import Any, Dict, List, Optional, Sequence, Tuple

import numpy as np
import shapely

from . import _native
from ._curved import OffsetPieces, offset_pieces_of
from ._api import check_corner_angle, check_errors, check_positive, check_threads
from ._errors import InvalidArgumentError, InvalidGeometryError, error_of, raise_failure
from ._pack import as_points, as_segments, is_many, pack_many, pack_one
from ._shapes import multilinestrings, multipolygons

__all__ = ["Diagram", "voronoi"]


def voronoi(
    points: Any = None,
    segments: Any = None,
    geometry: Any = None,
    *,
    arcs: Any = None,
    split_crossings: bool = False,
    threads: Optional[int] = None,
    errors: str = "raise",
) -> Any:
    """The Voronoi diagram of points, segments, circular arcs and a geometry.

    Args:
        points: an ``(n, 2)`` array of points (any float dtype, any strides);
            their input indices are the rows.
        segments: an ``(m, 2, 2)`` (or ``(m, 4)``) array of segments; they may
            share endpoints but not cross (:class:`IntersectingError`, naming
            both rows and a common point) unless ``split_crossings``.
        geometry: a shapely geometry, ``__geo_interface__`` or
            :class:`CurvedPolygon`; its polygons bound the domain (for :meth:`Diagram.medial_axis` and
            :meth:`Diagram.offsets`), its lines and points are obstacles.
            Its points come after ``points`` and its segments after
            ``segments``.
            A list, array or GeoSeries of geometries (without ``points``
            and ``segments``) gives an array of diagrams, built on up to
            ``threads`` threads; ``errors='coerce'`` puts None where a
            geometry fails instead of raising.
        arcs: a ``(k, 5)`` array of circular arcs, rows ``[start_x,
            start_y, end_x, end_y, bulge]`` with DXF's bulge ``tan(θ/4)``
            (θ the signed angle swept from start to end, positive
            counter-clockwise; 1 is a half circle; never 0: a straight
            piece is a segment); their input indices are the rows. They
            may share endpoints with each other and with the segments but
            not cross, overlap or touch inside (:class:`IntersectingError`,
            naming both); an invalid row raises :class:`InvalidArcError`
            naming it. Only with one geometry, and not with
            ``split_crossings`` (:class:`InvalidArgumentError`). See
            :attr:`Diagram.arc_circles`. They are obstacles: to bound a
            domain with arcs, give a :class:`CurvedPolygon` as
            ``geometry`` (whose arcs come after these in
            :attr:`Diagram.site_arc_index`).
        split_crossings: split crossings and overlaps by snap rounding
            instead of raising (the diagram is then that of the pieces).

    >>> import numpy as np
    >>> d = voronoi(points=np.array([[0.0, 0.0], [2.0, 0.0], [1.0, 2.0], [1.0, 0.7]]))
    >>> d.vertex_count, d.edge_count
    (3, 6)
    >>> print(d.topology())
    EDGES 6
    P0 P1
    P0 P2
    P0 P3
    P1 P2
    P1 P3
    P2 P3
    FACES 3
    P0 P1 P3
    P0 P2 P3
    P1 P2 P3
    <BLANKLINE>
    >>> from shapely import box
    >>> [d.edge_count for d in voronoi(geometry=[box(0, 0, 1, 1), box(0, 0, 2, 1), None])]
    [13, 13, 0]

    A slot: two sides and two half circles (bulge 1) of radius 1. Its
    vertices are the half circles' centres, each as far from its arc as
    from the sides:

    >>> slot = voronoi(segments=[[[0, 0], [4, 0]], [[4, 2], [0, 2]]],
    ...                arcs=[[4, 0, 4, 2, 1], [0, 2, 0, 0, 1]])
    >>> slot.site_kinds.tolist()  # four endpoints, two sides, two arcs
    [0, 0, 0, 0, 1, 1, 2, 2]
    >>> slot.site_arc_index[6:].tolist(), slot.arc_circles[6:].tolist()  # centre x, y, radius, bulge
    ([0, 1], [[4.0, 1.0, 1.0, 1.0], [0.0, 1.0, 1.0, 1.0]])
    >>> sorted(set(map(tuple, slot.vertices.tolist())))
    [(0.0, 1.0), (4.0, 1.0)]
    >>> on_arc = (slot.vertex_sites == 6).any(axis=1)  # the vertices of arc 0's cell
    >>> cx, cy, r, _ = slot.arc_circles[6]
    >>> to_circle = np.abs(np.hypot(*(slot.vertices[on_arc] - [cx, cy]).T) - r)
    >>> bool(np.array_equal(to_circle, slot.clearances[on_arc])), slot.clearances.tolist()
    (True, [1.0, 1.0, 1.0, 1.0, 1.0, 1.0])
    """
    if is_many(geometry):
        if points is not None or segments is not None:
            raise InvalidArgumentError("points and segments go with one geometry, not with many")
        if arcs is not None:
            raise InvalidArgumentError("arcs go with one geometry, not with many")
        check_threads(threads)
        check_errors(errors)
        results = _native.build_batch(pack_many(geometry), bool(split_crossings), threads)
        out = np.empty(len(results), dtype=object)
        for k, (built, failure) in enumerate(results):
            if failure is not None and errors == "raise":
                raise error_of(failure, True)
            out[k] = None if built is None else Diagram(built)
        return out
    pts = None if points is None else as_points(points)
    segs = None if segments is None else as_segments(segments)
    packed = _merge(pack_one(geometry), pts, segs)
    if arcs is None:
        built, failure = _native.build(packed, bool(split_crossings))
    else:
        built, failure = _native.build_with_arcs(packed, as_arcs(arcs), bool(split_crossings))
    if failure is not None or built is None:
        raise_failure(failure or (-1, "Internal", "no diagram and no error", (), None))
    assert built is not None
    return Diagram(built, 0 if pts is None else len(pts))


def as_arcs(arcs: Any) -> np.ndarray:
    """A ``(k, 5)`` float64 array of arcs (any strides and dtype accepted)."""
    a = np.asarray(arcs, dtype=np.float64)
    if a.size == 0:
        return np.zeros((0, 5), dtype=np.float64)
    if a.ndim == 1 and a.shape[0] == 5:
        a = a.reshape(1, 5)
    if a.ndim != 2 or a.shape[1] != 5:
        raise InvalidGeometryError(f"arcs must have shape (k, 5), got {a.shape}")
    return np.ascontiguousarray(a)


def _merge(base, pts, segs):
    """``base`` (one packed geometry) with ``pts`` and ``segs`` first."""
    out = base._asdict()
    if pts is not None and len(pts):
        out["pt_xy"] = np.concatenate([pts, base.pt_xy])
        out["gpt"] = np.array([0, len(out["pt_xy"])], dtype=np.int64)
    if segs is not None and len(segs):
        out["seg"] = segs
        out["gseg"] = np.array([0, len(segs)], dtype=np.int64)
    return type(base)(**out)


class Diagram:
    """A Voronoi diagram of points, segments and circular arcs (from
    :func:`voronoi`).

    Sites: ids ``0..site_count``; the point sites first (each distinct point
    once: the input points, then the segments' and arcs' endpoints), then
    the open segments in input order, then the open arcs. A segment is
    three sites: its two endpoints and the open segment between them; an
    arc likewise its start, its end and the open arc. Arrays are made on
    first access and kept.

    >>> import numpy as np
    >>> d = voronoi(segments=np.array([[[0, 0], [4, 0]]]), points=np.array([[2.0, 2.0]]))
    >>> d.site_kinds.tolist()  # the point, two endpoints, the open segment
    [0, 0, 0, 1]
    >>> int(d.nearest_site((2.0, 0.5))), int(d.nearest_site((2.0, 1.5)))
    (3, 0)
    """

    def __init__(self, native: "_native.Diagram", input_points: int = 0) -> None:
        self._d = native
        self._input_points = input_points
        counts = native.counts()
        self.site_count: int = counts[0]
        """Number of sites (point sites and open segments)."""
        self.point_site_count: int = counts[1]
        """Number of point sites (ids ``0..point_site_count``)."""
        self.vertex_count: int = counts[2]
        """Number of finite Voronoi vertices."""
        self.edge_count: int = counts[3]
        """Number of edges between two sites."""

    def __repr__(self) -> str:
        return (
            f"<segvoronoi.Diagram: {self.site_count} sites, {self.vertex_count} vertices, "
            f"{self.edge_count} edges{', a domain' if self.has_domain else ''}>"
        )

    @property
    def has_domain(self) -> bool:
        """Whether polygons bound a domain."""
        return self._d.has_domain()

    @cached_property
    def _vertex(self):
        return self._d.vertex_arrays()

    @property
    def vertices(self) -> np.ndarray:
        """``(V, 2)`` positions of the finite vertices."""
        return self._vertex[0]

    @property
    def clearances(self) -> np.ndarray:
        """``(V,)`` distance of each vertex to its three sites."""
        return self._vertex[1]

    @property
    def vertex_sites(self) -> np.ndarray:
        """``(V, 3)`` the three sites whose cells meet at each vertex,
        counter-clockwise."""
        return self._vertex[2]

    @cached_property
    def _edge(self):
        return self._d.edge_arrays()

    @property
    def edge_sites(self) -> np.ndarray:
        """``(E, 2)`` the sites left and right of each edge, walking from its
        first end to its second."""
        return self._edge[0]

    @property
    def edge_vertices(self) -> np.ndarray:
        """``(E, 2)`` the vertex at each end, -1 for an end at infinity."""
        return self._edge[1]

    @property
    def edge_directions(self) -> np.ndarray:
        """``(E, 2, 2)`` the unit direction of each end at infinity (NaN at
        finite ends)."""
        return self._edge[2]

    @cached_property
    def _site(self):
        return self._d.site_arrays()

    @property
    def site_kinds(self) -> np.ndarray:
        """``(S,)`` 0 for a point site, 1 for an open segment, 2 for an open
        circular arc."""
        return self._site[0]

    @property
    def site_coordinates(self) -> np.ndarray:
        """``(S, 2, 2)`` each site's endpoints (a point: itself twice; an
        arc: its start and end, its circle in :attr:`arc_circles`)."""
        return self._site[1]

    @property
    def site_segment_index(self) -> np.ndarray:
        """``(S,)`` each open segment's input index (a piece index with
        ``split_crossings``), -1 for point and arc sites."""
        return self._site[2]

    @cached_property
    def _arc(self):
        return self._d.arc_arrays()

    @property
    def site_arc_index(self) -> np.ndarray:
        """``(S,)`` each open arc's input index (its row of ``arcs``), -1
        for point and segment sites."""
        return self._arc[0]

    @property
    def arc_circles(self) -> np.ndarray:
        """``(S, 4)`` each open arc's ``[centre_x, centre_y, radius,
        bulge]`` (centre and radius rounded from the exact circle; the
        bulge as given), NaN for point and segment sites.

        >>> import numpy as np
        >>> d = voronoi(arcs=[[1, 0, -1, 0, 1]])  # the upper half of the unit circle
        >>> d.site_kinds.tolist(), d.site_arc_index.tolist()
        ([0, 0, 2], [-1, -1, 0])
        >>> d.arc_circles[2].tolist()
        [0.0, 0.0, 1.0, 1.0]
        """
        return self._arc[1]

    @cached_property
    def point_sites(self) -> np.ndarray:
        """``(n,)`` the site of each row of ``points`` (repeated points share
        one)."""
        return self._d.point_input_sites(self._input_points)

    @cached_property
    def _cells(self):
        return self._d.cell_arrays()

    def cell_edges(self, site: int) -> np.ndarray:
        """The edges around the cell of ``site``, counter-clockwise.

        >>> d = voronoi(points=[[0, 0], [1, 0], [0, 1]])
        >>> sorted(d.cell_edges(0).tolist())
        [0, 1]
        """
        off, edges = self._cells
        if not 0 <= site < self.site_count:
            raise InvalidArgumentError(f"site {site} is not in 0..{self.site_count}")
        return edges[off[site] : off[site + 1]]

    @property
    def cell_offsets(self) -> np.ndarray:
        """``(S + 1,)`` offsets into :attr:`cell_edge_ids`, per site."""
        return self._cells[0]

    @property
    def cell_edge_ids(self) -> np.ndarray:
        """The edges of every cell, concatenated (see :attr:`cell_offsets`)."""
        return self._cells[1]

    def edge_polylines(self, tolerance: float) -> List[np.ndarray]:
        """Every edge as a ``(k, 2)`` polyline within ``tolerance`` of the
        exact curve (parabolic arcs cut into chords); an empty array for
        edges that reach infinity.

        >>> d = voronoi(points=[[0, 0], [2, 0], [1, 2], [1, 0.7]])
        >>> [len(p) for p in d.edge_polylines(0.01)].count(2)
        3
        """
        check_positive("tolerance", tolerance)
        return self._d.edge_polylines(float(tolerance))

    def nearest_site(self, xy: Any) -> Any:
        """The site nearest to a point ``(x, y)`` (an int), or to each row of
        an ``(n, 2)`` array (an array); -1 for a non-finite point."""
        a = np.asarray(xy, dtype=np.float64)
        rows = np.ascontiguousarray(a.reshape(-1, 2))
        out = self._d.nearest_sites(rows)
        return int(out[0]) if a.ndim == 1 else out

    def locate(self, xy: Any) -> Any:
        """Where a point (or each row of an ``(n, 2)`` array) lies: 1 inside
        the domain, 0 on its boundary, -1 outside, -2 without a domain.

        >>> from shapely import box
        >>> voronoi(geometry=box(0, 0, 2, 2)).locate([[1, 1], [3, 3], [0, 1]]).tolist()
        [1, -1, 0]
        """
        a = np.asarray(xy, dtype=np.float64)
        out = self._d.locate(np.ascontiguousarray(a.reshape(-1, 2)))
        return int(out[0]) if a.ndim == 1 else out

    @cached_property
    def _locations(self):
        return self._d.locations()

    @property
    def vertex_locations(self) -> np.ndarray:
        """``(V,)`` where each vertex lies (codes as :meth:`locate`)."""
        return self._locations[0]

    @property
    def edge_locations(self) -> np.ndarray:
        """``(E,)`` where each edge lies (codes as :meth:`locate`)."""
        return self._locations[1]

    def topology(self, voronoi_pairs: bool = False, canonical_cuts: bool = False) -> str:
        """The canonical topology text of the Rust library (``EDGES`` and
        ``FACES`` sections naming sites ``P<site>`` and ``S<segment>``
        (an open arc, for now, by its site id as ``P<site>``),
        sorted; the same for every valid answer on the same input), with
        ``VPAIRS`` and ``VVERTICES`` when ``voronoi_pairs``.

        With ``canonical_cuts``, a degenerate vertex (four or more sites on
        one empty circle) is cut the one way its sites' coordinates decide,
        not the way the build happened to: the text of every build of the
        same input is then the same whatever the thread count (a large
        build on several threads numbers and cuts such vertices otherwise).

        >>> import numpy as np, segvoronoi
        >>> grid = np.array([[x, y] for x in range(3) for y in range(3)], dtype=float)
        >>> one = segvoronoi.voronoi(points=grid, threads=1).topology(canonical_cuts=True)
        >>> one == segvoronoi.voronoi(points=grid, threads=2).topology(canonical_cuts=True)
        True
        """
        return self._d.topology(bool(voronoi_pairs), bool(canonical_cuts))

    def medial_axis(
        self,
        *,
        tolerance: Optional[float] = None,
        corner_angle: Optional[float] = None,
        prune_spurs: Optional[float] = None,
    ) -> shapely.MultiLineString:
        """The medial axis of the domain (without one: every edge between
        two sites that is not a separator, rays cut off), with z the
        clearance; see :func:`segvoronoi.medial_axis`."""
        xyz, off = self._d.medial_axis(
            check_positive("tolerance", tolerance),
            check_corner_angle(corner_angle),
            check_positive("prune_spurs", prune_spurs),
        )
        return multilinestrings(xyz, off, np.array([0, len(off) - 1], dtype=np.int64))[0]

    def max_inscribed_circle(self) -> Optional[Tuple[float, float, float]]:
        """``(x, y, r)`` of the largest disk in the domain, None without one."""
        rows = self.inscribed_circles()
        return None if len(rows) == 0 else tuple(float(v) for v in rows[0])  # type: ignore[return-value]

    def inscribed_circles(self) -> np.ndarray:
        """``(k, 3)`` the largest disk of each connected component of the
        domain, largest first."""
        return self._d.inscribed_circles()

    def offsets(self, distances: Sequence[float], *, tolerance: Optional[float] = None) -> List[shapely.MultiPolygon]:
        """The offsets at several signed distances (see
        :func:`segvoronoi.offsets`), from this diagram.

        >>> from shapely import box
        >>> d = voronoi(geometry=box(0, 0, 10, 10))
        >>> [round(p.area, 6) for p in d.offsets([-1, -2], tolerance=1e-3)]
        [64.0, 36.0]
        """
        d = np.ascontiguousarray(np.atleast_1d(np.asarray(distances, dtype=np.float64)))
        xy, ring_off, poly_off, multi_off, failures = self._d.offsets(d, check_positive("tolerance", tolerance))
        if failures:
            raise_failure(failures[0])
        return list(multipolygons(xy, ring_off, poly_off, multi_off))

    def offset_pieces(self, distances: Sequence[float]) -> List[OffsetPieces]:
        """The offsets at several signed distances as exact lines and arcs
        (see :func:`segvoronoi.offset_pieces`), from this diagram.

        >>> from segvoronoi import CurvedPolygon
        >>> d = voronoi(geometry=CurvedPolygon([[-2, 0, 1], [2, 0, 1]]))  # a disc of radius 2
        >>> [p.loops[0][:, 7].tolist() for p in d.offset_pieces([-0.5, 1])]  # radii: two half circles
        [[1.5, 1.5], [3.0, 3.0]]
        """
        d = np.ascontiguousarray(np.atleast_1d(np.asarray(distances, dtype=np.float64)))
        *flat, failures = self._d.offset_pieces(d)
        if failures:
            raise_failure(failures[0])
        return offset_pieces_of(*flat, d)

    def offset(self, distance: float, *, tolerance: Optional[float] = None) -> shapely.MultiPolygon:
        """The offset at one signed distance (see :meth:`offsets`)."""
        return self.offsets([distance], tolerance=tolerance)[0]

    @property
    def stats(self) -> Dict[str, Any]:
        """The build's statistics: duplicate points, crossings split, ..."""
        return self._d.stats()

    def validate(self) -> None:
        """Checks every topological invariant; raises
        :class:`InternalError` naming the first that fails."""
        problem = self._d.validate()
        if problem is not None:
            raise_failure((-1, "Internal", problem, (), None))
