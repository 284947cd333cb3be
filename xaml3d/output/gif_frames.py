"""GIF frames: each frame quantized to a palette image (one adaptive colour table a frame) and
its image block LZW-compressed where it was drawn, written as the part that differs from the
frame before.

``gif_picture`` quantizes one frame (a ``GifPicture``: its indices and colour table;
``GifPicture.same`` tells a frame the writer merges into the one before). ``encode_gif`` makes
its image block (a ``GifFrame``): with the frame before known and both frames opaque (no
transparent pixel in either), only the box around the pixels whose shown colour differs is
written, over the frame before, which is kept (disposal 1), as Pillow's writer does. Frames with
transparent pixels are written as they stand: the box around their drawn pixels, the rest
showing the background they are disposed to (disposal 2: a pixel that becomes transparent can
only be shown by disposing the frame before it, and a moving model uncovers some in every
frame).

``link_gif`` encodes a run of consecutive pictures drawn in one process: each against the one
before it, the run's first opaque picture left for the writer (which knows the frame before
the run) and the last given its picture (which the writer needs to encode the next run's
first). The encoding of a frame depends only on it and the frame before, so the file is the
same whichever process encoded which frame.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
from PIL import GifImagePlugin, Image

from xaml3d.output.gif_matte import _compiled, flatten, marks_and_clear

KEEP, CLEAR = 1, 2  # GIF's disposal methods: keep the frame, restore its box to the background
SHOWN_CLEAR = np.uint32(1 << 24)  # a transparent pixel among shown colours (0xRRGGBB)


def _gif_frame(rgba: np.ndarray, reserve: bool = False, clear: bool | None = None):
    """A palette image for GIF: 255 adaptive colours, index 255 for transparent pixels. GIF
    has no partial transparency: a pixel with any coverage keeps its (straight) colour, fully,
    so translucent surfaces stay visible; only empty pixels become transparent. A frame without
    empty pixels gets 256 colours, unless ``reserve``: index 255 is then kept free (the file's
    transparent index) all the same. ``clear``: whether the frame has empty pixels, when the
    caller knows already. Returns (the image, its transparent index or None)."""
    return _gif_frame_parts(rgba, reserve, clear)[:2]


def _gif_frame_parts(rgba: np.ndarray, reserve: bool = False, clear: bool | None = None):
    """``_gif_frame``'s (image, transparent index or None), and the box (x0, y0, x1, y1) of
    the pixels that are not transparent when the compiled palette pass found it, else None."""
    alpha = rgba[..., 3]
    if clear is None:
        clear = bool((alpha == 0).any())
    opaque = not clear and not reserve
    exact = _exact_palette(rgba, 256 if opaque else 255)
    if exact is not None:
        idx, pal, box = exact
        out = Image.fromarray(idx, mode="P")
        out.putpalette(pal + [0, 0, 0] * (256 - len(pal) // 3))
        return out, (None if opaque else 255), box
    rgb = Image.fromarray(np.ascontiguousarray(rgba[..., :3]), mode="RGB")
    if opaque:
        q = rgb.quantize(256, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE)
        return q, None, None
    # the colours of visible pixels only choose the palette
    q = rgb.quantize(255, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE)
    idx = np.array(q, dtype=np.uint8)
    idx[alpha == 0] = 255
    out = Image.fromarray(idx, mode="P")
    pal = q.getpalette()[: 255 * 3]
    out.putpalette(pal + [0, 0, 0] * (256 - len(pal) // 3))
    return out, 255, None


def _exact_palette(rgba: np.ndarray, limit: int):
    """(indices, palette, box) of a frame with at most ``limit`` distinct colours (empty pixels
    at index 255; ``box``: see ``_gif_frame_parts``), else None. The median cut gives such a
    frame its exact colours too (every colour a box of its own), at several times the cost;
    here the palette is the colours in ascending order, so the file's bytes differ from the
    median cut's while every decoded pixel is the same. With numba loaded,
    ``gif_pass.exact_palette`` gives the same indices and palette in two compiled passes."""
    gif_pass = _compiled()
    if gif_pass is not None:
        idx = np.empty(rgba.shape[:2], dtype=np.uint8)
        keys = np.empty(256, dtype=np.int64)
        box = np.empty(4, dtype=np.int64)
        n = gif_pass.exact_palette(np.ascontiguousarray(rgba), limit, idx, keys, box)
        if n < 0:
            return None
        return idx, [int(k >> s) & 255 for k in keys[:n] for s in (16, 8, 0)], tuple(box)
    rgb = Image.fromarray(np.ascontiguousarray(rgba[..., :3]), mode="RGB")
    found = rgb.getcolors(limit)
    if found is None:
        return None
    colours = sorted(c for _, c in found)
    keys = np.array([(r << 16) | (g << 8) | b for r, g, b in colours], dtype=np.uint32)
    px = rgba[..., :3].astype(np.uint32)
    idx = np.searchsorted(keys, (px[..., 0] << 16) | (px[..., 1] << 8) | px[..., 2])
    idx = idx.astype(np.uint8)
    idx[rgba[..., 3] == 0] = 255
    return idx, [v for c in colours for v in c], None


@dataclass
class GifPlan:
    """How every frame of one GIF is made: flattened onto ``matte`` or not, index 255 kept for
    transparency in every frame or not (None: as the frame needs). The writer decides it from
    the frames and starts again with a new plan when a later frame shows the one in use wrong
    (``GifRestart``)."""

    matte: tuple[int, int, int] = (255, 255, 255)
    flatten: bool = False
    reserve: bool | None = None


class GifRestart(Exception):
    """The frames written so far were made under a plan a later frame showed wrong."""


@dataclass
class GifPicture:
    """One frame quantized for GIF under a plan (``gif_picture``), not yet encoded: its
    ``indices`` (H, W uint8), ``palette`` (the local colour table, 768 bytes), ``transparent``
    (its transparent index, or None: every pixel opaque), ``drawn`` (x, y, width, height of the
    part written when the frame stands alone: the box around its drawn pixels, the whole frame
    when opaque), whether the frame has empty pixels (``clear``), its
    ``gif_matte.frame_marks``, and ``flattened``/``reserve``: how it was made."""

    width: int
    height: int
    indices: np.ndarray
    palette: bytes
    transparent: int | None
    drawn: tuple[int, int, int, int]
    clear: bool
    marks: tuple
    flattened: bool
    reserve: bool

    @property
    def nbytes(self) -> int:
        return self.indices.nbytes + len(self.palette)

    def same(self, other: GifPicture) -> bool:
        """Whether ``other`` is written as the same block when standing alone (the writer
        merges such a frame into the one before, its display time added). Outside the drawn
        box every index is the transparent one, so the whole indices are compared."""
        return (
            (self.drawn, self.transparent, self.palette) == (other.drawn, other.transparent,
                                                             other.palette)
            and np.array_equal(self.indices, other.indices)
        )  # fmt: skip

    def colours(self) -> np.ndarray:
        """The colour of each palette index (256 uint32: 0xRRGGBB, ``SHOWN_CLEAR`` for the
        transparent index)."""
        rgb = np.frombuffer(self.palette, np.uint8).reshape(256, 3).astype(np.uint32)
        table = (rgb[:, 0] << 16) | (rgb[:, 1] << 8) | rgb[:, 2]
        if self.transparent is not None:
            table[self.transparent] = SHOWN_CLEAR
        return table

    def shown(self) -> np.ndarray:
        """The colour each pixel shows (H, W uint32, as ``colours``)."""
        return np.take(self.colours(), self.indices)


@dataclass
class GifFrame:
    """One frame's image block, made ready for the GIF writer where it was drawn: ``box`` (x,
    y, width, height of the part written), ``palette`` (the local colour table, 768 bytes),
    ``data`` (the LZW-compressed indices, as GIF's image data sub-blocks), ``transparent``
    (the block's transparent index, or None), ``disposal`` (KEEP or CLEAR), whether it is the
    frame standing alone (``alone``: the block ``same_picture`` compares) or a ``repeat`` of
    the frame before (no block: merged into it), ``clear``, ``marks``, ``flattened`` and
    ``reserve`` as its ``GifPicture`` has them, and ``picture``: that picture, given with the
    last frame of a run so that the writer can encode the next frame against it (else None).
    A fraction of the RGBA's bytes to send between processes, and compressed in parallel: the
    writer only puts the blocks together."""

    width: int
    height: int
    box: tuple[int, int, int, int]
    palette: bytes
    data: bytes
    transparent: int | None
    disposal: int
    alone: bool
    clear: bool
    marks: tuple
    flattened: bool
    reserve: bool
    repeat: bool = False
    picture: GifPicture | None = None

    @property
    def nbytes(self) -> int:
        return len(self.data) + len(self.palette) + (self.picture.nbytes if self.picture else 0)

    def same_picture(self, other: GifFrame) -> bool:
        """Whether ``other`` is a repeat of this frame, or both stand alone with the same block
        (the encoding is a function of the pixels)."""
        if other.repeat:
            return True
        return self.alone and other.alone and (
            (self.box, self.palette, self.transparent, self.data)
            == (other.box, other.palette, other.transparent, other.data)
        )  # fmt: skip


def gif_picture(rgba: np.ndarray, plan: GifPlan | None = None) -> GifPicture:
    """``rgba`` (H, W, 4 uint8) quantized as the GIF writer takes it under ``plan`` (default:
    not flattened, index 255 reserved only when the frame has empty pixels)."""
    plan = GifPlan() if plan is None else plan
    marks, clear = marks_and_clear(rgba)
    if plan.flatten:
        rgba, clear_now = flatten([rgba], plan.matte)[0], False
    else:
        clear_now = clear
    image, transparent, drawn = _gif_frame_parts(
        rgba, reserve=bool(plan.reserve) and not plan.flatten, clear=clear_now
    )
    indices = np.asarray(image)
    w, h = image.size
    palette = bytes(image.getpalette() or [])[:768]
    palette += bytes(768 - len(palette))
    return GifPicture(w, h, indices, palette, transparent, _drawn_box(indices, transparent, drawn),
                      clear and not plan.flatten, marks, plan.flatten,
                      bool(plan.reserve))  # fmt: skip


def _drawn_box(indices: np.ndarray, transparent: int | None, drawn: tuple | None) -> tuple:
    """The block a frame standing alone writes: with a transparent index, the box around its
    other pixels (one transparent pixel when there is none; ``drawn``: that box's first and
    last column and row when known), else the whole frame."""
    h, w = indices.shape
    if transparent is None:
        return (0, 0, w, h)
    if drawn is None:
        seen = indices != transparent
        rows, cols = np.flatnonzero(seen.any(axis=1)), np.flatnonzero(seen.any(axis=0))
        drawn = (cols[0], rows[0], cols[-1], rows[-1]) if rows.size else (0, 0, -1, -1)
    x0, y0, x1, y1 = (int(v) for v in drawn)
    if x1 < 0:
        return (0, 0, 1, 1)
    return (x0, y0, x1 - x0 + 1, y1 - y0 + 1)


def gif_frame(rgba: np.ndarray, plan: GifPlan | None = None) -> GifFrame:
    """``rgba`` (H, W, 4 uint8) as a GIF frame standing alone under ``plan`` (see
    ``gif_picture``)."""
    return encode_gif(gif_picture(rgba, plan))


def encode_gif(pic: GifPicture, before: GifPicture | None = None) -> GifFrame:
    """``pic``'s image block: the part that differs from ``before`` (the picture of the frame
    before it) when both are opaque, else the frame standing alone (module docstring)."""
    alone = (
        before is None
        or pic.transparent is not None
        or before.transparent is not None
        or (before.width, before.height) != (pic.width, pic.height)
    )
    if alone:
        x, y, w, h = pic.drawn
        data = _lzw(pic.indices[y : y + h, x : x + w], pic.palette)
        disposal = KEEP if pic.transparent is None else CLEAR
        return _frame(pic, pic.drawn, data, pic.transparent, disposal, alone=True)
    x0, y0, x1, y1 = _changed_box(pic, before)
    if x1 < 0:  # the same colours (a block of its own all the same): one pixel
        box = (0, 0, 1, 1)
    else:
        box = (x0, y0, x1 + 1 - x0, y1 + 1 - y0)
    x, y, w, h = box
    # The unchanged pixels inside the box keep their own indices: set to a transparent index
    # (Pillow's optimize) they made 005's flat-coloured faces speckled and its file 3 % larger.
    data = _lzw(pic.indices[y : y + h, x : x + w], pic.palette)
    return _frame(pic, box, data, None, KEEP, alone=False)


def _changed_box(pic: GifPicture, before: GifPicture) -> tuple[int, int, int, int]:
    """The first and last column and row of the pixels whose colour differs between two
    pictures of one size (x1 = -1 when none): one compiled pass when numba is loaded."""
    gif_pass = _compiled()
    if gif_pass is not None:
        box = np.empty(4, dtype=np.int64)
        gif_pass.changed_box(pic.indices, pic.colours(), before.indices, before.colours(), box)
        return tuple(int(v) for v in box)
    changed = pic.shown() != before.shown()
    rows = np.flatnonzero(changed.any(axis=1))
    if rows.size == 0:
        return (0, 0, -1, -1)
    cols = np.flatnonzero(changed[rows[0] : rows[-1] + 1].any(axis=0))
    return (int(cols[0]), int(rows[0]), int(cols[-1]), int(rows[-1]))


_LOADED: list = []


def _ready_to_compare() -> None:
    """Load ``gif_pass.changed_box``'s machine code (about 40 ms from numba's cache) once in
    this process: done by the parent for its first frame, before the worker processes are
    forked, they start with it loaded instead of each loading it while drawing."""
    gif_pass = None if _LOADED else _compiled()
    if gif_pass is None:
        return
    one, colours = np.zeros((1, 1), np.uint8), np.zeros(256, np.uint32)
    one.flags.writeable = False  # as a picture's indices (Pillow's buffer): the same signature
    gif_pass.changed_box(one, colours, one, colours, np.empty(4, dtype=np.int64))
    _LOADED.append(True)


def _frame(pic: GifPicture, box, data: bytes, transparent, disposal: int, alone: bool) -> GifFrame:
    return GifFrame(pic.width, pic.height, box, pic.palette, data, transparent, disposal, alone,
                    pic.clear, pic.marks, pic.flattened, pic.reserve)  # fmt: skip


def _repeat(pic: GifPicture) -> GifFrame:
    """A frame showing the picture of the one before (``GifPicture.same``): no block."""
    return GifFrame(pic.width, pic.height, (0, 0, 1, 1), b"", b"", pic.transparent, KEEP, False,
                    pic.clear, pic.marks, pic.flattened, pic.reserve, repeat=True)  # fmt: skip


def _lzw(indices: np.ndarray, palette: bytes) -> bytes:
    """The LZW image data of a block of palette indices: Pillow's GIF encoder
    (``GifImagePlugin.getdata``, whose image descriptor and code size byte are left out: the
    writer writes its own)."""
    image = Image.fromarray(np.ascontiguousarray(indices), mode="P")
    image.putpalette(palette)
    chunks = GifImagePlugin.getdata(image)
    # [image descriptor (10 bytes), LZW code size (1 byte), the data sub-blocks..., b"\0"]
    if len(chunks[0]) != 10 or chunks[0][:1] != b"," or chunks[1] != b"\x08":
        raise RuntimeError("Pillow's GIF frame data is not laid out as expected")
    return b"".join(chunks[2:])


def link_gif(pictures):
    """GIF frames of a run of consecutive ``GifPicture``s drawn in one process, in order, one
    for each: every picture encoded against the one before it (``encode_gif``; a repeat of it
    marked so) but the run's first when it is opaque, which is given as it is (the writer
    encodes it against the frame before the run); the last frame carries its picture (the
    frame before the next run)."""
    before = held = None
    for pic in pictures:
        if held is not None:
            yield held
        if before is not None and pic.same(before):
            held = _repeat(pic)
        elif before is None and pic.transparent is None:
            _ready_to_compare()
            held = pic
        else:
            held = encode_gif(pic, before)
        before = pic
    if isinstance(held, GifFrame) and before.transparent is None:
        held = replace(held, picture=before)
    if held is not None:
        yield held
