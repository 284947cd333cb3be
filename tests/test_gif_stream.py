"""GIF written frame by frame (``xaml3d.output.animation.write_gif``): the matte and the
transparent index decided from the frames as they come, the same file as from a list."""

from __future__ import annotations

import itertools
import subprocess
import sys
from pathlib import Path

import numpy as np
from PIL import Image

import xaml3d
from xaml3d.output.animation import (
    GifPlan,
    gif_frame,
    gif_picture,
    link_gif,
    save_animation,
    write_gif,
)
from xaml3d.output.gif_matte import MatteWatch, frame_marks, needs_matte

ROOT = Path(__file__).resolve().parent.parent


def square(colour=(0, 200, 30, 255), size=24) -> np.ndarray:
    f = np.zeros((size, size, 4), np.uint8)
    f[4:16, 4:16] = colour
    f[4:16, 3] = (*colour[:3], 128)  # an antialiased edge: partial alpha, not translucency
    return f


def frames_of_every_kind() -> list[np.ndarray]:
    base = square()
    glass = base.copy()
    glass[6:14, 6:14, 3] = 100  # a translucent surface
    moved = np.roll(base, 3, axis=1)
    tiny = np.zeros((60, 60, 4), np.uint8)
    tiny[:30] = (0, 0, 255, 255)
    tiny[40:42, 40:42] = (255, 0, 0, 200)
    tiny_faded = tiny.copy()
    tiny_faded[40:42, 40:42, 3] = 90  # differs from ``tiny`` only in alpha
    under = base.copy()
    under[0, 0] = (9, 0, 0, 0)  # a colour under an empty pixel: not what GIF draws
    return [base, glass, moved, under, tiny, tiny_faded]


def test_the_watch_decides_as_needs_matte_on_every_prefix():
    frames = frames_of_every_kind()
    small, big = frames[:4], frames[4:]
    for group in (small, big):
        for seq in itertools.permutations(group + group[:1], 3):
            watch = MatteWatch()
            for n, f in enumerate(seq, 1):
                assert watch.add(frame_marks(f)) == needs_matte(list(seq[:n]))


def in_runs(frames, plan, size: int):
    """The frames as workers give them to the GIF writer: quantized, and compressed in runs of
    ``size`` consecutive frames (``link_gif``)."""
    for i in range(0, len(frames), size):
        yield from link_gif(gif_picture(f, plan) for f in frames[i : i + size])


def gif_bytes(path: Path) -> bytes:
    return path.read_bytes()


def decoded(path: Path) -> list[np.ndarray]:
    with Image.open(path) as im:
        out = []
        for i in range(im.n_frames):
            im.seek(i)
            out.append(np.array(im.convert("RGBA")))
    return out


def test_a_late_translucent_frame_restarts_the_stream_flattened(tmp_path):
    opaque = [np.roll(square(), k, axis=1) for k in range(4)]
    glass = opaque[3].copy()
    glass[6:14, 6:14, 3] = 100
    frames = [*opaque, glass, opaque[0]]
    calls = []

    def source(plan):
        calls.append((plan.flatten, plan.reserve))
        return in_runs(frames, plan, 4)  # as workers make them

    assert write_gif(source, tmp_path / "s.gif", 0.6, len(frames), matte=(10, 20, 30))
    assert calls == [(False, None), (True, None)]  # asked again from the first frame
    save_animation(frames, tmp_path / "l.gif", 0.6, matte=(10, 20, 30))
    assert gif_bytes(tmp_path / "s.gif") == gif_bytes(tmp_path / "l.gif")
    first = decoded(tmp_path / "s.gif")[0]
    assert tuple(first[0, 0]) == (10, 20, 30, 255)  # flattened from the first frame on
    assert [p.name for p in tmp_path.iterdir()].count("s.gif") == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == ["l.gif", "s.gif"]  # no temporary


def test_frames_without_empty_pixels_among_frames_with_keep_index_255(tmp_path):
    rng = np.random.default_rng(5)
    full = np.concatenate([rng.integers(0, 256, (32, 32, 3), dtype=np.uint8),
                           np.full((32, 32, 1), 255, np.uint8)], axis=2)  # fmt: skip
    frames = [square(size=32), full]  # 1024 colours: every palette index in use
    calls = []

    def source(plan):
        calls.append(plan.reserve)
        return (gif_frame(f, plan) for f in frames)

    assert not write_gif(source, tmp_path / "a.gif", 0.2, 2)
    assert calls == [None, True]
    shown = decoded(tmp_path / "a.gif")
    assert (shown[1][..., 3] == 255).all()  # no colour of the full frame shown transparent
    assert shown[0][0, 0, 3] == 0  # the first frame's empty background stays transparent


