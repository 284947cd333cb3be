"""GIF frames written as their difference from the frame before (``xaml3d.output.gif_frames``):
the files decode, in Pillow and in a compositor that follows the GIF specification as browsers
do, to exactly the frames and display times of the same frames written standing alone."""

from __future__ import annotations

import struct
import subprocess
import sys
from dataclasses import replace
from io import BytesIO
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from xaml3d.output.animation import (
    GifPicture,
    encode_gif,
    gif_frame,
    gif_picture,
    link_gif,
    save_animation,
    write_gif,
)

ROOT = Path(__file__).resolve().parent.parent


def blocks(data: bytes) -> tuple[tuple[int, int], list[dict]]:
    """The logical screen size and every image of a GIF file written by xaml3d (no global
    colour table): each image's box, local colour table, indices, transparent index, disposal
    and display time."""
    assert data[:6] == b"GIF89a"
    width, height, flags = struct.unpack("<HHB", data[6:11])
    assert not flags & 0x80
    pos, control, images = 13, {}, []

    def sub_blocks(at: int) -> int:
        while data[at]:
            at += 1 + data[at]
        return at + 1

    while data[pos] != 0x3B:
        if data[pos] == 0x21:
            if data[pos + 1] == 0xF9:
                packed, delay, index = struct.unpack("<BHB", data[pos + 3 : pos + 7])
                control = {"disposal": packed >> 2 & 7, "ms": 10 * delay,
                           "transparent": index if packed & 1 else None}  # fmt: skip
            pos = sub_blocks(pos + 2)
            continue
        assert data[pos] == 0x2C
        x, y, w, h, packed = struct.unpack("<HHHHB", data[pos + 1 : pos + 10])
        assert packed & 0x80
        size = 3 << ((packed & 7) + 1)
        table = data[pos + 10 : pos + 10 + size]
        end = sub_blocks(pos + 11 + size)
        alone = (
            b"GIF89a"
            + struct.pack("<HHBBB", w, h, 0, 0, 0)
            + b","
            + struct.pack("<HHHHB", 0, 0, w, h, packed)
            + data[pos + 10 : end]
            + b";"
        )
        with Image.open(BytesIO(alone)) as im:  # fmt: skip
            indices = np.array(im)
        images.append({"box": (x, y, w, h), "table": table, "indices": indices, **control})
        control, pos = {}, end
    return (width, height), images


def composited(path: Path) -> list[tuple[bytes, int]]:
    """The frames a browser shows (a canvas cleared to transparent; each image drawn over it
    but for its transparent pixels, then disposed: 0 and 1 keep it, 2 clears its box to
    transparent) with their display times."""
    (width, height), images = blocks(path.read_bytes())
    canvas = np.zeros((height, width, 4), np.uint8)
    out = []
    for image in images:
        x, y, w, h = image["box"]
        table = np.frombuffer(image["table"], np.uint8).reshape(-1, 3)
        idx = image["indices"]
        drawn = idx != (-1 if image["transparent"] is None else image["transparent"])
        region = canvas[y : y + h, x : x + w]
        region[drawn, :3] = table[idx[drawn]]
        region[drawn, 3] = 255
        out.append((canvas.tobytes(), image["ms"]))
        assert image["disposal"] in (1, 2)
        if image["disposal"] == 2:
            region[:] = 0
    return out


def pillows(path: Path) -> list[tuple[bytes, int]]:
    """The frames Pillow decodes (each converted to RGBA) with their display times."""
    with Image.open(path) as im:
        out = []
        for i in range(im.n_frames):
            im.seek(i)
            out.append((np.array(im.convert("RGBA")).tobytes(), im.info["duration"]))
    return out


def standing_alone(frames, path: Path, total: float) -> None:
    """The frames written as the writer wrote them before: every frame standing alone."""
    write_gif(lambda plan: (gif_frame(f, plan) for f in frames), path, total, len(frames))


def in_runs(frames, size: int):
    """The frames as worker processes give them: quantized, and linked in runs."""

    def source(plan):
        for i in range(0, len(frames), size):
            yield from link_gif(gif_picture(f, plan) for f in frames[i : i + size])

    return source


