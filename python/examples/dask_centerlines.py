"""Centerlines of a partitioned GeoDataFrame on a Dask cluster.

The layer is split into partitions, `segvoronoi.medial_axis` runs on each
in a worker process (one thread each: the cluster supplies the
parallelism), and the pieces are put back in order. The result is the same
as the single-process call, geometry for geometry:

    pip install ./python geopandas "dask[distributed]"
    python python/examples/dask_centerlines.py            # a local cluster of 2 workers
    python python/examples/dask_centerlines.py tcp://scheduler:8786

Any GeoDataFrame works; this one repeats the repository's three countries
(examples/data/countries.geojson) to make a layer of 300 polygons.
"""

from __future__ import annotations

import functools
import sys
from pathlib import Path

import geopandas
import numpy as np
from dask.distributed import Client, LocalCluster

import segvoronoi

DATA = Path(__file__).resolve().parents[2] / "examples" / "data" / "countries.geojson"


def layer(copies: int = 100) -> geopandas.GeoDataFrame:
    countries = geopandas.read_file(DATA)
    return geopandas.GeoDataFrame(
        {"name": list(countries["name"]) * copies},
        geometry=list(countries.geometry) * copies,
        crs=countries.crs,
    )


def distributed_centerlines(client: Client, frame: geopandas.GeoDataFrame, partitions: int, **options) -> geopandas.GeoSeries:
    """The medial axis of every geometry of ``frame``, computed partition by
    partition on the cluster; same index and CRS as ``frame``."""
    job = functools.partial(segvoronoi.medial_axis, threads=1, **options)
    pieces = [frame.geometry.iloc[p] for p in np.array_split(np.arange(len(frame)), partitions)]
    futures = client.map(job, pieces)
    return geopandas.GeoSeries(
        np.concatenate([f.values for f in client.gather(futures)]), index=frame.index, crs=frame.crs
    )


def run(client: Client, copies: int = 100, partitions: int = 8) -> geopandas.GeoSeries:
    frame = layer(copies)
    options = dict(corner_angle=150, prune_spurs=1.5)
    distributed = distributed_centerlines(client, frame, partitions, **options)
    single = segvoronoi.medial_axis(frame.geometry, **options)
    assert distributed.geom_equals_exact(single, 0).all(), "the cluster's result differs"
    return distributed


def main() -> None:
    if len(sys.argv) > 1:
        with Client(sys.argv[1]) as client:
            result = run(client)
    else:
        with LocalCluster(n_workers=2, threads_per_worker=1, processes=True) as cluster, Client(cluster) as client:
            result = run(client)
    print(f"{len(result)} centerlines, equal to the single-process call")


if __name__ == "__main__":
    main()
