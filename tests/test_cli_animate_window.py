"""``xaml3d animate --window``: each frame is the whole window at its time, as ``render --window
--time t`` draws it (a storyboard that moves a viewport over its Canvas moves it over the
window), in every output format, with the workers of the other frames; and the warning ANIM016
plain ``animate`` gives when a viewport's own RenderTransform moves it. The CLI runs as a real
process.

Scene: ``tests/reference/layout/window-viewport-moves.xaml``, a 64x48 viewport (blue over lime,
cols 16..47) sliding 64 px right over a white 128x48 Canvas in 1 s; its reference PNGs at 0,
0.5 and 1 s were checked by eye.
"""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest
from conftest import CORPUS, ROOT, needs_corpus
from PIL import Image, ImageSequence

CASE = ROOT / "tests" / "reference" / "layout" / "window-viewport-moves.xaml"


def xaml3d(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "xaml3d", *map(str, args)], capture_output=True,
                          text=True, cwd=cwd, timeout=300)  # fmt: skip


def _reference(t: str) -> np.ndarray:
    name = CASE.stem + ("" if t == "0" else f"@{t}s") + ".png"
    return np.asarray(Image.open(CASE.parent / name).convert("RGBA"))


def _blue_cols(rgb: np.ndarray) -> tuple[int, int]:
    blue = (rgb[..., 2] > 200) & (rgb[..., 0] < 60) & (rgb[..., 1] < 60)
    cols = np.nonzero(blue.any(axis=0))[0]
    return int(cols.min()), int(cols.max())


@pytest.mark.parametrize("jobs", ["1", "2"])
def test_frames_are_the_window_at_each_time(tmp_path, jobs):
    out = tmp_path / "frames"
    r = xaml3d("animate", CASE, "-o", f"{out}/", "--window", "--fps", "2", "--duration", "1.5",
               "--jobs", jobs)  # fmt: skip
    assert r.returncode == 0, r.stderr
    assert "Traceback" not in r.stderr and "ANIM016" not in r.stderr
    names = sorted(p.name for p in out.iterdir())
    assert names == ["frame_0000.png", "frame_0001.png", "frame_0002.png"]
    for name, t in zip(names, ("0", "0.5", "1"), strict=True):
        frame = np.asarray(Image.open(out / name).convert("RGBA"))
        # the very pixels render --window --time t draws (its reference, checked by eye)
        assert np.array_equal(frame, _reference(t)), (name, t)


def test_every_format_holds_the_window_frames(tmp_path):
    expected = [(16, 47), (48, 79)]  # the viewport's blue at 0 s and 0.5 s
    for suffix in (".gif", ".png", ".webp"):
        out = tmp_path / f"moves{suffix}"
        r = xaml3d("animate", CASE, "-o", out, "--window", "--fps", "2", "--duration", "1",
                   "--jobs", "1", "-q")  # fmt: skip
        assert r.returncode == 0, (suffix, r.stderr)
        with Image.open(out) as im:
            assert im.size == (128, 48), suffix
            frames = [np.asarray(f.convert("RGB")) for f in ImageSequence.Iterator(im)]
        assert len(frames) == 2, suffix
        found = [_blue_cols(f) for f in frames]
        # WebP is lossy: its edges may move by a pixel
        assert np.abs(np.subtract(found, expected)).max() <= (1 if suffix == ".webp" else 0), (
            suffix, found)  # fmt: skip
        # the Canvas's white around the viewport, not a transparent or cut-off box
        assert (frames[1][:, 0] > 240).all() and (frames[0][:, 127] > 240).all(), suffix


def test_plain_animate_warns_that_the_viewport_moves_itself(tmp_path):
    r = xaml3d("animate", CASE, "-o", tmp_path / "box.png", "--fps", "4", "--jobs", "1")
    assert r.returncode == 0, r.stderr
    [line] = [x for x in r.stderr.splitlines() if "ANIM016" in x]
    # at the animation of the transform, naming it and the way out
    assert line.startswith(f"{CASE}:7:9: warning ANIM016 viewport 0 is moved by its own "
                           "RenderTransform (slide.X)")  # fmt: skip
    assert "--window" in line
    with Image.open(tmp_path / "box.png") as im:
        assert im.size == (64, 48)  # the viewport's own box, as before


