"""Many geometries in one call: the same results as one by one, on any
number of threads, with the GIL released, and interruptible by Ctrl-C
between geometries."""

import os
import signal
import threading
import time

import numpy as np
import pytest
import shapely

import segvoronoi
from conftest import random_polygon_with_holes


@pytest.fixture(scope="module")
def polygons():
    polys = [random_polygon_with_holes(s) for s in range(40)]
    polys.insert(5, None)
    polys.insert(9, shapely.MultiPolygon([polys[0], shapely.box(500, 500, 510, 520)]))
    return polys


def same(a, b):
    return all(
        (x is None and y is None) or shapely.equals_exact(x, y, 0)
        for x, y in zip(np.asarray(a, dtype=object).ravel(), np.asarray(b, dtype=object).ravel())
    )


def test_medial_axis_many_equals_one_by_one(polygons):
    one = [segvoronoi.medial_axis(p) for p in polygons]
    for threads in (1, 2, 3):
        many = segvoronoi.medial_axis(polygons, threads=threads)
        assert isinstance(many, np.ndarray) and many.shape == (len(polygons),)
        assert same(many, one)
    assert same(segvoronoi.medial_axis(np.array(polygons, dtype=object)), one)
    assert same(segvoronoi.medial_axis(tuple(polygons), corner_angle=150), [segvoronoi.medial_axis(p, corner_angle=150) for p in polygons])


def test_circles_and_offsets_many(polygons):
    circles = segvoronoi.max_inscribed_circle(polygons, threads=2)
    for p, row in zip(polygons, circles):
        one = segvoronoi.max_inscribed_circle(p)
        assert (one is None and np.isnan(row).all()) or tuple(row) == one
    table = segvoronoi.offsets(polygons, [-2.0, 1.0, 4.0], tolerance=1e-3, threads=2)
    assert table.shape == (len(polygons), 3)
    for p, row in zip(polygons, table):
        assert same(row, segvoronoi.offsets(p, [-2.0, 1.0, 4.0], tolerance=1e-3))
    single = segvoronoi.offset(polygons, 1.0, tolerance=1e-3, threads=1)
    assert same(single, table[:, 1])


def test_geopandas_series_keeps_index_and_crs(polygons):
    geopandas = pytest.importorskip("geopandas")
    s = geopandas.GeoSeries(polygons, index=[f"p{i}" for i in range(len(polygons))], crs="EPSG:3857")
    out = segvoronoi.medial_axis(s)
    assert isinstance(out, geopandas.GeoSeries) and list(out.index) == list(s.index) and out.crs == s.crs
    assert same(out.values, segvoronoi.medial_axis(polygons))
    frame = geopandas.GeoDataFrame({"name": list(s.index)}, geometry=s, index=s.index)
    assert same(segvoronoi.medial_axis(frame).values, out.values)


def test_gil_is_released(polygons):
    """A Python thread keeps running while a vectorised call works."""
    many = polygons * 30
    ticks = []
    stop = threading.Event()

    def count():
        while not stop.is_set():
            ticks.append(1)
            time.sleep(0.001)

    t = threading.Thread(target=count)
    t.start()
    time.sleep(0.01)
    before = len(ticks)
    start = time.perf_counter()
    segvoronoi.medial_axis(many, threads=1)
    took = time.perf_counter() - start
    during = len(ticks) - before
    stop.set()
    t.join()
    # with the GIL held the counter would not move at all during the call
    assert took < 0.05 or during > 5, (took, during)


@pytest.mark.skipif(not os.path.isdir("/proc/self/task"), reason="watches the threads in /proc")
def test_ctrl_c_interrupts_a_batch(countries):
    many = list(countries.values()) * 200  # tens of seconds of work
    # Send SIGINT once the call's worker thread exists: the call is then in
    # Rust with the GIL released (a signal that lands in Python code while
    # it packs the input may be swallowed by a weakref callback, as
    # KeyboardInterrupt in callbacks is, which would test nothing).
    sent, returned = threading.Event(), threading.Event()

    def interrupt(before):
        before = before | {str(threading.get_native_id())}  # not this thread
        while not returned.is_set() and not set(os.listdir("/proc/self/task")) - before:
            time.sleep(0.005)
        if not returned.wait(0.2):
            sent.set()
            os.kill(os.getpid(), signal.SIGINT)

    sender = threading.Thread(target=interrupt, args=(set(os.listdir("/proc/self/task")),))
    start = time.perf_counter()
    try:
        with pytest.raises(KeyboardInterrupt):
            sender.start()
            segvoronoi.medial_axis(many, threads=2)
    finally:
        returned.set()
        sender.join()
    took = time.perf_counter() - start
    assert sent.is_set() and took < 10, took


def test_diagrams_many(polygons):
    diagrams = segvoronoi.voronoi(geometry=polygons, threads=2)
    assert diagrams.shape == (len(polygons),)
    for p, d in zip(polygons, diagrams):
        assert d.topology() == segvoronoi.voronoi(geometry=p).topology()
        assert d.has_domain == (p is not None)
    bad = shapely.Polygon([(0, 0), (2, 2), (2, 0), (0, 2)])
    with pytest.raises(segvoronoi.IntersectingError) as info:
        segvoronoi.voronoi(geometry=[polygons[0], bad])
    assert info.value.geometry_index == 1
    assert segvoronoi.voronoi(geometry=[bad, polygons[0]], errors="coerce")[0] is None
    with pytest.raises(segvoronoi.InvalidArgumentError):
        segvoronoi.voronoi(points=[[0, 0]], geometry=polygons)
