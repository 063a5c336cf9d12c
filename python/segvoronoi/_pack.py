"""Input: shapely geometries, ``__geo_interface__`` objects and numpy
arrays packed into the flat arrays the compiled module reads.

A call on G geometries becomes one :class:`Packed`: per geometry its points,
free segments, polygons (rings of points), polylines and curved polygons
(:class:`CurvedPolygon`: rings of x, y, bulge), as coordinate arrays with
offsets (the layout of ``shapely.to_ragged_array``). Packing is
vectorised with shapely's array functions, so a column of a million parcels
costs no Python loop per parcel.
"""

from __future__ import annotations

from typing import Any, NamedTuple, Optional, Sequence, Union

import numpy as np
import shapely

from ._curved import CurvedPolygon
from ._errors import InvalidGeometryError

__all__ = ["Packed", "pack", "is_many", "as_geometry_array"]

_EMPTY_XY = np.zeros((0, 2), dtype=np.float64)
_ZERO = np.zeros(1, dtype=np.int64)

# shapely's type ids
_POINT, _LINESTRING, _LINEARRING, _POLYGON = 0, 1, 2, 3
_MULTI = (4, 5, 6, 7)  # MultiPoint, MultiLineString, MultiPolygon, GeometryCollection


class Packed(NamedTuple):
    """The arrays of ``_native`` calls, in the order of its ``PackedArgs``."""

    pt_xy: np.ndarray
    gpt: np.ndarray
    seg: np.ndarray
    gseg: np.ndarray
    poly_xy: np.ndarray
    ring_off: np.ndarray
    poly_off: np.ndarray
    gpoly: np.ndarray
    line_xy: np.ndarray
    line_off: np.ndarray
    gline: np.ndarray
    curve_xyb: np.ndarray
    curve_ring_off: np.ndarray
    curve_poly_off: np.ndarray
    gcurve: np.ndarray


def is_many(obj: Any) -> bool:
    """Whether ``obj`` is a collection of geometries (a list, tuple, numpy
    array, pandas or GeoPandas Series, GeoDataFrame or GeometryArray) rather
    than one geometry."""
    if isinstance(obj, (shapely.Geometry, dict, CurvedPolygon)):
        return False
    if isinstance(obj, (list, tuple, np.ndarray)):
        return True
    return type(obj).__module__.split(".")[0] in ("pandas", "geopandas")


def _to_shapely(obj: Any) -> Optional[shapely.Geometry]:
    """One geometry as shapely (None stays None: an empty input; a
    :class:`CurvedPolygon` stays itself)."""
    if obj is None or isinstance(obj, (shapely.Geometry, CurvedPolygon)):
        return obj
    if isinstance(obj, dict) or hasattr(obj, "__geo_interface__"):
        mapping = obj if isinstance(obj, dict) else obj.__geo_interface__
        if mapping.get("type") == "Feature":
            mapping = mapping.get("geometry")
            if mapping is None:
                return None
        if mapping.get("type") == "FeatureCollection":
            parts = [_to_shapely(f) for f in mapping.get("features", [])]
            return shapely.GeometryCollection([p for p in parts if p is not None])
        try:
            return shapely.geometry.shape(mapping)
        except Exception as e:  # shapely raises several kinds here
            raise InvalidGeometryError(f"cannot read __geo_interface__ {mapping.get('type')!r}: {e}") from e
    raise InvalidGeometryError(
        f"expected a shapely geometry or an object with __geo_interface__, got {type(obj).__name__}"
    )


def as_geometry_array(many: Any) -> np.ndarray:
    """A collection of geometries as a 1-d object array of shapely
    geometries, :class:`CurvedPolygon` or None."""
    if hasattr(many, "geometry") and type(many).__name__ == "GeoDataFrame":
        many = many.geometry
    values = getattr(many, "values", many)  # pandas: the array, not the index
    if isinstance(values, np.ndarray) and values.dtype == object and values.ndim == 1:
        arr = values
    else:
        arr = np.empty(len(values), dtype=object)
        arr[:] = list(values)
    if all(g is None or isinstance(g, (shapely.Geometry, CurvedPolygon)) for g in arr):
        return arr
    out = np.empty(len(arr), dtype=object)
    out[:] = [_to_shapely(g) for g in arr]
    return out


def _explode(geoms: np.ndarray):
    """Single-part geometries and, for each, the index of its geometry in
    ``geoms``, in order: multi-part geometries and collections (nested too)
    are taken apart; empty parts are dropped."""
    parts = geoms
    index = np.arange(len(geoms))
    keep = ~shapely.is_missing(parts)
    parts, index = parts[keep], index[keep]
    while True:
        types = shapely.get_type_id(parts)
        multi = np.isin(types, _MULTI)
        if not multi.any():
            break
        sub, sub_index = shapely.get_parts(parts[multi], return_index=True)
        owner = index[multi][sub_index]
        parts = np.concatenate([parts[~multi], sub])
        index = np.concatenate([index[~multi], owner])
        order = np.argsort(index, kind="stable")
        parts, index = parts[order], index[order]
    nonempty = ~shapely.is_empty(parts)
    return parts[nonempty], index[nonempty]


