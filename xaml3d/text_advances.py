"""Advance widths of a line of text read from the package font's own tables (layout's measure).

Layout needs a TextBlock's (or a control's text's) width, not its glyphs: importing skia for
that alone cost a whole process about 25-35 ms, more than reading a small scene. The widths
here are the numbers skia's ``Font.measureText`` gives for the same font at the same size with
subpixel positioning and no hinting (``xaml3d.text_metrics``), bit for bit: each glyph's linear
advance as FreeType computes it in 16.16 fixed point (``FT_Set_Char_Size`` at the size cut to
26.6, ``x_scale = FT_DivFix(size, units_per_em)``, ``FT_MulDiv(advance, x_scale, 64)``),
converted to float32 and summed in float32 in text order. Like skia, sizes above 256 px are
measured at 64 px and scaled, and sizes below 1 px at 1 px with each advance scaled.
``tests/test_text_advances.py`` compares both ways over random strings and sizes.

Only the tables measuring needs are read: ``head`` (units per em), ``hhea`` and ``hmtx`` (the
advances), ``cmap`` (its Unicode format 4 table, the one the Open Sans files have).
"""

from __future__ import annotations

import functools
import struct

import numpy as np


class FontTables:
    """The advance of every character of one font file, in font units."""

    def __init__(self, data: bytes) -> None:
        tables = {}
        for i in range(struct.unpack_from(">H", data, 4)[0]):
            tag, _, offset, length = struct.unpack_from(">4sIII", data, 12 + 16 * i)
            tables[tag] = (offset, length)
        self.units_per_em = struct.unpack_from(">H", data, tables[b"head"][0] + 18)[0]
        metrics = struct.unpack_from(">H", data, tables[b"hhea"][0] + 34)[0]
        hmtx = np.frombuffer(data, ">u2", metrics * 2, tables[b"hmtx"][0])
        # glyphs past the last long metric share its advance (the OpenType hmtx rule)
        self.advances = hmtx[0::2].astype(np.int64)
        self.glyphs = _cmap_format4(data, tables[b"cmap"][0])

    def advance_units(self, text: str) -> np.ndarray:
        """The advance (font units) of each character; a character the font lacks takes the
        .notdef glyph's (glyph 0), as skia draws it."""
        glyphs = self.glyphs
        ids = np.fromiter((glyphs.get(ord(c), 0) for c in text), np.int64, len(text))
        return self.advances[np.minimum(ids, len(self.advances) - 1)]


def _cmap_format4(data: bytes, cmap: int) -> dict[int, int]:
    """{code point: glyph} of the font's Unicode BMP table (platform 3 encoding 1, or
    platform 0), format 4: segments of code points with an offset or a glyph array."""
    found = None
    for i in range(struct.unpack_from(">H", data, cmap + 2)[0]):
        platform, encoding, offset = struct.unpack_from(">HHI", data, cmap + 4 + 8 * i)
        if (platform, encoding) == (3, 1) or platform == 0:
            if struct.unpack_from(">H", data, cmap + offset)[0] == 4:
                found = cmap + offset
                break
    if found is None:
        raise ValueError("the font has no Unicode format 4 cmap table")
    seg2 = struct.unpack_from(">H", data, found + 6)[0]
    ends = found + 14
    starts = ends + seg2 + 2
    deltas = starts + seg2
    ranges = deltas + seg2
    out: dict[int, int] = {}
    for s in range(seg2 // 2):
        end, start = (struct.unpack_from(">H", data, at + 2 * s)[0] for at in (ends, starts))
        delta = struct.unpack_from(">h", data, deltas + 2 * s)[0]
        at = ranges + 2 * s
        range_offset = struct.unpack_from(">H", data, at)[0]
        for cp in range(start, min(end, 0xFFFE) + 1):
            if range_offset == 0:
                glyph = (cp + delta) & 0xFFFF
            else:
                # idRangeOffset counts bytes from its own slot to the glyph array entry
                glyph = struct.unpack_from(">H", data, at + range_offset + 2 * (cp - start))[0]
                glyph = (glyph + delta) & 0xFFFF if glyph else 0
            if glyph:
                out[cp] = glyph
    return out


@functools.lru_cache(maxsize=16)
def font_tables(path: str) -> FontTables:
    with open(path, "rb") as f:
        return FontTables(f.read())


def _linear(units: np.ndarray, size: np.float32, upem: int) -> np.ndarray:
    """FreeType's linear advances (float32 pixels) of ``units`` at ``size``, cut to 26.6."""
    char_size = int(size * np.float32(64))  # skia's SkScalarToFDot6 truncates
    x_scale = (char_size * 65536 + upem // 2) // upem  # FT_DivFix
    fixed = (units * x_scale + 32) // 64  # FT_MulDiv(advance, x_scale, 64): 16.16 pixels
    return fixed.astype(np.float32) * np.float32(1 / 65536)


def measure(path: str, text: str, size: float) -> float:
    """The advance width of ``text`` at ``size`` px in the font at ``path``, as skia measures
    it (see the module's docstring). ``size`` must be finite and above 0."""
    tables = font_tables(path)
    units = tables.advance_units(text)
    if units.size == 0:
        return 0.0
    size32 = np.float32(size)
    if size32 > 256:  # skia measures large text on its canonical 64 px strike, then scales
        widths = _linear(units, np.float32(64), tables.units_per_em)
        total = np.add.accumulate(widths, dtype=np.float32)[-1]
        with np.errstate(over="ignore"):  # a size near float32's limit: inf, as skia gives
            return float(total * (size32 / np.float32(64)))
    if size32 < 1:  # FreeType is set to 1 px; skia's matrix scales each advance down
        widths = _linear(units, np.float32(1), tables.units_per_em) * size32
    else:
        widths = _linear(units, size32, tables.units_per_em)
    # summed one after another in float32, as skia adds advances (not numpy's pairwise sum)
    return float(np.add.accumulate(widths, dtype=np.float32)[-1])