def test_no_warning_when_the_transform_does_not_change_in_the_frames(tmp_path):
    # from 1 s on the animation holds its end value: nothing moves in these frames
    r = xaml3d("animate", CASE, "-o", tmp_path / "still.png", "--start", "1", "--duration",
               "0.5", "--fps", "4", "--jobs", "1")  # fmt: skip
    assert r.returncode == 0, r.stderr
    assert "ANIM016" not in r.stderr


@pytest.mark.parametrize(
    ("extra", "message"),
    [
        (["--viewport", "0"], "--window draws every viewport"),
        (["-W", "100"], "use --window-size"),
        (["--stereo", "anaglyph"], "not --window"),
    ],
)
def test_window_refuses_options_of_one_viewport(tmp_path, extra, message):
    out = tmp_path / "x.gif"
    r = xaml3d("animate", CASE, "-o", out, "--window", *extra)
    assert r.returncode == 2
    assert message in r.stderr and "Traceback" not in r.stderr
    assert not out.exists()


def test_window_size_lays_the_window_out_again(tmp_path):
    out = tmp_path / "wide.png"
    r = xaml3d("animate", CASE, "-o", out, "--window", "--window-size", "160x60", "--fps", "2",
               "--duration", "0.5", "--jobs", "1", "-q")  # fmt: skip
    assert r.returncode == 0, r.stderr
    with Image.open(out) as im:
        assert im.size == (160, 60)


@needs_corpus
def test_corpus_009_cube_follows_its_path_over_the_window(tmp_path):
    scene = CORPUS / "009_wpfsamples-animating-along-path.xaml"
    app = CORPUS / "008_wpfsamples-animationexamples-app-resources.xaml"
    out = tmp_path / "frames"
    r = xaml3d("animate", scene, "-r", app, "-o", f"{out}/", "--window", "--fps", "1",
               "--duration", "3", "-q")  # fmt: skip
    assert r.returncode == 0, r.stderr
    for i, t in enumerate(("0", "1", "2")):
        still = tmp_path / f"at-{t}.png"
        r = xaml3d("render", scene, "-r", app, "--window", "--time", t, "-o", still, "-q")
        assert r.returncode == 0, r.stderr
        frame = np.asarray(Image.open(out / f"frame_{i:04d}.png"))
        assert np.array_equal(frame, np.asarray(Image.open(still))), t
    # the cube's grey checker is in a different place in each frame, none of them empty
    boxes = []
    for i in range(3):
        a = np.asarray(Image.open(out / f"frame_{i:04d}.png").convert("RGB")).astype(int)
        grey = (abs(a[..., 0] - a[..., 1]) < 8) & (a[..., 0] > 90) & (a[..., 0] < 220)
        rows, cols = np.nonzero(grey)
        assert cols.size > 2000
        boxes.append((int(np.median(cols)), int(np.median(rows))))
    assert len(set(boxes)) == 3


def test_picture_moves_by_its_own_or_an_ancestors_transform():
    from xaml3d import load
    from xaml3d.animation.moment import picture_moves

    around = load(CASE.parent / "window-around-animated.xaml")  # a Border slides around it
    track, own = picture_moves(around, 0, [0.0, 0.25, 0.5])
    assert (track.target, own) == ("slide.X", False)
    moves = load(CASE)
    track, own = picture_moves(moves, 0, [0.0, 0.5])
    assert (track.target, own) == ("slide.X", True)
    assert picture_moves(moves, 0, [1.0, 1.5]) is None  # held at its end: nothing moves
    assert picture_moves(moves, 0, [0.0]) is None  # one frame shows no motion