def _offsets(counts: np.ndarray) -> np.ndarray:
    return np.concatenate([_ZERO, np.cumsum(counts, dtype=np.int64)])


def _per_geometry(index: np.ndarray, n: int) -> np.ndarray:
    """Offsets of items owned by geometries ``index`` (sorted) among ``n``."""
    return _offsets(np.bincount(index, minlength=n)) if len(index) else np.zeros(n + 1, dtype=np.int64)


def _coords(geoms: np.ndarray):
    """The 2-d coordinates of ``geoms`` (z dropped) and their offsets."""
    if len(geoms) == 0:
        return _EMPTY_XY, _ZERO.copy()
    xy = shapely.get_coordinates(geoms).astype(np.float64, copy=False)
    return np.ascontiguousarray(xy), _offsets(shapely.get_num_coordinates(geoms))


def as_points(points: Any) -> np.ndarray:
    """An ``(n, 2)`` float64 array (any strides and dtype accepted)."""
    a = np.asarray(points, dtype=np.float64)
    if a.size == 0:
        return _EMPTY_XY
    if a.ndim == 1 and a.shape[0] == 2:
        a = a.reshape(1, 2)
    if a.ndim != 2 or a.shape[1] != 2:
        raise InvalidGeometryError(f"points must have shape (n, 2), got {a.shape}")
    return np.ascontiguousarray(a)


def as_segments(segments: Any) -> np.ndarray:
    """An ``(m, 4)`` float64 array from ``(m, 2, 2)`` or ``(m, 4)``."""
    a = np.asarray(segments, dtype=np.float64)
    if a.size == 0:
        return np.zeros((0, 4), dtype=np.float64)
    if a.ndim == 3 and a.shape[1:] == (2, 2):
        a = a.reshape(len(a), 4)
    if a.ndim != 2 or a.shape[1] != 4:
        raise InvalidGeometryError(f"segments must have shape (m, 2, 2) or (m, 4), got {a.shape}")
    return np.ascontiguousarray(a)


def pack(geoms: Union[Sequence[Any], np.ndarray]) -> Packed:
    """Packs ``geoms`` (shapely, :class:`CurvedPolygon` or None, see
    :func:`as_geometry_array`)."""
    arr = geoms if isinstance(geoms, np.ndarray) else as_geometry_array(geoms)
    n = len(arr)
    curved = np.array([isinstance(g, CurvedPolygon) for g in arr], dtype=bool)
    curves = _pack_curved(arr[curved], np.flatnonzero(curved), n)
    if curved.any():
        arr = arr.copy()
        arr[curved] = None
    parts, owner = _explode(arr)
    types = shapely.get_type_id(parts)

    pts = types == _POINT
    pt_xy, _ = _coords(parts[pts])
    gpt = _per_geometry(owner[pts], n)

    polys = types == _POLYGON
    rings, ring_owner = (
        shapely.get_rings(parts[polys], return_index=True) if polys.any() else (parts[:0], owner[:0])
    )
    poly_xy, ring_off = _coords(rings)
    poly_off = _per_geometry(ring_owner, int(polys.sum()))
    gpoly = _per_geometry(owner[polys], n)

    lines = (types == _LINESTRING) | (types == _LINEARRING)
    line_xy, line_off = _coords(parts[lines])
    gline = _per_geometry(owner[lines], n)

    seg = np.zeros((0, 4), dtype=np.float64)
    gseg = np.zeros(n + 1, dtype=np.int64)
    return Packed(pt_xy, gpt, seg, gseg, poly_xy, ring_off, poly_off, gpoly, line_xy, line_off, gline, *curves)


def _pack_curved(polygons: np.ndarray, owner: np.ndarray, n: int):
    """The rows, ring offsets, polygon offsets and per-geometry offsets of
    curved polygons ``polygons`` of geometries ``owner`` (sorted) among
    ``n``."""
    rings = [r for p in polygons for r in p._rings]
    xyb = np.concatenate(rings) if rings else np.zeros((0, 3), dtype=np.float64)
    ring_off = _offsets(np.array([len(r) for r in rings], dtype=np.int64))
    poly_off = _offsets(np.array([len(p._rings) for p in polygons], dtype=np.int64))
    return np.ascontiguousarray(xyb), ring_off, poly_off, _per_geometry(owner, n)


def pack_one(geom: Any) -> Packed:
    """Packs a single geometry (shapely, ``__geo_interface__`` or None)."""
    arr = np.empty(1, dtype=object)
    arr[0] = _to_shapely(geom)
    return pack(arr)


def pack_many(many: Any) -> Packed:
    """Packs a collection of geometries."""
    return pack(as_geometry_array(many))