def scene(background, colour=(220, 30, 40), size=(40, 52)) -> list[np.ndarray]:
    """Frames of a square moving over ``background`` (RGBA), one of them repeated, one
    where only a small part changes, and one showing the first frame again."""
    h, w = size
    frames = []
    for k in (0, 3, 3, 6, 6, 9, 0):
        f = np.empty((h, w, 4), np.uint8)
        f[:] = background
        f[10:24, 5 + k : 19 + k] = (*colour, 255)
        f[10:24, 4 + k] = (*colour, 128)  # an antialiased edge
        frames.append(f)
    frames[4] = frames[4].copy()
    frames[4][30:33, 40:44] = (0, 0, 255, 255)  # a small change far from the square
    return frames


def noisy(count: int = 5) -> list[np.ndarray]:
    """Opaque frames of more than 256 colours (the median cut), a block moving over them."""
    rng = np.random.default_rng(4)
    base = np.full((36, 44, 4), 255, np.uint8)
    base[..., :3] = rng.integers(0, 256, (36, 44, 3), dtype=np.uint8)
    out = []
    for k in range(count):
        f = base.copy()
        f[5:15, 3 + 4 * k : 13 + 4 * k, :3] = (10 * k, 200, 90)
        out.append(f)
    return out


CASES = {
    "opaque": scene((250, 250, 240, 255)),
    "transparent": scene((0, 0, 0, 0)),
    "translucent": [
        f * np.array([1, 1, 1, 0], np.uint8) + np.array([0, 0, 0, 140], np.uint8)
        for f in scene((10, 80, 10, 255))
    ],  # fmt: skip
    "median-cut": noisy(),
    "one-frame": scene((250, 250, 240, 255))[:1],
}


@pytest.mark.parametrize("name", CASES)
@pytest.mark.parametrize("run", [1, 2, 3, 100])
def test_frames_cropped_to_their_difference_decode_as_frames_standing_alone(name, run, tmp_path):
    frames = CASES[name]
    total = 0.1 * len(frames)
    standing_alone(frames, tmp_path / "alone.gif", total)
    write_gif(in_runs(frames, run), tmp_path / "linked.gif", total, len(frames))
    want = composited(tmp_path / "alone.gif")
    assert composited(tmp_path / "linked.gif") == want
    assert pillows(tmp_path / "linked.gif") == pillows(tmp_path / "alone.gif")
    # the same file whichever process linked which frames, and from a list of arrays
    save_animation(frames, tmp_path / "list.gif", total)
    assert (tmp_path / "list.gif").read_bytes() == (tmp_path / "linked.gif").read_bytes()
    assert sum(ms for _, ms in want) == round(1000 * total)
    if name in ("opaque", "transparent"):
        assert len(want) == len(frames) - 1  # the repeated frame merged, its time added
        assert [ms for _, ms in want][1] == 200


def test_opaque_frames_are_written_as_the_box_that_changed(tmp_path):
    frames = CASES["opaque"]
    write_gif(in_runs(frames, 3), tmp_path / "a.gif", 0.7, len(frames))
    standing_alone(frames, tmp_path / "b.gif", 0.7)
    _, images = blocks((tmp_path / "a.gif").read_bytes())
    # The square shows columns 4 + k..18 + k of rows 10..23 (its edge included). Frame 1 over
    # frame 0: columns 4..21; frame 2 (a repeat) merged; frame 3 over 1: 7..24; frame 4: the
    # blue patch alone; frame 5: the square 10..27 and the patch gone; frame 6: 4..27.
    assert [im["box"] for im in images] == [(0, 0, 52, 40), (4, 10, 18, 14), (7, 10, 18, 14),
                                            (40, 30, 4, 3), (10, 10, 34, 23),
                                            (4, 10, 24, 14)]  # fmt: skip
    assert {im["disposal"] for im in images} == {1}
    assert all(im["transparent"] is None for im in images)
    assert (tmp_path / "a.gif").stat().st_size < (tmp_path / "b.gif").stat().st_size