def test_frames_made_under_another_plan_are_refused(tmp_path):
    f = square()
    made = gif_frame(f, GifPlan(flatten=True))
    try:
        write_gif(lambda plan: [made], tmp_path / "x.gif", 0.1, 1)
    except ValueError as exc:
        assert "another plan" in str(exc)
    else:
        raise AssertionError("accepted")
    assert list(tmp_path.iterdir()) == []


def test_the_command_line_writes_the_gif_the_api_writes(tmp_path):
    sample = ROOT / "samples" / "spinning-cube.xaml"
    out = tmp_path / "cli.gif"
    p = subprocess.run([sys.executable, "-m", "xaml3d", "animate", str(sample), "-o", str(out),
                        "-W", "64", "--duration", "0.5", "--fps", "10", "-j", "2"],
                       capture_output=True)  # fmt: skip
    assert p.returncode == 0, p.stderr
    scene = xaml3d.load(sample)
    times = xaml3d.frame_times(0.0, 0.5, 10)
    frames = [r.rgba for _, r in xaml3d.render_frames(scene, times, width=64, time=None)]
    save_animation(frames, tmp_path / "api.gif", 0.5)
    assert out.read_bytes() == (tmp_path / "api.gif").read_bytes()
    assert len(decoded(out)) == 5


def test_streamed_apng_decodes_as_pillows_apng(tmp_path):
    from xaml3d.output.animation import frame_durations, write_apng

    rng = np.random.default_rng(2)
    a, b, c = (rng.integers(0, 256, (20, 30, 4), dtype=np.uint8) for _ in range(3))
    frames = [a, a, b, c, c, c]
    write_apng(iter(frames), tmp_path / "s.png", 0.6, len(frames), loop=3)  # a one-shot iterator
    images = [Image.fromarray(f, mode="RGBA") for f in frames]
    images[0].save(tmp_path / "p.png", save_all=True, append_images=images[1:], loop=3,
                   duration=frame_durations(6, 0.6, 0.001), default_image=False)  # fmt: skip
    shown = []
    for name in ("s.png", "p.png"):
        with Image.open(tmp_path / name) as im:
            got = []
            for i in range(im.n_frames):
                im.seek(i)
                got.append((np.array(im.convert("RGBA")).tobytes(), im.info["duration"]))
            shown.append((got, im.info.get("loop")))
    assert shown[0] == shown[1]
    assert [d for _, d in shown[0][0]] == [200.0, 100.0, 300.0]  # identical frames merged


def test_a_frame_of_few_colours_keeps_them_exactly_as_the_median_cut_does():
    from xaml3d.output.animation import _gif_frame

    rng = np.random.default_rng(7)
    colours = rng.integers(0, 256, (40, 3), dtype=np.uint8)
    f = np.zeros((30, 40, 4), np.uint8)
    f[..., :3] = colours[rng.integers(0, 40, (30, 40))]
    f[..., 3] = 255
    f[:5] = 0  # empty rows: transparent
    image, transparent = _gif_frame(f)
    idx = np.array(image)
    assert transparent == 255 and (idx[:5] == 255).all() and (idx[5:] < 255).all()
    shown = np.array(image.convert("RGB"))
    assert np.array_equal(shown[5:], f[5:, :, :3])
    rgb = Image.fromarray(np.ascontiguousarray(f[..., :3]))
    cut = rgb.quantize(255, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE)
    assert np.array_equal(np.array(cut.convert("RGB"))[5:], shown[5:])  # the same pixels
    full = f.copy()
    full[..., 3] = 255  # no empty pixel: 256 colours allowed, no transparent index
    assert _gif_frame(full)[1] is None


def test_webp_is_streamed_and_is_the_file_pillow_writes_from_a_list(tmp_path):
    import gc
    import io
    import weakref

    from xaml3d.output.animation import WEBP_OPTIONS, frame_durations, write_webp

    rng = np.random.default_rng(5)
    frames = [rng.integers(0, 256, (20, 28, 4), dtype=np.uint8) for _ in range(7)]
    frames[3] = frames[2].copy()  # a repeated frame too
    alive_at_most = []

    def made():
        refs = []
        for f in frames:
            gc.collect()
            alive_at_most.append(sum(r() is not None for r in refs))
            g = f.copy()  # a frame only this stream holds
            refs.append(weakref.ref(g))
            yield g

    write_webp(made(), tmp_path / "s.webp", 0.7, len(frames), loop=2)
    # the first frame (the writer's first image) and the one before the current at most
    assert max(alive_at_most) <= 2
    buf = io.BytesIO()
    images = [Image.fromarray(f, mode="RGBA") for f in frames]
    images[0].save(buf, format="WEBP", save_all=True, append_images=images[1:],
                   duration=frame_durations(7, 0.7, 0.001), loop=2, **WEBP_OPTIONS)  # fmt: skip
    assert (tmp_path / "s.webp").read_bytes() == buf.getvalue()
    with Image.open(tmp_path / "s.webp") as im:
        assert im.n_frames == 6  # the encoder merges the repeated frame into the one before


