"""Outlines with circular arcs: :class:`CurvedPolygon` in (a polygon whose
rings are DXF LWPOLYLINE vertices with bulges), :class:`OffsetPieces` out
(offsets as exact lines and arcs)."""

from __future__ import annotations

from typing import Any, List, NamedTuple, Optional, Sequence

import numpy as np

from ._errors import InvalidGeometryError

__all__ = ["CurvedPolygon", "OffsetPieces", "PIECE_COLUMNS"]


def as_bulged_ring(ring: Any, k: int) -> np.ndarray:
    """Ring ``k`` as a C-contiguous ``(n, 3)`` float64 array."""
    try:
        a = np.asarray(ring, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise InvalidGeometryError(f"ring {k}: expected rows of x, y, bulge: {e}") from e
    if a.ndim != 2 or a.shape[1] != 3:
        raise InvalidGeometryError(f"ring {k} must have shape (n, 3) (rows of x, y, bulge), got {a.shape}")
    return np.ascontiguousarray(a)


class CurvedPolygon:
    """A polygon bounded by straight pieces and circular arcs, as DXF's
    closed LWPOLYLINE: each ring an ``(n, 3)`` array of rows ``x, y,
    bulge``, where the bulge is that of the piece from this row's vertex
    to the next (the last row's to the first): 0 for a straight piece, else
    ``tan(θ/4)`` for the signed angle θ the arc sweeps (positive
    counter-clockwise; 1 is a half circle).

    Give it wherever the functions take a geometry — :func:`medial_axis`,
    :func:`max_inscribed_circle`, :func:`offsets`, :func:`offset_pieces`,
    :func:`voronoi` — alone or in a list with shapely geometries. The
    diagram is that of the arcs themselves, not of chords: the medial axis
    beside an arc is a conic, the offsets' pieces beside it are concentric
    arcs.

    The rings bound the domain by the even-odd rule, as the library reads
    them: holes inside the shell, islands inside holes, and either
    orientation. A ring needs three distinct vertices (or two and an arc:
    a half disc, a circle as two half circles); a repeated consecutive
    vertex, and a last vertex that repeats the first, are dropped. Rings may
    touch one another at points only. Errors name the ring and the vertex
    (:class:`InvalidCoordinateError`, :class:`InvalidPolygonError`,
    :class:`InvalidArcError`; :class:`IntersectingError` for pieces that
    cross). With ``split_crossings=True`` the rings may cross and overlap:
    they are cut where they meet, arcs into arcs, and bound the even-odd
    region of the pieces.

    >>> import segvoronoi
    >>> slot = CurvedPolygon([[0, 0, 0], [4, 0, 1], [4, 2, 0], [0, 2, 1]])  # two half circles
    >>> segvoronoi.max_inscribed_circle(slot)  # any point of the axis from (0, 1) to (4, 1)
    (4.0, 1.0, 1.0)
    >>> round(segvoronoi.offset(slot, -0.5, tolerance=1e-8).area, 6), round(4 + 3.141592653589793 / 4, 6)
    (4.785398, 4.785398)
    >>> washer = CurvedPolygon([[-2, 0, 1], [2, 0, 1]], holes=[[[-1, 0, 1], [1, 0, 1]]])
    >>> round(segvoronoi.max_inscribed_circle(washer)[2], 12)
    0.5
    """

    __slots__ = ("_rings",)

    def __init__(self, shell: Any, holes: Optional[Sequence[Any]] = None) -> None:
        rings = [shell, *(holes if holes is not None else ())]
        self._rings = tuple(as_bulged_ring(r, k) for k, r in enumerate(rings))

    @property
    def rings(self) -> List[np.ndarray]:
        """The rings, the shell first: ``(n, 3)`` arrays of x, y, bulge."""
        return list(self._rings)

    @property
    def shell(self) -> np.ndarray:
        """The first ring."""
        return self._rings[0]

    @property
    def holes(self) -> List[np.ndarray]:
        """The rings after the first."""
        return list(self._rings[1:])

    def __repr__(self) -> str:
        sizes = ", ".join(str(len(r)) for r in self._rings)
        return f"<segvoronoi.CurvedPolygon: {len(self._rings)} rings of {sizes} vertices>"

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, CurvedPolygon):
            return NotImplemented
        return len(self._rings) == len(other._rings) and all(
            np.array_equal(a, b) for a, b in zip(self._rings, other._rings)
        )

    __hash__ = None  # type: ignore[assignment]

    def __reduce__(self):  # picklable (Dask ships the input to workers)
        return (CurvedPolygon, (self._rings[0], list(self._rings[1:])))


PIECE_COLUMNS = ("kind", "x0", "y0", "x1", "y1", "cx", "cy", "radius", "bulge")
"""The columns of :attr:`OffsetPieces.loops`' arrays: kind (0 a line, 1 an
arc), start, end, and for an arc its centre, radius and bulge (NaN and 0
for a line)."""


class OffsetPieces(NamedTuple):
    """An offset as exact pieces (from :func:`offset_pieces`): closed loops
    of lines and circular arcs, the region on their left (outer loops
    counter-clockwise, holes clockwise).

    Each loop is a ``(k, 9)`` array, a row a piece, its columns
    :data:`PIECE_COLUMNS`: ``kind`` (0 a line, 1 an arc), start ``x0, y0``,
    end ``x1, y1`` (the next row's start; the last row's end is the first
    row's start), and for an arc its centre ``cx, cy``, ``radius`` and DXF
    ``bulge`` ``tan(sweep/4)`` (negative clockwise); a line has NaN there
    and bulge 0. Beside an arc of the input of radius R the offset's arcs
    are concentric with it at ``R + |d|`` on its convex side and
    ``R - |d|`` on its concave side; around a convex corner they are
    centred on the corner, of radius ``|d|``. A whole circle is two half
    circles (bulge ±1), so that every row's ends tell its arc.
    """

    distance: float
    """The signed distance."""
    loops: List[np.ndarray]
    """The loops, each ``(k, 9)``; a loop's parent comes before it."""
    holes: np.ndarray
    """``(L,)`` whether each loop bounds a hole (runs clockwise)."""
    parents: np.ndarray
    """``(L,)`` the loop each lies directly inside, -1 for an outermost one."""

    def bulged_rings(self) -> List[np.ndarray]:
        """Each loop as DXF LWPOLYLINE vertices: ``(k, 3)`` rows of x, y and
        the bulge of the piece to the next row (as :class:`CurvedPolygon`
        takes them)."""
        return [np.ascontiguousarray(loop[:, [1, 2, 8]]) for loop in self.loops]

    def curved_polygon(self) -> Optional[CurvedPolygon]:
        """The offset's region as a :class:`CurvedPolygon` (its loops, read
        even-odd), to offset or measure again; None when it is empty."""
        rings = self.bulged_rings()
        return CurvedPolygon(rings[0], rings[1:]) if rings else None


def offset_pieces_of(rows, loop_off, holes, parents, offset_off, distances) -> List[OffsetPieces]:
    """The compiled module's flat arrays as one :class:`OffsetPieces` per
    offset (offset ``o`` at ``distances[o % len(distances)]``)."""
    loops = np.split(rows, loop_off[1:-1]) if len(loop_off) > 1 else []
    out = []
    for o in range(len(offset_off) - 1):
        a, b = int(offset_off[o]), int(offset_off[o + 1])
        out.append(OffsetPieces(float(distances[o % len(distances)]), loops[a:b], holes[a:b], parents[a:b]))
    return out
