"""Shared inputs of the tests: the repository's glyph and country outlines
(tests/data/*.rings), random polygons with holes, polygons with straight
vertices, and the C tests' Boost.Polygon-format fixtures."""

from __future__ import annotations

import functools
import math
from pathlib import Path
from typing import List, Tuple

import numpy as np
import pytest
import shapely
from shapely.geometry import Polygon

REPO = Path(__file__).resolve().parents[2]
DATA = REPO / "tests" / "data"
FIXTURES = REPO / "c_tests" / "fixtures"


def read_rings(path: Path) -> List[np.ndarray]:
    """A .rings file: comments, ``rings N``, then per ring a count and that
    many ``x y`` lines."""
    lines = [l for l in path.read_text().splitlines() if l.strip() and not l.startswith("#")]
    assert lines[0].startswith("rings ")
    n, k, rings = int(lines[0].split()[1]), 1, []
    for _ in range(n):
        count = int(lines[k])
        rings.append(np.array([[float(v) for v in l.split()] for l in lines[k + 1 : k + 1 + count]]))
        k += 1 + count
    return rings


def even_odd(rings: List[np.ndarray]):
    """The even-odd region of rings, as the library reads them, as a valid
    shapely (Multi)Polygon for GEOS to compare with."""
    return functools.reduce(shapely.symmetric_difference, [Polygon(r) for r in rings])


def read_boost(path: Path) -> Tuple[np.ndarray, np.ndarray]:
    """Boost.Polygon's voronoi text: a count of points, the points, a count
    of segments, the segments."""
    nums = path.read_text().split()
    n = int(nums[0])
    pts = np.array(nums[1 : 1 + 2 * n], dtype=float).reshape(n, 2)
    m = int(nums[1 + 2 * n])
    segs = np.array(nums[2 + 2 * n : 2 + 2 * n + 4 * m], dtype=float).reshape(m, 2, 2)
    return pts, segs


def star(rng: np.random.Generator, centre, radius: float, n: int, spread: float = 0.4) -> np.ndarray:
    """A star-shaped ring: n vertices at sorted random angles, radii in
    ``radius * [1 - spread, 1]``."""
    angles = np.sort(rng.uniform(0, 2 * math.pi, n))
    r = radius * rng.uniform(1 - spread, 1, n)
    return np.column_stack([centre[0] + r * np.cos(angles), centre[1] + r * np.sin(angles)])


def random_polygon_with_holes(seed: int) -> Polygon:
    """A star polygon with up to five disjoint star holes well inside it."""
    rng = np.random.default_rng(seed)
    outer = star(rng, (0.0, 0.0), 100.0, int(rng.integers(8, 60)))
    holes: List[np.ndarray] = []
    for _ in range(12):
        if len(holes) == 5:
            break
        c = rng.uniform(-45, 45, 2)
        hole = star(rng, c, rng.uniform(3, 12), int(rng.integers(3, 20)))
        hp = Polygon(hole)
        if not hp.is_valid or not Polygon(outer).buffer(-1).contains(hp) or any(hp.distance(Polygon(h)) < 1 for h in holes):
            continue
        holes.append(hole)
    poly = Polygon(outer, holes)
    assert poly.is_valid, shapely.is_valid_reason(poly)
    return poly


def integer_polygon_with_straight_vertices(seed: int) -> Polygon:
    """A random polygon with holes on integer coordinates, scaled by 4 so
    that every edge has lattice points inside, and with one of them
    inserted into every edge: vertices of exactly 180 degrees."""
    poly = random_polygon_with_holes(seed)

    def split(ring: np.ndarray) -> np.ndarray:
        ring = 4 * np.round(ring[:-1] * 10)
        out = []
        for a, b in zip(ring, np.roll(ring, -1, axis=0)):
            out.append(a)
            out.append(a + (b - a) * (int(seed + len(out)) % 3 + 1) / 4)  # exact: b - a is a multiple of 4
        return np.array(out)

    result = Polygon(split(np.asarray(poly.exterior.coords)), [split(np.asarray(h.coords)) for h in poly.interiors])
    assert result.is_valid
    return result


GLYPHS = sorted(DATA.glob("glyph_*.rings"))
COUNTRIES = sorted(DATA.glob("dcw_*.rings"))


@pytest.fixture(scope="session")
def glyphs():
    return {p.stem: even_odd(read_rings(p)) for p in GLYPHS}


@pytest.fixture(scope="session")
def countries():
    return {p.stem: even_odd(read_rings(p)) for p in COUNTRIES}