def test_apng_from_frames_encoded_where_drawn_is_the_same_file(tmp_path):
    from xaml3d.output.animation import png_frame, write_apng

    rng = np.random.default_rng(9)
    frames = [rng.integers(0, 256, (12, 17, 4), dtype=np.uint8) for _ in range(5)]
    frames[2] = frames[1].copy()  # merged into the frame before, its time added
    write_apng(iter(frames), tmp_path / "a.png", 0.5, 5, loop=3)
    write_apng((png_frame(f) for f in frames), tmp_path / "b.png", 0.5, 5, loop=3)
    mixed = [png_frame(f) if i % 2 else f for i, f in enumerate(frames)]
    write_apng(iter(mixed), tmp_path / "c.png", 0.5, 5, loop=3)
    data = (tmp_path / "a.png").read_bytes()
    assert (tmp_path / "b.png").read_bytes() == data == (tmp_path / "c.png").read_bytes()
    with Image.open(tmp_path / "a.png") as im:
        assert im.n_frames == 4
        im.seek(1)
        assert im.info["duration"] == 200.0
        assert np.array_equal(np.array(im.convert("RGBA")), frames[1])


def test_a_frame_file_encoded_where_drawn_is_the_file_save_image_writes(tmp_path):
    from xaml3d.cli_outputs import FrameSequence
    from xaml3d.output.images import png_bytes, save_image

    rng = np.random.default_rng(11)
    frame = rng.integers(0, 256, (9, 13, 4), dtype=np.uint8)
    save_image(frame, tmp_path / "direct.png", format="PNG")
    seq = FrameSequence(tmp_path / "d", ["frame_0000.png", "frame_0001.png"])
    seq.add(png_bytes(frame))
    seq.add(frame)
    seq.commit()
    want = (tmp_path / "direct.png").read_bytes()
    assert (tmp_path / "d" / "frame_0000.png").read_bytes() == want
    assert (tmp_path / "d" / "frame_0001.png").read_bytes() == want


def pillows_gif(frames, path: Path, total: float, reserve: bool) -> None:
    """The frames' palette images (``_gif_frame``) as Pillow's own writer writes them."""
    from xaml3d.output.animation import _gif_frame, frame_durations

    images = [_gif_frame(f, reserve=reserve)[0] for f in frames]
    extra = {"transparency": 255, "disposal": 2} if reserve else {}
    durations = [10 * d for d in frame_durations(len(frames), total, 0.01)]
    images[0].save(path, save_all=True, append_images=images[1:], duration=durations, loop=0,
                   optimize=False, **extra)  # fmt: skip


def decoded_with_times(path: Path) -> list[tuple[bytes, int]]:
    with Image.open(path) as im:
        out = []
        for i in range(im.n_frames):
            im.seek(i)
            out.append((np.array(im.convert("RGBA")).tobytes(), im.info["duration"]))
    return out


def test_frames_compressed_where_made_decode_as_pillows_gif(tmp_path):
    """Each frame's block is compressed by ``gif_frame`` (where a frame was drawn) and the
    writer puts them together as they come: the decoded frames and display times of the file
    are those of Pillow's writer given the same palette images (frames showing the picture of
    the one before merged into it, their times added; an empty frame; frames without empty
    pixels written whole)."""
    moving = [np.roll(square(), 2 * k, axis=1) for k in range(4)]
    empty = np.zeros_like(moving[0])
    with_empty = [moving[0], moving[1], moving[1], empty, moving[2], moving[3], moving[3]]
    rng = np.random.default_rng(3)
    alpha = np.full((20, 24, 1), 255, np.uint8)
    full = [np.concatenate([rng.integers(0, 256, (20, 24, 3), np.uint8), alpha], 2) for _ in "abc"]
    opaque = [full[0], full[1], full[1], full[2]]
    for name, frames, reserve in (("t", with_empty, True), ("o", opaque, False)):
        assert not write_gif(lambda plan, fs=frames: (gif_frame(f, plan) for f in fs),
                             tmp_path / f"{name}.gif", 0.7, len(frames))  # fmt: skip
        pillows_gif(frames, tmp_path / f"{name}-pillow.gif", 0.7, reserve)
        got = decoded_with_times(tmp_path / f"{name}.gif")
        assert got == decoded_with_times(tmp_path / f"{name}-pillow.gif")
        assert len(got) == len(frames) - 2 + (name == "o")  # the repeats merged
        assert sum(ms for _, ms in got) == 700
    with Image.open(tmp_path / "t.gif") as im:
        assert im.info["loop"] == 0 and im.size == (24, 24)
