"""The compiled GIF frame passes (``xaml3d.output.gif_pass``) give exactly what the numpy code
gives: the matte marks, the exact palette and its indices, hence the same GIF bytes."""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("numba")

from test_gif_stream import frames_of_every_kind  # noqa: E402

from xaml3d.output import gif_pass  # noqa: E402 (imports numba)
from xaml3d.output.animation import GifPlan, _gif_frame, gif_frame  # noqa: E402
from xaml3d.output.gif_matte import frame_marks  # noqa: E402


def frames() -> list[np.ndarray]:
    rng = np.random.default_rng(3)
    out = frames_of_every_kind()
    few = np.zeros((31, 47, 4), np.uint8)
    few[..., :3] = rng.integers(0, 256, (60, 3), dtype=np.uint8)[rng.integers(0, 60, (31, 47))]
    few[..., 3] = rng.choice([0, 255, 128], (31, 47), p=[0.2, 0.7, 0.1])
    out.append(few)
    exactly = np.zeros((16, 16, 4), np.uint8)  # 256 colours, no empty pixel
    exactly[..., 0] = np.arange(256).reshape(16, 16)
    exactly[..., 1] = 7
    exactly[..., 3] = 255
    out.append(exactly)
    many = rng.integers(0, 256, (20, 30, 4), dtype=np.uint8)  # too many colours: median cut
    out.append(many)
    edge = np.zeros((9, 9, 4), np.uint8)
    edge[:, :] = (10, 20, 30, 255)
    edge[0, :, 3] = 100  # partial alpha on the border only: never inside
    edge[4, 4, 3] = 100  # inside
    out.append(edge)
    out.append(np.zeros((5, 6, 4), np.uint8))  # nothing drawn
    return out


def both(fn, monkeypatch):
    compiled = fn()
    with monkeypatch.context() as m:
        m.setenv("XAML3D_KERNELS", "numpy")
        assert not gif_pass.available()
        plain = fn()
    return compiled, plain


@pytest.mark.parametrize("index", range(len(frames())))
def test_marks_and_palette_are_those_of_numpy(index, monkeypatch):
    f = frames()[index]
    assert gif_pass.available()  # numba is imported by this module
    compiled, plain = both(lambda: frame_marks(f), monkeypatch)
    assert compiled == plain
    for reserve in (False, True):
        (ci, ct), (pi, pt) = both(lambda r=reserve: _gif_frame(f, reserve=r), monkeypatch)
        assert ct == pt
        assert ci.tobytes() == pi.tobytes()
        assert ci.getpalette() == pi.getpalette()
    for plan in (GifPlan(), GifPlan(reserve=True), GifPlan(flatten=True)):
        cg, pg = both(lambda p=plan: gif_frame(f, p), monkeypatch)
        assert (cg.clear, cg.marks, cg.flattened, cg.reserve) == (
            pg.clear, pg.marks, pg.flattened, pg.reserve,
        )  # fmt: skip
        assert cg.image.tobytes() == pg.image.tobytes()
        assert cg.image.getpalette() == pg.image.getpalette()


def test_the_marks_of_a_known_frame():
    edge = frames()[-2]
    partial, translucent, seen, whole = frame_marks(edge)
    # 10 partial pixels (9 on the border, 1 inside) of 81 covered: inside 1 >= 0.01 * 81
    assert partial and translucent and seen != whole
    assert gif_pass.marks(edge, edge.view(np.uint32).reshape(-1), np.empty(81, np.uint32),
                          np.uint32(0))[:3] == (10, 1, 81)  # fmt: skip


def test_a_frame_without_partial_alpha_is_hashed_once(monkeypatch):
    """Opaque and empty (all-zero) pixels only: what GIF draws is the frame's very bytes, so
    its one digest serves as both (the same marks as numpy's two digests); an empty pixel
    holding a colour keeps the second digest."""
    import hashlib

    from xaml3d.output import gif_matte

    frame = np.zeros((6, 7, 4), np.uint8)
    frame[1:5, 2:6] = (200, 30, 40, 255)
    stray = frame.copy()
    stray[0, 0] = (9, 0, 0, 0)
    hashed = []
    real = hashlib.sha1

    def counted(data, **kw):
        hashed.append(bytes(data))
        return real(data, **kw)

    for f, count in ((frame, 1), (stray, 2)):
        monkeypatch.setattr(gif_matte.hashlib, "sha1", counted)
        del hashed[:]
        compiled = frame_marks(f)
        assert len(hashed) == count
        monkeypatch.setattr(gif_matte.hashlib, "sha1", real)
        compiled2, plain = both(lambda f=f: frame_marks(f), monkeypatch)
        assert compiled == compiled2 == plain
        assert compiled[3] == real(f.tobytes()).digest()
