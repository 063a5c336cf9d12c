"""The functions on geometries: medial axis, largest inscribed circle,
offsets. Each takes one geometry or many (a list, an array, a GeoSeries);
many are computed on every core with the GIL released. A geometry is a
shapely geometry, anything with ``__geo_interface__``, or a
:class:`CurvedPolygon` (rings with circular arcs)."""

from __future__ import annotations

import math
from typing import Any, Iterable, Optional, Tuple

import numpy as np
import shapely

from . import _native
from ._curved import OffsetPieces, offset_pieces_of
from ._errors import InvalidArgumentError, error_of
from ._pack import is_many, pack_many, pack_one
from ._shapes import multilinestrings, multipolygons

__all__ = ["medial_axis", "max_inscribed_circle", "offset", "offsets", "offset_pieces"]

Circle = Tuple[float, float, float]


def check_positive(name: str, value: Optional[float]) -> Optional[float]:
    """``value`` as a float if it is None or finite and positive."""
    if value is None:
        return None
    v = float(value)
    if not (math.isfinite(v) and v > 0):
        raise InvalidArgumentError(f"{name} must be finite and positive, got {value!r}")
    return v


def check_corner_angle(value: Optional[float]) -> Optional[float]:
    if value is None:
        return None
    v = float(value)
    if not (0 <= v <= 180):
        raise InvalidArgumentError(f"corner_angle must be in degrees between 0 and 180, got {value!r}")
    return v


def check_threads(threads: Optional[int]) -> Optional[int]:
    if threads is None:
        return None
    if isinstance(threads, bool) or not isinstance(threads, (int, np.integer)) or threads < 1:
        raise InvalidArgumentError(f"threads must be a positive integer or None, got {threads!r}")
    return int(threads)


def check_errors(errors: str) -> str:
    if errors not in ("raise", "coerce"):
        raise InvalidArgumentError(f"errors must be 'raise' or 'coerce', got {errors!r}")
    return errors


def _raise_or_coerce(failures: list, many: bool, errors: str) -> list:
    """Raises the first failure (by geometry) unless ``errors='coerce'``
    with many geometries; returns the indices of the geometries that
    failed."""
    if failures and (errors == "raise" or not many):
        raise min((error_of(f, many) for f in failures), key=lambda e: e.geometry_index or 0)
    return [f[0] for f in failures]


def _finish(results: np.ndarray, failures: list, many: bool, errors: str, like: Any) -> Any:
    """Raises the first failure (or with ``errors='coerce'`` sets the failed
    results to None); one result for one geometry, else an array, or a
    Series with the input's index for a pandas/GeoPandas input."""
    for g in _raise_or_coerce(failures, many, errors):
        results[g] = None
    if not many:
        return results[0]
    return _like(results, like)


def _like(results: np.ndarray, like: Any) -> Any:
    """``results`` as a Series/GeoSeries when ``like`` is one (same index,
    and the CRS for geometries), else the array."""
    module = type(like).__module__.split(".")[0]
    if module == "geopandas" and results.ndim == 1 and all(
        r is None or isinstance(r, shapely.Geometry) for r in results
    ):
        import geopandas

        return geopandas.GeoSeries(results, index=like.index, crs=getattr(like, "crs", None))
    if module in ("pandas", "geopandas") and results.ndim == 1:
        import pandas

        return pandas.Series(results, index=like.index)
    return results


def _packed(geom: Any):
    many = is_many(geom)
    return (pack_many(geom) if many else pack_one(geom)), many


