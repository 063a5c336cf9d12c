"""The exceptions of segvoronoi: one class per kind of library error.

The compiled module reports a failure as a tuple ``(geometry, kind, message,
indices, point)`` and :func:`raise_failure` raises the class of its kind, so
the classes live here, in Python: documented, typed, and picklable (Dask and
multiprocessing send exceptions between processes).
"""

from __future__ import annotations

from typing import Optional, Sequence, Tuple

__all__ = [
    "Error",
    "InvalidCoordinateError",
    "TooLargeError",
    "IntersectingError",
    "InvalidPolygonError",
    "InvalidArcError",
    "InvalidArgumentError",
    "InvalidGeometryError",
    "OutOfMemoryError",
    "InternalError",
    "UnsupportedRangeError",
]


class Error(Exception):
    """Base class of every segvoronoi error.

    Attributes:
        message: what went wrong, naming the offending input indices.
        indices: the input indices involved (see each subclass).
        geometry_index: in a vectorised call, the index of the geometry
            that failed; ``None`` otherwise.
    """

    kind = "Unknown"

    def __init__(
        self,
        message: str,
        indices: Sequence[int] = (),
        geometry_index: Optional[int] = None,
        point: Optional[Tuple[float, float]] = None,
    ) -> None:
        self.message = message
        self.indices = tuple(int(i) for i in indices)
        self.geometry_index = geometry_index
        self.point = point
        where = "" if geometry_index is None else f"geometry {geometry_index}: "
        super().__init__(where + message)

    def __reduce__(self):  # keep every attribute across pickling
        return (type(self), (self.message, self.indices, self.geometry_index, self.point))


class InvalidCoordinateError(Error, ValueError):
    """A coordinate is NaN or infinite; the message names where (point,
    segment, or polygon, ring and point index)."""

    kind = "InvalidCoordinate"


class TooLargeError(Error, ValueError):
    """More sites than the 32-bit ids of a diagram can hold (600 million
    points and segment endpoints)."""

    kind = "TooLarge"


class IntersectingError(Error, ValueError):
    """Two segments cross or overlap (pass ``split_crossings=True`` to split
    them instead), or an arc crosses, overlaps or touches another arc, a
    segment or a point inside it.

    Attributes:
        indices: the two segments' input indices: for ``voronoi(segments=S)``
            the rows of ``S``; for geometries, the order in which their
            rings and lines were added (the message names polygon and ring).
            With an arc, the message says what each index is (``arcs 0 and
            1 cross``, ``arc 0 and segment 2 cross``, ``point 3 lies on arc
            1``) and the arcs' indices are rows of ``arcs``.
        point: a point both segments share ``(x, y)``, where they cross or
            where their overlap begins (rounded to float); None for a
            conflict with an arc.
    """

    kind = "Intersecting"


class InvalidPolygonError(Error, ValueError):
    """A polygon ring has fewer than three distinct points; ``indices`` is
    ``(polygon, ring)`` within the geometry."""

    kind = "InvalidPolygon"


class InvalidArcError(Error, ValueError):
    """A row of ``arcs`` is not a circular arc: a zero, NaN or infinite
    bulge (a zero bulge is a straight segment: pass it in ``segments``), a
    non-finite coordinate, equal endpoints, or a circle beyond the range of
    float; the message says which. ``indices`` is ``(row,)``."""

    kind = "InvalidArc"


class InvalidArgumentError(Error, ValueError):
    """An argument is out of its domain: a distance that is zero, NaN or
    infinite, a tolerance that is not positive, ``threads`` < 1, and so on."""

    kind = "InvalidArgument"


class InvalidGeometryError(Error, TypeError):
    """The input is not a geometry segvoronoi can read: not shapely, not
    ``__geo_interface__``, or a numpy array of the wrong shape."""

    kind = "InvalidGeometry"


class OutOfMemoryError(Error, MemoryError):
    """Memory for the input could not be allocated."""

    kind = "OutOfMemory"


class InternalError(Error, RuntimeError):
    """The construction could not complete a valid diagram: a bug in
    segvoronoi, not in the input. Please report the input."""

    kind = "Internal"


class UnsupportedRangeError(Error, ValueError):
    """The coordinates span more than 2^480 (1e300 beside 1, say) and the
    construction at that span could not complete; round the smallest
    differences away or split the input."""

    kind = "UnsupportedRange"


_BY_KIND = {
    cls.kind: cls
    for cls in (
        InvalidCoordinateError,
        TooLargeError,
        IntersectingError,
        InvalidPolygonError,
        InvalidArcError,
        InvalidArgumentError,
        InvalidGeometryError,
        OutOfMemoryError,
        InternalError,
        UnsupportedRangeError,
    )
}

Failure = Tuple[int, str, str, Sequence[int], Optional[Tuple[float, float]]]


def error_of(failure: Failure, vectorised: bool) -> Error:
    """The exception for a failure tuple of the compiled module."""
    geometry, kind, message, indices, point = failure
    cls = _BY_KIND.get(kind, Error)
    index = int(geometry) if vectorised and geometry >= 0 else None
    return cls(message, indices, index, None if point is None else (float(point[0]), float(point[1])))


def raise_failure(failure: Failure, vectorised: bool = False) -> None:
    """Raises the exception of a failure tuple."""
    raise error_of(failure, vectorised)
