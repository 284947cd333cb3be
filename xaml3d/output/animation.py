"""Animated image files: GIF, APNG (.png), WebP, or numbered PNGs in a directory.

``save_animation`` writes GIF (one adaptive palette per frame; empty pixels become GIF
transparency, any other pixel is opaque; frames with translucent surfaces are flattened first,
``xaml3d.output.gif_matte``), APNG (.png), WebP, or numbered PNGs in a directory
(``frame_names``), atomically: a temporary file in the target's folder is written, fsynced and
renamed, so a failure leaves no partial file and an existing one untouched.

``write_gif`` streams: the frames come one by one (quantized and compressed where they were
drawn, e.g. in a worker process, each cropped to what differs from the frame before:
``xaml3d.output.gif_frames``) and each is written as it comes, one held; the matte and the
transparent index are decided from the frames as they come (``GifPlan``), and the frames are
asked for again from the first should a later frame show the decision wrong. ``write_apng``
streams APNG likewise (one frame held), and ``write_webp`` WebP (one RGBA frame held; libwebp's
encoder keeps the encoded frames).
"""

from __future__ import annotations

import functools
import hashlib
import io
import re
import struct
import zlib
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from PIL import Image

from xaml3d.errors import RenderError
from xaml3d.output.atomic import write_atomically
from xaml3d.output.gif_frames import (  # noqa: F401 (_gif_frame, link_gif: this module's interface)
    GifFrame,
    GifPicture,
    GifPlan,
    GifRestart,
    _gif_frame,
    encode_gif,
    gif_frame,
    gif_picture,
    link_gif,
)
from xaml3d.output.gif_matte import MatteWatch, needs_matte
from xaml3d.output.images import save_image

ANIMATED_FORMATS = {".gif": "GIF", ".png": "PNG", ".apng": "PNG", ".webp": "WEBP"}
# The files of a numbered sequence: frame_0000.png ... (4 digits at least, more when needed).
FRAME_FILE = re.compile(r"frame_[0-9]{4,}\.png")


def frame_durations(count: int, total: float, unit: float) -> list[int]:
    """Display time of each of ``count`` frames in whole ``unit``s (seconds per unit), summing
    to ``total`` seconds rounded to the unit."""
    units = total / unit
    return [round((i + 1) * units / count) - round(i * units / count) for i in range(count)]


def frame_names(count: int) -> list[str]:
    """The file names of a sequence of ``count`` frames, in order."""
    digits = max(4, len(str(count - 1)))
    return [f"frame_{i:0{digits}d}.png" for i in range(count)]


def write_gif(
    source,
    path,
    total: float,
    count: int,
    *,
    loop: int = 0,
    matte: tuple[int, int, int] = (255, 255, 255),
    flatten: bool = False,
) -> bool:
    """Write ``count`` frames lasting ``total`` seconds as a GIF at ``path``, atomically, frame
    by frame: ``source(plan)`` gives the frames (RGBA arrays, ``GifPicture``s made under
    ``plan`` by ``gif_picture``, or what ``link_gif`` makes of runs of them where they were
    drawn) in order, and is called again, from the first frame, when a frame shows the plan
    wrong (a translucent frame after opaque ones: the whole animation is flattened onto
    ``matte``; a frame without empty pixels among ones with: index 255 kept in every frame).
    Each frame is written as it comes (its block compressed where it was made, or here for the
    frames given as pictures) and one frame is held. ``flatten``: flatten from the first frame (the
    caller knows already). Returns whether the frames were flattened."""
    plan = GifPlan(matte=tuple(matte), flatten=bool(flatten))
    durations = [10 * d for d in frame_durations(count, total, 0.01)]
    while True:
        made = GifPlan(plan.matte, plan.flatten, plan.reserve)  # the frames' plan: never changed
        try:
            write = functools.partial(_write_gif, source=source, plan=plan, made=made,
                                      durations=durations, loop=loop)  # fmt: skip
            write_atomically(path, write)
            return plan.flatten
        except GifRestart:
            continue


