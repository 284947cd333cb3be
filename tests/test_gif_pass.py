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
        assert cg.same_picture(pg)  # the same box, colour table and compressed indices


def test_the_marks_of_a_known_frame():
    edge = frames()[-2]
    partial, translucent, seen, whole = frame_marks(edge)
    # 10 partial pixels (9 on the border, 1 inside) of 81 covered: inside 1 >= 0.01 * 81
    assert partial and translucent and seen != whole
    assert gif_pass.marks(edge, edge.view(np.uint32).reshape(-1), np.empty(81, np.uint32),
                          np.uint32(0), np.empty(81, np.uint8),
                          np.empty(81, np.int64))[:3] == (10, 1, 81)  # fmt: skip


def test_the_rest_digest_tells_frames_that_differ_only_in_alpha(monkeypatch):
    """The second digest covers the alpha plane and the empty pixels holding a colour: among
    frames GIF draws alike (the same first digest) it differs exactly when the frames do, the
    same with numpy and the compiled pass."""
    base = np.zeros((6, 7, 4), np.uint8)
    base[1:5, 2:6] = (200, 30, 40, 255)
    faded = base.copy()
    faded[2, 3, 3] = 128  # only alpha differs
    stray = base.copy()
    stray[0, 0] = (9, 0, 0, 0)  # an empty pixel holding a colour
    stray2 = base.copy()
    stray2[0, 1] = (9, 0, 0, 0)
    marks = {}
    for name, f in (("base", base), ("faded", faded), ("stray", stray), ("stray2", stray2)):
        compiled, plain = both(lambda f=f: frame_marks(f), monkeypatch)
        assert compiled == plain
        marks[name] = compiled
    assert len({m[2] for m in marks.values()}) == 1  # GIF draws them alike
    assert len({m[3] for m in marks.values()}) == 4  # yet all four differ
    assert frame_marks(base.copy()) == marks["base"]


def test_the_changed_box_is_that_of_numpy(monkeypatch):
    from xaml3d.output.gif_frames import _changed_box, gif_picture

    rng = np.random.default_rng(8)
    colours = rng.integers(0, 256, (50, 4), dtype=np.uint8)
    colours[:, 3] = 255
    base = colours[rng.integers(0, 50, (23, 31))]  # few colours: each kept exactly
    pairs = []
    for box in ((0, 0, 1, 1), (5, 7, 9, 12), (30, 22, 31, 23), (0, 10, 31, 11), (3, 0, 4, 23)):
        other = base.copy()
        x0, y0, x1, y1 = box
        other[y0:y1, x0:x1] = (1, 2, 3, 255)  # a colour of its own
        pairs.append((other, box))
    pairs.append((base.copy(), None))
    first = gif_picture(base)
    for other, box in pairs:
        pic = gif_picture(other)
        compiled, plain = both(lambda p=pic: _changed_box(p, first), monkeypatch)
        assert compiled == plain
        want = (0, 0, -1, -1) if box is None else (box[0], box[1], box[2] - 1, box[3] - 1)
        assert compiled == want
