"""Output: the compiled module's flat arrays as shapely geometries, built
with ``shapely.from_ragged_array`` (no Python loop per geometry)."""

from __future__ import annotations

import numpy as np
import shapely
from shapely import GeometryType


def multilinestrings(xyz: np.ndarray, line_off: np.ndarray, geom_off: np.ndarray) -> np.ndarray:
    """MultiLineStrings with z (the clearance), one per geometry."""
    if len(xyz) == 0:  # shapely wants coordinates to infer the dimension
        return _empty(len(geom_off) - 1, "MULTILINESTRING Z EMPTY")
    return shapely.from_ragged_array(GeometryType.MULTILINESTRING, xyz, (line_off, geom_off))


def multipolygons(xy: np.ndarray, ring_off: np.ndarray, poly_off: np.ndarray, multi_off: np.ndarray) -> np.ndarray:
    """MultiPolygons, one per entry of ``multi_off`` but the last."""
    if len(xy) == 0:
        return _empty(len(multi_off) - 1, "MULTIPOLYGON EMPTY")
    return shapely.from_ragged_array(GeometryType.MULTIPOLYGON, xy, (ring_off, poly_off, multi_off))


def _empty(n: int, wkt: str) -> np.ndarray:
    out = np.empty(n, dtype=object)
    out[:] = [shapely.from_wkt(wkt) for _ in range(n)]
    return out