def medial_axis(
    geom: Any,
    *,
    tolerance: Optional[float] = None,
    corner_angle: Optional[float] = None,
    prune_spurs: Optional[float] = None,
    split_crossings: bool = False,
    threads: Optional[int] = None,
    errors: str = "raise",
) -> Any:
    """The medial axis of a geometry, with the clearance as z.

    The axis is the exact one — straight pieces and parabolic arcs of the
    Voronoi diagram inside the polygons — sampled within ``tolerance``; z
    at every point is its clearance, the distance to the boundary.

    Args:
        geom: a shapely geometry or anything with ``__geo_interface__``
            (polygons bound the domain by the even-odd rule; lines and
            points are obstacles, and without polygons the whole diagram's
            edges between them are the axis), a :class:`CurvedPolygon`
            (rings with circular arcs: beside an arc the axis is a conic,
            sampled the same way), or a list, array or GeoSeries of them.
        tolerance: chord tolerance of the arcs, in input units (default
            1e-4 of the input's bounding-box diagonal).
        corner_angle: drop the branches into convex corners whose interior
            angle is above this many degrees (the spurs of flattened
            curves; 150 suits digitised arcs).
        prune_spurs: drop leaf branches shorter than ``k`` times the
            clearance at their junction.
        split_crossings: split input that crosses itself instead of raising
            :class:`IntersectingError`.
        threads: at most this many threads for many geometries (default:
            every core).
        errors: ``'raise'`` (the first failure by index) or ``'coerce'``
            (None for the geometries that failed) for many geometries.

    Returns:
        A ``MultiLineString`` with z, a line per chain of the axis (for
        many: an array of them, or a GeoSeries for a GeoSeries).

    >>> from shapely import box
    >>> axis = medial_axis(box(0, 0, 4, 2))
    >>> axis.geom_type, len(axis.geoms)
    ('MultiLineString', 5)
    >>> max(z for line in axis.geoms for _, _, z in line.coords)
    1.0
    >>> medial_axis(box(0, 0, 4, 2), corner_angle=80).wkt  # without the corners' branches
    'MULTILINESTRING Z ((3 1 1, 1 1 1))'
    >>> [len(a.geoms) for a in medial_axis([box(0, 0, 4, 2), None], threads=2)]
    [5, 0]

    A slot (two half circles of radius 1): its axis is the segment between
    their centres, at clearance 1:

    >>> from segvoronoi import CurvedPolygon
    >>> medial_axis(CurvedPolygon([[0, 0, 0], [4, 0, 1], [4, 2, 0], [0, 2, 1]])).wkt
    'MULTILINESTRING Z ((4 1 1, 0 1 1))'
    """
    tolerance = check_positive("tolerance", tolerance)
    corner_angle = check_corner_angle(corner_angle)
    prune_spurs = check_positive("prune_spurs", prune_spurs)
    threads, errors = check_threads(threads), check_errors(errors)
    packed, many = _packed(geom)
    xyz, line_off, geom_off, failures = _native.medial_axis_batch(
        packed, tolerance, corner_angle, prune_spurs, bool(split_crossings), threads
    )
    return _finish(multilinestrings(xyz, line_off, geom_off), failures, many, errors, geom)


def max_inscribed_circle(
    geom: Any,
    *,
    split_crossings: bool = False,
    threads: Optional[int] = None,
    errors: str = "raise",
) -> Any:
    """The largest circle inside the polygons: ``(x, y, r)``.

    Exact up to the rounding of one Voronoi vertex (it is the vertex of the
    medial axis with the largest clearance), not a grid search.

    Returns:
        ``(x, y, r)``, or None when ``geom`` has no polygon; for many
        geometries an ``(n, 3)`` array, NaN where there is none.

    >>> from shapely import box
    >>> max_inscribed_circle(box(0, 0, 6, 6))
    (3.0, 3.0, 3.0)
    >>> max_inscribed_circle([box(0, 0, 6, 6), box(1, 1, 3, 3)])
    array([[3., 3., 3.],
           [2., 2., 1.]])

    A :class:`CurvedPolygon`: a 6 x 4 rectangle with corners rounded to
    radius 1 about a hole of radius 0.5 at (2, 2). The circle touches the
    bottom, the right side and the hole: centre ``(6 - r, r)``, ``r`` the
    root of ``(4 - r)² + (r - 2)² = (r + 0.5)²``:

    >>> from segvoronoi import CurvedPolygon
    >>> q = 0.41421356237309503  # tan(pi / 8): a quarter circle
    >>> shell = [[1, 0, 0], [5, 0, q], [6, 1, 0], [6, 3, q], [5, 4, 0], [1, 4, q], [0, 3, 0], [0, 1, q]]
    >>> x, y, r = max_inscribed_circle(CurvedPolygon(shell, holes=[[[1.5, 2, 1], [2.5, 2, 1]]]))
    >>> abs(r - (13 - 90**0.5) / 2) < 1e-12, abs(x - (6 - r)) < 1e-12, abs(y - r) < 1e-12
    (True, True, True)
    """
    threads, errors = check_threads(threads), check_errors(errors)
    packed, many = _packed(geom)
    rows, failures = _native.inscribed_circle_batch(packed, bool(split_crossings), threads)
    for g in _raise_or_coerce(failures, many, errors):
        rows[g] = np.nan
    if many:
        return rows
    x, y, r = (float(v) for v in rows[0])
    return None if math.isnan(r) else (x, y, r)


def _distances(distances: Iterable[float]) -> np.ndarray:
    d = np.atleast_1d(np.asarray(distances, dtype=np.float64))
    if d.ndim != 1:
        raise InvalidArgumentError(f"distances must be one-dimensional, got shape {d.shape}")
    return np.ascontiguousarray(d)