def _write_gif(fh, *, source, plan: GifPlan, made: GifPlan, durations: list[int], loop: int):
    """Write the GIF of ``source(made)``'s frames; ``plan`` is updated from them, and
    GifRestart raised when the frames show ``made`` wrong. Each frame's block is written as it
    comes (one frame held: a frame showing the picture of the one before is merged into it, its
    display time added); a frame that comes as a picture (an array, or a ``GifPicture`` a run
    of ``link_gif`` left for the writer) is encoded here against the picture before it."""
    watch = MatteWatch()
    frames = iter(source(made))
    before: GifPicture | None = None  # the last frame's picture, when known

    def checked(f):
        g = gif_picture(f, made) if isinstance(f, np.ndarray) else f
        if g.flattened != made.flatten or g.reserve != bool(made.reserve):
            raise ValueError("a GIF frame made under another plan")
        if not plan.flatten and watch.add(g.marks):
            plan.flatten, plan.reserve = True, None
            raise GifRestart
        if plan.reserve is None:
            plan.reserve = g.clear  # the first frame decides...
        elif (g.clear and not plan.reserve) or (plan.reserve and not g.clear and not g.reserve):
            plan.reserve = True  # ...unless frames disagree: every frame keeps index 255
            raise GifRestart
        return g

    def encoded(g) -> GifFrame:
        nonlocal before
        if isinstance(g, GifPicture):
            g, before = encode_gif(g, before), g
        else:
            before = g.picture
        return g

    try:
        held = encoded(checked(next(frames)))
    except StopIteration:
        raise ValueError("no frames to write") from None
    # Logical screen: the frames' size, no global colour table (each frame has its own).
    fh.write(b"GIF89a" + struct.pack("<HHBBB", held.width, held.height, 0, 0, 0))
    if loop != 1:  # GIF's loop count is the number of REPEATS (0: for ever)
        repeats = 0 if loop == 0 else loop - 1
        fh.write(b"!\xff\x0bNETSCAPE2.0\x03\x01" + struct.pack("<H", repeats) + b"\0")
    held_ms = durations[0]
    for ms, f in zip(durations[1:], frames, strict=False):
        g = checked(f)
        if isinstance(g, GifPicture):
            same = before is not None and g.same(before)
        else:
            same = held.same_picture(g)
        if same:  # one frame showing the picture longer
            held_ms += ms
            if isinstance(g, GifFrame) and g.picture is not None:
                before = g.picture
            continue
        _put_gif_frame(fh, held, held_ms)
        held, held_ms = encoded(g), ms
    for _ in frames:  # more frames than durations: a caller's mistake
        raise ValueError("more GIF frames than their count")
    _put_gif_frame(fh, held, held_ms)
    fh.write(b";")


