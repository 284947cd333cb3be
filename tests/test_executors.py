"""Frames and batches rendered on any ``concurrent.futures.Executor``: a spawned process pool
and a Dask cluster's executor (``client.get_executor()``) give exactly the serial run's images.

The Scene goes to the workers pickled with each task (render_frames), or a path goes and is
read there (render_batch). The cluster is local, two worker processes of one thread each, and is
closed when the module's tests are done.
"""

from __future__ import annotations

import multiprocessing
import pickle
from concurrent.futures import ProcessPoolExecutor

import numpy as np
import pytest
from conftest import ROOT

import xaml3d

SPIN = ROOT / "samples" / "spinning-cube.xaml"
TIMES = [0.0, 0.3, 0.7, 1.1, 1.6]
SIZE = {"width": 48, "height": 36}


@pytest.fixture(scope="module")
def spin():
    return xaml3d.load(SPIN)


@pytest.fixture(scope="module")
def serial(spin):
    return [(t, r.rgba, r.depth) for t, r in xaml3d.render_frames(spin, TIMES, **SIZE)]


@pytest.fixture(scope="module")
def dask_executor():
    distributed = pytest.importorskip("dask.distributed", reason="dask[distributed] not installed")
    cluster = distributed.LocalCluster(
        n_workers=2, processes=True, threads_per_worker=1, dashboard_address=None
    )
    client = distributed.Client(cluster)
    try:
        yield client.get_executor()
    finally:
        client.close()
        cluster.close()


def same_frames(got, want) -> None:
    assert [t for t, *_ in got] == TIMES
    for (_, rgba, depth), (_, rgba0, depth0) in zip(got, want, strict=True):
        assert np.array_equal(rgba, rgba0) and np.array_equal(depth, depth0)


def test_the_frames_compared_differ_and_the_scene_pickles_small(spin, serial):
    # the comparisons below would prove nothing on a still scene
    assert not np.array_equal(serial[0][1], serial[2][1])
    assert len(pickle.dumps(spin)) < 64_000


def test_render_frames_on_a_spawned_process_pool(spin, serial):
    spawn = multiprocessing.get_context("spawn")
    with ProcessPoolExecutor(2, mp_context=spawn) as pool:
        frames = xaml3d.render_frames(spin, TIMES, executor=pool, **SIZE)
        got = [(t, r.rgba, r.depth) for t, r in frames]
    same_frames(got, serial)


def test_render_frames_on_a_dask_cluster(spin, serial, dask_executor):
    frames = xaml3d.render_frames(spin, TIMES, executor=dask_executor, **SIZE)
    got = [(t, r.rgba, r.depth) for t, r in frames]
    same_frames(got, serial)


def test_render_batch_on_a_dask_cluster(spin, dask_executor):
    items = [spin, SPIN, ROOT / "samples" / "cube.xaml"]
    want = [r.rgba for r in xaml3d.render_batch(items, time=0.5, **SIZE)]
    got = [r.rgba for r in xaml3d.render_batch(items, executor=dask_executor, time=0.5, **SIZE)]
    assert len(got) == 3 and all(np.array_equal(a, b) for a, b in zip(got, want, strict=True))
    assert not np.array_equal(want[0], want[2])


def test_a_bad_item_raises_its_error_from_the_cluster(dask_executor, tmp_path):
    bad = tmp_path / "bad.xaml"
    bad.write_text("<Viewport3D")
    with pytest.raises(xaml3d.XamlError) as exc:
        list(xaml3d.render_batch([SPIN, bad], executor=dask_executor, **SIZE))
    assert exc.value.code == "XML001"
