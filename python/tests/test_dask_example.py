"""The scale-out example on a local cluster of two worker processes:
results equal to the single-process call (the example asserts it)."""

import importlib.util

import pytest

from conftest import REPO

pytest.importorskip("geopandas")
pytest.importorskip("dask.distributed")


def test_two_worker_cluster():
    from dask.distributed import Client, LocalCluster

    spec = importlib.util.spec_from_file_location("dask_centerlines", REPO / "python" / "examples" / "dask_centerlines.py")
    example = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(example)
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with Client(cluster) as client:
            assert len(client.scheduler_info()["workers"]) == 2
            result = example.run(client, copies=30, partitions=4)
            # the partitions ran on both workers' processes
            assert len(result) == 90 and not result.is_empty.any()