def test_a_pixel_becoming_transparent_is_shown_by_disposal(tmp_path):
    """Frames with empty pixels are written standing alone, each disposed to the background
    (disposal 2): the square's old place becomes transparent again."""
    frames = CASES["transparent"]
    write_gif(in_runs(frames, 4), tmp_path / "t.gif", 0.7, len(frames))
    _, images = blocks((tmp_path / "t.gif").read_bytes())
    assert {im["disposal"] for im in images} == {2}
    assert {im["transparent"] for im in images} == {255}
    shown = composited(tmp_path / "t.gif")
    second = np.frombuffer(shown[1][0], np.uint8).reshape(40, 52, 4)
    assert second[12, 5, 3] == 0 and second[12, 8, 3] == 255  # the square moved right by 3


def test_a_frame_showing_the_same_colours_under_another_table_is_one_pixel(tmp_path):
    """Two frames with the same colours in another order of their colour tables (not merged:
    their blocks differ) give a one-pixel frame, which shows the same picture."""
    first = gif_picture(CASES["opaque"][0])
    order = np.roll(np.arange(256), 1).astype(np.uint8)  # index i holds colour i - 1
    table = np.frombuffer(first.palette, np.uint8).reshape(256, 3)
    second = replace(first, indices=order[first.indices],
                     palette=table[np.argsort(order)].tobytes())  # fmt: skip
    assert not second.same(first)
    assert np.array_equal(second.shown(), first.shown())
    g = encode_gif(second, first)
    assert g.box == (0, 0, 1, 1) and g.disposal == 1 and g.transparent is None

    def source(plan):
        return iter([first, second])

    write_gif(source, tmp_path / "s.gif", 0.2, 2)
    shown = composited(tmp_path / "s.gif")
    assert len(shown) == 2 and shown[0][0] == shown[1][0]
    assert [p for p, _ in pillows(tmp_path / "s.gif")] == [p for p, _ in shown]


def test_a_run_gives_its_first_opaque_picture_and_its_last_frame_carries_its_picture():
    pics = [gif_picture(f) for f in CASES["opaque"][:3]]
    out = list(link_gif(iter(pics)))
    assert out[0] is pics[0]
    assert out[1].picture is None and out[2].picture is pics[2]
    clear = [gif_picture(f) for f in CASES["transparent"][:2]]
    out = list(link_gif(iter(clear)))
    assert not isinstance(out[0], GifPicture) and out[1].picture is None


@pytest.mark.parametrize("background", ["White", None])
def test_the_command_line_writes_the_same_gif_with_one_or_two_workers(background, tmp_path):
    sample = ROOT / "samples" / "spinning-cube.xaml"
    files = []
    for jobs in ("1", "2"):
        out = tmp_path / f"j{jobs}.gif"
        args = [sys.executable, "-m", "xaml3d", "animate", str(sample), "-o", str(out), "-W",
                "48", "--duration", "1", "--fps", "20", "-j", jobs, "-q"]  # fmt: skip
        if background:
            args += ["--background", background]
        p = subprocess.run(args, capture_output=True)
        assert p.returncode == 0, p.stderr
        files.append(out)
    assert files[0].read_bytes() == files[1].read_bytes()
    import xaml3d

    scene_ = xaml3d.load(sample)
    times = xaml3d.frame_times(0.0, 1.0, 20)
    bg = (1.0, 1.0, 1.0, 1.0) if background else None
    frames = [r.rgba for _, r in xaml3d.render_frames(scene_, times, width=48, time=None,
                                                      background=bg)]  # fmt: skip
    standing_alone(frames, tmp_path / "alone.gif", 1.0)
    assert composited(files[1]) == composited(tmp_path / "alone.gif")
    assert pillows(files[1]) == pillows(tmp_path / "alone.gif")
    _, images = blocks(files[1].read_bytes())
    if background:  # cropped: the cube turns within a part of the frame
        assert all(im["disposal"] == 1 for im in images)
        assert any(im["box"][2] < 48 for im in images[1:])
