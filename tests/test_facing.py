"""Facing (camera-pipeline.md section 6, step 2): the compiled loop (``setup_kernels.facing``)
against ``draw._facing``'s numpy expressions, sign for sign, and when each is used."""

from __future__ import annotations

import numpy as np
import pytest

from xaml3d.render import accel, draw


def _clip_coordinates(n=4000, seed=4):
    rng = np.random.default_rng(seed)
    clip = rng.normal(size=(n, 4)) * rng.choice([1e-300, 1e-5, 1.0, 1e5, 1e300], size=(n, 1))
    clip[::7, 3] = 0.0  # on the eye plane
    clip[1::11] = 0.0  # every coordinate 0: the scale falls back to 1
    idx = rng.integers(0, n, size=(3 * n, 3))
    idx[::5, 2] = idx[::5, 0]  # edge-on: a repeated vertex, det exactly 0
    collinear = clip[idx[1::9, 0]] + clip[idx[1::9, 1]]  # a vertex on the others' line
    clip[idx[1::9, 2]] = collinear  # (exact zeros only sometimes: rounding decides)
    return clip, idx


@pytest.mark.parametrize("mirror", [False, True])
def test_compiled_facing_equals_numpy(mirror, monkeypatch):
    clip, idx = _clip_coordinates()
    monkeypatch.setenv(accel.ENV, "numpy")
    want = draw._facing(clip, idx, mirror)
    monkeypatch.setenv(accel.ENV, "numba")
    accel.plan(0.0, 0)  # loads the kernels
    got = draw._facing(clip, idx, mirror)
    for a, b in zip(want, got, strict=True):
        assert a.dtype == b.dtype == np.bool_
        assert np.array_equal(a, b)
    front, back = got
    assert front.any() and back.any() and (~front & ~back).any()  # edge-on ones: neither
    assert not (front & back).any()


def test_compiled_facing_only_for_big_meshes_once_numba_is_imported(monkeypatch):
    """Before the frame's plan, the kernels are loaded for a mesh's facing only when numba is
    imported already and the mesh is big (``accel.SET_UP_WORTH``)."""
    import numba  # noqa: F401 (imported, as the reader's scanner does for a big file)

    monkeypatch.setenv(accel.ENV, "auto")
    monkeypatch.setattr(accel, "_kernels", None)
    assert accel.for_set_up(accel.SET_UP_WORTH - 1) is None
    assert accel.for_set_up(accel.SET_UP_WORTH) is not None
    monkeypatch.setenv(accel.ENV, "numpy")
    assert accel.for_set_up(10**9) is None