def _put_gif_frame(fh, g: GifFrame, ms: int) -> None:
    """One frame's graphic control extension (display time in 10 ms units, its disposal, its
    transparent index if any), its image descriptor with its local colour table, and its image
    data."""
    t = g.transparent
    flags = g.disposal << 2 | (t is not None)
    fh.write(b"!\xf9\x04" + struct.pack("<BHBB", flags, ms // 10, t or 0, 0))
    x, y, w, h = g.box
    fh.write(b"," + struct.pack("<HHHHB", x, y, w, h, 0x80 | 7) + g.palette + b"\x08")
    fh.write(g.data)


PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def _chunk(kind: bytes, data: bytes) -> bytes:
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


def _png_data(rgba: np.ndarray) -> tuple[bytes, bytes]:
    """(IHDR data, the image's compressed data) of ``rgba`` as Pillow encodes a PNG."""
    buf = io.BytesIO()
    Image.fromarray(np.ascontiguousarray(rgba), mode="RGBA").save(buf, format="PNG")
    raw, pos, ihdr, idat = buf.getvalue(), len(PNG_SIGNATURE), b"", []
    while pos < len(raw):
        (n,) = struct.unpack(">I", raw[pos : pos + 4])
        kind, data = raw[pos + 4 : pos + 8], raw[pos + 8 : pos + 8 + n]
        if kind == b"IHDR":
            ihdr = data
        elif kind == b"IDAT":
            idat.append(data)
        pos += 12 + n
    return ihdr, b"".join(idat)


@dataclass
class PngFrame:
    """One frame made ready for the APNG writer where it was drawn (``png_frame``): its size,
    IHDR data and compressed image data as Pillow encodes it, and a digest of its pixels (to
    merge it into the frame before when they are the same: SHA-1, no collision in practice).
    A fraction of the RGBA's bytes to send between processes, and encoded in parallel."""

    width: int
    height: int
    ihdr: bytes
    data: bytes
    digest: bytes


def png_frame(rgba: np.ndarray) -> PngFrame:
    """``rgba`` (H, W, 4 uint8) encoded for ``write_apng``."""
    rgba = np.ascontiguousarray(rgba)
    ihdr, data = _png_data(rgba)
    h, w = rgba.shape[:2]
    return PngFrame(w, h, ihdr, data, _digest(rgba))


def _digest(rgba: np.ndarray) -> bytes:
    shape = struct.pack(">III", *rgba.shape)
    return hashlib.sha1(shape + rgba.tobytes(), usedforsecurity=False).digest()


def write_apng(frames, path, total: float, count: int, *, loop: int = 0) -> None:
    """Write ``count`` RGBA frames (any iterable, taken one by one; arrays, or ``PngFrame``s
    made by ``png_frame`` where they were drawn) lasting ``total`` seconds as an APNG at
    ``path``, atomically, frame by frame: one frame is held (to merge a frame identical to the
    one before into it, its display time added, as Pillow's writer does). Every frame is a
    whole picture (no cropping to what changed): the decoded frames are those Pillow's writer
    gives, and the file is the same whichever form the frames come in."""
    durations = frame_durations(count, total, 0.001)

    def write(fh) -> None:
        it = iter(frames)
        first = _as_png_frame(next(it))
        fh.write(PNG_SIGNATURE + _chunk(b"IHDR", first.ihdr))
        actl = fh.tell()
        fh.write(_chunk(b"acTL", struct.pack(">II", 0, loop)))  # the count is set at the end
        seq, written = 0, 0
        held, held_ms = first, durations[0]

        def put(data: bytes, ms: int) -> None:
            nonlocal seq, written
            w, h = first.width, first.height
            fh.write(_chunk(b"fcTL", struct.pack(">IIIIIHHBB", seq, w, h, 0, 0, ms, 1000, 0, 0)))
            seq += 1
            if written == 0:
                fh.write(_chunk(b"IDAT", data))
            else:
                fh.write(_chunk(b"fdAT", struct.pack(">I", seq) + data))
                seq += 1
            written += 1

        for ms, f in zip(durations[1:], it, strict=True):
            if _same_frame(f, held):
                held_ms += ms
                continue
            put(held.data, held_ms)
            held, held_ms = _as_png_frame(f), ms
        put(held.data, held_ms)
        fh.write(_chunk(b"IEND", b""))
        fh.seek(actl)
        fh.write(_chunk(b"acTL", struct.pack(">II", written, loop)))

    write_atomically(path, write)


def _as_png_frame(f) -> PngFrame:
    return f if isinstance(f, PngFrame) else png_frame(f)


def _same_frame(f, held: PngFrame) -> bool:
    """Whether the frame ``f`` (an array or a PngFrame) has the pixels of ``held``."""
    if isinstance(f, PngFrame):
        return f.digest == held.digest
    return _digest(np.ascontiguousarray(f)) == held.digest


def save_animation(
    frames: list[np.ndarray],
    path,
    total: float,
    *,
    loop: int = 0,
    directory: bool = False,
    matte: tuple[int, int, int] = (255, 255, 255),
) -> list[Path]:
    """Write (H, W, 4) uint8 RGBA frames lasting ``total`` seconds in all. ``loop``: 0 for
    ever, else the number of plays. ``directory``: numbered PNGs ``frame_0000.png``... in the
    folder ``path``. ``matte``: the opaque RGB (0..255) a GIF's frames are flattened onto when
    they show translucent surfaces (``gif_matte.frames_for_gif``). Returns the files written.
    Raises RenderError (RND006 format, RND007)."""
    path = Path(path)
    if directory:
        path.mkdir(parents=True, exist_ok=True)
        out = []
        for name, f in zip(frame_names(len(frames)), frames, strict=True):
            target = path / name
            save_image(f, target, format="PNG")
            out.append(target)
        return out
    fmt = ANIMATED_FORMATS.get(path.suffix.lower())
    if fmt is None:
        raise RenderError(
            f"cannot write {path.name!r}: unknown animation format "
            "(use .gif, .png (APNG), .webp, or a directory ending in /)",
            code="RND006",
        )
    if fmt == "GIF":
        flat = needs_matte(frames)
        write_gif(lambda plan: frames, path, total, len(frames), loop=loop, matte=matte,
                  flatten=flat)  # fmt: skip
        return [path]
    if fmt == "PNG":
        write_apng(frames, path, total, len(frames), loop=loop)
        return [path]
    write_webp(frames, path, total, len(frames), loop=loop)
    return [path]


WEBP_OPTIONS = {"lossless": False, "quality": 90}


def write_webp(frames, path, total: float, count: int, *, loop: int = 0) -> None:
    """Write ``count`` RGBA frames (any iterable, taken one by one) lasting ``total`` seconds
    as an animated WebP at ``path``, atomically. Pillow's writer makes a list of the images it
    is given, but reads a multi-frame image frame by frame (``seek``): the frames after the
    first are given as one such image (``_FrameStream``) that makes each frame's image when
    the writer seeks to it, so one RGBA frame is held at a time (the encoder keeps the frames
    it has encoded, compressed)."""
    durations = frame_durations(count, total, 0.001)

    def write(fh) -> None:
        it = iter(frames)
        first = Image.fromarray(np.ascontiguousarray(next(it)), mode="RGBA")
        rest = [_FrameStream(it, count - 1)] if count > 1 else []
        first.save(fh, format="WEBP", save_all=True, append_images=rest, duration=durations,
                   loop=loop, **WEBP_OPTIONS)  # fmt: skip

    write_atomically(path, write)


class _FrameStream:
    """RGBA frames as one multi-frame image for Pillow's writers: ``n_frames``, ``seek`` (only
    forwards: the frames are made as they come; seeking back is ignored, as the WebP writer
    seeks back to where it began once it is done) and, for everything else, the current
    frame's image."""

    def __init__(self, frames, count: int) -> None:
        self.n_frames = count
        self._frames = frames
        self._at = -1
        self._image: Image.Image | None = None

    def seek(self, index: int) -> None:
        while self._at < index:
            self._image = None  # the frame before is dropped first
            rgba = next(self._frames)
            self._image = Image.fromarray(np.ascontiguousarray(rgba), mode="RGBA")
            self._at += 1

    def tell(self) -> int:
        return max(self._at, 0)

    def __getattr__(self, name: str):
        if self._image is None:
            self.seek(0)
        return getattr(self._image, name)
