"""segvoronoi: exact Voronoi diagrams of points, line segments and circular
arcs.

Medial axes with clearance, largest inscribed circles and offsets of shapely
and numpy input, from the Rust library segvoronoi (the topology-oriented
method: the construction never fails on degenerate input, and every sign is
decided exactly). One geometry, or many at once on every core:

>>> import segvoronoi
>>> from shapely import Polygon
>>> L = Polygon([(0, 0), (6, 0), (6, 2), (2, 2), (2, 6), (0, 6)])
>>> x, y, r = segvoronoi.max_inscribed_circle(L)
>>> round(r, 12) == round(2 * 2**0.5 / (1 + 2**0.5), 12)  # touches the inner corner
True
>>> axis = segvoronoi.medial_axis(L, corner_angle=80)
>>> len(axis.geoms)
1
>>> [round(p.area, 3) for p in segvoronoi.offsets(L, [-0.5, 0.5], tolerance=1e-5)]
[9.054, 32.732]
>>> round(L.buffer(-0.5, quad_segs=64).area, 3), round(L.buffer(0.5, quad_segs=64).area, 3)
(9.054, 32.732)

Polygons with circular arcs (DXF bulges) are :class:`segvoronoi.CurvedPolygon`;
:func:`segvoronoi.offset_pieces` gives offsets as exact lines and arcs.

Errors are subclasses of :class:`segvoronoi.Error`.
"""

from ._api import max_inscribed_circle, medial_axis, offset, offset_pieces, offsets
from ._curved import PIECE_COLUMNS, CurvedPolygon, OffsetPieces
from ._diagram import Diagram, voronoi
from ._errors import (
    Error,
    IntersectingError,
    InternalError,
    InvalidArcError,
    InvalidArgumentError,
    InvalidCoordinateError,
    InvalidGeometryError,
    InvalidPolygonError,
    OutOfMemoryError,
    TooLargeError,
    UnsupportedRangeError,
)
from ._native import VERSION as _RUST_VERSION

__version__ = "0.2.0"
__all__ = [
    "medial_axis",
    "max_inscribed_circle",
    "offset",
    "offsets",
    "offset_pieces",
    "voronoi",
    "CurvedPolygon",
    "OffsetPieces",
    "PIECE_COLUMNS",
    "Diagram",
    "Error",
    "IntersectingError",
    "InternalError",
    "InvalidArcError",
    "InvalidArgumentError",
    "InvalidCoordinateError",
    "InvalidGeometryError",
    "InvalidPolygonError",
    "OutOfMemoryError",
    "TooLargeError",
    "UnsupportedRangeError",
]
