"""Benchmarks of the Python package beside the peers a Python user would
pick, one run each (not part of CI):

1. centerlines of 1,000 polygons: segvoronoi.medial_axis (vectorised,
   default settings) against pygeoops.centerline and the `centerline`
   package, both with their default settings, on the same polygons;
2. offsets of the same polygons at 10 distances: segvoronoi.offsets
   against shapely's buffer (vectorised over the polygons, once per
   distance);
3. the Voronoi diagram of 100,000 segments: segvoronoi.voronoi against
   pyvoronoi (Boost.Polygon; integer input, added one by one as its API
   wants);
4. the vectorised medial axis on 1 and 2 threads.

    pip install ./python pygeoops centerline pyvoronoi
    python python/bench/bench.py [--polygons 1000] [--segments 100000] [--skip-centerline]

The polygons: random star-shaped polygons of 8 to 60 vertices with up to
five holes (the test suite's generator), about 200 units across. Prints a
Markdown table (python/BENCHMARKS.md has the figures of one run).
"""

from __future__ import annotations

import argparse
import math
import os
import platform
import sys
import time
from pathlib import Path
from typing import Callable, List

import numpy as np
import shapely

import segvoronoi

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
from conftest import random_polygon_with_holes  # noqa: E402


def timed(f: Callable[[], object]):
    start = time.perf_counter()
    out = f()
    return time.perf_counter() - start, out


def per_geometry(f, geoms) -> tuple:
    """Runs ``f`` on each geometry, counting failures (the peers raise on
    some inputs)."""
    out, failed = [], 0
    for g in geoms:
        try:
            out.append(f(g))
        except Exception:  # noqa: BLE001 - whatever the peer raises
            out.append(None)
            failed += 1
    return out, failed


def grid_segments(n: int, seed: int = 1) -> np.ndarray:
    """``n`` random segments on integer coordinates, each inside its own
    cell of a square grid, so none cross."""
    rng = np.random.default_rng(seed)
    side = math.ceil(math.sqrt(n))
    cells = np.stack(np.divmod(np.arange(n), side), axis=1) * 1000
    a = cells + rng.integers(0, 1000, (n, 2))
    b = cells + rng.integers(0, 1000, (n, 2))
    same = (a == b).all(axis=1)
    b[same, 0] = cells[same, 0] + (a[same, 0] + 1) % 1000
    return np.stack([a, b], axis=1).astype(np.float64)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--polygons", type=int, default=1000)
    ap.add_argument("--segments", type=int, default=100_000)
    ap.add_argument("--skip-centerline", action="store_true", help="skip the slow `centerline` package")
    ap.add_argument(
        "--sections",
        default="centerlines,offsets,diagram,threads",
        help="comma-separated sections to run (default: all)",
    )
    args = ap.parse_args()

    polygons = [random_polygon_with_holes(s) for s in range(args.polygons)]
    vertices = int(shapely.get_num_coordinates(np.array(polygons)).sum())
    rows: List[str] = []

    def row(task: str, tool: str, seconds: float, note: str = "") -> None:
        rows.append(f"| {task} | {tool} | {seconds:.3f} | {note} |")
        print(rows[-1], flush=True)

    print(f"# {len(polygons)} polygons, {vertices} vertices; load average {os.getloadavg()}", flush=True)
    print("| task | tool | seconds | note |\n|---|---|---|---|", flush=True)

    sections = set(args.sections.split(","))

    if "centerlines" in sections:
        centerlines(polygons, row, args.skip_centerline)
    if "offsets" in sections:
        offsets(polygons, row)
    if "diagram" in sections:
        diagram(args.segments, row)
    if "threads" in sections:
        for threads in (1, 2):
            wall, cpu = time.perf_counter(), time.process_time()
            segvoronoi.medial_axis(polygons, threads=threads)
            wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
            row("vectorised medial axis", f"threads={threads}", wall, f"{cpu / wall:.2f} cores busy on average")
    print(f"\n{platform.processor() or platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}, "
          f"segvoronoi {segvoronoi.__version__}; load average after {os.getloadavg()}")


def centerlines(polygons, row, skip_centerline: bool) -> None:
    t, axes = timed(lambda: segvoronoi.medial_axis(polygons))
    row("centerlines of %d polygons" % len(polygons), "segvoronoi.medial_axis (all cores)", t, f"{sum(len(a.geoms) for a in axes)} lines")
    t, _ = timed(lambda: segvoronoi.medial_axis(polygons, corner_angle=150, prune_spurs=1.5))
    row("", "segvoronoi.medial_axis, corner 150, spurs 1.5", t)
    t, _ = timed(lambda: [segvoronoi.medial_axis(p) for p in polygons])
    row("", "segvoronoi.medial_axis, a Python loop", t)
    try:
        import pygeoops

        t, (_, failed) = timed(lambda: per_geometry(pygeoops.centerline, polygons))
        row("", "pygeoops.centerline (defaults)", t, f"{failed} failed")
    except ImportError:
        row("", "pygeoops.centerline", math.nan, "not installed")
    if not skip_centerline:
        try:
            from centerline.geometry import Centerline

            t, (_, failed) = timed(lambda: per_geometry(Centerline, polygons))
            row("", "centerline.Centerline (defaults)", t, f"{failed} failed")
        except ImportError:
            row("", "centerline.Centerline", math.nan, "not installed")


def offsets(polygons, row) -> None:
    distances = [-8.0, -4.0, -2.0, -1.0, -0.5, 0.5, 1.0, 2.0, 4.0, 8.0]
    t, _ = timed(lambda: segvoronoi.offsets(polygons, distances))
    row("offsets at 10 distances", "segvoronoi.offsets (all cores)", t, "chords within 1e-4 of the diagonal")
    t, _ = timed(lambda: segvoronoi.offsets(polygons, distances, threads=1))
    row("", "segvoronoi.offsets, 1 thread", t)
    arr = np.array(polygons)
    t, _ = timed(lambda: [shapely.buffer(arr, d) for d in distances])
    row("", "shapely.buffer (quad_segs=8), per distance", t, "arcs of 8 chords per quarter")
    t, _ = timed(lambda: [shapely.buffer(arr, d, quad_segs=64) for d in distances])
    row("", "shapely.buffer (quad_segs=64), per distance", t, "error 0.0006 at d = 8 (ours: 0.003 at every d)")


def diagram(count: int, row) -> None:
    segs = grid_segments(count)
    t, d = timed(lambda: segvoronoi.voronoi(segments=segs))
    row(f"diagram of {len(segs)} segments", "segvoronoi.voronoi", t, f"{d.vertex_count} vertices")
    t, _ = timed(lambda: (d.vertices, d.edge_sites, d.vertex_sites))
    row("", "segvoronoi: vertex and edge arrays", t)
    try:
        import pyvoronoi

        def boost():
            pv = pyvoronoi.Pyvoronoi(1)
            for (x1, y1), (x2, y2) in segs.astype(np.int64).tolist():
                pv.AddSegment([[x1, y1], [x2, y2]])
            pv.Construct()
            return pv

        t, pv = timed(boost)
        row("", "pyvoronoi (add one by one, Construct)", t, f"{pv.CountVertices()} vertices")
        t, _ = timed(lambda: pv.GetVertices())
        row("", "pyvoronoi: GetVertices", t)
    except ImportError:
        row("", "pyvoronoi", math.nan, "not installed")


if __name__ == "__main__":
    main()