def offsets(
    geom: Any,
    distances: Iterable[float],
    *,
    tolerance: Optional[float] = None,
    split_crossings: bool = False,
    threads: Optional[int] = None,
    errors: str = "raise",
) -> Any:
    """The offsets of a geometry at several distances, sharing the work.

    One Voronoi diagram serves every distance, and an index of its edges by
    clearance is built once per side, so each further distance costs about
    the size of its own output. The sign is shapely's ``buffer``'s:
    negative shrinks the polygons, positive grows them; lines and points
    only grow (a negative distance gives an empty region, as ``buffer``
    does). Arcs are cut into chords within ``tolerance`` (default 1e-4 of
    the bounding-box diagonal); the polygons are valid, nested as the exact
    loops are.

    Returns:
        A list of ``MultiPolygon``, one per distance; for many geometries an
        ``(n, len(distances))`` object array.

    >>> from shapely import box
    >>> shrunk, grown = offsets(box(0, 0, 4, 2), [-0.5, 1.0], tolerance=1e-3)
    >>> round(shrunk.area, 9), round(grown.area, 3)
    (3.0, 23.138)

    A :class:`CurvedPolygon`'s arcs are cut within ``tolerance`` too (see
    :func:`offset_pieces` for the exact arcs); a disc of radius 2:

    >>> from segvoronoi import CurvedPolygon
    >>> disc = CurvedPolygon([[-2, 0, 1], [2, 0, 1]])
    >>> [round(p.area / 3.141592653589793, 5) for p in offsets(disc, [-1, 1], tolerance=1e-7)]
    [1.0, 9.0]
    """
    tolerance = check_positive("tolerance", tolerance)
    threads, errors = check_threads(threads), check_errors(errors)
    d = _distances(distances)
    packed, many = _packed(geom)
    xy, ring_off, poly_off, multi_off, failures = _native.offsets_batch(
        packed, d, tolerance, bool(split_crossings), threads
    )
    flat = multipolygons(xy, ring_off, poly_off, multi_off)
    table = flat.reshape(-1, len(d)) if len(d) else np.empty((len(packed.gpt) - 1, 0), dtype=object)
    for g in _raise_or_coerce(failures, many, errors):
        table[g, :] = None
    return table if many else list(table[0])


def offset_pieces(
    geom: Any,
    distances: Iterable[float],
    *,
    split_crossings: bool = False,
    threads: Optional[int] = None,
    errors: str = "raise",
) -> Any:
    """The offsets of a geometry as exact pieces: lines and circular arcs,
    for whoever keeps arcs as arcs (CAM tool paths, DXF, G2/G3).

    The same offsets as :func:`offsets` (same signs, same loops), not cut
    into chords: each an :class:`OffsetPieces`, its loops ``(k, 9)`` arrays
    of rows ``kind, x0, y0, x1, y1, cx, cy, radius, bulge`` (kind 0 a line,
    1 an arc; :data:`PIECE_COLUMNS`), their nesting and which are holes.
    ``bulged_rings()`` gives each loop as LWPOLYLINE vertices (x, y,
    bulge), ``curved_polygon()`` the region as a :class:`CurvedPolygon`.

    Returns:
        A list of :class:`OffsetPieces`, one per distance; for many
        geometries an ``(n, len(distances))`` object array (None where a
        geometry failed, with ``errors='coerce'``).

    A slot of half-width 1 shrunk by 0.25: two lines and two half circles
    of radius 0.75 about the slot's centres (bulge 1: counter-clockwise):

    >>> from segvoronoi import CurvedPolygon
    >>> slot = CurvedPolygon([[0, 0, 0], [4, 0, 1], [4, 2, 0], [0, 2, 1]])
    >>> (inner,) = offset_pieces(slot, [-0.25])
    >>> loop = inner.loops[0]
    >>> loop[:, 0].tolist()  # kinds
    [1.0, 0.0, 1.0, 0.0]
    >>> loop[loop[:, 0] == 1][:, 5:].tolist()  # cx, cy, radius, bulge
    [[4.0, 1.0, 0.75, 1.0], [0.0, 1.0, 0.75, 1.0]]
    >>> inner.holes.tolist(), inner.parents.tolist()
    ([False], [-1])
    """
    threads, errors = check_threads(threads), check_errors(errors)
    d = _distances(distances)
    packed, many = _packed(geom)
    *flat, failures = _native.offset_pieces_batch(packed, d, bool(split_crossings), threads)
    table = np.empty((len(packed.gpt) - 1, len(d)), dtype=object)
    for k, pieces in enumerate(offset_pieces_of(*flat, d)):
        table[divmod(k, len(d))] = pieces  # one object: not unpacked as a sequence
    for g in _raise_or_coerce(failures, many, errors):
        table[g, :] = None
    return table if many else list(table[0])


def offset(
    geom: Any,
    distance: float,
    *,
    tolerance: Optional[float] = None,
    split_crossings: bool = False,
    threads: Optional[int] = None,
    errors: str = "raise",
) -> Any:
    """The offset of a geometry at one signed distance, as a
    ``MultiPolygon`` (see :func:`offsets`; for many geometries an array).

    >>> from shapely import Point
    >>> disk = offset(Point(0, 0), 1.0, tolerance=1e-6)
    >>> abs(disk.area - 3.141592) < 1e-5
    True
    """
    table = offsets(
        geom,
        [distance],
        tolerance=tolerance,
        split_crossings=split_crossings,
        threads=threads,
        errors=errors,
    )
    if isinstance(table, list):
        return table[0]
    return _like(table[:, 0], geom)
